//! Real roots of polynomials of degree at most four on an interval.
//!
//! Contact times are first roots of low-degree polynomials (quadratic for cushions, quartic
//! for ball pairs under constant deceleration). Closed-form cubic and quartic formulas lose
//! precision near double roots and degenerate leading coefficients, so roots are isolated
//! instead: the critical points (roots of the derivative, found recursively) split the
//! interval into pieces where the polynomial is monotone, and each sign change is refined by
//! a safeguarded Newton iteration that never leaves its bracket. A small leading coefficient
//! then simply makes a flat piece, never a division by almost zero.

/// A polynomial `c[0] + c[1] t + c[2] t^2 + c[3] t^3 + c[4] t^4`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Poly {
    /// Coefficients, lowest degree first.
    pub c: [f64; 5],
}

impl Poly {
    /// A polynomial from its coefficients, lowest degree first.
    pub const fn new(c: [f64; 5]) -> Self {
        Self { c }
    }

    /// Index of the highest non-zero coefficient (0 for constants, including zero).
    fn degree(&self) -> usize {
        (1..5).rev().find(|&k| self.c[k] != 0.0).unwrap_or(0)
    }

    /// Value at `t` (Horner).
    #[inline]
    pub fn eval(&self, t: f64) -> f64 {
        let c = &self.c;
        (((c[4] * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0]
    }

    /// The derivative.
    pub fn derivative(&self) -> Self {
        let c = &self.c;
        Self::new([c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0])
    }

    /// This polynomial plus a constant.
    pub fn shifted(mut self, k: f64) -> Self {
        self.c[0] += k;
        self
    }

    /// The negated polynomial.
    pub fn negated(self) -> Self {
        Self::new(self.c.map(|x| -x))
    }

    /// Visits the roots of this polynomial in the open interval `(a, b)` in ascending order
    /// (sign changes, and exact zeros at critical points) until `visit` returns `true`; returns
    /// whether it stopped early. Lazy, so a caller that needs only the first root pays only for
    /// the critical points before it. Generic in `visit` so that a contact search's closures
    /// are inlined (the same arithmetic in the same order: no result changes); the derivative
    /// of a quartic is searched through [`Poly::for_each_root_dyn`], which ends the
    /// recursion of closure types.
    fn for_each_root<F: FnMut(f64) -> bool + ?Sized>(&self, a: f64, b: f64, visit: &mut F) -> bool {
        if self.degree() <= 2 {
            return self.for_each_root_low(a, b, visit);
        }
        let mut lo = a;
        let mut flo = self.eval(a);
        let mut piece = |hi: f64, fhi: f64, lo: &mut f64, flo: &mut f64| -> bool {
            let stop = if (*flo > 0.0 && fhi < 0.0) || (*flo < 0.0 && fhi > 0.0) {
                let r = if *flo > 0.0 {
                    refine(self, *lo, hi, *flo, fhi)
                } else {
                    refine(&self.negated(), *lo, hi, -*flo, -fhi)
                };
                r > a && r < b && visit(r)
            } else {
                fhi == 0.0 && hi < b && visit(hi)
            };
            *lo = hi;
            *flo = fhi;
            stop
        };
        let derivative = self.derivative();
        let mut critical = |c: f64| piece(c, self.eval(c), &mut lo, &mut flo);
        let stopped = if derivative.degree() <= 2 {
            derivative.for_each_root_low(a, b, &mut critical)
        } else {
            derivative.for_each_root_dyn(a, b, &mut critical)
        };
        if stopped {
            return true;
        }
        piece(b, self.eval(b), &mut lo, &mut flo)
    }

    /// [`Poly::for_each_root`] through a trait object (the quartic's derivative, a cubic).
    fn for_each_root_dyn(&self, a: f64, b: f64, visit: &mut dyn FnMut(f64) -> bool) -> bool {
        self.for_each_root(a, b, visit)
    }

    /// [`Poly::for_each_root`] of degree at most two, in closed form.
    fn for_each_root_low<F: FnMut(f64) -> bool + ?Sized>(
        &self,
        a: f64,
        b: f64,
        visit: &mut F,
    ) -> bool {
        match self.degree() {
            0 => false,
            1 => {
                let t = -self.c[0] / self.c[1];
                t > a && t < b && visit(t)
            }
            _ => {
                let (q0, q1, q2) = (self.c[0], self.c[1], self.c[2]);
                let disc = q1 * q1 - 4.0 * q2 * q0;
                if disc < 0.0 {
                    return false;
                }
                // Numerically stable pair (no cancellation between -b and sqrt(disc)).
                let q = -0.5 * (q1 + q1.signum() * disc.sqrt());
                let (mut r1, mut r2) = (q / q2, if q != 0.0 { q0 / q } else { q / q2 });
                if r1 > r2 {
                    std::mem::swap(&mut r1, &mut r2);
                }
                (r1 > a && r1 < b && visit(r1)) || (r2 != r1 && r2 > a && r2 < b && visit(r2))
            }
        }
    }
}

/// Smallest `t` in `[a, b]` with `p(t) <= 0`, or `None` if `p > 0` on the whole interval.
///
/// The answer is the upper end of a bracket no wider than a few ulps, so `p` at the returned
/// time is never positive: a contact is never reported before it is reached.
pub fn first_entry(p: &Poly, a: f64, b: f64) -> Option<f64> {
    let fa = p.eval(a);
    if fa <= 0.0 {
        return Some(a);
    }
    if b.is_nan() || b <= a {
        return None;
    }
    if p.degree() <= 2 {
        return first_entry_quadratic(p, a, b);
    }
    let (mut lo, mut flo) = (a, fa);
    let mut found = None;
    // Between consecutive critical points p is monotone: the first piece whose end is not
    // positive holds the first root.
    p.derivative().for_each_root(a, b, &mut |c| {
        let fc = p.eval(c);
        if fc <= 0.0 {
            found = Some(refine(p, lo, c, flo, fc));
            return true;
        }
        (lo, flo) = (c, fc);
        false
    });
    if found.is_some() {
        return found;
    }
    let fb = p.eval(b);
    (fb <= 0.0).then(|| refine(p, lo, b, flo, fb))
}

/// [`first_entry`] for degree at most two, in closed form (`p(a) > 0`, `a < b`): the
/// numerically stable root, then nudged up by ulps until `p` is not positive there, so the
/// contact is never reported early.
fn first_entry_quadratic(p: &Poly, a: f64, b: f64) -> Option<f64> {
    let (c0, c1, c2) = (p.c[0], p.c[1], p.c[2]);
    if let Some(answer) = closed_form_entry(c0, c1, c2, a, b) {
        return answer;
    }
    // Rounding left the closed form further off than expected: bracket it properly. Opening
    // upwards, only up to the vertex: past the second root `p(b)` is positive again, and a
    // bracket to `b` would lose a contact the path really makes (soak seed 110421: a ball
    // through a pocket jaw).
    let hi = if c2 > 0.0 {
        (-c1 / (2.0 * c2)).clamp(a, b)
    } else {
        b
    };
    let fhi = p.eval(hi);
    (fhi <= 0.0).then(|| refine(p, a, hi, p.eval(a), fhi))
}

/// The closed-form part of [`first_entry_quadratic`] for `c0 + c1 t + c2 t^2` (`p(a) > 0`):
/// the numerically stable root, nudged up by at most 16 ulps until `p` is not positive there.
/// `None` when that fails (a root further off, or a non-finite time): bracket it instead. At a
/// finite `t`, `(c2 t + c1) t + c0` is exactly the quartic Horner sum with zero `c3`, `c4`.
fn closed_form_entry(c0: f64, c1: f64, c2: f64, a: f64, b: f64) -> Option<Option<f64>> {
    let root = if c2 == 0.0 {
        if c1 >= 0.0 || c1.is_nan() {
            return Some(None);
        }
        -c0 / c1
    } else {
        let disc = c1 * c1 - 4.0 * c2 * c0;
        if disc < 0.0 {
            return Some(None);
        }
        let q = -0.5 * (c1 + c1.signum() * disc.sqrt());
        let (r1, r2) = (q / c2, c0 / q);
        let (lo, hi) = (r1.min(r2), r1.max(r2));
        // Opening upwards p <= 0 between the roots; downwards, outside them.
        let r = if c2 > 0.0 { lo } else { hi };
        if r.is_nan() || r < a {
            return Some(None);
        }
        r
    };
    if root.is_nan() || root > b {
        return Some(None);
    }
    let mut t = root.max(a);
    for _ in 0..16 {
        if !t.is_finite() {
            return None;
        }
        if (c2 * t + c1) * t + c0 <= 0.0 {
            return Some(Some(t));
        }
        t = t.next_up();
    }
    None
}

/// [`first_entry`] of `p` on `[0, b]` when `p` is surely decreasing from its start, through a
/// bracket found by Newton's method instead of the critical points: `None` when it cannot
/// certify one (then the general search runs). Newton from 0 (where `p > 0`), then a probe
/// twice its last step further; the bracket `[lo, x]` (`p(lo) > 0 >= p(x)` as evaluated) is
/// refined as [`first_entry`] refines its piece, once `falls(x)` shows `p' < 0` on all of
/// `[0, x]`: `p` then has one root there and none before, so the answer is the first root, to
/// the same few ulps (the bracket differs, so the last ulps may).
pub(crate) fn first_entry_decreasing(p: &Poly, b: f64, falls: impl Fn(f64) -> bool) -> Option<f64> {
    let dp = p.derivative();
    let (mut lo, mut flo) = (0.0, p.eval(0.0));
    if flo.is_nan() || flo <= 0.0 {
        return None;
    }
    for step in 0..3 {
        let d = dp.eval(lo);
        if d.is_nan() || d >= 0.0 {
            return None;
        }
        let delta = -flo / d;
        // Newton's step, and the probe past it on the last round.
        let x = lo + if step == 2 { 2.0 * delta } else { delta };
        if !(x > lo && x <= b) {
            return None;
        }
        let fx = p.eval(x);
        if fx <= 0.0 {
            return falls(x).then(|| refine(p, lo, x, flo, fx));
        }
        (lo, flo) = (x, fx);
    }
    None
}

/// Refines a bracket with `p(lo) = flo > 0 >= p(hi) = fhi`, `p` monotone on it, to a few ulps;
/// returns the upper end (where `p <= 0`). Safeguarded Newton started from the secant point.
fn refine(p: &Poly, mut lo: f64, mut hi: f64, flo: f64, fhi: f64) -> f64 {
    let dp = p.derivative();
    let tol = |lo: f64, hi: f64| (4.0 * f64::EPSILON * hi.abs().max(lo.abs())).max(1e-300);
    let mut x = lo + (hi - lo) * (flo / (flo - fhi));
    if !(x > lo && x < hi) {
        x = 0.5 * (lo + hi);
    }
    for _ in 0..200 {
        let fx = p.eval(x);
        if fx > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let width_tol = tol(lo, hi);
        if hi - lo <= width_tol {
            break;
        }
        let d = dp.eval(x);
        let mut next = x - fx / d;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        } else if (next - x).abs() < 0.5 * width_tol {
            // Newton has converged: close the bracket around its answer.
            let (a, b) = ((next - width_tol).max(lo), (next + width_tol).min(hi));
            if p.eval(a) > 0.0 {
                lo = a;
            }
            if p.eval(b) <= 0.0 {
                hi = b;
            }
            if hi - lo <= 2.0 * width_tol {
                break;
            }
            next = 0.5 * (lo + hi);
        }
        if next <= lo || next >= hi {
            break;
        }
        x = next;
    }
    hi
}

/// Which way a contact function must move for a contact to count.
///
/// A contact function is positive while two things are apart and non-positive while they touch
/// (gap to a cushion, or squared distance minus squared contact distance).
#[derive(Clone, Copy, Debug)]
pub struct ContactTolerance {
    /// Rate of decrease of the contact function below which a touching pair counts as resting,
    /// not approaching; keeps a pair that was just resolved from colliding again at once.
    pub slack: f64,
    /// Value of the contact function above which a touching pair counts as separated.
    pub separation: f64,
    /// How far below zero the contact function of a resting pair may sink before the contact
    /// counts (a resting contact); it is counted again only after the pair has risen back
    /// above half of it, or separated.
    pub depth: f64,
}

/// First time in `[0, h]` at which the contact function `f` starts a contact (`h` may be
/// infinite).
///
/// Apart now (`f(0) > 0`): the first root. Touching now and approaching faster than the slack:
/// `0`. Touching and resting (approaching slower than the slack, or pressed together by their
/// accelerations): the first moment, while approaching at all (faster than a thousandth of the
/// slack), that `f` has sunk to `-depth`: a resting contact, which the caller resolves so that
/// the pair hops apart by about `depth` (see [`crate::resolve::resting_contact`]); a pressed
/// pair then touches a finite number of times per second instead of in a Zeno cascade, and a
/// pair drifting together slower than the slack cannot sink deeper than `depth`. A pair that
/// separates first gets the first root after it. Separating pairs get no false root.
pub fn first_contact(f: &Poly, h: f64, tol: ContactTolerance) -> Option<f64> {
    // Each search runs to the horizon or to the root bound of the polynomial it searches, not
    // of `f`: a pair drifting together at 9e-11 m/s sinks to the resting depth after f's own
    // roots are behind it (soak seed 334696: a ball 1.04e-9 m into a rail after 11 s).
    let entry = |p: &Poly, a: f64| first_entry(p, a, h.min(root_bound(p)));
    if let Some(q) = first_contact_quadratic(f)
        && let Some(answer) = first_entry_quadratic_fast(q, h)
    {
        return answer;
    }
    if f.c[0] > 0.0 {
        return entry(f, 0.0);
    }
    let df = f.derivative();
    if df.c[0] < -tol.slack {
        return Some(0.0);
    }
    let separate = entry(&f.negated().shifted(tol.separation), 0.0);
    let approaching = entry(&df.shifted(1e-3 * tol.slack), 0.0);
    // A sinking contact starts no earlier than the approach (`tc >= ta`), so when the pair
    // separates first (`ta >= ts`) it cannot come before the separation and the answer is the
    // first root after it: the sinking search is skipped, the answer the same (a pair just
    // resolved in space that parts, then falls back together).
    let sink = approaching
        .filter(|&ta| separate.is_none_or(|ts| ta < ts))
        .and_then(|ta| entry(&f.shifted(tol.depth), ta));
    match (sink, separate) {
        (Some(tc), Some(ts)) if tc < ts => Some(tc),
        (Some(tc), None) => Some(tc),
        (_, Some(ts)) => entry(f, ts),
        (None, None) => None,
    }
}

/// [`first_contact`] of the line `c0 + c1 t` with `c0 > 0 > c1` (a ball heading for a line on
/// a straight path, as every cushion contact of the frictionless model), step for step as the
/// general search does it (the entry bound of [`root_bound`], the closed-form root of
/// [`first_entry`] nudged up by ulps) but without building, scanning and evaluating a quartic:
/// at a finite `t` the quartic's Horner sum with its zero terms is exactly `c1 t + c0`.
/// `None` when it cannot answer the same way (a non-finite time, a root more than 16 ulps
/// off): the caller then runs the general search.
pub(crate) fn first_contact_line(c0: f64, c1: f64, h: f64) -> Option<Option<f64>> {
    if !(c0 > 0.0 && c1 < 0.0) {
        return None;
    }
    // `first_entry(f, 0, h.min(root_bound(f)))`, `f(0) = c0 > 0`.
    let b = h.min(1.0 + 0.0f64.max(c0.abs() / c1.abs()));
    if b.is_nan() || b <= 0.0 {
        return Some(None);
    }
    closed_form_entry(c0, c1, 0.0, 0.0, b)
}

/// [`first_contact`] of `f` apart now (`c0 > 0`) with `c3 = c4 = 0` and `c2 > 0` (two balls
/// without relative acceleration: the quartic is a quadratic), step for step as the general
/// search does it ([`root_bound`], then the closed form of [`first_entry`] nudged up by ulps):
/// at a finite `t` the Horner sum's zero terms vanish exactly, leaving `(c2 t + c1) t + c0`.
/// `None` when it cannot answer the same way (a non-finite time, a root more than 16 ulps
/// off): the caller then runs the general search.
fn first_contact_quadratic(f: &Poly) -> Option<(f64, f64, f64)> {
    let [c0, c1, c2, c3, c4] = f.c;
    (c0 > 0.0 && c2 > 0.0 && c3 == 0.0 && c4 == 0.0).then_some((c0, c1, c2))
}

/// The answer of [`first_contact`] for the quadratic of [`first_contact_quadratic`], or `None`
/// to run the general search.
fn first_entry_quadratic_fast((c0, c1, c2): (f64, f64, f64), h: f64) -> Option<Option<f64>> {
    // `first_entry(f, 0, h.min(root_bound(f)))`, `f(0) = c0 > 0`, degree 2.
    let b = h.min(1.0 + 0.0f64.max(c0.abs() / c2).max(c1.abs() / c2));
    if b.is_nan() || b <= 0.0 {
        return Some(None);
    }
    closed_form_entry(c0, c1, c2, 0.0, b)
}

/// An upper bound on the magnitude of every real root (Cauchy), for an unbounded horizon.
pub fn root_bound(p: &Poly) -> f64 {
    let n = p.degree();
    if n == 0 {
        return 0.0;
    }
    let lead = p.c[n].abs();
    1.0 + p.c[..n].iter().map(|c| c.abs() / lead).fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn from_roots(r: &[f64]) -> Poly {
        let mut c = [0.0; 5];
        c[0] = 1.0;
        for &root in r {
            let mut n = [0.0; 5];
            for k in 0..4 {
                n[k + 1] += c[k];
                n[k] -= root * c[k];
            }
            c = n;
        }
        Poly::new(c)
    }

    #[test]
    fn quartic_with_four_simple_roots_finds_the_smallest_in_range() {
        let p = from_roots(&[0.5, 1.25, 2.0, 3.0]);
        assert_eq!(
            first_entry(&p, 0.0, 10.0).map(|t| (t - 0.5).abs() < 1e-15),
            Some(true)
        );
        let mut r = Vec::new();
        p.for_each_root(0.0, 10.0, &mut |t| {
            r.push(t);
            false
        });
        assert_eq!(r.len(), 4);
        for (got, want) in r.iter().zip([0.5, 1.25, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-14, "{got} vs {want}");
        }
    }

    #[test]
    fn quadratic_entry_off_by_more_than_sixteen_ulps_is_still_found_before_the_exit() {
        // Soak seed 110421: a ball at 11.6 m/s crossing a pocket jaw's circle, in and out
        // within 3.7 ms. The closed-form entry time was 17+ ulps early, and the fallback
        // bracket ran to the horizon, past the exit, where the contact function is positive
        // again: no contact, and the ball went through the jaw.
        let f = Poly::new([
            3.9153355766839453,
            -46.066420798322504,
            135.4850913893127,
            0.0,
            0.0,
        ]);
        for h in [0.17, 0.2, 1.0, root_bound(&f)] {
            let t = first_entry(&f, 0.0, h).expect("the path enters the circle");
            assert!(f.eval(t) <= 0.0, "{h}: {t}");
            assert!((t - 0.16820991061557272).abs() < 1e-14, "{h}: {t}");
        }
    }

    #[test]
    fn first_entry_skips_a_root_before_the_interval() {
        let p = from_roots(&[0.5, 1.25, 2.0, 3.0]);
        let t = first_entry(&p.negated(), 0.6, 10.0).unwrap();
        assert!((t - 1.25).abs() < 1e-14);
    }

    #[test]
    fn double_root_tangency_is_found_when_reached_and_missed_when_not() {
        // (t - 1)^2 touches zero at t = 1 only.
        // Near a double root p is below rounding over about sqrt(eps) around it, so the time
        // is good to ~1e-8 there (harmless: the approach speed vanishes at a graze).
        let p = from_roots(&[1.0, 1.0]);
        let t = first_entry(&p, 0.0, 2.0).unwrap();
        assert!((t - 1.0).abs() < 2e-8 && p.eval(t) <= 0.0, "{t}");
        // Lifted by a hair it never reaches zero.
        assert_eq!(first_entry(&p.shifted(1e-12), 0.0, 2.0), None);
    }

    #[test]
    fn vanishing_leading_coefficient_degrades_to_lower_degree() {
        // 1e-30 t^4 - t + 0.5: in [0, 1] it is the line with root 0.5.
        let p = Poly::new([0.5, -1.0, 0.0, 0.0, 1e-30]);
        let t = first_entry(&p, 0.0, 1.0).unwrap();
        assert!((t - 0.5).abs() < 1e-15);
    }

    #[test]
    fn returned_time_never_precedes_the_contact() {
        let p = from_roots(&[0.1 + 1e-9, 7.0]);
        let t = first_entry(&p, 0.0, 1.0).unwrap();
        assert!(p.eval(t) <= 0.0);
        assert!(t - (0.1 + 1e-9) < 1e-15);
    }

    #[test]
    fn separating_touching_pair_has_no_false_root() {
        // f(t) = t (apart and moving apart from exact contact).
        let tol = ContactTolerance {
            slack: 1e-12,
            separation: 1e-15,
            depth: 1e-10,
        };
        assert_eq!(
            first_contact(&Poly::new([0.0, 1.0, 0.0, 0.0, 0.0]), 5.0, tol),
            None
        );
        // Slightly overlapping by rounding, separating: still none.
        assert_eq!(
            first_contact(&Poly::new([-1e-19, 1.0, 0.0, 0.0, 0.0]), 5.0, tol),
            None
        );
    }

    #[test]
    fn touching_pair_that_approaches_collides_at_zero() {
        let tol = ContactTolerance {
            slack: 1e-12,
            separation: 1e-15,
            depth: 1e-10,
        };
        assert_eq!(
            first_contact(&Poly::new([0.0, -1.0, 0.0, 0.0, 0.0]), 5.0, tol),
            Some(0.0)
        );
    }

    #[test]
    fn separating_pair_that_comes_back_collides_at_its_return() {
        // f = t (2 - t): apart on (0, 2), back in contact at 2.
        let tol = ContactTolerance {
            slack: 1e-12,
            separation: 1e-15,
            depth: 1e-10,
        };
        let t = first_contact(&Poly::new([0.0, 2.0, -1.0, 0.0, 0.0]), 5.0, tol).unwrap();
        assert!((t - 2.0).abs() < 1e-12, "{t}");
    }

    #[test]
    fn root_bound_contains_all_roots() {
        let p = from_roots(&[-40.0, 0.5, 3.0, 17.0]);
        assert!(root_bound(&p) >= 40.0);
    }
}
