//! Ball in hand: where to put the cue ball. Places are proposed behind the ghost ball of each
//! legal ball and pocket (straight in and at small cut angles, near and far, since a little
//! angle is what lets the cue ball be moved on), kept only where the rules allow them
//! ([`check_placement`]: on the table, clear of every ball, behind the head string when the
//! rule says so), ranked by the analytic success of the best shot from there, and the best
//! few are searched in full by the caller with the same noisy evaluation as any shot.

use crate::candidates::{Layout, pocket_target};
use crate::noise::Noise;
use crate::position::best_success;
use billiards_physics::{BallId, Pocket, Simulation, Vec2};
use billiards_rules::{CueBall, check_placement};

/// Cut angles of the proposed places, degrees (0 is straight in).
const CUTS: [f64; 5] = [0.0, 12.0, -12.0, 25.0, -25.0];
/// Distances of the proposed places from the ghost ball, metres.
const DISTANCES: [f64; 2] = [0.18, 0.4];
/// Places closer than this to a better one are dropped, metres.
const MIN_APART: f64 = 0.05;

/// Up to `count` places for the cue ball of `sim` (ball `cue`) under `rule`, best first;
/// every one passes [`check_placement`]. When no proposed place is legal, the legal points of
/// a coarse grid over the allowed area are ranked instead.
pub fn places(
    sim: &Simulation,
    cue: BallId,
    rule: CueBall,
    legal: &[u8],
    noise: Noise,
    count: usize,
) -> Vec<Vec2> {
    let Some(mut layout) = Layout::of(sim, Some(Vec2::ZERO)) else {
        return Vec::new();
    };
    let r = layout.radius;
    let mut proposed = Vec::new();
    for &n in legal {
        let Some(b) = layout.ball(n) else { continue };
        for pocket in Pocket::ALL {
            let (target, _) = pocket_target(&layout.table, r, pocket);
            let Some(u) = (target - b).normalized() else {
                continue;
            };
            let ghost = b - u * (2.0 * r);
            for cut in CUTS {
                for d in DISTANCES {
                    proposed.push(ghost - u.rotated(cut.to_radians()) * d);
                }
            }
        }
    }
    let ok = |p: &Vec2| check_placement(sim, cue, *p, rule).is_ok();
    proposed.retain(ok);
    if proposed.is_empty() {
        proposed = grid(&layout, 0.1).into_iter().filter(ok).collect();
    }
    best_apart(proposed, count, |p| {
        layout.cue = p;
        best_success(&layout, legal, noise)
    })
}

/// Up to `count` of `proposed`, best `value` first, each at least `MIN_APART` (5 cm) from
/// every better one kept; equal values in the order proposed (deterministic). Pool's places
/// and snooker's in the D ([`crate::snooker::value::d_places`]) are ranked by it.
pub fn best_apart(
    proposed: Vec<Vec2>,
    count: usize,
    mut value: impl FnMut(Vec2) -> f64,
) -> Vec<Vec2> {
    let mut ranked: Vec<(f64, usize, Vec2)> = proposed
        .into_iter()
        .enumerate()
        .map(|(i, p)| (value(p), i, p))
        .collect();
    ranked.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut out: Vec<Vec2> = Vec::new();
    for (_, _, p) in ranked {
        if out.len() == count {
            break;
        }
        if out.iter().all(|q| (*q - p).length() >= MIN_APART) {
            out.push(p);
        }
    }
    out
}

/// Points of a grid of spacing `step` over the area a ball's centre may occupy.
fn grid(layout: &Layout, step: f64) -> Vec<Vec2> {
    let b = layout.table.centre_bounds(layout.radius);
    let (nx, ny) = ((2.0 * b.x / step) as i32, (2.0 * b.y / step) as i32);
    let mut out = Vec::new();
    for i in 0..=nx {
        for j in 0..=ny {
            out.push(Vec2::new(-b.x + i as f64 * step, -b.y + j as f64 * step));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn best_apart_keeps_the_best_first_drops_near_ones_and_breaks_ties_in_order() {
        // b is best; a lies 1 cm from it (under MIN_APART) and goes; c and d tie and keep
        // the order proposed; `count` cuts the list.
        let (a, b) = (Vec2::new(0.0, 0.0), Vec2::new(0.01, 0.0));
        let (c, d) = (Vec2::new(1.0, 0.0), Vec2::new(2.0, 0.0));
        let value = |p: Vec2| if p == b { 0.9 } else { 0.5 };
        assert_eq!(best_apart(vec![a, b, c, d], 3, value), vec![b, c, d]);
        assert_eq!(best_apart(vec![a, b, d, c], 2, value), vec![b, d]);
        assert_eq!(best_apart(vec![a, b, c], 0, value), Vec::<Vec2>::new());
    }
}
