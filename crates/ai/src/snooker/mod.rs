//! The computer at snooker (WPBSA Official Rules, November 2019): [`decide_snooker`] reads a
//! [`Frame`] and the table at rest and returns a choice after a foul or a stroke to play.
//!
//! How it decides, in points (the striker's expected points minus the opponent's):
//! - candidates (`strokes.rs`): ghost-ball pots of every ball on into every pocket (with banks,
//!   kicks and red-on-red plants when the level's budget has them) in the level's speeds and
//!   tips, the best aims first; safeties (hits from full to thin on the nearest balls on, three
//!   speeds) when nothing pots well or snookers are needed; with the cue ball in hand, the same
//!   from the best few places in the D ([`value::d_places`]);
//! - each candidate struck (`sample.rs`) under the level's execution noise and judged by the rules
//!   ([`Frame::play`] on a clone); value = points scored − penalty conceded, plus the
//!   position: the analytic chance of the next ball on times its worth for the striker if he
//!   stays at the table, minus the same for the opponent otherwise; a snooker left earns a
//!   bonus (the opponent's expected foul, 3.10). After a red the colour whose pot leaves the
//!   best continuation is the one aimed at and nominated (2.12);
//! - when the striker needs snookers (behind by more than the points left,
//!   [`Frame::snookers_required`]) a pot gains nothing, so a snooker or a safety wins;
//! - choices after a foul (play on, put the offender back, replace after a miss, who plays the
//!   re-spotted black) by the same search from each resulting table, for whoever plays it.
//!
//! Randomness comes from [`crate::noise::stream`] named by the seed and the candidate and
//! sample indices: the same seed gives the same decision on any number of threads.

pub mod budget;
mod context;
mod decision;
pub mod play;
mod sample;
mod search;
mod strokes;
pub mod value;

use crate::AiError;
use crate::level::Level;
use billiards_physics::Simulation;
use billiards_rules::snooker::Frame;

pub use budget::{SnookerBudget, SnookerTwoPly};
pub use decision::{Nominated, SnookerDecision, SnookerPlan};
pub use search::decide_snooker_with;

/// The computer's decision at `level` for what `frame` asks next, on the resting table
/// `sim` (the snooker table, `Params::snooker()`, colours of the last verdict spotted, a
/// replaced layout set). With the cue ball in hand it may be anywhere or off the table; the
/// plan's place is in the D. The same `seed` gives the same decision on any number of
/// threads.
pub fn decide_snooker(
    frame: &Frame,
    sim: &Simulation,
    level: Level,
    seed: u64,
) -> Result<SnookerDecision, AiError> {
    decide_snooker_with(
        frame,
        sim,
        level.planning_noise(),
        &SnookerBudget::of(level),
        seed,
    )
}
