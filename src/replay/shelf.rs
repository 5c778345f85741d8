//! The live game put aside while a recording is shown: on entering [`GameMode::Replay`] the
//! live balls are hidden and lose their [`Ball`] component (so every system that works on balls
//! sees the recorded ones only); on leaving it they get both back, with their transforms, and
//! are re-synced from the live solver, which waited untouched.

use bevy::{prelude::*, window::RequestRedraw};

use super::balls::{ReplayBall, show_state};
use crate::{
    mode::GameMode,
    sim::Solver,
    table::balls::{Ball, Pocketed},
};

/// Shelves the live game on entering a replay and restores it on leaving.
pub fn plugin(app: &mut App) {
    app.init_resource::<Shelf>()
        .add_systems(OnEnter(GameMode::Replay), shelve_live_balls)
        .add_systems(OnExit(GameMode::Replay), restore_live_balls)
        .add_systems(
            PostUpdate,
            restore_transforms.before(TransformSystems::Propagate),
        );
}

/// The live balls put aside while a recording is shown.
#[derive(Resource, Debug, Default)]
pub struct Shelf(Vec<ShelvedBall>);

/// A live ball put aside while a recording is shown.
#[derive(Debug, Clone, Copy)]
struct ShelvedBall {
    entity: Entity,
    ball: Ball,
    visibility: Visibility,
    transform: Transform,
}

/// Hides the live balls and takes their [`Ball`] component away.
fn shelve_live_balls(world: &mut World) {
    let live: Vec<ShelvedBall> = world
        .query_filtered::<(Entity, &Ball, &Visibility, &Transform), Without<ReplayBall>>()
        .iter(world)
        .map(|(entity, &ball, &visibility, &transform)| ShelvedBall {
            entity,
            ball,
            visibility,
            transform,
        })
        .collect();
    for shelved in &live {
        world
            .entity_mut(shelved.entity)
            .remove::<Ball>()
            .insert(Visibility::Hidden);
    }
    world.resource_mut::<Shelf>().0 = live;
}

/// Back to the live game, exactly as it was left.
fn restore_live_balls(world: &mut World) {
    let shelf = std::mem::take(&mut world.resource_mut::<Shelf>().0);
    for shelved in shelf {
        let Ok(mut entity) = world.get_entity_mut(shelved.entity) else {
            continue;
        };
        let visibility = if entity.contains::<Pocketed>() {
            Visibility::Hidden
        } else {
            shelved.visibility
        };
        // The ball's look is attached anew (`Added<Ball>`), which turns it number-up; its
        // rotation is put back after that, in `PostUpdate`.
        entity.insert((
            shelved.ball,
            visibility,
            shelved.transform,
            RestoreTransform(shelved.transform),
        ));
    }
    // The live balls were not touched; re-sync them from the solver all the same.
    if world.contains_resource::<Solver>() {
        world.resource_scope(|world, solver: Mut<Solver>| {
            for id in 0..solver.simulation().ball_count() {
                if let Some(entity) = solver.entity(id) {
                    show_state(world, entity, &solver.simulation().ball(id));
                }
            }
        });
    }
    world.write_message(RequestRedraw);
}

/// The transform a live ball had when it was shelved, put back after its look was attached.
#[derive(Component, Debug, Clone, Copy)]
struct RestoreTransform(Transform);

fn restore_transforms(
    mut commands: Commands,
    mut balls: Query<(Entity, &RestoreTransform, &mut Transform)>,
) {
    for (entity, restore, mut transform) in &mut balls {
        *transform = restore.0;
        commands.entity(entity).remove::<RestoreTransform>();
    }
}
