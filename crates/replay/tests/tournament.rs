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
        let o = bin()
            .args(common)
            .args(["--games", "4", "--seed", "9"])
            .args(extra)
            .arg("--out")
            .arg(&path)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        path
    };
    let whole = run(&[], "whole.json");
    let a = run(&["--shard", "1/2"], "a.json");
    let b = run(&["--shard", "2/2"], "b.json");
    let merged = dir.join("merged.json");
    let o = bin()
        .args(["tournament", "--merge"])
        .arg(&a)
        .arg(&b)
        .arg("--out")
        .arg(&merged)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("4 of 4 games"));
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
