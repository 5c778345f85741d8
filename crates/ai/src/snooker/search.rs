//! The snooker search: the rounds of noisy evaluation, the second ply and the choices after
//! a foul. Candidates are built in `strokes.rs`, sampled in `sample.rs`, valued in
//! `value.rs`.

use super::budget::{SnookerBudget, SnookerTwoPly};
use super::context::Snook;
use super::decision::{SnookerDecision, SnookerPlan};
use super::strokes::Cand;
use super::value::d_places;
use crate::AiError;
use crate::noise::Noise;
use crate::rounds::Rounds;
use billiards_physics::{BallSetup, Simulation, Vec2};
use billiards_rules::snooker::balls::WHITE;
use billiards_rules::snooker::{Choice, Frame};
use rayon::prelude::*;

/// Below this chance of a fair pot, safeties are searched too.
const SAFETY_BELOW: f64 = 0.6;

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
        second_ply(&mut pool, &s, two);
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

/// Every candidate evaluated so far, with its samples ([`Rounds`], the skeleton every
/// game's search shares).
type Pool = Rounds<Cand>;

/// Values the best finalists two plies deep; they become the only candidates
/// [`Rounds::best`] chooses from. A stroke's value: its one-ply mean plus the mean, over
/// its searched outcomes, of (second-ply value - one-ply value) of the same outcome (a
/// control variate, as [`crate::twoply`]).
fn second_ply(pool: &mut Pool, s: &Snook, two: &SnookerTwoPly) {
    let order = pool.second_ply_order(two.finalists);
    let jobs: Vec<(usize, u64)> = order
        .iter()
        .flat_map(|&i| (0..two.outcomes as u64).map(move |k| (i, k)))
        .collect();
    let corrections: Vec<(f64, usize, usize)> = jobs
        .par_iter()
        .map(|&(i, k)| s.correction(&pool.cands[i], k, &two.reply))
        .collect();
    for (n, &i) in order.iter().enumerate() {
        let mine = &corrections[n * two.outcomes..(n + 1) * two.outcomes];
        let shift = mine.iter().map(|c| c.0).sum::<f64>() / two.outcomes.max(1) as f64;
        pool.two.push((i, pool.stats[i].mean() + shift));
        pool.simulations += mine.iter().map(|c| c.1).sum::<usize>();
        pool.events += mine.iter().map(|c| c.2).sum::<usize>();
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
