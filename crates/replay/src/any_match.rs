//! `match --game ID`: a whole match of any game of the catalog
//! ([`billiards_rules::catalog`]) between two computer levels, played through the one game
//! interface alone ([`billiards_ai::any_match`], issue 50), each stroke's verdict printed.

use billiards_ai::any_match::{Seating, play_match};
use billiards_ai::{Level, Player};
use billiards_physics::{Model, Params, SpinModel};
use billiards_rules::catalog::{MatchSettings, find};

/// `match` options.
#[derive(clap::Args, Debug)]
pub struct MatchArgs {
    /// The game, by id: nine-ball, eight-ball, snooker, ... (every game of the catalog).
    #[arg(long, default_value = "nine-ball")]
    pub game: String,
    /// The two computer levels, `A,B` (easy, medium, hard, expert, perfect).
    #[arg(long, default_value = "medium,medium")]
    pub players: String,
    /// The match's length in the game's unit (racks to win, frames best of, points);
    /// default the game's usual length.
    #[arg(long)]
    pub length: Option<u32>,
    /// Seed of the racks and of every draw.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Stop after this many strokes.
    #[arg(long, default_value_t = 2000)]
    pub max_strokes: usize,
    /// Print only the result, not each stroke.
    #[arg(long)]
    pub quiet: bool,
}

fn levels(s: &str) -> Result<[Level; 2], String> {
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| format!("--players {s:?}: expected A,B (e.g. hard,medium)"))?;
    let p = |x: &str| x.trim().parse::<Level>().map_err(|e| e.to_string());
    Ok([p(a)?, p(b)?])
}

/// Plays the match; an error for an unknown game, bad levels or a refused stroke.
pub fn run(a: MatchArgs) -> Result<(), String> {
    let entry = find(&a.game).map_err(|e| e.0)?;
    let levels = levels(&a.players)?;
    let length = a.length.unwrap_or(entry.default_length);
    let names = [
        format!("A ({})", levels[0].name()),
        format!("B ({})", levels[1].name()),
    ];
    let mut game = entry
        .start(&MatchSettings::new(names, length, a.seed))
        .map_err(|e| e.0)?;
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    println!(
        "{}, {} {length}: {} vs {}, seed {}",
        entry.label,
        entry.length_unit,
        levels[0].name(),
        levels[1].name(),
        a.seed
    );
    let quiet = a.quiet;
    let mut say = |line: String| {
        if !quiet {
            println!("{line}");
        }
    };
    let seating = Seating::new(levels.map(Player::Computer), params, a.seed, a.max_strokes);
    let run = play_match(game.as_mut(), &seating, &mut say)?;
    match run.winner {
        Some(w) => println!(
            "{} wins the match in {} strokes ({} games; fouls {} - {}): {}",
            game.players()[w.index()],
            run.strokes,
            run.games(),
            run.fouls()[0],
            run.fouls()[1],
            run.score_line
        ),
        None => println!(
            "no winner after {} strokes: {}",
            run.strokes, run.score_line
        ),
    }
    Ok(())
}
