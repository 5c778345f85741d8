//! Soak testing: many random scenes (breaks, shots on scattered layouts, follow-up shots),
//! each reproducible from one seed, run on all cores with every event checked by
//! [`check::Monitor`](crate::check::Monitor).
//!
//! Used by `examples/soak.rs` (long runs, progress bar, `--seed` replay) and by the
//! `soak` integration test (a bounded run in CI).

use crate::ball::BallId;
use crate::check::{Monitor, Stats, Tolerances, Violation};
use crate::event::Event;
use crate::sim::Simulation;
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};

mod carom;
mod clusters;
mod scenes;
pub use carom::carom_scenario;
pub use clusters::cluster_scenario;
pub use scenes::{
    SOAK_EVENT_CAP, Scenario, Variation, has_friction, models, scale_friction, scenario, vary,
};

/// The ball a scene's shot is played on: the cue ball, or the lowest-numbered ball in play.
fn shooter(sim: &Simulation) -> Option<BallId> {
    (0..sim.ball_count()).find(|&i| sim.ball(i).motion.on_table())
}

/// What one scene measured.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SceneStats {
    /// Shots played.
    pub shots: u64,
    /// Most events in one shot.
    pub most_events: usize,
    /// Invariant figures over the whole scene.
    pub check: Stats,
}

/// Runs scene `s` with every event checked.
pub fn run_scenario(s: &Scenario, tol: Tolerances) -> Result<SceneStats, Violation> {
    run_scenario_traced(s, tol, &mut |_| {})
}

/// [`run_scenario`], calling `trace` with every event processed (for replays).
pub fn run_scenario_traced(
    s: &Scenario,
    tol: Tolerances,
    trace: &mut dyn FnMut(&Event),
) -> Result<SceneStats, Violation> {
    let mut sim = Simulation::new(s.table, s.params, &s.balls)
        .unwrap_or_else(|e| panic!("scene {} cannot be built: {e}", s.seed));
    let mut monitor = Monitor::new(&sim, tol)?;
    let mut stats = SceneStats::default();
    for shot in &s.shots {
        let Some(ball) = shooter(&sim) else { break };
        monitor
            .strike(&mut sim, ball, *shot)
            .expect("a valid shot on a ball in play");
        let before = monitor.stats().events;
        let seen = sim.history().events().len();
        match s.duration {
            None => {
                let mut count = 0;
                while let Some(e) = monitor.step(&mut sim)? {
                    trace(&e);
                    count += 1;
                    if count == s.params.max_events && sim.next_event_time().is_some() {
                        return Err(Violation::EventCap {
                            events: count,
                            cap: count,
                            time: sim.time(),
                        });
                    }
                }
            }
            Some(d) => {
                let until = sim.time() + d;
                let r = monitor.run_until(&mut sim, until);
                for e in &sim.history().events()[seen..] {
                    trace(e);
                }
                r?;
            }
        }
        stats.shots += 1;
        stats.most_events = stats.most_events.max(monitor.stats().events - before);
    }
    stats.check = monitor.stats();
    Ok(stats)
}

/// A scene that broke an invariant (or panicked), with what is needed to replay it.
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// Its seed: `cargo run --release -p billiards-physics --example soak -- --seed <seed>`.
    pub seed: u64,
    /// Model configuration name.
    pub model: &'static str,
    /// Scene kind.
    pub kind: &'static str,
    /// What went wrong.
    pub what: String,
}

/// Runs scene `seed`, turning a violation or a panic into a [`Failure`].
pub fn run_seed(seed: u64, tol: Tolerances) -> Result<SceneStats, Failure> {
    run_drawn(scenario(seed), tol)
}

/// Runs cluster scene `seed` ([`cluster_scenario`]), as [`run_seed`].
pub fn run_cluster_seed(seed: u64, tol: Tolerances) -> Result<SceneStats, Failure> {
    run_drawn(cluster_scenario(seed), tol)
}

fn run_drawn(s: Scenario, tol: Tolerances) -> Result<SceneStats, Failure> {
    let seed = s.seed;
    let fail = |what: String| Failure {
        seed,
        model: s.model,
        kind: s.kind,
        what,
    };
    match std::panic::catch_unwind(|| run_scenario(&s, tol)) {
        Ok(Ok(stats)) => Ok(stats),
        Ok(Err(v)) => Err(fail(v.to_string())),
        Err(panic) => {
            let msg = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown panic".into());
            Err(fail(format!("panicked: {msg}")))
        }
    }
}

/// What a soak runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoakConfig {
    /// Number of scenes (seeds `first_seed..first_seed + scenes`).
    pub scenes: u64,
    /// First seed.
    pub first_seed: u64,
    /// Worker threads (0: one per core).
    pub threads: usize,
    /// Tolerances of the checks.
    pub tolerances: Tolerances,
    /// Run the cluster scenes ([`cluster_scenario`]) instead of [`scenario`]'s.
    pub clusters: bool,
}

/// A soak's results.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SoakReport {
    /// Scenes run.
    pub scenes: u64,
    /// Shots played (every strike, follow-up shots included).
    pub shots: u64,
    /// Invariant figures over every passing scene (events summed, worst of the rest).
    pub check: Stats,
    /// Most events in one shot.
    pub most_events: usize,
    /// Seed of the shot with the most events.
    pub most_events_seed: u64,
    /// Seed of the scene with the largest relative energy gain (`check.worst_energy_gain`).
    pub worst_energy_gain_seed: u64,
    /// Every failing scene, by seed.
    pub failures: Vec<Failure>,
    /// Wall-clock time, seconds.
    pub seconds: f64,
}

/// Runs `cfg.scenes` scenes on `cfg.threads` threads; `done` (if given) counts finished scenes
/// as they complete, for a progress display.
pub fn soak(cfg: &SoakConfig, done: Option<&AtomicU64>) -> SoakReport {
    let start = std::time::Instant::now();
    let threads = match cfg.threads {
        0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
        n => n,
    };
    let next = AtomicU64::new(0);
    let report = Mutex::new(SoakReport::default());
    const CHUNK: u64 = 16;
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                let mut local = SoakReport::default();
                loop {
                    let from = next.fetch_add(CHUNK, Ordering::Relaxed);
                    if from >= cfg.scenes {
                        break;
                    }
                    let to = (from + CHUNK).min(cfg.scenes);
                    for i in from..to {
                        let seed = cfg.first_seed.wrapping_add(i);
                        local.scenes += 1;
                        let run = if cfg.clusters {
                            run_cluster_seed
                        } else {
                            run_seed
                        };
                        match run(seed, cfg.tolerances) {
                            Ok(s) => {
                                local.shots += s.shots;
                                if s.check.worst_energy_gain > local.check.worst_energy_gain {
                                    local.worst_energy_gain_seed = seed;
                                }
                                local.check.merge(&s.check);
                                if s.most_events > local.most_events {
                                    local.most_events = s.most_events;
                                    local.most_events_seed = seed;
                                }
                            }
                            Err(f) => local.failures.push(f),
                        }
                    }
                    if let Some(d) = done {
                        d.fetch_add(to - from, Ordering::Relaxed);
                    }
                }
                let mut r = report.lock().expect("no worker panics while holding it");
                r.scenes += local.scenes;
                r.shots += local.shots;
                if local.check.worst_energy_gain > r.check.worst_energy_gain {
                    r.worst_energy_gain_seed = local.worst_energy_gain_seed;
                }
                r.check.merge(&local.check);
                if local.most_events > r.most_events {
                    r.most_events = local.most_events;
                    r.most_events_seed = local.most_events_seed;
                }
                r.failures.extend(local.failures);
            });
        }
    });
    let mut r = report.into_inner().expect("workers finished");
    r.failures.sort_by_key(|f| f.seed);
    r.seconds = start.elapsed().as_secs_f64();
    r
}
