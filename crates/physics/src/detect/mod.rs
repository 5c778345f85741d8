//! Detection: when does the next contact of each kind happen? One time-of-impact function per
//! pair kind, each returning `None` for "never within the horizon".

mod ball_air;
mod ball_ball;
mod ball_cushion;
mod ball_jaw;
pub(crate) mod cull;
mod kinematics;
mod straight;
mod tolerances;

pub use ball_ball::{ball_ball, ball_ball_kept, segments_apart};
pub use ball_cushion::{ball_cushion, ball_line, cushion_contact, line_contact};
pub use ball_jaw::ball_jaw;
pub use cull::{MISS_ABSOLUTE_MARGIN, MISS_RELATIVE_MARGIN, MISS_ROUNDING, misses};
pub use kinematics::Kinematics;
pub use tolerances::{LEVEL, RESTING_DEPTH, RESTING_HOP, RESTING_SPEED, SEPARATION};
