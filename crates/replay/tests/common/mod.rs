//! Helpers the command-line tests share: the binary, a scratch folder, a recorded break,
//! a run's outcome.

// Each test file compiles this module on its own and uses only some of it.
#![allow(dead_code)]

use billiards_physics::recording::{Recorder, Recording};
use billiards_physics::*;
use std::path::PathBuf;
use std::process::Command;

/// The `billiards-cli` binary of this build.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_billiards-cli"))
}

/// A fresh folder for one test's files (named by process and test).
pub fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A 15-ball break on an 8-ft table under the spin model, recorded to rest.
pub fn break_recording() -> Recording {
    let table = Table::wpa_8ft().with_jaws(0.015);
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let mut rec = Recorder::new(
        table,
        params,
        Rack::FifteenBall.layout(&table, &params.ball),
    )
    .unwrap();
    rec.strike(0, Shot::new(0.0, 9.0)).unwrap();
    rec.run_to_rest().unwrap();
    rec.recording()
}

/// Runs a command: whether it succeeded, its standard output and its standard error.
pub fn run(cmd: &mut Command) -> (bool, String, String) {
    let out = cmd.output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}
