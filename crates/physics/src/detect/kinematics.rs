//! How a time of impact is predicted: with the balls' real accelerations or linearly.

/// How a time of impact is predicted (see [`crate::Prediction`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kinematics {
    /// With each ball's real constant acceleration.
    Exact,
    /// As if each ball kept its current velocity (the paper's linear prediction).
    Linear,
}
