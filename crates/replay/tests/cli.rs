//! The command line and the exports, end to end.

use billiards_physics::recording::{Recorder, Recording};
use billiards_physics::*;
use billiards_replay::export::{self, ExportOptions};
use std::ops::ControlFlow;
use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn break_recording() -> Recording {
    let table = Table::wpa_8ft().with_jaws(0.015);
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let mut rec = Recorder::new(
        table,
        params,
        Rack::FifteenBall.layout(&table, &params.ball),
    )
    .unwrap();
    rec.strike(0, Shot::new(0.0, 9.0)).unwrap();
    rec.run_to_rest().unwrap();
    rec.recording()
}

#[test]
fn exported_gif_frames_show_the_balls_moving() {
    let rec = break_recording();
    let dir = temp("gif");
    let out = dir.join("break.gif");
    let opts = ExportOptions {
        fps: 10.0,
        width: 200,
        height: 110,
        span: (0.0, 1.0),
    };
    let n = export::gif(&rec, &opts, &out, &mut |_, _| ControlFlow::Continue(())).unwrap();
    assert_eq!(n, 11);
    // Decode and compare: between the first and the sixth frame (0.5 s into a 9 m/s break)
    // the cue ball and the rack have moved, so many pixels changed; the background did not.
    let mut dec = gif::DecodeOptions::new();
    dec.set_color_output(gif::ColorOutput::RGBA);
    let mut d = dec.read_info(std::fs::File::open(&out).unwrap()).unwrap();
    let mut frames = Vec::new();
    while let Some(f) = d.read_next_frame().unwrap() {
        frames.push(f.buffer.to_vec());
    }
    assert_eq!(frames.len(), 11);
    let changed = frames[0]
        .chunks(4)
        .zip(frames[5].chunks(4))
        .filter(|(a, b)| a != b)
        .count();
    assert!(changed > 50, "only {changed} pixels changed");
    assert!(
        changed < 200 * 110 / 4,
        "{changed} pixels changed: more than the balls"
    );
    let white = |f: &Vec<u8>| {
        f.chunks(4)
            .filter(|p| p[0] > 220 && p[1] > 220 && p[2] > 200)
            .count()
    };
    assert!(white(&frames[0]) > 0, "the cue ball is drawn");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn png_sequence_is_numbered_and_timed_by_simulated_time() {
    let rec = break_recording();
    let dir = temp("png");
    let opts = ExportOptions {
        fps: 4.0,
        width: 64,
        height: 40,
        span: (0.0, 2.0),
    };
    let n = export::png_sequence(&rec, &opts, &dir, &mut |_, _| ControlFlow::Continue(())).unwrap();
    assert_eq!(n, 9);
    assert!(dir.join("frame_00008.png").exists() && !dir.join("frame_00009.png").exists());
    std::fs::remove_dir_all(dir).ok();
}

/// A cancelled GIF export stops at once, says after how many frames, and leaves neither a
/// truncated GIF nor its temporary file; an earlier complete GIF at the same path survives.
#[test]
fn cancelled_gif_export_leaves_no_partial_file() {
    let rec = break_recording();
    let dir = temp("cancel-gif");
    let out = dir.join("break.gif");
    let opts = ExportOptions {
        fps: 10.0,
        width: 64,
        height: 40,
        span: (0.0, 2.0),
    };
    let mut calls = 0;
    let mut stop_at_3 = |done: usize, _| {
        calls += 1;
        if done == 3 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    match export::gif(&rec, &opts, &out, &mut stop_at_3) {
        Err(export::ExportError::Cancelled(3)) => {}
        other => panic!("expected a cancel after 3 frames, got {other:?}"),
    }
    assert_eq!(calls, 3, "no frame is rendered after the cancel");
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert!(left.is_empty(), "left behind: {left:?}");

    // A complete export, then a cancelled one over it: the complete one is still there.
    assert_eq!(
        export::gif(&rec, &opts, &out, &mut |_, _| ControlFlow::Continue(())).unwrap(),
        21
    );
    let before = std::fs::read(&out).unwrap();
    assert!(export::gif(&rec, &opts, &out, &mut |_, _| ControlFlow::Break(())).is_err());
    assert_eq!(std::fs::read(&out).unwrap(), before);
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    std::fs::remove_dir_all(dir).ok();
}

/// A cancelled PNG export keeps the frames it wrote, and only those.
#[test]
fn cancelled_png_export_keeps_the_frames_written() {
    let rec = break_recording();
    let dir = temp("cancel-png");
    let opts = ExportOptions {
        fps: 4.0,
        width: 64,
        height: 40,
        span: (0.0, 2.0),
    };
    let mut stop_at_2 = |done: usize, _| {
        if done == 2 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    assert!(matches!(
        export::png_sequence(&rec, &opts, &dir, &mut stop_at_2),
        Err(export::ExportError::Cancelled(2))
    ));
    assert!(dir.join("frame_00001.png").exists() && !dir.join("frame_00002.png").exists());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn bad_export_options_are_errors() {
    let rec = break_recording();
    for opts in [
        ExportOptions {
            fps: 0.0,
            width: 64,
            height: 40,
            span: (0.0, 1.0),
        },
        ExportOptions {
            fps: f64::NAN,
            width: 64,
            height: 40,
            span: (0.0, 1.0),
        },
        ExportOptions {
            fps: 10.0,
            width: 1,
            height: 40,
            span: (0.0, 1.0),
        },
        ExportOptions {
            fps: 10.0,
            width: 64,
            height: 40,
            span: (2.0, 1.0),
        },
    ] {
        assert!(
            export::frames(&rec, &opts, &mut |_, _| ControlFlow::Continue(())).is_err(),
            "{opts:?}"
        );
    }
}

fn run(cmd: &mut Command) -> (bool, String, String) {
    let out = cmd.output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

#[test]
fn simulate_writes_a_recording_that_verifies_and_an_edit_fails_with_its_location() {
    let dir = temp("sim");
    let file = dir.join("game.json");
    let (ok, stdout, err) = run(bin()
        .args([
            "simulate",
            "--rack",
            "nine-ball",
            "--shot",
            "0:8",
            "--shot",
            "30:2:0.2:-0.3",
            "--seed",
            "3",
            "--json",
            "--out",
        ])
        .arg(&file));
    assert!(ok, "{err}");
    let summary: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(summary.as_array().unwrap().len(), 2);
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok && stdout.contains("bit for bit"), "{stdout} {err}");
    // One value changed by hand: verify fails, says which event, exits non-zero.
    let mut rec = Recording::load(&file).unwrap();
    rec.events[1].after[0].velocity.x += 1e-12;
    rec.save(&file).unwrap();
    let (ok, _, err) = run(bin().arg("verify").arg(&file));
    assert!(!ok && err.contains("differs at event 1"), "{err}");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn commands_on_broken_files_fail_cleanly_naming_the_file() {
    let dir = temp("broken");
    let file = dir.join("empty.json");
    std::fs::write(&file, "").unwrap();
    for cmd in ["verify", "export"] {
        let (ok, _, err) = run(bin().arg(cmd).arg(&file).args(
            ["--gif", "/dev/null"]
                .iter()
                .take(if cmd == "export" { 2 } else { 0 }),
        ));
        assert!(
            !ok && err.contains("empty.json") && !err.contains("panicked"),
            "{cmd}: {err}"
        );
    }
    let (ok, _, err) = run(bin().args(["simulate", "--shot", "nonsense"]));
    assert!(!ok && !err.is_empty());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn killing_the_recorder_mid_game_leaves_the_last_complete_shot_on_disk() {
    let dir = temp("crash");
    let file = dir.join("game.json");
    let mut cmd = bin();
    cmd.args([
        "simulate",
        "--rack",
        "fifteen-ball",
        "--model",
        "paper",
        "--out",
    ])
    .arg(&file);
    for k in 0..4000 {
        cmd.args(["--shot", &format!("{}:{}", (k * 37) % 360, 1 + k % 5)]);
    }
    let mut child = cmd.stdout(std::process::Stdio::null()).spawn().unwrap();
    // Wait for a few saves (counted in the file, not timed: a loaded machine only takes
    // longer), then kill it while it is still playing and saving. Each save replaces the file
    // whole (a rename), so every read sees a complete recording.
    const SAVES: usize = 3;
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            panic!("the recorder ended ({status}) before {SAVES} saves");
        }
        if Recording::load(&file).is_ok_and(|rec| rec.inputs.len() >= SAVES) {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let rec = Recording::load(&file).expect("the file on disk is a complete recording");
    assert!(!rec.inputs.is_empty());
    // Whatever was on disk is whole: it ends with a shot that came to rest, and verifies.
    assert!(matches!(
        rec.verify().unwrap(),
        billiards_physics::recording::Verdict::Reproduced { .. }
    ));
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn shots_outside_the_contract_fail_naming_the_speed_and_the_limit() {
    use billiards_physics::limits::{MAX_SPEED, MIN_SPEED};
    let simulate =
        |shot: &str| run(bin().args(["simulate", "--rack", "nine-ball", "--shot", shot]));
    // The limits themselves are played.
    for speed in [0.0, MIN_SPEED, MAX_SPEED] {
        let (ok, _, err) = simulate(&format!("0:{speed:e}"));
        assert!(ok, "{speed}: {err}");
    }
    let up = |x: f64| f64::from_bits(x.to_bits() + 1);
    let down = |x: f64| f64::from_bits(x.to_bits() - 1);
    for speed in [up(MAX_SPEED), down(MIN_SPEED), 1e308, 1e-308, -1.0] {
        let out = bin()
            .args(["simulate", "--rack", "nine-ball", "--shot"])
            .arg(format!("0:{speed:e}"))
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success() && out.status.code() != Some(0),
            "{speed}"
        );
        assert!(
            err.contains("shot speed") && err.contains("m/s"),
            "{speed}: {err}"
        );
    }
    let (_, _, err) = simulate("0:1e308");
    assert!(
        err.contains("shot speed 1e308 m/s") && err.contains("from 1e-10 to 100 m/s"),
        "{err}"
    );
    // The help states the range.
    let (ok, help, _) = run(bin().args(["simulate", "--help"]));
    assert!(ok && help.contains("0 or from 1e-10 to 100"), "{help}");
}

#[test]
fn scenes_and_recordings_outside_the_contract_fail_naming_the_value() {
    let dir = temp("limits");
    let scene = dir.join("scene.json");
    std::fs::write(
        &scene,
        r#"{"rack": "nine_ball", "shots": [{"angle": 0, "speed": 1e308}]}"#,
    )
    .unwrap();
    let (ok, _, err) = run(bin().args(["simulate", "--scene"]).arg(&scene));
    assert!(!ok && err.contains("shot speed 1e308"), "{err}");
    // A recording whose strike was edited past the limit: refused on load, not replayed.
    let mut rec = break_recording();
    let file = dir.join("fast.json");
    if let recording::Action::Strike { shot, .. } = &mut rec.inputs[0].action {
        shot.speed = 1e308;
    }
    rec.save(&file).unwrap();
    for cmd in ["verify", "export"] {
        let (ok, _, err) = run(bin().arg(cmd).arg(&file).args(
            ["--gif", "/dev/null"]
                .iter()
                .take(if cmd == "export" { 2 } else { 0 }),
        ));
        assert!(
            !ok && err.contains("fast.json") && err.contains("shot speed 1e308"),
            "{cmd}: {err}"
        );
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn shots_count_from_one_in_simulate_and_export() {
    let dir = temp("shot-numbers");
    let file = dir.join("game.json");
    let (ok, stdout, err) = run(bin()
        .args([
            "simulate",
            "--rack",
            "nine-ball",
            "--shot",
            "0:8",
            "--shot",
            "90:1",
            "--out",
        ])
        .arg(&file));
    assert!(ok, "{err}");
    assert!(
        stdout.starts_with("shot 1:") && stdout.contains("\nshot 2:"),
        "{stdout}"
    );
    let export = |shot: &str| {
        run(bin()
            .arg("export")
            .arg(&file)
            .args(["--fps", "2", "--size", "32x18", "--shot", shot, "--gif"])
            .arg(dir.join(format!("shot{shot}.gif"))))
    };
    for good in ["1", "2"] {
        let (ok, _, err) = export(good);
        assert!(ok, "shot {good}: {err}");
    }
    for bad in ["0", "3"] {
        let (ok, _, err) = export(bad);
        assert!(
            !ok && err.contains(&format!("there is no shot {bad} (shots count from 1")),
            "shot {bad}: {err}"
        );
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn a_scratch_respots_the_cue_ball_by_the_rules_crate() {
    // From the head spot straight into the foot-left corner, with only the cue ball and a ball
    // on the head spot's right: the second shot starts from billiards_rules' spot.
    let table = Table::wpa_8ft();
    let r = Params::default().ball.radius;
    let blocker = table.head_spot() + Vec2::new(0.0, -0.01);
    let scene = serde_json::json!({
        "balls": [
            { "number": 0, "position": table.head_spot() + Vec2::new(0.4, 0.0) },
            { "number": 1, "position": blocker },
        ],
        "shots": [],
    });
    let dir = temp("respot");
    let scene_file = dir.join("scene.json");
    std::fs::write(&scene_file, scene.to_string()).unwrap();
    let corner = Vec2::new(table.length / 2.0, table.width / 2.0);
    let start = table.head_spot() + Vec2::new(0.4, 0.0);
    let angle = (corner - start).angle().to_degrees();
    let file = dir.join("game.json");
    let (ok, _, err) = run(bin()
        .arg("simulate")
        .arg("--scene")
        .arg(&scene_file)
        .args([
            "--shot",
            &format!("{angle}:3"),
            "--shot",
            "180:0.5",
            "--out",
        ])
        .arg(&file));
    assert!(ok, "{err}");
    let rec = Recording::load(&file).unwrap();
    let placed: Vec<Vec2> = rec
        .inputs
        .iter()
        .filter_map(|input| match input.action {
            recording::Action::Place { position, .. } => Some(position),
            _ => None,
        })
        .collect();
    let want = billiards_rules::head_string_spot(&table, r, &[blocker]).unwrap();
    assert_eq!(
        placed,
        vec![want],
        "the cue ball was respotted once, at the rule's spot"
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn simulate_a_nine_ball_game_prints_verdicts_and_verify_rejudges_them() {
    let dir = temp("nine");
    let file = dir.join("rack.json");
    // Rack seed 1: a break at 9 m/s that pockets nothing (seed 4 did until the cluster
    // impact's friction moved inside the impact, issue 49: it now pockets the 9).
    let (ok, stdout, err) = run(bin()
        .args(["simulate", "--game", "nine-ball", "--rack-seed", "1"])
        .args(["--shot", "0:9", "--shot", "10:2", "--call", "2:push-out"])
        .args(["--choice", "pass", "--shot", "45:2", "--out"])
        .arg(&file));
    assert!(ok, "{err}");
    assert!(
        stdout.contains("shot 1: A (break): legal; B to shoot (push out allowed)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("shot 2: B (push out): legal push out"),
        "{stdout}"
    );
    assert!(stdout.contains("A chooses PassBack"), "{stdout}");
    assert!(stdout.contains("shot 3: B: foul"), "{stdout}");
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok, "{err}");
    assert!(
        stdout.contains("3 verdicts of NineBall re-judged identically"),
        "{stdout}"
    );
    // A verdict edited in the log: verify names the shot and fails.
    let log = dir.join("rack.game.json");
    let text = std::fs::read_to_string(&log).unwrap();
    std::fs::write(&log, text.replacen("\"passes\"", "\"continues\"", 1)).unwrap();
    let (ok, _, err) = run(bin().arg("verify").arg(&file));
    assert!(!ok && err.contains("shot 1: logged"), "{err}");
    // A call this game does not use is refused with the rules' reason.
    let (ok, _, err) = run(bin().args([
        "simulate",
        "--game",
        "nine-ball",
        "--shot",
        "0:9",
        "--call",
        "1:9:foot-left",
    ]));
    assert!(
        !ok && err.contains("shot 1: NineBall has no called shots"),
        "{err}"
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn simulate_on_a_nine_foot_table_saves_the_table_and_a_bad_table_is_refused() {
    let dir = temp("table");
    let file = dir.join("nine.json");
    let (ok, stdout, err) = run(bin()
        .args(["simulate", "--game", "nine-ball", "--rack-seed", "2"])
        .args(["--table", "9ft-tight", "--rack-style", "template"])
        .args(["--shot", "0:11", "--out"])
        .arg(&file));
    assert!(ok, "{err}");
    assert!(stdout.contains("shot 1: A (break)"), "{stdout}");
    let rec = Recording::load(&file).unwrap();
    assert_eq!(rec.table.length, 100.0 * table::INCH);
    assert_eq!(rec.table.corner_mouth, 4.0 * table::INCH);
    // The template rack: the 1 exactly on the 9-ft table's foot spot.
    let one = rec.balls.iter().find(|b| b.number == 1).unwrap();
    assert_eq!(one.position, rec.table.foot_spot());
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok && stdout.contains("reproduced"), "{stdout} {err}");
    let (ok, _, err) = run(bin().args(["simulate", "--table", "6ft", "--shot", "0:9"]));
    assert!(!ok && err.contains("expected 7ft, 8ft or 9ft"), "{err}");
    let (ok, _, err) = run(bin().args(["simulate", "--table", "9ft-huge", "--shot", "0:9"]));
    assert!(
        !ok && err.contains("pockets expected wpa, wide or tight"),
        "{err}"
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn model_choices_reach_the_recording_and_need_the_spin_model() {
    let dir = temp("choices");
    let file = dir.join("throw.json");
    let (ok, _, err) = run(bin()
        .args([
            "simulate",
            "--rack",
            "nine-ball",
            "--shot",
            "1:3",
            "--ball-friction",
            "speed-dependent",
            "--cushion",
            "mathavan2010",
            "--end-mass",
            "0.004",
            "--out",
        ])
        .arg(&file));
    assert!(ok, "{err}");
    let rec = Recording::load(&file).unwrap();
    let Model::Spin(m) = rec.params.model else {
        panic!("spin model expected: {:?}", rec.params.model);
    };
    assert_eq!(m.ball_friction, BallFriction::ALCIATORE);
    assert_eq!(m.cushion, CushionModel::MATHAVAN_2010);
    assert_eq!(m.end_mass, Some(0.004));
    let (ok, _, err) = run(bin().args(["simulate", "--end-mass", "0"]));
    assert!(!ok && err.contains("end mass"), "{err}");
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok && stdout.contains("bit for bit"), "{stdout} {err}");
    let (ok, _, err) = run(bin().args([
        "simulate",
        "--model",
        "paper",
        "--ball-friction",
        "speed-dependent",
    ]));
    assert!(!ok && err.contains("need the spin model"), "{err}");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn elevation_reaches_every_shot_and_beyond_30_degrees_is_refused() {
    let dir = temp("elevation");
    let file = dir.join("swerve.json");
    let (ok, _, err) = run(bin()
        .args([
            "simulate",
            "--rack",
            "nine-ball",
            "--shot",
            "1:3:0.3:0",
            "--shot=-2:1",
            "--elevation",
            "20",
            "--out",
        ])
        .arg(&file));
    assert!(ok, "{err}");
    let rec = Recording::load(&file).unwrap();
    let strikes: Vec<Shot> = rec
        .events
        .iter()
        .filter_map(|e| match e.kind {
            EventKind::Strike { shot, .. } => Some(shot),
            _ => None,
        })
        .collect();
    assert_eq!(strikes.len(), 2);
    for s in &strikes {
        assert_eq!(s.elevation, 20f64.to_radians());
    }
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok && stdout.contains("bit for bit"), "{stdout} {err}");
    for bad in ["31", "-1", "x"] {
        let flag = format!("--elevation={bad}");
        let (ok, _, err) = run(bin().args(["simulate", "--shot", "0:1", &flag]));
        assert!(!ok && err.contains("elevation"), "{bad}: {err}");
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn simulate_a_snooker_frame_and_verify_rejudges_its_log() {
    let dir = temp("snooker");
    let file = dir.join("frame.json");
    let (ok, stdout, err) = run(bin()
        .args(["simulate", "--game", "snooker", "--computer", "easy,easy"])
        .args(["--players", "Ann,Bob", "--rack-seed", "3", "--out"])
        .arg(&file));
    assert!(ok, "{err}");
    assert!(
        stdout.contains("Ann (easy) breaks off against Bob (easy)"),
        "{stdout}"
    );
    assert!(stdout.contains("stroke 1: "), "{stdout}");
    // One name for every game's log: the frame's is `NAME.game.json`, as a rack's.
    let log = dir.join("frame.game.json");
    assert!(log.exists());
    assert!(!dir.join("frame.snooker.json").exists());
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok, "{err}");
    assert!(stdout.contains("reproduced bit for bit"), "{stdout}");
    assert!(
        stdout.contains("snooker verdicts re-judged identically"),
        "{stdout}"
    );
    // The first verdict's scores edited: verify names the stroke and fails.
    let text = std::fs::read_to_string(&log).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    json["strokes"][0]["verdict"]["scores"][0] = serde_json::json!(99);
    std::fs::write(&log, json.to_string()).unwrap();
    let (ok, _, err) = run(bin().arg("verify").arg(&file));
    assert!(!ok && err.contains("stroke 1: logged"), "{err}");
    // Kept under the name older builds gave it, the log is still found and re-judged.
    std::fs::write(&log, &text).unwrap();
    let old = dir.join("frame.snooker.json");
    std::fs::rename(&log, &old).unwrap();
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok, "{err}");
    assert!(
        stdout.contains("frame.snooker.json: ") && stdout.contains("re-judged identically"),
        "{stdout}"
    );
    // Pool's scripted shots are refused for snooker, with the reason.
    let (ok, _, err) = run(bin().args(["simulate", "--game", "snooker", "--shot", "0:3"]));
    assert!(!ok && err.contains("played by the computer"), "{err}");
    let (ok, _, err) =
        run(bin().args(["simulate", "--game", "snooker", "--computer", "hard,greedy"]));
    assert!(
        !ok && err.contains("snooker has computer levels only"),
        "{err}"
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn stress_runs_many_balls_with_the_checks_and_refuses_what_cannot_fit() {
    let (ok, out, err) = run(bin().args(["stress", "--balls", "300", "--time", "2", "--json"]));
    assert!(ok, "{err}");
    let r: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(r["balls"], 300);
    assert_eq!(r["frames"], 120);
    assert!(r["events"].as_u64().unwrap() > 100, "{out}");
    assert!(r["events_per_second"].as_f64().unwrap() > 0.0);
    // Frictionless and elastic: the energy stays; no two balls ever overlap.
    let (e0, e1) = (
        r["energy"][0].as_f64().unwrap(),
        r["energy"][1].as_f64().unwrap(),
    );
    assert!(e0 > 1.0 && (e1 - e0).abs() < 1e-9 * e0, "{e0} -> {e1}");
    assert_eq!(r["worst_overlap"], 0.0);
    assert_eq!(r["at_rest"], false);

    let (ok, out, err) = run(bin().args(["stress", "--balls", "50", "--friction", "--time", "30"]));
    assert!(ok, "{err}");
    assert!(out.contains("50 balls (with friction)"), "{out}");
    assert!(out.contains("every ball at rest"), "{out}");

    for (args, message) in [
        (&["--balls", "0"][..], "needs at least 1 ball, got 0"),
        (
            &["--balls", "10001"],
            "10001 balls is more than the stress scene's maximum of 10000",
        ),
        (
            &["--balls", "2000", "--scale", "1"],
            "2000 balls do not fit on a 2.34 x 1.17 m table",
        ),
        (&["--balls", "16", "--scale=-2"], "table scale -2 must be"),
        (
            &["--balls", "16", "--time", "0"],
            "--time 0: simulated seconds",
        ),
    ] {
        let (ok, out, err) = run(bin().arg("stress").args(args));
        assert!(!ok, "{args:?} was accepted: {out}");
        assert!(err.contains(message), "{args:?}: {err}");
    }
}

#[test]
fn verify_given_a_rules_log_says_so_and_names_the_recording() {
    let dir = temp("verify-log");
    let file = dir.join("rack.json");
    let (ok, _, err) = run(bin()
        .args(["simulate", "--game", "nine-ball", "--rack-seed", "4"])
        .args(["--shot", "0:8", "--out"])
        .arg(&file));
    assert!(ok, "{err}");
    let log = dir.join("rack.game.json");
    assert!(log.exists());
    // The log itself, by its name and content.
    let (ok, _, err) = run(bin().arg("verify").arg(&log));
    let want = format!(
        "{} is a rules log, not a recording: verify the recording beside it, {}",
        log.display(),
        file.display()
    );
    assert!(!ok && err.contains(&want), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    // A log under another name is known by its content.
    let renamed = dir.join("copy.json");
    std::fs::copy(&log, &renamed).unwrap();
    let (ok, _, err) = run(bin().arg("verify").arg(&renamed));
    assert!(
        !ok && err.contains("copy.json is a rules log, not a recording"),
        "{err}"
    );
    // A snooker frame's log, under its old name, likewise.
    let frame = dir.join("frame.json");
    let (ok, _, err) = run(bin()
        .args(["simulate", "--game", "snooker", "--computer", "easy,easy"])
        .args(["--rack-seed", "5", "--out"])
        .arg(&frame));
    assert!(ok, "{err}");
    let old = dir.join("frame.snooker.json");
    std::fs::rename(dir.join("frame.game.json"), &old).unwrap();
    let (ok, _, err) = run(bin().arg("verify").arg(&old));
    assert!(
        !ok && err.contains("is a rules log, not a recording: verify the recording beside it")
            && err.contains("frame.json"),
        "{err}"
    );
    // The recording itself still verifies.
    let (ok, _, err) = run(bin().arg("verify").arg(&file));
    assert!(ok, "{err}");
    std::fs::remove_dir_all(dir).ok();
}
