//! The command line's dispatcher: `verify`, `export` (and `replay`, which the game binary
//! handles) here, every other subcommand in its own module, the arguments they share in
//! `args.rs`. Errors go to stderr with a non-zero exit code.

use crate::args::parse_size;
use crate::export::{self, ExportOptions};
use billiards_physics::recording::{Recording, Verdict};
use billiards_rules::{RulesLog, Shots};
use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
use std::process::ExitCode;

/// Billiards: exact event-driven pool physics, headless tools.
#[derive(Parser, Debug)]
#[command(name = "billiards", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Simulate shots from a rack or a scene file; write a recording and print a summary.
    Simulate(crate::simulate::SimulateArgs),
    /// Re-simulate a recording and check it reproduces its history bit for bit.
    Verify {
        /// The recording.
        file: PathBuf,
    },
    /// Export a recording (or one shot of it) as an animated GIF or a PNG sequence.
    Export(ExportArgs),
    /// Whole racks between two computer players on all cores: win rates and figures.
    Tournament(crate::tournament::TournamentArgs),
    /// One whole match of any game between two computer levels, through the one game
    /// interface, each stroke's verdict printed.
    Match(crate::any_match::MatchArgs),
    /// The break study: breaks per game, table, rack, speed and cue position, judged by the
    /// rules; sharded (`--shard K/M`, `--merge`).
    Breaks(crate::breaks::BreaksArgs),
    /// The physics soak: seeded random scenes with every event checked; sharded.
    Soak(crate::soak::SoakArgs),
    /// The stress table: up to 10,000 seeded balls on a larger table, run in 60 Hz frames:
    /// events, events a second, the solver's cost per frame, energy and overlap checks.
    Stress(crate::stress::StressArgs),
    /// The success probability of one shot from every cell of a grid of cue-ball places,
    /// under a player's execution noise, with an SVG heat map; sharded.
    Study(crate::study::StudyArgs),
    /// A position as a short code, to and from JSON (`encode FILE.json`, `decode CODE`).
    #[command(subcommand)]
    Position(crate::position::PositionCmd),
    /// A drill played by the computer: each try's judgement and the score.
    Drill(crate::drill::DrillArgs),
    /// Open the game on a recording (needs the game binary: `billiards replay FILE`).
    Replay {
        /// The recording.
        file: PathBuf,
    },
}

/// `export` options.
#[derive(clap::Args, Debug)]
pub struct ExportArgs {
    /// The recording.
    pub file: PathBuf,
    /// Write an animated GIF here.
    #[arg(long)]
    pub gif: Option<PathBuf>,
    /// Write a numbered PNG sequence into this folder.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write a video here: MP4, or WebM for a `.webm` name (needs `ffmpeg` on the PATH).
    #[arg(long)]
    pub video: Option<PathBuf>,
    /// Frames per second of simulated time.
    #[arg(long, default_value_t = 30.0)]
    pub fps: f64,
    /// Frame size, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "640x360", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Export only this shot, counted from 1 as in the game's timeline; default the whole game.
    #[arg(long)]
    pub shot: Option<usize>,
}

/// Runs the command line; returns the process exit code.
pub fn run(cli: Cli) -> ExitCode {
    let result = match cli.command {
        Command::Simulate(a) => crate::simulate::simulate(a),
        Command::Verify { file } => verify(&file),
        Command::Export(a) => export_cmd(a),
        Command::Tournament(a) => return crate::tournament::run(a),
        Command::Match(a) => crate::any_match::run(a),
        Command::Breaks(a) => return crate::breaks::run(a),
        Command::Soak(a) => return crate::soak::run(a),
        Command::Stress(a) => return crate::stress::run(a),
        Command::Study(a) => return crate::study::run(a),
        Command::Position(c) => crate::position::run(c),
        Command::Drill(a) => crate::drill::run(a),
        Command::Replay { file } => Err(format!(
            "{}: replay opens the game: run `billiards replay {}`",
            file.display(),
            file.display()
        )),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn verify(file: &std::path::Path) -> Result<(), String> {
    let rec = Recording::load(file).map_err(|e| not_a_recording(file, e.to_string()))?;
    match rec
        .verify()
        .map_err(|e| format!("{}: {e}", file.display()))?
    {
        Verdict::Reproduced { events } => {
            println!(
                "{}: reproduced bit for bit ({events} events)",
                file.display()
            );
            // The rules' log, when the game was played under rules (kept beside the file as
            // `NAME.game.json`, or `NAME.snooker.json` by older builds).
            match RulesLog::beside(file) {
                None => Ok(()),
                Some((_, Err(e))) => Err(e),
                Some((path, Ok(log))) => {
                    let n = log
                        .check(&rec)
                        .map_err(|e| format!("{}: {e}", path.display()))?;
                    println!(
                        "{}: {n} {} re-judged identically",
                        path.display(),
                        log.verdicts()
                    );
                    Ok(())
                }
            }
        }
        Verdict::Differs {
            index,
            recorded,
            replayed,
        } => Err(format!(
            "{}: differs at event {index}:\n  recorded: {recorded:?}\n  replayed: {replayed:?}",
            file.display()
        )),
    }
}

/// Why `file` could not be verified, `error` being the loader's answer: a rules log given by
/// mistake (by its content, or by its `.game.json` name) is named as such, with the recording
/// to verify instead.
fn not_a_recording(file: &std::path::Path, error: String) -> String {
    RulesLog::mistaken_for_recording(file, "verify").unwrap_or(error)
}

fn export_cmd(a: ExportArgs) -> Result<(), String> {
    let rec = Recording::load(&a.file).map_err(|e| e.to_string())?;
    let shots = Shots::of(&rec);
    let span = match a.shot {
        Some(k) => shots.span(k).ok_or_else(|| {
            format!(
                "{}: there is no shot {k} (shots count from 1; this recording has {})",
                a.file.display(),
                shots.len()
            )
        })?,
        None => shots.whole(),
    };
    let opts = ExportOptions {
        fps: a.fps,
        width: a.size.0,
        height: a.size.1,
        span,
    };
    if a.gif.is_none() && a.png.is_none() && a.video.is_none() {
        return Err("nothing to export: give --gif FILE, --png DIR and/or --video FILE".into());
    }
    let bar = ProgressBar::new(0);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} frames").expect("template"));
    let mut progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
        std::ops::ControlFlow::Continue(())
    };
    if let Some(out) = &a.gif {
        let n = export::gif(&rec, &opts, out, &mut progress).map_err(|e| e.to_string())?;
        bar.finish_and_clear();
        println!("{}: {n} frames", out.display());
    }
    if let Some(dir) = &a.png {
        let n = export::png_sequence(&rec, &opts, dir, &mut progress).map_err(|e| e.to_string())?;
        bar.finish_and_clear();
        println!("{}: {n} frames", dir.display());
    }
    if let Some(out) = &a.video {
        let n = export::video(&rec, &opts, out, &mut progress).map_err(|e| e.to_string())?;
        bar.finish_and_clear();
        println!("{}: {n} frames", out.display());
    }
    Ok(())
}
