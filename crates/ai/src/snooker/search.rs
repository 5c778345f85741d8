//! The snooker search: candidates, noisy samples judged by [`Frame::play`], the value of a
//! sample in points, the rounds of refinement, places in the D and the choices after a foul.

use super::{SnookerDecision, SnookerPlan};
use crate::AiError;
use crate::candidates::{Candidate, Layout, ShotKind, combo_aims, direct_aims, expand, rail_aims};
use crate::evaluate::{Mode, Search, Stats};
use crate::level::Level;
use crate::noise::{Noise, stream};
use crate::position::aim_probability;
use crate::quiet::final_layout;
use billiards_physics::{
    BallId, BallSetup, EventKind, Shot, Simulation, SnookerMarks, TipOffset, Vec2, Vec3,
};
use billiards_rules::snooker::balls::{WHITE, is_colour, is_red, value};
use billiards_rules::snooker::geometry::snookered;
use billiards_rules::snooker::{BallOn, Choice, Frame, Stroke, Verdict};
use billiards_rules::{Call, Game, GameState, Seat, ShotSummary};
use rand::Rng;
use rayon::prelude::*;

/// What a red is worth to the player who pots it: its point and the colour that follows
/// (about the average of a blue and a pink, what a break-builder takes after a red).
const RED_WORTH: f64 = 1.0 + 4.0;
/// Points a player at the table is expected to add beyond the ball on, when he pots it
/// (the break goes on; a rough mean of a visit's continuation).
const CONTINUATION: f64 = 2.0;
/// The value of winning (or losing) the frame with this stroke, in points.
const FRAME: f64 = 40.0;
/// A snooker left: the opponent's expected foul (at least 4 points, 3.10, less his escapes).
const SNOOKER_BONUS: f64 = 2.0;
/// The same when snookers are needed to win: a snooker is the only way back.
const NEEDED_SNOOKER_BONUS: f64 = 6.0;
/// The stream of the second ply's outcomes: common to every finalist (close strokes meet the
/// same errors), far from the candidates' own streams and [`SnookerPlan::executed`]'s.
const OUTCOMES: u64 = 1 << 62;
/// The stream of the seeds of the second ply's searches.
const STREAMS: u64 = (1 << 62) + 1;
/// A ball potted while snookers are needed: one fewer ball to snooker behind.
const NEEDED_POT_COST: f64 = 4.0;
/// Below this chance of a fair pot, safeties are searched too.
const SAFETY_BELOW: f64 = 0.6;
/// Most events one sample may take before it is scored on the layout of the moment.
const MAX_EVENTS: usize = 600;
/// A refused stroke (a place the solver rejects, a stroke the rules refuse) costs this.
const REFUSED: f64 = 10.0;

/// How much search a level spends at snooker: the pool budget's shape ([`Level::budget`]),
/// trimmed for a 22-ball table (more balls on, longer runs).
#[derive(Clone, Debug, PartialEq)]
pub struct SnookerBudget {
    /// Noisy samples of every candidate in the first round.
    pub samples: usize,
    /// Rounds of refinement: the best `k` get `m` more samples each.
    pub rounds: Vec<(usize, usize)>,
    /// Pot aims kept (best analytic value first) before speeds and tips.
    pub aims: usize,
    /// Cue speeds, as multiples of the speed an aim needs.
    pub speeds: Vec<f64>,
    /// Tip offsets of straight and cut pots.
    pub tips: Vec<TipOffset>,
    /// Banks, kicks and red-on-red plants.
    pub banks: bool,
    /// Places in the D searched with the cue ball in hand.
    pub placements: usize,
    /// Pot aims corrected for throw before sampling.
    pub correct_aim: bool,
    /// Balls on that safeties are played at (the nearest in view).
    pub safety_balls: usize,
    /// Contacts per safety ball, from full to thin on either side.
    pub safety_hits: usize,
    /// The budget of the search behind each choice after a foul (`None`: this one).
    pub choice: Option<Box<SnookerBudget>>,
    /// The second ply (`None`: positions valued analytically, one ply).
    pub second: Option<SnookerTwoPly>,
}

/// The second ply at snooker, as [`crate::twoply`] at pool: the `finalists` best strokes
/// each struck `outcomes` more times (one stream common to them), run to rest and judged;
/// from each table the next stroke is searched with `reply`, for whoever plays it.
#[derive(Clone, Debug, PartialEq)]
pub struct SnookerTwoPly {
    /// Strokes valued two plies deep (the best by their one-ply value).
    pub finalists: usize,
    /// Noisy outcomes of each, searched for the next stroke.
    pub outcomes: usize,
    /// The budget of each search of the next stroke.
    pub reply: Box<SnookerBudget>,
}

impl SnookerBudget {
    /// The budget of `level`.
    pub fn of(level: Level) -> Self {
        let b = level.budget();
        let reply = SnookerBudget {
            samples: 4,
            rounds: vec![(4, 12)],
            aims: 4,
            speeds: vec![1.0, 1.6],
            tips: b.tips.iter().copied().take(3).collect(),
            banks: false,
            placements: 2,
            correct_aim: false,
            safety_balls: 2,
            safety_hits: 3,
            choice: None,
            second: None,
        };
        let second = |finalists, outcomes| SnookerTwoPly {
            finalists,
            outcomes,
            reply: Box::new(reply.clone()),
        };
        match level {
            Level::Easy | Level::Medium => SnookerBudget {
                samples: b.samples.min(8),
                rounds: b.rounds.iter().map(|&(k, m)| (k, m.min(24))).collect(),
                aims: b.aims,
                speeds: b.speeds.to_vec(),
                tips: b.tips.to_vec(),
                banks: b.banks_kicks_combos,
                placements: b.placements.min(3),
                correct_aim: b.correct_aim,
                safety_balls: 2,
                safety_hits: b.safeties.min(5),
                choice: Some(Box::new(reply.clone())),
                second: None,
            },
            Level::Hard | Level::Expert | Level::Perfect => SnookerBudget {
                samples: 6,
                rounds: vec![(20, 18), (6, 48)],
                aims: 8,
                speeds: vec![0.8, 1.1, 1.6, 2.4],
                tips: b.tips.iter().copied().take(4).collect(),
                banks: true,
                placements: 3,
                correct_aim: true,
                safety_balls: if level == Level::Expert { 5 } else { 4 },
                safety_hits: 7,
                choice: Some(Box::new(reply.clone())),
                second: Some(if level == Level::Expert {
                    second(6, 16)
                } else {
                    second(4, 8)
                }),
            },
        }
    }
}

/// A candidate stroke and the ball it nominates.
#[derive(Clone, Copy, Debug)]
struct Cand {
    cand: Candidate,
    nominated: Option<u8>,
}

/// What one search shares: the frame, the table at rest and the noise it plans under.
struct Snook<'a> {
    frame: &'a Frame,
    base: Simulation,
    cue: BallId,
    noise: Noise,
    seed: u64,
    me: Seat,
    /// The striker needs snookers: a pot gains him nothing.
    needs: bool,
}

/// [`super::decide_snooker`] planned under `noise` with `budget`.
pub fn decide_snooker_with(
    frame: &Frame,
    sim: &Simulation,
    noise: Noise,
    budget: &SnookerBudget,
    seed: u64,
) -> Result<SnookerDecision, AiError> {
    if frame.end.is_some() {
        return Err(AiError::GameOver);
    }
    if !sim.is_at_rest() {
        return Err(AiError::NotAtRest);
    }
    if !frame.next.choices.is_empty() {
        let inner = budget.choice.as_deref().unwrap_or(budget);
        let (choice, estimate) = choose(frame, sim, noise, inner, seed);
        return Ok(SnookerDecision::Choose { choice, estimate });
    }
    let cue = sim
        .numbers()
        .iter()
        .position(|&n| n == WHITE)
        .ok_or(AiError::NoCueBall)?;
    let in_hand = frame.next.in_hand;
    if !in_hand && !sim.ball(cue).motion.on_table() {
        return Err(AiError::CueBallOff);
    }
    let mut base = sim.clone();
    base.set_record_history(false);
    let me = frame.next.striker;
    let s = Snook {
        frame,
        base,
        cue,
        noise,
        seed,
        me,
        needs: frame.snookers_required(me) > 0,
    };
    let places: Vec<Option<Vec2>> = if in_hand {
        let found = d_places(frame, sim, noise, budget.placements);
        if found.is_empty() {
            return Err(AiError::NoPlace);
        }
        found.into_iter().map(Some).collect()
    } else {
        vec![None]
    };
    let mut pool = Pool::default();
    let first: Vec<Cand> = places.iter().flat_map(|&p| s.offence(p, budget)).collect();
    pool.add(&s, first, budget.samples);
    let scoring = pool
        .best()
        .is_some_and(|i| pool.stats[i].pot_rate() >= SAFETY_BELOW);
    if !scoring || s.needs {
        let more: Vec<Cand> = places.iter().flat_map(|&p| s.safeties(p, budget)).collect();
        pool.add(&s, more, budget.samples);
    }
    for &(k, m) in &budget.rounds {
        pool.refine(&s, k, m);
    }
    if let Some(two) = &budget.second {
        pool.second_ply(&s, two);
    }
    let best = pool.best().ok_or(AiError::NoBall)?;
    let (c, st) = (pool.cands[best], pool.stats[best]);
    let value = pool.value(best);
    Ok(SnookerDecision::Shoot(SnookerPlan {
        shot: c.cand.shot,
        place: c.cand.place,
        nominated: c.nominated,
        kind: c.cand.kind,
        success: st.pot_rate(),
        foul: st.fouls as f64 / st.n.max(1) as f64,
        value,
        samples: st.n,
        simulations: pool.simulations,
        events: pool.events,
    }))
}

/// Every candidate evaluated so far, with its samples.
#[derive(Default)]
struct Pool {
    cands: Vec<Cand>,
    stats: Vec<Stats>,
    simulations: usize,
    events: usize,
    finalists: Vec<usize>,
    /// Candidates valued two plies deep, with their values (empty: one ply).
    two: Vec<(usize, f64)>,
}

impl Pool {
    /// Evaluates `cands` with `samples` each; candidate `i` of the pool draws from stream `i`.
    fn add(&mut self, s: &Snook, cands: Vec<Cand>, samples: usize) {
        let salt = self.cands.len() as u64;
        let runs: Vec<(usize, u64, std::ops::Range<u64>)> = (0..cands.len())
            .map(|i| (i, salt + i as u64, 0..samples as u64))
            .collect();
        let stats = s.evaluate(&cands, &runs);
        self.count(&stats);
        self.cands.extend(cands);
        self.stats.extend(stats);
    }

    /// The best `k` so far get `m` more samples each and become the finalists.
    fn refine(&mut self, s: &Snook, k: usize, m: usize) {
        let mut order: Vec<usize> = (0..self.cands.len()).collect();
        let mean = |i: usize| self.stats[i].mean();
        order.sort_by(|&a, &b| mean(b).total_cmp(&mean(a)).then(a.cmp(&b)));
        order.truncate(k);
        let runs: Vec<(usize, u64, std::ops::Range<u64>)> = order
            .iter()
            .map(|&i| {
                let n = self.stats[i].n as u64;
                (i, i as u64, n..n + m as u64)
            })
            .collect();
        let more = s.evaluate(&self.cands, &runs);
        self.count(&more);
        for (&i, st) in order.iter().zip(more) {
            self.stats[i] = self.stats[i].merged(st);
        }
        self.finalists = order;
    }

    fn count(&mut self, stats: &[Stats]) {
        self.simulations += stats.iter().map(|s| s.n).sum::<usize>();
        self.events += stats.iter().map(|s| s.events).sum::<usize>();
    }

    /// Values the best finalists two plies deep; they become the only candidates
    /// [`Pool::best`] chooses from. A stroke's value: its one-ply mean plus the mean, over
    /// its searched outcomes, of (second-ply value - one-ply value) of the same outcome (a
    /// control variate, as [`crate::twoply`]).
    fn second_ply(&mut self, s: &Snook, two: &SnookerTwoPly) {
        let mut order = if self.finalists.is_empty() {
            (0..self.cands.len()).collect()
        } else {
            self.finalists.clone()
        };
        let mean = |i: usize| self.stats[i].mean();
        order.sort_by(|&a, &b| mean(b).total_cmp(&mean(a)).then(a.cmp(&b)));
        order.truncate(two.finalists);
        let jobs: Vec<(usize, u64)> = order
            .iter()
            .flat_map(|&i| (0..two.outcomes as u64).map(move |k| (i, k)))
            .collect();
        let corrections: Vec<(f64, usize, usize)> = jobs
            .par_iter()
            .map(|&(i, k)| s.correction(&self.cands[i], k, &two.reply))
            .collect();
        for (n, &i) in order.iter().enumerate() {
            let mine = &corrections[n * two.outcomes..(n + 1) * two.outcomes];
            let shift = mine.iter().map(|c| c.0).sum::<f64>() / two.outcomes.max(1) as f64;
            self.two.push((i, self.stats[i].mean() + shift));
            self.simulations += mine.iter().map(|c| c.1).sum::<usize>();
            self.events += mine.iter().map(|c| c.2).sum::<usize>();
        }
    }

    /// The value of candidate `i`: two plies deep when it was so valued, else its mean.
    fn value(&self, i: usize) -> f64 {
        self.two
            .iter()
            .find(|v| v.0 == i)
            .map_or(self.stats[i].mean(), |v| v.1)
    }

    /// The best mean among the finalists (all candidates before any round; ties: the first);
    /// after a second ply, the best two-ply value.
    fn best(&self) -> Option<usize> {
        if !self.two.is_empty() {
            return self
                .two
                .iter()
                .copied()
                .reduce(|a, b| if b.1 > a.1 { b } else { a })
                .map(|v| v.0);
        }
        let all: Vec<usize> = (0..self.cands.len()).collect();
        let pool = if self.finalists.is_empty() {
            &all
        } else {
            &self.finalists
        };
        pool.iter().copied().reduce(|a, b| {
            let (ma, mb) = (self.stats[a].mean(), self.stats[b].mean());
            if mb > ma || (mb == ma && b < a) { b } else { a }
        })
    }
}

/// What potting ball `n` is worth to the player at the table.
fn worth(n: u8) -> f64 {
    if is_red(n) {
        RED_WORTH
    } else {
        value(n).map_or(0.0, f64::from)
    }
}

/// The expected points of the player at the table with the cue ball at `layout.cue`: the
/// best straight or cut pot of a ball of `on`, its chance times the ball's worth and the
/// continuation (the pool search's one-ply position value, weighted by the balls' values).
pub fn chance(layout: &Layout, on: &[u8], noise: Noise) -> f64 {
    direct_aims(layout, on)
        .iter()
        .map(|a| aim_probability(a, noise) * (worth(a.first) + CONTINUATION))
        .fold(0.0, f64::max)
}

/// [`chance`] with the cue ball in hand: the best of three places in the D (behind the
/// brown, towards the yellow, towards the green) that are clear of every ball.
fn chance_in_hand(layout: &Layout, marks: &SnookerMarks, on: &[u8], noise: Noise) -> f64 {
    let r = layout.radius;
    let back = marks.brown - Vec2::new(0.1, 0.0);
    let probes = [
        back,
        back - Vec2::new(0.0, 0.18),
        back + Vec2::new(0.0, 0.18),
    ];
    let mut l = layout.clone();
    probes
        .iter()
        .filter(|&&p| {
            layout
                .balls
                .iter()
                .all(|&(_, q)| (p - q).length() > 2.0 * r)
        })
        .map(|&p| {
            l.cue = p;
            chance(&l, on, noise)
        })
        .fold(0.0, f64::max)
}

/// Up to `count` places in the D for the cue ball in hand (3.4), best first: a fan of
/// points behind the baulk-line clear of every ball, ranked by [`chance`] at the balls on;
/// equal values keep the order proposed, whose first two are the usual break-off places
/// between the brown and the yellow or the green.
pub fn d_places(frame: &Frame, sim: &Simulation, noise: Noise, count: usize) -> Vec<Vec2> {
    let Some(mut layout) = Layout::of(sim, Some(Vec2::ZERO)) else {
        return Vec::new();
    };
    let m = &frame.marks;
    let r = layout.radius;
    let mut proposed = vec![
        m.brown + Vec2::new(-0.02, -0.5 * m.d_radius),
        m.brown + Vec2::new(-0.02, 0.5 * m.d_radius),
    ];
    for radius in [0.06, 0.15, 0.24, 0.285] {
        for k in 0..=8 {
            // From the yellow's side round the back of the D to the green's.
            let a = std::f64::consts::PI * (f64::from(k) / 8.0 - 0.5);
            let dir = Vec2::new(-a.cos(), a.sin());
            proposed.push(m.brown + dir * radius);
        }
    }
    let bound = layout.table.centre_bounds(r);
    proposed.retain(|&p| {
        m.in_d(p)
            && p.x.abs() < bound.x
            && p.y.abs() < bound.y
            && layout
                .balls
                .iter()
                .all(|&(_, q)| (p - q).length() > 2.0 * r + 1e-4)
    });
    let on = frame.balls_on(frame.next.on);
    let mut ranked: Vec<(f64, usize, Vec2)> = proposed
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            layout.cue = p;
            (chance(&layout, &on, noise), i, p)
        })
        .collect();
    ranked.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut out: Vec<Vec2> = Vec::new();
    for (_, _, p) in ranked {
        if out.len() == count {
            break;
        }
        if out.iter().all(|q| (*q - p).length() >= 0.05) {
            out.push(p);
        }
    }
    out
}

/// The first ball the cue ball meets sent straight along unit `dir` (no cushion).
fn first_hit(layout: &Layout, dir: Vec2) -> Option<u8> {
    let d = 2.0 * layout.radius;
    layout
        .balls
        .iter()
        .filter_map(|&(n, q)| {
            let w = q - layout.cue;
            let along = w.dot(dir);
            let off2 = w.length_squared() - along * along;
            (along > 0.0 && off2 < d * d).then(|| (along - (d * d - off2).sqrt(), n))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)))
        .map(|(_, n)| n)
}

/// The balls of `sim` on the table, by number.
fn on_table(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}

impl Snook<'_> {
    /// The balls the striker may pot: the balls on and, with a free ball (3.12), any other
    /// object ball (nominated).
    fn targets(&self) -> (Vec<u8>, Vec<u8>) {
        let on = self.frame.balls_on(self.frame.next.on);
        let free: Vec<u8> = if self.frame.next.free_ball {
            self.frame
                .on_table
                .iter()
                .copied()
                .filter(|n| !on.contains(n))
                .collect()
        } else {
            Vec::new()
        };
        (on, free)
    }

    /// The nomination that goes with a stroke at `ball` first: the colour after a red
    /// (2.12), a free ball (3.12), else none.
    fn nomination(&self, ball: u8, free: &[u8]) -> Option<u8> {
        match self.frame.next.on {
            BallOn::Colour { .. } if is_colour(ball) => Some(ball),
            _ if free.contains(&ball) => Some(ball),
            _ => None,
        }
    }

    /// Pots (and banks, kicks, plants) from `place`: the best `budget.aims` aims by chance
    /// times worth, in the budget's speeds and tips.
    fn offence(&self, place: Option<Vec2>, budget: &SnookerBudget) -> Vec<Cand> {
        let Some(layout) = Layout::of(&self.base, place) else {
            return Vec::new();
        };
        let (on, free) = self.targets();
        let mut legal = on.clone();
        legal.extend(&free);
        let mut aims = direct_aims(&layout, &legal);
        if budget.banks {
            aims.extend(rail_aims(&layout, &legal));
            if self.frame.next.on == BallOn::Red {
                // A red into a red: both are on (3.3(a)).
                aims.extend(combo_aims(&layout, &on, &on));
            }
        }
        let mut ranked: Vec<(f64, usize)> = aims
            .iter()
            .enumerate()
            .map(|(i, a)| {
                let ball = match a.kind {
                    ShotKind::Combo { ball, .. } => ball,
                    _ => a.first,
                };
                (aim_probability(a, self.noise) * (worth(ball) + 1.0), i)
            })
            .collect();
        ranked.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        let kept: Vec<_> = ranked
            .iter()
            .take(budget.aims)
            .map(|&(_, i)| aims[i])
            .collect();
        let cands = expand(&kept, &budget.speeds, &budget.tips, false, place);
        let cands: Vec<Candidate> = if budget.correct_aim {
            let dummy = GameState::new(Game::FreePlay, Seat::A);
            let pool = Search {
                state: &dummy,
                base: self.base.clone(),
                cue: self.cue,
                noise: self.noise,
                seed: self.seed,
                mode: Mode::Lean,
            };
            cands.into_par_iter().map(|c| pool.correct_aim(c)).collect()
        } else {
            cands
        };
        cands
            .into_iter()
            .map(|c| {
                let first = match c.kind {
                    ShotKind::Pot { ball, .. }
                    | ShotKind::Bank { ball, .. }
                    | ShotKind::Kick { ball, .. } => ball,
                    ShotKind::Combo { first, .. } => first,
                    _ => 0,
                };
                Cand {
                    cand: c,
                    nominated: self.nomination(first, &free),
                }
            })
            .collect()
    }

    /// Safeties from `place`: at the nearest balls on in view, contacts from full to thin on
    /// either side at three weights (back to baulk, to a cushion and back, a touch); a ball
    /// on hidden is kicked at off each cushion ([`crate::candidates::safeties`]).
    fn safeties(&self, place: Option<Vec2>, budget: &SnookerBudget) -> Vec<Cand> {
        let Some(layout) = Layout::of(&self.base, place) else {
            return Vec::new();
        };
        let (on, _) = self.targets();
        let r = layout.radius;
        let mut balls: Vec<(f64, u8, Vec2)> = on
            .iter()
            .filter_map(|&n| layout.ball(n).map(|b| ((b - layout.cue).length(), n, b)))
            .collect();
        balls.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut out = Vec::new();
        let push = |out: &mut Vec<Cand>, ball: u8, angle: f64, speed: f64| {
            out.push(Cand {
                cand: Candidate {
                    kind: ShotKind::Safety { ball },
                    shot: Shot::new(angle, speed.clamp(0.3, 7.0)),
                    call: Call::None,
                    place,
                    object: None,
                },
                nominated: matches!(self.frame.next.on, BallOn::Colour { .. }).then_some(ball),
            })
        };
        let k = budget.safety_hits.max(1);
        let mut seen = 0;
        for &(d, n, b) in &balls {
            if seen == budget.safety_balls {
                break;
            }
            let to = (b - layout.cue).normalized().unwrap_or(Vec2::new(1.0, 0.0));
            // A red may meet another red first (any red is on, 3.3(a)); a colour must be met
            // itself.
            let fair = |m: u8| if is_red(n) { on.contains(&m) } else { m == n };
            let angles: Vec<f64> = (0..k)
                .map(|j| {
                    let f = if k == 1 {
                        0.0
                    } else {
                        -0.95 + 1.9 * j as f64 / (k - 1) as f64
                    };
                    to.angle() + (2.0 * r * f / d).clamp(-1.0, 1.0).asin()
                })
                .filter(|&a| first_hit(&layout, Vec2::from_angle(a)).is_some_and(fair))
                .collect();
            if angles.is_empty() {
                continue;
            }
            seen += 1;
            for a in angles {
                // Rolling distances of about d + 0.3, d + 3 and d + 7 m (0.1 m/s^2 with
                // the losses of the contact and the cushions).
                for extra in [0.3, 3.0, 7.0] {
                    let speed = 1.4 * (0.2 * (d + extra)).sqrt() + 0.3;
                    push(&mut out, n, a, speed);
                }
            }
        }
        if seen == 0 {
            // Snookered: the kicks of the pool safeties (a cushion first, then the ball on).
            for c in crate::candidates::safeties(&layout, &on, 1, place) {
                let ball = match c.kind {
                    ShotKind::Safety { ball } => ball,
                    _ => continue,
                };
                for k in [0.8, 1.0, 1.4] {
                    push(&mut out, ball, c.shot.angle, c.shot.speed * k);
                }
            }
        }
        out
    }

    /// Samples of each run `(candidate, stream, draws)` on all cores, summed in the order of
    /// their draws (so the result does not depend on the threads).
    fn evaluate(&self, cands: &[Cand], runs: &[(usize, u64, std::ops::Range<u64>)]) -> Vec<Stats> {
        let mut starts = Vec::with_capacity(runs.len() + 1);
        let mut total = 0usize;
        for r in runs {
            starts.push(total);
            total += (r.2.end - r.2.start) as usize;
        }
        starts.push(total);
        let samples: Vec<Stats> = (0..total)
            .into_par_iter()
            .map_init(
                || self.base.clone(),
                |sim, n| {
                    let r = starts.partition_point(|&s| s <= n) - 1;
                    let (i, stream_id, ref draws) = runs[r];
                    let k = draws.start + (n - starts[r]) as u64;
                    self.sample(&cands[i], stream_id, k, sim)
                },
            )
            .collect();
        starts
            .windows(2)
            .map(|w| {
                samples[w[0]..w[1]]
                    .iter()
                    .fold(Stats::default(), |s, x| s.merged(*x))
            })
            .collect()
    }

    /// One noisy sample of `c` (draw `k` of stream `id`) in the scratch simulation `sim`.
    fn sample(&self, c: &Cand, id: u64, k: u64, sim: &mut Simulation) -> Stats {
        let refused = Stats {
            n: 1,
            value: -REFUSED,
            fouls: 1,
            ..Stats::default()
        };
        sim.clone_from(&self.base);
        if let Some(p) = c.cand.place
            && sim.place(self.cue, p, Vec2::ZERO, Vec3::ZERO).is_err()
        {
            return refused;
        }
        let before = on_table(sim);
        let shot = self
            .noise
            .apply(c.cand.shot, sim.params(), &mut stream(self.seed, id, k));
        let first = sim.event_count();
        if sim.strike(self.cue, shot).is_err() {
            return refused;
        }
        let mut summary = ShotSummary::default();
        let mut layout = None;
        while let Some(e) = sim.step_event() {
            summary.record(&e.kind, sim.numbers());
            if sim.event_count() - first > MAX_EVENTS {
                break;
            }
            if matches!(e.kind, EventKind::Transition { .. }) {
                layout = final_layout(sim);
                if layout.is_some() {
                    break;
                }
            }
        }
        let events = sim.event_count() - first;
        let after: Vec<(u8, Vec2)> = match layout {
            Some(l) => std::iter::once((WHITE, l.cue)).chain(l.balls).collect(),
            None => on_table(sim),
        };
        let mut frame = self.frame.clone();
        let Ok(verdict) = frame.play(Stroke {
            summary: &summary,
            nominated: c.nominated,
            before: &before,
            after: &after,
        }) else {
            return Stats { events, ..refused };
        };
        let value = self.score(&frame, &verdict, &after);
        let pot = verdict.fair() && verdict.points > 0;
        Stats {
            n: 1,
            value,
            pots: usize::from(pot),
            fouls: usize::from(!verdict.fair()),
            losses: usize::from(verdict.end.is_some_and(|(w, _)| w != self.me)),
            events,
        }
    }

    /// The value of `verdict` for the striker, in points, the balls at rest in `after` and
    /// `frame` the frame after the stroke: the stroke's own points and the position's.
    fn score(&self, frame: &Frame, verdict: &Verdict, after: &[(u8, Vec2)]) -> f64 {
        let (now, position) = self.terms(frame, verdict, after);
        now + position
    }

    /// [`Snook::score`] in two terms: what the stroke itself earns (points, a penalty, the
    /// frame, a pot for nothing) and what the position is worth (the next player's chance,
    /// for or against the striker, and a snooker's bonus).
    fn terms(&self, frame: &Frame, verdict: &Verdict, after: &[(u8, Vec2)]) -> (f64, f64) {
        let me = self.me;
        if let Some((w, _)) = verdict.end {
            return (if w == me { FRAME } else { -FRAME }, 0.0);
        }
        let Some(next) = &verdict.next else {
            return (0.0, 0.0);
        };
        let mut balls: Vec<(u8, Vec2)> = after.to_vec();
        for &(c, p) in &verdict.spots {
            balls.retain(|&(n, _)| n != c);
            balls.push((c, p));
        }
        let cue = balls.iter().find(|b| b.0 == WHITE).map(|b| b.1);
        let objects: Vec<(u8, Vec2)> = balls.iter().copied().filter(|b| b.0 != WHITE).collect();
        let on_next = frame.balls_on(next.on);
        let layout = Layout {
            table: frame.table,
            radius: frame.radius,
            cue: cue.unwrap_or(Vec2::ZERO),
            balls: objects.clone(),
        };
        let next_chance = match cue {
            Some(_) if !next.in_hand => chance(&layout, &on_next, self.noise),
            _ => chance_in_hand(&layout, &frame.marks, &on_next, self.noise),
        };
        if !verdict.fair() {
            return (-f64::from(verdict.penalty), -next_chance);
        }
        if self.needs && verdict.points > 0 {
            // A pot for nothing: the points do not close the gap (3.3, 3.10), and each ball
            // gone is one fewer to lay a snooker behind; with one object ball left there is
            // none.
            let gone = self
                .frame
                .on_table
                .len()
                .saturating_sub(frame.on_table.len());
            let cost = if frame.on_table.len() <= 1 {
                0.5 * FRAME
            } else {
                NEEDED_POT_COST * gone.max(1) as f64
            };
            return (-cost, 0.0);
        }
        let gained = f64::from(verdict.points);
        if next.striker == me && next.choices.is_empty() {
            return (gained, next_chance);
        }
        let bonus = match cue {
            Some(c) if !next.in_hand && snookered(c, &on_next, &objects, frame.radius) => {
                if self.needs {
                    NEEDED_SNOOKER_BONUS
                } else {
                    SNOOKER_BONUS
                }
            }
            _ => 0.0,
        };
        (gained, bonus - next_chance)
    }

    /// Draw `k` of the outcomes' stream struck as `c`, run to rest and judged: its
    /// second-ply value (the stroke's own points and the next stroke's searched value, for
    /// or against the striker) minus its one-ply value, the simulations and the events. The
    /// end of the frame or a choice to make is not searched (a difference of 0).
    fn correction(&self, c: &Cand, k: u64, reply: &SnookerBudget) -> (f64, usize, usize) {
        let mut sim = self.base.clone();
        if let Some(p) = c.cand.place
            && sim.place(self.cue, p, Vec2::ZERO, Vec3::ZERO).is_err()
        {
            return (0.0, 1, 0);
        }
        let before = on_table(&sim);
        let shot = self.noise.apply(
            c.cand.shot,
            sim.params(),
            &mut stream(self.seed, OUTCOMES, k),
        );
        let first = sim.event_count();
        if sim.strike(self.cue, shot).is_err() {
            return (0.0, 1, 0);
        }
        let mut summary = ShotSummary::default();
        while let Some(e) = sim.step_event() {
            summary.record(&e.kind, sim.numbers());
            if sim.event_count() - first > 20 * MAX_EVENTS {
                return (0.0, 1, sim.event_count() - first);
            }
        }
        let events = sim.event_count() - first;
        let after = on_table(&sim);
        let mut frame = self.frame.clone();
        let Ok(verdict) = frame.play(Stroke {
            summary: &summary,
            nominated: c.nominated,
            before: &before,
            after: &after,
        }) else {
            return (0.0, 1, events);
        };
        let Some(next) = verdict.next.clone() else {
            return (0.0, 1, events);
        };
        if !next.choices.is_empty() {
            return (0.0, 1, events);
        }
        let (_, position) = self.terms(&frame, &verdict, &after);
        for &(n, p) in &verdict.spots {
            let Some(id) = sim.numbers().iter().position(|&m| m == n) else {
                return (0.0, 1, events);
            };
            if sim.place(id, p, Vec2::ZERO, Vec3::ZERO).is_err() {
                return (0.0, 1, events);
            }
        }
        let sign = if next.striker == self.me { 1.0 } else { -1.0 };
        let seed = stream(self.seed, STREAMS, k).random();
        match decide_snooker_with(&frame, &sim, self.noise, reply, seed) {
            Ok(SnookerDecision::Shoot(plan)) => (
                sign * plan.value - position,
                1 + plan.simulations,
                events + plan.events,
            ),
            _ => (0.0, 1, events),
        }
    }
}

/// The table after `chosen`'s replace (3.14): every ball where the layout puts it, the others
/// off the table (a fresh simulation of those balls only: the search needs no history).
fn replaced(sim: &Simulation, layout: &[(u8, Vec2)]) -> Option<Simulation> {
    let balls: Vec<BallSetup> = layout.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
    let mut s = Simulation::new(*sim.table(), *sim.params(), &balls).ok()?;
    s.set_record_history(false);
    Some(s)
}

/// The choice after a foul (or the tie's re-spotted black, 3.3(d)): each option taken on a
/// copy of the frame, the stroke it leads to searched with `budget` from the side of whoever
/// plays it; its value counts for the chooser, or against him when the other plays.
fn choose(
    frame: &Frame,
    sim: &Simulation,
    noise: Noise,
    budget: &SnookerBudget,
    seed: u64,
) -> (Choice, f64) {
    let me = frame.next.striker;
    let mut best: Option<(f64, Choice)> = None;
    for (k, &choice) in frame.next.choices.iter().enumerate() {
        let mut after = frame.clone();
        let Ok(chosen) = after.choose(choice) else {
            continue;
        };
        let table = match &chosen.layout {
            Some(l) => match replaced(sim, l) {
                Some(t) => t,
                None => continue,
            },
            None => sim.clone(),
        };
        let sign = if chosen.next.striker == me { 1.0 } else { -1.0 };
        let salt = seed.wrapping_add(0x9e37_79b9 * (k as u64 + 1));
        let value = match decide_snooker_with(&after, &table, noise, budget, salt) {
            Ok(SnookerDecision::Shoot(plan)) => sign * plan.value,
            _ => continue,
        };
        if best.is_none_or(|b| value > b.0) {
            best = Some((value, choice));
        }
    }
    match best {
        Some((v, c)) => (c, v),
        None => (frame.next.choices[0], 0.0),
    }
}
