//! `billiards-cli position encode` and `decode`, end to end: a JSON position to its code and
//! back to the same JSON; a bad code or file fails with its reason and a non-zero exit.

use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
}

#[test]
fn a_position_goes_to_a_code_and_back_to_the_same_json() {
    let dir = std::env::temp_dir().join(format!("billiards-position-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("p.json");
    let json = r#"{"game": "nine_ball",
        "table": {"length": 2.54, "width": 1.27, "corner_mouth": 0.1143, "side_mouth": 0.127,
                  "pockets": {"kind": "jaws", "radius": 0.015}},
        "balls": [{"number": 0, "position": {"x": -0.6, "y": 0.1}},
                  {"number": 9, "position": {"x": 0.635, "y": 0.0}}],
        "shot": {"angle": 0.1, "speed": 3.0, "tip": {"side": 0.0, "height": -0.2}}}"#;
    std::fs::write(&file, json).unwrap();
    let out = bin()
        .args(["position", "encode"])
        .arg(&file)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let code = String::from_utf8(out.stdout).unwrap().trim().to_owned();
    let out = bin().args(["position", "decode", &code]).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let back: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mut want: serde_json::Value = serde_json::from_str(json).unwrap();
    // The shot's elevation is level, which the JSON form leaves out.
    assert_eq!(back, want.take());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_bad_code_or_file_fails_with_its_reason() {
    let out = bin().args(["position", "decode", "AQ"]).output().unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("cut short"));
    let out = bin()
        .args(["position", "decode", "not a code!"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("base64url"));
    let out = bin()
        .args(["position", "encode", "/nonexistent/p.json"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent/p.json"));
}
