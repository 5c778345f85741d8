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
    pub(super) fn at(&self, theta: f64) -> State {
        let (y, y1, h, k7) = (&self.y0, &self.y, self.h, &self.k7);
        let [k1, k3, k4, k5, k6] = &self.k;
        let t1 = 1.0 - theta;
        std::array::from_fn(|i| {
            let r2 = y1[i] - y[i];
            let r3 = h * k1[i] - r2;
            let r4 = r2 - h * k7[i] - r3;
            let r5 =
                h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
            y[i] + theta * (r2 + t1 * (r3 + theta * (r4 + t1 * r5)))
        })
    }
}

/// One step of `h` from `y`, whose rate `k1` the caller has.
pub(super) fn step(y: &State, k1: &State, h: f64, rate: impl Fn(&State) -> State) -> Step {
    let k2 = rate(&std::array::from_fn(|i| y[i] + h * A21 * k1[i]));
    let k3 = rate(&std::array::from_fn(|i| {
        y[i] + h * (A31 * k1[i] + A32 * k2[i])
    }));
    let k4 = rate(&std::array::from_fn(|i| {
        y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i])
    }));
    let k5 = rate(&std::array::from_fn(|i| {
        y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i])
    }));
    let k6 = rate(&std::array::from_fn(|i| {
        y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i])
    }));
    let y1: State = std::array::from_fn(|i| {
        y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i])
    });
    let k7 = rate(&y1);
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
