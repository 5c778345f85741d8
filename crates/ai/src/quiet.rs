//! The end of a shot known before it is simulated: once every moving ball rolls straight to
//! its stop, inside the playing area (so no cushion, jaw or pocket can be reached), and no
//! two of the paths left (nor a path and a resting ball) come within a ball's diameter,
//! nothing but the stops can happen any more. Each ball then ends where its current segment
//! stops, and the search skips the stop events (the lean mode's second early exit: the
//! position, which is what a legal shot is scored on, is already known).

use crate::candidates::Layout;
use billiards_physics::detect::segments_apart;
use billiards_physics::{Motion, Simulation, Vec2};
use billiards_rules::CUE;

/// Clearance kept from every boundary and between paths, metres (far above rounding).
const MARGIN: f64 = 1e-6;
/// Most balls the shortcut looks at (a pool rack has 16).
const MAX_BALLS: usize = 24;

/// The layout every ball of `sim` comes to rest in, when nothing but the stops is left.
pub fn final_layout(sim: &Simulation) -> Option<Layout> {
    let t = sim.time();
    let table = sim.table();
    let r = sim.params().ball.radius;
    let b = table.centre_bounds(r);
    // A corner pocket's opening: sx x + sy y >= hx - leg + hy drops the ball.
    let corner = 0.5 * (table.length + table.width) - table.corner_leg();
    let inside = |p: Vec2| {
        p.x.abs() <= b.x - MARGIN
            && p.y.abs() <= b.y - MARGIN
            && p.x.abs() + p.y.abs() < corner - MARGIN
    };
    // A ball still sliding (or curving, or in the air) answers at once, before anything is
    // built.
    let curving = |s: &billiards_physics::Segment| match s.state.motion {
        Motion::Sliding | Motion::Airborne => true,
        Motion::Rolling => !s.straight,
        _ => false,
    };
    if (0..sim.ball_count()).any(|id| curving(sim.segment(id))) {
        return None;
    }
    // Each ball on the table: its path from now to where it stops (on the stack: this runs
    // after every transition of every sample; a larger scene takes no shortcut).
    let mut buffer = [(0u8, Vec2::ZERO, Vec2::ZERO); MAX_BALLS];
    let mut len = 0;
    let mut push = |path| {
        let slot = buffer.get_mut(len)?;
        *slot = path;
        len += 1;
        Some(())
    };
    for (id, &n) in sim.numbers().iter().enumerate() {
        let seg = sim.segment(id);
        match seg.state.motion {
            Motion::Pocketed(_) | Motion::OffTable => continue,
            Motion::Stationary | Motion::Spinning => {
                let p = seg.position_at(t.max(seg.start));
                push((n, p, p))?;
            }
            Motion::Rolling if seg.straight => {
                let end = seg.end?;
                let (from, to) = (seg.position_at(t), seg.position_at(end));
                if !(inside(from) && inside(to)) {
                    return None;
                }
                push((n, from, to))?;
            }
            Motion::Rolling | Motion::Sliding | Motion::Airborne => return None,
        }
    }
    let paths = &buffer[..len];
    let contact = 2.0 * r + MARGIN;
    // Boxes further apart than a contact on some axis need no exact distance.
    let apart = |a: &(u8, Vec2, Vec2), c: &(u8, Vec2, Vec2)| {
        a.1.x.max(a.2.x) + contact < c.1.x.min(c.2.x)
            || c.1.x.max(c.2.x) + contact < a.1.x.min(a.2.x)
            || a.1.y.max(a.2.y) + contact < c.1.y.min(c.2.y)
            || c.1.y.max(c.2.y) + contact < a.1.y.min(a.2.y)
    };
    for (i, a) in paths.iter().enumerate() {
        for c in &paths[i + 1..] {
            let moving = a.1 != a.2 || c.1 != c.2;
            if moving && !apart(a, c) && segments_apart((a.1, a.2), (c.1, c.2)) <= contact {
                return None;
            }
        }
    }
    let cue = paths.iter().find(|p| p.0 == CUE)?.2;
    Some(Layout {
        table: *table,
        radius: r,
        cue,
        balls: paths
            .iter()
            .filter(|p| p.0 != CUE)
            .map(|p| (p.0, p.2))
            .collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::play::table_and_params;
    use billiards_physics::{BallSetup, Shot};

    /// Whenever the shortcut answers, the layout it gives is where the solver, run on to
    /// rest, leaves every ball (to a micrometre), and no ball drops after it.
    #[test]
    fn the_final_layout_is_where_the_solver_stops_the_balls() {
        let (table, params) = table_and_params();
        let (mut answered, mut shots) = (0, 0);
        for k in 0..60 {
            let balls = [
                BallSetup::at(0, Vec2::new(-0.5, 0.1)),
                BallSetup::at(1, Vec2::new(0.1, 0.05)),
                BallSetup::at(2, Vec2::new(0.5, -0.3)),
                BallSetup::at(3, Vec2::new(-0.2, 0.4)),
            ];
            let mut sim = Simulation::new(table, params, &balls).unwrap();
            sim.set_record_history(false);
            sim.strike(0, Shot::new(-0.3 + 0.01 * k as f64, 0.8 + 0.05 * k as f64))
                .unwrap();
            shots += 1;
            let mut early = None;
            while sim.step_event().is_some() {
                if early.is_none() {
                    early = final_layout(&sim);
                }
            }
            let Some(early) = early else { continue };
            answered += 1;
            let end = Layout::of(&sim, None).unwrap();
            assert_eq!(early.balls.len(), end.balls.len(), "shot {k}");
            assert!((early.cue - end.cue).length() < 1e-6, "shot {k}");
            for (a, b) in early.balls.iter().zip(&end.balls) {
                assert_eq!(a.0, b.0);
                assert!((a.1 - b.1).length() < 1e-6, "shot {k}: {a:?} {b:?}");
            }
        }
        assert!(answered > shots / 2, "{answered} of {shots}");
    }
}
