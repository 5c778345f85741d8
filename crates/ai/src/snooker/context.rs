//! What one snooker search shares ([`Snook`]): the frame, the table at rest and the noise it
//! plans under. The search (`search.rs`) builds it; the strokes, samples and values
//! (`strokes.rs`, `sample.rs`, `value.rs`) each add their methods to it. It lives here, not in
//! the search that calls them, so that they need not import the search back (issue 50).

use crate::noise::Noise;
use billiards_physics::{BallId, Simulation};
use billiards_rules::Seat;
use billiards_rules::snooker::Frame;

/// What one search shares: the frame, the table at rest and the noise it plans under.
pub(super) struct Snook<'a> {
    pub(super) frame: &'a Frame,
    pub(super) base: Simulation,
    pub(super) cue: BallId,
    pub(super) noise: Noise,
    pub(super) seed: u64,
    pub(super) me: Seat,
    /// The striker needs snookers: a pot gains him nothing.
    pub(super) needs: bool,
}
