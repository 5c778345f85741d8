//! Runs a scene file and prints the events and final states as JSON.
//!
//! ```text
//! cargo run --release -p billiards-physics --example scene -- crates/physics/examples/break.json
//! ```

use billiards_physics::scene::Scene;
use std::process::ExitCode;

fn main() -> ExitCode {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: scene FILE.json   (format: crates/physics/README.md, \"Scene files\")");
        return ExitCode::from(2);
    };
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("{path}: {e}");
            return ExitCode::FAILURE;
        }
    };
    match Scene::from_json(&text).and_then(|s| s.run()) {
        Ok(result) => {
            println!(
                "{}",
                serde_json::to_string_pretty(&result).expect("results serialize")
            );
            if result.error.is_some() {
                ExitCode::FAILURE
            } else {
                ExitCode::SUCCESS
            }
        }
        Err(e) => {
            eprintln!("{path}: {e}");
            ExitCode::FAILURE
        }
    }
}
