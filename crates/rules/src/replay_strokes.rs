//! A recording replayed stroke by stroke for a rules log to re-judge it: its setup, its
//! placements, parameter changes and strikes in order, and for each stroke the table at its
//! strike and the solver once its balls rest ([`replay_strokes`]). The logs of every kind
//! ([`crate::StrokeLog`], [`crate::snooker::FrameLog`]) judge through it, each with its own
//! rules ([`StrokeJudge`]).

use billiards_physics::recording::{Action, Recording};
use billiards_physics::{Simulation, Vec2};

/// A stroke whose balls have come to rest (or whose recording went on before they did).
#[derive(Clone, Debug, PartialEq)]
pub struct Replayed {
    /// Its number, from 1.
    pub k: usize,
    /// Every ball on the table at its strike, by number.
    pub before: Vec<(u8, Vec2)>,
    /// The index of its first event (the strike) in the solver's history.
    pub first: usize,
}

/// What a rules log does at each stroke of a replayed recording.
pub trait StrokeJudge {
    /// The log's error.
    type Error;
    /// The error for a recording that does not replay: `what` says where and why.
    fn replay_error(&self, what: String) -> Self::Error;
    /// Stroke `k` is about to strike solver ball `ball` on the table `sim` shows (the
    /// logged options are taken here, the cue ball and the table checked).
    fn strike(&mut self, k: usize, sim: &Simulation, ball: usize) -> Result<(), Self::Error>;
    /// The balls of `stroke` rest, or the next input came before they did (`sim` says which):
    /// judge it.
    fn rest(&mut self, sim: &Simulation, stroke: Replayed) -> Result<(), Self::Error>;
}

/// The strikes `recording` holds.
pub fn strikes(recording: &Recording) -> usize {
    recording
        .inputs
        .iter()
        .filter(|i| matches!(i.action, Action::Strike { .. }))
        .count()
}

/// Replays `recording`, calling `judge` at each strike and once each stroke's balls rest (the
/// last one run to rest when the recording was saved while they moved). Returns the strokes
/// replayed.
pub fn replay_strokes<J: StrokeJudge>(
    recording: &Recording,
    judge: &mut J,
) -> Result<usize, J::Error> {
    let mut sim = recording
        .start()
        .map_err(|e| judge.replay_error(format!("setup: {e}")))?;
    let mut pending: Option<Replayed> = None;
    let mut k = 0;
    for (i, input) in recording.inputs.iter().enumerate() {
        let at = |e: &dyn std::fmt::Display| format!("input {i} at t = {}: {e}", input.time);
        sim.advance_to(input.time)
            .map_err(|e| judge.replay_error(at(&e)))?;
        if let Some(stroke) = pending.take() {
            judge.rest(&sim, stroke)?;
        }
        if let Action::Strike { ball, .. } = input.action {
            k += 1;
            judge.strike(k, &sim, ball)?;
            let before = layout(&sim);
            let first = sim.history().events().len();
            pending = Some(Replayed { k, before, first });
        }
        input
            .action
            .apply_to(&mut sim)
            .map_err(|e| judge.replay_error(at(&e)))?;
    }
    if let Some(stroke) = pending.take() {
        sim.advance_to(recording.end_time)
            .map_err(|e| judge.replay_error(format!("to the end: {e}")))?;
        if !sim.is_at_rest() {
            // Saved while the balls were moving: the rest follows from the physics.
            sim.run_to_rest()
                .map_err(|e| judge.replay_error(format!("to rest: {e}")))?;
        }
        judge.rest(&sim, stroke)?;
    }
    Ok(k)
}

/// Every ball on the table by number.
pub fn layout(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}
