//! The computer at a drill ([`billiards_rules::Drill`]): each shot of an attempt chosen by one
//! of two methods, then struck with the level's execution noise and judged by the drill.
//!
//! - [`Method::Rules`], for a run-out: the game's own search ([`crate::decide`]) on the
//!   drill's rules state ([`Drill::game_state`]), which already plays for the legal order and
//!   the next shot; the drill's judge only scores what it did.
//! - [`Method::Goals`], for everything else: the rules' search cannot see a drill's goal
//!   ("stop the cue ball in the circle"), so the candidates of the search ([`candidates`]:
//!   pots, banks, kicks, safeties, in many speeds and tips) are each simulated under the
//!   level's planning noise and scored by [`Drill::judge`] itself; the best (success rate,
//!   then mean score) is refined with small aim offsets (throw, a cut's squirt) and more
//!   samples.

use crate::candidates::{self, Candidate, Layout};
use crate::noise::{Noise, stream};
use crate::{AiError, Decision, Level};
use billiards_physics::{Params, Shot, Simulation, TipOffset};
use billiards_rules::drill::resting;
use billiards_rules::{Attempt, CUE, Drill, DrillScore, DrillShot, Goal};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// How the computer chooses a drill's shots.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// The game's search under the drill's rules (run-outs).
    Rules,
    /// Candidates scored by the drill's own judge.
    Goals,
}

impl Method {
    /// The method for `drill`: the rules for a run-out, the goals otherwise.
    pub fn of(drill: &Drill) -> Method {
        if drill.goals.contains(&Goal::RunOut) {
            Method::Rules
        } else {
            Method::Goals
        }
    }
}

/// A session of the computer at a drill.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Session {
    /// How its shots were chosen.
    pub method: Method,
    /// Each attempt's judgement, in order.
    pub attempts: Vec<Attempt>,
    /// The tally.
    pub score: DrillScore,
}

/// Speeds tried, as multiples of the speed an aim needs to reach its pocket.
const SPEEDS: [f64; 6] = [0.8, 1.0, 1.3, 1.7, 2.2, 3.0];

/// Tips tried on straight and cut shots: stun, follow, draw, and english either side.
const TIPS: [TipOffset; 8] = [
    TipOffset {
        side: 0.0,
        height: 0.0,
    },
    TipOffset {
        side: 0.0,
        height: 0.25,
    },
    TipOffset {
        side: 0.0,
        height: 0.45,
    },
    TipOffset {
        side: 0.0,
        height: -0.25,
    },
    TipOffset {
        side: 0.0,
        height: -0.45,
    },
    TipOffset {
        side: 0.0,
        height: -0.6,
    },
    TipOffset {
        side: 0.3,
        height: 0.0,
    },
    TipOffset {
        side: -0.3,
        height: 0.0,
    },
];

/// Aim offsets of the refinement: -3 to 3 degrees in steps of 0.25 (throw, a cut's error;
/// a cushion is not a mirror, so banks and kicks want the wider ones).
const OFFSETS: std::ops::RangeInclusive<i32> = -12..=12;

/// Events a sampled shot may run before it is scored as it stands.
const MAX_EVENTS: usize = 3000;

/// The shot the computer at `level` plays next in an attempt at `drill` on `sim` (at rest),
/// after `shots` of the attempt, the search's draws from `seed`.
pub fn decide_drill(
    drill: &Drill,
    sim: &Simulation,
    shots: &[DrillShot],
    level: Level,
    seed: u64,
) -> Result<Shot, AiError> {
    match Method::of(drill) {
        Method::Rules => {
            let mut state = drill.game_state();
            for s in shots {
                state
                    .play(&s.summary, billiards_rules::Call::None)
                    .map_err(|_| AiError::GameOver)?;
            }
            match crate::decide(&state, sim, level, seed)? {
                Decision::Shoot(plan) => Ok(plan.shot),
                Decision::Choose { .. } => Err(AiError::GameOver),
            }
        }
        Method::Goals => goal_search(drill, sim, shots, level.planning_noise(), seed),
    }
}

/// The goal search of [`Method::Goals`].
fn goal_search(
    drill: &Drill,
    sim: &Simulation,
    shots: &[DrillShot],
    noise: Noise,
    seed: u64,
) -> Result<Shot, AiError> {
    if !sim.is_at_rest() {
        return Err(AiError::NotAtRest);
    }
    let layout = Layout::of(sim, None).ok_or(AiError::NoCueBall)?;
    let mut base = sim.clone();
    base.set_record_history(false);
    let cands = candidates_for(drill, &layout);
    if cands.is_empty() {
        return Err(AiError::NoBall);
    }
    let eval =
        |shot: Shot, id: u64, n: u64| sample_mean(drill, &base, shots, shot, noise, seed, id, n);
    // Round 1: every candidate, 4 samples.
    let mut scored: Vec<(Shot, (f64, f64))> = cands
        .par_iter()
        .enumerate()
        .map(|(i, c)| (c.shot, eval(c.shot, i as u64, 4)))
        .collect();
    sort(&mut scored);
    // Round 2: the best 8 at small aim offsets, 6 samples.
    let mut refined: Vec<(Shot, (f64, f64))> = scored
        .iter()
        .take(8)
        .flat_map(|&(s, _)| {
            OFFSETS.map(move |k| Shot {
                angle: s.angle + (0.25 * f64::from(k)).to_radians(),
                ..s
            })
        })
        .collect::<Vec<_>>()
        .par_iter()
        .enumerate()
        .map(|(i, &s)| (s, eval(s, 10_000 + i as u64, 6)))
        .collect();
    sort(&mut refined);
    // Round 3: the best 4, 24 samples more.
    let mut last: Vec<(Shot, (f64, f64))> = refined
        .iter()
        .take(4)
        .collect::<Vec<_>>()
        .par_iter()
        .enumerate()
        .map(|(i, &&(s, _))| (s, eval(s, 20_000 + i as u64, 24)))
        .collect();
    sort(&mut last);
    Ok(last[0].0)
}

/// Best first: success rate, then mean score.
fn sort(v: &mut [(Shot, (f64, f64))]) {
    v.sort_by(|a, b| b.1.0.total_cmp(&a.1.0).then(b.1.1.total_cmp(&a.1.1)));
}

/// The candidates of the search for `drill`: aims at the balls its goals name (every object
/// ball when none is named), pots and banks and kicks in [`SPEEDS`] and [`TIPS`], and
/// safeties when a goal wants nothing pocketed or the ball hidden.
fn candidates_for(drill: &Drill, layout: &Layout) -> Vec<Candidate> {
    let mut balls: Vec<u8> = drill
        .goals
        .iter()
        .filter_map(|g| match *g {
            Goal::Pocket { ball, .. } | Goal::FirstContact { ball, .. } => Some(ball),
            _ => None,
        })
        .collect();
    if balls.is_empty() {
        balls = drill.game_state().next.legal_first;
    }
    let pocket_of = |b: u8| {
        drill.goals.iter().find_map(|g| match *g {
            Goal::Pocket { ball, pocket, .. } if ball == b => pocket,
            _ => None,
        })
    };
    let wanted = |kind: crate::ShotKind| match kind {
        crate::ShotKind::Pot { ball, pocket }
        | crate::ShotKind::Bank { ball, pocket, .. }
        | crate::ShotKind::Kick { ball, pocket, .. }
        | crate::ShotKind::Combo { ball, pocket, .. } => {
            pocket_of(ball).is_none_or(|p| p == pocket)
        }
        _ => true,
    };
    let mut aims = candidates::direct_aims(layout, &balls);
    aims.extend(candidates::rail_aims(layout, &balls));
    aims.retain(|a| wanted(a.kind));
    let mut out = candidates::expand(&aims, &SPEEDS, &TIPS, false, None);
    let safe = drill.goals.iter().any(|g| {
        matches!(
            g,
            Goal::NoPocket | Goal::Hide { .. } | Goal::FirstContact { .. }
        )
    });
    if safe {
        out.extend(candidates::safeties(layout, &balls, 13, None));
        // The safeties' speeds again, softer and firmer.
        let extra: Vec<Candidate> = out
            .iter()
            .filter(|c| matches!(c.kind, crate::ShotKind::Safety { .. }))
            .flat_map(|c| {
                [0.6, 1.4].map(|k| Candidate {
                    shot: Shot {
                        speed: c.shot.speed * k,
                        ..c.shot
                    },
                    ..*c
                })
            })
            .collect();
        out.extend(extra);
    }
    out
}

/// The success rate and mean score of `n` noisy samples of `shot` after `shots`.
#[allow(clippy::too_many_arguments)]
fn sample_mean(
    drill: &Drill,
    base: &Simulation,
    shots: &[DrillShot],
    shot: Shot,
    noise: Noise,
    seed: u64,
    id: u64,
    n: u64,
) -> (f64, f64) {
    let mut list = shots.to_vec();
    let (mut ok, mut score) = (0.0, 0.0);
    for k in 0..n {
        let s = noise.apply(shot, base.params(), &mut stream(seed, id, k));
        let mut sim = base.clone();
        let Some(one) = strike_lean(&mut sim, s) else {
            continue;
        };
        list.truncate(shots.len());
        list.push(one);
        let a = drill.judge(&list);
        ok += f64::from(u8::from(a.success));
        score += a.score;
    }
    (ok / n as f64, score / n as f64)
}

/// Strikes the cue ball of `sim` (lean) and runs it to rest, recording the drill's facts.
fn strike_lean(sim: &mut Simulation, shot: Shot) -> Option<DrillShot> {
    let cue = sim.numbers().iter().position(|&n| n == CUE)?;
    sim.strike(cue, shot).ok()?;
    let mut one = DrillShot::default();
    let mut events = 0;
    while let Some(e) = sim.step_event() {
        one.record(&e.kind, sim.numbers());
        events += 1;
        if events > MAX_EVENTS {
            break;
        }
    }
    one.rest = resting(sim);
    Some(one)
}

/// One attempt at `drill` by the computer at `level`: shots chosen by [`decide_drill`] and
/// struck with the level's execution noise (from `seed`) until the drill's attempt ends
/// ([`Drill::continues`]); `params` are the player's physics (the drill's own win). The
/// first shot, from the drill's position, is `first` when given (a session decides it once).
pub fn attempt(
    drill: &Drill,
    params: Params,
    level: Level,
    seed: u64,
    first: Option<Shot>,
) -> Result<Attempt, String> {
    let mut sim = drill.simulation(params).map_err(|e| e.to_string())?;
    let mut shots: Vec<DrillShot> = Vec::new();
    let mut k = 0u64;
    while drill.continues(&shots) {
        let cue = sim
            .numbers()
            .iter()
            .position(|&n| n == CUE)
            .ok_or("no cue ball")?;
        if !sim.ball(cue).motion.on_table() {
            break;
        }
        let shot = match first.filter(|_| k == 0) {
            Some(s) => s,
            None => decide_drill(drill, &sim, &shots, level, stream(seed, 1, k).random_u64())
                .map_err(|e| format!("shot {}: {e}", k + 1))?,
        };
        let struck = level
            .execution_noise()
            .apply(shot, sim.params(), &mut stream(seed, 2, k));
        let from = sim.history().events().len();
        sim.strike(cue, struck).map_err(|e| e.to_string())?;
        sim.run_to_rest().map_err(|e| e.to_string())?;
        shots.push(DrillShot::of(&sim, from));
        k += 1;
    }
    Ok(drill.judge(&shots))
}

/// `tries` attempts, judged and tallied: the first shot decided once from `seed`, each
/// attempt's noise and later decisions from its own seed drawn from `seed`.
pub fn session(
    drill: &Drill,
    params: Params,
    level: Level,
    tries: u32,
    seed: u64,
) -> Result<Session, String> {
    let sim = drill.simulation(params).map_err(|e| e.to_string())?;
    let first = decide_drill(drill, &sim, &[], level, seed).map_err(|e| format!("shot 1: {e}"))?;
    let mut score = DrillScore::default();
    let mut attempts = Vec::new();
    for t in 0..tries {
        let s = stream(seed, 3, u64::from(t)).random_u64();
        let a = attempt(drill, params, level, s, Some(first))?;
        score.add(&a);
        attempts.push(a);
    }
    Ok(Session {
        method: Method::of(drill),
        attempts,
        score,
    })
}

/// A random `u64` from a stream (the streams' first draw).
trait First {
    fn random_u64(self) -> u64;
}

impl First for rand_chacha::ChaCha8Rng {
    fn random_u64(mut self) -> u64 {
        rand::Rng::random(&mut self)
    }
}

/// The game's default physics for drills: the spin model with Mathavan 2010's cushion and
/// its fitted constants (the game's settings default since issue 24), 15 mm jaws being the
/// drill's table's own.
pub fn game_params() -> Params {
    Params {
        model: billiards_physics::Model::Spin(billiards_physics::SpinModel {
            cushion: billiards_physics::CushionModel::MATHAVAN_2010,
            ..Default::default()
        }),
        ..Params::default()
    }
}
