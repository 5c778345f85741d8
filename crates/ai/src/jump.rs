//! Jump shots (issue 52): when every legal ball is hidden behind other balls, the cue ball
//! can be made to fly over the blocker. The elevated cue drives the ball into the slate,
//! which throws it up (the solver's own strike law, `billiards_physics::resolve::cue`: a
//! centre-ball strike at speed `v` and elevation `theta` takes off at `e v sin(theta)`
//! upwards, `e` = 0.5, and along the cloth at what the slate's friction leaves of
//! `v cos(theta)`, `(5/7) v cos(theta)` when it grips, above 43.6 degrees). Its centre then
//! follows the parabola `h(t) = v_z t - g t^2 / 2` while moving at constant speed `v_x` in
//! the plane, and it passes a resting ball without touching it when the least distance
//! between their centres in space stays at least `2R` (the physics README's flight section:
//! 2.779 m/s at 50 degrees clears a ball 15 cm away).
//!
//! For each elevation of the budget ([`Jumps`]) the least cue speed that clears every ball
//! on the path (landing beyond each, never within `2R` of one) is found by bisection on
//! that closed form, then struck at the budget's multiples of it; a stroke that would fly
//! over the object ball itself is dropped. The candidates are pots (the ghost ball of a
//! legal ball whose path to the pocket is open) and safeties (a full hit on the nearest
//! legal balls); the search samples them under noise like every other candidate, so a
//! jump is only played when its samples beat the kicks and safeties.

use crate::candidates::{Candidate, Layout, ShotKind, call_for, each_direct_aim};
use crate::level::Jumps;
use crate::noise::Noise;
use crate::position::aim_probability;
use billiards_physics::resolve::Laws;
use billiards_physics::resolve::cue::Cue;
use billiards_physics::{Params, Shot, TipOffset, Vec2};
use billiards_rules::{CUE, Call};

/// Fastest cue ball speed a jump is struck at, m/s (a firm jump stroke; the speeds that
/// clear a ball 10 to 40 cm away at 30 to 60 degrees are 2 to 5 m/s).
pub const MAX_JUMP_SPEED: f64 = 7.0;

/// Least distance kept between the flying cue ball's centre and a blocker's, in diameters:
/// 2 % above touching, so the noise of a reference player (0.075 m/s of speed) rarely
/// clips the blocker at the least speed.
const CLEARANCE: f64 = 1.02;

/// Whether the cue ball cannot reach any legal ball of `legal` in a straight line: every
/// one on the table has the full-hit path and every ghost-ball path of its pots blocked by
/// another ball (false when none is on the table).
pub fn hidden(layout: &Layout, legal: &[u8]) -> bool {
    let mut any = false;
    for &n in legal {
        let Some(b) = layout.ball(n) else { continue };
        any = true;
        if layout.clear(layout.cue, full_hit(layout, b), &[CUE, n]) {
            return false;
        }
    }
    let mut open = false;
    each_direct_aim(layout, legal, false, |_, lines| {
        open = open || lines.cue_open(layout);
    });
    any && !open
}

/// Where the cue ball's centre touches a ball at `b` full on.
fn full_hit(layout: &Layout, b: Vec2) -> Vec2 {
    match (b - layout.cue).normalized() {
        Some(to) => b - to * (2.0 * layout.radius),
        None => b,
    }
}

/// Jump pots: of the pots of `legal` whose path from the ball to the pocket is open but
/// whose cue ball path is blocked, the `jumps.aims` best by analytic chance under `noise`
/// that a jump can reach, each in [`strokes`]; `called` as in [`call_for`].
pub fn jump_pots(
    layout: &Layout,
    legal: &[u8],
    params: &Params,
    noise: Noise,
    jumps: &Jumps,
    (called, place): (bool, Option<Vec2>),
) -> Vec<Candidate> {
    let mut aims = Vec::new();
    each_direct_aim(layout, legal, true, |aim, lines| {
        if lines.pocket_open(layout) && !lines.cue_open(layout) {
            aims.push((aim_probability(&aim, noise), aim, lines.ghost()));
        }
    });
    // Stable: equal chances keep the geometric order, so the same table gives the same list.
    aims.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut out = Vec::new();
    let mut kept = 0;
    for (_, aim, ghost) in aims {
        if kept == jumps.aims {
            break;
        }
        let strokes = strokes(layout, params, jumps, aim.first, ghost);
        kept += usize::from(!strokes.is_empty());
        out.extend(strokes.into_iter().map(|(elevation, speed)| Candidate {
            kind: aim.kind,
            shot: jump_shot(aim.angle, speed, elevation),
            call: call_for(aim.kind, called),
            place,
            object: Some((aim.first, aim.object_dir)),
        }));
    }
    out
}

/// Jump safeties: a full hit over the blockers on each of the `jumps.hits` legal balls
/// nearest the cue ball, in [`strokes`] (a legal first contact is what they are for).
pub fn jump_hits(
    layout: &Layout,
    legal: &[u8],
    params: &Params,
    jumps: &Jumps,
    place: Option<Vec2>,
) -> Vec<Candidate> {
    let mut balls: Vec<(u8, Vec2)> = legal
        .iter()
        .filter_map(|&n| layout.ball(n).map(|b| (n, b)))
        .collect();
    let dist = |b: Vec2| (b - layout.cue).length();
    balls.sort_by(|a, b| dist(a.1).total_cmp(&dist(b.1)));
    let mut out = Vec::new();
    for (n, b) in balls.into_iter().take(jumps.hits) {
        let g = full_hit(layout, b);
        let angle = (g - layout.cue).angle();
        for (elevation, speed) in strokes(layout, params, jumps, n, g) {
            out.push(Candidate {
                kind: ShotKind::Safety { ball: n },
                shot: jump_shot(angle, speed, elevation),
                call: Call::None,
                place,
                object: None,
            });
        }
    }
    out
}

/// A centre-ball strike at `angle`, `speed` and `elevation` (radians).
fn jump_shot(angle: f64, speed: f64, elevation: f64) -> Shot {
    Shot {
        angle,
        speed,
        tip: TipOffset::default(),
        elevation,
    }
}

/// The jump strokes, `(elevation in radians, cue speed)`, that send the cue ball from where
/// it is to `ghost` over every ball on that line and still meet ball `ball` there: at each
/// elevation of `jumps`, the budget's multiples of the least clearing speed, up to
/// [`MAX_JUMP_SPEED`], those whose first flight does not pass over `ball`. None when no
/// ball is on the line (no jump is needed) or the model lifts no ball.
pub fn strokes(
    layout: &Layout,
    params: &Params,
    jumps: &Jumps,
    ball: u8,
    ghost: Vec2,
) -> Vec<(f64, f64)> {
    let (cue, r) = (layout.cue, layout.radius);
    let Some(dir) = (ghost - cue).normalized() else {
        return Vec::new();
    };
    let length = (ghost - cue).length();
    // Each ball as (distance along the line, distance off it).
    let along = |p: Vec2| ((p - cue).dot(dir), (p - cue).perp_dot(dir));
    let blockers: Vec<(f64, f64)> = layout
        .balls
        .iter()
        .filter(|b| b.0 != ball)
        .map(|b| along(b.1))
        .filter(|&(a, c)| a > 0.0 && a < length + 2.0 * r && c.abs() < 2.0 * r)
        .collect();
    let Some(object) = layout.ball(ball).map(along) else {
        return Vec::new();
    };
    if blockers.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::new();
    for &degrees in jumps.elevations {
        let elevation = degrees.to_radians();
        let Some(least) = least_speed(params, elevation, &blockers) else {
            continue;
        };
        for &k in jumps.speeds {
            let speed = least * k;
            let Some(flight) = Flight::of(params, elevation, speed) else {
                continue;
            };
            if speed <= MAX_JUMP_SPEED && !flight.passes(object, 2.0 * r) {
                out.push((elevation, speed));
            }
        }
    }
    out
}

/// The least cue speed at `elevation` whose first flight clears every ball of `blockers`
/// ((along, off) the line, metres), by bisection to 1 mm/s; `None` when even
/// [`MAX_JUMP_SPEED`] does not.
fn least_speed(params: &Params, elevation: f64, blockers: &[(f64, f64)]) -> Option<f64> {
    let contact = 2.0 * params.ball.radius;
    let clears = |v: f64| {
        Flight::of(params, elevation, v)
            .is_some_and(|f| blockers.iter().all(|&b| f.passes(b, CLEARANCE * contact)))
    };
    if !clears(MAX_JUMP_SPEED) {
        return None;
    }
    let (mut lo, mut hi) = (0.0, MAX_JUMP_SPEED);
    while hi - lo > 1e-3 {
        let mid = 0.5 * (lo + hi);
        if clears(mid) { hi = mid } else { lo = mid }
    }
    Some(hi)
}

/// The cue ball's first flight after a centre-ball strike: its speed along the cloth and
/// upwards at take-off, and gravity.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Flight {
    along: f64,
    up: f64,
    gravity: f64,
}

impl Flight {
    /// The first flight of a centre-ball strike at `elevation` and `speed`, by the solver's
    /// strike law; `None` when the ball stays on the cloth (a rise under 5 mm, or the
    /// paper's model, whose cue lifts nothing).
    fn of(params: &Params, elevation: f64, speed: f64) -> Option<Flight> {
        let cue = Cue {
            dir: Vec2::new(1.0, 0.0),
            elevation,
        };
        let law = Laws::of(&params.model).cue;
        let b = law
            .strike(
                &params.ball,
                params.gravity,
                cue,
                speed,
                TipOffset::default(),
            )
            .ok()?;
        (b.vertical > 0.0).then_some(Flight {
            along: b.velocity.length(),
            up: b.vertical,
            gravity: params.gravity,
        })
    }

    /// Time of the first landing, seconds.
    fn duration(&self) -> f64 {
        2.0 * self.up / self.gravity
    }

    /// Whether a ball resting at `(along, off)` the line is passed in the air: the first
    /// landing is beyond it and the centres never come closer than `gap` in space (sampled
    /// at 200 instants, the closest refined by ternary search: the distance to a parabola
    /// can have two local minima, one on each leg).
    fn passes(&self, (a, c): (f64, f64), gap: f64) -> bool {
        let t_end = self.duration();
        if self.along * t_end <= a {
            return false;
        }
        let d2 = |t: f64| {
            let h = self.up * t - 0.5 * self.gravity * t * t;
            (self.along * t - a).powi(2) + c * c + h * h
        };
        const N: usize = 200;
        let step = t_end / N as f64;
        let k = (0..=N)
            .min_by(|&i, &j| d2(i as f64 * step).total_cmp(&d2(j as f64 * step)))
            .unwrap_or(0);
        let (mut lo, mut hi) = (
            k.saturating_sub(1) as f64 * step,
            (k + 1).min(N) as f64 * step,
        );
        for _ in 0..40 {
            let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
            if d2(m1) < d2(m2) { hi = m2 } else { lo = m1 }
        }
        d2(0.5 * (lo + hi)) >= gap * gap
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::Table;

    /// The game's parameters (the spin model: the paper's cue lifts nothing).
    fn params() -> Params {
        crate::play::table_and_params().1
    }

    /// The physics' own figure (crates/physics/tests/flight.rs, README "Balls in the air"):
    /// at 50 degrees a centre-ball strike clears a ball 15 cm ahead from 2.779 m/s.
    #[test]
    fn the_least_speed_over_a_ball_fifteen_centimetres_away_is_the_physics_threshold() {
        let params = params();
        let v = least_speed(&params, 50f64.to_radians(), &[(0.15, 0.0)]).unwrap();
        // CLEARANCE keeps 2 % of a diameter more than touching: a little above 2.779.
        assert!(v > 2.779 && v < 2.779 * 1.03, "{v}");
        let exact = |v: f64| {
            let f = Flight::of(&params, 50f64.to_radians(), v).unwrap();
            f.passes((0.15, 0.0), 2.0 * params.ball.radius)
        };
        assert!(exact(2.779 * 1.001) && !exact(2.779 * 0.999));
    }

    /// A ball 15 cm ahead of the cue ball and the 1 70 cm ahead on the same line: hidden;
    /// the strokes found jump the blocker and come down before passing the 1; with the blocker moved aside nothing
    /// is hidden and no jump is offered.
    #[test]
    fn a_blocked_ball_is_hidden_and_gets_jumps_an_open_one_none() {
        let params = params();
        let r = params.ball.radius;
        let mut layout = Layout {
            table: Table::wpa_9ft(),
            radius: r,
            cue: Vec2::new(-0.6, 0.0),
            balls: vec![(1, Vec2::new(0.1, 0.0)), (2, Vec2::new(-0.45, 0.0))],
        };
        assert!(hidden(&layout, &[1]));
        let jumps = Jumps {
            aims: 2,
            elevations: &[30.0, 45.0, 60.0],
            speeds: &[1.05, 1.2],
            hits: 1,
        };
        let hits = jump_hits(&layout, &[1], &params, &jumps, None);
        // At 30 degrees the flight that clears a ball this near is long and passes over
        // the 1 as well: those strokes are dropped, the 45- and 60-degree ones kept.
        assert_eq!(hits.len(), 4, "{hits:?}");
        for c in &hits {
            assert!(c.shot.elevation >= 30f64.to_radians() && c.shot.speed > 1.0);
            let f = Flight::of(&params, c.shot.elevation, c.shot.speed).unwrap();
            assert!(f.passes((0.15, 0.0), 2.0 * r) && !f.passes((0.7, 0.0), 2.0 * r));
        }
        layout.balls[1].1 = Vec2::new(-0.45, 0.3);
        assert!(!hidden(&layout, &[1]));
        assert!(strokes(&layout, &params, &jumps, 1, Vec2::new(0.1 - 2.0 * r, 0.0)).is_empty());
    }
}
