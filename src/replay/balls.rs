//! The entities that show a recording: one [`ReplayBall`] per recorded ball, spawned when a
//! recording opens, written from the recording's history every frame, despawned on close.

use bevy::prelude::*;
use billiards_physics::{BallState, Motion};

use super::open::OpenRecording;
use crate::{
    sim::ball_motion,
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
};

/// Marks the entities that show a recorded ball (despawned when the replay closes).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReplayBall;

/// Spawns one [`ReplayBall`] per ball of `open`, at its state at time 0; returns them by
/// recorded ball index.
pub fn spawn_replay_balls(world: &mut World, open: &OpenRecording) -> Vec<Entity> {
    let spec = world.resource::<TableSpec>().clone();
    (0..open.history.ball_count())
        .map(|id| {
            let number = open.number(id);
            let state = open.history.state_at(id, 0.0);
            let motion = ball_motion(&state);
            let mut ball = world.spawn((
                Ball { id, number },
                motion,
                Transform::from_translation(spec.ball_world_position(motion.position)),
                Name::new(format!("Replay ball {number}")),
                ReplayBall,
            ));
            if let Motion::Pocketed(pocket) = state.motion {
                ball.insert((Pocketed { pocket }, Visibility::Hidden));
            }
            ball.id()
        })
        .collect()
}

/// Despawns the entities that still exist.
pub fn despawn_all(world: &mut World, entities: &[Entity]) {
    for &entity in entities {
        if let Ok(entity) = world.get_entity_mut(entity) {
            entity.despawn();
        }
    }
}

/// Writes a solver state to a ball's components: [`BallMotion`] only when it differs (so
/// balls at rest are not redrawn) and [`Pocketed`] as the state says.
pub fn show_state(world: &mut World, entity: Entity, state: &BallState) {
    let Ok(mut ball) = world.get_entity_mut(entity) else {
        return;
    };
    let pocket = match state.motion {
        Motion::Pocketed(pocket) => Some(pocket),
        _ => None,
    };
    let was_pocketed = ball.contains::<Pocketed>();
    if let Some(mut motion) = ball.get_mut::<BallMotion>()
        && !motion.set_if_neq(ball_motion(state))
        && was_pocketed
        && pocket.is_none()
    {
        // Back from a pocket where it dropped: drawn at its place again.
        motion.set_changed();
    }
    match (pocket, was_pocketed) {
        (Some(pocket), false) => {
            ball.insert(Pocketed { pocket });
        }
        (None, true) => {
            ball.remove::<Pocketed>();
        }
        _ => {}
    }
}
