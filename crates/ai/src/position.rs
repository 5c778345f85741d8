//! The value of a position, estimated analytically (no simulation): the success probability
//! of the best straight or cut shot the player at the table has.
//!
//! An aim error `e` (radians, Gaussian of deviation `sigma`) misses the pocket's centre line
//! by `spread * e` ([`Aim::spread`]: the ghost-ball relation carried to the pocket), so the
//! shot drops when `|spread * e| < tolerance`: probability `erf(tolerance / (sqrt 2 spread
//! sigma))`. A floor on `sigma` (a quarter of the reference noise) keeps a noiseless
//! player's estimates from saturating at 1, which would make every position look alike.

use crate::candidates::{Aim, Layout, best_open, each_direct_aim};
use crate::noise::{Noise, erf};

/// Smallest aim deviation the estimates assume, radians (a quarter of FastFiz's 0.125 deg).
const MIN_SIGMA: f64 = 0.25 * 0.125 * std::f64::consts::PI / 180.0;

/// How a long shot also costs speed control: each metre the cue ball travels beyond the
/// first takes this fraction off the success probability.
const DISTANCE_COST: f64 = 0.08;

/// Success probability of one aim under `noise`.
pub fn aim_probability(aim: &Aim, noise: Noise) -> f64 {
    let sigma = noise.sigma_angle().max(MIN_SIGMA);
    let p = erf(aim.tolerance / (std::f64::consts::SQRT_2 * aim.spread * sigma));
    let travel = aim.speed; // a proxy for distance: speed grows with both distances
    (p * (1.0 - DISTANCE_COST * (travel - 1.5).max(0.0))).clamp(0.0, 1.0)
}

/// The best success probability among the straight and cut shots at the balls of `legal`
/// from `layout`, under `noise` (0 when none is open).
pub fn best_success(layout: &Layout, legal: &[u8], noise: Noise) -> f64 {
    // The maximum over the open aims of `direct_aims` (0 without one): only the lines of
    // the best aims are checked, best first, up to the first open one.
    let mut values = Vec::new();
    each_direct_aim(layout, legal, false, |aim, lines| {
        values.push((aim_probability(&aim, noise), lines));
    });
    best_open(layout, &mut values)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::candidates::direct_aims;
    use billiards_physics::{Table, Vec2};

    fn layout(cue: Vec2, balls: Vec<(u8, Vec2)>) -> Layout {
        Layout {
            table: Table::wpa_8ft(),
            radius: 0.028575,
            cue,
            balls,
        }
    }

    #[test]
    fn short_straight_shots_beat_long_cuts_and_a_blocked_ball_has_none() {
        let t = Table::wpa_8ft();
        let corner = Vec2::new(t.length / 2.0, t.width / 2.0);
        let dir = corner.normalized().unwrap();
        let ball = corner - dir * 0.4;
        let near = layout(ball - dir * 0.3, vec![(1, ball)]);
        let far = layout(Vec2::new(-0.9, -0.3), vec![(1, ball)]);
        let (p_near, p_far) = (
            best_success(&near, &[1], Noise::REFERENCE),
            best_success(&far, &[1], Noise::REFERENCE),
        );
        assert!(p_near > 0.9 && p_far < p_near, "{p_near} {p_far}");
        // More noise, less chance.
        assert!(best_success(&far, &[1], Noise { magnitude: 3.0 }) < p_far);
        // A ball between the cue ball and the 1 blocks every shot.
        let mut blocked = near.clone();
        blocked.cue = ball - dir * 0.6;
        blocked.balls.push((2, ball - dir * 0.3));
        let open: Vec<_> = direct_aims(&blocked, &[1])
            .into_iter()
            .filter(|a| matches!(a.kind, crate::ShotKind::Pot { .. }))
            .collect();
        assert!(open.is_empty(), "{open:?}");
    }
}
