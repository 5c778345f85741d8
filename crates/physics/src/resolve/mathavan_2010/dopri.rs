//! Dormand & Prince's embedded Runge–Kutta pair 5(4) (the "RK5(4)7M" of Dormand & Prince,
//! "A family of embedded Runge–Kutta formulae", J. Comp. Appl. Math. 6, 1980, Table 2),
//! with its error estimate and the 4th-order dense output of Hairer, Nørsett & Wanner,
//! "Solving Ordinary Differential Equations I" (2nd ed., 1993), section II.6, eq. (6.12) and
//! the coefficients of their code `DOPRI5`.

use super::contact::State;

const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
// The 5th-order weights (also the last stage's row: first same as last).
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
// 5th minus 4th-order weights: the local error estimate.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Dense output (DOPRI5's `D1..D7`).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// One step taken: the state at its end, the rate there (the next step's first stage), the
/// local error estimate, and what the continuous extension over the step needs.
pub(super) struct Step {
    pub(super) y: State,
    pub(super) k7: State,
    pub(super) err: State,
    y0: State,
    h: f64,
    k: [State; 5],
}

impl Step {
    /// The state at fraction `theta` of the step (4th order; exact at 0 and 1), from the
    /// stages kept (computed here: most steps never need it).
    #[inline]
    pub(super) fn at(&self, theta: f64) -> State {
        std::array::from_fn(|i| self.at_one(i, theta))
    }

    /// Component `i` of [`Self::at`] (an event on one component needs no other).
    #[inline]
    pub(super) fn at_one(&self, i: usize, theta: f64) -> f64 {
        let (y, y1, h, k7) = (&self.y0, &self.y, self.h, &self.k7);
        let [k1, k3, k4, k5, k6] = &self.k;
        let t1 = 1.0 - theta;
        let r2 = y1[i] - y[i];
        let r3 = h * k1[i] - r2;
        let r4 = r2 - h * k7[i] - r3;
        let r5 = h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
        y[i] + theta * (r2 + t1 * (r3 + theta * (r4 + t1 * r5)))
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
/// and `dz1`: `z` and its rate at `y`. With each stage's coefficients multiplied by `h` once
/// and the newest stage added last, a stage waits one multiply and one add for the last.
#[allow(clippy::too_many_arguments)]
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
    let (a21, a31, a32) = (h * A21, h * A31, h * A32);
    let (a41, a42, a43) = (h * A41, h * A42, h * A43);
    let (a51, a52, a53, a54) = (h * A51, h * A52, h * A53, h * A54);
    let (a61, a62, a63, a64, a65) = (h * A61, h * A62, h * A63, h * A64, h * A65);
    let (b1, b3, b4, b5, b6) = (h * B1, h * B3, h * B4, h * B5, h * B6);
    let dz: [f64; N] = dz1;
    let (dz2, f2) = fast(&std::array::from_fn(|i| z0[i] + a21 * dz[i]));
    let (dz3, f3) = fast(&std::array::from_fn(|i| z0[i] + a31 * dz[i] + a32 * dz2[i]));
    let (dz4, f4) = fast(&std::array::from_fn(|i| {
        z0[i] + a41 * dz[i] + a42 * dz2[i] + a43 * dz3[i]
    }));
    let (dz5, f5) = fast(&std::array::from_fn(|i| {
        z0[i] + a51 * dz[i] + a52 * dz2[i] + a53 * dz3[i] + a54 * dz4[i]
    }));
    let (dz6, f6) = fast(&std::array::from_fn(|i| {
        z0[i] + a61 * dz[i] + a62 * dz2[i] + a63 * dz3[i] + a64 * dz4[i] + a65 * dz5[i]
    }));
    let (_, f7) = fast(&std::array::from_fn(|i| {
        z0[i] + b1 * dz[i] + b3 * dz3[i] + b4 * dz4[i] + b5 * dz5[i] + b6 * dz6[i]
    }));
    // The full state's stages (off the chain above when N > 0).
    let k2 = slow(&f2, &std::array::from_fn(|i| y[i] + a21 * k1[i]));
    let k3 = slow(
        &f3,
        &std::array::from_fn(|i| y[i] + a31 * k1[i] + a32 * k2[i]),
    );
    let k4 = slow(
        &f4,
        &std::array::from_fn(|i| y[i] + a41 * k1[i] + a42 * k2[i] + a43 * k3[i]),
    );
    let k5 = slow(
        &f5,
        &std::array::from_fn(|i| y[i] + a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]),
    );
    let k6 = slow(
        &f6,
        &std::array::from_fn(|i| {
            y[i] + a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]
        }),
    );
    let y1: State = std::array::from_fn(|i| {
        y[i] + b1 * k1[i] + b3 * k3[i] + b4 * k4[i] + b5 * k5[i] + b6 * k6[i]
    });
    let k7 = slow(&f7, &y1);
    let err = std::array::from_fn(|i| {
        h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])
    });
    Step {
        y: y1,
        k7,
        err,
        y0: *y,
        h,
        k: [*k1, k3, k4, k5, k6],
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
    fn fifth_order_step_fourth_order_estimate_and_dense_output() {
        // Halving h divides the step's error by about 2^6 (local order 5 + 1), the estimate
        // by 2^5 (its 4th-order member), and the dense output's error at mid-step by 2^5.
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
        assert!(
            (a.0 / b.0).log2() > 5.5,
            "step order {}",
            (a.0 / b.0).log2()
        );
        assert!(
            (a.1 / b.1).log2() > 4.5,
            "estimate order {}",
            (a.1 / b.1).log2()
        );
        assert!(
            (a.2 / b.2).log2() > 4.5,
            "dense order {}",
            (a.2 / b.2).log2()
        );
        assert_eq!(a.3, 0.0);
    }

    #[test]
    fn a_rate_linear_in_time_is_integrated_exactly() {
        // y0' = 1, y1' = y0: y1 = t^2 / 2, which a 5th-order step and its dense output hit.
        let rate = |t: &State| [1.0, t[0], 0.0, 0.0, 0.0, 0.0];
        let y0 = [0.0; 6];
        let s = step(&y0, &rate(&y0), 3.0, rate);
        assert!((s.y[1] - 4.5).abs() < 1e-14 && s.err[1].abs() < 1e-14);
        assert!((s.at(1.0 / 3.0)[1] - 0.5).abs() < 1e-14);
    }
}
