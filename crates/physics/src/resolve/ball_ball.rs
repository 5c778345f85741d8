//! Ball–ball collision of the paper's model (3.2, after Berchek): equal masses, smooth balls.

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
