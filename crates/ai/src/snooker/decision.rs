//! What the computer decides at snooker: the one plan and decision of every game
//! ([`crate::plan`]) with snooker's choice and its per-game part, the nomination. The search
//! (`search.rs`) returns it and `mod.rs` hands it on; it lives here, below both, so that the
//! search need not import its caller (issue 50).

use crate::plan::{Decision, Plan};
use billiards_rules::snooker::Choice;

/// Snooker's part of a plan: the ball nominated with the stroke.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Nominated {
    /// The colour nominated after a red (2.12) or the free ball (3.12): pass it as
    /// `Stroke::nominated`.
    pub nominated: Option<u8>,
}

/// What the computer does next at snooker: a choice after a foul
/// ([`Frame::choose`](billiards_rules::snooker::Frame::choose)) or a stroke.
pub type SnookerDecision = Decision<Choice, Nominated>;

/// A stroke decided on at snooker (`plan.nominated` the nomination).
pub type SnookerPlan = Plan<Nominated>;
