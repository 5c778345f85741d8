//! Ball–ball time of impact when a ball is in the air: the sphere–sphere quartic in 3D.

use super::tolerances::{RESTING_DEPTH, RESTING_SPEED, SEPARATION};
use crate::ball::Segment;
use crate::math::Vec2;
use crate::poly::{ContactTolerance, Poly, first_contact};

/// Time after `t`, within `horizon`, at which the balls of `a` and `b` touch in space, given
/// their relative position, velocity and acceleration `(dp, dv, da)` in the plane at `t`.
///
/// Each centre's height is `z(tau) = h + v_z tau - g tau^2 / 2` in the air and 0 on the cloth
/// ([`Segment::height_at`]), so with `dz`, `dv_z`, `da_z = g_a - g_b` the relative height,
/// upward speed and acceleration, contact is
/// `|dp + dv tau + da tau^2/2|^2 + (dz + dv_z tau + da_z tau^2/2)^2 = (2R)^2`: the plane's
/// quartic with the same three terms in `z` added, still a quartic in `tau` (quadratic when
/// both fly, gravity cancelling). The culls in the plane stay valid (two centres are at least
/// as far apart in space as in the plane).
pub(super) fn air_contact(
    a: &Segment,
    b: &Segment,
    t: f64,
    (dp, dv, da): (Vec2, Vec2, Vec2),
    contact: f64,
    horizon: f64,
) -> Option<f64> {
    let dz = b.height_at(t) - a.height_at(t);
    let dvz = b.vertical_at(t) - a.vertical_at(t);
    let daz = a.fall - b.fall;
    let f = Poly::new([
        dp.length_squared() + dz * dz - contact * contact,
        2.0 * (dp.dot(dv) + dz * dvz),
        dv.length_squared() + dp.dot(da) + dvz * dvz + dz * daz,
        dv.dot(da) + dvz * daz,
        0.25 * (da.length_squared() + daz * daz),
    ]);
    // The same tolerances as in the plane: f' = 2 d . d' about 2 (contact) x approach speed.
    let tol = ContactTolerance {
        slack: 2.0 * contact * RESTING_SPEED,
        separation: 2.0 * contact * SEPARATION,
        depth: 2.0 * contact * RESTING_DEPTH,
    };
    first_contact(&f, horizon, tol)
}
