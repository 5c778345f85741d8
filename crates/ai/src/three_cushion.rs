//! The computer at three-cushion: a search with the solver. Every cue-ball direction around
//! the ball (a fine fan), in a few speeds, side spins and heights, is simulated on the carom
//! table without noise and judged by the UMB rules ([`billiards_rules::three_cushion`]); the
//! shots that score are then re-simulated under the level's execution noise ([`Noise`]), a
//! few samples each and more for the best, as the pool search does, and the one that scores
//! most often is played.

use crate::noise::{Noise, stream};
use billiards_physics::{
    BallSetup, BallState, Event, EventKind, Params, Shot, Simulation, Table, TipOffset, Vec2,
};
use billiards_rules::three_cushion::{Ball, BallIds, fouls, frozen_to, read_stroke};
use rayon::prelude::*;
use std::f64::consts::TAU;

/// How much the search tries.
#[derive(Clone, Debug, PartialEq)]
pub struct CaromBudget {
    /// Directions, evenly spread round the cue ball.
    pub directions: usize,
    /// Cue speeds, m/s.
    pub speeds: Vec<f64>,
    /// Tip offsets (side, height), fractions of the radius.
    pub tips: Vec<TipOffset>,
    /// Noisy samples of every shot that scores without noise.
    pub samples: u64,
    /// How many of the best go on to [`CaromBudget::final_samples`].
    pub finalists: usize,
    /// Noisy samples of each finalist (its first `samples` included), and of each variant
    /// of the refinement.
    pub final_samples: u64,
    /// How many of the finalists are refined (their aim and speed moved a little).
    pub refined: usize,
    /// Most events a simulated shot may take before it is dropped.
    pub max_events: usize,
}

impl Default for CaromBudget {
    /// 1440 directions (a quarter degree apart) x 4 speeds x 9 tips (centre; left and right
    /// english, follow and draw; the four mixes) = 51 840 shots; 32 noisy samples of each
    /// scoring shot, 100 of the best 20; the best 3 refined (15 variants each, 100 samples).
    /// A carom shot is a few dozen events, a few microseconds in the solver: the whole search
    /// takes a few tenths of a second on two cores.
    fn default() -> Self {
        let tip = |side, height| TipOffset { side, height };
        Self {
            directions: 1440,
            speeds: vec![2.0, 3.0, 4.0, 5.5],
            tips: vec![
                tip(0.0, 0.0),
                tip(-0.4, 0.0),
                tip(0.4, 0.0),
                tip(0.0, 0.3),
                tip(0.0, -0.3),
                tip(-0.35, 0.25),
                tip(0.35, 0.25),
                tip(-0.35, -0.25),
                tip(0.35, -0.25),
            ],
            samples: 32,
            finalists: 20,
            final_samples: 100,
            refined: 3,
            max_events: 5_000,
        }
    }
}

/// The shot decided on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaromPlan {
    /// The strike meant (before execution noise).
    pub shot: Shot,
    /// The share of its noisy samples that scored (0 if no shot scores even without noise).
    pub success: f64,
    /// Its noisy samples.
    pub samples: u64,
    /// Shots that scored without noise, of all tried.
    pub scoring: usize,
    /// Shots tried without noise.
    pub tried: usize,
}

/// The stroke to judge: where the balls are, whose cue ball, the opening or not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaromStroke {
    /// Positions of the white, yellow and red ([`Ball::index`]).
    pub positions: [Vec2; 3],
    /// The striker's cue ball.
    pub cue: Ball,
    /// The opening stroke (the red first, directly).
    pub opening: bool,
}

/// What the search shares: the table at rest (lean, no history), the stroke and its rules.
struct Carom {
    base: Simulation,
    stroke: CaromStroke,
    frozen: Vec<Ball>,
    max_events: usize,
}

/// How one simulated shot ended for the striker.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Judged {
    /// A point.
    Point,
    /// No point: how near (cushions before the second ball, object balls touched).
    Miss(u32),
}

impl Carom {
    fn new(stroke: CaromStroke, table: &Table, params: &Params, max_events: usize) -> Option<Self> {
        let balls: Vec<BallSetup> = Ball::ALL
            .into_iter()
            .map(|b| BallSetup::at(b.index() as u8, stroke.positions[b.index()]))
            .collect();
        let mut base = Simulation::new(*table, *params, &balls).ok()?;
        base.set_record_history(false);
        Some(Self {
            frozen: frozen_to(&stroke.positions, stroke.cue, params.ball.radius),
            base,
            stroke,
            max_events,
        })
    }

    /// `shot` played in `sim` (reset from the base) and judged; `None` if the solver refuses
    /// it or it takes too many events.
    fn play(&self, shot: Shot, sim: &mut Simulation, events: &mut Vec<Event>) -> Option<Judged> {
        sim.clone_from(&self.base);
        events.clear();
        let ids = BallIds::default();
        let cue = ids.id(self.stroke.cue);
        sim.strike(cue, shot).ok()?;
        // The strike itself is an input, not handed out by `step_event`: the judge reads it
        // from the list.
        events.push(Event {
            time: sim.time(),
            kind: EventKind::Strike { ball: cue, shot },
            after: [sim.ball(cue), BallState::default()],
        });
        while let Some(e) = sim.step_event() {
            events.push(e);
            if events.len() > self.max_events {
                return None;
            }
        }
        let facts = read_stroke(&ids, self.stroke.positions, events).ok()?;
        let foul = !fouls(&facts, self.stroke.cue, self.stroke.opening, &self.frozen).is_empty();
        Some(if !foul && facts.carom() {
            Judged::Point
        } else if foul {
            Judged::Miss(0)
        } else {
            let balls = u32::from(facts.first.is_some()) + u32::from(facts.second.is_some());
            Judged::Miss(facts.counted_cushions().min(3) + 4 * balls)
        })
    }

    /// Noisy samples `from..to` of `shot` (candidate `index`): how many scored.
    fn sample(&self, shot: Shot, index: u64, from: u64, to: u64, noise: Noise, seed: u64) -> u64 {
        let mut sim = self.base.clone();
        let mut events = Vec::new();
        (from..to)
            .filter(|&k| {
                let mut rng = stream(seed, index, k);
                let s = noise.apply(shot, self.base.params(), &mut rng);
                self.play(s, &mut sim, &mut events) == Some(Judged::Point)
            })
            .count() as u64
    }
}

/// The shots of `budget` for `stroke` of balls of `radius`, in a fixed order: directions
/// all round the cue ball; on the opening only those that meet the red (UMB 3.3: any other
/// first contact is a foul), as many directions spread over that narrower fan.
fn candidates(budget: &CaromBudget, stroke: &CaromStroke, radius: f64) -> Vec<Shot> {
    let cue = stroke.positions[stroke.cue.index()];
    let to_red = stroke.positions[Ball::Red.index()] - cue;
    let (from, width) = match to_red.length() {
        d if stroke.opening && d > 2.0 * radius => {
            let half = (2.0 * radius / d).asin();
            (to_red.angle() - half, 2.0 * half)
        }
        _ => (0.0, TAU),
    };
    let mut out = Vec::with_capacity(budget.directions * budget.speeds.len() * budget.tips.len());
    for d in 0..budget.directions {
        let angle = from + width * (d as f64 + 0.5) / budget.directions as f64;
        for &speed in &budget.speeds {
            for &tip in &budget.tips {
                out.push(Shot {
                    angle,
                    speed,
                    tip,
                    elevation: 0.0,
                });
            }
        }
    }
    out
}

/// Why the search could not run.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CaromError {
    /// The balls, table or parameters make no simulation.
    #[error("three-cushion search: the layout cannot be simulated")]
    Layout,
    /// The budget tries nothing.
    #[error("three-cushion search: the budget tries no shot")]
    Budget,
}

/// The computer's stroke at three-cushion: `stroke` on `table` under `params`, planned
/// under execution `noise`, with `budget`; the same `seed` gives the same plan on any number
/// of threads. With no shot that scores without noise, the nearest miss (most cushions
/// before the second ball, most balls touched, no foul) with a success of 0.
pub fn decide_three_cushion(
    stroke: CaromStroke,
    table: &Table,
    params: &Params,
    noise: Noise,
    budget: &CaromBudget,
    seed: u64,
) -> Result<CaromPlan, CaromError> {
    let carom = Carom::new(stroke, table, params, budget.max_events).ok_or(CaromError::Layout)?;
    let shots = candidates(budget, &stroke, params.ball.radius);
    if shots.is_empty() {
        return Err(CaromError::Budget);
    }
    let results: Vec<Option<Judged>> = shots
        .par_iter()
        .map_init(
            || (carom.base.clone(), Vec::new()),
            |(sim, events), &shot| carom.play(shot, sim, events),
        )
        .collect();
    let scoring: Vec<usize> = (0..shots.len())
        .filter(|&i| results[i] == Some(Judged::Point))
        .collect();
    if scoring.is_empty() {
        let nearest = (0..shots.len())
            .max_by(|&a, &b| {
                let key = |i: usize| match results[i] {
                    Some(Judged::Miss(k)) => k as i64,
                    _ => -1,
                };
                key(a).cmp(&key(b)).then(b.cmp(&a))
            })
            .unwrap_or(0);
        return Ok(CaromPlan {
            shot: shots[nearest],
            success: 0.0,
            samples: 0,
            scoring: 0,
            tried: shots.len(),
        });
    }
    // Round one: every scoring shot, a few samples; round two: the best, more samples.
    let first: Vec<(usize, u64)> = scoring
        .par_iter()
        .map(|&i| {
            (
                i,
                carom.sample(shots[i], i as u64, 0, budget.samples, noise, seed),
            )
        })
        .collect();
    let mut ranked = first.clone();
    ranked.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    ranked.truncate(budget.finalists.max(1));
    let more = budget.final_samples.max(budget.samples);
    let finals: Vec<(usize, u64)> = ranked
        .par_iter()
        .map(|&(i, hits)| {
            let extra = carom.sample(shots[i], i as u64, budget.samples, more, noise, seed);
            (i, hits + extra)
        })
        .collect();
    let mut finals = finals;
    finals.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let tops: Vec<Shot> = finals
        .iter()
        .take(budget.refined.max(1))
        .map(|&(i, _)| shots[i])
        .collect();
    let (shot, hits) = refine(&carom, &tops, budget, noise, seed);
    Ok(CaromPlan {
        shot,
        success: hits as f64 / more as f64,
        samples: more,
        scoring: scoring.len(),
        tried: shots.len(),
    })
}

/// The stream index the refinement samples on: every variant draws the same noise (common
/// random numbers), so their counts differ by the shots, not by the luck of their draws.
const REFINE_STREAM: u64 = u64::MAX;

/// Round three: each of `tops` and its neighbours (the aim moved by a third and two thirds of
/// the fan's step either way, the speed by 10 % either way, the same tip), sampled on common
/// streams; the variant that scores most often and its count. A shot on the grid may sit at
/// the edge of the region of aims that score; a neighbour nearer its middle tolerates more
/// noise.
fn refine(
    carom: &Carom,
    tops: &[Shot],
    budget: &CaromBudget,
    noise: Noise,
    seed: u64,
) -> (Shot, u64) {
    let step = TAU / budget.directions.max(1) as f64;
    let more = budget.final_samples.max(budget.samples);
    let variants: Vec<Shot> = tops
        .iter()
        .flat_map(|&shot| {
            [-2.0, -1.0, 0.0, 1.0, 2.0].into_iter().flat_map(move |a| {
                [1.0, 0.9, 1.1].into_iter().map(move |v| Shot {
                    angle: shot.angle + a * step / 3.0,
                    speed: shot.speed * v,
                    ..shot
                })
            })
        })
        .collect();
    let counts: Vec<u64> = variants
        .par_iter()
        .map(|&v| carom.sample(v, REFINE_STREAM, 0, more, noise, seed))
        .collect();
    // The first of the best: the grid's own shot wins a tie with its neighbours.
    let best = (0..variants.len())
        .max_by(|&a, &b| counts[a].cmp(&counts[b]).then(b.cmp(&a)))
        .expect("at least one variant");
    (variants[best], counts[best])
}

/// `shot` played once from `stroke` on `table` under `params` (no noise): does it score?
/// `None` if the solver refuses it.
pub fn scores(stroke: CaromStroke, table: &Table, params: &Params, shot: Shot) -> Option<bool> {
    let carom = Carom::new(stroke, table, params, usize::MAX)?;
    let mut sim = carom.base.clone();
    let mut events = Vec::new();
    carom
        .play(shot, &mut sim, &mut events)
        .map(|r| r == Judged::Point)
}
