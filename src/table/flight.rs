//! Balls in the air and off the table, drawn (issue 52): a ball in flight is drawn at its
//! height by [`super::balls`]; here its shadow on the cloth (a dark disc under it, smaller and
//! fainter the higher it flies, so the height reads from any camera), and a ball driven off
//! the table falling to the floor beyond the rail it crossed, where it stays until it is put
//! back or the table is set again.

use std::collections::HashMap;

use bevy::{light::NotShadowCaster, math::DVec2, prelude::*};

use super::balls::{Ball, BallMotion, MotionState};
use super::geometry::{CLOTH_HEIGHT, TableSpec, to_world};

/// Adds the shadows of balls in the air and the fall of balls off the table.
pub fn plugin(app: &mut App) {
    app.add_systems(Startup, create_shadow_assets).add_systems(
        PostUpdate,
        (follow_shadows, start_floor_drops, animate_floor_drops)
            .before(TransformSystems::Propagate),
    );
}

/// The shadow's mesh (a unit disc); each shadow has a material of its own
/// ([`shadow_material`]), as each fades with its own ball's height.
#[derive(Resource, Debug, Clone)]
struct ShadowAssets {
    mesh: Handle<Mesh>,
}

/// The shadow's opacity under a ball on the cloth.
const SHADOW_ALPHA: f32 = 0.45;

/// A shadow's material: black, unlit, [`SHADOW_ALPHA`] opaque until its ball rises.
fn shadow_material() -> StandardMaterial {
    StandardMaterial {
        base_color: Color::srgba(0.0, 0.0, 0.0, SHADOW_ALPHA),
        alpha_mode: AlphaMode::Blend,
        unlit: true,
        ..default()
    }
}

/// The shadow of the ball it names.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
struct FlightShadow;

/// Below this height a ball reads as on the cloth: no shadow is drawn (the resting hop of
/// touching balls is 1e-7 m).
const SHADOW_MIN_HEIGHT: f64 = 1e-3;

fn create_shadow_assets(mut commands: Commands, mut meshes: ResMut<Assets<Mesh>>) {
    commands.insert_resource(ShadowAssets {
        mesh: meshes.add(Circle::new(1.0)),
    });
}

/// The shadow's radius and opacity for a ball of radius `r` whose centre is `h` above its
/// resting height: the ball's own size on the cloth, shrinking to half and fading to a third
/// at a height of 4 radii (a soft light from above).
pub fn shadow_size(r: f64, h: f64) -> (f64, f64) {
    let k = (h / (4.0 * r)).clamp(0.0, 1.0);
    (r * (1.0 - 0.5 * k), 1.0 - 2.0 / 3.0 * k)
}

/// Balls whose motion changed.
type MovedBall = (With<Ball>, Changed<BallMotion>);

/// A shadow's place, look and material.
type ShadowParts<'a> = (
    &'a mut Transform,
    &'a mut Visibility,
    &'a MeshMaterial3d<StandardMaterial>,
);

/// Puts a shadow under every ball in the air (spawned on first need), sized and faded by its
/// height, and hides it once the ball is down, for the balls whose motion changed; despawns
/// the shadows of balls gone.
fn follow_shadows(
    mut commands: Commands,
    (assets, mut materials): (Option<Res<ShadowAssets>>, ResMut<Assets<StandardMaterial>>),
    spec: Res<TableSpec>,
    balls: Query<(Entity, &BallMotion), MovedBall>,
    mut gone: RemovedComponents<Ball>,
    mut shadows: Query<ShadowParts, With<FlightShadow>>,
    mut of_ball: Local<HashMap<Entity, Entity>>,
) {
    let Some(assets) = assets else { return };
    for ball in gone.read() {
        if let Some(shadow) = of_ball.remove(&ball) {
            commands.entity(shadow).try_despawn();
        }
    }
    let flat = Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2);
    for (ball, motion) in &balls {
        let flying = motion.state == MotionState::Airborne && motion.height > SHADOW_MIN_HEIGHT;
        let Some(&shadow) = of_ball.get(&ball) else {
            if flying {
                let shadow = commands
                    .spawn((
                        FlightShadow,
                        Name::new("Flight shadow"),
                        Mesh3d(assets.mesh.clone()),
                        MeshMaterial3d(materials.add(shadow_material())),
                        NotShadowCaster,
                        Transform::from_translation(Vec3::splat(1e4)),
                        Visibility::Hidden,
                    ))
                    .id();
                of_ball.insert(ball, shadow);
            }
            continue;
        };
        let Ok((mut transform, mut visibility, material)) = shadows.get_mut(shadow) else {
            continue;
        };
        let wanted = if flying {
            Visibility::Inherited
        } else {
            Visibility::Hidden
        };
        visibility.set_if_neq(wanted);
        if flying {
            let (radius, opacity) = shadow_size(spec.ball_radius, motion.height);
            // Just above the cloth, below the aiming aid's lines (2 mm).
            transform.translation = to_world(motion.position.extend(0.001));
            transform.rotation = flat;
            transform.scale = Vec3::splat(radius as f32);
            if let Some(mut m) = materials.get_mut(&material.0) {
                m.base_color.set_alpha(SHADOW_ALPHA * opacity as f32);
            }
        }
    }
}

/// A ball off the table falling to the floor: from where it left to `to`, over
/// [`FALL_SECONDS`].
#[derive(Component, Debug, Clone, Copy, PartialEq)]
struct FloorDrop {
    from: Vec3,
    to: Vec3,
    elapsed: f32,
}

/// How long the fall to the floor is drawn (a drop of 0.78 m takes 0.4 s).
const FALL_SECONDS: f32 = 0.4;

/// Where a ball that left the table at `at` (table plane, metres) lands on the floor: a
/// ball's width beyond the outer edge of the rail nearest to it, on the floor.
pub fn floor_spot(spec: &TableSpec, at: DVec2) -> Vec3 {
    let outer = spec.outer_half_extents();
    let beyond = spec.ball_radius * 3.0;
    let over_x = at.x.abs() / outer.x;
    let over_y = at.y.abs() / outer.y;
    let spot = if over_x >= over_y {
        DVec2::new(
            at.x.signum() * (outer.x + beyond),
            at.y.clamp(-outer.y, outer.y),
        )
    } else {
        DVec2::new(
            at.x.clamp(-outer.x, outer.x),
            at.y.signum() * (outer.y + beyond),
        )
    };
    // The floor is CLOTH_HEIGHT below the cloth; the ball's centre a radius above it.
    to_world(spot.extend(spec.ball_radius - CLOTH_HEIGHT))
}

/// A ball that has just gone off the table starts its fall; one back in play (put back by
/// the rules, a new layout) stops falling.
fn start_floor_drops(
    mut commands: Commands,
    spec: Res<TableSpec>,
    balls: Query<(Entity, &BallMotion, &Transform, Has<FloorDrop>), Changed<BallMotion>>,
) {
    for (entity, motion, transform, falling) in &balls {
        match (motion.state == MotionState::OffTable, falling) {
            (true, false) => {
                commands.entity(entity).insert(FloorDrop {
                    from: transform.translation,
                    to: floor_spot(&spec, motion.position),
                    elapsed: 0.0,
                });
            }
            (false, true) => {
                commands.entity(entity).remove::<FloorDrop>();
            }
            _ => {}
        }
    }
}

/// Moves falling balls over the rail and down to the floor (a quarter of the time over the
/// rail's top, then the fall), on virtual time so the fall pauses with the game.
fn animate_floor_drops(
    mut commands: Commands,
    time: Res<Time>,
    mut balls: Query<(Entity, &mut FloorDrop, &mut Transform)>,
    mut redraw: MessageWriter<bevy::window::RequestRedraw>,
) {
    for (entity, mut drop, mut transform) in &mut balls {
        drop.elapsed = (drop.elapsed + time.delta_secs()).min(FALL_SECONDS);
        let t = drop.elapsed / FALL_SECONDS;
        // Out over the floor spot at its height, then down.
        let over = Vec3::new(drop.to.x, drop.from.y, drop.to.z);
        transform.translation = if t < 0.25 {
            drop.from.lerp(over, t * 4.0)
        } else {
            let fall = (t - 0.25) / 0.75;
            over.lerp(drop.to, fall * fall)
        };
        if t < 1.0 {
            redraw.write(bevy::window::RequestRedraw);
        } else {
            // On the floor: it lies there until its state changes.
            commands.entity(entity).remove::<FloorDrop>();
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::table::flight::{floor_spot, shadow_size};
    use crate::table::geometry::{TableSpec, to_world};
    use bevy::math::DVec2;

    /// The shadow is the ball's own size on the cloth and shrinks and fades with height,
    /// to half the radius and a third of the opacity at 4 radii and no further.
    #[test]
    fn the_shadow_shrinks_and_fades_with_height() {
        let r = 0.028575;
        assert_eq!(shadow_size(r, 0.0), (r, 1.0));
        let (low, low_alpha) = shadow_size(r, r);
        let (high, high_alpha) = shadow_size(r, 4.0 * r);
        assert!(low < r && high < low && low_alpha > high_alpha);
        assert!((high - r / 2.0).abs() < 1e-15 && (high_alpha - 1.0 / 3.0).abs() < 1e-15);
        assert_eq!(shadow_size(r, 40.0 * r), shadow_size(r, 4.0 * r));
    }

    /// A ball off the table lands on the floor beyond the rail it crossed: past the outer
    /// edge on that side, within the table's span along it, a radius above the floor.
    #[test]
    fn a_ball_off_the_table_lands_beyond_the_rail_it_crossed() {
        let spec = TableSpec::default();
        let outer = spec.outer_half_extents();
        let floor_y = (spec.ball_radius - crate::table::geometry::CLOTH_HEIGHT) as f32;
        // Over the foot rail (+x), near a side.
        let spot = floor_spot(&spec, DVec2::new(outer.x - 0.01, 0.2));
        let edge = to_world(DVec2::new(outer.x, 0.2).extend(0.0));
        assert!(spot.x > edge.x, "{spot} beyond {edge}");
        assert!((spot.y - floor_y).abs() < 1e-6);
        // Over a long rail (-y).
        let spot = floor_spot(&spec, DVec2::new(0.3, -outer.y + 0.01));
        let side = to_world(DVec2::new(0.3, -outer.y).extend(0.0));
        assert!((spot - side).length() > 0.05 && (spot.x - side.x).abs() < 1e-6);
    }
}
