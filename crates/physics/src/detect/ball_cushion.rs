//! Ball–cushion time of impact: the smallest valid root of a quadratic.

use super::kinematics::Kinematics;
use super::tolerances::{RESTING_DEPTH, RESTING_SPEED, SEPARATION};
use crate::ball::Segment;
use crate::math::Vec2;
use crate::poly::{ContactTolerance, Poly, first_contact};
use crate::table::{Cushion, PocketShape, Table};

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
    n: Vec2,
    offset: f64,
    horizon: f64,
    kin: Kinematics,
) -> Option<f64> {
    let p = seg.position_at(t);
    let v = seg.velocity_at(t);
    let a = match kin {
        Kinematics::Exact => seg.acceleration,
        Kinematics::Linear => Vec2::ZERO,
    };
    line_contact(p, v, a, n, offset, horizon)
}

/// [`ball_line`] for a centre at `p` with velocity `v` and acceleration `a` (already chosen by
/// the kinematics) at the start of the search: lets a caller trying several lines compute the
/// state once.
#[inline]
pub fn line_contact(p: Vec2, v: Vec2, a: Vec2, n: Vec2, offset: f64, horizon: f64) -> Option<f64> {
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

/// Time after `t` at which the ball of `seg` touches `cushion` of `table`, within `horizon`
/// seconds; `limit` as in [`ball_cushion`], `(p, v, a)` the centre's position and velocity
/// at `t` and its acceleration as the kinematics predict it (computed once for all four
/// cushions).
///
/// With the paper's mouths, any contact with the cushion line counts (a contact inside a
/// mouth pockets the ball); on a table without pockets every contact is on the cushion. With jaws, only contacts on the cushion itself count: a root in a
/// mouth means the ball crossed the line's extension into the mouth, and the search goes on
/// from where it comes back out.
#[inline]
pub fn cushion_contact(
    seg: &Segment,
    t: f64,
    (p, v, a): (Vec2, Vec2, Vec2),
    cushion: Cushion,
    limit: f64,
    table: &Table,
    horizon: f64,
) -> Option<f64> {
    let tau = line_contact(p, v, a, cushion.inward_normal(), limit, horizon)?;
    if !matches!(table.pockets, PocketShape::Jaws { .. })
        || table.on_cushion(cushion, seg.position_at(t + tau))
    {
        return Some(tau);
    }
    cushion_contact_past_mouths(seg, t, a, cushion, limit, table, horizon)
}

/// [`cushion_contact`] on a table with jaws, searched from `t` again: each root in a mouth
/// is skipped to where the centre is back on the table side of the line.
fn cushion_contact_past_mouths(
    seg: &Segment,
    t: f64,
    a: Vec2,
    cushion: Cushion,
    limit: f64,
    table: &Table,
    horizon: f64,
) -> Option<f64> {
    let n = cushion.inward_normal();
    let mut from = 0.0;
    // A path is a parabola: it crosses a line at most twice, so two retries suffice.
    for _ in 0..3 {
        let start = t + from;
        let (p, v) = (seg.position_at(start), seg.velocity_at(start));
        let tau = line_contact(p, v, a, n, limit, horizon - from)? + from;
        if !matches!(table.pockets, PocketShape::Jaws { .. })
            || table.on_cushion(cushion, seg.position_at(t + tau))
        {
            return Some(tau);
        }
        // In a mouth: skip to where the centre is back on the table side of the line.
        let p = seg.position_at(t + tau);
        let v = seg.velocity_at(t + tau);
        let back = Poly::new([
            -(limit + n.dot(p)) + SEPARATION,
            -n.dot(v),
            -0.5 * n.dot(a),
            0.0,
            0.0,
        ]);
        let out = crate::poly::first_entry(
            &back,
            0.0,
            (horizon - tau).min(crate::poly::root_bound(&back)),
        )?;
        from = tau + out.max(f64::EPSILON * (t + tau).abs());
    }
    None
}
