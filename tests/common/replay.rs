//! What the replay tests share: a headless game with the replay viewer, shots played and
//! saved, the balls as the app and the solver have them, a recording made with the library.

#![allow(dead_code, reason = "only the replay tests use these")]

use std::path::{Path, PathBuf};

use bevy::{math::DVec2, prelude::*};
use billiards::{
    mode::GameMode,
    recording::{self, Autosave, RecordingsFolder},
    replay::{self, Replay, ReplayCommand},
    settings::PhysicsSettings,
    sim::{RackRequested, ShotRequested, SimStatus, Solver, params_for},
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
};
use billiards_physics::{
    Motion, Rack, Shot,
    recording::{Recorder, Recording},
};

/// A fresh, empty folder for one test.
pub fn temp_folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-replay-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A headless app with the simulation, the autosave and the replay, in 16 ms frames; no
/// frame run yet.
pub fn headless() -> App {
    super::headless(replay::plugin)
}

/// A headless game saving into `folder`, with `rack` on the table.
pub fn game(folder: &Path, rack: Rack) -> App {
    let mut app = headless();
    app.insert_resource(RecordingsFolder(Some(folder.to_path_buf())));
    app.update();
    app.world_mut().write_message(RackRequested::standard(rack));
    app.update();
    app
}

/// Shoots in the live game and runs frames until every ball rests again.
pub fn play_shot(app: &mut App, angle: f64, speed: f64) {
    app.world_mut().write_message(ShotRequested {
        angle,
        speed,
        tip: Default::default(),
        elevation: 0.0,
    });
    for i in 0..20_000 {
        app.update();
        if i > 0 && app.world().resource::<SimStatus>().at_rest {
            // One more frame: the autosave runs after the step that came to rest.
            app.update();
            return;
        }
    }
    panic!("balls still moving");
}

/// (id, position, pocketed) of the balls matching `F`, by id.
pub fn balls<F: bevy::ecs::query::QueryFilter>(app: &mut App) -> Vec<(usize, DVec2, bool)> {
    let mut balls: Vec<_> = app
        .world_mut()
        .query_filtered::<(&Ball, &BallMotion, Has<Pocketed>), F>()
        .iter(app.world())
        .map(|(ball, motion, pocketed)| (ball.id, motion.position, pocketed))
        .collect();
    balls.sort_by_key(|&(id, _, _)| id);
    balls
}

/// The live balls as the live solver has them.
pub fn solver_balls(app: &App) -> Vec<(usize, DVec2, bool)> {
    let sim = app.world().resource::<Solver>().simulation();
    sim.balls()
        .enumerate()
        .map(|(id, s)| {
            let pocketed = matches!(s.motion, Motion::Pocketed(_));
            (id, DVec2::new(s.position.x, s.position.y), pocketed)
        })
        .collect()
}

/// Sends a replay command and runs a frame.
pub fn command(app: &mut App, command: ReplayCommand) {
    app.world_mut().write_message(command);
    app.update();
}

/// The replay's time, seconds.
pub fn replay_time(app: &App) -> f64 {
    app.world().resource::<Replay>().time
}

/// The game's mode now.
pub fn mode(app: &App) -> GameMode {
    *app.world().resource::<State<GameMode>>().get()
}

/// Two shots played and autosaved in a 9-ball game; returns the app and the saved file.
pub fn played_game(name: &str) -> (App, PathBuf) {
    let folder = temp_folder(name);
    let mut app = game(&folder, Rack::NineBall);
    play_shot(&mut app, 0.0, 7.0);
    play_shot(&mut app, 1.9, 2.0);
    let file = app
        .world()
        .resource::<Autosave>()
        .file
        .clone()
        .expect("the game was saved");
    assert_eq!(recording::list_recordings(&folder), vec![file.clone()]);
    (app, file)
}

/// A 16-ball recording made with the library alone, saved to `path`.
pub fn fifteen_ball_recording(path: &Path) -> Recording {
    let spec = TableSpec::default();
    let params = params_for(&spec, &PhysicsSettings::default());
    let table = spec.physics_table();
    let layout = Rack::FifteenBall.layout(&table, &params.ball);
    let mut rec = Recorder::new(table, params, layout).unwrap();
    rec.strike(0, Shot::new(0.01, 8.0)).unwrap();
    rec.run_to_rest().unwrap();
    let recording = rec.recording();
    recording.save(path).unwrap();
    recording
}
