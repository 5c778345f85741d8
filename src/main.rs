//! The billiards game: `cargo run --release` to play, `--help` for the command-line flags.

use std::process::ExitCode;

use bevy::prelude::*;
use billiards::{GamePlugin, LaunchOptions};

fn main() -> ExitCode {
    let options = match LaunchOptions::from_args(std::env::args().skip(1)) {
        Ok(options) => options,
        Err(error) => {
            eprintln!("billiards: {error}\n\n{}", LaunchOptions::USAGE);
            return ExitCode::from(2);
        }
    };
    if options.show_help {
        println!("{}", LaunchOptions::USAGE);
        return ExitCode::SUCCESS;
    }
    if let Err(error) = billiards::view::display::check(std::env::var("DISPLAY").ok().as_deref()) {
        eprintln!("billiards: {error}");
        return ExitCode::FAILURE;
    }
    match App::new().add_plugins(GamePlugin { options }).run() {
        AppExit::Success => ExitCode::SUCCESS,
        AppExit::Error(code) => ExitCode::from(code.get()),
    }
}
