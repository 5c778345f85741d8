//! Detection: when does the next contact of each kind happen? One time-of-impact function per
//! pair kind, each returning `None` for "never within the horizon".

mod ball_ball;
mod ball_cushion;

pub use ball_ball::ball_ball;
pub use ball_cushion::{ball_cushion, ball_line};

/// Approach speed (m/s) below which touching bodies count as resting against each other rather
/// than colliding. Far above rounding noise in velocities (about 1e-15 m/s at break speeds),
/// far below any speed that moves a ball measurably.
pub const RESTING_SPEED: f64 = 1e-10;

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
