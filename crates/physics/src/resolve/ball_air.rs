//! Ball–ball impact with a ball in the air: the impulse along the line of centres in space.
//!
//! Model: two equal smooth spheres meet with unit normal `n` (from `a`'s centre to `b`'s, in
//! 3D: the height difference included) and restitution `e`; the normal impulse per unit mass
//! `J = (1 + e) / 2 ((v_a - v_b) . n)` gives `v_a' = v_a - J n`, `v_b' = v_b + J n`
//! (Alciatore TP A-5's equal-mass collision, along the 3D normal), spins unchanged: the
//! balls' mutual friction over so short a contact is neglected here (the plane's throw model
//! is not carried into 3D). A ball on the cloth that the impulse drives down (a ball landing
//! on it above its equator) meets the slate at once: the slate's reaction
//! ([`super::slate::bounce`]) returns it `e_s` of that downward speed, which lifts it if the
//! rebound would rise at least 5 mm, and its friction takes up some of the slip; otherwise it
//! goes on along the cloth with the impulse's part in the plane. A ball in the air keeps
//! flying from its height with its new upward speed. Neither step can add energy (`e <= 1`;
//! the slate's impact dissipates).

use super::slate::{self, Slate};
use crate::ball::{BallState, Motion};
use crate::detect::RESTING_HOP;
use crate::math::Vec3;

/// A ball's state at a contact in space with its acceleration there: in the plane (the
/// cloth's friction) and upward (`-g` in the air, 0 on the cloth).
pub type Moving<'a> = (&'a BallState, Vec3);

/// States of `a` and `b` (their heights and upward speeds set, a ball on the cloth at height
/// 0) just after they touch in space, with radius `radius`; `motion` is `Airborne` for a ball
/// that leaves or stays off the cloth, and `Sliding` (to be decided by the caller) for one on
/// it.
///
/// A resting contact in space ([`super::is_resting`], as on the cloth: sunk past half the
/// resting depth, or pressed together by gravity along the normal and approaching too slowly
/// to hop apart on its own; a ball in the air leaning on another's side as it slides down it)
/// is elastic with the cloth's minimum hop ([`resting_contact_3d`]): with restitution under 1
/// its bounces would shrink geometrically to an accumulation point, an inelastic collapse of
/// unboundedly many events (flight soak seed 51, shot 1,084).
pub fn air_pair(
    e: f64,
    table: &Slate,
    (sa, acc_a): Moving,
    (sb, acc_b): Moving,
) -> (BallState, BallState) {
    let d = Vec3::new(
        sb.position.x - sa.position.x,
        sb.position.y - sa.position.y,
        sb.height - sa.height,
    );
    let len = d.length();
    let n = if len > 0.0 {
        d * (1.0 / len)
    } else {
        Vec3::new(1.0, 0.0, 0.0)
    };
    let va = Vec3::new(sa.velocity.x, sa.velocity.y, sa.vertical);
    let vb = Vec3::new(sb.velocity.x, sb.velocity.y, sb.vertical);
    let approach = (va - vb).dot(n);
    // Relative normal acceleration pushing the pair together, less the centripetal term of
    // their sliding past each other (as on the cloth, `resolve::ball_pair`).
    let dv = vb - va;
    let slide = dv - n * dv.dot(n);
    let pressing = -(acc_b - acc_a).dot(n) - slide.dot(slide) / len.max(f64::MIN_POSITIVE);
    let depth = 2.0 * table.radius - len;
    let (va, vb) = if super::is_resting(depth, approach, pressing) {
        resting_contact_3d(va, vb, n, pressing, RESTING_HOP)
    } else {
        let j = if approach > 0.0 {
            0.5 * (1.0 + e) * approach
        } else {
            0.0
        };
        (va - n * j, vb + n * j)
    };
    (after(table, sa, va), after(table, sb, vb))
}

/// [`super::resting_contact`] in space: the pair leaves elastic and separating at no less
/// than `sqrt(2 pressing hop)`, the extra normal speed turned from their relative
/// tangential velocity (never lengthened), each ball taking half the change: momentum kept,
/// kinetic energy never raised.
pub fn resting_contact_3d(va: Vec3, vb: Vec3, n: Vec3, pressing: f64, hop: f64) -> (Vec3, Vec3) {
    let dv = vb - va;
    let vn = dv.dot(n);
    let tangential = dv - n * vn;
    let vt = tangential.length();
    let want = (-vn).max((2.0 * pressing.max(0.0) * hop).sqrt());
    if vn >= want {
        return (va, vb);
    }
    let speed2 = vn * vn + vt * vt;
    let vn2 = want.min(speed2.sqrt());
    let vt2 = (speed2 - vn2 * vn2).max(0.0).sqrt().min(vt);
    let t = if vt > 0.0 {
        tangential * (1.0 / vt)
    } else {
        Vec3::ZERO
    };
    let half = (n * (vn2 - vn) + t * (vt2 - vt)) * 0.5;
    (va - half, vb + half)
}

/// Ball `s` after its velocity became `v`: on the cloth and driven down, the slate's
/// reaction; in the air or lifted, a flight.
fn after(table: &Slate, s: &BallState, v: Vec3) -> BallState {
    let on_cloth = s.motion != Motion::Airborne && s.height == 0.0;
    let (velocity, vertical, spin) = if on_cloth && v.z < 0.0 {
        let b = slate::bounce(table, v.xy(), v.z, s.angular_velocity);
        (b.velocity, b.vertical, b.spin)
    } else if on_cloth {
        // Driven sideways only (n in the plane): no lift.
        (v.xy(), 0.0, s.angular_velocity)
    } else {
        (v.xy(), v.z, s.angular_velocity)
    };
    let flies = vertical > 0.0 || s.height > 0.0;
    BallState {
        velocity,
        vertical,
        angular_velocity: spin,
        motion: if flies {
            Motion::Airborne
        } else {
            Motion::Sliding
        },
        ..*s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec2;

    const SLATE: Slate = Slate {
        restitution: slate::SLATE_RESTITUTION,
        mu: 0.2,
        gravity: 9.81,
        radius: 0.028575,
    };

    #[test]
    fn a_ball_landing_on_top_drives_the_other_into_the_slate() {
        let r = SLATE.radius;
        // a falls at 2 m/s onto b from straight above-left at 45 degrees (n = (1, 0, -1)/sqrt 2).
        let h = 2.0 * r / 2f64.sqrt();
        let a = BallState {
            position: Vec2::new(0.0, 0.0),
            velocity: Vec2::new(1.0, 0.0),
            height: h,
            vertical: -2.0,
            motion: Motion::Airborne,
            ..BallState::default()
        };
        let b = BallState {
            position: Vec2::new(h, 0.0),
            ..BallState::default()
        };
        let fall = Vec3::new(0.0, 0.0, -SLATE.gravity);
        let (na, nb) = air_pair(1.0, &SLATE, (&a, fall), (&b, Vec3::ZERO));
        // Elastic, equal masses: b takes the whole normal component (1 + 2)/sqrt 2 along n;
        // its downward part 1.5 m/s meets the slate and comes back at 0.75 m/s (28.7 mm).
        let vn = 3.0 / 2f64.sqrt();
        assert!(
            (nb.vertical - 0.5 * vn / 2f64.sqrt()).abs() < 1e-12,
            "{nb:?}"
        );
        assert_eq!(nb.motion, Motion::Airborne);
        // a keeps its tangential part: (1, 0, -2) - vn n = (-0.5, 0, -0.5).
        assert!((na.velocity.x + 0.5).abs() < 1e-12 && (na.vertical + 0.5).abs() < 1e-12);
        // Energy per unit mass never grows (the slate's friction acts on b's slip).
        let ke = |s: &BallState| {
            0.5 * (s.velocity.length_squared() + s.vertical.powi(2))
                + 0.2 * r * r * s.angular_velocity.dot(s.angular_velocity)
        };
        assert!(ke(&na) + ke(&nb) <= ke(&a) + ke(&b));
    }

    /// The resting contact in space keeps momentum, never raises kinetic energy, and leaves
    /// the pair separating at `sqrt(2 a hop)` (here 4e-4 m/s at 0.8 m/s^2, 1e-7 m), turned
    /// from their sliding past each other.
    #[test]
    fn a_resting_contact_in_space_hops_apart_without_gaining_energy() {
        // b leans on a's side 5 mm up (n 0.084 off the plane) and slides down it at 0.076
        // m/s, approaching along n at 1 um/s.
        let k = 1.0 / (0.996f64.powi(2) + 0.084f64.powi(2)).sqrt();
        let n = Vec3::new(0.996, 0.0, 0.084) * k;
        let t = Vec3::new(-0.084, 0.0, 0.996) * k;
        let va = Vec3::new(0.3, 0.0, 0.0);
        let vb = va - t * 0.076 - n * 1e-6;
        let (a2, b2) = resting_contact_3d(va, vb, n, 0.8, 1e-7);
        assert!(((a2 + b2) - (va + vb)).length() < 1e-15, "momentum");
        let ke = |x: Vec3, y: Vec3| x.dot(x) + y.dot(y);
        assert!(ke(a2, b2) <= ke(va, vb) * (1.0 + 1e-15), "energy");
        let want = (2.0f64 * 0.8 * 1e-7).sqrt();
        let apart = (b2 - a2).dot(n);
        assert!((apart - want).abs() < 1e-12, "{apart} vs {want}");
        // Already separating faster than that: untouched.
        let (a3, b3) = (va, va + n * 0.01);
        assert_eq!(resting_contact_3d(a3, b3, n, 0.8, 1e-7), (a3, b3));
    }
}
