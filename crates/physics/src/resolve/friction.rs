//! The ball–ball friction of a model, as every ball–ball law reads it: the isolated pair's
//! impulse laws and the cluster's tangential force.

use crate::params::{BallFriction, SpinModel};

/// The ball–ball friction of one model: its constant `mu_ball` and how the coefficient
/// depends on the contact's slip speed ([`BallFriction`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairFriction {
    /// The model's constant coefficient, used by [`BallFriction::Constant`].
    pub constant: f64,
    /// Constant, or speed-dependent (Alciatore TP A-14).
    pub law: BallFriction,
}

impl PairFriction {
    /// The same coefficient `mu` at every slip speed.
    pub fn constant(mu: f64) -> Self {
        Self {
            constant: mu,
            law: BallFriction::Constant,
        }
    }

    /// The spin model's ball–ball friction.
    pub fn of(m: &SpinModel) -> Self {
        Self {
            constant: m.mu_ball,
            law: m.ball_friction,
        }
    }

    /// The coefficient at slip speed `v` (m/s).
    #[inline]
    pub fn at(&self, v: f64) -> f64 {
        self.law.mu(self.constant, v)
    }
}
