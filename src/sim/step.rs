//! The solver step: the frame's virtual time, the writeback, the event messages.

use std::{ops::Range, time::Instant};

use bevy::{prelude::*, window::RequestRedraw};
use billiards_physics::{EventKind, Motion};

use super::{messages::*, solver::*};
use crate::{
    settings::PhysicsSettings,
    table::balls::{BallMotion, Pocketed},
};

/// The largest real time one frame may advance the game by, seconds. Bevy's default (0.25 s)
/// made a machine drawing a frame every 1-2 s run the game 4-8 times slower than real time (a
/// break took a minute); the solver is exact for any step, so simulated time now follows real
/// time through such frames. A longer stall (the process stopped) still resumes where it was.
pub const MAX_FRAME_STEP: f64 = 3.0;

/// Lets the virtual clock follow real time through slow frames ([`MAX_FRAME_STEP`]).
pub(super) fn allow_slow_frames(mut time: ResMut<Time<Virtual>>) {
    time.set_max_delta(std::time::Duration::from_secs_f64(MAX_FRAME_STEP));
}

/// Applies the pause and time-scale settings to the virtual clock the solver advances by.
pub(super) fn apply_clock_settings(
    settings: Res<PhysicsSettings>,
    mut time: ResMut<Time<Virtual>>,
) {
    if !settings.is_changed() {
        return;
    }
    time.set_relative_speed_f64(settings.time_scale);
    if settings.paused {
        time.pause();
    } else {
        time.unpause();
    }
}

pub(super) fn request_default_rack(mut racks: MessageWriter<RackRequested>) {
    racks.write(RackRequested::standard(STARTING_RACK));
}

/// The solver step (see the module docs). Exclusive: it needs the solver, the ball
/// components and the message queues at once, and nothing else may run beside it anyway.
pub(super) fn advance_solver(world: &mut World) {
    let step_requested = world
        .resource_mut::<Messages<StepRequested>>()
        .drain()
        .count()
        > 0;
    if !world.contains_resource::<Solver>() {
        return;
    }
    let dt = world.resource::<Time>().delta_secs_f64();
    let paused = world.resource::<Time<Virtual>>().is_paused();
    world.resource_scope(|world, mut solver: Mut<Solver>| {
        if solver.simulation().is_at_rest() {
            return;
        }
        let started = Instant::now();
        let outcome: Result<Range<usize>, String> = if paused {
            if !step_requested {
                return;
            }
            let before = solver.simulation().history().events().len();
            solver.rec.step_event();
            Ok(before..solver.simulation().history().events().len())
        } else if dt > 0.0 {
            solver
                .rec
                .advance(dt)
                .map(|advance| advance.events)
                .map_err(|error| error.to_string())
        } else {
            return;
        };
        let cost = started.elapsed().as_secs_f64();
        write_back(world, &solver);
        let events = match outcome {
            Ok(range) => range,
            Err(error) => {
                // The solver's state is valid where it stopped; show why it stopped.
                world.resource_mut::<SimStatus>().note = Some(format!("solver: {error}"));
                0..0
            }
        };
        send_event_messages(world, &solver, events.clone());
        let at_rest = solver.simulation().is_at_rest();
        {
            let mut status = world.resource_mut::<SimStatus>();
            status.at_rest = at_rest;
            // The game's time: Undo takes back the time of the shots it undoes.
            status.sim_time = solver.game_time();
            status.events_this_shot += events.len();
            status.solver_seconds_last_frame = cost;
        }
        if let Some(mut shown) = world.get_resource_mut::<crate::table::balls::ShownTime>() {
            shown.0 = solver.simulation().time();
        }
        if at_rest {
            let scratch = solver
                .cue_ball()
                .is_some_and(|id| !solver.simulation().ball(id).motion.on_table());
            world.write_message(ShotFinished { scratch });
        } else {
            // The window only redraws on demand; moving balls demand it.
            world.write_message(RequestRedraw);
        }
    });
}

/// Copies changed solver states to the ball components (`set_if_neq`: a ball at rest is not
/// touched, so change detection downstream sees only what moved).
fn write_back(world: &mut World, solver: &Solver) {
    for (id, &entity) in solver.entities.iter().enumerate() {
        let state = solver.simulation().ball(id);
        let Ok(mut ball) = world.get_entity_mut(entity) else {
            continue;
        };
        if let Some(mut motion) = ball.get_mut::<BallMotion>() {
            motion.set_if_neq(ball_motion(&state));
        }
        if let Motion::Pocketed(pocket) = state.motion
            && !ball.contains::<Pocketed>()
        {
            ball.insert(Pocketed { pocket });
        }
    }
}

fn send_event_messages(world: &mut World, solver: &Solver, events: Range<usize>) {
    let entity = |id: usize| solver.entities[id];
    for event in &solver.simulation().history().events()[events] {
        let time = event.time;
        match event.kind {
            EventKind::BallBall { a, b } => {
                world.write_message(BallContact {
                    a: entity(a),
                    b: entity(b),
                    speed: (event.after[0].velocity - event.after[1].velocity).length(),
                    time,
                });
            }
            EventKind::Cushion { ball, cushion } => {
                world.write_message(CushionHit {
                    ball: entity(ball),
                    part: CushionPart::Cushion(cushion),
                    speed: event.after[0].velocity.length(),
                    time,
                });
            }
            EventKind::Jaw { ball, pocket } => {
                world.write_message(CushionHit {
                    ball: entity(ball),
                    part: CushionPart::Jaw(pocket),
                    speed: event.after[0].velocity.length(),
                    time,
                });
            }
            EventKind::Strike { ball, shot } => {
                world.write_message(CueStruck {
                    ball: entity(ball),
                    speed: shot.speed,
                    time,
                });
            }
            EventKind::Pocketed { ball, pocket } => {
                world.write_message(BallPocketed {
                    ball: entity(ball),
                    number: solver.simulation().numbers()[ball],
                    pocket,
                    time,
                });
            }
            EventKind::Placed { .. } | EventKind::ParamsChanged | EventKind::Transition { .. } => {}
        }
    }
}
