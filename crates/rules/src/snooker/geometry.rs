//! Pure geometry of the rules: where a colour is re-spotted (WPBSA 3.6) and whether the cue
//! ball is snookered (2.16) or has a clear path to a ball on (3.14). Positions are the
//! caller's: `(number, centre)` of every ball on the table.

use super::balls::{COLOURS, value};
use billiards_physics::{SnookerMarks, Table, Vec2};

/// The gap left between a re-spotted colour and a ball it would otherwise touch: 0.01 mm.
pub const SPOT_GAP: f64 = 1e-5;

/// Why a colour could not be spotted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SpotError {
    /// The number is not a colour.
    #[error("ball {0} is not a colour: only colours are re-spotted (3.6)")]
    NotAColour(u8),
    /// No place on the centre line or the spot's line is free (never on a real table).
    #[error("no free place for the {0} on its line")]
    NoRoom(&'static str),
}

fn occupied(p: Vec2, balls: &[(u8, Vec2)], r: f64) -> bool {
    balls.iter().any(|&(_, q)| (p - q).length() < 2.0 * r)
}

/// The first `x` from `x0` in direction `sign` (+1 towards the top cushion) where a ball at
/// `(x, y)` touches no ball of `balls`, within `limit` (the last centre `x` on the bed).
fn nearest_free(
    x0: f64,
    y: f64,
    sign: f64,
    limit: f64,
    balls: &[(u8, Vec2)],
    r: f64,
) -> Option<f64> {
    let mut x = x0;
    // Each step leaves a ball it touched; at most one step a ball.
    for _ in 0..=balls.len() {
        let blocking = balls.iter().find_map(|&(_, q)| {
            let dy = q.y - y;
            let w2 = 4.0 * r * r - dy * dy;
            (w2 > 0.0 && (x - q.x).abs() < w2.sqrt()).then(|| q.x + sign * (w2.sqrt() + SPOT_GAP))
        });
        match blocking {
            None => return (sign * (limit - x) >= 0.0).then_some(x),
            Some(next) => x = next,
        }
    }
    None
}

/// Where colour `colour` is spotted (3.6): its own spot if free; else the spot of the
/// highest value that is free; else as near its own spot as possible on the line from it
/// straight towards the top cushion; else, with no room there, towards the bottom cushion.
/// `balls` are the balls on the table (the cue ball included when it is on the table, and
/// the colours already spotted by this rule); a spot is occupied when a ball placed on it
/// would touch another (2.18).
pub fn respot(
    colour: u8,
    marks: &SnookerMarks,
    table: &Table,
    radius: f64,
    balls: &[(u8, Vec2)],
) -> Result<Vec2, SpotError> {
    let own = marks.spot(colour).ok_or(SpotError::NotAColour(colour))?;
    let others: Vec<(u8, Vec2)> = balls
        .iter()
        .copied()
        .filter(|&(n, _)| n != colour)
        .collect();
    if !occupied(own, &others, radius) {
        return Ok(own);
    }
    for c in COLOURS.iter().rev() {
        if let Some(spot) = marks.spot(*c)
            && !occupied(spot, &others, radius)
        {
            return Ok(spot);
        }
    }
    let limit = 0.5 * table.length - radius;
    nearest_free(own.x, own.y, 1.0, limit, &others, radius)
        .or_else(|| nearest_free(own.x, own.y, -1.0, -limit, &others, radius))
        .map(|x| Vec2::new(x, own.y))
        .ok_or(SpotError::NoRoom(super::balls::name(colour)))
}

/// Spots several colours (3.6(c)): the highest value first, each seeing those spotted before.
pub fn respot_all(
    colours: &[u8],
    marks: &SnookerMarks,
    table: &Table,
    radius: f64,
    balls: &[(u8, Vec2)],
) -> Result<Vec<(u8, Vec2)>, SpotError> {
    let mut order = colours.to_vec();
    order.sort_by_key(|&c| std::cmp::Reverse(value(c).unwrap_or(0)));
    let mut on_table = balls.to_vec();
    let mut out = Vec::new();
    for c in order {
        let p = respot(c, marks, table, radius, &on_table)?;
        on_table.push((c, p));
        out.push((c, p));
    }
    Ok(out)
}

/// Directions (angles) in which the cue ball at `cue` meets the ball at `target` at its
/// extreme edges: the two thinnest contacts. `None` when they touch.
fn edges(cue: Vec2, target: Vec2, r: f64) -> Option<(f64, f64, f64)> {
    let d = target - cue;
    let len = d.length();
    if len <= 2.0 * r {
        return None;
    }
    let half = (2.0 * r / len).asin();
    Some((d.angle() - half, d.angle() + half, len))
}

/// Does the cue ball, sent from `cue` in direction `angle`, reach a ball of `obstacles`
/// nearer than `reach` (the distance travelled to the ball aimed at)?
fn blocked(cue: Vec2, angle: f64, reach: f64, r: f64, obstacles: &[Vec2]) -> bool {
    let u = Vec2::from_angle(angle);
    obstacles.iter().any(|&q| {
        let w = q - cue;
        let along = w.dot(u);
        let off2 = w.length_squared() - along * along;
        let hit2 = 4.0 * r * r - off2;
        hit2 > 0.0 && along - hit2.sqrt() < reach && along > 0.0
    })
}

/// The distance the cue ball travels in direction `angle` to meet the ball at `target`.
fn reach(cue: Vec2, target: Vec2, angle: f64, r: f64) -> f64 {
    let u = Vec2::from_angle(angle);
    let w = target - cue;
    let along = w.dot(u);
    let off2 = (w.length_squared() - along * along).max(0.0);
    along - (4.0 * r * r - off2).max(0.0).sqrt()
}

fn split(cue: Vec2, on: &[u8], balls: &[(u8, Vec2)]) -> (Vec<Vec2>, Vec<Vec2>) {
    let (mut targets, mut obstacles) = (Vec::new(), Vec::new());
    for &(n, p) in balls {
        if p == cue && n == super::balls::WHITE {
            continue;
        }
        if on.contains(&n) {
            targets.push(p);
        } else if n != super::balls::WHITE {
            obstacles.push(p);
        }
    }
    (targets, obstacles)
}

/// 2.16: is the cue ball at `cue` snookered? It is not when some ball of `on` can be hit at
/// both extreme edges by a straight stroke free of every ball not on; cushions do not count
/// (a straight line only). `balls` are the object balls on the table.
pub fn snookered(cue: Vec2, on: &[u8], balls: &[(u8, Vec2)], r: f64) -> bool {
    let (targets, obstacles) = split(cue, on, balls);
    !targets.iter().any(|&t| match edges(cue, t, r) {
        // A ball on touching the cue ball can be played away from: not snookered.
        None => true,
        Some((a, b, _)) => [a, b]
            .iter()
            .all(|&ang| !blocked(cue, ang, reach(cue, t, ang, r), r, &obstacles)),
    })
}

/// 3.14: is there a straight path from the cue ball to any part of any ball of `on`? The
/// directions that meet a ball on are checked at 1/64 of their span and at both edges
/// (exact for the edges, a sampling between them).
pub fn clear_path(cue: Vec2, on: &[u8], balls: &[(u8, Vec2)], r: f64) -> bool {
    let (targets, obstacles) = split(cue, on, balls);
    targets.iter().any(|&t| match edges(cue, t, r) {
        None => true,
        Some((a, b, _)) => (0..=64).any(|k| {
            let ang = a + (b - a) * f64::from(k) / 64.0;
            !blocked(cue, ang, reach(cue, t, ang, r), r, &obstacles)
        }),
    })
}
