//! What the headless app tests share.

pub mod replay;

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

/// A headless game with the practice tools (and the rules and the replay they read), a
/// 15-ball rack on the table.
#[allow(dead_code, reason = "the practice and clipboard tests use it")]
pub fn practice_app() -> App {
    use billiards::{play::game, practice, replay};
    let mut app = headless((game::plugin, replay::plugin, practice::plugin));
    app.update();
    app.world_mut().write_message(sim::RackRequested::standard(
        billiards_physics::Rack::FifteenBall,
    ));
    app.update();
    app
}

/// Every ball on the table: its number and centre, by number.
#[allow(dead_code, reason = "the practice and clipboard tests use it")]
pub fn layout(app: &App) -> Vec<(u8, bevy::math::DVec2)> {
    let sim = app.world().resource::<sim::Solver>().simulation();
    let mut balls: Vec<(u8, bevy::math::DVec2)> = sim::layout_now(sim)
        .into_iter()
        .map(|b| (b.number, bevy::math::DVec2::new(b.position.x, b.position.y)))
        .collect();
    balls.sort_by_key(|b| b.0);
    balls
}

/// Strikes the cue ball at `angle` (radians) with `speed` (m/s), no spin, and runs frames
/// until every ball rests.
#[allow(dead_code, reason = "the practice and clipboard tests use it")]
pub fn shoot_to_rest(app: &mut App, angle: f64, speed: f64) {
    app.world_mut()
        .write_message(sim::ShotRequested::from(billiards_physics::Shot {
            angle,
            speed,
            tip: Default::default(),
            elevation: 0.0,
        }));
    app.update();
    update_until(app, |app| {
        app.world()
            .resource::<sim::Solver>()
            .simulation()
            .is_at_rest()
    });
}
