//! Ball–ball collision of the paper's model (3.2, after Berchek): equal masses, smooth balls.

use crate::ball::BallState;
use crate::math::Vec2;

/// Post-collision velocities of two equal-mass smooth balls meeting along the unit normal `n`
/// (from `a` towards `b`), with restitution `e`.
///
/// The impulse form `J = (1 + e)/2 · (v_a − v_b)·n`, `v_a' = v_a − J n`, `v_b' = v_b + J n` is
/// the paper's `v1' = n (n·v2) + t (t·v1)` for `e = 1` (the normal components are exchanged
/// exactly, tangential components kept; slip 3: `n` is normalised, `t = (−n_y, n_x)`), and it
/// conserves momentum to rounding for any `e`. Returns `None` if the balls are not approaching
/// along `n`.
pub fn equal_mass_restitution(va: Vec2, vb: Vec2, n: Vec2, e: f64) -> Option<(Vec2, Vec2)> {
    let approach = (va - vb).dot(n);
    if approach <= 0.0 {
        return None;
    }
    let j = 0.5 * (1.0 + e) * approach;
    Some((va - n * j, vb + n * j))
}

/// Collision of two equal smooth-surfaced but frictional spheres (spin model): the normal
/// impulse of [`equal_mass_restitution`], plus a tangential friction impulse opposing the slip
/// of the contact points, Coulomb-limited to `mu` times the normal impulse and never more than
/// what stops the slip (Alciatore, TP A-14 "throw"; pooltool's frictional inelastic model).
///
/// The slip is 3D (side spin gives a horizontal slip, follow and draw a vertical one), so a
/// rolling ball throws less than a stun ball. The vertical part of the impulse changes only
/// the spins: the cloth takes the vertical force. Returns `None` if the balls are not
/// approaching along `n` (unit, from `a` to `b`).
pub fn frictional_spheres(
    a: &BallState,
    b: &BallState,
    n: Vec2,
    e: f64,
    mu: f64,
    radius: f64,
) -> Option<(BallState, BallState)> {
    let approach = (a.velocity - b.velocity).dot(n);
    if approach <= 0.0 {
        return None;
    }
    // Normal impulse per unit mass.
    let jn = 0.5 * (1.0 + e) * approach;
    let n3 = n.extend();
    let (wa, wb) = (a.angular_velocity, b.angular_velocity);
    // Velocities of the two contact points (a at +R n, b at -R n), and their relative slip.
    let ca = a.velocity.extend() + wa.cross(n3 * radius);
    let cb = b.velocity.extend() + wb.cross(n3 * -radius);
    let rel = ca - cb;
    let slip = rel - n3 * rel.dot(n3);
    let slip_speed = slip.length();
    let mut va = a.velocity - n * jn;
    let mut vb = b.velocity + n * jn;
    let (mut wa2, mut wb2) = (wa, wb);
    if slip_speed > 0.0 && mu > 0.0 {
        // Per unit mass; 7 = 2 (linear, both balls) + 2 x 5/2 (angular, I = 2/5 m R^2).
        let jt = (mu * jn).min(slip_speed / 7.0);
        let dir = slip / slip_speed;
        let j = dir * -jt; // on a; b receives the opposite
        va += j.xy();
        vb -= j.xy();
        // dw = (r x J) / I, with r = +R n for a and -R n for b; J_b = -J_a: equal changes.
        let dw = n3.cross(j) * (2.5 / radius);
        wa2 = wa + dw;
        wb2 = wb + dw;
    }
    Some((
        BallState {
            velocity: va,
            angular_velocity: wa2,
            ..*a
        },
        BallState {
            velocity: vb,
            angular_velocity: wb2,
            ..*b
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn head_on_elastic_collision_exchanges_velocities_exactly() {
        let (a, b) =
            equal_mass_restitution(Vec2::new(2.5, 0.0), Vec2::ZERO, Vec2::new(1.0, 0.0), 1.0)
                .unwrap();
        assert_eq!(a, Vec2::ZERO);
        assert_eq!(b, Vec2::new(2.5, 0.0));
    }

    #[test]
    fn separating_balls_are_left_alone() {
        assert!(
            equal_mass_restitution(Vec2::new(-1.0, 0.0), Vec2::ZERO, Vec2::new(1.0, 0.0), 1.0)
                .is_none()
        );
    }

    #[test]
    fn inelastic_collision_loses_energy_and_keeps_momentum() {
        let (va, vb) = (Vec2::new(1.0, 0.3), Vec2::new(-0.2, 0.1));
        let n = Vec2::new(1.0, 1.0).normalized().unwrap();
        let (a, b) = equal_mass_restitution(va, vb, n, 0.9).unwrap();
        let p0 = va + vb;
        let p1 = a + b;
        assert!((p0 - p1).length() < 1e-15);
        assert!(
            a.length_squared() + b.length_squared() < va.length_squared() + vb.length_squared()
        );
    }
}
