//! The ball–slate impact: a ball driven into the bed (an elevated cue's downward impulse, a
//! landing) rebounds with the slate's restitution and loses slip to its friction.
//!
//! Model (pooltool's main branch, `physics/resolve/ball_table/frictional_inelastic`; the same
//! impulse balance as Alciatore's jump-shot proofs, TP A.x, with a slate restitution): a ball
//! of mass `m`, radius `R`, `I = (2/5) m R^2`, meets the slate with vertical speed `v_z < 0`.
//! The normal impulse per unit mass is `P = (1 + e) |v_z|`, so it leaves with
//! `v_z' = e |v_z|`. The contact point, at `-R z`, slips at `u = v_xy + w x (-R z)`; a
//! tangential impulse `c` per unit mass against `u` changes `u` by `(7/2) c` (a solid
//! sphere), so the friction impulse is the smaller of Coulomb's `mu P` and the no-slip limit
//! `(2/7) |u|`: `dv = -c u_hat`, `dw = (5 / 2R) (dv_y, -dv_x, 0)`. The ball then rises
//! `v_z'^2 / 2g`; under [`MIN_BOUNCE_HEIGHT`] the cloth keeps it (`v_z' = 0`), as pooltool
//! stops bouncing under 5 mm. Neither impulse can add energy: the normal one keeps `e <= 1`
//! of the normal speed, the tangential one at most removes the slip.

use crate::math::{Vec2, Vec3};

/// Restitution of a ball on the slate through the cloth (pooltool's default `e_t`).
pub const SLATE_RESTITUTION: f64 = 0.5;

/// Smallest rise, metres, for which a rebound off the slate leaves the cloth (pooltool: 5 mm);
/// a lower one is absorbed and the ball slides on.
pub const MIN_BOUNCE_HEIGHT: f64 = 0.005;

/// A ball's velocity and spin just after it meets the slate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounce {
    /// Velocity in the table plane, m/s.
    pub velocity: Vec2,
    /// Upward speed, m/s: zero when the rebound would rise under [`MIN_BOUNCE_HEIGHT`].
    pub vertical: f64,
    /// Angular velocity, rad/s.
    pub spin: Vec3,
}

/// The slate's properties at an impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slate {
    /// Restitution of the vertical speed.
    pub restitution: f64,
    /// Ball–slate (through the cloth) friction.
    pub mu: f64,
    /// Gravity, m/s^2 (decides the rebound's rise).
    pub gravity: f64,
    /// Ball radius, metres.
    pub radius: f64,
}

/// The ball leaving the slate after meeting it with `velocity`, downward speed `vertical`
/// (`< 0`; a ball not moving down is returned unchanged, with no upward speed) and `spin`.
pub fn bounce(slate: &Slate, velocity: Vec2, vertical: f64, spin: Vec3) -> Bounce {
    if vertical.is_nan() || vertical >= 0.0 {
        return Bounce {
            velocity,
            vertical: 0.0,
            spin,
        };
    }
    let r = slate.radius;
    let normal = (1.0 + slate.restitution) * -vertical;
    let slip = Vec2::new(velocity.x - r * spin.y, velocity.y + r * spin.x);
    let slip_speed = slip.length();
    let (velocity, spin) = if slip_speed > 0.0 {
        let c = (slate.mu * normal).min(slip_speed * (2.0 / 7.0));
        let dv = slip * (-c / slip_speed);
        let k = 2.5 / r;
        (velocity + dv, spin + Vec3::new(k * dv.y, -k * dv.x, 0.0))
    } else {
        (velocity, spin)
    };
    let up = slate.restitution * -vertical;
    let rises = up * up / (2.0 * slate.gravity) >= MIN_BOUNCE_HEIGHT;
    Bounce {
        velocity,
        vertical: if rises { up } else { 0.0 },
        spin,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SLATE: Slate = Slate {
        restitution: SLATE_RESTITUTION,
        mu: 0.2,
        gravity: 9.81,
        radius: 0.028575,
    };

    /// Kinetic energy per unit mass of a solid sphere: `v^2 / 2 + (1/5) R^2 w^2`.
    fn energy(v: Vec2, vz: f64, w: Vec3) -> f64 {
        let r = SLATE.radius;
        0.5 * (v.length_squared() + vz * vz) + 0.2 * r * r * w.dot(w)
    }

    #[test]
    fn rebound_keeps_e_of_the_vertical_speed_and_friction_never_adds_energy() {
        let (v, w) = (Vec2::new(2.0, 0.5), Vec3::new(10.0, -30.0, 5.0));
        let b = bounce(&SLATE, v, -1.0, w);
        assert_eq!(b.vertical, 0.5, "v_z' = e |v_z|");
        assert!(energy(b.velocity, b.vertical, b.spin) <= energy(v, -1.0, w));
        // Coulomb-limited here: the slip speed's change is (7/2) mu (1 + e) |v_z|.
        let slip = |v: Vec2, w: Vec3| Vec2::new(v.x - SLATE.radius * w.y, v.y + SLATE.radius * w.x);
        let drop = slip(v, w).length() - slip(b.velocity, b.spin).length();
        assert!((drop - 3.5 * 0.2 * 1.5).abs() < 1e-12, "{drop}");
    }

    #[test]
    fn small_slip_is_removed_exactly_and_low_rebounds_stay_on_the_cloth() {
        // Slip 0.01 m/s, far under mu P: the no-slip limit leaves the ball rolling.
        let v = Vec2::new(1.0, 0.0);
        let w = Vec3::new(0.0, (1.0 - 0.01) / SLATE.radius, 0.0);
        let b = bounce(&SLATE, v, -0.5, w);
        let u = b.velocity.x - SLATE.radius * b.spin.y;
        assert!(u.abs() < 1e-14, "slip left {u}");
        // e |v_z| = 0.25 m/s rises 3.2 mm < 5 mm: absorbed.
        assert_eq!(b.vertical, 0.0);
        // 0.4 m/s up rises 8.2 mm: it leaves the cloth.
        assert_eq!(bounce(&SLATE, v, -0.8, w).vertical, 0.4);
        // A ball not moving down is untouched.
        let still = bounce(&SLATE, v, 0.0, w);
        assert_eq!((still.velocity, still.spin), (v, w));
    }
}
