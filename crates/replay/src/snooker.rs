//! Snooker on the command line: `simulate --game snooker` (a frame between two computer
//! levels through the one match loop, recorded, its [`StrokeLog`] written beside the
//! recording) and `tournament --game snooker`
//! (frames on all cores: frames won, breaks, centuries, fouls, decision time).

use crate::args::{SimulateArgs, TournamentArgs};
use crate::shard::{Batch, Shard};
use crate::stats::wilson;
use billiards_ai::Level;
use billiards_ai::noise::stream;
use billiards_ai::snooker::play::{FrameRecord, play_frame};
use billiards_rules::Seat;
use billiards_rules::StrokeLog;
use indicatif::{ProgressBar, ProgressStyle};
use rand::Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;

/// A century: a break of 100 points or more.
pub const CENTURY: u32 = 100;

/// Parses `A,B` as two computer levels.
pub fn levels(s: &str) -> Result<[Level; 2], String> {
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| format!("{s:?}: expected A,B (e.g. hard,easy)"))?;
    let p = |x: &str| {
        x.trim()
            .parse::<Level>()
            .map_err(|e| format!("{e} (snooker has computer levels only)"))
    };
    Ok([p(a)?, p(b)?])
}

/// `simulate --game snooker`: one frame between `--computer A,B`, seat A (the first name of
/// `--players`) breaking off, every draw from `--rack-seed` (else `--seed`, else 0); the
/// strokes printed, and with `--out` the recording and its log beside it.
pub fn simulate(a: &SimulateArgs) -> Result<(), String> {
    if !a.calls.is_empty() || !a.choices.is_empty() {
        return Err(
            "a snooker frame between computers takes no --call or --choice (give --computer \
             LEVEL,LEVEL, or --shot for a scripted frame)"
                .into(),
        );
    }
    let names: [String; 2] = match a.players.split_once(',') {
        Some((x, y)) => [x.trim().to_string(), y.trim().to_string()],
        None => return Err(format!("--players {:?}: expected NAME,NAME", a.players)),
    };
    let lv = levels(&a.computer).map_err(|e| format!("--computer {e}"))?;
    let seed = a.rack_seed.or(a.seed).unwrap_or(0);
    println!(
        "snooker, seed {seed}: {} ({}) breaks off against {} ({})",
        names[0], lv[0], names[1], lv[1]
    );
    let run = play_frame(
        lv,
        names,
        (0, seed),
        Seat::A,
        a.out.is_some(),
        &mut |line| println!("{line}"),
    )?;
    let r = &run.record;
    println!(
        "{}-{} in {} strokes ({}); highest breaks {} and {}",
        r.scores[0],
        r.scores[1],
        r.strokes,
        r.reason,
        run.frame.highest_break[0],
        run.frame.highest_break[1]
    );
    if let (Some(path), Some((rec, log))) = (&a.out, &run.recorded) {
        rec.save(path).map_err(|e| e.to_string())?;
        crate::interface_game::save_json(&StrokeLog::path_beside(path), log)?;
        println!(
            "{} and {}",
            path.display(),
            StrokeLog::path_beside(path).display()
        );
    }
    Ok(())
}

/// A snooker tournament's results (or one shard's).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SnookerResults {
    /// `"snooker-tournament"`.
    pub command: String,
    /// The slice of the frames played here; `None`: all of them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// The players, A first.
    pub players: [Level; 2],
    /// Frames in the whole tournament.
    pub games: u64,
    /// Its seed.
    pub seed: u64,
    /// The frames played here, by index.
    pub frames: Vec<FrameRecord>,
}

impl Batch for SnookerResults {
    const COMMAND: &'static str = "snooker-tournament";

    fn shard(&self) -> Option<Shard> {
        self.shard
    }

    fn set_shard(&mut self, shard: Option<Shard>) {
        self.shard = shard;
    }

    fn arguments(&self) -> serde_json::Value {
        serde_json::json!({ "players": self.players, "games": self.games, "seed": self.seed })
    }

    fn check_items(&self) -> Result<(), String> {
        let shard = self.shard.unwrap_or(Shard::WHOLE);
        let want: Vec<u64> = crate::shard::items(shard, self.games).collect();
        let have: Vec<u64> = self.frames.iter().map(|r| r.index).collect();
        if have == want {
            return Ok(());
        }
        let (w, h): (BTreeSet<u64>, BTreeSet<u64>) = (
            want.iter().copied().collect(),
            have.iter().copied().collect(),
        );
        Err(format!(
            "{} of its {} frames ({} missing)",
            have.len(),
            want.len(),
            w.difference(&h).count()
        ))
    }

    fn absorb(&mut self, other: Self) {
        self.frames.extend(other.frames);
    }

    fn finish(&mut self) {
        self.frames.sort_by_key(|r| r.index);
    }
}

/// `tournament --game snooker`: plays (or merges) and reports; `Err((message, input))`,
/// `input` when it is the user's mistake.
pub fn tournament(a: &TournamentArgs) -> Result<(), (String, bool)> {
    let results = if a.merge.is_empty() {
        let players = levels(&a.players).map_err(|e| (format!("--players {e}"), true))?;
        crate::shard::fail_once(SnookerResults::COMMAND, a.shard).map_err(|e| (e, false))?;
        play(players, a.games, a.seed, a.shard).map_err(|e| (e, false))?
    } else {
        crate::shard::merge::<SnookerResults>(&a.merge).map_err(|e| (e.to_string(), true))?
    };
    if let Some(path) = &a.out {
        crate::shard::write_json(&results, path).map_err(|e| (e, false))?;
    }
    print!("{}", report(&results));
    Ok(())
}

/// Frame `g` of a tournament of `seed`: its own seed, seat A breaking off in even frames.
fn play(
    players: [Level; 2],
    games: u64,
    seed: u64,
    part: Option<Shard>,
) -> Result<SnookerResults, String> {
    let shard = part.unwrap_or(Shard::WHOLE);
    let mine: Vec<u64> = crate::shard::items(shard, games).collect();
    let bar = ProgressBar::new(mine.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} frames {elapsed} (eta {eta})")
            .expect("template"),
    );
    let names = players.map(|l| l.to_string());
    let frames: Vec<FrameRecord> = mine
        .par_iter()
        .map(|&g| {
            let breaker = if g % 2 == 0 { Seat::A } else { Seat::B };
            let r = play_frame(
                players,
                names.clone(),
                (g, stream(seed, 3, g).random()),
                breaker,
                false,
                &mut |_| {},
            );
            bar.inc(1);
            r.map(|run| run.record)
                .map_err(|e| format!("frame {g}: {e}"))
        })
        .collect::<Result<_, _>>()?;
    bar.finish_and_clear();
    Ok(SnookerResults {
        command: SnookerResults::COMMAND.into(),
        shard: part,
        players,
        games,
        seed,
        frames,
    })
}

/// The report: per player, frames won (Wilson 95 %), points a frame, mean and highest
/// break, centuries (count and per frame), fouls a stroke, decision time mean/max.
pub fn report(r: &SnookerResults) -> String {
    let n = r.frames.len();
    let mut out = format!(
        "snooker, {} vs {}: {n} of {} frames (seed {}), 12-ft table\n",
        r.players[0], r.players[1], r.games, r.seed
    );
    out += &format!(
        "{:<8} {:>5} {:>7} {:>13} {:>9} {:>10} {:>8} {:>15} {:>11} {:>17}\n",
        "player",
        "wins",
        "win %",
        "95 % interval",
        "pts/frame",
        "mean break",
        "highest",
        "centuries",
        "fouls/shot",
        "decision mean/max"
    );
    for p in 0..2 {
        let wins = r.frames.iter().filter(|f| f.winner == Some(p)).count();
        let breaks: Vec<u32> = r
            .frames
            .iter()
            .flat_map(|f| f.players[p].breaks.iter().copied())
            .collect();
        let points: u32 = r.frames.iter().map(|f| f.scores[p]).sum();
        let centuries = breaks.iter().filter(|&&b| b >= CENTURY).count();
        let strokes: usize = r.frames.iter().map(|f| f.players[p].strokes).sum();
        let fouls: usize = r.frames.iter().map(|f| f.players[p].fouls).sum();
        let decisions: usize = r.frames.iter().map(|f| f.players[p].decisions).sum();
        let secs: f64 = r.frames.iter().map(|f| f.players[p].decision_secs).sum();
        let max = r
            .frames
            .iter()
            .map(|f| f.players[p].max_decision_secs)
            .fold(0.0, f64::max);
        // Clamped: rounding can leave the interval's ends a hair outside 0..1.
        let (lo, hi) = wilson(wins, n);
        let (lo, hi) = (lo.max(0.0), hi.min(1.0));
        out += &format!(
            "{:<8} {:>5} {:>6.1}% {:>5.1}-{:>5.1}% {:>9.1} {:>10.2} {:>8} {:>5} ({:>5.3}/fr) {:>11.3} {:>7.3}/{:.3} s\n",
            r.players[p].to_string(),
            wins,
            100.0 * wins as f64 / n.max(1) as f64,
            100.0 * lo,
            100.0 * hi,
            f64::from(points) / n.max(1) as f64,
            f64::from(breaks.iter().sum::<u32>()) / breaks.len().max(1) as f64,
            breaks.iter().max().copied().unwrap_or(0),
            centuries,
            centuries as f64 / n.max(1) as f64,
            fouls as f64 / strokes.max(1) as f64,
            secs / decisions.max(1) as f64,
            max,
        );
    }
    let draws = r.frames.iter().filter(|f| f.winner.is_none()).count();
    if draws > 0 {
        out += &format!("{draws} frames without a winner\n");
    }
    let capped = r
        .frames
        .iter()
        .filter(|f| f.reason.contains("strokes"))
        .count();
    if capped > 0 {
        out += &format!("{capped} frames stopped at the stroke limit, decided on points\n");
    }
    out
}
