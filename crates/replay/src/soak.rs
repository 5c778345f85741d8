//! `soak`: the physics crate's soak ([`billiards_physics::soak`]) as a batch command. Scene
//! `i` is seed `first_seed + i`, run with every event checked; the figures are sums of
//! counts and maxima, and the scene with the most events in one shot is the lowest seed
//! among equals, so any split into shards merges to one process's result exactly.
//!
//! Exit status: 0 when every scene passed; 1 when one failed, except for a shard
//! (`--shard`), whose failures are results for the merge to report (its exit status is 0,
//! so a runner does not retry it).

use crate::shard::{Batch, Shard, parse_shard};
use billiards_physics::check::Tolerances;
use billiards_physics::soak::run_seed;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;
use std::process::ExitCode;

/// `soak` options.
#[derive(clap::Args, Debug)]
pub struct SoakArgs {
    /// Scenes in the whole soak.
    #[arg(long, default_value_t = 10_000)]
    pub scenes: u64,
    /// The first scene's seed (scene `i` is seed `first_seed + i`).
    #[arg(long, default_value_t = 0)]
    pub first_seed: u64,
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

/// A scene that broke an invariant (or panicked).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SoakFailure {
    /// Its seed: `cargo run --release -p billiards-physics --example soak -- --seed SEED`.
    pub seed: u64,
    /// The model configuration.
    pub model: String,
    /// The kind of scene.
    pub kind: String,
    /// What went wrong.
    pub what: String,
}

/// A soak's figures over the scenes run (passing scenes only, but for `scenes`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SoakTotals {
    /// Scenes run, failing ones included.
    pub scenes: u64,
    /// Shots played.
    pub shots: u64,
    /// Events processed.
    pub events: u64,
    /// Deepest overlap, metres.
    pub worst_overlap: f64,
    /// Largest relative kinetic-energy gain where energy may not rise.
    pub worst_energy_gain: f64,
    /// Largest relative momentum change at a ball–ball contact.
    pub worst_momentum: f64,
    /// Most events in one burst.
    pub longest_burst: u64,
    /// Most events in one shot.
    pub most_events: u64,
    /// The lowest seed with that many.
    pub most_events_seed: u64,
}

impl SoakTotals {
    /// Both together (order does not matter: sums, maxima, the lowest seed among equals).
    pub fn merged(self, o: SoakTotals) -> SoakTotals {
        let (most_events, most_events_seed) = match self.most_events.cmp(&o.most_events) {
            std::cmp::Ordering::Greater => (self.most_events, self.most_events_seed),
            std::cmp::Ordering::Less => (o.most_events, o.most_events_seed),
            std::cmp::Ordering::Equal => (
                self.most_events,
                self.most_events_seed.min(o.most_events_seed),
            ),
        };
        SoakTotals {
            scenes: self.scenes + o.scenes,
            shots: self.shots + o.shots,
            events: self.events + o.events,
            worst_overlap: self.worst_overlap.max(o.worst_overlap),
            worst_energy_gain: self.worst_energy_gain.max(o.worst_energy_gain),
            worst_momentum: self.worst_momentum.max(o.worst_momentum),
            longest_burst: self.longest_burst.max(o.longest_burst),
            most_events,
            most_events_seed,
        }
    }
}

/// A soak's result (or one shard's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SoakResult {
    /// `"soak"`.
    pub command: String,
    /// The slice run here; `None`: all of it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// Scenes in the whole soak.
    pub scenes: u64,
    /// The first seed.
    pub first_seed: u64,
    /// The figures.
    pub totals: SoakTotals,
    /// Every failing scene, by seed.
    pub failures: Vec<SoakFailure>,
}

impl Batch for SoakResult {
    const COMMAND: &'static str = "soak";

    fn shard(&self) -> Option<Shard> {
        self.shard
    }

    fn set_shard(&mut self, shard: Option<Shard>) {
        self.shard = shard;
    }

    fn arguments(&self) -> serde_json::Value {
        serde_json::json!({ "scenes": self.scenes, "first_seed": self.first_seed })
    }

    fn check_items(&self) -> Result<(), String> {
        let want = self.shard.unwrap_or(Shard::WHOLE).count(self.scenes);
        if self.totals.scenes != want {
            return Err(format!(
                "{} scenes where its shard has {want}",
                self.totals.scenes
            ));
        }
        Ok(())
    }

    fn absorb(&mut self, other: Self) {
        self.totals = self.totals.merged(other.totals);
        self.failures.extend(other.failures);
    }

    fn finish(&mut self) {
        self.failures.sort_by_key(|f| f.seed);
    }
}

/// Runs the scenes of shard `part` (`None`: all of them) on all cores.
pub fn soak(scenes: u64, first_seed: u64, part: Option<Shard>) -> SoakResult {
    let shard = part.unwrap_or(Shard::WHOLE);
    let runs: Vec<_> = crate::shard::items(shard, scenes)
        .collect::<Vec<_>>()
        .into_par_iter()
        .map(|i| {
            let seed = first_seed.wrapping_add(i);
            (seed, run_seed(seed, Tolerances::default()))
        })
        .collect();
    let mut totals = SoakTotals::default();
    let mut failures = Vec::new();
    for (seed, r) in runs {
        let one = match r {
            Ok(s) => SoakTotals {
                scenes: 1,
                shots: s.shots,
                events: s.check.events as u64,
                worst_overlap: s.check.worst_overlap,
                worst_energy_gain: s.check.worst_energy_gain,
                worst_momentum: s.check.worst_momentum,
                longest_burst: s.check.longest_burst as u64,
                most_events: s.most_events as u64,
                most_events_seed: seed,
            },
            Err(f) => {
                failures.push(SoakFailure {
                    seed,
                    model: f.model.into(),
                    kind: f.kind.into(),
                    what: f.what,
                });
                SoakTotals {
                    scenes: 1,
                    most_events_seed: seed,
                    ..SoakTotals::default()
                }
            }
        };
        totals = totals.merged(one);
    }
    SoakResult {
        command: SoakResult::COMMAND.into(),
        shard: part,
        scenes,
        first_seed,
        totals,
        failures,
    }
}

/// The result in words.
pub fn report(r: &SoakResult) -> String {
    let t = &r.totals;
    let mut out = format!(
        "{} scenes (seeds {} to {}), {} shots, {} events; worst overlap {:.3e} m, energy gain \
         {:.3e}, momentum {:.3e}; longest burst {} events; most events in a shot {} (seed {})\n",
        t.scenes,
        r.first_seed,
        r.first_seed.wrapping_add(r.scenes.saturating_sub(1)),
        t.shots,
        t.events,
        t.worst_overlap,
        t.worst_energy_gain,
        t.worst_momentum,
        t.longest_burst,
        t.most_events,
        t.most_events_seed
    );
    for f in &r.failures {
        out += &format!(
            "FAILED seed {} ({} {}): {} (replay: cargo run --release -p billiards-physics \
             --example soak -- --seed {})\n",
            f.seed, f.model, f.kind, f.what, f.seed
        );
    }
    if r.failures.is_empty() {
        out += "every scene passed\n";
    }
    out
}

/// Runs `soak`; returns the exit code.
pub fn run(a: SoakArgs) -> ExitCode {
    let result = if a.merge.is_empty() {
        if let Err(e) = crate::shard::fail_once("soak", a.shard) {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
        soak(a.scenes, a.first_seed, a.shard)
    } else {
        match crate::shard::merge::<SoakResult>(&a.merge) {
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
    if result.failures.is_empty() || result.shard.is_some() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
