//! `billiards-cli`: the game's headless commands without the game (builds in seconds).

use clap::Parser;

fn main() -> std::process::ExitCode {
    billiards_replay::cli::run(billiards_replay::cli::Cli::parse())
}
