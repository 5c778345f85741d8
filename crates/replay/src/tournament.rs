//! `tournament --game ID`: matches of any game of the catalog between two players,
//! headless, on all cores, each played by the one match loop through the one game interface
//! ([`billiards_ai::any_match`], issue 50): win rates, fouls, decision times and what the
//! game counts besides ([`Unit`]: pool's balls an inning and break and run, snooker's
//! breaks and centuries, carom's average and high run). A match is one game by default
//! ([`GameEntry::one_game`]: a rack, a frame, a carom game), `--length` otherwise.
//! `--shard K/M` plays the K-th of M slices of the matches (match `g` belongs to slice
//! `g % M + 1`); `--merge` combines the JSON of the slices (`--out`) into one report, the same
//! as one process's but for the decision times ([`crate::shard`]).
//!
//! Match `g` takes its draws from `stream(seed, 3, g)` and its rack (pool's gaps) from that
//! seed's own stream 0; player `g % 2` sits in seat A and opens.

pub use crate::args::TournamentArgs;
pub use crate::stats::wilson;

use crate::shard::{Batch, Shard};
use billiards_ai::Player;
use billiards_ai::any_match::SeatTally;
use billiards_ai::match_record::{Between, MatchRecord, play_between};
use billiards_ai::noise::stream;
use billiards_ai::play::{MAX_SHOTS, Venue};
use billiards_rules::GameRules;
use billiards_rules::catalog::{GameEntry, MatchSettings, Unit, find};
use indicatif::{ProgressBar, ProgressStyle};
use rand::Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use std::process::ExitCode;

/// A tournament's results (or one shard's).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Results {
    /// `"tournament"`.
    pub command: String,
    /// The slice of the matches played here; `None`: all of them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// The game, by its catalog id.
    pub game: String,
    /// The players, by index.
    pub players: [Player; 2],
    /// Matches in the whole tournament.
    pub games: u64,
    /// Its seed.
    pub seed: u64,
    /// Each match's length in the game's unit.
    pub length: u32,
    /// Where pool's games were played (the other games have their own tables).
    pub venue: Venue,
    /// The matches played here, by index.
    pub matches: Vec<MatchRecord>,
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
            "length": self.length,
            "venue": self.venue,
        })
    }

    fn check_items(&self) -> Result<(), String> {
        let shard = self.shard.unwrap_or(Shard::WHOLE);
        let want: Vec<u64> = crate::shard::items(shard, self.games).collect();
        let have: Vec<u64> = self.matches.iter().map(|r| r.index).collect();
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
        self.matches.extend(other.matches);
    }

    fn finish(&mut self) {
        self.matches.sort_by_key(|r| r.index);
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

/// What one tournament plays: the game, its settings, the players.
struct Plan {
    entry: &'static GameEntry,
    players: [Player; 2],
    length: u32,
    venue: Venue,
}

impl Plan {
    fn of(a: &TournamentArgs) -> Result<Self, String> {
        let entry = find(a.game.id()).map_err(|e| e.0)?;
        let plan = Plan {
            entry,
            players: players(&a.players)?,
            length: a.length.unwrap_or(entry.one_game),
            venue: Venue {
                table: a.table,
                rack: a.rack_style,
            },
        };
        // Refused before any match is played: a game without a winner, a length the rules
        // refuse, a player who does not play this game.
        let game = plan.start(plan.players.map(|p| p.to_string()), 0)?;
        if game.sandbox() {
            return Err(format!(
                "{} has no winner: --game nine-ball, ten-ball, eight-ball, snooker or \
                 three-cushion",
                entry.label
            ));
        }
        for player in plan.players {
            player.plays(game.as_ref())?;
        }
        Ok(plan)
    }

    /// A match between `names` (seat A first), its rack from `rack_seed`: pool's games at
    /// the venue, the others on their own tables.
    fn start(&self, names: [String; 2], rack_seed: u64) -> Result<Box<dyn GameRules>, String> {
        let mut settings = MatchSettings::new(names, self.length, rack_seed);
        if self.entry.pool_table {
            let (table, params) = billiards_ai::play::table_and_params_on(self.venue.table);
            settings.equipment = Some((table, params.ball));
            settings.style = self.venue.rack;
        }
        self.entry.start(&settings).map_err(|e| e.0)
    }

    /// Plays match `g` of a tournament of `seed`: player `g % 2` opens.
    fn play(&self, g: u64, seed: u64) -> Result<MatchRecord, String> {
        let seed = stream(seed, 3, g).random();
        let between = Between {
            players: self.players,
            params: (self.entry.params)(),
            seed,
            // The stroke limit of pool's racks and snooker's frames, for each game of the
            // match (each point of a carom game).
            max_strokes: MAX_SHOTS * self.length as usize,
        };
        let rack = stream(seed, 0, 0).random();
        let start = |names| self.start(names, rack);
        play_between(g, (g % 2) as usize, &between, &start).map(|(record, _)| record)
    }
}

fn tournament(a: TournamentArgs) -> Result<(), Failure> {
    let results = if a.merge.is_empty() {
        let plan = Plan::of(&a).map_err(Failure::Input)?;
        crate::shard::fail_once("tournament", a.shard).map_err(Failure::Run)?;
        play(&plan, a.games, a.seed, a.shard).map_err(Failure::Run)?
    } else {
        crate::shard::merge::<Results>(&a.merge).map_err(|e| Failure::Input(e.to_string()))?
    };
    if let Some(path) = &a.out {
        crate::shard::write_json(&results, path).map_err(Failure::Run)?;
    }
    let entry = find(&results.game).map_err(|e| Failure::Input(e.0))?;
    print!("{}", report(entry, &results));
    Ok(())
}

/// Plays the matches of shard `part` (`None`: all of them) on all cores, with a progress
/// bar.
fn play(plan: &Plan, games: u64, seed: u64, part: Option<Shard>) -> Result<Results, String> {
    let shard = part.unwrap_or(Shard::WHOLE);
    let mine: Vec<u64> = crate::shard::items(shard, games).collect();
    let bar = ProgressBar::new(mine.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} games {elapsed} (eta {eta})")
            .expect("template"),
    );
    let matches: Vec<MatchRecord> = mine
        .par_iter()
        .map(|&g| {
            let r = plan.play(g, seed);
            bar.inc(1);
            r.map_err(|e| format!("game {g}: {e}"))
        })
        .collect::<Result<_, _>>()?;
    bar.finish_and_clear();
    Ok(Results {
        command: "tournament".into(),
        shard: part,
        game: plan.entry.id.to_owned(),
        players: plan.players,
        games,
        seed,
        length: plan.length,
        venue: plan.venue,
        matches,
    })
}

/// The report: per player, wins (with a 95 % interval), the game's own figures, fouls a
/// stroke, decision times.
pub fn report(entry: &GameEntry, r: &Results) -> String {
    let n = r.matches.len();
    let table = if entry.pool_table {
        format!(
            "{} table, {} racks",
            r.venue.table,
            r.venue.rack.name().to_lowercase()
        )
    } else {
        format!("{}'s own table", entry.label)
    };
    let mut out = format!(
        "{}, {} {}, {} vs {}: {n} of {} games (seed {}), {table}\n",
        entry.label, entry.length_unit, r.length, r.players[0], r.players[1], r.games, r.seed,
    );
    out += &format!(
        "{:<8} {:>5} {:>7} {:>13} {} {:>11} {:>17}\n",
        "player",
        "wins",
        "win %",
        "95 % interval",
        head(entry.unit),
        "fouls/shot",
        "decision mean/max"
    );
    for p in 0..2 {
        let wins = r.matches.iter().filter(|x| x.winner == Some(p)).count();
        let t = |f: &dyn Fn(&SeatTally) -> f64| r.matches.iter().map(|x| f(&x.players[p])).sum();
        let strokes: f64 = t(&|x| x.strokes as f64);
        let fouls: f64 = t(&|x| x.fouls as f64);
        let decisions: f64 = t(&|x| x.decisions as f64);
        let secs: f64 = t(&|x| x.decision_secs);
        let max = r
            .matches
            .iter()
            .map(|x| x.players[p].max_decision_secs)
            .fold(0.0, f64::max);
        // Clamped: rounding can leave the interval's ends a hair outside 0..1.
        let (lo, hi) = wilson(wins, n);
        let (lo, hi) = (lo.max(0.0), hi.min(1.0));
        out += &format!(
            "{:<8} {:>5} {:>6.1}% {:>5.1}-{:>5.1}% {} {:>11.3} {:>7.3}/{:.3} s\n",
            r.players[p].to_string(),
            wins,
            100.0 * wins as f64 / n.max(1) as f64,
            100.0 * lo,
            100.0 * hi,
            row(entry.unit, r, p),
            fouls / strokes.max(1.0),
            secs / decisions.max(1.0),
            max,
        );
    }
    let draws = r.matches.iter().filter(|x| x.winner.is_none()).count();
    if draws > 0 {
        out += &format!("{} without a winner\n", games(draws));
    }
    let on_points = r
        .matches
        .iter()
        .filter(|x| x.winner.is_some() && x.reason.starts_with("on points after"))
        .count();
    if on_points > 0 {
        out += &format!(
            "{} stopped at the stroke limit, decided on points\n",
            games(on_points)
        );
    }
    out
}

/// "1 game", "3 games".
fn games(n: usize) -> String {
    format!("{n} game{}", if n == 1 { "" } else { "s" })
}

/// A snooker break of 100 or more.
pub const CENTURY: u32 = 100;

/// The game's own columns' heads ([`Unit`]).
fn head(unit: Unit) -> String {
    match unit {
        Unit::Racks => format!("{:>12} {:>14}", "balls/inning", "break and run"),
        Unit::Frames => format!(
            "{:>9} {:>10} {:>8} {:>15}",
            "pts/frame", "mean break", "highest", "centuries"
        ),
        Unit::Points => format!("{:>9} {:>8}", "average", "high run"),
    }
}

/// Player `p`'s figures in the game's own columns ([`Unit`]).
fn row(unit: Unit, r: &Results, p: usize) -> String {
    let n = r.matches.len().max(1) as f64;
    let sum = |f: &dyn Fn(&MatchRecord) -> f64| r.matches.iter().map(f).sum::<f64>();
    let runs: Vec<u32> = r
        .matches
        .iter()
        .flat_map(|x| x.players[p].runs.iter().copied())
        .collect();
    let highest = runs.iter().max().copied().unwrap_or(0);
    match unit {
        Unit::Racks => {
            let balls = sum(&|x| x.players[p].pocketed as f64);
            let innings = sum(&|x| x.players[p].visits as f64);
            let runs_out = sum(&|x| x.run_outs[p] as f64);
            let opened = sum(&|x| x.openings[p] as f64);
            format!(
                "{:>12.2} {:>7}/{:<3} {:>3.0}%",
                balls / innings.max(1.0),
                runs_out,
                opened,
                100.0 * runs_out / opened.max(1.0)
            )
        }
        Unit::Frames => {
            let points = sum(&|x| f64::from(x.points[p]));
            let centuries = runs.iter().filter(|&&b| b >= CENTURY).count();
            format!(
                "{:>9.1} {:>10.2} {:>8} {:>5} ({:>5.3}/fr)",
                points / n,
                f64::from(runs.iter().sum::<u32>()) / runs.len().max(1) as f64,
                highest,
                centuries,
                centuries as f64 / n
            )
        }
        Unit::Points => {
            let points = sum(&|x| f64::from(x.players[p].points));
            let innings = sum(&|x| x.players[p].visits as f64);
            format!("{:>9.3} {:>8}", points / innings.max(1.0), highest)
        }
    }
}
