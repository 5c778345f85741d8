//! Ball–cushion time of impact: the smallest valid root of a quadratic.

use super::{Kinematics, RESTING_DEPTH, RESTING_SPEED, SEPARATION};
use crate::ball::Segment;
use crate::poly::{ContactTolerance, Poly, first_contact};
use crate::table::Cushion;

/// Time after `t` at which the ball of `seg` reaches `cushion`, within `horizon` seconds.
///
/// `limit` is how far the centre may go from the table's centre line towards this cushion
/// (half the length or width, minus the radius). The gap `limit + n·p(τ)` (n the inward
/// normal) is quadratic in τ; the contact is its first root (paper 3.1, with the deceleration
/// of 3.3 that the paper's linear ray test leaves out).
pub fn ball_cushion(
    seg: &Segment,
    t: f64,
    cushion: Cushion,
    limit: f64,
    horizon: f64,
    kin: Kinematics,
) -> Option<f64> {
    ball_line(seg, t, cushion.inward_normal(), limit, horizon, kin)
}

/// Time after `t` at which the centre of the ball of `seg` reaches the line where
/// `offset + n·p = 0`, coming from the side where it is positive, within `horizon` seconds.
pub fn ball_line(
    seg: &Segment,
    t: f64,
    n: crate::Vec2,
    offset: f64,
    horizon: f64,
    kin: Kinematics,
) -> Option<f64> {
    let p = seg.position_at(t);
    let v = seg.velocity_at(t);
    let a = match kin {
        Kinematics::Exact => seg.acceleration,
        Kinematics::Linear => crate::Vec2::ZERO,
    };
    line_contact(p, v, a, n, offset, horizon)
}

/// [`ball_line`] for a centre at `p` with velocity `v` and acceleration `a` (already chosen by
/// the kinematics) at the start of the search: lets a caller trying several lines compute the
/// state once.
#[inline]
pub fn line_contact(
    p: crate::Vec2,
    v: crate::Vec2,
    a: crate::Vec2,
    n: crate::Vec2,
    offset: f64,
    horizon: f64,
) -> Option<f64> {
    let (vn, an) = (n.dot(v), n.dot(a));
    // Moving away and never turning back: no contact (the common case, decided without roots).
    if vn >= 0.0 && an >= 0.0 {
        return None;
    }
    let c0 = offset + n.dot(p);
    // A straight path (no acceleration towards the line): the same root without the general
    // search.
    if an == 0.0
        && let Some(tau) = crate::poly::first_contact_line(c0, vn, horizon)
    {
        return tau;
    }
    let gap = Poly::new([c0, vn, 0.5 * an, 0.0, 0.0]);
    let tol = ContactTolerance {
        slack: RESTING_SPEED,
        separation: SEPARATION,
        depth: RESTING_DEPTH,
    };
    first_contact(&gap, horizon, tol)
}
