//! Ball–ball collision of the paper's model (3.2, after Berchek): equal masses, smooth balls.

use crate::ball::BallState;
use crate::math::{Vec2, Vec3};

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
    mu: super::friction::PairFriction,
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
    let mu = mu.at(slip_speed);
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

/// Post-contact velocities of two equal-mass balls in a resting contact along the unit normal
/// `n` (from `a` towards `b`): touching, approaching slowly or pressed together by a relative
/// normal acceleration `pressing` (m/s^2, `>= 0`).
///
/// The contact is elastic, and the pair leaves it separating at no less than
/// `sqrt(2 pressing hop)`, so that it hops apart by about `hop` metres before pressing brings
/// it back; the normal speed this needs beyond the elastic rebound is taken from the pair's
/// relative tangential speed (the relative velocity is turned, never lengthened). Momentum is
/// kept exactly and kinetic energy never rises, so a pressed pair touches at a bounded rate
/// instead of in a Zeno cascade, at no cost in energy. With no tangential speed to spare the
/// result is the elastic one.
pub fn resting_contact(va: Vec2, vb: Vec2, n: Vec2, pressing: f64, hop: f64) -> (Vec2, Vec2) {
    let dv = vb - va;
    let t = n.perp();
    let (vn, vt) = (dv.dot(n), dv.dot(t));
    let want = (-vn).max((2.0 * pressing.max(0.0) * hop).sqrt());
    if vn >= want {
        return (va, vb);
    }
    let speed2 = vn * vn + vt * vt;
    let vn2 = want.min(speed2.sqrt());
    let vt2 = vt.signum() * (speed2 - vn2 * vn2).max(0.0).sqrt().min(vt.abs());
    // Symmetric impulse: each ball takes half the change of the relative velocity.
    let half = (n * (vn2 - vn) + t * (vt2 - vt)) * 0.5;
    (va - half, vb + half)
}

/// Spin of a sliding ball (velocity `v`, spin `w`) whose cloth slip drives it along the unit
/// vector `toward` into a body that holds it: the spin about the axis `toward.perp()` is set so
/// that the contact point no longer slips along `toward` (`(v + w x (-R z)) . toward = 0`),
/// which removes the friction pressing it in. `None` when the slip does not press it in, or
/// when that would raise the spin's energy.
pub fn unpress(v: Vec2, w: Vec3, toward: Vec2, radius: f64) -> Option<Vec3> {
    let p = toward.perp();
    let (vn, wp) = (v.dot(toward), w.xy().dot(p));
    // Friction is -mu g along the slip: it presses along `toward` when the slip opposes it.
    let slip = vn - radius * wp;
    if slip >= 0.0 {
        return None;
    }
    let wp2 = vn / radius;
    (wp2.abs() <= wp.abs()).then(|| w + p.extend() * (wp2 - wp))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resting_contact_hops_apart_without_gaining_energy() {
        let n = Vec2::new(1.0, 0.0);
        // Touching, approaching at 1e-12 m/s, sliding past each other at 1 mm/s, pressed at
        // 0.01 m/s^2: they leave at sqrt(2 * 0.01 * 1e-10), the relative speed unchanged.
        let (va, vb) = (Vec2::new(0.3, 0.001), Vec2::new(0.3 - 1e-12, 0.0));
        let (a, b) = resting_contact(va, vb, n, 0.01, 1e-10);
        let sep = (b - a).dot(n);
        assert!(
            (sep - (2.0 * 0.01 * 1e-10f64).sqrt()).abs() < 1e-15,
            "{sep}"
        );
        assert!((a + b - (va + vb)).length() < 1e-16);
        let ke = |x: Vec2, y: Vec2| x.length_squared() + y.length_squared();
        assert!(ke(a, b) <= ke(va, vb) * (1.0 + 1e-15));
        // Not pressed: a plain elastic rebound.
        let (a, b) = resting_contact(va, vb, n, 0.0, 1e-10);
        assert!(((b - a).dot(n) - 1e-12).abs() < 1e-16);
    }

    #[test]
    fn unpressing_removes_the_slip_into_the_other_ball_and_never_adds_spin_energy() {
        let r = 0.028575;
        let n = Vec2::new(0.0, 1.0);
        // Still, spinning so that its contact point slips along -y: friction pushes it along +y.
        let (v, w) = (Vec2::new(0.001, 0.0), Vec3::new(-0.5, 0.2, 70.0));
        let w2 = unpress(v, w, n, r).expect("the slip presses it in");
        let slip = Vec2::new(v.x - r * w2.y, v.y + r * w2.x);
        assert!(slip.dot(n).abs() < 1e-18, "{slip:?}");
        assert_eq!((w2.y, w2.z), (w.y, w.z));
        assert!(w2.dot(w2) <= w.dot(w));
        // Slipping the other way, friction pulls it off: nothing to do.
        assert_eq!(unpress(v, Vec3::new(0.5, 0.0, 0.0), n, r), None);
    }

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
