//! `billiards-cli tournament`: bad input is a clear error with exit status 2, and the merge
//! of two shards is the whole tournament.

use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-tour-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `billiards-cli ARGS --out OUT`, which must succeed; its report.
fn played(args: &[&str], out: &PathBuf) -> String {
    let o = bin().args(args).arg("--out").arg(out).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// `tournament --merge a b --out merged`, which must succeed; its report.
fn merge(a: &PathBuf, b: &PathBuf, merged: &PathBuf) -> String {
    let o = bin()
        .args(["tournament", "--merge"])
        .arg(a)
        .arg(b)
        .arg("--out")
        .arg(merged)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn bad_input_exits_2_with_a_sentence_and_no_panic() {
    for (args, says) in [
        (&["--shard", "3/2"][..], "1 <= K <= M"),
        (&["--shard", "0/2"][..], "1 <= K <= M"),
        (&["--players", "hard,pro"][..], "unknown player \"pro\""),
        (&["--players", "hard"][..], "expected A,B"),
        (&["--game", "free-play"][..], "free play has no winner"),
        (
            &["--merge", "/nonexistent/results.json"][..],
            "/nonexistent/results.json",
        ),
    ] {
        let out = bin().arg("tournament").args(args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn two_shards_merged_are_the_whole_tournament() {
    let dir = temp("shards");
    let common = [
        "tournament",
        "--game",
        "nine-ball",
        "--players",
        "greedy,greedy",
    ];
    let run = |extra: &[&str], out: &str| {
        let path = dir.join(out);
        let args = [&common[..], &["--games", "4", "--seed", "9"], extra].concat();
        played(&args, &path);
        path
    };
    let whole = run(&[], "whole.json");
    let a = run(&["--shard", "1/2"], "a.json");
    let b = run(&["--shard", "2/2"], "b.json");
    let merged = dir.join("merged.json");
    assert!(merge(&a, &b, &merged).contains("4 of 4 games"));
    // The same racks, game for game (decision times aside).
    let racks = |p: &PathBuf| {
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap();
        v["matches"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| {
                (
                    r["index"].clone(),
                    r["winner"].clone(),
                    r["strokes"].clone(),
                    r["seed"].clone(),
                )
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(racks(&whole).len(), 4);
    assert_eq!(racks(&whole), racks(&merged));
    // A shard merged twice is refused.
    let o = bin()
        .args(["tournament", "--merge"])
        .arg(&a)
        .arg(&a)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("the seeds overlap"));
}

#[test]
fn a_snooker_tournament_reports_frames_breaks_and_centuries() {
    let out = bin()
        .args(["tournament", "--game", "snooker", "--players", "easy,easy"])
        .args(["--games", "2", "--seed", "4"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("snooker, best of 1, easy vs easy: 2 of 2 games"),
        "{stdout}"
    );
    for column in [
        "mean break",
        "highest",
        "centuries",
        "fouls/shot",
        "decision",
    ] {
        assert!(stdout.contains(column), "{column}: {stdout}");
    }
    let out = bin()
        .args([
            "tournament",
            "--game",
            "snooker",
            "--players",
            "hard,greedy",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("computer levels only"), "{err}");
}

/// Every game's tournament is the same path (issue 50): snooker's frames and carom's games
/// shard and merge as pool's racks do, each match with its figures from the interface.
#[test]
fn every_game_shards_and_merges_into_the_whole_tournament() {
    let dir = temp("every-game");
    let without_times = |p: &PathBuf| {
        let mut v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap();
        for m in v["matches"].as_array_mut().unwrap() {
            for player in m["players"].as_array_mut().unwrap() {
                let player = player.as_object_mut().unwrap();
                player.remove("decision_secs");
                player.remove("max_decision_secs");
            }
        }
        v.as_object_mut().unwrap().remove("shard");
        v
    };
    for (game, length, columns) in [
        (
            "snooker",
            "1",
            &["pts/frame", "mean break", "centuries"][..],
        ),
        ("three-cushion", "2", &["average", "high run"][..]),
    ] {
        let common = [
            "tournament",
            "--game",
            game,
            "--players",
            "medium,easy",
            "--games",
            "3",
            "--seed",
            "8",
            "--length",
            length,
        ];
        let run = |extra: &[&str], name: &str| {
            let path = dir.join(format!("{game}-{name}.json"));
            let report = played(&[&common[..], extra].concat(), &path);
            (path, report)
        };
        let (whole, report) = run(&[], "whole");
        for column in columns {
            assert!(report.contains(column), "{game}: {column}: {report}");
        }
        let (a, _) = run(&["--shard", "1/2"], "a");
        let (b, _) = run(&["--shard", "2/2"], "b");
        let merged = dir.join(format!("{game}-merged.json"));
        assert!(merge(&a, &b, &merged).contains("3 of 3 games"), "{game}");
        assert_eq!(without_times(&whole), without_times(&merged), "{game}");
        // Each match has a result: a winner, or level on points at the stroke limit.
        let v = without_times(&whole);
        for m in v["matches"].as_array().unwrap() {
            assert!(
                m["winner"].is_u64() || m["points"][0] == m["points"][1],
                "{game}: {m}"
            );
        }
    }
    std::fs::remove_dir_all(dir).ok();
}
