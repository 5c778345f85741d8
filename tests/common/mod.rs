//! What the headless app tests share.

use std::time::Duration;

use bevy::{app::Plugins, prelude::*, time::TimeUpdateStrategy};
use billiards::{mode, recording, settings, sim};

/// A headless game: `MinimalPlugins`, the modes, the settings, the simulation and the
/// autosave, then `extra`, in 16 ms frames; no frame run yet.
pub fn headless<M>(extra: impl Plugins<M>) -> App {
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins,
        mode::plugin,
        settings::plugin,
        sim::plugin,
        recording::plugin,
    ))
    .add_plugins(extra);
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(
        16,
    )));
    app
}

/// Runs frames until `done` holds, however long the machine takes: the work it waits for
/// (a verification, an export, a decision) runs on a thread of its own, and a loaded machine
/// must not fail a test that a quiet one passes. Between frames the thread is given the core
/// for a moment. A hang is a bug to find, and shows as a test that does not end.
#[allow(dead_code, reason = "not every test file waits for a thread")]
pub fn update_until(app: &mut App, mut done: impl FnMut(&mut App) -> bool) {
    while !done(app) {
        std::thread::sleep(Duration::from_millis(2));
        app.update();
    }
}

/// Puts the cue ball in hand at `at` the way the drag does (an edit the solver records).
#[allow(dead_code, reason = "not every test file places the cue ball")]
pub fn place(app: &mut App, at: bevy::math::DVec2) -> Result<(), sim::HandError> {
    use billiards::table::{
        balls::{Ball, BallMotion},
        geometry::TableSpec,
    };
    let rule = app
        .world()
        .resource::<sim::SimStatus>()
        .ball_in_hand
        .unwrap();
    let result = app
        .world_mut()
        .resource_scope(|world, solver: Mut<sim::Solver>| {
            let spec = world.resource::<TableSpec>().clone();
            let mut query = world.query::<(&Ball, &mut BallMotion)>();
            let (_, mut motion) = query
                .iter_mut(world)
                .find(|(ball, _)| ball.number == 0)
                .unwrap();
            sim::place_ball_in_hand(&solver, &spec, &mut motion, at, rule)
        });
    app.update();
    result
}
