//! `billiards-cli drill FILE.json`: a drill (`billiards_rules::Drill`) played headless by the
//! computer (`billiards_ai::drill::session`), each attempt and the tally printed.

use billiards_ai::Level;
use billiards_ai::drill::{self, Method};
use billiards_physics::Params;
use billiards_rules::Drill;
use std::path::PathBuf;

/// `drill` options.
#[derive(clap::Args, Debug)]
pub struct DrillArgs {
    /// The drill (a JSON file, as in `assets/drills/`).
    pub file: PathBuf,
    /// Attempts (default: the drill's own count).
    #[arg(long)]
    pub tries: Option<u32>,
    /// The computer's level: easy, medium, hard, expert or perfect (its execution noise; a
    /// run-out is also decided by its search).
    #[arg(long, default_value = "hard")]
    pub level: Level,
    /// Seed of the search and of the execution noise.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The spin model's default cushion (Han 2005) instead of the game's (Mathavan 2010).
    #[arg(long)]
    pub han: bool,
    /// Print the tally as JSON (`DrillScore`) after the attempts.
    #[arg(long)]
    pub json: bool,
}

/// Runs `drill`.
pub fn run(a: DrillArgs) -> Result<(), String> {
    let d = Drill::load(&a.file).map_err(|e| e.to_string())?;
    let params = if a.han {
        Params {
            model: billiards_physics::Model::Spin(Default::default()),
            ..Params::default()
        }
    } else {
        drill::game_params()
    };
    let tries = a.tries.unwrap_or(d.tries);
    let method = match Method::of(&d) {
        Method::Rules => "the rules' search",
        Method::Goals => "a search scored by the drill",
    };
    println!("{}: {}", d.name, d.description);
    println!("{tries} tries at {} ({method})", a.level);
    let s = drill::session(&d, params, a.level, tries, a.seed)?;
    for (k, at) in s.attempts.iter().enumerate() {
        let verdict = if at.success { "success" } else { "missed" };
        println!(
            "try {:>2}: {verdict:<7} score {:>5.1}  {} shot(s)",
            k + 1,
            at.score,
            at.shots
        );
        for r in &at.reasons {
            println!("         {r}");
        }
    }
    println!(
        "{} of {} (best score {:.1})",
        s.score.successes, s.score.tries, s.score.best
    );
    if a.json {
        println!(
            "{}",
            serde_json::to_string(&s.score).map_err(|e| e.to_string())?
        );
    }
    Ok(())
}
