//! Ball–cushion collision of the paper's model (3.1): reflection about the cushion normal.

use crate::math::{Vec2, Vec3};

/// Velocity after a cushion contact with unit inward normal `n` and restitution `e`:
/// `R = v − (1 + e) n (v·n)`; `e = 1` is the paper's mirror reflection `v − 2 n (v·n)`.
/// Returns `None` if the ball is not moving into the cushion.
pub fn reflect(v: Vec2, n: Vec2, e: f64) -> Option<Vec2> {
    let vn = v.dot(n);
    (vn < 0.0).then(|| v - n * ((1.0 + e) * vn))
}

/// Han (2005), "Dynamics in carom and three cushion billiards" (J. Mech. Sci. Tech. 19):
/// the cushion touches the ball at its nose, at angle `theta` above the ball's centre
/// (`sin theta = h/R - 1`). The compression impulse along the contact normal is
/// `(1 + e) m c`, with `c` the normal approach speed there; the tangential impulse opposes the
/// slip `s` of the contact point, sticking if `|s| / A <= mu P_n` (`A = 7/(2m)`), sliding
/// with `mu P_n` otherwise (Han's eqs. 14–22). Impulses are applied to `v` (in the plane) and
/// to `w`. `n` is the unit inward normal, `height` the nose height above the cloth.
/// Returns `None` if the ball is not moving into the cushion.
pub fn han_2005(
    v: Vec2,
    w: Vec3,
    n: Vec2,
    e: f64,
    mu: f64,
    radius: f64,
    height: f64,
) -> Option<(Vec2, Vec3)> {
    // Cushion frame: x towards the cushion, y along it, z up (right-handed).
    let (ex, ey) = (-n, (-n).perp());
    let (vx, vy) = (v.dot(ex), v.dot(ey));
    if vx <= 0.0 {
        return None;
    }
    let (wx, wy, wz) = (w.xy().dot(ex), w.xy().dot(ey), w.z);
    let sin_t = (height / radius - 1.0).clamp(-1.0, 1.0);
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    // Per unit mass throughout (m = 1): A = 7/2, B = 1.
    let sx = vx * sin_t + radius * wy;
    let sy = -vy - radius * wz * cos_t + radius * wx * sin_t;
    let c = vx * cos_t;
    let pz = (1.0 + e) * c;
    let slip = (sx * sx + sy * sy).sqrt();
    let (px, py) = if slip / 3.5 <= mu * pz {
        (sx / 3.5, sy / 3.5)
    } else {
        (mu * pz * sx / slip, mu * pz * sy / slip)
    };
    // Back from the contact frame to the cushion frame.
    let big_x = -px * sin_t - pz * cos_t;
    let big_y = py;
    let big_z = px * cos_t - pz * sin_t;
    let k = 2.5 / radius; // R / I per unit mass
    let (vx2, vy2) = (vx + big_x, vy + big_y);
    let wx2 = wx - k * big_y * sin_t;
    let wy2 = wy + k * (big_x * sin_t - big_z * cos_t);
    let wz2 = wz + k * big_y * cos_t;
    Some((
        ex * vx2 + ey * vy2,
        (ex * wx2 + ey * wy2).extend() + Vec3::new(0.0, 0.0, wz2),
    ))
}

/// Normal approach speed (m/s) below which a spinning ball meeting a cushion or jaw settles
/// against it ([`settle`]) instead of rebounding. A rebound this slow would carry the ball at
/// most `v^2 / (2 mu g)`, nanometres, before cloth friction on its spin turned it back into
/// the rail: a Zeno cascade of rebounds and slide/roll transitions (soak seed 10288).
pub const SETTLE_SPEED: f64 = 1e-4;

/// Velocity and spin of a ball that settles against a fixed body of unit normal `n` (towards
/// the ball): the rail's compliance takes the normal approach and the grip of its nose the
/// spin that rolls the ball into or out of it, so neither the velocity nor the cloth contact
/// point moves along `n` afterwards (`v . n = 0` and `(v + w x (-R z)) . n = 0`). The ball
/// then runs along the rail, any sliding friction along it. Energy only falls: both removed
/// parts are squares.
pub fn settle(v: Vec2, w: Vec3, n: Vec2) -> (Vec2, Vec3) {
    let t = n.perp();
    let v2 = t * v.dot(t);
    // The cloth contact point moves by R (-w_y, w_x); its normal part is -R (w_xy . t).
    let wt = w.xy().dot(t);
    let w2 = w - t.extend() * wt;
    (v2, w2)
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
    fn settling_removes_normal_velocity_and_normal_slip_and_never_adds_energy() {
        let n = Vec2::new(0.0, 1.0);
        let (v, w) = (Vec2::new(0.3, -2e-6), Vec3::new(0.4, -10.0, 3.0));
        let (v2, w2) = settle(v, w, n);
        let r = 0.028575;
        assert_eq!(v2.dot(n), 0.0);
        assert_eq!(v2.dot(n.perp()), v.dot(n.perp()));
        // The cloth contact point no longer moves along n, so sliding friction cannot push
        // the ball back into the rail.
        let slip = Vec2::new(v2.x - r * w2.y, v2.y + r * w2.x);
        assert!(slip.dot(n).abs() < 1e-18, "{slip:?}");
        assert_eq!(w2.z, w.z);
        let e = |v: Vec2, w: Vec3| v.length_squared() + 0.4 * r * r * w.dot(w);
        assert!(e(v2, w2) <= e(v, w));
    }

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
