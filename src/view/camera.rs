//! The camera: orbit and zoom with the mouse, a top view, and following the cue ball.
//!
//! Input changes the [`OrbitCamera`] target; the camera eases toward it in real time, so
//! it keeps moving smoothly while the simulation is paused.

use std::f32::consts::FRAC_PI_2;

use crate::{
    input::InputSystems,
    table::balls::{Ball, Pocketed},
    table::geometry::TableSpec,
};
use bevy::{
    input::mouse::{AccumulatedMouseMotion, AccumulatedMouseScroll, MouseScrollUnit},
    prelude::*,
    window::RequestRedraw,
};

/// Registers the camera and its controls.
pub fn plugin(app: &mut App) {
    app.init_resource::<OrbitCamera>()
        .add_systems(Startup, spawn_camera)
        .add_systems(
            Update,
            (
                orbit_and_zoom.in_set(InputSystems::Pointer),
                camera_keys.in_set(InputSystems::Keyboard),
                frame_table.run_if(resource_changed::<TableSpec>),
                follow_cue_ball,
                ease_camera,
            )
                .chain()
                .in_set(CameraSystems),
        );
}

/// The camera systems, for ordering against them.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct CameraSystems;

/// Marks the camera that renders the table.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct TableCamera;

/// What the camera looks at.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CameraMode {
    /// Orbit around a fixed point on the table.
    #[default]
    Free,
    /// Straight down at the whole table, head rail on the left.
    Top,
    /// Orbit around the cue ball, following it.
    FollowCue,
}

/// Where the camera should be: an orbit around `focus`.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct OrbitCamera {
    /// The point the camera looks at and orbits around (Bevy world coordinates).
    pub focus: Vec3,
    /// Rotation about the vertical, radians; 0 looks along -Z (toward physics +y).
    pub yaw: f32,
    /// Elevation, radians; negative looks down.
    pub pitch: f32,
    /// Distance from the focus, metres.
    pub distance: f32,
    /// Free orbit, top view or following the cue ball.
    pub mode: CameraMode,
    /// The table's size against the 8-ft table's ([`TableSpec::reach`]): the views and the
    /// zoom limit scale by it.
    pub reach: f32,
}

impl Default for OrbitCamera {
    fn default() -> Self {
        // Standing behind the head rail, a little to the right, looking up the table.
        Self {
            focus: Vec3::new(0.1, 0.0, 0.0),
            yaw: -1.25,
            pitch: -0.66,
            // Far enough that the near rail shows below the HUD strip, a 9-ft table too.
            distance: 3.45,
            mode: CameraMode::Free,
            reach: 1.0,
        }
    }
}

impl OrbitCamera {
    /// Pitch limits: never quite straight down (the view would flip) nor below the cloth.
    const PITCH_MIN: f32 = -FRAC_PI_2 + 0.001;
    const PITCH_MAX: f32 = -0.05;
    const DISTANCE_MIN: f32 = 0.3;
    const DISTANCE_MAX: f32 = 8.0;

    /// The top view of the whole table.
    pub fn top_view() -> Self {
        Self {
            focus: Vec3::ZERO,
            yaw: 0.0,
            pitch: Self::PITCH_MIN,
            distance: 3.5,
            mode: CameraMode::Top,
            reach: 1.0,
        }
    }

    /// This view for a table `reach` times the 8-ft table: as far again, the focus too.
    pub fn scaled(self, reach: f32) -> Self {
        Self {
            focus: self.focus * reach,
            distance: self.distance * reach,
            reach,
            ..self
        }
    }

    /// The camera transform this orbit describes.
    pub fn transform(&self) -> Transform {
        let rotation = Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0);
        let translation = self.focus - rotation * Vec3::NEG_Z * self.distance;
        Transform::from_translation(translation).with_rotation(rotation)
    }
}

fn spawn_camera(mut commands: Commands, orbit: Res<OrbitCamera>) {
    commands.spawn((
        TableCamera,
        Name::new("Table camera"),
        Camera3d::default(),
        Projection::Perspective(PerspectiveProjection {
            fov: 40f32.to_radians(),
            near: 0.02,
            ..default()
        }),
        orbit.transform(),
    ));
}

/// Right or middle drag orbits, the wheel zooms (Shift + wheel is the cue's power).
fn orbit_and_zoom(
    buttons: Res<ButtonInput<MouseButton>>,
    keys: Res<ButtonInput<KeyCode>>,
    motion: Res<AccumulatedMouseMotion>,
    scroll: Res<AccumulatedMouseScroll>,
    mut orbit: ResMut<OrbitCamera>,
) {
    const RADIANS_PER_PIXEL: f32 = 0.005;
    let dragging = buttons.pressed(MouseButton::Right) || buttons.pressed(MouseButton::Middle);
    if dragging && motion.delta != Vec2::ZERO {
        if orbit.mode == CameraMode::Top {
            orbit.mode = CameraMode::Free;
        }
        orbit.yaw -= motion.delta.x * RADIANS_PER_PIXEL;
        orbit.pitch = (orbit.pitch - motion.delta.y * RADIANS_PER_PIXEL)
            .clamp(OrbitCamera::PITCH_MIN, OrbitCamera::PITCH_MAX);
    }
    let shift = keys.any_pressed([KeyCode::ShiftLeft, KeyCode::ShiftRight]);
    if !shift && scroll.delta.y != 0.0 {
        let lines = match scroll.unit {
            MouseScrollUnit::Line => scroll.delta.y,
            // Touchpads report pixels; about 40 make one wheel notch.
            MouseScrollUnit::Pixel => scroll.delta.y / 40.0,
        };
        orbit.distance = (orbit.distance * (-0.12 * lines).exp()).clamp(
            OrbitCamera::DISTANCE_MIN,
            OrbitCamera::DISTANCE_MAX * orbit.reach,
        );
    }
}

/// T toggles the top view, F toggles following the cue ball, Home resets the view.
fn camera_keys(keys: Res<ButtonInput<KeyCode>>, mut orbit: ResMut<OrbitCamera>) {
    let reach = orbit.reach;
    if keys.just_pressed(KeyCode::KeyT) {
        *orbit = if orbit.mode == CameraMode::Top {
            OrbitCamera::default().scaled(reach)
        } else {
            OrbitCamera::top_view().scaled(reach)
        };
    }
    if keys.just_pressed(KeyCode::KeyF) {
        orbit.mode = if orbit.mode == CameraMode::FollowCue {
            OrbitCamera::default().mode
        } else {
            CameraMode::FollowCue
        };
        if orbit.mode == CameraMode::Free {
            orbit.focus = OrbitCamera::default().scaled(reach).focus;
        }
    }
    if keys.just_pressed(KeyCode::Home) {
        *orbit = OrbitCamera::default().scaled(reach);
    }
}

/// Another table: a larger one (the stress table) is framed whole from above, and back on a
/// regulation table the usual view returns.
fn frame_table(spec: Res<TableSpec>, mut orbit: ResMut<OrbitCamera>) {
    let reach = spec.reach();
    if reach == orbit.reach {
        return;
    }
    *orbit = if reach > 1.0 {
        OrbitCamera::top_view().scaled(reach)
    } else {
        OrbitCamera::default()
    };
}

fn follow_cue_ball(
    mut orbit: ResMut<OrbitCamera>,
    balls: Query<(&Ball, &Transform), Without<Pocketed>>,
    solver: Option<Res<crate::sim::Solver>>,
) {
    if orbit.mode != CameraMode::FollowCue {
        return;
    }
    // The ball the next stroke strikes (three-cushion: the white or the yellow).
    let cue = solver.map_or(0, |s| s.cue_number());
    if let Some((_, transform)) = balls.iter().find(|(ball, _)| ball.number == cue) {
        let focus = transform.translation.with_y(0.0);
        if orbit.focus != focus {
            orbit.focus = focus;
        }
    }
}

/// Eases the camera toward its orbit target, asking for more frames until it arrives (the
/// window only redraws on demand when nothing moves).
fn ease_camera(
    time: Res<Time<Real>>,
    orbit: Res<OrbitCamera>,
    mut camera: Single<&mut Transform, With<TableCamera>>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    let target = orbit.transform();
    // Exponential approach: frame-rate independent, about 95 % of the way in 0.25 s.
    let blend = 1.0 - (-12.0 * time.delta_secs()).exp();
    // Quaternion components, not `angle_between`: its f32 acos cannot resolve angles under
    // about 7e-4 rad, so a 1e-4 rad test never passed and the camera asked for frames forever.
    let (q, t) = (camera.rotation, target.rotation);
    let same_turn = q.abs_diff_eq(t, 1e-5) || q.abs_diff_eq(-t, 1e-5);
    let close = camera.translation.distance(target.translation) < 1e-4 && same_turn;
    if close {
        if **camera != target {
            **camera = target;
        }
        return;
    }
    camera.translation = camera.translation.lerp(target.translation, blend);
    camera.rotation = camera.rotation.slerp(target.rotation, blend);
    redraw.write(RequestRedraw);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orbit_looks_at_its_focus() {
        let orbit = OrbitCamera::default();
        let transform = orbit.transform();
        let to_focus = (orbit.focus - transform.translation).normalize();
        assert!(transform.forward().dot(to_focus) > 0.9999);
        assert!((transform.translation.distance(orbit.focus) - orbit.distance).abs() < 1e-5);
        // It stands above the table, at the head end (-x).
        assert!(transform.translation.y > 0.5);
        assert!(transform.translation.x < 0.0);
    }

    #[test]
    fn top_view_looks_down_with_the_head_rail_on_the_left() {
        let transform = OrbitCamera::top_view().transform();
        assert!(transform.forward().dot(Vec3::NEG_Y) > 0.999);
        assert!(transform.right().dot(Vec3::X) > 0.999);
    }
}
