//! `tournament`: whole racks between two players, headless, on all cores; win rates, balls
//! pocketed per inning, break-and-run rate, fouls and decision time. `--shard K/M` plays the
//! K-th of M slices of the games (game `g` belongs to slice `g % M + 1`); `--merge` combines
//! the JSON of the slices (`--out`) into one report, the same as one process's but for the
//! decision times ([`crate::shard`]).

pub use crate::args::TournamentArgs;
pub use crate::stats::wilson;

use crate::shard::{Batch, Shard};
use billiards_ai::Player;
use billiards_ai::noise::stream;
use billiards_ai::play::{RackRecord, Venue, play_rack_at};
use billiards_rules::Game;
use indicatif::{ProgressBar, ProgressStyle};
use rand::Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use std::process::ExitCode;

/// A tournament's results (or one shard's).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Results {
    /// `"tournament"` (results written before other batch commands have none).
    #[serde(default = "tournament_command")]
    pub command: String,
    /// The slice of the games played here; `None`: all of them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// The game.
    pub game: Game,
    /// The players, A first.
    pub players: [Player; 2],
    /// Games in the whole tournament.
    pub games: u64,
    /// Its seed.
    pub seed: u64,
    /// The racks played here, by game index.
    pub racks: Vec<RackRecord>,
    /// Where they were played (results written before tables existed: the 8-ft table).
    #[serde(default)]
    pub venue: Venue,
}

fn tournament_command() -> String {
    "tournament".into()
}

impl Batch for Results {
    const COMMAND: &'static str = "tournament";

    fn shard(&self) -> Option<Shard> {
        self.shard
    }

    fn set_shard(&mut self, shard: Option<Shard>) {
        self.shard = shard;
    }

    fn arguments(&self) -> serde_json::Value {
        serde_json::json!({
            "game": self.game,
            "players": self.players,
            "games": self.games,
            "seed": self.seed,
            "venue": self.venue,
        })
    }

    fn check_items(&self) -> Result<(), String> {
        let shard = self.shard.unwrap_or(Shard::WHOLE);
        let want: Vec<u64> = crate::shard::items(shard, self.games).collect();
        let have: Vec<u64> = self.racks.iter().map(|r| r.index).collect();
        if have == want {
            return Ok(());
        }
        let (want_set, have_set): (BTreeSet<u64>, BTreeSet<u64>) = (
            want.iter().copied().collect(),
            have.iter().copied().collect(),
        );
        let missing = want_set.difference(&have_set).count();
        let foreign = have.len() - have_set.intersection(&want_set).count();
        Err(format!(
            "{} of its {} games ({missing} missing, {foreign} not its own or repeated)",
            have.len(),
            want.len()
        ))
    }

    fn absorb(&mut self, other: Self) {
        self.racks.extend(other.racks);
    }

    fn finish(&mut self) {
        self.racks.sort_by_key(|r| r.index);
    }
}

/// A user's mistake (exit status 2) or a failure while playing (1).
enum Failure {
    Input(String),
    Run(String),
}

/// Runs `tournament`; returns the process exit code.
pub fn run(a: TournamentArgs) -> ExitCode {
    match tournament(a) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
        Err(Failure::Run(e)) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn players(s: &str) -> Result<[Player; 2], String> {
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| format!("--players {s:?}: expected A,B (e.g. hard,easy)"))?;
    let p = |x: &str| x.trim().parse::<Player>().map_err(|e| e.to_string());
    Ok([p(a)?, p(b)?])
}

fn tournament(a: TournamentArgs) -> Result<(), Failure> {
    if matches!(a.game, crate::args::GameArg::ThreeCushion) {
        return crate::interface_game::tournament(a.game.id(), &a).map_err(|(e, input)| {
            if input {
                Failure::Input(e)
            } else {
                Failure::Run(e)
            }
        });
    }
    if a.game.pool().is_none() {
        return crate::snooker::tournament(&a).map_err(|(e, input)| {
            if input {
                Failure::Input(e)
            } else {
                Failure::Run(e)
            }
        });
    }
    let results = if a.merge.is_empty() {
        let game: Game = a.game.pool().unwrap_or(Game::NineBall);
        if game == Game::FreePlay {
            return Err(Failure::Input(
                "free play has no winner: --game nine-ball, ten-ball or eight-ball".into(),
            ));
        }
        let players = players(&a.players).map_err(Failure::Input)?;
        crate::shard::fail_once("tournament", a.shard).map_err(Failure::Run)?;
        let venue = Venue {
            table: a.table,
            rack: a.rack_style,
        };
        play(venue, game, players, a.games, a.seed, a.shard).map_err(Failure::Run)?
    } else {
        crate::shard::merge::<Results>(&a.merge).map_err(|e| Failure::Input(e.to_string()))?
    };
    if let Some(path) = &a.out {
        crate::shard::write_json(&results, path).map_err(Failure::Run)?;
    }
    print!("{}", report(&results));
    Ok(())
}

/// Plays the games of shard `part` (`None`: all of them) on all cores, with a progress bar.
fn play(
    venue: Venue,
    game: Game,
    players: [Player; 2],
    games: u64,
    seed: u64,
    part: Option<Shard>,
) -> Result<Results, String> {
    let shard = part.unwrap_or(Shard::WHOLE);
    let mine: Vec<u64> = crate::shard::items(shard, games).collect();
    let bar = ProgressBar::new(mine.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} games {elapsed} (eta {eta})")
            .expect("template"),
    );
    let racks: Vec<RackRecord> = mine
        .par_iter()
        .map(|&g| {
            let r = play_rack_at(
                venue,
                game,
                players,
                g,
                stream(seed, 3, g).random(),
                (g % 2) as usize,
            );
            bar.inc(1);
            r.map_err(|e| format!("game {g}: {e}"))
        })
        .collect::<Result<_, _>>()?;
    bar.finish_and_clear();
    Ok(Results {
        command: tournament_command(),
        shard: part,
        game,
        players,
        games,
        seed,
        racks,
        venue,
    })
}

/// The report: per player, wins (with a 95 % interval), balls per inning, break-and-run
/// rate, fouls, decision times.
pub fn report(r: &Results) -> String {
    let n = r.racks.len();
    let mut out = format!(
        "{:?}, {} vs {}: {n} of {} games (seed {}), {} table, {} racks\n",
        r.game,
        r.players[0],
        r.players[1],
        r.games,
        r.seed,
        r.venue.table,
        r.venue.rack.name()
    );
    out += &format!(
        "{:<8} {:>5} {:>7} {:>13} {:>12} {:>14} {:>11} {:>15}\n",
        "player",
        "wins",
        "win %",
        "95 % interval",
        "balls/inning",
        "break and run",
        "fouls/shot",
        "decision mean/max"
    );
    for p in 0..2 {
        let wins = r.racks.iter().filter(|x| x.winner == Some(p)).count();
        let t = |f: &dyn Fn(&RackRecord) -> f64| r.racks.iter().map(f).sum::<f64>();
        let innings = t(&|x| x.players[p].innings as f64);
        let balls = t(&|x| x.players[p].pocketed as f64);
        let shots = t(&|x| x.players[p].shots as f64);
        let fouls = t(&|x| x.players[p].fouls as f64);
        let decisions = t(&|x| x.players[p].decisions as f64);
        let secs = t(&|x| x.players[p].decision_secs);
        let max = r
            .racks
            .iter()
            .map(|x| x.players[p].max_decision_secs)
            .fold(0.0, f64::max);
        let broke = r.racks.iter().filter(|x| x.breaker == p).count();
        let runs = r
            .racks
            .iter()
            .filter(|x| x.breaker == p && x.break_and_run)
            .count();
        let (lo, hi) = wilson(wins, n);
        out += &format!(
            "{:<8} {:>5} {:>6.1}% {:>5.1}-{:>5.1}% {:>12.2} {:>7}/{:<3} {:>3.0}% {:>11.3} {:>7.3}/{:.3} s\n",
            r.players[p].to_string(),
            wins,
            100.0 * wins as f64 / n.max(1) as f64,
            100.0 * lo,
            100.0 * hi,
            balls / innings.max(1.0),
            runs,
            broke,
            100.0 * runs as f64 / broke.max(1) as f64,
            fouls / shots.max(1.0),
            secs / decisions.max(1.0),
            max,
        );
    }
    let draws = r.racks.iter().filter(|x| x.winner.is_none()).count();
    if draws > 0 {
        out += &format!("{draws} games without a winner\n");
    }
    out
}
