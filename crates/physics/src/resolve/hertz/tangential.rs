//! Friction between the balls of a cluster, integrated with the Hertz normal forces of the
//! impact: every contact's tangential force comes from the same state at every stage of the
//! integration, so no contact goes first and the order the balls are listed in is moot.
//!
//! At a contact pushing with normal force `F_n` along the unit normal `n` (from `a` to `b`),
//! the contact points (`a` at `+R n`, `b` at `-R n`) slip past each other at
//!
//! ```text
//! s = (v_a + w_a x R n) - (v_b + w_b x (-R n)),  minus its part along n,
//! ```
//!
//! which in the basis `t = (-n_y, n_x, 0)`, `z` is `s_t = (v_a - v_b).t + R (w_a + w_b)_z`,
//! `s_z = R ((w_a + w_b)_x n_y - (w_a + w_b)_y n_x)`. As in discrete-element models, the
//! tangential force is integrated beside the normal one at each contact (Cundall & Strack,
//! Geotechnique 29, 47, 1979, whose tangential spring capped at `mu F_n` is here
//! replaced by a smooth slip law); the law is Coulomb's with stick regularised by the slip
//! speed (the regularised friction laws of Oden & Martins, Comput. Methods Appl. Mech. Eng.
//! 52, 527, 1985; shared/reference/physics.md, "Contact friction inside an impact", names
//! the `tanh` form the simplest order-free choice, and this is its algebraic twin):
//!
//! ```text
//! F = -mu(|s|) F_n s / sqrt(|s|^2 + v_eps^2),     on b: -F,
//! ```
//!
//! with `mu(|s|)` the model's ball–ball coefficient ([`crate::params::BallFriction`]) at the
//! instantaneous slip speed. It has `tanh(|s|/v_eps)`'s slope at zero slip and its limit
//! `mu F_n` far above `v_eps`, and needs one square root where `tanh` took a third of a
//! break's computing time. It acts on the balls' velocities in the table plane (its vertical
//! part goes into the cloth, as in [`crate::resolve::frictional_spheres`]) and on both
//! spins through the torque `R n x F` (`I = 2/5 m R^2`): `dw = 5 / (2 m R) (F_t z - F_z t)`
//! for each ball. Its power `F . s = -mu F_n |s|^2 / sqrt(|s|^2 + v_eps^2)` is never
//! positive: the law only ever takes energy out.
//!
//! **The regularisation speed.** Under `|s| << v_eps` the law is a viscous drag
//! `mu F_n s / v_eps` that brings the slip towards zero at the rate `7 mu F_n / (m v_eps)`
//! (the vertical slip at `5 mu F_n / (m v_eps)`); a Coulomb contact that would stick creeps
//! at a slip under `v_eps` instead, and one that slides feels `1 - v_eps^2 / (2 |s|^2)` of
//! Coulomb's force. `v_eps` is [`SLIP_SCALE`] times the impact's fastest approach, so the
//! impact's equations keep the Hertz law's property of having no speed scale: the same
//! steps at 1 mm/s as at 10 m/s, and the same relative creep. With the peak force of an
//! impact about `1.6 m v / tau` (`tau` its duration) the drag's rate peaks near
//! `11 mu / (SLIP_SCALE tau)`: 19 per contact time at mu 0.05 and 3e-2, within the
//! Dormand–Prince stability bound (`h |lambda| < 3.3`) at the steps of about `tau / 9` the
//! tolerance already takes for the normal forces. At 1e-2 (56 per contact) the steps were
//! set by stability and a 9-ball break cost 1.75x the smooth balls' instead of 1.4x.
//! Against the exact impulse law of an isolated pair ([`crate::resolve::frictional_spheres`])
//! the throw of a sliding cut is 0.3 % short and a sticking one agrees to 1e-4
//! (`hertz/tests.rs`).
//!
//! **The cloth during the impact** is left out: over a break contact (0.25 ms) sliding
//! friction 0.2 changes a ball's velocity by `mu_s g tau` = 5e-4 m/s, 5e-5 of a 10 m/s
//! break, against ball–ball friction impulses of `mu v` = 0.5 m/s; the event loop applies
//! the cloth's friction before and after the impact.

use crate::params::BallFriction;
use crate::resolve::friction::PairFriction;

/// The regularisation speed `v_eps` of the slip law, as a fraction of the impact's fastest
/// approach speed (see the module's documentation for why 3e-2).
pub const SLIP_SCALE: f64 = 3e-2;

/// The friction law of the contacts of one impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tangential {
    /// Ball–ball friction coefficient, possibly slip-dependent.
    pub friction: PairFriction,
    /// Ball radius `R`, m.
    pub radius: f64,
    /// Regularisation speed `v_eps`, m/s.
    pub slip_scale: f64,
}

impl Tangential {
    /// The law for an impact whose fastest pair approaches at `vmax` (m/s), between balls of
    /// radius `radius`.
    pub fn new(friction: PairFriction, radius: f64, vmax: f64) -> Self {
        Self {
            friction,
            radius,
            slip_scale: SLIP_SCALE * vmax,
        }
    }

    /// The slip `(s_t, s_z)` of a contact along `n` (unit, from `a` to `b`), from the balls'
    /// relative velocity `dv = v_a - v_b` and the sum of their spins `w = w_a + w_b`.
    #[inline]
    pub fn slip(&self, n: [f64; 2], dv: [f64; 2], w: [f64; 3]) -> (f64, f64) {
        let r = self.radius;
        let st = -dv[0] * n[1] + dv[1] * n[0] + r * w[2];
        let sz = r * (w[0] * n[1] - w[1] * n[0]);
        (st, sz)
    }

    /// The friction force on ball `a`, `(F_t, F_z)` along `t = (-n_y, n_x, 0)` and `z`, at a
    /// contact pushing with `normal` newtons and slipping at `(s_t, s_z)` m/s.
    #[inline]
    pub fn force(&self, normal: f64, (st, sz): (f64, f64)) -> (f64, f64) {
        let s2 = st * st + sz * sz;
        let mu = match self.friction.law {
            BallFriction::Constant => self.friction.constant,
            law => law.mu(self.friction.constant, s2.sqrt()),
        };
        if mu == 0.0 || normal <= 0.0 {
            return (0.0, 0.0);
        }
        // |F| = mu F_n |s| / sqrt(|s|^2 + v_eps^2): smooth through zero slip.
        let c = -mu * normal / (s2 + self.slip_scale * self.slip_scale).sqrt();
        (c * st, c * sz)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The law's power `F . s` on random slips and spins is never positive (it only ever
    /// takes energy out), it is the algebraic law, tending to `mu F_n` far above `v_eps`, and
    /// it is odd in the slip.
    #[test]
    fn the_slip_law_never_gives_energy_and_saturates_at_coulomb() {
        let law = Tangential::new(PairFriction::constant(0.05), 0.028575, 10.0);
        let mut seed = 12345u64;
        let mut rand = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for _ in 0..10_000 {
            let a = rand() * std::f64::consts::PI;
            let n = [a.cos(), a.sin()];
            let scale = 10f64.powf(3.0 * rand());
            let dv = [scale * rand(), scale * rand()];
            let w = [100.0 * rand(), 100.0 * rand(), 100.0 * rand()];
            let s = law.slip(n, dv, w);
            let f = law.force(1000.0, s);
            assert!(f.0 * s.0 + f.1 * s.1 <= 0.0, "power {:?} {:?}", f, s);
            let m = law.force(1000.0, (-s.0, -s.1));
            assert_eq!((m.0, m.1), (-f.0, -f.1));
        }
        // mu F_n = 50 N: 50 x^2 / sqrt(x^2 + 1) at x = |s| / v_eps, to 1/(2 x^2) of it.
        for x in [0.5, 3.0, 1e4] {
            let f = law.force(1000.0, (x * law.slip_scale, 0.0));
            let want = -50.0 * x / (x * x + 1.0f64).sqrt();
            assert!((f.0 - want).abs() < 1e-12 * 50.0 && f.1 == 0.0, "{f:?}");
            assert!((f.0 + 50.0).abs() <= 50.0 / (2.0 * x * x), "{f:?}");
        }
        let f = law.force(1000.0, (0.0, 0.0));
        assert_eq!(f, (0.0, 0.0));
    }
}
