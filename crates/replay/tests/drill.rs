//! `billiards-cli drill`, end to end: a standard drill played by the computer prints its
//! tries and the tally (as JSON with `--json`); a bad drill file fails with its reason.

use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
}

#[test]
fn a_drill_prints_its_tries_and_score() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/drills/01-stop-shot.json"
    );
    let out = bin()
        .args(["drill", file, "--tries", "2", "--json"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.starts_with("Stop shot:"), "{text}");
    assert_eq!(text.matches("try ").count(), 2, "{text}");
    let last = text.lines().last().unwrap();
    let score: serde_json::Value = serde_json::from_str(last).unwrap();
    assert_eq!(score["tries"], 2);
    assert!(score["best"].as_f64().unwrap() > 0.0, "{text}");
}

#[test]
fn a_bad_drill_file_fails_with_its_reason() {
    let dir = std::env::temp_dir().join(format!("billiards-drill-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("bad.json");
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/drills/01-stop-shot.json"
    ))
    .unwrap()
    .replace(r#""ball": 1"#, r#""ball": 7"#);
    std::fs::write(&file, text).unwrap();
    let out = bin().arg("drill").arg(&file).output().unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("names the 7, which is not on the table"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
