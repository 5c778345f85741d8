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
pub mod play;
mod sample;
mod search;
mod strokes;
pub mod value;

use crate::level::Level;
use crate::noise::{self, Noise};
use crate::{AiError, ShotKind};
use billiards_physics::{Params, Shot, Simulation, Vec2};
use billiards_rules::snooker::{Choice, Frame};

pub use budget::{SnookerBudget, SnookerTwoPly};
pub use search::decide_snooker_with;

/// What the computer does next at snooker.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SnookerDecision {
    /// Take one of the choices the rules offer ([`Frame::choose`]).
    Choose {
        /// The choice.
        choice: Choice,
        /// The search's value of the table the choice leads to, in points for the chooser.
        estimate: f64,
    },
    /// Play this stroke.
    Shoot(SnookerPlan),
}

/// A stroke decided on.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SnookerPlan {
    /// The strike meant (angle, speed, tip), before execution noise.
    pub shot: Shot,
    /// Cue ball in hand: where to put it first (inside the D, clear of every ball).
    pub place: Option<Vec2>,
    /// The colour nominated after a red (2.12) or the free ball (3.12): pass it as
    /// `Stroke::nominated`.
    pub nominated: Option<u8>,
    /// What the stroke tries.
    pub kind: ShotKind,
    /// Estimated probability of a fair pot.
    pub success: f64,
    /// Estimated probability of a foul.
    pub foul: f64,
    /// The search's mean value of the stroke, in points for the striker.
    pub value: f64,
    /// Noisy samples behind the estimates of this stroke.
    pub samples: usize,
    /// Noisy simulations the whole decision ran.
    pub simulations: usize,
    /// Solver events those simulations processed.
    pub events: usize,
}

impl SnookerPlan {
    /// The shot as a player of execution noise `noise` strikes it, from the stream of
    /// `seed` (a function of the seed only), as [`crate::Plan::executed`].
    pub fn executed(&self, noise: Noise, params: &Params, seed: u64) -> Shot {
        noise.apply(self.shot, params, &mut noise::stream(seed, u64::MAX, 0))
    }
}

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
