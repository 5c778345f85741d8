//! Headless tests of a replay's files: exports run in the background (and cancelled), a
//! game struck while paused saved before a rack replaces it, a verification's report.

mod common;

use common::replay::*;
use std::path::Path;

use bevy::prelude::*;
use billiards::{
    recording::Autosave,
    replay::{ExportFormat, ExportRequest, ExportScope, Replay, ReplayCommand},
    settings::PhysicsSettings,
    sim::{RackRequested, ShotRequested, Solver},
};
use billiards_physics::{
    Rack, Shot,
    recording::{Recorder, Recording, Verdict},
};
use billiards_rules::Shots;

#[test]
fn a_cancelled_export_stops_and_leaves_no_gif() {
    let (mut app, file) = played_game("export-cancel");
    command(&mut app, ReplayCommand::Open(file.clone()));
    command(&mut app, ReplayCommand::Pause);
    let out = file.with_file_name("whole.gif");
    // Hundreds of large frames: far longer than the few frames before the cancel is seen.
    command(
        &mut app,
        ReplayCommand::Export(ExportRequest {
            format: ExportFormat::Gif,
            scope: ExportScope::WholeGame,
            fps: 50.0,
            width: 1280,
            height: 720,
            path: Some(out.clone()),
        }),
    );
    assert!(app.world().resource::<Replay>().export.is_some());
    command(&mut app, ReplayCommand::CancelExport);
    common::update_until(&mut app, |app| {
        app.world().resource::<Replay>().export.is_none()
    });
    let finished = app.world().resource::<Replay>().export_result.clone();
    let error = finished.expect("the export ended").unwrap_err();
    assert!(error.contains("cancelled after"), "{error}");
    let left: Vec<_> = std::fs::read_dir(file.parent().unwrap())
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|name| name.contains("whole"))
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(file.parent().unwrap());
}

#[test]
fn an_export_runs_in_the_background_and_reports_its_frames() {
    let (mut app, file) = played_game("export");
    command(&mut app, ReplayCommand::Open(file.clone()));
    command(&mut app, ReplayCommand::Pause);
    let out = file.with_file_name("shot.gif");
    command(
        &mut app,
        ReplayCommand::Export(ExportRequest {
            format: ExportFormat::Gif,
            scope: ExportScope::CurrentShot,
            fps: 5.0,
            width: 64,
            height: 36,
            path: Some(out.clone()),
        }),
    );
    common::update_until(&mut app, |app| {
        match &app.world().resource::<Replay>().export {
            Some(job) => {
                let (done, total) = job.progress();
                assert!(done <= total || total == 0);
                false
            }
            None => true,
        }
    });
    let finished = app.world().resource::<Replay>().export_result.clone();
    let message = finished.expect("export finished").unwrap();
    assert!(message.ends_with("frames"), "{message}");
    assert!(std::fs::metadata(&out).unwrap().len() > 100);

    // The whole game as PNGs, to the default place next to the recording.
    command(
        &mut app,
        ReplayCommand::Export(ExportRequest {
            format: ExportFormat::PngSequence,
            scope: ExportScope::WholeGame,
            fps: 2.0,
            width: 32,
            height: 18,
            path: None,
        }),
    );
    let stem = file.file_stem().unwrap().to_string_lossy().into_owned();
    let target = file.with_file_name(format!("{stem}_frames"));
    common::update_until(&mut app, |app| {
        app.world().resource::<Replay>().export.is_none()
    });
    let result = app
        .world()
        .resource::<Replay>()
        .export_result
        .clone()
        .unwrap()
        .unwrap();
    assert!(
        result.starts_with(&target.display().to_string()),
        "{result}"
    );
    assert!(target.join("frame_00000.png").exists());
    // Left behind when the test fails, for a look.
    let _ = std::fs::remove_dir_all(file.parent().unwrap());
}

#[test]
fn a_shot_struck_while_paused_is_saved_before_a_rack_replaces_the_game() {
    let folder = temp_folder("paused-shot");
    let mut app = game(&folder, Rack::NineBall);
    app.world_mut().resource_mut::<PhysicsSettings>().paused = true;
    app.update();
    app.world_mut().write_message(ShotRequested {
        angle: 0.0,
        speed: 7.0,
        tip: Default::default(),
        elevation: 0.0,
    });
    for _ in 0..3 {
        app.update();
    }
    // Nothing finished (paused), so the shot is not saved yet: then a rack is asked for.
    assert!(app.world().resource::<Autosave>().file.is_none());
    app.world_mut()
        .write_message(RackRequested::standard(Rack::FifteenBall));
    app.update();
    let saved = app
        .world()
        .resource::<Autosave>()
        .file
        .clone()
        .expect("the game was saved before the rack");
    let recording = Recording::load(&saved).unwrap();
    let strikes = Shots::of(&recording).len();
    assert_eq!(strikes, 1, "the paused shot is in the file");
    assert!(matches!(
        recording.verify().unwrap(),
        Verdict::Reproduced { .. }
    ));
    // The new rack is on the table.
    assert_eq!(
        app.world().resource::<Solver>().simulation().ball_count(),
        16
    );
    // A second rack request with nothing new played writes nothing more.
    let modified = std::fs::metadata(&saved).unwrap().modified().unwrap();
    app.world_mut()
        .write_message(RackRequested::standard(Rack::NineBall));
    app.update();
    assert_eq!(
        std::fs::metadata(&saved).unwrap().modified().unwrap(),
        modified
    );
    std::fs::remove_dir_all(folder).ok();
}

/// A verification that fails says where with every digit needed: a recorded strike at
/// 6.0 m/s replayed at 6.000001 m/s does not read "6.00 m/s" on both sides.
#[test]
fn a_difference_is_printed_with_the_digits_that_differ() {
    use billiards::replay::OpenRecording;
    use billiards_physics::{Params, Table, recording::Action};
    let table = Table::wpa_8ft();
    let params = Params::default();
    let layout = Rack::FifteenBall.layout(&table, &params.ball);
    let mut rec = Recorder::new(table, params, layout).unwrap();
    rec.strike(0, Shot::new(0.0, 6.0)).unwrap();
    rec.run_to_rest().unwrap();
    let mut recording = rec.recording();
    if let Action::Strike { shot, .. } = &mut recording.inputs[0].action {
        shot.speed = 6.000001;
    }
    let verdict = recording.verify();
    let open = OpenRecording::new(Path::new("tampered.json"), recording).unwrap();
    let text = open.verdict_text(&verdict);
    assert!(
        text.contains(" 6 m/s") && text.contains(" 6.000001 m/s"),
        "{text}"
    );
}
