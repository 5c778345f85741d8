//! The direction a sliding contact's slip grows in, for a slip that has left zero slowly and
//! whose direction is therefore stiff.
//!
//! With the other contact's friction direction given (or that contact stuck), a contact's slip
//! rate is affine in its own sliding direction `u`: `dS/dP = A + B u` (the equations of
//! `contact.rs`: friction `-mu u`, the other contact's friction linear in it through the
//! table's normal `N`, or through the constraint that holds it). Its direction `phi` then
//! obeys `|S| dphi/dP = F(phi) = u_perp . (A + B u)`: it relaxes to the root `u*` of `F` at
//! the rate `kappa / |S|`, `kappa = lambda - u_perp . B u_perp`, while `|S|` grows at
//! `lambda = u* . (A + B u*) > 0`. Near zero `kappa / |S|` is far above the rate at which
//! `u*` moves (only as the other contact turns), so an explicit step must stay below
//! `STABLE |S| / kappa` (`bs3.rs`) to stay stable, though nothing turns but `u*`.
//!
//! Slaved, the contact's friction takes `u*` itself (the slow manifold, Tikhonov's zeroth
//! order): `(lambda I - B) u = A` with `|u| = 1`. Both contacts' `B` are upper triangular
//! (`B21 = 0`), so `u(lambda)` is explicit and `|u(lambda)| = 1` is solved by Newton's
//! method in `lambda`, safeguarded by bisection; a root with `lambda > 0` exists exactly when
//! the cone cannot hold the contact stuck (`|B^-1 A| > 1`, `|u(0)| > 1`). The true direction
//! lags `u*` by `|S| (dphi*/dP) / kappa`: the integration slaves a contact only while the
//! friction impulse that lag misdirects stays within its tolerance (`limits.rs`).

use super::contact::Setup;
use super::contact::hypot;

impl Setup {
    /// The slaved direction `u*` of the nose's (`nose`) or the cloth's slip, given the other
    /// contact's sliding direction `other` or that it is stuck, with its growth rate
    /// `lambda` and relaxation `kappa`; `None` where the cone holds the contact (no growing
    /// direction) or the affine form does not apply (the cloth with the nose stuck, or a
    /// table's normal that may vanish). `lambda0` starts the iteration.
    pub(super) fn slaved(
        &self,
        nose: bool,
        other: [f64; 2],
        other_stuck: bool,
        lambda0: f64,
    ) -> Option<([f64; 2], f64, f64)> {
        let (s, c) = (self.s, self.c);
        let (kx, ka, kb) = (1.0 - 2.5 * s, s * s + 2.5, 2.5 - s);
        let (mu_w, mu_s) = (self.mu_w, self.mu_s);
        if !nose {
            // The cloth, the nose sliding along `other` (fixing `a`, `b` and `N`):
            // A = (kx a, -c + kb b), B = -7/2 mu_s N I, so u* is A's direction.
            if other_stuck {
                return None;
            }
            let (a, b) = (-mu_w * other[0], -mu_w * other[1]);
            let beta = 3.5 * mu_s * (s - c * b).max(0.0);
            let (ax, ay) = (kx * a, -c + kb * b);
            let len = hypot([ax, ay]);
            return (len > beta).then(|| ([ax / len, ay / len], len - beta, len));
        }
        // The nose: with the cloth sliding along `other`, p = -mu_s N ucx, q = -mu_s N ucy,
        // N = s + c mu_w u_y; with the cloth stuck, p = -kx a / 7/2, q = (c - kb b) / 7/2.
        let (ax, ay, b11, b12, b22) = if other_stuck {
            (
                0.0,
                s * c + kb * c / 3.5,
                -mu_w * (3.5 - kx * kx / 3.5),
                0.0,
                -mu_w * (ka - kb * kb / 3.5),
            )
        } else {
            if s <= c * mu_w {
                return None; // N = s + c mu_w u_y could reach zero (and be clamped)
            }
            (
                -kx * mu_s * s * other[0],
                s * c - kb * mu_s * s * other[1],
                -3.5 * mu_w,
                -kx * mu_s * c * mu_w * other[0],
                -ka * mu_w - kb * mu_s * c * mu_w * other[1],
            )
        };
        if !(b11 < 0.0 && b22 < 0.0) {
            return None;
        }
        // u(lambda): u_y = A_y / (lambda - B22), u_x = (A_x + B12 u_y) / (lambda - B11).
        let u_of = |l: f64| {
            let (iy, ix) = (1.0 / (l - b22), 1.0 / (l - b11));
            let uy = ay * iy;
            ((ax + b12 * uy) * ix, uy, ix, iy)
        };
        let (ux, uy, _, _) = u_of(0.0);
        if ux * ux + uy * uy <= 1.0 {
            return None; // the cone holds it
        }
        // |u(hi)| < 1 at hi: |u_y| <= 1/2 and |u_x| <= (|A_x| + |B12| / 2) / hi < 1/2.
        let (mut lo, mut hi) = (0.0, 2.0 * (ax.abs() + ay.abs() + b12.abs()));
        // Without a start, from zero: |u(lambda)|^2 - 1 falls and is (mostly) convex, so Newton's
        // iterates from the left of the root rise to it without overshooting (from the middle
        // of the bracket, a root near zero took some 30 bisections).
        let mut l = if lambda0 > lo && lambda0 < hi {
            lambda0
        } else {
            lo
        };
        // `u(l)` once the iteration stops at `l` itself (not after a last step).
        let mut at_l = None;
        for _ in 0..60 {
            let (ux, uy, ix, iy) = u_of(l);
            let g = ux * ux + uy * uy - 1.0;
            if g.abs() <= 1e-14 {
                at_l = Some((ux, uy));
                break; // |u| = 1 to rounding: no further step needed
            }
            if g > 0.0 {
                lo = l;
            } else {
                hi = l;
            }
            let duy = -uy * iy;
            let dux = (b12 * duy - ux) * ix;
            let mut next = l - g / (2.0 * (ux * dux + uy * duy));
            if !(next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            let done = (next - l).abs() <= 1e-14 * l;
            l = next;
            if done || hi - lo <= 1e-15 * hi {
                break;
            }
        }
        let (ux, uy) = at_l.unwrap_or_else(|| {
            let (ux, uy, _, _) = u_of(l);
            (ux, uy)
        });
        let inv = 1.0 / hypot([ux, uy]);
        let u = [ux * inv, uy * inv];
        let kappa = l - (b11 * u[1] * u[1] - b12 * u[0] * u[1] + b22 * u[0] * u[0]);
        Some((u, l, kappa))
    }
}
