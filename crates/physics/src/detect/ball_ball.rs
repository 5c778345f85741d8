//! Ball–ball time of impact: the smallest non-negative root of a quartic.

use super::ball_air::air_contact;
use super::cull::misses;
use super::kinematics::Kinematics;
use super::straight::straight_contact;
use super::tolerances::{RESTING_DEPTH, RESTING_SPEED, SEPARATION};
use crate::ball::{Motion, Segment};
use crate::math::Vec2;
use crate::poly::{ContactTolerance, Poly, first_contact};

/// Time after `t` at which the balls of `a` and `b` touch, within `horizon` seconds.
///
/// With `dp`, `dv`, `da` the relative position, velocity and acceleration at `t`, contact is
/// `|dp + dv τ + da τ²/2|² = (2R)²`, a quartic in τ (the paper's quadratic of 3.2 has
/// `2 (dp · dv)` as its middle coefficient, slip 2, and omits `da`, slip 4).
/// Pairs whose reachable discs cannot meet are culled before any polynomial is built.
pub fn ball_ball(
    a: &Segment,
    b: &Segment,
    t: f64,
    radius: f64,
    horizon: f64,
    kin: Kinematics,
) -> Option<f64> {
    let (dp, dv, da) = relative(a, b, t, kin)?;
    let contact = 2.0 * radius;
    if misses(dp, dv, da, contact, horizon) {
        return None;
    }
    reachable_contact(a, b, t, (dp, dv, da), contact, horizon)
}

/// [`ball_ball`] for a pair that [`misses`] has kept already (the batched cull of a
/// single-cell scene makes the same test): the reach and sweep culls, then the quartic.
pub fn ball_ball_kept(
    a: &Segment,
    b: &Segment,
    t: f64,
    radius: f64,
    horizon: f64,
    kin: Kinematics,
) -> Option<f64> {
    let rel = relative(a, b, t, kin)?;
    reachable_contact(a, b, t, rel, 2.0 * radius, horizon)
}

/// Position, velocity and acceleration (as the kinematics predict it) of `b` relative to
/// `a` at `t`; `None` when neither moves.
#[inline]
fn relative(a: &Segment, b: &Segment, t: f64, kin: Kinematics) -> Option<(Vec2, Vec2, Vec2)> {
    if !a.state.motion.is_moving() && !b.state.motion.is_moving() {
        return None;
    }
    let dp = b.position_at(t) - a.position_at(t);
    let dv = b.velocity_at(t) - a.velocity_at(t);
    let da = match kin {
        Kinematics::Exact => b.acceleration - a.acceleration,
        Kinematics::Linear => Vec2::ZERO,
    };
    Some((dp, dv, da))
}

/// The reach and sweep culls of [`ball_ball`], then the contact quartic, for relative
/// position, velocity and acceleration `(dp, dv, da)` at `t`.
#[inline]
fn reachable_contact(
    a: &Segment,
    b: &Segment,
    t: f64,
    (dp, dv, da): (Vec2, Vec2, Vec2),
    contact: f64,
    horizon: f64,
) -> Option<f64> {
    let (ma, mb) = (a.state.motion.is_moving(), b.state.motion.is_moving());
    let (ra, rb) = (a.reach(t, horizon), b.reach(t, horizon));
    // Margin covers rounding in the reach bound itself.
    let reach = (ra + rb) * (1.0 + 1e-12) + 1e-12 + contact;
    if dp.length_squared() > reach * reach {
        return None;
    }
    // Against a resting ball (where the cull above knows nothing of the deceleration).
    if !(ma && mb)
        && let (Some(pa), Some(pb)) = (sweep(a, t, ra), sweep(b, t, rb))
        && segments_apart(pa, pb) > (contact + 2.0 * (ra + rb) * 1e-12) * (1.0 + 1e-9) + 1e-9
    {
        return None;
    }
    if a.state.motion == Motion::Airborne || b.state.motion == Motion::Airborne {
        return air_contact(a, b, t, (dp, dv, da), contact, horizon);
    }
    contact_quartic(dp, dv, da, contact, horizon)
}

/// The segment swept by the centre of a ball on a straight path (at rest, or decelerating
/// along its velocity, as in the paper's model) from `t` over a distance `reach`: from its
/// position at `t` along its velocity. `None` for a curving path.
fn sweep(s: &Segment, t: f64, reach: f64) -> Option<(Vec2, Vec2)> {
    let p = s.position_at(t);
    if !s.state.motion.is_moving() {
        return Some((p, p));
    }
    if !s.straight {
        return None;
    }
    let dir = s.velocity_at(t).normalized().unwrap_or(Vec2::ZERO);
    Some((p, p + dir * reach))
}

/// Smallest distance between two segments (zero if they cross). Two balls on straight paths
/// can touch only if their swept segments come within the contact distance, whenever each
/// passes there: for a ball driven at a resting one (most pairs of a break) this is the exact
/// test of its path, where the reach bound is only a disc. The computer player's quiet-table
/// test uses it too.
pub fn segments_apart((p, q): (Vec2, Vec2), (r, s): (Vec2, Vec2)) -> f64 {
    let side = |a: Vec2, b: Vec2, c: Vec2| (b - a).perp_dot(c - a);
    let (d1, d2) = (side(p, q, r), side(p, q, s));
    let (d3, d4) = (side(r, s, p), side(r, s, q));
    if (d1 > 0.0 && d2 < 0.0 || d1 < 0.0 && d2 > 0.0)
        && (d3 > 0.0 && d4 < 0.0 || d3 < 0.0 && d4 > 0.0)
    {
        return 0.0;
    }
    let to = |x: Vec2, a: Vec2, b: Vec2| {
        let ab = b - a;
        let len2 = ab.length_squared();
        let u = if len2 > 0.0 {
            ((x - a).dot(ab) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (x - (a + ab * u)).length()
    };
    to(p, r, s)
        .min(to(q, r, s))
        .min(to(r, p, q))
        .min(to(s, p, q))
}

/// First time within `horizon` at which `|dp + dv τ + da τ²/2|` comes down to `contact`
/// (a contact that starts; see [`first_contact`]). A pair apart whose relative motion runs
/// along a line (a straight path against a resting ball or a jaw) is answered in closed form
/// when it can be vouched for ([`super::straight`]), as the general search would to 1e-13 s.
pub(super) fn contact_quartic(
    dp: Vec2,
    dv: Vec2,
    da: Vec2,
    contact: f64,
    horizon: f64,
) -> Option<f64> {
    let (f, tol) = quartic(dp, dv, da, contact);
    if da != Vec2::ZERO
        && let Some(answer) = straight_contact(&f, (dp, dv, da), contact, horizon)
    {
        return answer;
    }
    first_contact(&f, horizon, tol)
}

/// [`contact_quartic`] by the general search alone (the reference of the closed form's tests).
#[cfg(test)]
pub(super) fn contact_quartic_general(
    dp: Vec2,
    dv: Vec2,
    da: Vec2,
    contact: f64,
    horizon: f64,
) -> Option<f64> {
    let (f, tol) = quartic(dp, dv, da, contact);
    first_contact(&f, horizon, tol)
}

/// The contact function `|dp + dv τ + da τ²/2|² - contact²` and its tolerances.
#[inline]
pub(super) fn quartic(dp: Vec2, dv: Vec2, da: Vec2, contact: f64) -> (Poly, ContactTolerance) {
    let f = Poly::new([
        dp.length_squared() - contact * contact,
        2.0 * dp.dot(dv),
        dv.length_squared() + dp.dot(da),
        dv.dot(da),
        0.25 * da.length_squared(),
    ]);
    // f' = 2 d · d' ≈ 2 (contact) × approach speed, so the speed tolerances scale by it.
    let tol = ContactTolerance {
        slack: 2.0 * contact * RESTING_SPEED,
        separation: 2.0 * contact * SEPARATION,
        // |d|^2 - contact^2 at a depth of RESTING_DEPTH, to first order.
        depth: 2.0 * contact * RESTING_DEPTH,
    };
    (f, tol)
}
