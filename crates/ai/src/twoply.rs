//! The second ply: position valued by simulation, as the computational-pool tournament
//! winners did (CueCard and PickPocket on FastFiz searched the next shot from each sampled
//! outcome of a candidate).
//!
//! For each of the best few shots of a decision, [`TwoPly::outcomes`] noisy draws (one
//! stream common to the shots: close shots meet the same errors) are run to rest and judged
//! by the rules;
//! the rules' state after each says who shoots next and what is legal (ball in hand after a
//! foul, the group after an 8-ball pot). From that table the next shot is searched with the
//! same candidates and noise on a smaller budget ([`TwoPly::reply`]), and its best value
//! counts for the shooter when they stay at the table, against them when the opponent
//! shoots (a safety is worth what the opponent's best reply leaves them).
//!
//! The blend: the two-ply value of a shot is its one-ply mean over all its samples plus the
//! mean, over the searched outcomes, of (second-ply value - one-ply value) of the same
//! outcome. The one-ply mean measures how often the shot pots, fouls or loses with all its
//! samples (hard: 172); the few searched outcomes only correct the value of the positions
//! they leave, and since both terms of each difference come from the same run, the luck of
//! which outcome was drawn cancels (a control variate). Over many outcomes this is the plain
//! two-ply mean; with few it is far less noisy than their plain mean.
//!
//! Tried and dropped: centring the differences (subtracting their mean over the decision's
//! outcomes, by who shoots next) to keep the one-ply balance of pots against safeties. The
//! outcomes of safeties and of missed pots differ too much for one mean: a good safety came
//! out 0.55 above its one-ply value, where its plain difference is 0.25.
//! Outcomes that end the game, ask for a choice (a push out to accept) or a re-rack are not
//! searched: their difference is 0.

use crate::candidates::{Candidate, Layout};
use crate::evaluate::Search;
use crate::level::{Budget, TwoPly};
use crate::noise::stream;
use crate::rounds::Correction;
use crate::{Decision, decide_planned};
use rand::Rng;

/// The stream of the outcomes' draws: common to every shot (common random numbers: shots
/// that differ a little meet the same execution errors, so the second ply compares their
/// positions, not their luck), far from the candidates' own streams and
/// [`crate::Plan::executed`]'s `u64::MAX`.
const OUTCOMES: u64 = 1 << 62;
/// The stream of the seeds of the next-shot searches, draw `k` at `(seed, STREAMS, k)`.
const STREAMS: u64 = (1 << 62) + 1;

/// Draw `k` of the outcomes' stream struck as `cand`: its second-ply value minus its one-ply
/// value, and the work it took ([`crate::rounds::Rounds::second_ply`] runs the outcomes and
/// blends them).
pub(crate) fn correction(search: &Search, cand: &Candidate, k: u64, two: TwoPly) -> Correction {
    let Some((mut table, summary, events)) = search.outcome(cand, OUTCOMES, k) else {
        return (0.0, 1, 0);
    };
    let me = search.state.next.shooter;
    let mut after = search.state.clone();
    let Ok(verdict) = after.play(&summary, cand.call) else {
        return (0.0, 1, events);
    };
    let potted = summary.pocketed_object_balls().next().is_some();
    let layout = Layout::of(&table, None);
    let (one, _) = search.score(&verdict, layout.as_ref(), me, potted);
    let next = &after.next;
    if after.over.is_some() || !next.choices.is_empty() || next.rerack || next.break_shot {
        return (0.0, 1, events);
    }
    let sign = if next.shooter == me { 1.0 } else { -1.0 };
    if crate::play::spot_balls(&mut table, &next.spot.clone()).is_err() {
        return (0.0, 1, events);
    }
    after.next.spot.clear();
    let seed = stream(search.seed, STREAMS, k).random();
    let reply = Budget {
        second: None,
        ..two.reply.clone()
    };
    match decide_planned(&after, &table, search.noise, &reply, seed, search.mode) {
        Ok(Decision::Shoot(plan)) => (
            sign * plan.value - one,
            1 + plan.simulations,
            events + plan.events,
        ),
        _ => (0.0, 1, events),
    }
}
