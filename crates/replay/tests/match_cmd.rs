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
