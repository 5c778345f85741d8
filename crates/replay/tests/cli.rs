//! The command line, end to end: simulate and verify, broken files, the physics contract's
//! limits, tables, models and elevation, the stress run.

mod common;

use billiards_physics::recording::Recording;
use billiards_physics::*;
use common::*;

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
fn simulate_on_a_nine_foot_table_saves_the_table_and_a_bad_table_is_refused() {
    let dir = temp("table");
    let file = dir.join("nine.json");
    let (ok, stdout, err) = run(bin()
        .args(["simulate", "--game", "nine-ball", "--rack-seed", "2"])
        .args(["--table", "9ft-tight", "--rack-style", "template"])
        .args(["--shot", "0:11", "--out"])
        .arg(&file));
    assert!(ok, "{err}");
    assert!(stdout.contains("stroke 1: A: legal"), "{stdout}");
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
fn elevation_reaches_every_shot_and_beyond_85_degrees_is_refused() {
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
    for bad in ["86", "-1", "x"] {
        let flag = format!("--elevation={bad}");
        let (ok, _, err) = run(bin().args(["simulate", "--shot", "0:1", &flag]));
        assert!(!ok && err.contains("elevation"), "{bad}: {err}");
    }
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
