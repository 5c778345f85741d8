//! When a ball–ball contact is a cluster impact: how far its reach goes, the slowest approach
//! that makes one and the largest cluster resolved at once (`cluster.rs` resolves it).

use crate::params::{HertzContact, Model};
use crate::resolve;
use crate::resolve::hertz::Hertz;

/// Slowest approach (m/s) that makes a cluster impact; slower contacts are resolved pair by
/// pair (their balls move less than a micrometre before stopping, so their order is moot).
pub const CLUSTER_MIN_SPEED: f64 = 1e-3;

/// Most balls in one cluster impact; a larger connected cluster is resolved pair by pair.
pub const MAX_CLUSTER: usize = 64;

/// The cluster distance: balls whose surfaces are closer than this to a ball of a contact
/// whose pair approaches at `approach` (m/s, along their normal) take part in it (`None`
/// without a cluster model, or when the contact is too slow or resting: `depth` is how far
/// the pair is into each other, `pressing` their relative normal acceleration, as in
/// [`resolve::is_resting`]).
pub fn cluster_reach(
    model: &Model,
    ball: &crate::params::BallSpec,
    approach: f64,
    depth: f64,
    pressing: f64,
) -> Option<f64> {
    let Model::Spin(m) = model else { return None };
    let material: HertzContact = m.cluster?;
    if approach.is_nan()
        || approach <= CLUSTER_MIN_SPEED
        || resolve::is_resting(depth, approach, pressing)
    {
        return None;
    }
    Some(Hertz::elastic(&material, ball).reach(approach))
}
