//! `breaks`: the break study. Many breaks of seeded racks, judged by the rules
//! ([`billiards_rules::breaks`]), one row for each game, table, rack style, speed and cue
//! position asked for (their product), with 95 % intervals.
//!
//! Break `i` of every row draws from the stream `(seed, BREAKS, i)`: the rows see the same
//! racks and draws (common random numbers, so rows compare with less noise), and a break
//! depends on nothing else. The items are numbered row by row (`row * breaks + i`) and split
//! by `--shard K/M` as in [`crate::shard`]; the counts are whole numbers, so the merge of
//! the shards equals one process's result exactly.

use crate::args::GameArg;
use crate::shard::{Batch, Shard, parse_shard};
use billiards_ai::noise::stream;
use billiards_physics::TableChoice;
use billiards_rules::breaks::{BreakSpec, BreakStats, Cue, one_break, params, wilson};
use billiards_rules::{Game, RackStyle};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;
use std::process::ExitCode;

/// The stream index of the break study's draws.
const BREAKS: u64 = 0x6272_6561_6b73;

/// `breaks` options.
#[derive(clap::Args, Debug)]
pub struct BreaksArgs {
    /// The games, comma-separated: nine-ball, ten-ball, eight-ball.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "nine-ball")]
    pub game: Vec<GameArg>,
    /// The tables, comma-separated (`7ft`, `8ft`, `9ft`, optionally `-wide` or `-tight`);
    /// default each game's: 9ft for 9-ball, 7ft for 8-ball.
    #[arg(long, value_delimiter = ',')]
    pub table: Vec<TableChoice>,
    /// Rack styles, comma-separated: `template` (frozen) or `triangle` (small seeded gaps).
    #[arg(long, value_delimiter = ',', default_value = "triangle")]
    pub rack_style: Vec<RackStyle>,
    /// Cue ball speeds, comma-separated: `V` (m/s) or `MIN:MAX` (uniform).
    #[arg(long, value_delimiter = ',', value_parser = parse_speed, default_value = "10:12")]
    pub speed: Vec<(f64, f64)>,
    /// Cue ball places, comma-separated: `box`, `kitchen`, `string`, `side` or `y:F` (on the
    /// head string at F in [0, 1] of the way from the head spot to a long cushion).
    #[arg(long, value_delimiter = ',', default_value = "box")]
    pub cue: Vec<Cue>,
    /// Breaks per row.
    #[arg(long, default_value_t = 1000)]
    pub breaks: u64,
    /// Seed of the study.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Gaussian aim error, standard deviation in degrees (FastFiz's at magnitude 1: 0.125).
    #[arg(long, default_value_t = 0.0, value_parser = parse_aim_sd)]
    pub aim_sd_deg: f64,
    /// Tip height as a fraction of the radius (negative: draw).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub tip_height: f64,
    /// A physical constant of the game's physics (Mathavan 2010 cushion) changed,
    /// `NAME=VALUE` (repeatable): mu_slide, mu_roll, e_ball, mu_ball, e_cushion, mu_cushion,
    /// young, poisson, mu_ball_slip, cushion_height.
    #[arg(long = "set", value_parser = parse_set)]
    pub set: Vec<(String, f64)>,
    /// Every contact resolved pair by pair (no cluster impacts).
    #[arg(long)]
    pub pairwise: bool,
    /// Run only slice K of M (`K/M`).
    #[arg(long, value_parser = parse_shard, conflicts_with = "merge")]
    pub shard: Option<Shard>,
    /// Combine these shard files (written by `--out`) instead of running.
    #[arg(long, num_args = 1..)]
    pub merge: Vec<PathBuf>,
    /// Write the result as JSON here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

fn parse_speed(s: &str) -> Result<(f64, f64), String> {
    let num = |x: &str| x.trim().parse::<f64>().map_err(|e| format!("{s:?}: {e}"));
    let (a, b) = match s.split_once(':') {
        Some((a, b)) => (num(a)?, num(b)?),
        None => (num(s)?, num(s)?),
    };
    if !(0.0 < a && a <= b && b <= 100.0) {
        return Err(format!(
            "{s:?}: expected V or MIN:MAX with 0 < MIN <= MAX <= 100 m/s"
        ));
    }
    Ok((a, b))
}

fn parse_aim_sd(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(d) if (0.0..=10.0).contains(&d) => Ok(d),
        _ => Err(format!("{s:?}: expected 0 to 10 degrees")),
    }
}

fn parse_set(s: &str) -> Result<(String, f64), String> {
    let (k, v) = s
        .split_once('=')
        .ok_or_else(|| format!("{s:?}: expected NAME=VALUE"))?;
    let v: f64 = v.parse().map_err(|e| format!("{s:?}: {e}"))?;
    Ok((k.trim().into(), v))
}

/// One row: a kind of break and its counts.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// The kind of break.
    pub spec: BreakSpec,
    /// The rack style.
    pub rack: RackStyle,
    /// Its counts over the breaks run here.
    pub stats: BreakStats,
}

/// A break study's result (or one shard's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BreaksResult {
    /// `"breaks"`.
    pub command: String,
    /// The slice run here; `None`: all of it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// Breaks per row.
    pub breaks: u64,
    /// Seed.
    pub seed: u64,
    /// Physical constants changed.
    pub set: Vec<(String, f64)>,
    /// Contacts pair by pair.
    pub pairwise: bool,
    /// The rows, in the order of the product game x table x rack x speed x cue.
    pub rows: Vec<Row>,
}

impl Batch for BreaksResult {
    const COMMAND: &'static str = "breaks";

    fn shard(&self) -> Option<Shard> {
        self.shard
    }

    fn set_shard(&mut self, shard: Option<Shard>) {
        self.shard = shard;
    }

    fn arguments(&self) -> serde_json::Value {
        let specs: Vec<_> = self.rows.iter().map(|r| (r.spec, r.rack)).collect();
        serde_json::json!({
            "breaks": self.breaks,
            "seed": self.seed,
            "set": self.set,
            "pairwise": self.pairwise,
            "rows": specs,
        })
    }

    fn check_items(&self) -> Result<(), String> {
        let shard = self.shard.unwrap_or(Shard::WHOLE);
        for (r, row) in self.rows.iter().enumerate() {
            let want = row_items(shard, r as u64, self.breaks).count() as u64;
            if row.stats.breaks as u64 != want {
                return Err(format!(
                    "row {} has {} breaks where its shard has {want}",
                    r + 1,
                    row.stats.breaks
                ));
            }
        }
        Ok(())
    }

    fn absorb(&mut self, other: Self) {
        for (a, b) in self.rows.iter_mut().zip(other.rows) {
            a.stats = a.stats.merged(b.stats);
        }
    }

    fn finish(&mut self) {}
}

/// The breaks `i` of row `row` that `shard` runs.
fn row_items(shard: Shard, row: u64, breaks: u64) -> impl Iterator<Item = u64> {
    (0..breaks).filter(move |i| shard.contains(row * breaks + i))
}

/// The rows the arguments ask for: game x table x rack x speed x cue.
fn rows(a: &BreaksArgs) -> Result<Vec<(BreakSpec, RackStyle)>, String> {
    let mut out = Vec::new();
    for &g in &a.game {
        let Some(game) = g.pool() else {
            return Err(
                "the break study is pool's: --game nine-ball, ten-ball or eight-ball".into(),
            );
        };
        if game == Game::FreePlay {
            return Err("free play has no break: --game nine-ball, ten-ball or eight-ball".into());
        }
        // 9-ball and 10-ball are played on 9-ft tables, 8-ball in bars on 7-ft ones.
        let default = [match game {
            Game::NineBall | Game::TenBall => "9ft",
            Game::EightBall | Game::FreePlay => "7ft",
        }
        .parse::<TableChoice>()?];
        let tables = if a.table.is_empty() {
            &default[..]
        } else {
            &a.table[..]
        };
        for &table in tables {
            for &rack in &a.rack_style {
                for &speed in &a.speed {
                    for &cue in &a.cue {
                        out.push((
                            BreakSpec {
                                game,
                                table,
                                gap: rack.gap(),
                                cue,
                                speed,
                                aim_sd: a.aim_sd_deg.to_radians(),
                                tip_height: a.tip_height,
                                elevation: 0.0,
                                nine_on_spot: false,
                            },
                            rack,
                        ));
                    }
                }
            }
        }
    }
    Ok(out)
}

/// Runs the breaks of shard `part` (`None`: all of them), on all cores.
pub fn study(a: &BreaksArgs, part: Option<Shard>) -> Result<BreaksResult, String> {
    let shard = part.unwrap_or(Shard::WHOLE);
    let specs = rows(a)?;
    let p = params(a.pairwise, &a.set)?;
    let work: Vec<(usize, u64)> = (0..specs.len())
        .flat_map(|r| row_items(shard, r as u64, a.breaks).map(move |i| (r, i)))
        .collect();
    let outcomes = work
        .par_iter()
        .map(|&(r, i)| {
            one_break(&specs[r].0, &p, &mut stream(a.seed, BREAKS, i))
                .map(|o| (r, o))
                .map_err(|e| format!("row {}, break {i}: {e}", r + 1))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut stats = vec![BreakStats::default(); specs.len()];
    for (r, o) in &outcomes {
        stats[*r].add(o);
    }
    Ok(BreaksResult {
        command: BreaksResult::COMMAND.into(),
        shard: part,
        breaks: a.breaks,
        seed: a.seed,
        set: a.set.clone(),
        pairwise: a.pairwise,
        rows: specs
            .into_iter()
            .zip(stats)
            .map(|((spec, rack), stats)| Row { spec, rack, stats })
            .collect(),
    })
}

/// The result as a Markdown table.
pub fn report(r: &BreaksResult) -> String {
    let mut out = format!(
        "{} breaks a row, seed {}{}{}\n",
        r.breaks,
        r.seed,
        if r.pairwise {
            ", contacts pair by pair"
        } else {
            ""
        },
        r.set
            .iter()
            .map(|(k, v)| format!(", {k} = {v}"))
            .collect::<String>()
    );
    out += "| game | table | rack | speed m/s | cue | aim sd | >= 1 ball (95 %) | balls/break | \
            scratch | legal | success | 9/8 on the break | events/break |\n";
    out += "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for row in &r.rows {
        let (s, st) = (&row.spec, &row.stats);
        let n = st.breaks.max(1) as f64;
        let pct = |k: usize| 100.0 * k as f64 / n;
        let (lo, hi) = wilson(st.with_ball, st.breaks);
        let (mean, half) = st.balls_per_break();
        out += &format!(
            "| {} | {} | {} | {}{} | {} | {:.3}° | {:.1} % ({lo:.1}–{hi:.1}) | {mean:.2} ± \
             {half:.2} | {:.1} % | {:.1} % | {:.1} % | {:.1} % | {:.0} |\n",
            match s.game {
                Game::NineBall => "9-ball",
                Game::TenBall => "10-ball",
                Game::EightBall => "8-ball",
                Game::FreePlay => "free play",
            },
            s.table,
            row.rack.name(),
            s.speed.0,
            if s.speed.1 > s.speed.0 {
                format!("–{}", s.speed.1)
            } else {
                String::new()
            },
            s.cue,
            s.aim_sd.to_degrees(),
            pct(st.with_ball),
            pct(st.scratches),
            pct(st.legal),
            pct(st.success),
            pct(st.money_ball),
            st.events as f64 / n,
        );
    }
    out
}

/// Runs `breaks`; returns the exit code (2: bad input or a refused merge, 1: a failure).
pub fn run(a: BreaksArgs) -> ExitCode {
    let result = if a.merge.is_empty() {
        if let Err(e) = crate::shard::fail_once("breaks", a.shard) {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
        if let Err(e) = rows(&a).and_then(|_| params(a.pairwise, &a.set)) {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
        match study(&a, a.shard) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::FAILURE;
            }
        }
    } else {
        match crate::shard::merge::<BreaksResult>(&a.merge) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    };
    if let Some(path) = &a.out
        && let Err(e) = crate::shard::write_json(&result, path)
    {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    print!("{}", report(&result));
    ExitCode::SUCCESS
}
