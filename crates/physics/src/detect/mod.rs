//! Detection: when does the next contact of each kind happen? One time-of-impact function per
//! pair kind, each returning `None` for "never within the horizon".

mod ball_ball;
mod ball_cushion;

pub use ball_ball::{ball_ball, ball_jaw};
pub use ball_cushion::{ball_cushion, ball_line};

/// Approach speed (m/s) below which touching bodies count as resting against each other rather
/// than colliding. Far above rounding noise in velocities (about 1e-15 m/s at break speeds),
/// far below any speed that moves a ball measurably.
pub const RESTING_SPEED: f64 = 1e-10;

/// Overlap (m) that a resting contact may build up before its approach counts as a collision.
///
/// Two touching bodies whose accelerations press them together (a ball pushing another, a
/// ball curving into a rail) would otherwise collide again and again at ever shorter
/// intervals (Zeno). An approach only counts once it is faster than `sqrt(2 a depth)`, `a`
/// the relative acceleration: slower, the bodies cannot sink into each other by more than
/// this depth before the approach becomes a collision, and the cycle is bounded.
pub const PRESSING_DEPTH: f64 = 1e-10;

/// Approach speed below which touching bodies with relative acceleration `accel` count as
/// resting against each other (see [`PRESSING_DEPTH`]).
pub fn resting_speed(accel: f64) -> f64 {
    RESTING_SPEED.max((2.0 * accel * PRESSING_DEPTH).sqrt())
}

/// Distance (m) by which touching bodies must separate before a new contact can start.
pub const SEPARATION: f64 = 1e-15;

/// How a time of impact is predicted (see [`crate::Prediction`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kinematics {
    /// With each ball's real constant acceleration.
    Exact,
    /// As if each ball kept its current velocity (the paper's linear prediction).
    Linear,
}
