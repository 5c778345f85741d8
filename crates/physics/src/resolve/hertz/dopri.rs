//! The Dormand–Prince 5(4) tableau of the impact's integrator and its stage sums.

// Dormand–Prince 5(4) (Hairer, Norsett & Wanner, Solving ODE I, table II.5.2); the system is
// autonomous, so the nodes c_i are not needed. Row 6 is the fifth-order solution (FSAL).
pub(super) const DP_A: [[f64; 6]; 6] = [
    [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// Fifth- minus fourth-order weights: the local error estimate.
pub(super) const DP_E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// `tmp = y + c[0] k[0] + c[1] k[1] + ...`, element by element, the terms in order; a zero
/// coefficient's term is skipped (as adding it could turn a -0 into +0).
#[inline]
pub(super) fn combine<const N: usize>(tmp: &mut [f64], y: &[f64], c: [f64; N], k: [&[f64]; N]) {
    if c.contains(&0.0) {
        tmp.copy_from_slice(y);
        for (c, k) in c.iter().zip(k) {
            if *c != 0.0 {
                for (t, x) in tmp.iter_mut().zip(k) {
                    *t += c * x;
                }
            }
        }
        return;
    }
    for (i, (t, y)) in tmp.iter_mut().zip(y).enumerate() {
        let mut acc = *y;
        for (c, k) in c.iter().zip(k) {
            acc += c * k[i];
        }
        *t = acc;
    }
}
