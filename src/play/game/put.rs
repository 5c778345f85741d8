//! Balls put where the rules say, between strokes: the layout of the table by number, and the
//! balls a judgement or an option puts back (spotted balls, a cue ball in hand, a replace),
//! in the solver and in their components at once.

use bevy::{math::DVec2, prelude::*};
use billiards_physics::Vec2;

use crate::{
    sim::{SimStatus, Solver, to_dvec2},
    table::balls::{BallMotion, MotionState, Pocketed},
};

/// Every ball on the table of `sim` at time `t` of its history, by number.
pub fn layout_at(sim: &billiards_physics::Simulation, t: Option<f64>) -> Vec<(u8, Vec2)> {
    let states: Vec<billiards_physics::BallState> = match t {
        Some(t) => sim.history().states_at(t),
        None => sim.balls().collect(),
    };
    states
        .iter()
        .zip(sim.numbers())
        .filter(|(s, _)| s.motion.on_table())
        .map(|(s, &n)| (n, s.position))
        .collect()
}

/// Puts the balls `moves` names where it says, in the solver directly (a replace can move
/// a ball onto the place another one leaves, so they go in passes: each pass places every
/// ball whose place is free) and in their components; pocketed ones come back. A ball that
/// cannot be put is named by `name` in the status note.
pub fn set_balls(
    commands: &mut Commands,
    solver: &mut Solver,
    moves: &[(u8, Vec2)],
    balls: &mut Query<(&mut BallMotion, Has<Pocketed>)>,
    status: &mut SimStatus,
    name: &dyn Fn(u8) -> String,
) {
    let mut left: Vec<(usize, Vec2)> = moves
        .iter()
        .filter_map(|&(n, p)| {
            let id = solver.simulation().numbers().iter().position(|&m| m == n)?;
            let s = solver.simulation().ball(id);
            (!(s.motion.on_table() && s.position == p)).then_some((id, p))
        })
        .collect();
    while !left.is_empty() {
        let before = left.len();
        left.retain(|&(id, p)| {
            if solver.place_at_rest(id, p).is_err() {
                return true;
            }
            if let Some(entity) = solver.entity(id)
                && let Ok((mut motion, pocketed)) = balls.get_mut(entity)
            {
                // The solver has it already: the component follows without a second edit.
                *motion.bypass_change_detection() = BallMotion {
                    position: to_dvec2(p),
                    velocity: DVec2::ZERO,
                    state: MotionState::Stationary,
                    spin: bevy::math::DVec3::ZERO,
                    height: 0.0,
                };
                motion.set_changed();
                if pocketed {
                    commands.entity(entity).remove::<Pocketed>();
                }
            }
            false
        });
        if left.len() == before {
            let names: Vec<String> = left
                .iter()
                .map(|&(id, _)| name(solver.simulation().numbers()[id]))
                .collect();
            status.note = Some(format!("could not put back: {}", names.join(", ")));
            break;
        }
    }
    status.at_rest = solver.simulation().is_at_rest();
}
