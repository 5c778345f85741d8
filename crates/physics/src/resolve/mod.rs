//! Resolution: what a contact does to the velocities. One model per collision kind, named
//! after its source.

mod ball_ball;
mod ball_cushion;

pub use ball_ball::{equal_mass_restitution, resting_contact};
pub use ball_cushion::{reflect, resting_reflect};
