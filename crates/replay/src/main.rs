//! `billiards-cli`: the game's headless commands without the game (builds in seconds).

use clap::Parser;

/// The exit status of a Unix tool killed by SIGPIPE (128 + 13).
const BROKEN_PIPE: i32 = 141;

fn main() -> std::process::ExitCode {
    // `billiards-cli match ... | head`: once the reader is gone the next print fails with a
    // broken pipe; the command ends quietly, as Unix tools do, not with a panic's message.
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let message = info
            .payload()
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| info.payload().downcast_ref::<&str>().copied())
            .unwrap_or("");
        if message.starts_with("failed printing to stdout") && message.contains("Broken pipe") {
            std::process::exit(BROKEN_PIPE);
        }
        default(info);
    }));
    billiards_replay::cli::run(billiards_replay::cli::Cli::parse())
}
