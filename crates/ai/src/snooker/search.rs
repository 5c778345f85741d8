//! The snooker search: its parts of the one search skeleton ([`search`]: places in the D,
//! strokes, second ply) and the choices after a foul. Candidates are built in `strokes.rs`, sampled in `sample.rs`, valued in
//! `value.rs`.

use super::budget::SnookerBudget;
use super::context::Snook;
use super::decision::{Nominated, SnookerDecision};
use super::strokes::Cand;
use super::value::d_places;
use crate::AiError;
use crate::candidates::ShotKind;
use crate::noise::Noise;
use crate::rounds::{Planned, Rounds, Searched, at_rest, best_choice, cue_and_base, search};
use billiards_physics::{BallSetup, Shot, Simulation, Vec2};
use billiards_rules::snooker::balls::WHITE;
use billiards_rules::snooker::{Choice, Frame};

/// [`super::decide_snooker`] planned under `noise` with `budget`.
pub fn decide_snooker_with(
    frame: &Frame,
    sim: &Simulation,
    noise: Noise,
    budget: &SnookerBudget,
    seed: u64,
) -> Result<SnookerDecision, AiError> {
    at_rest(frame.end.is_some(), sim)?;
    if !frame.next.choices.is_empty() {
        let inner = budget.choice.as_deref().unwrap_or(budget);
        let (choice, estimate) = choose(frame, sim, noise, inner, seed);
        return Ok(SnookerDecision::Choose { choice, estimate });
    }
    let (cue, base) = cue_and_base(sim, WHITE, frame.next.in_hand)?;
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
    search(&s, budget).map(SnookerDecision::Shoot)
}

/// Snooker's parts of the one search skeleton ([`search`]): places in the D, pots and
/// safeties valued in points (safeties even when a pot scores, if snookers are needed) and
/// the second ply; the nomination is [`Planned`]'s.
impl Searched for Snook<'_> {
    type Budget = SnookerBudget;

    fn places(&self, budget: &SnookerBudget) -> Result<Vec<Option<Vec2>>, AiError> {
        if !self.frame.next.in_hand {
            return Ok(vec![None]);
        }
        let found = d_places(self.frame, &self.base, self.noise, budget.placements);
        if found.is_empty() {
            return Err(AiError::NoPlace);
        }
        Ok(found.into_iter().map(Some).collect())
    }

    fn offence(&self, places: &[Option<Vec2>], budget: &SnookerBudget) -> Vec<Cand> {
        places
            .iter()
            .flat_map(|&p| self.offence(p, budget))
            .collect()
    }

    fn safeties(
        &self,
        places: &[Option<Vec2>],
        budget: &SnookerBudget,
        scoring: bool,
    ) -> Vec<Cand> {
        if scoring && !self.needs {
            return Vec::new();
        }
        places
            .iter()
            .flat_map(|&p| self.safeties(p, budget))
            .collect()
    }

    fn rounds<'b>(&self, budget: &'b SnookerBudget) -> (usize, &'b [(usize, usize)]) {
        (budget.samples, &budget.rounds)
    }

    /// A stroke's two-ply value is as [`crate::twoply`]'s, its outcomes' corrections by
    /// [`Snook::correction`].
    fn second_ply(&self, pool: &mut Rounds<Cand>, budget: &SnookerBudget) {
        if let Some(two) = &budget.second {
            let correct = |c: &Cand, k| self.correction(c, k, &two.reply);
            pool.second_ply(two.finalists, two.outcomes, correct);
        }
    }
}

/// Snooker's plan: the nomination goes with the stroke.
impl Planned for Snook<'_> {
    type Part = Nominated;

    fn stroke(&self, c: &Cand) -> (Shot, Option<Vec2>, ShotKind, Nominated) {
        let nominated = Nominated {
            nominated: c.nominated,
        };
        (c.cand.shot, c.cand.place, c.cand.kind, nominated)
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
    let best = best_choice(&frame.next.choices, seed, |choice, salt| {
        let mut after = frame.clone();
        let chosen = after.choose(choice).ok()?;
        let table = match &chosen.layout {
            Some(l) => replaced(sim, l)?,
            None => sim.clone(),
        };
        let sign = if chosen.next.striker == me { 1.0 } else { -1.0 };
        match decide_snooker_with(&after, &table, noise, budget, salt) {
            Ok(SnookerDecision::Shoot(plan)) => Some((sign * plan.value, ())),
            _ => None,
        }
    });
    match best {
        Some((choice, value, ())) => (choice, value),
        None => (frame.next.choices[0], 0.0),
    }
}
