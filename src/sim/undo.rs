//! Undo: the table goes back to where it rested before the last strike.

use bevy::{prelude::*, window::RequestRedraw};
use billiards_physics::{self as physics, BallState, Simulation, recording::Recorder};

use super::{messages::*, solver::*};
use crate::{
    table::balls::{BallMotion, Pocketed},
    table::geometry::TableSpec,
};

/// Takes the last shot back ([`UndoRequested`]): each ball goes back where it was before the
/// strike, by placements the recorder logs; the panel gets the shot back ([`ShotUndone`]).
#[allow(clippy::too_many_arguments)]
pub(super) fn undo_last_shot(
    mut commands: Commands,
    mut requests: MessageReader<UndoRequested>,
    solver: Option<ResMut<Solver>>,
    referee: Res<Referee>,
    spec: Res<TableSpec>,
    mut balls: Query<&mut BallMotion>,
    mut status: ResMut<SimStatus>,
    mut undone: MessageWriter<ShotUndone>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    if requests.read().count() == 0 {
        return;
    }
    let Some(mut solver) = solver else { return };
    if !referee.edits {
        status.note = Some("undo is for practice (free play): a match's shots stand".to_owned());
        return;
    }
    let Some(before) = solver.undo.pop() else {
        status.note = Some("no shot to undo since the rack".to_owned());
        return;
    };
    if let Err(error) = restore(&mut solver.rec, &spec, &before.balls) {
        status.note = Some(format!("undo incomplete: {error}"));
    } else {
        status.note = None;
    }
    for (id, &entity) in solver.entities.iter().enumerate() {
        let state = solver.simulation().ball(id);
        if let Ok(mut motion) = balls.get_mut(entity) {
            motion.set_if_neq(ball_motion(&state));
        }
        if state.motion.on_table() {
            commands.entity(entity).remove::<Pocketed>();
        }
    }
    status.at_rest = solver.simulation().is_at_rest();
    // The HUD's "simulated N s" goes back with the table: to the time of the strike undone.
    solver.undone_time = solver.simulation().time() - before.game_time;
    status.sim_time = solver.game_time();
    status.shots = before.shots;
    status.ball_in_hand = before.ball_in_hand;
    status.events_this_shot = 0;
    undone.write(ShotUndone { shot: before.shot });
    redraw.write(RequestRedraw);
}

/// Puts every ball back in `target` (its state before a shot) by recorded placements. A ball
/// whose old spot is taken by another not yet moved back waits; when every waiting ball is
/// blocked (two balls swapped places), one of the blockers is first set down on a free spot.
fn restore(rec: &mut Recorder, spec: &TableSpec, target: &[BallState]) -> Result<(), String> {
    let differs = |rec: &Recorder, id: usize| {
        let now = rec.sim().ball(id);
        let want = &target[id];
        want.motion.on_table()
            && (!now.motion.on_table()
                || now.position != want.position
                || now.velocity != want.velocity
                || now.angular_velocity != want.angular_velocity)
    };
    let mut pending: Vec<usize> = (0..target.len()).filter(|&id| differs(rec, id)).collect();
    // Each round places at least one ball for good, or parks one blocker: bounded.
    for _ in 0..4 * target.len() + 4 {
        if pending.is_empty() {
            return Ok(());
        }
        let placed = pending.iter().position(|&id| {
            let want = target[id];
            rec.place(id, want.position, want.velocity, want.angular_velocity)
                .is_ok()
        });
        if let Some(k) = placed {
            pending.remove(k);
            continue;
        }
        // Every waiting ball is blocked by another waiting one: park the first blocker.
        let id = pending[0];
        let r = rec.sim().params().ball.radius;
        let blocker = pending
            .iter()
            .copied()
            .find(|&j| {
                j != id
                    && rec.sim().ball(j).motion.on_table()
                    && (rec.sim().ball(j).position - target[id].position).length() < 2.0 * r
            })
            .ok_or_else(|| format!("ball {id} cannot go back"))?;
        let spot = free_spot(rec.sim(), spec, target).ok_or("no free spot on the table")?;
        rec.place(blocker, spot, physics::Vec2::ZERO, physics::Vec3::ZERO)
            .map_err(|error| error.to_string())?;
    }
    Err("the balls could not all be put back".to_owned())
}

/// A spot on the cloth clear of every ball on the table and of every spot in `target`.
fn free_spot(sim: &Simulation, spec: &TableSpec, target: &[BallState]) -> Option<physics::Vec2> {
    let r = spec.ball_radius;
    let clear = 2.0 * r + 0.005;
    let (hx, hy) = (spec.length / 2.0 - 2.0 * r, spec.width / 2.0 - 2.0 * r);
    let taken: Vec<physics::Vec2> = sim
        .balls()
        .filter(|b| b.motion.on_table())
        .map(|b| b.position)
        .chain(
            target
                .iter()
                .filter(|b| b.motion.on_table())
                .map(|b| b.position),
        )
        .collect();
    let steps = 24;
    (0..=steps)
        .flat_map(|i| (0..=steps / 2).map(move |j| (i, j)))
        .map(|(i, j)| {
            physics::Vec2::new(
                -hx + 2.0 * hx * f64::from(i) / f64::from(steps),
                -hy + 2.0 * hy * f64::from(j) / f64::from(steps / 2),
            )
        })
        .find(|&p| taken.iter().all(|&q| (p - q).length() >= clear))
}
