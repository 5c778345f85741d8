//! Ball–ball friction that depends on the sliding speed at the contact (Alciatore, TP A-14
//! "The effects of cut angle, speed, and spin on object ball throw", with the fit of TP A-28).

use super::ball_ball::frictional_spheres;
use super::friction::PairFriction;
use crate::ball::BallState;
use crate::math::Vec2;
use crate::params::BallFriction;

/// Sliding speed (m/s) of the contact points of balls `a` and `b` touching along unit `n`
/// (from `a` to `b`): TP A-14's `v_rel`, the tangential part of the relative velocity of the
/// points at `+R n` on `a` and `-R n` on `b`, in 3D (side spin slips horizontally, follow and
/// draw vertically).
pub fn contact_slip_speed(a: &BallState, b: &BallState, n: Vec2, radius: f64) -> f64 {
    let n3 = n.extend();
    let ca = a.velocity.extend() + a.angular_velocity.cross(n3 * radius);
    let cb = b.velocity.extend() + b.angular_velocity.cross(n3 * -radius);
    let rel = ca - cb;
    (rel - n3 * rel.dot(n3)).length()
}

/// [`frictional_spheres`] with the friction coefficient of `friction` at the sliding speed the
/// collision starts with (TP A-14 eq. for `mu(v_rel)`: one coefficient for the whole impulse,
/// as in Alciatore's throw formula). Returns `None` if the balls are not approaching along
/// `n`.
pub fn speed_dependent_spheres(
    a: &BallState,
    b: &BallState,
    n: Vec2,
    e: f64,
    friction: BallFriction,
    radius: f64,
) -> Option<(BallState, BallState)> {
    // `frictional_spheres` evaluates the coefficient at the same starting slip speed.
    let friction = PairFriction {
        constant: 0.0,
        law: friction,
    };
    frictional_spheres(a, b, n, e, friction, radius)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Motion;
    use crate::math::Vec3;

    const R: f64 = 0.028575;

    fn ball(x: f64, v: Vec2, w: Vec3) -> BallState {
        BallState {
            position: Vec2::new(x, 0.0),
            velocity: v,
            angular_velocity: w,
            motion: Motion::Sliding,
            ..BallState::default()
        }
    }

    /// Throw angle (degrees) of a stun cue ball at `speed` hitting a still ball at cut `phi`.
    fn stun_throw(speed: f64, phi: f64, friction: BallFriction) -> f64 {
        let n = Vec2::from_angle(phi);
        let a = ball(0.0, Vec2::new(speed, 0.0), Vec3::ZERO);
        let b = ball(2.0 * R, Vec2::ZERO, Vec3::ZERO);
        let (_, b2) = speed_dependent_spheres(&a, &b, n, 1.0, friction, R).unwrap();
        (b2.velocity.angle() - phi).abs().to_degrees()
    }

    #[test]
    fn the_fit_gives_alciatores_coefficients() {
        // TP A-28 p. 1 fits Marlow's mu = 0.11, 0.06, 0.01 at v sin 45 deg for v = 0.1, 1, 10.
        let f = BallFriction::ALCIATORE;
        let s = std::f64::consts::FRAC_1_SQRT_2;
        for (v, mu) in [(0.1, 0.11), (1.0, 0.06), (10.0, 0.01)] {
            let got = f.mu(0.0, v * s);
            assert!(
                (got - mu).abs() < 2e-3,
                "mu({v} sin 45) = {got}, Marlow {mu}"
            );
        }
        assert_eq!(BallFriction::Constant.mu(0.05, 3.0), 0.05);
    }

    #[test]
    fn stun_throw_follows_tp_a14_closed_form() {
        // TP A-14 (e = 1, stun): tan(throw) = min(mu(v sin phi) cos phi / sin phi, 1/7) tan phi.
        let f = BallFriction::ALCIATORE;
        for speed in [0.5, 1.5, 3.0] {
            for deg in [5.0, 15.0, 30.0, 45.0, 60.0, 80.0] {
                let phi = f64::to_radians(deg);
                let v_rel = speed * phi.sin();
                let mu = f.mu(0.0, v_rel);
                let want = ((mu * speed * phi.cos() / v_rel).min(1.0 / 7.0) * phi.tan())
                    .atan()
                    .to_degrees();
                let got = stun_throw(speed, phi, f);
                assert!(
                    (got - want).abs() < 1e-9,
                    "{speed} m/s, {deg} deg: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn zero_friction_is_the_frictionless_collision() {
        let f = BallFriction::SpeedDependent {
            a: 0.0,
            b: 0.0,
            c: 1.0,
        };
        let a = ball(0.0, Vec2::new(1.2, 0.1), Vec3::new(3.0, -20.0, 15.0));
        let b = ball(2.0 * R, Vec2::ZERO, Vec3::ZERO);
        let n = Vec2::new(1.0, 0.3).normalized().unwrap();
        let got = speed_dependent_spheres(&a, &b, n, 0.95, f, R).unwrap();
        let (va, vb) =
            super::super::equal_mass_restitution(a.velocity, b.velocity, n, 0.95).unwrap();
        assert_eq!((got.0.velocity, got.1.velocity), (va, vb));
        assert_eq!(got.0.angular_velocity, a.angular_velocity);
    }

    #[test]
    fn slow_cuts_throw_more_than_fast_ones() {
        // TP A-14 fig. "throw vs cut angle for various speeds": a half-ball stun hit throws
        // more at 0.5 m/s than at 3 m/s.
        let phi = f64::to_radians(30.0);
        let (slow, fast) = (
            stun_throw(0.5, phi, BallFriction::ALCIATORE),
            stun_throw(3.0, phi, BallFriction::ALCIATORE),
        );
        assert!(slow > fast + 1.0, "slow {slow} deg, fast {fast} deg");
    }
}
