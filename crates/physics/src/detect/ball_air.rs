//! Ball–ball time of impact when a ball is in the air: the sphere–sphere quartic in 3D.

use super::tolerances::{RESTING_DEPTH, RESTING_SPEED, SEPARATION};
use crate::ball::Segment;
use crate::math::Vec2;
use crate::poly::{ContactTolerance, Poly, first_contact, first_entry_decreasing, root_bound};

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
    space_contact((dp, dv, da), (dz, dvz, daz), contact, horizon)
}

/// [`air_contact`] from the relative motion in the plane `(dp, dv, da)` and in height
/// `(dz, dvz, daz)`: the quartic, unless the balls surely recede ([`receding`]).
fn space_contact(
    (dp, dv, da): (Vec2, Vec2, Vec2),
    (dz, dvz, daz): (f64, f64, f64),
    contact: f64,
    horizon: f64,
) -> Option<f64> {
    let f = contact_poly((dp, dv, da), (dz, dvz, daz), contact);
    if receding(&f, horizon) || clear(&f, horizon) {
        return None;
    }
    if let Some(t) = falling_contact(&f, horizon) {
        return Some(t);
    }
    first_contact(&f, horizon, tolerance(contact))
}

/// The contact function `f(t) = |d(t)|^2 - contact^2` of two balls whose centres differ by
/// `d(t) = (dp + dv t + da t^2 / 2, dz + dvz t + daz t^2 / 2)`: a quartic in `t`.
fn contact_poly(
    (dp, dv, da): (Vec2, Vec2, Vec2),
    (dz, dvz, daz): (f64, f64, f64),
    contact: f64,
) -> Poly {
    Poly::new([
        dp.length_squared() + dz * dz - contact * contact,
        2.0 * (dp.dot(dv) + dz * dvz),
        dv.length_squared() + dp.dot(da) + dvz * dvz + dz * daz,
        dv.dot(da) + dvz * daz,
        0.25 * (da.length_squared() + daz * daz),
    ])
}

/// The sum of the sizes of `f`'s terms at `t = h`, the scale of the rounding of its
/// evaluations over `[0, h]`.
fn terms_size(f: &Poly, h: f64) -> f64 {
    let [c0, c1, c2, c3, c4] = f.c;
    c0.abs() + (c1.abs() + (c2.abs() + (c3.abs() + c4.abs() * h) * h) * h) * h
}

/// The first contact of a pair apart now and drawing together (`f(0) > 0 > f'(0)`), when
/// `f` surely falls all the way to it ([`first_entry_decreasing`]): a ball coming down into a
/// rack, most contacts in space. Over the same window as [`first_contact`]'s search of a pair
/// apart (the horizon, or the root bound). `p'(t) = c1 + 2 c2 t + 3 c3 t^2 + 4 c4 t^3` is at
/// most `c1` plus its other terms' positive parts, which only grow with `t`: below zero at
/// `x` by [`RECEDING_MARGIN`] of its terms' sizes (far above rounding), `f' < 0` on `[0, x]`.
/// A quadratic (both balls in the air) keeps the closed form of [`first_contact`].
fn falling_contact(f: &Poly, horizon: f64) -> Option<f64> {
    let [c0, c1, c2, c3, c4] = f.c;
    if !(c0 > 0.0 && c1 < 0.0 && (c3 != 0.0 || c4 != 0.0)) {
        return None;
    }
    let b = horizon.min(root_bound(f));
    let (k2, k3, k4) = (
        (2.0 * c2).max(0.0),
        (3.0 * c3).max(0.0),
        (4.0 * c4).max(0.0),
    );
    let falls = |x: f64| {
        let rise = ((k4 * x + k3) * x + k2) * x;
        rise + c1 < RECEDING_MARGIN * (c1 - rise)
    };
    first_entry_decreasing(f, b, falls)
}

/// The same tolerances as in the plane: `f' = 2 d . d'` about 2 (contact) x approach speed.
fn tolerance(contact: f64) -> ContactTolerance {
    ContactTolerance {
        slack: 2.0 * contact * RESTING_SPEED,
        separation: 2.0 * contact * SEPARATION,
        depth: 2.0 * contact * RESTING_DEPTH,
    }
}

/// Relative margin of [`receding`] over the rounding of the contact function's evaluation
/// (about 1e-16 of the sum of its terms' sizes over the window).
const RECEDING_MARGIN: f64 = 1e-8;

/// Do the balls surely draw apart over the whole of `[0, horizon]`? Then [`first_contact`]
/// finds no contact, and its searches are saved. The contact function `f = |d|^2 - (2R)^2`
/// must be increasing throughout: its derivative, a cubic, at least `RECEDING_MARGIN` of its
/// terms' sizes at its least over the window (at an end or at a critical point, the closed-form
/// roots of its derivative, a quadratic), far above rounding. With `f` apart now by as much
/// (`f(0) > 0`), every evaluation the search makes is positive; touching now (`f(0) <= 0`, the
/// pair just resolved, parting), the search's approach test never fires, so no sinking
/// contact, and `f` is positive from the time it counts them apart onwards, so no new
/// contact. Most pairs in space that touched or meet no one part so: a ball bounced up off
/// another, or one coming down beside others while they move away.
fn receding(f: &Poly, horizon: f64) -> bool {
    if !(horizon.is_finite() && horizon > 0.0) {
        return false;
    }
    let h = horizon;
    let [c0, c1, c2, c3, c4] = f.c;
    // f' = a0 + a1 t + a2 t^2 + a3 t^3.
    let (a0, a1, a2, a3) = (c1, 2.0 * c2, 3.0 * c3, 4.0 * c4);
    let d_scale = a0.abs() + (a1.abs() + (a2.abs() + a3.abs() * h) * h) * h;
    let f_scale = terms_size(f, h);
    let floor = RECEDING_MARGIN * d_scale;
    // NaN anywhere fails every test below and keeps the pair.
    if floor.is_nan() || floor <= 0.0 || (c0 > 0.0 && c0 < RECEDING_MARGIN * f_scale) {
        return false;
    }
    let d = |t: f64| ((a3 * t + a2) * t + a1) * t + a0;
    let (first, last) = (a0, d(h));
    if first.is_nan() || last.is_nan() || first < floor || last < floor {
        return false;
    }
    // The critical points of f' inside the window: roots of a1 + 2 a2 t + 3 a3 t^2.
    let (q0, q1, q2) = (a1, 2.0 * a2, 3.0 * a3);
    let inside = |t: f64| {
        if t > 0.0 && t < h {
            d(t) >= floor
        } else {
            !t.is_nan()
        }
    };
    if q2 == 0.0 {
        return q1 == 0.0 || inside(-q0 / q1);
    }
    let disc = q1 * q1 - 4.0 * q2 * q0;
    if disc < 0.0 {
        return true;
    }
    let w = -0.5 * (q1 + q1.signum() * disc.sqrt());
    if w == 0.0 {
        return inside(0.0);
    }
    inside(w / q2) && inside(q0 / w)
}

/// Are the balls surely apart over the whole of `[0, horizon]`? Then [`first_contact`] finds no
/// contact, and its search is saved (a ball coming down beside a rack that passes its
/// neighbours, a pair whose closest approach in the window stays wider than `2R`). A lower
/// bound of the contact function `f = c0 + c1 t + c2 t^2 + c3 t^3 + c4 t^4` over the window, in
/// closed form: `c3 t^3 + c4 t^4 = t^2 (c3 t + c4 t^2) >= m t^2` with `m` the least of
/// `c3 t + c4 t^2` on `[0, horizon]` (`c4 = |da|^2 / 4 >= 0`), so `f >= c0 + c1 t + (c2 + m)
/// t^2`, a quadratic whose least over the window is at an end or its vertex. Above
/// [`RECEDING_MARGIN`] of `f`'s terms' sizes, far above the rounding of every evaluation the
/// search makes (all in the window, or ulps past its end), every one is positive: no root.
fn clear(f: &Poly, horizon: f64) -> bool {
    let h = horizon;
    let [c0, c1, c2, c3, c4] = f.c;
    if !(h.is_finite() && h > 0.0 && c0 > 0.0 && c4 >= 0.0) {
        return false;
    }
    let m = if c3 >= 0.0 {
        0.0
    } else if 2.0 * c4 * h > -c3 {
        // The vertex `-c3 / (2 c4)` inside the window.
        -c3 * c3 / (4.0 * c4)
    } else {
        (c3 + c4 * h) * h
    };
    let q2 = c2 + m;
    let mut least = c0.min(c0 + (c1 + q2 * h) * h);
    if q2 > 0.0 && c1 < 0.0 && -c1 < 2.0 * q2 * h {
        least = least.min(c0 - c1 * c1 / (4.0 * q2));
    }
    // NaN anywhere fails the test and keeps the pair.
    least > RECEDING_MARGIN * terms_size(f, h)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// A random pair in space: a ball in the air against one on the cloth (a quarter of
    /// them: no relative fall) or in the air, touching now when `touching` or else up to
    /// 30 cm apart, over a window up to 0.5 s; its relative motions, contact function and
    /// window.
    #[allow(clippy::type_complexity)]
    fn random_pair(
        rng: &mut ChaCha8Rng,
        i: usize,
        touching: bool,
    ) -> ((Vec2, Vec2, Vec2), (f64, f64, f64), Poly, f64) {
        let g = 9.80665;
        let angle = rng.random_range(0.0..std::f64::consts::TAU);
        let gap = if touching {
            0.0
        } else {
            rng.random_range(0.0..0.3)
        };
        let dir = Vec2::new(angle.cos(), angle.sin());
        let dz = rng.random_range(-CONTACT..CONTACT);
        let dp = dir * ((CONTACT * CONTACT - dz * dz).sqrt() + gap);
        let dv = Vec2::new(rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0));
        let da = Vec2::new(rng.random_range(-2.0..2.0), rng.random_range(-2.0..2.0));
        let (dvz, daz) = (
            rng.random_range(-3.0..3.0),
            if i.is_multiple_of(4) { 0.0 } else { g },
        );
        let horizon = rng.random_range(0.0..0.5);
        let (plane, height) = ((dp, dv, da), (dz, dvz, daz));
        (plane, height, contact_poly(plane, height, CONTACT), horizon)
    }

    /// Two pool balls' contact distance, m.
    const CONTACT: f64 = 0.05715;

    /// Two answers of a contact search within `[0, h]` agree: both none, or both at the same
    /// time to within the rounding of the root (16 ulps; 16 ulps of the terms' sizes over the
    /// slope there, for a grazing contact; 8 ulps of the window, as the general refinement
    /// stops at a width relative to its bracket's end, for a root near 0), neither before `f`
    /// is reached (`f(t) <= 0`).
    fn same_contact(f: &Poly, h: f64, t: Option<f64>, s: Option<f64>) -> bool {
        match (t, s) {
            (None, None) => true,
            (Some(t), Some(s)) => {
                let scale: f64 = (0..5).map(|k| f.c[k].abs() * s.powi(k as i32)).sum();
                let slope = f.derivative().eval(s).abs();
                let eps = 16.0 * f64::EPSILON;
                (t - s).abs() <= eps * (s + scale / slope + 0.5 * h) && f.eval(t) <= 0.0
            }
            _ => false,
        }
    }

    /// The culls are exact: over random pairs in space (a ball in the air against one on the
    /// cloth or in the air, touching now or up to 30 cm apart, over flights up to 0.5 s),
    /// every pair [`receding`] or [`clear`] rejects has no contact by the general search
    /// either, so [`space_contact`] answers as the search alone does ([`same_contact`]: to
    /// rounding, as [`falling_contact`] may end its refinement ulps apart); and each rejects a good
    /// share (pairs parting, pairs passing), or it would save nothing.
    #[test]
    fn culls_reject_only_pairs_the_search_finds_apart() {
        let mut rng = ChaCha8Rng::seed_from_u64(51);
        let (mut culled, mut cleared, mut contacts, n) = (0, 0, 0, 200_000);
        for i in 0..n {
            // A third of the pairs touch now (just resolved), the rest are apart.
            let (plane, height, f, horizon) = random_pair(&mut rng, i, i % 3 == 0);
            let search = first_contact(&f, horizon, tolerance(CONTACT));
            let answer = space_contact(plane, height, CONTACT, horizon);
            assert!(
                same_contact(&f, horizon, answer, search),
                "pair {i}: {answer:?} vs {search:?}"
            );
            if receding(&f, horizon) {
                assert_eq!(search, None, "pair {i} culled with a contact");
                culled += 1;
            }
            if clear(&f, horizon) {
                assert_eq!(search, None, "pair {i} cleared with a contact");
                cleared += 1;
            }
            contacts += usize::from(search.is_some());
        }
        assert!(
            culled > n / 5 && cleared > n / 20 && contacts > n / 10,
            "{culled} culled, {cleared} cleared, {contacts} contacts of {n}"
        );
    }

    /// The falling search is exact: over random pairs in space (as in the culls' test, apart
    /// now), whenever [`falling_contact`] answers, the general search finds the same contact
    /// to rounding ([`same_contact`]; its bracket differs, so the refinement may stop ulps
    /// apart); and it answers most contacts, or it would save nothing.
    #[test]
    fn falling_search_finds_the_general_search_contact() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let (mut answered, mut contacts, n) = (0, 0, 100_000);
        for i in 0..n {
            let (_, _, f, horizon) = random_pair(&mut rng, i, false);
            let search = first_contact(&f, horizon, tolerance(CONTACT));
            contacts += usize::from(search.is_some());
            if let Some(t) = falling_contact(&f, horizon) {
                assert!(
                    same_contact(&f, horizon, Some(t), search),
                    "pair {i}: {t} vs {search:?}"
                );
                answered += 1;
            }
        }
        assert!(
            answered > contacts / 2,
            "{answered} answered of {contacts} contacts"
        );
    }
}
