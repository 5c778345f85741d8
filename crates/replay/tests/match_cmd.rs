//! `billiards-cli match --game ID`: any game of the catalog played to the end between two
//! computers through the one game interface (issue 50), three-cushion among them.

use std::process::Command;

fn cli(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn three_cushion_is_played_to_its_distance_between_computers() {
    let (ok, out, err) = cli(&[
        "match",
        "--game",
        "three-cushion",
        "--players",
        "medium,medium",
        "--length",
        "2",
        "--seed",
        "4",
    ]);
    assert!(ok, "{err}");
    // UMB Art. 83: a point needs three cushions before the second ball; each is said.
    assert!(out.contains("Point: the"), "{out}");
    let last = out.lines().last().unwrap();
    assert!(last.contains("wins the match"), "{last}");
    assert!(last.contains("three-cushion to 2"), "{last}");
}

#[test]
fn every_game_id_is_known_and_a_wrong_one_is_refused_with_the_list() {
    let (ok, _, err) = cli(&["match", "--game", "pinball"]);
    assert!(!ok);
    assert!(
        err.contains("three-cushion") && err.contains("nine-ball"),
        "{err}"
    );
    let (ok, _, err) = cli(&["match", "--game", "snooker", "--length", "2"]);
    assert!(!ok, "snooker's best-of must be odd (WPBSA 2.1)");
    assert!(err.contains("odd"), "{err}");
}

#[test]
fn tournament_and_simulate_take_three_cushion() {
    let (ok, out, err) = cli(&[
        "tournament",
        "--game",
        "three-cushion",
        "--players",
        "medium,easy",
        "--games",
        "2",
        "--length",
        "2",
    ]);
    assert!(ok, "{err}");
    assert!(
        out.contains("three-cushion, points to 2, medium vs easy: 2 of 2 games"),
        "{out}"
    );
    // Every game has a winner: the wins add up to the games.
    let wins: u64 = out
        .lines()
        .filter(|l| l.starts_with("medium ") || l.starts_with("easy "))
        .map(|l| l.split_whitespace().nth(1).unwrap().parse::<u64>().unwrap())
        .sum();
    assert_eq!(wins, 2, "{out}");
    // Pool-only players are refused with a reason.
    let (ok, _, err) = cli(&[
        "tournament",
        "--game",
        "three-cushion",
        "--players",
        "greedy,easy",
    ]);
    assert!(
        !ok && err.contains("three-cushion has computer levels only"),
        "{err}"
    );
    // Scripted strokes: the opening stroke that misses the red is a foul (UMB 3.3), and
    // the recording verifies bit for bit.
    let dir = std::env::temp_dir().join(format!("carom-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("carom.json");
    let (ok, out, err) = cli(&[
        "simulate",
        "--game",
        "three-cushion",
        "--shot",
        "90:2",
        "--shot",
        "120:4",
        "--out",
        file.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    assert!(
        out.contains("stroke 1: A: Foul: the opening stroke"),
        "{out}"
    );
    assert!(out.contains("stroke 2: B:"), "the yellow plays next: {out}");
    let (ok, out, err) = cli(&["verify", file.to_str().unwrap()]);
    assert!(ok && out.contains("bit for bit"), "{out}{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A reader that stops early (`billiards-cli match ... | head -1`) ends the command quietly
/// with a broken pipe's status (141, as a Unix tool killed by SIGPIPE), never a panic. The
/// pipe's reading end is closed before the command starts, so its first line meets it.
#[test]
fn a_reader_that_stops_early_is_no_panic() {
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
        .args(["match", "--game", "nine-ball", "--players", "easy,easy"])
        .args(["--length", "1", "--seed", "1"])
        .stdout(writer)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(out.status.code(), Some(141), "{err}");
}
