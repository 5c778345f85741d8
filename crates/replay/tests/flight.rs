//! Balls in the air on the command line: `--shot`'s elevation field, the summary's flight
//! events (text and `--json`), a jump over a blocking ball from a scene file, and its
//! recording reproduced bit for bit by `verify`.

mod common;

use billiards_physics::recording::Recording;
use billiards_physics::*;
use common::*;

/// The cue ball 15 cm (centre to centre) behind a blocking ball, spin model.
const JUMP_SCENE: &str = r#"{
  "params": { "model": { "kind": "spin" } },
  "balls": [
    { "number": 0, "position": { "x": -0.5, "y": 0.0 } },
    { "number": 1, "position": { "x": -0.35, "y": 0.0 } }
  ]
}"#;

/// `simulate --json` of `shot` on the jump scene, recorded: the summary and the recording.
fn jump(dir: &std::path::Path, shot: &str) -> (serde_json::Value, Recording) {
    let (scene, file) = (dir.join("jump.json"), dir.join(format!("{shot}.rec.json")));
    std::fs::write(&scene, JUMP_SCENE).unwrap();
    let (ok, stdout, err) = run(bin()
        .args(["simulate", "--json", "--shot", shot, "--scene"])
        .arg(&scene)
        .arg("--out")
        .arg(&file));
    assert!(ok, "{err}");
    let (ok, out, err) = run(bin().arg("verify").arg(&file));
    assert!(ok && out.contains("bit for bit"), "{shot}: {out} {err}");
    (
        serde_json::from_str(&stdout).unwrap(),
        Recording::load(&file).unwrap(),
    )
}

/// 4 m/s at 50 degrees (above the 2.78 m/s this distance needs at 50 degrees; the physics'
/// tests/flight.rs): the summary lists the take-off at the strike and the cue ball's first
/// touchdown beyond the blocker; in the recording the blocker is in no event (no contact, it
/// never moves) until the cue ball has landed; `verify` reproduces the flight bit for bit. At 2 m/s the cue ball
/// comes down short of it and hits it.
#[test]
fn a_jump_over_a_blocking_ball_passes_over_it_lands_beyond_and_verifies() {
    let dir = temp("jump");
    let (summary, rec) = jump(&dir, "0:4:0:0:50");
    let flight = summary[0]["flight"].as_array().unwrap();
    assert_eq!(flight[0]["kind"], "take-off", "{flight:#?}");
    assert_eq!(
        (flight[0]["ball"].as_u64(), flight[0]["time"].as_f64()),
        (Some(0), Some(0.0))
    );
    assert!(flight[0]["vertical"].as_f64().unwrap() > 1.0);
    let down = &flight[1];
    assert!(
        down["kind"] == "bounce" || down["kind"] == "landing",
        "{down}"
    );
    let x = down["position"]["x"].as_f64().unwrap();
    let r = Params::default().ball.radius;
    assert!(
        x > -0.35 + 2.0 * r,
        "first touchdown beyond the blocker: {x}"
    );
    let landed = flight.iter().find(|f| f["kind"] == "landing");
    let down_at = landed.expect("it comes down")["time"].as_f64().unwrap();
    // Until it is down (the strike is at t = 0 in the recording): it comes back from the
    // foot cushion later.
    let touched = |rec: &Recording, until: f64| {
        rec.events
            .iter()
            .take_while(|e| e.time <= until)
            .any(|e| e.kind.balls().any(|b| b == 1))
    };
    assert!(
        !touched(&rec, down_at),
        "the cue ball passed over the blocker"
    );
    let (summary, rec) = jump(&dir, "0:2:0:0:50");
    assert!(touched(&rec, 1.0), "too slow: it hits the blocker");
    let flight = summary[0]["flight"].as_array().unwrap();
    // Its first touchdown is short of the blocker's centre.
    assert!(flight[1]["position"]["x"].as_f64().unwrap() < -0.35);
    std::fs::remove_dir_all(dir).ok();
}

/// The text summary lists each flight event under its shot, and a level shot none.
#[test]
fn the_text_summary_lists_take_off_bounces_and_landing() {
    let dir = temp("jump-text");
    let scene = dir.join("jump.json");
    std::fs::write(&scene, JUMP_SCENE).unwrap();
    let (ok, out, err) = run(bin()
        .args([
            "simulate",
            "--shot",
            "0:4:0:0:50",
            "--shot",
            "90:1",
            "--scene",
        ])
        .arg(&scene));
    assert!(ok, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].starts_with("shot 1:"), "{out}");
    assert!(lines[1].contains("ball 0 take-off at 0.000 s"), "{out}");
    assert!(lines.iter().any(|l| l.contains("ball 0 bounce")), "{out}");
    let second = lines.iter().position(|l| l.starts_with("shot 2:")).unwrap();
    assert!(lines[second - 1].contains("ball 0 landing"), "{out}");
    assert_eq!(second + 1, lines.len(), "a level shot has no flight: {out}");
    std::fs::remove_dir_all(dir).ok();
}

/// The fifth field of `--shot` is the cue elevation in degrees: it wins over `--elevation`
/// for its shot, and outside 0..85 degrees it is refused by the contract (limits.rs), naming
/// the elevation and the range, without a panic.
#[test]
fn a_shots_own_elevation_wins_and_beyond_85_degrees_is_refused() {
    let dir = temp("shot-elevation");
    let file = dir.join("rec.json");
    let (ok, _, err) = run(bin()
        .args(["simulate", "--rack", "nine-ball", "--shot", "0:1:0:0:40"])
        .args(["--shot", "0:1", "--elevation", "20", "--out"])
        .arg(&file));
    assert!(ok, "{err}");
    let rec = Recording::load(&file).unwrap();
    let elevations: Vec<f64> = rec
        .events
        .iter()
        .filter_map(|e| match e.kind {
            EventKind::Strike { shot, .. } => Some(shot.elevation),
            _ => None,
        })
        .collect();
    assert_eq!(elevations, [40f64.to_radians(), 20f64.to_radians()]);
    for bad in [
        "0:1:0:0:86",
        "0:1:0:0:-1",
        "0:1:0:0:NaN",
        "0:1:0:0:x",
        "0:1:0:0:5:5",
    ] {
        let (ok, _, err) = run(bin().args(["simulate", "--shot", bad]));
        assert!(!ok && !err.contains("panicked"), "{bad}: {err}");
        let named = err.contains("elevation") || err.contains("expected ANGLE_DEG");
        assert!(named || err.contains("\"x\""), "{bad}: {err}");
    }
    let (_, _, err) = run(bin().args(["simulate", "--shot", "0:1:0:0:86"]));
    assert!(err.contains("86 degrees: from 0 to 85 degrees"), "{err}");
    std::fs::remove_dir_all(dir).ok();
}

/// A scene file's ball in the air (`"flights"`): `simulate` records it as an input, the
/// summary lists its bounces and landing under the first shot, and `verify` reproduces it bit for bit.
#[test]
fn a_scene_ball_in_the_air_lands_in_the_summary_and_verifies() {
    let dir = temp("scene-flight");
    let (scene, file) = (dir.join("drop.json"), dir.join("drop.rec.json"));
    let text = r#"{
      "params": { "model": { "kind": "spin" } },
      "balls": [
        { "number": 0, "position": { "x": -0.5, "y": 0.0 } },
        { "number": 1, "position": { "x": 0.3, "y": 0.2 } }
      ],
      "flights": [ { "ball": 1, "height": 0.2 } ]
    }"#;
    std::fs::write(&scene, text).unwrap();
    let (ok, stdout, err) = run(bin()
        .args(["simulate", "--json", "--shot", "0:1", "--scene"])
        .arg(&scene)
        .arg("--out")
        .arg(&file));
    assert!(ok, "{err}");
    let summary: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let flight = summary[0]["flight"].as_array().unwrap();
    let down: Vec<_> = flight.iter().filter(|f| f["ball"] == 1).collect();
    // It comes down from 0.2 m at rest sqrt(2 h / g) later (the scene's default gravity),
    // bounces while the slate's rebound rises 5 mm or more, and lands.
    assert_eq!(down[0]["kind"], "bounce", "{flight:#?}");
    let t = down[0]["time"].as_f64().unwrap();
    let g = Params::default().gravity;
    assert!((t - (0.4 / g).sqrt()).abs() < 1e-12, "{t}");
    assert_eq!(down.last().unwrap()["kind"], "landing", "{flight:#?}");
    let (ok, out, err) = run(bin().arg("verify").arg(&file));
    assert!(ok && out.contains("bit for bit"), "{out} {err}");
    std::fs::remove_dir_all(dir).ok();
}
