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
//! replaced by a smooth slip law); the law is Coulomb's with stick regularised by a `tanh`
//! of the slip speed (the smoothed friction laws of Oden & Martins, Comput. Methods Appl.
//! Mech. Eng. 52, 527, 1985; shared/reference/physics.md, "Contact friction inside an
//! impact", calls it the simplest order-free choice):
//!
//! ```text
//! F = -mu(|s|) F_n tanh(|s| / v_eps) s / |s|,     on b: -F,
//! ```
//!
//! with `mu(|s|)` the model's ball–ball coefficient ([`crate::params::BallFriction`]) at the
//! instantaneous slip speed. It acts on the balls' velocities in the table plane (its
//! vertical part goes into the cloth, as in [`crate::resolve::frictional_spheres`]) and on
//! both spins through the torque `R n x F` (`I = 2/5 m R^2`): `dw = 5 / (2 m R) (F_t z - F_z t)`
//! for each ball. Its power `F . s = -mu F_n tanh(|s|/v_eps) |s|` is never positive: the
//! law only ever takes energy out.
//!
//! **The regularisation speed.** Under `|s| << v_eps` the law is a viscous drag
//! `mu F_n s / v_eps` that brings the slip towards zero at the rate `7 mu F_n / (m v_eps)`;
//! a Coulomb contact that would stick creeps at a slip about `v_eps` instead. `v_eps` is
//! [`SLIP_SCALE`] times the impact's fastest approach, so the impact's equations keep the
//! Hertz law's property of having no speed scale: the same number of steps at 1 mm/s as at
//! 10 m/s, and the same relative creep. At `1e-2`, with the peak force of an impact about
//! `1.6 m v / tau` (`tau` its duration), the drag's rate is about `11 mu / (1e-2 tau)`, 56 per
//! contact time at mu 0.05: the explicit integrator's steps stay near the 1/20 of a contact
//! its tolerance asks of the normal forces alone, so the friction costs little. Against the
//! exact impulse law of an isolated pair ([`crate::resolve::frictional_spheres`]) the throw
//! differs by under 2 % of the friction impulse (the tests in `hertz/tests.rs`).
//!
//! **The cloth during the impact** is left out: over a break contact (0.25 ms) sliding
//! friction 0.2 changes a ball's velocity by `mu_s g tau` = 5e-4 m/s, 5e-5 of a 10 m/s
//! break, against ball–ball friction impulses of `mu v` = 0.5 m/s; the event loop applies
//! the cloth's friction before and after the impact.

use crate::resolve::PairFriction;

/// The regularisation speed `v_eps` of the slip law, as a fraction of the impact's fastest
/// approach speed (see the module's documentation for why 1e-2).
pub const SLIP_SCALE: f64 = 1e-2;

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
        let speed = (st * st + sz * sz).sqrt();
        let mu = self.friction.at(speed);
        if mu == 0.0 || normal <= 0.0 {
            return (0.0, 0.0);
        }
        // tanh(x) / |s| with x = |s| / v_eps; near zero its series, so the law is smooth
        // (a drag 1/v_eps) through zero slip.
        let x = speed / self.slip_scale;
        let g = if x < 1e-4 {
            (1.0 - x * x / 3.0) / self.slip_scale
        } else {
            x.tanh() / speed
        };
        let c = -mu * normal * g;
        (c * st, c * sz)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The law's power `F . s` on random slips and spins is never positive (it only ever
    /// takes energy out), it tends to `mu F_n` far above `v_eps`, and it is odd in the slip.
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
        let f = law.force(1000.0, (50.0 * law.slip_scale, 0.0));
        assert!((f.0 + 50.0).abs() < 1e-9, "{f:?}");
        let f = law.force(1000.0, (0.0, 0.0));
        assert_eq!(f, (0.0, 0.0));
    }
}
