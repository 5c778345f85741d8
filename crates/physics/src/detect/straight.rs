//! The contact quartic in closed form when the relative motion runs along a line: a ball on
//! a straight path (at rest, rolling or sliding along its velocity) against a resting ball or
//! a pocket jaw.
//!
//! With `u` the direction of the relative velocity `dv` and `da = α u` (no part across `u`),
//! the relative position is `dp + u s(τ)` with `s(τ) = |dv| τ + α τ²/2`, and the quartic
//! `f(τ) = |dp + dv τ + da τ²/2|² - C²` is the quadratic `g(s) = s² + 2 (u·dp) s + C0`
//! (`C0 = |dp|² - C²`) of the quadratic `s(τ)`. Its first root is the first root `s1` of `g`,
//! reached while `s` still grows, at `τ1 = 2 s1 / (|dv| + sqrt(|dv|² + 2 α s1))`: two square
//! roots instead of isolating the quartic's roots between its critical points
//! (Leckie & Greenspan 2006, section 3, the event times as polynomial roots; here the
//! polynomial factors, because the paper's motion of section 3.3, and a rolling or
//! centre-struck sliding ball in the spin model, decelerates along its own velocity).
//!
//! What the general search would answer is kept to well under 1e-12 s: a part `π` of `da`
//! across `u` (rounding) changes `f` by at most `E = |π| τ² |dp| + π² τ⁴/4`, and rounding in
//! `f` by `N`; before `τ1`, `g(s(τ)) >= ṡ_min (s2 - s1) (τ1 - τ)`, so any earlier root of the
//! computed `f` lies within `(E + N) / (ṡ_min (s2 - s1))` of `τ1`. The closed form answers only
//! when that is below [`AGREEMENT`] and far from the horizon; the root is then settled on
//! `f` itself as the general search's bracket is (one Newton step on `f`, then the first
//! float where `f` is not positive after one where it is, within 16 ulps), so a contact is
//! never reported before it is reached. A grazing path, a ball stopping at the contact, or a
//! contact at the horizon is left to the general search.

use crate::math::Vec2;
use crate::poly::{Poly, root_bound};

/// Largest distance, seconds, between the closed-form root and any root the general search
/// could find, for the closed form to answer (see the module's bound): half the 1e-12 s
/// that issue 27 allows.
pub const AGREEMENT: f64 = 5e-13;

/// Largest part of the relative acceleration across the relative velocity, relative to its
/// length, that is tried in closed form (rounding in a straight path's acceleration is about
/// 1e-16; a curving ball goes to the general search at once).
const MAX_CROSS: f64 = 1e-9;

/// Least gap, metres, between the bodies for the closed form to answer. Bodies about to
/// touch again (a pair just resolved, a resting contact's hop of 1e-7 m, the balls of a
/// cluster impact) are left to the general search, whose handling of contacts within
/// rounding of now (see [`crate::poly::first_contact`]) decides whether they fall on the same
/// instant: the closed form, though as close, could move such a contact by the few
/// femtoseconds that make it simultaneous with the event just processed, or not.
const MIN_GAP: f64 = 1e-6;

/// The first contact of `f` (the contact quartic of `dp`, `dv`, `da` at the distance
/// `contact`, apart now) within `h`, as [`crate::poly::first_contact`] finds it, when the
/// relative motion runs along a line; `None` when the closed form cannot vouch for the
/// answer (the general search then runs).
#[inline]
pub(super) fn straight_contact(
    f: &Poly,
    (dp, dv, da): (Vec2, Vec2, Vec2),
    contact: f64,
    h: f64,
) -> Option<Option<f64>> {
    let c0 = f.c[0];
    let w2 = dv.length_squared();
    let w = w2.sqrt();
    // |dp|² - contact² is about 2 contact gap.
    if !(c0 > 2.0 * contact * MIN_GAP && w > 0.0 && w.is_finite()) {
        return None;
    }
    let u = dv / w;
    let (alpha, cross) = (da.dot(u), u.perp_dot(da));
    // (Written so that a NaN goes to the general search.)
    let along_a_line = cross.abs() <= MAX_CROSS * da.length();
    if !along_a_line {
        return None;
    }
    // The search window of `first_contact` for a pair apart now.
    let hb = h.min(root_bound(f));
    if hb.is_nan() || hb <= 0.0 {
        return Some(None);
    }
    if !hb.is_finite() {
        return None;
    }
    // Where `s` stops growing (a decelerating pair), and the window's end along the line; a
    // window reaching past the turn (by more than rounding) is left to the general search.
    let end = if alpha < 0.0 {
        let turn = w / -alpha;
        if hb > turn * (1.0 + 1e-6) {
            return None;
        }
        hb.min(turn)
    } else {
        hb
    };
    let s_end = (w + 0.5 * alpha * end) * end;
    let b = u.dot(dp);
    // What `f` may differ from `g(s(τ))` by up to `τ`: the part across the line, rounding.
    let slack = |tau: f64| {
        let tt = tau * tau;
        let across = cross.abs() * tt * dp.length() + 0.25 * cross * cross * tt * tt;
        let c = &f.c;
        let terms = (((c[4].abs() * tau + c[3].abs()) * tau + c[2].abs()) * tau + c[1].abs()) * tau
            + c[0].abs();
        across + 12.0 * f64::EPSILON * terms
    };
    let disc = b * b - c0;
    if b < 0.0 && disc > 0.0 {
        let root = disc.sqrt();
        // The smaller root of g, without cancellation (s1 s2 = c0).
        let s1 = c0 / (root - b);
        if s1 <= s_end {
            let sdot = (w2 + 2.0 * alpha * s1).max(0.0).sqrt();
            let t1 = 2.0 * s1 / (w + sdot);
            let spread = slack(t1) / (w.min(sdot) * 2.0 * root);
            let margin = spread + 64.0 * f64::EPSILON * t1;
            if !(spread <= AGREEMENT && t1 + margin < hb) {
                return None;
            }
            // The first float where `f` is not positive, as the general search's bracket
            // ends (it narrows to the last positive float and the next): a contact is never
            // reported before it is reached. Rounding in `f` may move its sign change from
            // τ1 by more than a few ulps: one Newton step on `f` first, within the bound.
            let f1 = f.eval(t1);
            let next = t1 - f1 / f.derivative().eval(t1);
            let mut t = if (next - t1).abs() <= margin {
                next
            } else {
                t1
            };
            if f.eval(t) <= 0.0 {
                for _ in 0..16 {
                    let before = t.next_down();
                    if f.eval(before) > 0.0 {
                        return Some(Some(t));
                    }
                    t = before;
                }
                return None;
            }
            for _ in 0..16 {
                t = t.next_up();
                if f.eval(t) <= 0.0 {
                    return Some(Some(t));
                }
            }
            return None;
        }
    }
    // No root of g on [0, s_end]: its least value there must clear what f may differ by.
    let sv = (-b).clamp(0.0, s_end);
    let least = (sv + 2.0 * b) * sv + c0;
    let rounding = 16.0 * f64::EPSILON * ((sv + 2.0 * b.abs()) * sv + c0);
    (least > 2.0 * slack(hb) + rounding).then_some(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detect::ball_ball::{contact_quartic, contact_quartic_general, quartic};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    const RADIUS: f64 = 0.028575;

    /// A ball on a straight path and a still body (a resting ball, or a jaw): relative
    /// position, velocity and acceleration at the start of a search, and the horizon (the
    /// mover's stop, or sooner). The mover decelerates along its velocity (rolling, or
    /// sliding with draw), accelerates along it (sliding with overspin), or coasts.
    fn random_straight(rng: &mut ChaCha8Rng) -> (Vec2, Vec2, Vec2, f64) {
        let dp = Vec2::new(rng.random_range(-2.2..2.2), rng.random_range(-1.1..1.1));
        // Aimed near the other body, so that most paths touch it.
        let aim = -dp + Vec2::new(rng.random_range(-0.06..0.06), rng.random_range(-0.06..0.06));
        let dir = aim.normalized().unwrap_or(Vec2::new(1.0, 0.0));
        let speed = 10f64.powf(rng.random_range(-1.0..0.9));
        let dv = dir * speed;
        let (da, stop) = match rng.random_range(0..4) {
            // Rolling (0.01 g) or sliding (0.2 g) to a stop.
            0 | 1 => {
                let a = if rng.random_bool(0.5) { 0.0981 } else { 1.962 };
                (-(dv / speed) * a, speed / a)
            }
            // Sliding with overspin: speeding up along the line until it rolls.
            2 => ((dv / speed) * 0.56, rng.random_range(0.01..1.0)),
            // A rolling ball in the paper's decelerated form, with rounding across the line.
            _ => {
                let a = dv * (-0.0981 / speed);
                (a, speed / 0.0981)
            }
        };
        let h = if rng.random_bool(0.8) {
            stop
        } else {
            stop * rng.random_range(0.0..1.0)
        };
        (dp, dv, da, h)
    }

    /// Over many random straight paths against a still body, the closed form answers most
    /// searches, and every answer it gives is the general search's to [`AGREEMENT`] (well
    /// within 1e-12 s); contacts and misses both occur. Prints the largest difference.
    #[test]
    fn the_closed_form_finds_the_general_searchs_time() {
        let mut rng = ChaCha8Rng::seed_from_u64(27);
        let (mut answered, mut contacts, mut worst) = (0, 0, 0.0f64);
        let (mut found, mut equal) = (0, 0);
        let cases = 200_000;
        for _ in 0..cases {
            let (dp, dv, da, h) = random_straight(&mut rng);
            let contact = if rng.random_bool(0.7) {
                2.0 * RADIUS
            } else {
                RADIUS + 0.01
            };
            let general = contact_quartic_general(dp, dv, da, contact, h);
            let new = contact_quartic(dp, dv, da, contact, h);
            match (general, new) {
                (Some(a), Some(b)) => {
                    worst = worst.max((a - b).abs());
                    found += 1;
                    equal += usize::from(a == b);
                }
                (None, None) => {}
                _ => panic!("{dp:?} {dv:?} {da:?} {h}: general {general:?}, new {new:?}"),
            }
            let (f, _) = quartic(dp, dv, da, contact);
            if let Some(answer) = straight_contact(&f, (dp, dv, da), contact, h) {
                answered += 1;
                contacts += usize::from(answer.is_some());
            }
        }
        println!(
            "closed form: {answered} of {cases} searches ({contacts} contacts); of the \
             {found} contacts, {equal} the same to the bit, the largest difference {worst:e} s"
        );
        assert!(worst <= AGREEMENT, "{worst:e}");
        assert!(answered > cases * 9 / 10, "{answered}");
        assert!(contacts > answered / 4 && contacts < answered, "{contacts}");
    }

    /// A curving pair (acceleration across the velocity), a pair touching now and one within
    /// a micrometre of touching are left to the general search.
    #[test]
    fn curving_and_touching_pairs_go_to_the_general_search() {
        let contact = 2.0 * RADIUS;
        let (dp, dv) = (Vec2::new(0.5, 0.0), Vec2::new(-1.0, 0.0));
        let curving = Vec2::new(0.5, 0.3);
        let (f, _) = quartic(dp, dv, curving, contact);
        assert_eq!(straight_contact(&f, (dp, dv, curving), contact, 1.0), None);
        let touching = Vec2::new(contact, 0.0);
        let (f, _) = quartic(touching, dv, -dv * 0.1, contact);
        assert_eq!(
            straight_contact(&f, (touching, dv, -dv * 0.1), contact, 1.0),
            None
        );
        let near = Vec2::new(contact + 0.9 * MIN_GAP, 0.0);
        let (f, _) = quartic(near, dv, -dv * 0.1, contact);
        assert_eq!(
            straight_contact(&f, (near, dv, -dv * 0.1), contact, 1.0),
            None
        );
        let apart = Vec2::new(contact + 1.1 * MIN_GAP, 0.0);
        let (f, _) = quartic(apart, dv, -dv * 0.1, contact);
        assert!(straight_contact(&f, (apart, dv, -dv * 0.1), contact, 1.0).is_some());
    }

    /// Head on at 1 m/s decelerating at 0.1 m/s² from 0.5 m: the contact after
    /// `s = 0.5 - 2R`, at `τ = (1 - sqrt(1 - 0.2 s)) / 0.1`; a ball stopping short has none.
    #[test]
    fn head_on_contact_matches_the_kinematics() {
        let contact = 2.0 * RADIUS;
        let (dp, dv) = (Vec2::new(0.5, 0.0), Vec2::new(-1.0, 0.0));
        let da = Vec2::new(0.1, 0.0);
        let (f, _) = quartic(dp, dv, da, contact);
        let s = 0.5 - contact;
        let want = (1.0 - (1.0 - 0.2 * s).sqrt()) / 0.1;
        let got = straight_contact(&f, (dp, dv, da), contact, 10.0)
            .flatten()
            .unwrap();
        assert!((got - want).abs() < 1e-14, "{got} {want}");
        // At 0.1 m/s it stops after 1 s and 0.05 m, short of the contact.
        let slow = dv * 0.1;
        let (f, _) = quartic(dp, slow, da, contact);
        assert_eq!(
            straight_contact(&f, (dp, slow, da), contact, 1.0),
            Some(None)
        );
    }
}
