//! Ball–jaw time of impact: a ball meeting the rounded end of a cushion at a pocket (a fixed
//! circle), the ball–ball quartic with one body still.

use super::ball_ball::contact_quartic;
use super::cull::misses;
use super::kinematics::Kinematics;
use crate::ball::Segment;
use crate::math::Vec2;

/// Time after `t` at which the ball of `seg` touches a fixed circle (a rounded pocket jaw)
/// centred at `centre`, their centres then `contact` apart: the same quartic as two balls.
pub fn ball_jaw(
    seg: &Segment,
    t: f64,
    centre: Vec2,
    contact: f64,
    horizon: f64,
    kin: Kinematics,
) -> Option<f64> {
    if !seg.state.motion.is_moving() {
        return None;
    }
    let dp = seg.position_at(t) - centre;
    let reach = seg.reach(t, horizon) * (1.0 + 1e-12) + 1e-12 + contact;
    if dp.length_squared() > reach * reach {
        return None;
    }
    let a = match kin {
        Kinematics::Exact => seg.acceleration,
        Kinematics::Linear => Vec2::ZERO,
    };
    let v = seg.velocity_at(t);
    // The closest-approach cull of ball pairs, against a still body: it rejects only paths
    // with no contact root, so it changes no result (a ball passing a jaw mostly skips the
    // quartic).
    if misses(dp, v, a, contact, horizon) {
        return None;
    }
    contact_quartic(dp, v, a, contact, horizon)
}
