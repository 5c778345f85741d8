//! The batch commands split into shards: the merge of the shards is one process's result bit
//! for bit, and a merge of the wrong files is refused with a sentence naming the file (exit
//! status 2, no panic).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-shards-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Small runs of each batch command (the tournament is tested in tournament.rs).
const COMMANDS: [(&str, &[&str]); 3] = [
    (
        "breaks",
        &["--breaks", "5", "--cue", "box,side", "--speed", "10:12,8"],
    ),
    ("soak", &["--scenes", "12", "--first-seed", "100"]),
    ("study", &["--grid", "6x3", "--samples", "4"]),
];

fn run(cmd: &str, args: &[&str], extra: &[&str], out: &Path) -> Output {
    let o = bin()
        .arg(cmd)
        .args(args)
        .args(extra)
        .arg("--out")
        .arg(out)
        .env_remove("BILLIARDS_FAIL_ONCE_DIR")
        .output()
        .unwrap();
    assert!(o.status.success(), "{cmd} {extra:?}: {o:?}");
    o
}

fn merge(cmd: &str, files: &[&Path], out: Option<&Path>) -> Output {
    let mut c = bin();
    c.arg(cmd).arg("--merge").args(files);
    if let Some(out) = out {
        c.arg("--out").arg(out);
    }
    c.output().unwrap()
}

fn refused(o: &Output, says: &str) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains(says), "wanted {says:?} in: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn three_shards_merged_are_one_process_bit_for_bit() {
    for (cmd, args) in COMMANDS {
        let dir = temp(cmd);
        let whole = dir.join("whole.json");
        let w = run(cmd, args, &[], &whole);
        let shards: Vec<PathBuf> = (1..=3)
            .map(|k| {
                let p = dir.join(format!("{k}.json"));
                run(cmd, args, &["--shard", &format!("{k}/3")], &p);
                p
            })
            .collect();
        // In any order.
        let merged = dir.join("merged.json");
        let m = merge(
            cmd,
            &[&shards[2], &shards[0], &shards[1]],
            Some(merged.as_path()),
        );
        assert!(m.status.success(), "{cmd}: {m:?}");
        assert_eq!(
            std::fs::read(&whole).unwrap(),
            std::fs::read(&merged).unwrap(),
            "{cmd}: the merged JSON differs from one process's"
        );
        assert_eq!(w.stdout, m.stdout, "{cmd}: the reports differ");
        std::fs::remove_dir_all(dir).ok();
    }
}

#[test]
fn a_merge_of_the_wrong_files_is_refused_with_the_reason() {
    let dir = temp("refusals");
    let (cmd, args) = COMMANDS[0];
    let s: Vec<PathBuf> = (1..=3)
        .map(|k| {
            let p = dir.join(format!("{k}.json"));
            run(cmd, args, &["--shard", &format!("{k}/3")], &p);
            p
        })
        .collect();
    let (a, b, c) = (s[0].as_path(), s[1].as_path(), s[2].as_path());

    // Cut short while written or copied.
    let text = std::fs::read_to_string(b).unwrap();
    let cut = dir.join("cut.json");
    std::fs::write(&cut, &text[..text.len() / 2]).unwrap();
    refused(&merge(cmd, &[a, &cut, c], None), "cut.json: truncated");
    std::fs::write(&cut, "").unwrap();
    refused(&merge(cmd, &[a, &cut, c], None), "cut.json: truncated");

    // Another command's shard.
    let soak = dir.join("soak.json");
    run("soak", &["--scenes", "3"], &["--shard", "2/3"], &soak);
    refused(
        &merge(cmd, &[a, &soak, c], None),
        "soak.json: a result of `soak`, not of `breaks`",
    );

    // Other arguments: another seed, more breaks.
    let other = dir.join("other.json");
    run(cmd, args, &["--shard", "2/3", "--seed", "7"], &other);
    refused(
        &merge(cmd, &[a, &other, c], None),
        "other.json: another run than",
    );
    refused(&merge(cmd, &[a, &other, c], None), "seed: 7 against 1");

    // Another split of the seeds, a shard twice, a shard missing.
    let half = dir.join("half.json");
    run(cmd, args, &["--shard", "2/2"], &half);
    refused(
        &merge(cmd, &[a, &half, c], None),
        "half.json: shard 2/2, but",
    );
    refused(&merge(cmd, &[a, b, a, c], None), "shard 1/3 is also");
    refused(&merge(cmd, &[a, c], None), "shards missing (of 3): 2");

    // A whole run is not a shard; a merged file cannot be merged again.
    let whole = dir.join("whole.json");
    run(cmd, args, &[], &whole);
    refused(&merge(cmd, &[&whole], None), "whole.json: a whole run");

    // A shard whose counts were altered: not its shard's items.
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["rows"][0]["stats"]["breaks"] = serde_json::json!(1);
    let altered = dir.join("altered.json");
    std::fs::write(&altered, v.to_string()).unwrap();
    refused(
        &merge(cmd, &[a, &altered, c], None),
        "altered.json: shard 2/3 is incomplete or altered",
    );

    // Not JSON at all; not there at all.
    let junk = dir.join("junk.json");
    std::fs::write(&junk, "hello").unwrap();
    refused(&merge(cmd, &[a, &junk, c], None), "junk.json: not a result");
    refused(
        &merge(cmd, &[a, Path::new("/nonexistent/2.json"), c], None),
        "/nonexistent/2.json",
    );

    // The right files still merge.
    assert!(merge(cmd, &[c, b, a], None).status.success());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn a_tournament_shard_that_lost_games_is_refused() {
    let dir = temp("tournament");
    let args = ["--players", "greedy,greedy", "--games", "4", "--seed", "3"];
    let (a, b) = (dir.join("a.json"), dir.join("b.json"));
    run("tournament", &args, &["--shard", "1/2"], &a);
    run("tournament", &args, &["--shard", "2/2"], &b);
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&b).unwrap()).unwrap();
    v["matches"].as_array_mut().unwrap().pop();
    std::fs::write(&b, v.to_string()).unwrap();
    refused(
        &merge("tournament", &[&a, &b], None),
        "b.json: shard 2/2 is incomplete or altered: 1 of its 2 games",
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn the_fail_once_hook_fails_a_shard_once_then_lets_it_run() {
    let dir = temp("fail-once");
    let (cmd, args) = COMMANDS[1];
    let out = dir.join("1.json");
    let go = || {
        bin()
            .arg(cmd)
            .args(args)
            .args(["--shard", "1/2", "--out"])
            .arg(&out)
            .env("BILLIARDS_FAIL_ONCE_DIR", &dir)
            .output()
            .unwrap()
    };
    let first = go();
    assert_eq!(first.status.code(), Some(1), "{first:?}");
    assert!(String::from_utf8_lossy(&first.stderr).contains("failing on purpose"));
    assert!(!out.exists(), "no result from the failed run");
    assert!(dir.join("soak-1-of-2").exists());
    let second = go();
    assert!(second.status.success(), "{second:?}");
    assert!(out.exists());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn the_study_heat_map_of_the_merge_is_one_process_s() {
    let dir = temp("svg");
    let args = ["--grid", "5x3", "--samples", "3"];
    let svg = |name: &str| dir.join(name);
    let o = bin()
        .arg("study")
        .args(args)
        .arg("--svg")
        .arg(svg("whole.svg"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{o:?}");
    let shards: Vec<PathBuf> = (1..=2)
        .map(|k| {
            let p = dir.join(format!("{k}.json"));
            run("study", &args, &["--shard", &format!("{k}/2")], &p);
            p
        })
        .collect();
    let o = bin()
        .args(["study", "--merge"])
        .args(&shards)
        .arg("--svg")
        .arg(svg("merged.svg"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{o:?}");
    let whole = std::fs::read_to_string(svg("whole.svg")).unwrap();
    assert_eq!(whole, std::fs::read_to_string(svg("merged.svg")).unwrap());
    // The table, 15 cells, the ball, the scale's 11 steps.
    assert!(whole.matches("<rect").count() >= 1 + 1 + 15 + 11, "{whole}");
    assert!(whole.contains("P(the 1 into foot-left)"));
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn one_shard_of_one_merges_to_the_whole_run() {
    let dir = temp("one-of-one");
    let (cmd, args) = COMMANDS[1];
    let (whole, one, merged) = (dir.join("w.json"), dir.join("1.json"), dir.join("m.json"));
    run(cmd, args, &[], &whole);
    run(cmd, args, &["--shard", "1/1"], &one);
    assert!(merge(cmd, &[&one], Some(merged.as_path())).status.success());
    assert_eq!(
        std::fs::read(&whole).unwrap(),
        std::fs::read(&merged).unwrap()
    );
    std::fs::remove_dir_all(dir).ok();
}
