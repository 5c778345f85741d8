//! Lighting: two lamps over the table, as in a pool hall, with shadows, plus a dim ambient.

use bevy::prelude::*;

/// Spawns the lights.
pub fn plugin(app: &mut App) {
    app.insert_resource(ClearColor(Color::srgb(0.03, 0.03, 0.035)))
        .insert_resource(GlobalAmbientLight {
            color: Color::srgb(1.0, 0.95, 0.88),
            brightness: 250.0,
            ..default()
        })
        .add_systems(Startup, spawn_lamps)
        .add_systems(
            Update,
            follow_table.run_if(resource_changed::<crate::table::geometry::TableSpec>),
        );
}

/// One of the lamps, at `x` over a regulation table.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
struct Lamp {
    x: f32,
}

/// Light of one lamp (candela-like units of Bevy's spot light) over a regulation table.
const LAMP_INTENSITY: f32 = 200_000.0;
/// How far a lamp's light reaches over a regulation table.
const LAMP_RANGE: f32 = 4.0;

/// A larger table (the stress table) is lit all over: the lamps rise and spread with its size
/// ([`crate::table::geometry::TableSpec::reach`]), brighter by its square so the cloth under
/// them looks the same.
fn follow_table(
    spec: Res<crate::table::geometry::TableSpec>,
    mut lamps: Query<(&Lamp, &mut SpotLight, &mut Transform)>,
) {
    let k = spec.reach();
    for (lamp, mut light, mut transform) in &mut lamps {
        let x = lamp.x * k;
        *transform = Transform::from_xyz(x, LAMP_HEIGHT * k, 0.0)
            .looking_at(Vec3::new(x, 0.0, 0.0), Vec3::X);
        light.range = LAMP_RANGE * k;
        light.intensity = LAMP_INTENSITY * k * k;
    }
}

/// Height of the lamps above the cloth.
const LAMP_HEIGHT: f32 = 1.1;

fn spawn_lamps(mut commands: Commands) {
    // Two lamps over the length of the table: the balls get a highlight from above and
    // shadows straight under them, so they read as spheres from any side.
    for x in [-0.55, 0.55] {
        commands.spawn((
            Name::new("Lamp"),
            Lamp { x },
            SpotLight {
                color: Color::srgb(1.0, 0.96, 0.88),
                intensity: LAMP_INTENSITY,
                range: LAMP_RANGE,
                radius: 0.05,
                shadow_maps_enabled: true,
                outer_angle: 1.05,
                inner_angle: 0.6,
                ..default()
            },
            Transform::from_xyz(x, LAMP_HEIGHT, 0.0).looking_at(Vec3::new(x, 0.0, 0.0), Vec3::X),
        ));
    }
}
