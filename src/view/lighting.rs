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
        .add_systems(Startup, spawn_lamps);
}

/// Height of the lamps above the cloth.
const LAMP_HEIGHT: f32 = 1.1;

fn spawn_lamps(mut commands: Commands) {
    // Two lamps over the length of the table: the balls get a highlight from above and
    // shadows straight under them, so they read as spheres from any side.
    for x in [-0.55, 0.55] {
        commands.spawn((
            Name::new("Lamp"),
            SpotLight {
                color: Color::srgb(1.0, 0.96, 0.88),
                intensity: 200_000.0,
                range: 4.0,
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
