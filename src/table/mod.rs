//! The table: cloth, cushions, wooden rails, pockets (none on the carom table), diamond
//! sights, legs and the floor; balls in the air and off the table ([`flight`]).

pub mod balls;
pub mod flight;
pub mod geometry;
pub mod mesh;

use bevy::{light::NotShadowCaster, math::DVec3, prelude::*};

use geometry::{CLOTH_HEIGHT, TableKind, TableSpec, to_world};

/// Spawns the table from the [`TableSpec`] resource, and again when another table is chosen.
/// The first spawn is in the first frame's `PostUpdate` (an added resource counts as
/// changed), after a game started at launch has set its table: a snooker match set in that
/// frame would otherwise be drawn on the pool table spawned at startup.
pub fn plugin(app: &mut App) {
    app.add_plugins(flight::plugin);
    app.init_resource::<TableSpec>().add_systems(
        PostUpdate,
        (despawn_table, spawn_table)
            .chain()
            .run_if(resource_changed::<TableSpec>),
    );
}

/// Clears the old table before another is spawned (a new game on another table).
fn despawn_table(mut commands: Commands, parts: Query<Entity, With<TablePart>>) {
    for part in &parts {
        commands.entity(part).despawn();
    }
}

/// Marks every part of the table.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct TablePart;

/// The cloth, whose colour the render test looks for.
pub const CLOTH_COLOUR: Color = Color::srgb(0.05, 0.42, 0.20);
/// The carom table's cloth.
pub const CAROM_CLOTH_COLOUR: Color = Color::srgb(0.06, 0.25, 0.55);

/// How far the apron reaches below the cloth.
const APRON_DEPTH: f64 = 0.18;
/// Depth of the pocket liners below the cloth.
const POCKET_DEPTH: f64 = 0.12;

fn spawn_table(
    mut commands: Commands,
    spec: Res<TableSpec>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    let (cloth_colour, cushion_colour) = match spec.kind {
        TableKind::Pool | TableKind::Snooker => (CLOTH_COLOUR, Color::srgb(0.04, 0.36, 0.17)),
        // The blue cloth of carom match tables.
        TableKind::Carom => (CAROM_CLOTH_COLOUR, Color::srgb(0.04, 0.20, 0.46)),
    };
    let cloth = materials.add(StandardMaterial {
        base_color: cloth_colour,
        perceptual_roughness: 0.95,
        reflectance: 0.2,
        ..default()
    });
    let cushion_cloth = materials.add(StandardMaterial {
        base_color: cushion_colour,
        perceptual_roughness: 0.95,
        reflectance: 0.2,
        ..default()
    });
    let wood = materials.add(StandardMaterial {
        base_color: Color::srgb(0.20, 0.08, 0.03),
        perceptual_roughness: 0.35,
        reflectance: 0.4,
        ..default()
    });
    // Unlit: the inside of a pocket is out of the lamps' light, and lit walls would read as
    // grey shapes on the cloth rather than as holes.
    let liner = materials.add(StandardMaterial {
        base_color: Color::srgb(0.012, 0.012, 0.012),
        unlit: true,
        ..default()
    });
    let pearl = materials.add(StandardMaterial {
        base_color: Color::srgb(0.93, 0.90, 0.82),
        perceptual_roughness: 0.2,
        ..default()
    });

    let mut part = |mesh: Mesh, material: &Handle<StandardMaterial>, name: &'static str| {
        commands
            .spawn((
                TablePart,
                Name::new(name),
                Mesh3d(meshes.add(mesh)),
                MeshMaterial3d(material.clone()),
            ))
            .id()
    };
    part(mesh::cloth(&spec), &cloth, "Cloth");
    part(mesh::cushions(&spec), &cushion_cloth, "Cushions");
    part(mesh::rails(&spec, -APRON_DEPTH), &wood, "Rails");
    // The liners cast shadows: a pocket is a closed bag, and the lamps' light that went
    // through the holes lit pocket-shaped patches on the floor. The carom table has no
    // pockets, and no empty mesh is spawned for them.
    if spec.has_pockets() {
        part(
            mesh::pocket_liners(&spec, POCKET_DEPTH),
            &liner,
            "Pocket liners",
        );
    }

    spawn_diamonds(&mut commands, &spec, &mut meshes, &pearl);
    if spec.is_snooker() {
        spawn_snooker_marks(&mut commands, &spec, &mut meshes, &mut materials);
    }
    spawn_legs_and_floor(&mut commands, &spec, &mut meshes, &mut materials, &wood);
}

/// Diamond sights: small flat rhombi inlaid in the rail tops.
fn spawn_diamonds(
    commands: &mut Commands,
    spec: &TableSpec,
    meshes: &mut Assets<Mesh>,
    pearl: &Handle<StandardMaterial>,
) {
    let diamond = meshes.add(Rhombus::new(0.028, 0.014));
    for (rail, position) in mesh::diamond_positions(spec) {
        use crate::table::geometry::Rail;
        // Lay the 2D rhombus flat, its long diagonal across the rail.
        let across = match rail {
            Rail::Left | Rail::Right => 0.0,
            Rail::Head | Rail::Foot => std::f32::consts::FRAC_PI_2,
        };
        commands.spawn((
            TablePart,
            Name::new("Diamond sight"),
            Mesh3d(diamond.clone()),
            MeshMaterial3d(pearl.clone()),
            NotShadowCaster,
            Transform::from_translation(to_world(position + DVec3::Z * 5e-4)).with_rotation(
                Quat::from_rotation_y(across) * Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2),
            ),
        ));
    }
}

/// A snooker table's chalked lines and spots (WPBSA 1.1: the baulk-line, the D, the spots).
fn spawn_snooker_marks(
    commands: &mut Commands,
    spec: &TableSpec,
    meshes: &mut Assets<Mesh>,
    materials: &mut Assets<StandardMaterial>,
) {
    let chalk = materials.add(StandardMaterial {
        base_color: Color::srgb(0.85, 0.88, 0.85),
        perceptual_roughness: 0.95,
        ..default()
    });
    for (name, mark) in snooker_marks(spec) {
        commands.spawn((
            TablePart,
            Name::new(name),
            Mesh3d(meshes.add(mark)),
            MeshMaterial3d(chalk.clone()),
            NotShadowCaster,
        ));
    }
}

/// Four legs under the corners, and the floor.
fn spawn_legs_and_floor(
    commands: &mut Commands,
    spec: &TableSpec,
    meshes: &mut Assets<Mesh>,
    materials: &mut Assets<StandardMaterial>,
    wood: &Handle<StandardMaterial>,
) {
    let outer = spec.outer_half_extents();
    let leg_height = (CLOTH_HEIGHT - APRON_DEPTH) as f32;
    let leg = meshes.add(Cuboid::new(0.14, leg_height, 0.14));
    for (sx, sy) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
        let at = DVec3::new(
            sx * (outer.x - 0.12),
            sy * (outer.y - 0.12),
            -APRON_DEPTH - f64::from(leg_height) / 2.0,
        );
        commands.spawn((
            TablePart,
            Name::new("Leg"),
            Mesh3d(leg.clone()),
            MeshMaterial3d(wood.clone()),
            Transform::from_translation(to_world(at)),
        ));
    }
    commands.spawn((
        TablePart,
        Name::new("Floor"),
        // Wider than the table, however large (the stress table).
        Mesh3d(meshes.add(Plane3d::default().mesh().size(
            (12.0f64).max(2.0 * outer.x + 4.0) as f32,
            (12.0f64).max(2.0 * outer.y + 4.0) as f32,
        ))),
        MeshMaterial3d(materials.add(StandardMaterial {
            base_color: Color::srgb(0.16, 0.10, 0.08),
            perceptual_roughness: 0.9,
            ..default()
        })),
        Transform::from_xyz(0.0, -CLOTH_HEIGHT as f32, 0.0),
    ));
}

/// Width of the chalked lines of a snooker table.
const LINE_WIDTH: f64 = 0.004;
/// Radius of the spots.
const SPOT_RADIUS: f64 = 0.006;
/// Height of the marks above the cloth (drawn over it, not into it).
const MARK_LIFT: f64 = 4e-4;

/// The marks of the snooker cloth (WPBSA 1.1(d)-(f)): the baulk-line, the D and the six
/// spots, as flat meshes just above the cloth.
fn snooker_marks(spec: &TableSpec) -> Vec<(&'static str, Mesh)> {
    let Ok(marks) = billiards_physics::SnookerMarks::of(&spec.physics_table()) else {
        return Vec::new();
    };
    let at = |p: billiards_physics::Vec2| bevy::math::DVec2::new(p.x, p.y);
    let hy = spec.width / 2.0;
    let baulk = [
        bevy::math::DVec2::new(marks.baulk_x, -hy),
        bevy::math::DVec2::new(marks.baulk_x, hy),
    ];
    let d = geometry::d_outline(&marks, 48);
    let mut out = vec![
        ("Baulk-line", flat_strip(&baulk, LINE_WIDTH)),
        ("The D", flat_strip(&d, LINE_WIDTH)),
    ];
    for spot in [
        marks.yellow,
        marks.green,
        marks.brown,
        marks.blue,
        marks.pink,
        marks.black,
    ] {
        out.push(("Spot", flat_disc(at(spot), SPOT_RADIUS)));
    }
    out
}

/// A flat band of `width` along the polyline `points` (table plane), as a triangle list.
fn flat_strip(points: &[bevy::math::DVec2], width: f64) -> Mesh {
    let mut positions = Vec::new();
    for (k, &p) in points.iter().enumerate() {
        let prev = points[k.saturating_sub(1)];
        let next = points[(k + 1).min(points.len() - 1)];
        let side = (next - prev).normalize_or_zero().perp() * (width / 2.0);
        for q in [p + side, p - side] {
            positions.push(to_world(q.extend(MARK_LIFT)).to_array());
        }
    }
    let mut indices = Vec::new();
    for k in 0..points.len().saturating_sub(1) as u32 {
        let (a, b, c, d) = (2 * k, 2 * k + 1, 2 * k + 2, 2 * k + 3);
        // Both windings: the band is seen from above whichever way the polyline runs.
        indices.extend([a, b, c, b, d, c, a, c, b, b, c, d]);
    }
    flat_mesh(positions, indices)
}

/// A flat disc of `radius` at `centre` (table plane).
fn flat_disc(centre: bevy::math::DVec2, radius: f64) -> Mesh {
    let mut positions = vec![to_world(centre.extend(MARK_LIFT)).to_array()];
    let mut indices = Vec::new();
    for k in 0..24u32 {
        let a = std::f64::consts::TAU * f64::from(k) / 24.0;
        let p = centre + radius * bevy::math::DVec2::from_angle(a);
        positions.push(to_world(p.extend(MARK_LIFT)).to_array());
        let (b, c) = (1 + k, 1 + (k + 1) % 24);
        indices.extend([0, b, c, 0, c, b]);
    }
    flat_mesh(positions, indices)
}

fn flat_mesh(positions: Vec<[f32; 3]>, indices: Vec<u32>) -> Mesh {
    let normals = vec![[0.0, 1.0, 0.0]; positions.len()];
    Mesh::new(
        bevy::mesh::PrimitiveTopology::TriangleList,
        bevy::asset::RenderAssetUsages::default(),
    )
    .with_inserted_attribute(Mesh::ATTRIBUTE_POSITION, positions)
    .with_inserted_attribute(Mesh::ATTRIBUTE_NORMAL, normals)
    .with_inserted_indices(bevy::mesh::Indices::U32(indices))
}
