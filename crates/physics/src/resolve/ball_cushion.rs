//! Ball–cushion collision of the paper's model (3.1): reflection about the cushion normal.

use crate::math::Vec2;

/// Velocity after a cushion contact with unit inward normal `n` and restitution `e`:
/// `R = v − (1 + e) n (v·n)`; `e = 1` is the paper's mirror reflection `v − 2 n (v·n)`.
/// Returns `None` if the ball is not moving into the cushion.
pub fn reflect(v: Vec2, n: Vec2, e: f64) -> Option<Vec2> {
    let vn = v.dot(n);
    (vn < 0.0).then(|| v - n * ((1.0 + e) * vn))
}

/// Velocity after a resting contact with a cushion of unit inward normal `n`: touching,
/// approaching slowly or pressed into it by an acceleration `pressing` (m/s^2, `>= 0`).
/// Elastic, leaving at no less than `sqrt(2 pressing hop)`, the extra normal speed taken from
/// the tangential speed so the speed never rises (see [`super::resting_contact`]).
pub fn resting_reflect(v: Vec2, n: Vec2, pressing: f64, hop: f64) -> Vec2 {
    let t = n.perp();
    let (vn, vt) = (v.dot(n), v.dot(t));
    let want = (-vn).max((2.0 * pressing.max(0.0) * hop).sqrt());
    if vn >= want {
        return v;
    }
    let speed2 = vn * vn + vt * vt;
    let vn2 = want.min(speed2.sqrt());
    let vt2 = vt.signum() * (speed2 - vn2 * vn2).max(0.0).sqrt().min(vt.abs());
    v + n * (vn2 - vn) + t * (vt2 - vt)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elastic_reflection_mirrors_the_angle_of_incidence() {
        let v = Vec2::from_angle(-0.7) * 1.5;
        let r = reflect(v, Vec2::new(0.0, 1.0), 1.0).unwrap();
        assert!((r.angle() - 0.7).abs() < 1e-15);
        assert!((r.length() - 1.5).abs() < 1e-15);
    }

    #[test]
    fn restitution_scales_only_the_normal_component() {
        let r = reflect(Vec2::new(0.4, -2.0), Vec2::new(0.0, 1.0), 0.85).unwrap();
        assert_eq!(r.x, 0.4);
        assert!((r.y - 1.7).abs() < 1e-15);
    }
}
