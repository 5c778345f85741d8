//! Headless tests of the replay viewer: a live game (`MinimalPlugins` plus the settings,
//! simulation, autosave and replay plugins) plays and saves shots; the saved file is opened
//! in replay mode through [`ReplayCommand`]s, as the panel does.

mod common;

use common::replay::*;

use bevy::{math::DVec2, prelude::*, window::FileDragAndDrop};
use billiards::{
    mode::GameMode,
    replay::{OpenAtStart, Replay, ReplayBall, ReplayCommand},
    sim::{RackRequested, ShotRequested, SimStatus, Solver},
    table::balls::Ball,
};
use billiards_physics::{
    Motion, Rack,
    recording::{Recording, Verdict},
};
use billiards_rules::Shots;

#[test]
fn a_saved_game_replays_exactly_at_any_time_and_closing_restores_the_live_game() {
    let (mut app, file) = played_game("exact");
    let live_before = balls::<With<Ball>>(&mut app);
    assert_eq!(live_before, solver_balls(&app));
    let solver_time = app.world().resource::<Solver>().simulation().time();
    let live_events = app
        .world()
        .resource::<Solver>()
        .simulation()
        .history()
        .events()
        .len();

    command(&mut app, ReplayCommand::Open(file.clone()));
    assert_eq!(mode(&app), GameMode::Replay);
    assert_eq!(app.world().resource::<Replay>().error, None);
    command(&mut app, ReplayCommand::Pause);

    let recording = Recording::load(&file).unwrap();
    let history = recording.history().unwrap();
    let end = recording.end_time;
    assert!(end > 1.0, "end time {end}");
    // Only the recorded balls carry `Ball` while replaying.
    assert_eq!(balls::<With<Ball>>(&mut app).len(), recording.balls.len());
    let strike = recording.inputs[1].time;
    for t in [
        0.0,
        0.013,
        0.25,
        end / 3.0,
        strike,
        strike + 0.1234567,
        end * 0.9,
        end,
    ] {
        command(&mut app, ReplayCommand::Seek(t));
        assert_eq!(replay_time(&app), t);
        let expected: Vec<(usize, DVec2, bool)> = history
            .states_at(t)
            .iter()
            .enumerate()
            .map(|(id, s)| {
                let pocketed = matches!(s.motion, Motion::Pocketed(_));
                (id, DVec2::new(s.position.x, s.position.y), pocketed)
            })
            .collect();
        assert_eq!(balls::<With<ReplayBall>>(&mut app), expected, "t = {t}");
    }
    // Out of range: clamped to the recording.
    command(&mut app, ReplayCommand::Seek(end + 10.0));
    assert_eq!(replay_time(&app), end);

    // Playing runs the replay clock at the chosen speed from the frame after the Play (the
    // frame of the click may follow an idle window); the live solver stays put.
    command(&mut app, ReplayCommand::Seek(0.5));
    command(&mut app, ReplayCommand::SetSpeed(2.0));
    command(&mut app, ReplayCommand::Play);
    for _ in 0..10 {
        app.update();
    }
    let t = replay_time(&app);
    assert!((t - (0.5 + 10.0 * 0.016 * 2.0)).abs() < 1e-9, "t = {t}");
    let solver = app.world().resource::<Solver>().simulation();
    assert_eq!(solver.time(), solver_time);
    assert_eq!(solver.history().events().len(), live_events);

    // A shot asked for while replaying is not taken.
    app.world_mut().write_message(ShotRequested {
        angle: 0.0,
        speed: 3.0,
        tip: Default::default(),
        elevation: 0.0,
    });
    app.update();
    assert!(app.world().resource::<Solver>().simulation().is_at_rest());

    command(&mut app, ReplayCommand::Close);
    assert_eq!(mode(&app), GameMode::Play);
    assert!(app.world().resource::<Replay>().open.is_none());
    assert_eq!(
        app.world_mut()
            .query_filtered::<(), With<ReplayBall>>()
            .iter(app.world())
            .count(),
        0
    );
    assert_eq!(balls::<With<Ball>>(&mut app), live_before);
    assert_eq!(
        app.world().resource::<Solver>().simulation().time(),
        solver_time
    );

    // The live game goes on: a new shot is struck and played out.
    let shots = app.world().resource::<SimStatus>().shots;
    play_shot(&mut app, -1.0, 1.5);
    assert_eq!(app.world().resource::<SimStatus>().shots, shots + 1);
    assert_eq!(balls::<With<Ball>>(&mut app), solver_balls(&app));
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(file.parent().unwrap());
}

#[test]
fn stepping_lands_on_event_and_shot_times() {
    let (mut app, file) = played_game("steps");
    command(&mut app, ReplayCommand::Open(file.clone()));
    command(&mut app, ReplayCommand::Pause);
    let recording = Recording::load(&file).unwrap();
    let times: Vec<f64> = recording.events.iter().map(|e| e.time).collect();
    let mut distinct = times.clone();
    distinct.dedup();
    assert!(distinct.len() > 5);

    // Forward from the start through the first events, each step on the next event time.
    command(&mut app, ReplayCommand::Seek(0.0));
    for &expected in distinct.iter().filter(|&&t| t > 0.0).take(8) {
        command(&mut app, ReplayCommand::NextEvent);
        assert_eq!(replay_time(&app), expected);
        let replay = app.world().resource::<Replay>();
        let open = replay.open.as_ref().unwrap();
        let (index, event) = open.event_at(replay.time).unwrap();
        assert_eq!(event.time, expected);
        // The event under the cursor is the last one at that time.
        assert!(times.get(index + 1).is_none_or(|&next| next > expected));
        assert!(!replay.playing, "stepping pauses");
    }
    // Backward from between two events: the earlier one, then the one before.
    let (a, b) = (distinct[3], distinct[4]);
    command(&mut app, ReplayCommand::Seek((a + b) / 2.0));
    command(&mut app, ReplayCommand::PreviousEvent);
    assert_eq!(replay_time(&app), a);
    command(&mut app, ReplayCommand::PreviousEvent);
    assert_eq!(replay_time(&app), distinct[2]);
    // At the end there is no next event: the time stays.
    let end = app
        .world()
        .resource::<Replay>()
        .open
        .as_ref()
        .unwrap()
        .end_time();
    command(&mut app, ReplayCommand::Seek(end));
    command(&mut app, ReplayCommand::NextEvent);
    assert_eq!(replay_time(&app), end);

    // Shots: the strike inputs.
    let strikes = Shots::of(&recording).starts().to_vec();
    assert_eq!(strikes.len(), 2);
    command(&mut app, ReplayCommand::Seek(0.0));
    let shot = |app: &App| {
        let replay = app.world().resource::<Replay>();
        replay.open.as_ref().unwrap().shot_at(replay.time)
    };
    assert_eq!(shot(&app), 1, "the first strike is at t = 0");
    command(&mut app, ReplayCommand::NextShot);
    assert_eq!(replay_time(&app), strikes[1]);
    assert_eq!(shot(&app), 2);
    command(&mut app, ReplayCommand::Seek(strikes[1] + 0.5));
    command(&mut app, ReplayCommand::PreviousShot);
    assert_eq!(replay_time(&app), strikes[1]);
    command(&mut app, ReplayCommand::PreviousShot);
    assert_eq!(replay_time(&app), strikes[0]);
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(file.parent().unwrap());
}

#[test]
fn a_bad_file_shows_an_error_and_leaves_the_live_game() {
    let folder = temp_folder("bad");
    let mut app = game(&folder, Rack::NineBall);
    let live = balls::<With<Ball>>(&mut app);
    let bad = folder.join("broken.json");
    std::fs::write(&bad, "{ \"version\": 1, \"table\": ").unwrap();
    command(&mut app, ReplayCommand::Open(bad.clone()));
    assert_eq!(mode(&app), GameMode::Play);
    let error = app.world().resource::<Replay>().error.clone().unwrap();
    assert!(error.contains("broken.json"), "{error}");
    assert!(error.contains("not a valid recording"), "{error}");
    assert_eq!(balls::<With<Ball>>(&mut app), live);
    // Said in a window over the table (src/ui/recordings.rs), not only in the panel below the
    // fold: the window shows the reason until the player dismisses it.
    assert_eq!(
        app.world().resource::<Replay>().error_to_show(),
        Some(error.as_str()),
        "the window is up with the reason"
    );
    command(&mut app, ReplayCommand::DismissError);
    assert_eq!(
        app.world().resource::<Replay>().error_to_show(),
        None,
        "OK closes the window"
    );
    // The Recordings section keeps the reason.
    assert_eq!(app.world().resource::<Replay>().error, Some(error));
    assert_eq!(mode(&app), GameMode::Play);

    let missing = folder.join("missing.json");
    command(&mut app, ReplayCommand::Open(missing));
    assert_eq!(mode(&app), GameMode::Play);
    assert!(
        app.world()
            .resource::<Replay>()
            .error
            .as_ref()
            .unwrap()
            .contains("missing.json")
    );
    // A rules log opened by mistake is named as such, with the recording to open instead.
    let log = folder.join("rack.game.json");
    std::fs::write(
        &log,
        r#"{"version":1,"game":"nine_ball","rack_seed":1,"players":["A","B"],"breaker":"a","shots":[]}"#,
    )
    .unwrap();
    command(&mut app, ReplayCommand::Open(log.clone()));
    let error = app.world().resource::<Replay>().error.clone().unwrap();
    assert!(
        error.contains("is a rules log, not a recording: open the recording beside it")
            && error.contains("rack.json"),
        "{error}"
    );
    command(&mut app, ReplayCommand::Open(folder.join("missing.json")));
    // A new bad file brings the window back, with its own reason.
    let shown = app
        .world()
        .resource::<Replay>()
        .error_to_show()
        .map(str::to_owned);
    assert!(shown.is_some_and(|e| e.contains("missing.json")));
    // The live game still plays.
    play_shot(&mut app, 0.0, 2.0);
    assert_eq!(app.world().resource::<SimStatus>().shots, 1);
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn another_ball_count_gets_its_own_balls_and_the_live_ones_come_back() {
    let folder = temp_folder("count");
    let mut app = game(&folder, Rack::NineBall);
    let live = balls::<With<Ball>>(&mut app);
    assert_eq!(live.len(), 10);
    let file = folder.join("break.json");
    let recording = fifteen_ball_recording(&file);

    // Opened by dropping the file on the window.
    app.world_mut().write_message(FileDragAndDrop::DroppedFile {
        window: Entity::PLACEHOLDER,
        path_buf: file.clone(),
    });
    app.update();
    assert_eq!(mode(&app), GameMode::Replay);
    command(&mut app, ReplayCommand::Pause);
    command(&mut app, ReplayCommand::Seek(1.0));
    let history = recording.history().unwrap();
    let shown = balls::<With<Ball>>(&mut app);
    assert_eq!(shown.len(), 16);
    for (id, position, _) in shown {
        let s = history.state_at(id, 1.0);
        assert_eq!(position, DVec2::new(s.position.x, s.position.y));
    }

    // Verify re-simulates the recording, on its own thread.
    command(&mut app, ReplayCommand::Verify);
    common::update_until(&mut app, |app| {
        app.world().resource::<Replay>().verifying.is_none()
    });
    let replay = app.world().resource::<Replay>();
    let verdict = replay
        .verdict
        .clone()
        .expect("a verdict once the thread is done");
    assert!(
        matches!(verdict, Ok(Verdict::Reproduced { events }) if events == recording.events.len())
    );
    let text = replay.open.as_ref().unwrap().verdict_text(&verdict);
    assert!(text.starts_with("reproduced bit for bit ("), "{text}");

    // A rack asked for while replaying closes the replay and racks the live table.
    app.world_mut()
        .write_message(RackRequested::standard(Rack::PaperDefault));
    app.update();
    assert_eq!(mode(&app), GameMode::Play);
    assert_eq!(balls::<With<Ball>>(&mut app).len(), 1);
    assert_eq!(
        app.world_mut().query::<&Ball>().iter(app.world()).count()
            + app
                .world_mut()
                .query_filtered::<(), With<ReplayBall>>()
                .iter(app.world())
                .count(),
        1
    );
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn closing_a_replay_of_another_ball_count_restores_the_live_balls() {
    let folder = temp_folder("count-close");
    let mut app = game(&folder, Rack::NineBall);
    play_shot(&mut app, 0.0, 6.0);
    let live = balls::<With<Ball>>(&mut app);
    let file = folder.join("break.json");
    fifteen_ball_recording(&file);
    command(&mut app, ReplayCommand::Open(file));
    assert_eq!(balls::<With<Ball>>(&mut app).len(), 16);
    command(&mut app, ReplayCommand::Close);
    assert_eq!(balls::<With<Ball>>(&mut app), live);
    assert_eq!(live, solver_balls(&app));
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn the_command_line_file_opens_once_the_table_is_racked() {
    let folder = temp_folder("start");
    let file = folder.join("break.json");
    fifteen_ball_recording(&file);
    let mut app = headless();
    app.insert_resource(OpenAtStart(file.clone()));
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(mode(&app), GameMode::Replay);
    assert!(app.world().get_resource::<OpenAtStart>().is_none());
    // The live table behind it was racked (the starting rack), and comes back on close.
    command(&mut app, ReplayCommand::Close);
    assert_eq!(balls::<With<Ball>>(&mut app), solver_balls(&app));
    assert!(!solver_balls(&app).is_empty());
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn a_bad_command_line_file_is_said_in_a_window_over_free_play() {
    // `billiards replay BAD.json`: free play opens, and the reason is up in a window
    // (src/ui/recordings.rs `error_window` shows `Replay::error_to_show`).
    let folder = temp_folder("start-bad");
    let bad = folder.join("bad.json");
    std::fs::write(&bad, "not json at all").unwrap();
    let mut app = headless();
    app.insert_resource(OpenAtStart(bad.clone()));
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(mode(&app), GameMode::Play);
    let shown = app
        .world()
        .resource::<Replay>()
        .error_to_show()
        .map(str::to_owned);
    let shown = shown.expect("the window is up");
    assert!(shown.contains("bad.json"), "{shown}");
    command(&mut app, ReplayCommand::DismissError);
    assert_eq!(app.world().resource::<Replay>().error_to_show(), None);
    let _ = std::fs::remove_dir_all(&folder);
}
