//! What the computer decides at snooker: a choice after a foul, or a stroke
//! ([`SnookerPlan`]). The search (`search.rs`) returns it and `mod.rs` hands it on; it lives
//! here, below both, so that the search need not import its caller (issue 50).

use crate::ShotKind;
use crate::noise::{self, Noise};
use billiards_physics::{Params, Shot, Vec2};
use billiards_rules::snooker::Choice;

/// What the computer does next at snooker.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SnookerDecision {
    /// Take one of the choices the rules offer ([`Frame::choose`](billiards_rules::snooker::Frame::choose)).
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
