//! The soak's scenes: the model configurations under test, their random variations, and the
//! scene each seed draws (`clusters.rs` draws the cluster scenes from the same seed).

use crate::event::{Shot, TipOffset};
use crate::params::{CushionModel, Model, PaperModel, Params, Randomization, SpinModel};
use crate::racks::{Rack, scattered};
use crate::sim::BallSetup;
use crate::table::Table;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Every model configuration the stability invariants are checked for, by name. Each is run
/// with [`crate::Prediction::Exact`] (the paper's linear prediction is a comparison mode, not
/// subject to them). Adding a model here puts it under every stress test and the soak.
pub fn models() -> Vec<(&'static str, Params)> {
    let paper = |m: PaperModel| Params {
        model: Model::Paper(m),
        ..Params::default()
    };
    vec![
        // The paper's constants: elastic balls and cushions.
        ("paper", Params::default()),
        // Realistic restitution (the reference's typical values).
        (
            "paper-inelastic",
            paper(PaperModel {
                e_ball: 0.95,
                e_cushion: 0.85,
                ..PaperModel::default()
            }),
        ),
        // Spin, throw and Han's cushion with the reference's typical constants.
        (
            "spin",
            Params {
                model: Model::Spin(SpinModel::default()),
                ..Params::default()
            },
        ),
    ]
}

/// Changes to a model's constants, applied by [`vary`]: the knobs property tests and the soak
/// turn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variation {
    /// Factor on every friction coefficient (0: frictionless).
    pub friction: f64,
    /// Ball–ball restitution.
    pub e_ball: f64,
    /// Ball–cushion restitution.
    pub e_cushion: f64,
    /// Factor on the slide/roll threshold speed (the paper's model; the spin model has none).
    pub threshold: f64,
    /// Perturbation of collision normals.
    pub randomization: Option<Randomization>,
}

/// `params` with the constants of its model changed by `v`.
pub fn vary(params: Params, v: &Variation) -> Params {
    let model = match params.model {
        Model::Paper(m) => Model::Paper(PaperModel {
            mu_slide: m.mu_slide * v.friction,
            mu_roll: m.mu_roll * v.friction,
            slide_roll_speed: m.slide_roll_speed * v.threshold,
            e_ball: v.e_ball,
            e_cushion: v.e_cushion,
        }),
        Model::Spin(m) => Model::Spin(SpinModel {
            mu_slide: m.mu_slide * v.friction,
            mu_roll: m.mu_roll * v.friction,
            mu_spin: m.mu_spin * v.friction,
            e_ball: v.e_ball,
            cushion: match m.cushion {
                CushionModel::Reflect { .. } => CushionModel::Reflect { e: v.e_cushion },
                CushionModel::Han2005 { mu, .. } => CushionModel::Han2005 { e: v.e_cushion, mu },
                CushionModel::Mathavan2010 { mu, .. } => {
                    CushionModel::Mathavan2010 { e: v.e_cushion, mu }
                }
            },
            ..m
        }),
    };
    Params {
        model,
        randomization: v.randomization,
        ..params
    }
}

/// `params` with every friction coefficient of its model multiplied by `k` (0: frictionless).
pub fn scale_friction(params: Params, k: f64) -> Params {
    let model = match params.model {
        Model::Paper(m) => Model::Paper(PaperModel {
            mu_slide: m.mu_slide * k,
            mu_roll: m.mu_roll * k,
            ..m
        }),
        Model::Spin(m) => Model::Spin(SpinModel {
            mu_slide: m.mu_slide * k,
            mu_roll: m.mu_roll * k,
            mu_spin: m.mu_spin * k,
            ..m
        }),
    };
    Params { model, ..params }
}

/// Whether a model's balls ever come to rest by themselves (some friction somewhere).
pub fn has_friction(params: &Params) -> bool {
    match params.model {
        Model::Paper(m) => m.mu_slide > 0.0 && m.mu_roll > 0.0 && params.gravity > 0.0,
        Model::Spin(m) => {
            m.mu_slide > 0.0 && m.mu_roll > 0.0 && m.mu_spin > 0.0 && params.gravity > 0.0
        }
    }
}

/// One random scene, fully determined by its seed.
#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    /// The seed it was drawn from.
    pub seed: u64,
    /// Name of the model configuration (from [`models`]).
    pub model: &'static str,
    /// What kind of scene: "break", "shot" or "moving".
    pub kind: &'static str,
    /// The table.
    pub table: Table,
    /// The parameters.
    pub params: Params,
    /// The layout at time 0.
    pub balls: Vec<BallSetup>,
    /// Shots, each played when the previous one has come to rest (or its time is up), on the
    /// cue ball or, if it is pocketed, the lowest-numbered ball in play.
    pub shots: Vec<Shot>,
    /// Simulated seconds each shot runs for, if the balls never rest by themselves.
    pub duration: Option<f64>,
}

/// Most events one shot of a soak scene may take before it counts as a failure (the default
/// `Params::max_events`).
pub const SOAK_EVENT_CAP: usize = 1_000_000;

pub(super) fn log_uniform(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    (lo.ln() + (hi.ln() - lo.ln()) * rng.random::<f64>()).exp()
}

/// A restitution: often exactly 1 or 0 (edge cases), otherwise uniform.
pub(super) fn restitution(rng: &mut ChaCha8Rng) -> f64 {
    match rng.random_range(0..10) {
        0..=1 => 1.0,
        2 => 0.0,
        _ => rng.random::<f64>(),
    }
}

/// A cue tip offset: half the time the centre, otherwise anywhere within 0.45 R of it (inside
/// the default miscue limit). Only the spin model uses it.
pub(super) fn tip(rng: &mut ChaCha8Rng) -> TipOffset {
    if rng.random_bool(0.5) {
        return TipOffset::default();
    }
    let (a, r) = (
        rng.random_range(0.0..std::f64::consts::TAU),
        0.45 * rng.random::<f64>().sqrt(),
    );
    TipOffset {
        side: r * a.cos(),
        height: r * a.sin(),
    }
}

/// The scene for `seed`.
pub fn scenario(seed: u64) -> Scenario {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let all = models();
    let (model, base) = all[rng.random_range(0..all.len())];
    let base = Params {
        max_events: SOAK_EVENT_CAP,
        ..base
    };
    let params = if rng.random_bool(0.5) {
        base
    } else {
        // Friction from a fiftieth to fifty times the model's (or none at all). Far lower
        // friction makes a resting contact (a ball pressed into a cushion or another ball)
        // last so long that its hops exceed the event cap: see the crate README.
        let friction = match rng.random_range(0..20) {
            0 => 0.0,
            _ => log_uniform(&mut rng, 0.02, 50.0),
        };
        let v = Variation {
            friction,
            e_ball: restitution(&mut rng),
            e_cushion: restitution(&mut rng),
            threshold: log_uniform(&mut rng, 1e-3, 10.0),
            randomization: rng.random_bool(0.3).then(|| Randomization {
                spread: rng.random_range(0.0..0.1),
                seed: rng.random(),
            }),
        };
        vary(base, &v)
    };
    let table = if rng.random_bool(0.9) {
        Table::wpa_8ft()
    } else {
        Table::scaled(rng.random_range(1.0..3.0))
    };
    // Pockets as the paper's mouths, or with rounded jaws a ball can rattle between.
    let table = if rng.random_bool(0.5) {
        table
    } else {
        table.with_jaws(rng.random_range(0.005..0.03))
    };
    let speed = |rng: &mut ChaCha8Rng| {
        if rng.random_bool(0.2) {
            log_uniform(rng, 1e-9, 100.0)
        } else {
            rng.random_range(0.5..12.0)
        }
    };
    let (kind, balls, first) = match rng.random_range(0..10) {
        0..=4 => {
            let rack = [Rack::FifteenBall, Rack::Tight, Rack::NineBall][rng.random_range(0..3)];
            let balls = rack.layout(&table, &params.ball);
            // At the apex, or anywhere near it (cut breaks), sometimes dead straight.
            let aim = table.foot_spot() - balls[0].position;
            let jitter = match rng.random_range(0..4) {
                0 => 0.0,
                _ => rng.random_range(-0.05..0.05),
            };
            let first = Shot {
                angle: aim.angle() + jitter,
                speed: if rng.random_bool(0.8) {
                    rng.random_range(3.0..14.0)
                } else {
                    speed(&mut rng)
                },
                tip: tip(&mut rng),
                elevation: 0.0,
            };
            ("break", balls, first)
        }
        k => {
            let n = rng.random_range(1..=16);
            let moving = k == 9;
            let max_speed = if moving {
                rng.random_range(0.0..5.0)
            } else {
                0.0
            };
            let balls = scattered(&table, &params.ball, n, max_speed, rng.random());
            let first = Shot {
                angle: rng.random_range(-std::f64::consts::PI..std::f64::consts::PI),
                speed: speed(&mut rng),
                tip: tip(&mut rng),
                elevation: 0.0,
            };
            (if moving { "moving" } else { "shot" }, balls, first)
        }
    };
    let mut shots = vec![first];
    for _ in 0..rng.random_range(0..=3) {
        shots.push(Shot {
            angle: rng.random_range(-std::f64::consts::PI..std::f64::consts::PI),
            speed: speed(&mut rng),
            tip: tip(&mut rng),
            elevation: 0.0,
        });
    }
    let duration = (!has_friction(&params)).then_some(3.0);
    Scenario {
        seed,
        model,
        kind,
        table,
        params,
        balls,
        shots,
        duration,
    }
}
