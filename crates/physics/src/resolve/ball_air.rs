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
use crate::math::Vec3;

/// States of `a` and `b` (their heights and upward speeds set, a ball on the cloth at height
/// 0) just after they touch in space; `motion` is `Airborne` for a ball that leaves or stays
/// off the cloth, and `Sliding` (to be decided by the caller) for one on it.
pub fn air_pair(e: f64, table: &Slate, sa: &BallState, sb: &BallState) -> (BallState, BallState) {
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
    let j = if approach > 0.0 {
        0.5 * (1.0 + e) * approach
    } else {
        0.0
    };
    (after(table, sa, va - n * j), after(table, sb, vb + n * j))
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
        let (na, nb) = air_pair(1.0, &SLATE, &a, &b);
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
}
