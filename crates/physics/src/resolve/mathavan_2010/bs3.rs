//! Bogacki & Shampine's embedded Runge–Kutta pair 3(2) ("A 3(2) pair of Runge–Kutta
//! formulas", Appl. Math. Lett. 2(4), 1989, pp. 321–325; MATLAB's `ode23`): three rate
//! evaluations a step (the last stage is the next step's first), the 2nd-order member's
//! difference as the error estimate, and the cubic Hermite interpolant of the step's ends as
//! dense output (3rd order, as Hairer, Nørsett & Wanner, section II.6, construct it).
//!
//! It replaced Dormand & Prince's 5(4) pair (six evaluations a step): an impact's steps are
//! mostly bounded by its events and its slips' relaxation, not by the error, so the cheaper
//! step wins. Over 3,000 random impacts against a 1e-9 reference, at 5e-5 a step: the largest
//! difference 2.0e-4 (99 % within 8.0e-5) and 51 evaluations an impact, where the 5(4) pair
//! at 1e-4 gave 3.0e-4 (1.3e-4) and 78 (docs/realism.md, Cost); at 7e-5 with a step size
//! control aiming lower (safety 0.8), and steps going on past compression's end, 1.4e-4
//! (7.3e-5) in 48.7.

use super::contact::State;

/// Rate evaluations a step (first same as last).
pub(super) const EVALS: usize = 3;
/// How far a step may reach along the negative real axis (the step times a relaxation rate):
/// a 3-stage 3rd-order method is stable to 2.51; at 2 a relaxing mode shrinks by 1/3 a step
/// (at 2.5 by 0.98 only, which let 8 of 3,000 random impacts end above 2e-4 of the
/// reference at 1e-4 a step; 3 at 2).
pub(super) const STABLE: f64 = 2.0;
/// Where in a step (as a fraction of it) [`step`] evaluates the rate, in the order it does.
pub(super) const STAGES: [f64; 3] = [0.5, 0.75, 1.0];

const B1: f64 = 2.0 / 9.0;
const B2: f64 = 1.0 / 3.0;
const B3: f64 = 4.0 / 9.0;
// 3rd minus 2nd-order weights: the local error estimate.
const E1: f64 = 2.0 / 9.0 - 7.0 / 24.0;
const E2: f64 = 1.0 / 3.0 - 1.0 / 4.0;
const E3: f64 = 4.0 / 9.0 - 1.0 / 3.0;
const E4: f64 = -1.0 / 8.0;

/// One step taken: the state at its end, the rate there (the next step's first stage), the
/// local error estimate, and what the continuous extension over the step needs.
pub(super) struct Step {
    pub(super) y: State,
    pub(super) k4: State,
    pub(super) err: State,
    y0: State,
    h: f64,
    k1: State,
}

impl Step {
    /// The state at fraction `theta` of the step (3rd order; exact at 0 and 1).
    #[inline]
    pub(super) fn at(&self, theta: f64) -> State {
        std::array::from_fn(|i| self.at_one(i, theta))
    }

    /// Component `i` of [`Self::at`] (an event on one component needs no other).
    #[inline]
    pub(super) fn at_one(&self, i: usize, theta: f64) -> f64 {
        let (y0, y1, h) = (self.y0[i], self.y[i], self.h);
        let (f0, f1) = (h * self.k1[i], h * self.k4[i]);
        let t = theta;
        let t2 = t * t;
        let t3 = t2 * t;
        let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        let h10 = t3 - 2.0 * t2 + t;
        let h01 = -2.0 * t3 + 3.0 * t2;
        let h11 = t3 - t2;
        h00 * y0 + h10 * f0 + h01 * y1 + h11 * f1
    }
}

/// One step of `h` from `y`, whose rate `k1` the caller has.
pub(super) fn step(y: &State, k1: &State, h: f64, rate: impl Fn(&State) -> State) -> Step {
    step_split(
        y,
        k1,
        h,
        [0.0; 0],
        [0.0; 0],
        |_: &[f64; 0]| ([0.0; 0], ()),
        |_, t| rate(t),
    )
}

/// [`step`] for a rate that depends on the state only through `N` linear combinations `z` of
/// it (the slips) and on the state itself only where nothing feeds back (`slow`): the stages
/// follow `z` along the chain of rate evaluations (`fast` gives `dz/dP` and what `slow` needs
/// from `z`), the full state off it. Runge–Kutta methods commute with linear maps, so this is
/// the same step to rounding, with a shorter chain of dependent operations per stage. `z0`
/// and `dz1`: `z` and its rate at `y`.
#[inline(always)]
pub(super) fn step_split<const N: usize, F>(
    y: &State,
    k1: &State,
    h: f64,
    z0: [f64; N],
    dz1: [f64; N],
    fast: impl Fn(&[f64; N]) -> ([f64; N], F),
    slow: impl Fn(&F, &State) -> State,
) -> Step {
    let (a21, a32) = (0.5 * h, 0.75 * h);
    let (b1, b2, b3) = (h * B1, h * B2, h * B3);
    let dz = dz1;
    let (dz2, f2) = fast(&std::array::from_fn(|i| z0[i] + a21 * dz[i]));
    let (dz3, f3) = fast(&std::array::from_fn(|i| z0[i] + a32 * dz2[i]));
    let (_, f4) = fast(&std::array::from_fn(|i| {
        z0[i] + b1 * dz[i] + b2 * dz2[i] + b3 * dz3[i]
    }));
    let k2 = slow(&f2, &std::array::from_fn(|i| y[i] + a21 * k1[i]));
    let k3 = slow(&f3, &std::array::from_fn(|i| y[i] + a32 * k2[i]));
    let y1: State = std::array::from_fn(|i| y[i] + b1 * k1[i] + b2 * k2[i] + b3 * k3[i]);
    let k4 = slow(&f4, &y1);
    let err = std::array::from_fn(|i| h * (E1 * k1[i] + E2 * k2[i] + E3 * k3[i] + E4 * k4[i]));
    Step {
        y: y1,
        k4,
        err,
        y0: *y,
        h,
        k1: *k1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y' = (y1, -y0, 0, 0, 0, 0): a rotation, exact solution (sin, cos).
    fn rotation(t: &State) -> State {
        [t[1], -t[0], 0.0, 0.0, 0.0, 0.0]
    }

    #[test]
    fn third_order_step_second_order_estimate_and_dense_output() {
        // Halving h divides the step's error by about 2^4 (local order 3 + 1), the estimate
        // by 2^3 (its 2nd-order member), and the dense output's error at mid-step by 2^4.
        let y0: State = [0.0, 1.0, 0.0, 0.0, 0.0, 0.0];
        let errs = |h: f64| {
            let s = step(&y0, &rotation(&y0), h, rotation);
            let mid = s.at(0.5);
            (
                (s.y[0] - h.sin()).abs(),
                s.err[0].abs().max(s.err[1].abs()),
                (mid[0] - (0.5 * h).sin()).abs(),
                s.at(1.0)[0] - s.y[0],
            )
        };
        let (a, b) = (errs(0.4), errs(0.2));
        let order = |x: f64, y: f64| (x / y).log2();
        assert!(order(a.0, b.0) > 3.5, "step order {}", order(a.0, b.0));
        assert!(order(a.1, b.1) > 2.5, "estimate order {}", order(a.1, b.1));
        assert!(order(a.2, b.2) > 3.5, "dense order {}", order(a.2, b.2));
        assert_eq!(a.3, 0.0);
    }

    #[test]
    fn a_rate_linear_in_time_is_integrated_exactly() {
        // y0' = 1, y1' = y0: y1 = t^2 / 2, which a 3rd-order step and its dense output hit,
        // with no error estimated.
        let rate = |t: &State| [1.0, t[0], 0.0, 0.0, 0.0, 0.0];
        let y0 = [0.0; 6];
        let s = step(&y0, &rate(&y0), 3.0, rate);
        assert!((s.y[1] - 4.5).abs() < 1e-14 && s.err[1].abs() < 1e-14);
        assert!((s.at(1.0 / 3.0)[1] - 0.5).abs() < 1e-14);
    }

    #[test]
    fn the_split_step_is_the_plain_step() {
        // The rotation's rate depends on the state through z = (y0, y1) itself.
        let y0: State = [0.3, 0.9, 0.1, 0.0, 0.0, 0.0];
        let plain = step(&y0, &rotation(&y0), 0.3, rotation);
        let split = step_split(
            &y0,
            &rotation(&y0),
            0.3,
            [y0[0], y0[1]],
            [y0[1], -y0[0]],
            |z: &[f64; 2]| ([z[1], -z[0]], *z),
            |z, _| [z[1], -z[0], 0.0, 0.0, 0.0, 0.0],
        );
        for i in 0..6 {
            assert!((plain.y[i] - split.y[i]).abs() < 1e-15, "{i}");
            assert!((plain.err[i] - split.err[i]).abs() < 1e-15, "{i}");
        }
    }
}
