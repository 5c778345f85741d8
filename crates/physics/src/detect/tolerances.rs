//! What counts as touching, resting and apart: the speed, depth and gap thresholds every
//! detector and the resting-contact resolution share.

/// Approach speed (m/s) below which touching bodies count as resting against each other rather
/// than colliding. Far above rounding noise in velocities (about 1e-15 m/s at break speeds),
/// far below any speed that moves a ball measurably.
pub const RESTING_SPEED: f64 = 1e-10;

/// Depth (m) to which bodies resting against each other may sink into one another (or a ball
/// into a cushion or jaw) before the contact is resolved as a resting contact (see
/// [`crate::resolve::resting_contact`]), which makes the pair hop apart by about this much.
///
/// Without it, two bodies pressed together by their accelerations (the paper's model
/// decelerates each ball along its own velocity, so neighbours moving in slightly different
/// directions push into each other; a spinning ball curves into a rail) touch again every
/// `2 RESTING_SPEED / a` seconds: a Zeno cascade of millions of events; and bodies drifting
/// into each other slower than [`RESTING_SPEED`] would sink without bound. With it, a pair
/// pressed at `a` m/s^2 touches about `sqrt(a / (8 RESTING_DEPTH))` times a second. Far below
/// the 1e-9 m the stress tests allow.
pub const RESTING_DEPTH: f64 = 2e-10;

/// Gap (m) a resting contact opens between bodies pressed together: they leave it at
/// `sqrt(2 a RESTING_HOP)` for a pressing acceleration `a` (the speed turned from their
/// tangential motion, never added), so a pressed pair touches `sqrt(a / (8 RESTING_HOP))`
/// times a second. Hopping by [`RESTING_DEPTH`] alone, balls wedged in a pocket mouth by a
/// sliding neighbour touched ~50,000 times a second per contact and a jam could exceed the
/// event cap (soak seeds 38383, 43317). A tenth of a micrometre is below the elastic
/// compression of two balls pressed by their own weight, and far below anything visible.
pub const RESTING_HOP: f64 = 1e-7;

/// Distance (m) by which touching bodies must separate before a new contact can start.
pub const SEPARATION: f64 = 1e-15;

/// Height (m) above the cloth under which a ball in the air is level with the balls on it:
/// its contacts with them (and theirs with each other) are resolved in the plane, by the
/// pair law or inside a cluster impact, as on the cloth. Two centres `dz` apart in height
/// and touching in space are `dz^2 / 4R` (8.7e-12 m at 1 um) closer in the plane than
/// touching, far under [`RESTING_DEPTH`], and their normal leaves the plane by `dz / 2R`
/// (1.7e-5): a ball lifted off the slate while frozen against its neighbours (a landing on
/// a rack) is still touching them, and resolving those contacts pair by pair in space,
/// without the cluster impact, repeated them without end at one instant (flight soak seed
/// 5151, shot 17,622).
pub const LEVEL: f64 = 1e-6;
