//! Respotting the cue ball after a scratch: on the head string, at the head spot or the free
//! point of the string nearest to it.
//!
//! The free points are found exactly, not by stepping along the string: every other ball
//! within reach of the string blocks one open interval of it, and the nearest free point is
//! the head spot itself or an end of one of those intervals.

use billiards_physics::{BallId, Simulation, Table, Vec2, sim::PLACEMENT_TOLERANCE};

/// How far a respotted cue ball stays from every other ball (metres): 1 mm, so it is never
/// frozen to a ball it was not frozen to before the scratch (a frozen cue ball changes what
/// the next shot can do).
pub const RESPOT_CLEARANCE: f64 = 1e-3;

/// Where the cue ball goes after a scratch in `sim`: [`head_string_spot`] for the balls still
/// on the table (all but `cue`). `None` when the whole string is blocked.
pub fn cue_ball_spot(sim: &Simulation, cue: BallId) -> Option<Vec2> {
    let others: Vec<Vec2> = sim
        .balls()
        .enumerate()
        .filter(|&(id, ref state)| id != cue && state.motion.on_table())
        .map(|(_, state)| state.position)
        .collect();
    head_string_spot(sim.table(), sim.params().ball.radius, &others)
}

/// The point of the head string (x of [`Table::head_spot`]) nearest the head spot where a ball
/// of radius `radius` clears every ball centred in `others` by [`RESPOT_CLEARANCE`] and stays
/// between the side cushions. Ties go to the left side (+y). `None` when no such point exists.
pub fn head_string_spot(table: &Table, radius: f64, others: &[Vec2]) -> Option<Vec2> {
    let spot = table.head_spot();
    let limit = table.centre_bounds(radius).y;
    let reach = 2.0 * radius + RESPOT_CLEARANCE;
    // Open intervals of y blocked by each ball near the string.
    let blocked: Vec<(f64, f64)> = others
        .iter()
        .filter_map(|other| {
            let dx = other.x - spot.x;
            let half = (reach * reach - dx * dx).sqrt();
            (half > 0.0).then_some((other.y - half, other.y + half))
        })
        .collect();
    let free = |y: f64| {
        y.abs() <= limit
            && others.iter().all(|other| {
                let d = Vec2::new(spot.x, y) - *other;
                // The interval ends are exact up to rounding: allow the solver's own tolerance.
                d.length() >= reach - PLACEMENT_TOLERANCE
            })
    };
    let candidates = std::iter::once(spot.y)
        .chain(blocked.iter().flat_map(|&(low, high)| [high, low]))
        .chain([limit, -limit]);
    let mut best: Option<f64> = None;
    for y in candidates.filter(|&y| free(y)) {
        let better = match best {
            None => true,
            Some(b) => {
                let (d, db) = ((y - spot.y).abs(), (b - spot.y).abs());
                d < db || (d == db && y > b)
            }
        };
        if better {
            best = Some(y);
        }
    }
    best.map(|y| Vec2::new(spot.x, y))
}

/// How far a spotted object ball stays from the ball it is spotted against (metres): WPA
/// 1.4 freezes it to that ball; a micrometre keeps the solver's placement check clear of
/// rounding while looking frozen.
pub const SPOT_CLEARANCE: f64 = 1e-6;

/// Where an object ball is spotted (WPA 1.4): on the long string (`y = 0`), at the foot spot
/// or as near to it as possible between it and the foot cushion; if that part of the string
/// is full, as near as possible in front of the foot spot. `others` are the centres of the
/// balls on the table. `None` when the whole string is blocked.
pub fn foot_spot_position(table: &Table, radius: f64, others: &[Vec2]) -> Option<Vec2> {
    let spot = table.foot_spot();
    let limit = table.centre_bounds(radius).x;
    let reach = 2.0 * radius + SPOT_CLEARANCE;
    let blocked = others.iter().filter_map(|other| {
        let half = (reach * reach - other.y * other.y).sqrt();
        (half > 0.0).then_some([other.x - half, other.x + half])
    });
    let free = |x: f64| {
        x.abs() <= limit
            && others
                .iter()
                .all(|other| (Vec2::new(x, 0.0) - *other).length() >= reach - PLACEMENT_TOLERANCE)
    };
    let candidates: Vec<f64> = std::iter::once(spot.x)
        .chain(blocked.flatten())
        .chain([limit, -limit])
        .filter(|&x| free(x))
        .collect();
    let behind = candidates
        .iter()
        .copied()
        .filter(|&x| x >= spot.x)
        .min_by(f64::total_cmp);
    let front = || {
        candidates
            .iter()
            .copied()
            .filter(|&x| x < spot.x)
            .max_by(f64::total_cmp)
    };
    behind.or_else(front).map(|x| Vec2::new(x, 0.0))
}

/// Where `ball` of `sim` is spotted ([`foot_spot_position`] among the other balls on the
/// table).
pub fn object_ball_spot(sim: &Simulation, ball: BallId) -> Option<Vec2> {
    let others: Vec<Vec2> = sim
        .balls()
        .enumerate()
        .filter(|&(id, ref state)| id != ball && state.motion.on_table())
        .map(|(_, state)| state.position)
        .collect();
    foot_spot_position(sim.table(), sim.params().ball.radius, &others)
}

#[cfg(test)]
mod tests {
    use super::*;

    const R: f64 = 0.028575;

    fn table() -> Table {
        Table::wpa_8ft()
    }

    #[test]
    fn an_empty_string_gives_the_head_spot() {
        let t = table();
        assert_eq!(head_string_spot(&t, R, &[]), Some(t.head_spot()));
        // A ball far from the string blocks nothing.
        let far = [t.foot_spot()];
        assert_eq!(head_string_spot(&t, R, &far), Some(t.head_spot()));
    }

    #[test]
    fn a_ball_on_the_head_spot_pushes_the_cue_ball_exactly_clear_of_it() {
        let t = table();
        let on_spot = [t.head_spot()];
        let p = head_string_spot(&t, R, &on_spot).unwrap();
        // Nearest free point: 2R + clearance to the left (+y wins the tie).
        assert_eq!(p.x, t.head_spot().x);
        assert!((p.y - (2.0 * R + RESPOT_CLEARANCE)).abs() < 1e-15, "{p:?}");
    }

    #[test]
    fn a_ball_beside_the_string_blocks_a_chord() {
        let t = table();
        // 3 cm off the string, 1 cm to the right: blocked half-width sqrt(reach^2 - 0.03^2).
        let other = t.head_spot() + Vec2::new(0.03, -0.01);
        let reach = 2.0 * R + RESPOT_CLEARANCE;
        let half = (reach * reach - 0.03 * 0.03).sqrt();
        let p = head_string_spot(&t, R, &[other]).unwrap();
        let want = -0.01 + half;
        assert!((p.y - want).abs() < 1e-12, "{} vs {want}", p.y);
        assert!((p - other).length() >= reach - PLACEMENT_TOLERANCE);
    }

    #[test]
    fn a_full_string_has_no_spot_and_a_gap_is_found() {
        let t = table();
        let limit = t.centre_bounds(R).y;
        let step = 2.0 * R + RESPOT_CLEARANCE;
        // Balls every `step` along the string, from one cushion to the other.
        let mut wall: Vec<Vec2> = (0..)
            .map(|k| -limit + f64::from(k) * step * 0.99)
            .take_while(|&y| y <= limit + step)
            .map(|y| Vec2::new(t.head_spot().x, y))
            .collect();
        assert_eq!(head_string_spot(&t, R, &wall), None);
        // One ball out leaves 1.98 reach between its neighbours: still no room (2 needed).
        let mut one_out = wall.clone();
        one_out.remove(wall.len() / 3);
        assert_eq!(head_string_spot(&t, R, &one_out), None);
        // Two neighbours out leave 2.97 reach: the spot is in that gap, clear of both sides.
        let gap = wall.remove(wall.len() / 3);
        wall.remove(wall.len() / 3);
        let p = head_string_spot(&t, R, &wall).expect("a gap");
        assert!((p.y - gap.y).abs() < 2.0 * step, "{p:?} near {gap:?}");
        for other in &wall {
            assert!((p - *other).length() >= step - PLACEMENT_TOLERANCE);
        }
    }

    #[test]
    fn the_spot_never_leaves_the_table() {
        let t = table();
        let limit = t.centre_bounds(R).y;
        // A ball near the left cushion: the spot must not go past the cushion line.
        let others = [
            Vec2::new(t.head_spot().x, 0.0),
            Vec2::new(t.head_spot().x, 0.06),
        ];
        let p = head_string_spot(&t, R, &others).unwrap();
        assert!(p.y.abs() <= limit);
        assert!(p.y < 0.0, "the right side is nearer: {p:?}");
    }

    #[test]
    fn wpa_1_4_a_ball_is_spotted_on_the_foot_spot_or_behind_it_frozen() {
        let t = table();
        assert_eq!(foot_spot_position(&t, R, &[]), Some(t.foot_spot()));
        // A ball on the spot: the spotted ball goes behind it, towards the foot cushion.
        let p = foot_spot_position(&t, R, &[t.foot_spot()]).unwrap();
        assert_eq!(p.y, 0.0);
        assert!((p.x - (t.foot_spot().x + 2.0 * R + SPOT_CLEARANCE)).abs() < 1e-12);
        // The string behind the spot full: in front of the spot, as near as possible.
        let limit = t.centre_bounds(R).x;
        let step = 2.0 * R;
        let wall: Vec<Vec2> = (0..)
            .map(|k| t.foot_spot().x + f64::from(k) * step)
            .take_while(|&x| x <= limit + step)
            .map(|x| Vec2::new(x, 0.0))
            .collect();
        let p = foot_spot_position(&t, R, &wall).unwrap();
        assert!((p.x - (t.foot_spot().x - 2.0 * R - SPOT_CLEARANCE)).abs() < 1e-12);
    }
}
