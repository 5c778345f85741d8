//! Resolution: what a contact does to the velocities. One model per collision kind, named
//! after its source.

mod ball_ball;
mod ball_cushion;
pub mod cue;

pub use ball_ball::{equal_mass_restitution, frictional_spheres, resting_contact, unpress};
pub use ball_cushion::{SETTLE_SPEED, han_2005, reflect, resting_reflect, settle};
