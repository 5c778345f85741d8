//! `billiards-cli` with `--game ten-ball` (WPA section 9): computers play whole racks to a
//! winner, and a scripted rack is judged, logged and re-judged by `verify`.

use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-ten-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn wpa_9_5_a_ten_ball_tournament_plays_every_rack_to_a_winner() {
    let dir = temp("tour");
    let out = dir.join("results.json");
    // The greedy player and the easiest searching level: both must call every shot.
    let o = bin()
        .args([
            "tournament",
            "--game",
            "ten-ball",
            "--players",
            "easy,greedy",
        ])
        .args(["--games", "4", "--seed", "3", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        stdout.contains("10-ball, race to 1, easy vs greedy: 4 of 4 games"),
        "{stdout}"
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let racks = v["matches"].as_array().unwrap();
    assert_eq!(racks.len(), 4);
    for r in racks {
        // Every rack ends with a winner: the called 10 made (9.5) or three fouls (9.11).
        assert!(r["winner"].is_u64(), "{r}");
        let reason = r["reason"].as_str().unwrap();
        assert!(
            reason == "the called 10 was pocketed in the called pocket"
                || reason == "three fouls in a row",
            "{reason}"
        );
        assert!(
            r["strokes"].as_u64().unwrap() >= 2,
            "no win on the break (9.9): {r}"
        );
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn wpa_9_3_9_5_simulate_a_ten_ball_rack_logs_calls_and_verify_rejudges_them() {
    let dir = temp("sim");
    let file = dir.join("rack.json");
    // Rack seed 11 broken at 12 m/s, half a degree left of the 1: only the 10 drops.
    let (ok, stdout, err) = run(bin()
        .args(["simulate", "--game", "ten-ball", "--rack-seed", "11"])
        .args([
            "--shot",
            "0.5:12",
            "--shot",
            "10:2",
            "--call",
            "2:1:foot-left",
        ])
        .arg("--out")
        .arg(&file));
    assert!(ok, "{err}");
    assert!(stdout.contains("10-ball, rack seed 11: "), "{stdout}");
    // WPA 9, 9.9: the 10 made on a legal break is spotted, no win, the breaker continues.
    assert!(
        stdout.contains(
            "stroke 1: A: legal: the 10 in the head-right corner; the 10 is spotted; A to \
             shoot (push out allowed)"
        ),
        "{stdout}"
    );
    assert!(stdout.contains("stroke 2: A: "), "{stdout}");
    assert!(!stdout.contains("game over"), "{stdout}");
    let (ok, stdout, err) = run(bin().arg("verify").arg(&file));
    assert!(ok, "{err}");
    assert!(
        stdout.contains("2 10-ball verdicts re-judged identically"),
        "{stdout}"
    );
    // WPA 9: no ball is called on the break.
    let (ok, _, err) = run(bin().args([
        "simulate",
        "--game",
        "ten-ball",
        "--shot",
        "0:9",
        "--call",
        "1:1:foot-left",
    ]));
    assert!(
        !ok && err.contains("stroke 1: TenBall has no call on the break"),
        "{err}"
    );
    std::fs::remove_dir_all(dir).ok();
}

fn run(cmd: &mut Command) -> (bool, String, String) {
    let o = cmd.output().unwrap();
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}
