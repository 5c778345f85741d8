//! The computer at any game, through the one game interface alone
//! ([`billiards_rules::GameRules`], issue 50): it never asks which game it plays.
//!
//! The search: geometric aims at the balls it may hit first ([`direct_aims`] and
//! [`rail_aims`]: into each pocket, and off a rail), or, on a table without pockets or with
//! no aim, a fan of directions (1440 at hard: a quarter degree apart) in four speeds and
//! nine tips; each candidate is simulated once without noise and judged by a copy of the
//! game ([`GameRules::boxed_clone`]). The best kept (256 at hard) are sampled under the
//! level's planning noise and refined in rounds: the one search skeleton the pool and
//! snooker searches run too ([`rounds::find`]; this game's parts: [`Searched`]). A value is
//! read from the judgement ([`stroke_value`]): the game won or lost, a foul, the turn kept,
//! the points scored. Ball in hand: the same search from a few places the rules accept.
//! Options offered before a stroke: each is taken on a copy and valued by the best stroke
//! that follows, from the chooser's side.
//!
//! Every random draw comes from [`stream`], named by the seed and the candidate, so the same
//! seed gives the same decision on any number of threads.

use crate::AiError;
use crate::candidates::{Aim, Layout, ShotKind, direct_aims, rail_aims};
use crate::level::Level;
use crate::noise::{Noise, stream};
use crate::rounds::{self, Rounds, Sampler, Searched, Stats, best_choice};
use billiards_physics::{Event, PocketShape, Shot, Simulation, TipOffset, Vec2};
use billiards_rules::{
    CueBallPlace, Declaration, GameRules, Judgement, Need, Seat, StrokeRecord, Turn,
};
use rayon::prelude::*;

/// What the computer does next.
#[derive(Clone, Debug, PartialEq)]
pub enum Move {
    /// Take option `index` of [`Turn::choices`].
    Choose(usize),
    /// Strike.
    Strike(Stroke),
}

/// A stroke: where to put the cue ball in hand, the shot (before execution noise) and the
/// declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct Stroke {
    /// The cue ball's place, when it is in hand.
    pub place: Option<Vec2>,
    /// The shot as planned.
    pub shot: Shot,
    /// What is declared.
    pub declared: Declaration,
    /// What it tries, when it was aimed (a pot, a bank, a kick, a combination); `None`
    /// for a direction of the fan or an opening stroke.
    pub kind: Option<ShotKind>,
    /// The expected value the search found ([`stroke_value`] units).
    pub value: f64,
}

/// The size of the search at a level.
#[derive(Clone, Copy, Debug)]
struct Effort {
    /// Candidates kept from the noiseless scan, the best first.
    keep: usize,
    /// Noisy samples of each kept candidate.
    samples: usize,
    /// Refinement rounds: the best `k` get `m` more samples each.
    rounds: &'static [(usize, usize)],
    /// Directions of the fan when there is no aim.
    fan: usize,
    /// Places tried with the cue ball in hand.
    places: usize,
}

fn effort(level: Level) -> Effort {
    match level {
        Level::Easy => Effort {
            keep: 16,
            samples: 8,
            rounds: &[(4, 16)],
            fan: 180,
            places: 2,
        },
        Level::Medium => Effort {
            keep: 32,
            samples: 16,
            rounds: &[(8, 32)],
            fan: 360,
            places: 3,
        },
        Level::Hard | Level::Expert | Level::Perfect => Effort {
            keep: 256,
            samples: 32,
            rounds: &[(20, 68), (3, 100)],
            fan: 1440,
            places: 4,
        },
    }
}

/// The value of a judged stroke for its striker: the game won +10 (lost -10), a foul -1,
/// the turn kept +1, with a twentieth of a point for each point the striker gained on the
/// opponent (snooker's pots and penalties, carom's points).
pub fn stroke_value(judgement: &Judgement, before: [u32; 2], after: [u32; 2]) -> f64 {
    let me = judgement.striker.index();
    if let Some(end) = &judgement.end {
        return if end.winner == judgement.striker {
            10.0
        } else {
            -10.0
        };
    }
    let gain = |s: usize| f64::from(after[s]) - f64::from(before[s]);
    let lead = gain(me) - gain(1 - me);
    let turn = if !judgement.fair {
        -1.0
    } else if judgement.continues {
        1.0
    } else {
        0.0
    };
    turn + 0.05 * lead
}

/// The balls on the table of a simulation, by number (the drills' `resting`).
pub use billiards_rules::drill::resting as layout_of;

/// The solver's id of ball `number`.
pub(crate) fn id_of(sim: &Simulation, number: u8) -> Option<usize> {
    sim.numbers().iter().position(|&n| n == number)
}

/// One candidate stroke: the cue ball's place if in hand, the shot, the declaration.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    place: Option<Vec2>,
    shot: Shot,
    declared: Declaration,
    /// What its aim tries (for the words of the decision; the search never reads it).
    kind: Option<ShotKind>,
}

/// Plays `shot` from `sim` (the cue ball at `place` if given) and judges it on a copy of
/// `game`; `None` when the solver or the rules refuse it.
fn try_stroke(game: &dyn GameRules, sim: &Simulation, cue: u8, c: Candidate) -> Option<f64> {
    let mut sim = sim.clone();
    sim.set_record_history(false);
    let id = id_of(&sim, cue)?;
    if let Some(at) = c.place {
        sim.place(id, at, Vec2::ZERO, Default::default()).ok()?;
    }
    let before = layout_of(&sim);
    // A history from here on: the stroke's events start with its strike, as the rules read
    // them (a lean run yields no strike event).
    sim.set_record_history(true);
    sim.strike(id, c.shot).ok()?;
    sim.run_to_rest().ok()?;
    let events: &[Event] = sim.history().events();
    let after = layout_of(&sim);
    let mut copy = game.boxed_clone();
    let points = copy.points();
    let judged = copy
        .judge(&StrokeRecord {
            events,
            numbers: sim.numbers(),
            before: &before,
            after: &after,
            declared: c.declared,
        })
        .ok()?;
    Some(stroke_value(&judged, points, copy.points()))
}

/// The candidates from the cue ball at `from`: aims at the legal balls (into each pocket,
/// off each rail), else a fan of directions; speeds and tips around each.
fn candidates(
    turn: &Turn,
    sim: &Simulation,
    (place, from): (Option<Vec2>, Vec2),
    fan: usize,
) -> Vec<Candidate> {
    let balls: Vec<(u8, Vec2)> = layout_of(sim)
        .into_iter()
        .filter(|&(n, _)| n != turn.cue_ball)
        .collect();
    let layout = Layout {
        table: *sim.table(),
        radius: sim.params().ball.radius,
        cue: from,
        balls,
    };
    let mut out = Vec::new();
    if turn.opening {
        out.extend(opening_candidates(turn, &layout, place));
    }
    // A table without pockets (carom) has no pots to aim at: the fan alone.
    let pocketless = layout.table.pockets == PocketShape::Pocketless;
    let mut aims = Vec::new();
    if !pocketless {
        aims = direct_aims(&layout, &turn.legal_first);
        aims.extend(rail_aims(&layout, &turn.legal_first));
    }
    out.extend(aimed_candidates(turn, &aims, place));
    if aims.is_empty() {
        out.extend(fan_candidates(place, fan));
    }
    out
}

/// Centre, follow and draw: the tips every aimed shot is tried with, since the cue ball's path
/// after contact decides the next shot.
fn aim_tips() -> [TipOffset; 3] {
    [
        TipOffset::default(),
        TipOffset {
            side: 0.0,
            height: 0.3,
        },
        TipOffset {
            side: 0.0,
            height: -0.3,
        },
    ]
}

/// The opening stroke: hard at each legal ball, as a break is played; a separate list because
/// no aim or pocket matters before the rack is open.
fn opening_candidates(turn: &Turn, layout: &Layout, place: Option<Vec2>) -> Vec<Candidate> {
    let from = layout.cue;
    let mut out = Vec::new();
    for &(n, p) in layout
        .balls
        .iter()
        .filter(|(n, _)| turn.legal_first.contains(n))
    {
        let angle = (p.y - from.y).atan2(p.x - from.x);
        for speed in [3.0, 6.0, 9.0] {
            out.push(Candidate {
                place,
                shot: Shot::new(angle, speed),
                // No call on an opening stroke (WPA 2.3, 9.3); a nomination stays.
                declared: if turn.declare.nominate.contains(&n) {
                    Declaration::Nominate { ball: n }
                } else {
                    Declaration::None
                },
                kind: None,
            });
        }
    }
    out
}

/// Each aim at two speeds and three tips, carrying the call the game asks for: the call depends
/// on the game's declaration rule, so it is made here where the aim's pocket is known.
fn aimed_candidates(turn: &Turn, aims: &[Aim], place: Option<Vec2>) -> Vec<Candidate> {
    let declare = |ball: u8, pocket| {
        if turn.declare.pocket != Need::NotUsed {
            Declaration::Pocket { ball, pocket }
        } else if turn.declare.nominate.contains(&ball) {
            Declaration::Nominate { ball }
        } else {
            Declaration::None
        }
    };
    let mut out = Vec::new();
    for aim in aims {
        let pocket = match aim.kind {
            crate::ShotKind::Pot { pocket, .. }
            | crate::ShotKind::Bank { pocket, .. }
            | crate::ShotKind::Kick { pocket, .. }
            | crate::ShotKind::Combo { pocket, .. } => Some(pocket),
            _ => None,
        };
        for k in [1.0, 1.6] {
            for tip in aim_tips() {
                let mut shot = Shot::new(aim.angle, (aim.speed * k).clamp(0.5, 9.0));
                shot.tip = tip;
                out.push(Candidate {
                    place,
                    shot,
                    declared: pocket.map_or(Declaration::None, |p| declare(aim.first, p)),
                    kind: Some(aim.kind),
                });
            }
        }
    }
    out
}

/// No pocket, or no clear line: a fan of directions at several speeds (carom, kicks, escapes).
fn fan_candidates(place: Option<Vec2>, fan: usize) -> Vec<Candidate> {
    // The fan also tries side and its mixes with follow and draw: english bends a carom's
    // rebounds off the cushions.
    let tips = aim_tips();
    let tip = |side: f64, height: f64| TipOffset { side, height };
    let d = 0.3 * std::f64::consts::FRAC_1_SQRT_2;
    let fan_tips = [
        tips[0],
        tips[1],
        tips[2],
        tip(0.3, 0.0),
        tip(-0.3, 0.0),
        tip(d, d),
        tip(-d, d),
        tip(d, -d),
        tip(-d, -d),
    ];
    let mut out = Vec::new();
    for i in 0..fan {
        let angle = std::f64::consts::TAU * i as f64 / fan as f64;
        for speed in [1.5, 2.5, 3.5, 5.0] {
            for tip in fan_tips {
                let mut shot = Shot::new(angle, speed);
                shot.tip = tip;
                out.push(Candidate {
                    place,
                    shot,
                    declared: Declaration::None,
                    kind: None,
                });
            }
        }
    }
    out
}

/// The search of a turn: the noisy samples of a candidate, executed under the planning noise
/// and judged by a copy of the game ([`Sampler`]), and its parts of the one search skeleton
/// ([`Searched`]).
struct Any<'a> {
    game: &'a dyn GameRules,
    sim: &'a Simulation,
    turn: &'a Turn,
    /// Where the cue ball lies: its strokes start there when it is not in hand.
    from: Vec2,
    noise: Noise,
    seed: u64,
}

impl Sampler for Any<'_> {
    type Cand = Candidate;
    type Scratch = ();

    fn scratch(&self) {}

    fn sample(&self, c: &Candidate, id: u64, k: u64, _: &mut ()) -> Stats {
        let mut rng = stream(self.seed, id, k);
        let shot = self.noise.apply(c.shot, self.sim.params(), &mut rng);
        let cue = self.turn.cue_ball;
        let value = try_stroke(self.game, self.sim, cue, Candidate { shot, ..*c });
        // A stroke the solver or the rules refuse counts as a foul.
        let v = value.unwrap_or(-1.0);
        Stats {
            n: 1,
            value: v,
            pots: usize::from(v >= 1.0),
            fouls: usize::from(v < 0.0),
            losses: usize::from(v <= -10.0),
            events: 0,
        }
    }
}

/// Any game's parts of the one search skeleton ([`rounds::find`]): the places the rules
/// accept, every candidate simulated once without noise and the best kept, the level's rounds;
/// no safeties apart and no second ply.
impl Searched for Any<'_> {
    type Budget = Effort;

    fn places(&self, e: &Effort) -> Result<Vec<Option<Vec2>>, AiError> {
        Ok(match self.turn.place {
            CueBallPlace::InHand { .. } => places(self.game, self.sim, self.turn, e.places)
                .into_iter()
                .map(Some)
                .collect(),
            CueBallPlace::AsItLies | CueBallPlace::Placed => vec![None],
        })
    }

    /// Every candidate from every place, each simulated once without noise; the best
    /// `e.keep` by that value (ties: the first generated).
    fn offence(&self, places: &[Option<Vec2>], e: &Effort) -> Vec<Candidate> {
        let all: Vec<Candidate> = places
            .iter()
            .flat_map(|&place| {
                let from = place.unwrap_or(self.from);
                candidates(self.turn, self.sim, (place, from), e.fan)
            })
            .collect();
        let cue = self.turn.cue_ball;
        let mut scanned: Vec<(f64, usize)> = all
            .par_iter()
            .enumerate()
            .filter_map(|(i, &c)| try_stroke(self.game, self.sim, cue, c).map(|v| (v, i)))
            .collect();
        scanned.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        scanned.truncate(e.keep);
        scanned.iter().map(|&(_, i)| all[i]).collect()
    }

    /// None apart: the kept candidates hold the safeties already (a legal hit that passes
    /// the turn is kept when it is valued above the rest).
    fn safeties(&self, _: &[Option<Vec2>], _: &Effort, _: bool) -> Vec<Candidate> {
        Vec::new()
    }

    fn rounds<'b>(&self, e: &'b Effort) -> (usize, &'b [(usize, usize)]) {
        (e.samples, e.rounds)
    }

    /// One ply: the judgement of a stroke is its value.
    fn second_ply(&self, _: &mut Rounds<Candidate>, _: &Effort) {}
}

/// Places for the cue ball in hand that the rules accept: where it lies if allowed, then
/// the accepted points of a grid nearest the legal balls.
fn places(game: &dyn GameRules, sim: &Simulation, turn: &Turn, count: usize) -> Vec<Vec2> {
    let layout = layout_of(sim);
    let others: Vec<(u8, Vec2)> = layout
        .iter()
        .copied()
        .filter(|&(n, _)| n != turn.cue_ball)
        .collect();
    let targets: Vec<Vec2> = layout
        .iter()
        .filter(|(n, _)| turn.legal_first.contains(n))
        .map(|&(_, p)| p)
        .collect();
    let table = game.table();
    let mut grid: Vec<Vec2> = Vec::new();
    let (nx, ny) = (48, 24);
    for i in 1..nx {
        for j in 1..ny {
            let at = Vec2::new(
                (i as f64 / nx as f64 - 0.5) * table.length,
                (j as f64 / ny as f64 - 0.5) * table.width,
            );
            if game.check_hand(at, &others).is_ok() {
                grid.push(at);
            }
        }
    }
    // About 30 cm from a legal ball: near enough to aim well, far enough to cue.
    let cost = |p: Vec2| {
        targets
            .iter()
            .map(|&t| ((t - p).length() - 0.3).abs())
            .fold(f64::INFINITY, f64::min)
    };
    grid.sort_by(|a, b| cost(*a).total_cmp(&cost(*b)));
    let mut out: Vec<Vec2> = Vec::new();
    if let Some(id) = id_of(sim, turn.cue_ball)
        && sim.ball(id).motion.on_table()
        && game.check_hand(sim.ball(id).position, &others).is_ok()
    {
        out.push(sim.ball(id).position);
    }
    for p in grid {
        if out.len() >= count {
            break;
        }
        if out.iter().all(|q| (*q - p).length() > 0.2) {
            out.push(p);
        }
    }
    out
}

/// The best stroke of the turn in play, the cue ball placed if it is in hand: the one search
/// skeleton ([`rounds::find`]) on any game's parts: the places, the kept candidates, the rounds.
pub fn best_stroke(
    game: &dyn GameRules,
    sim: &Simulation,
    level: Level,
    seed: u64,
) -> Result<Stroke, String> {
    let turn = game.turn();
    let cue = id_of(sim, turn.cue_ball)
        .ok_or_else(|| format!("{}: no cue ball on this table", game.name()))?;
    let search = Any {
        game,
        sim,
        turn: &turn,
        from: sim.ball(cue).position,
        noise: level.planning_noise(),
        seed,
    };
    let (c, found) = rounds::find(&search, &effort(level)).map_err(|e| match e {
        AiError::NoBall => format!("{}: no stroke the rules accept was found", game.name()),
        e => format!("{}: {e}", game.name()),
    })?;
    Ok(Stroke {
        place: c.place,
        shot: c.shot,
        declared: c.declared,
        kind: c.kind,
        value: found.value,
    })
}

/// What the computer does next in any game: an option when the rules offer some, else the
/// best stroke.
pub fn decide_any(
    game: &dyn GameRules,
    sim: &Simulation,
    level: Level,
    seed: u64,
) -> Result<Move, String> {
    let turn = game.turn();
    if turn.choices.is_empty() {
        return best_stroke(game, sim, level, seed).map(Move::Strike);
    }
    let me: Seat = turn.striker;
    let layout = layout_of(sim);
    // The options by index; each search behind one is seeded by `seed` itself (no salt).
    let options: Vec<usize> = (0..turn.choices.len()).collect();
    let best = best_choice(&options, seed, |index, _| {
        let mut copy = game.boxed_clone();
        let setup = copy.choose(index, &layout).ok()?;
        // A re-rack or a replace cannot be valued on this table: an even chance.
        let value = match setup {
            billiards_rules::Setup::Keep => {
                let next = copy.turn();
                let v = if next.choices.is_empty() {
                    best_stroke(copy.as_ref(), sim, Level::Easy, seed).map_or(0.0, |s| s.value)
                } else {
                    0.0
                };
                if next.striker == me { v } else { -v }
            }
            _ => 0.0,
        };
        Some((value, ()))
    });
    best.map(|(i, _, ())| Move::Choose(i))
        .ok_or_else(|| format!("{}: no option offered could be taken", game.name()))
}
