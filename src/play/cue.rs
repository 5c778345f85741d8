//! The cue: aiming and power input, the cue stick mesh, the shot key and the paper's vectors.
//!
//! Controls (also listed in the panel):
//! - left drag on the table: aim the cue ball at the pointer;
//! - Shift + left drag down / Shift + wheel: pull the cue back (power);
//! - Left/Right arrows: turn the aim (hold Shift for fine steps); Up/Down: power;
//! - Space: shoot.

use crate::{
    input::{InputSystems, aim_unlocked, held_or_clicked},
    mode::GameMode,
    play::key_repeat::HeldKeys,
    settings::{ClampReport, ShotSettings, ViewSettings, apply_shot_edit},
    sim::{Referee, ShotRequested, ShotUndone, SimStatus, SimSystems, Solver, place_ball_in_hand},
    table::balls::{Ball, BallMotion, Pocketed, world_velocity},
    table::geometry::{TableSpec, table_dir_to_world, to_table_plane},
    view,
    view::camera::{CameraSystems, TableCamera},
};
use bevy::{
    input::{
        ButtonState,
        keyboard::KeyboardInput,
        mouse::{AccumulatedMouseMotion, AccumulatedMouseScroll, MouseScrollUnit},
    },
    math::DVec2,
    prelude::*,
    window::{PrimaryWindow, RequestRedraw},
};

/// Registers the cue stick and its controls.
pub fn plugin(app: &mut App) {
    app.add_systems(Startup, spawn_cue)
        // Input before the simulation's commands, so a shot is struck in the same frame;
        // drawing after them, so the cue and the vectors show this frame's state.
        .add_systems(
            Update,
            (
                aim_with_mouse
                    .in_set(InputSystems::Pointer)
                    .run_if(aim_unlocked)
                    .run_if(crate::input::no_pointer_tool),
                cue_keys.in_set(InputSystems::Keyboard),
            )
                .chain()
                .after(CameraSystems)
                .before(SimSystems::Commands)
                .run_if(in_state(GameMode::Play)),
        )
        .add_systems(
            Update,
            (
                retry_undone_shot,
                place_cue.run_if(in_state(GameMode::Play)),
                draw_vectors,
            )
                .chain()
                .after(SimSystems::Commands),
        )
        // No cue over a recording; back in play, `place_cue` shows it again when it may.
        .add_systems(OnEnter(GameMode::Replay), hide_cue);
}

/// The cue stick.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct CueStick;

/// Length of a cue (58 in).
const CUE_LENGTH: f32 = 1.47;
/// Cue tip and butt radii (13 mm tip; a butt about 30 mm across).
const TIP_RADIUS: f32 = 0.0065;
const BUTT_RADIUS: f32 = 0.015;
/// Gap between tip and ball at zero power, and the pull-back at full power.
const REST_GAP: f32 = 0.012;
const FULL_PULL_BACK: f32 = 0.30;
/// The cue is raised at the butt just enough to clear the rails.
const ELEVATION: f32 = 0.09;
/// The steepest a player jacks the cue up over a ball in the way (about 50 degrees).
const MAX_ELEVATION: f32 = 0.87;

/// The maple shaft colour, which the render test looks for.
pub const SHAFT_COLOUR: Color = Color::srgb(0.93, 0.80, 0.58);

fn spawn_cue(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    // The stick's local +Y runs from the tip (at the origin) to the butt.
    let radius_at = |y: f32| TIP_RADIUS + (BUTT_RADIUS - TIP_RADIUS) * y / CUE_LENGTH;
    let mut piece = |from: f32, to: f32, colour: Color, roughness: f32| {
        let mesh = ConicalFrustum {
            radius_top: radius_at(to),
            radius_bottom: radius_at(from),
            height: to - from,
        };
        (
            Mesh3d(meshes.add(mesh)),
            MeshMaterial3d(materials.add(StandardMaterial {
                base_color: colour,
                perceptual_roughness: roughness,
                ..default()
            })),
            Transform::from_xyz(0.0, (from + to) / 2.0, 0.0),
        )
    };
    let tip = piece(0.0, 0.012, Color::srgb(0.10, 0.25, 0.55), 0.9);
    let ferrule = piece(0.012, 0.035, Color::srgb(0.95, 0.95, 0.92), 0.3);
    let shaft = piece(0.035, 0.80, SHAFT_COLOUR, 0.35);
    let ring = piece(0.80, 0.82, Color::srgb(0.05, 0.05, 0.05), 0.2);
    let butt = piece(0.82, CUE_LENGTH - 0.03, Color::srgb(0.22, 0.07, 0.03), 0.3);
    let cap = piece(
        CUE_LENGTH - 0.03,
        CUE_LENGTH,
        Color::srgb(0.05, 0.05, 0.05),
        0.5,
    );
    commands.spawn((
        CueStick,
        Name::new("Cue stick"),
        Transform::default(),
        Visibility::Hidden,
        children![tip, ferrule, shaft, ring, butt, cap],
    ));
}

/// After an undo the cue is lined up as for the shot taken back, so it can be retried or
/// adjusted.
fn retry_undone_shot(mut undone: MessageReader<ShotUndone>, mut shot: ResMut<ShotSettings>) {
    if let Some(ShotUndone { shot: last }) = undone.read().last() {
        shot.set_if_neq(ShotSettings {
            angle: last.angle,
            power: last.speed,
            tip: last.tip,
            elevation: last.elevation.to_degrees(),
        });
    }
}

/// The cue ball's table position, if it is on the table: the ball the next stroke strikes
/// (`cue`, [`Solver::cue_number`]).
fn cue_ball_position(
    balls: &Query<(&Ball, &BallMotion), Without<Pocketed>>,
    cue: u8,
) -> Option<DVec2> {
    balls
        .iter()
        .find(|(ball, _)| ball.number == cue)
        .map(|(_, motion)| motion.position)
}

/// The cue stick's transform and visibility.
type CueStickQuery<'w, 's> =
    Single<'w, 's, (&'static mut Transform, &'static mut Visibility), With<CueStick>>;

/// The number of the ball the next stroke strikes: the solver's, 0 without one.
fn cue_number(solver: &Option<Res<Solver>>) -> u8 {
    solver.as_ref().map_or(0, |s| s.cue_number())
}

/// The mouse, the modifier keys and what the pointer is over.
#[derive(bevy::ecs::system::SystemParam)]
pub struct PointerInput<'w, 's> {
    buttons: Res<'w, ButtonInput<MouseButton>>,
    keys: Res<'w, ButtonInput<KeyCode>>,
    motion: Res<'w, AccumulatedMouseMotion>,
    scroll: Res<'w, AccumulatedMouseScroll>,
    window: Single<'w, 's, &'static Window, With<PrimaryWindow>>,
    camera: Single<'w, 's, (&'static Camera, &'static GlobalTransform), With<TableCamera>>,
}

impl PointerInput<'_, '_> {
    /// Whether the left button went down this frame.
    pub fn clicked(&self) -> bool {
        self.buttons.just_pressed(MouseButton::Left)
    }

    /// Whether the left button is held, or was clicked within this frame.
    pub fn left_down(&self) -> bool {
        held_or_clicked(&self.buttons, MouseButton::Left)
    }

    /// The table-plane point under the pointer, on the horizontal plane `height` above the
    /// cloth (Bevy world units).
    pub fn table_point(&self, height: f32) -> Option<DVec2> {
        let window = *self.window;
        let (camera, camera_transform) = *self.camera;
        // Below 100 % render scale the camera draws into a smaller image than the window.
        let cursor = view::cursor_in_target(
            window.cursor_position()?,
            window.scale_factor(),
            window.physical_size(),
            camera.physical_target_size()?,
            camera.target_scaling_factor()?,
        );
        let ray = camera.viewport_to_world(camera_transform, cursor).ok()?;
        let distance = ray.intersect_plane(Vec3::Y * height, InfinitePlane3d::new(Vec3::Y))?;
        Some(to_table_plane(ray.get_point(distance)))
    }
}

/// Left drag aims at the pointer; with Shift, dragging down (or the wheel) sets the power.
/// With the cue ball in hand, a drag that starts on the cue ball (or any drag with Ctrl)
/// moves it: anywhere legal under the rules (a spot on another ball, off the table or, when
/// it must be, in front of the head string is refused and the ball stays), along the head
/// string after a free-play scratch.
#[allow(clippy::too_many_arguments)]
fn aim_with_mouse(
    input: PointerInput,
    spec: Res<TableSpec>,
    mut balls: Query<(&Ball, &mut BallMotion), Without<Pocketed>>,
    mut status: ResMut<SimStatus>,
    solver: Option<Res<Solver>>,
    mut shot: ResMut<ShotSettings>,
    mut report: ResMut<ClampReport>,
    mut dragging_ball: Local<bool>,
) {
    if !input.buttons.pressed(MouseButton::Left) {
        *dragging_ball = false;
    }
    if !status.at_rest {
        return;
    }
    let cue = cue_number(&solver);
    if let Some(rule) = status.ball_in_hand
        && let Some(solver) = solver
    {
        let ctrl = input
            .keys
            .any_pressed([KeyCode::ControlLeft, KeyCode::ControlRight]);
        let target = input.table_point(spec.ball_radius as f32);
        if input.clicked()
            && let Some(target) = target
            && let Some(cue_ball) = balls
                .iter()
                .find(|(ball, _)| ball.number == cue)
                .map(|(_, motion)| motion.position)
            && target.distance(cue_ball) < 1.5 * spec.ball_radius
        {
            *dragging_ball = true;
        }
        if (*dragging_ball || ctrl) && input.left_down() {
            if let Some(target) = target
                && let Some((_, mut motion)) = balls.iter_mut().find(|(ball, _)| ball.number == cue)
            {
                // A refused spot keeps the ball where it last was legal.
                let placed = place_ball_in_hand(&solver, &spec, &mut motion, target, rule);
                status.note = placed.err().map(|error| format!("ball in hand: {error}"));
            }
            return;
        }
    }
    let Some(cue_ball) = balls
        .iter()
        .find(|(ball, _)| ball.number == cue)
        .map(|(_, motion)| motion.position)
    else {
        return;
    };
    let shift = input
        .keys
        .any_pressed([KeyCode::ShiftLeft, KeyCode::ShiftRight]);
    let mut next = *shot;
    if input.left_down() {
        if shift {
            // Pulling the mouse toward the player pulls the cue back: 2 cm/s per pixel.
            next.power += f64::from(input.motion.delta.y) * 0.02;
        } else {
            // Aim from the ball's centre height, so the cue ball heads for the pointer.
            let target = input.table_point(spec.ball_radius as f32);
            if let Some(target) = target
                && target.distance(cue_ball) > 1e-3
            {
                next.angle = (target - cue_ball).to_angle();
            }
        }
    }
    if shift && input.scroll.delta.y != 0.0 {
        let notches = match input.scroll.unit {
            MouseScrollUnit::Line => input.scroll.delta.y,
            MouseScrollUnit::Pixel => input.scroll.delta.y / 40.0,
        };
        next.power += f64::from(notches) * 0.25;
    }
    apply_shot_edit(next, &mut shot, &mut report);
}

/// Arrow keys turn the aim and change the power, E and D raise and lower the cue, a tap by
/// one step and a held key at a rate in real time ([`HeldKeys`]); Space shoots.
#[allow(clippy::too_many_arguments)]
fn cue_keys(
    keys: Res<ButtonInput<KeyCode>>,
    mut typed: MessageReader<KeyboardInput>,
    time: Res<Time<Real>>,
    status: Res<SimStatus>,
    mut held: Local<HeldKeys>,
    mut shot: ResMut<ShotSettings>,
    mut report: ResMut<ClampReport>,
    mut shots: MessageWriter<ShotRequested>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    // Every press of this frame (several taps can fall in one slow frame), read even when
    // unused so none is applied late.
    let presses: Vec<KeyCode> = typed
        .read()
        .filter(|k| k.state == ButtonState::Pressed && !k.repeat)
        .map(|k| k.key_code)
        .collect();
    if !status.at_rest {
        *held = HeldKeys::default();
        return;
    }
    let now = time.elapsed_secs_f64();
    let frame = (now - time.delta_secs_f64(), now);
    let fine = keys.any_pressed([KeyCode::ShiftLeft, KeyCode::ShiftRight]);
    // A tap: 1 degree (0.1 with Shift) or 0.1 m/s; held: 30 (2) degrees or 3 m/s a second.
    let turn: (f64, f64) = if fine { (0.1, 2.0) } else { (1.0, 30.0) };
    let turn = (turn.0.to_radians(), turn.1.to_radians());
    let mut motion = |key: KeyCode, rates: (f64, f64)| {
        let taps = presses.iter().filter(|&&k| k == key).count() as u32;
        let state = (taps, keys.pressed(key));
        held.motion(key, state, frame, rates)
    };
    let mut next = *shot;
    next.angle += motion(KeyCode::ArrowLeft, turn) - motion(KeyCode::ArrowRight, turn);
    next.power += motion(KeyCode::ArrowUp, (0.1, 3.0)) - motion(KeyCode::ArrowDown, (0.1, 3.0));
    // The cue's elevation (a jump, a masse): a tap 1 degree (0.1 with Shift); held 15 (2)
    // degrees a second.
    let raise = if fine { (0.1, 2.0) } else { (1.0, 15.0) };
    next.elevation += motion(KeyCode::KeyE, raise) - motion(KeyCode::KeyD, raise);
    // A key held at the end of its range stops there: the player asked for the end, not for
    // a value beyond it to be clamped and warned about (played: "cue elevation
    // 95.50192516999994 deg is outside 0..85 deg").
    for (value, range, before) in [
        (&mut next.power, ShotSettings::POWER, shot.power),
        (&mut next.elevation, ShotSettings::ELEVATION, shot.elevation),
    ] {
        if *value != before && before.is_finite() {
            *value = value.clamp(range.min.min(before), range.max.max(before));
        }
    }
    if held.any_held() {
        // The window draws on input only: keep frames coming while a key is held.
        redraw.write(RequestRedraw);
    }
    apply_shot_edit(next, &mut shot, &mut report);
    if keys.just_pressed(KeyCode::Space) {
        shots.write(ShotRequested::from_settings(&shot));
    }
}

/// Puts the cue behind the cue ball along the aim, pulled back in proportion to the power,
/// and shows it only while a shot can be taken.
fn place_cue(
    spec: Res<TableSpec>,
    referee: Res<Referee>,
    shot: Res<ShotSettings>,
    status: Res<SimStatus>,
    balls: Query<(&Ball, &BallMotion), Without<Pocketed>>,
    (cue, solver): (CueStickQuery, Option<Res<Solver>>),
    mut redraw: MessageWriter<RequestRedraw>,
) {
    let (mut transform, mut visibility) = cue.into_inner();
    let number = cue_number(&solver);
    let cue_ball =
        cue_ball_position(&balls, number).filter(|_| status.at_rest && !referee.rack_over);
    let wanted_visibility = if cue_ball.is_some() {
        Visibility::Inherited
    } else {
        Visibility::Hidden
    };
    visibility.set_if_neq(wanted_visibility);
    let Some(cue_ball) = cue_ball else { return };

    let aim = table_dir_to_world(shot.direction());
    let power = (shot.power / ShotSettings::POWER.max) as f32;
    let gap = REST_GAP + FULL_PULL_BACK * power.clamp(0.0, 1.0);
    // Raised over any ball behind the cue ball, as a player jacks up the butt.
    let others = balls
        .iter()
        .filter(|(b, _)| b.number != number)
        .map(|(_, m)| m.position);
    let elevation = cue_elevation(
        cue_ball,
        shot.direction(),
        others,
        spec.ball_radius as f32,
        gap,
    )
    // The player's own elevation, or more when a ball is in the way.
    .max(shot.elevation.to_radians() as f32);
    // From the tip toward the butt: backward along the aim, raised by the elevation.
    let back = (-aim * elevation.cos() + Vec3::Y * elevation.sin()).normalize();
    let centre = spec.ball_world_position(cue_ball);
    let target = Transform::from_translation(centre + back * (spec.ball_radius as f32 + gap))
        .with_rotation(Quat::from_rotation_arc(Vec3::Y, back));
    if *transform != target {
        *transform = target;
        redraw.write(RequestRedraw);
    }
}

/// The cue's elevation (radians above the cloth) for a cue ball at `cue_ball` aimed along
/// `aim` (table plane, unit), its tip `gap` behind the ball: the rail-clearing minimum, or
/// steeper so the stick passes over every ball in `others` behind the cue ball, up to
/// about 50 degrees.
pub fn cue_elevation(
    cue_ball: DVec2,
    aim: DVec2,
    others: impl Iterator<Item = DVec2>,
    radius: f32,
    gap: f32,
) -> f32 {
    let back = -aim;
    let tip = radius + gap;
    let mut elevation = ELEVATION;
    for other in others {
        let v = other - cue_ball;
        let along = v.dot(back) as f32;
        let across = v.perp_dot(back).abs() as f32;
        // Where the stick is about as thick as it gets over a ball (a few mm of margin).
        let thickness = BUTT_RADIUS + 0.004;
        let reach = radius + thickness;
        if across >= reach || along <= 0.0 || along - radius > tip + CUE_LENGTH {
            continue;
        }
        // The stick's axis must pass this high over the ball's centre (both at the same
        // height: the tip strikes the cue ball about its centre) ...
        let over = (reach * reach - across * across).sqrt();
        // ... from the ball's near side on, measured from the tip.
        let run = (along - over - tip).max(1e-3);
        elevation = elevation.max(over.atan2(run));
    }
    elevation.min(MAX_ELEVATION)
}

/// The paper's vectors: red for the cue (direction and strength of the shot), blue for each
/// moving ball's velocity.
fn draw_vectors(
    view: Res<ViewSettings>,
    spec: Res<TableSpec>,
    shot: Res<ShotSettings>,
    status: Res<SimStatus>,
    balls: Query<(&Ball, &BallMotion), Without<Pocketed>>,
    mode: Res<State<GameMode>>,
    (mut gizmos, solver): (Gizmos, Option<Res<Solver>>),
) {
    if !view.show_vectors {
        return;
    }
    // The cue vector belongs to the live shot; a replay shows only the balls' velocities.
    let live = *mode.get() == GameMode::Play;
    // Drawn just above the cloth so the balls do not hide them: 5 cm per m/s.
    const METRES_PER_MPS: f32 = 0.05;
    let lift = Vec3::Y * (2.05 * spec.ball_radius as f32);
    if live
        && status.at_rest
        && let Some(cue_ball) = cue_ball_position(&balls, cue_number(&solver))
    {
        let start = spec.ball_world_position(cue_ball) + lift;
        let end = start + table_dir_to_world(shot.direction()) * METRES_PER_MPS * shot.power as f32;
        gizmos.arrow(start, end, Color::srgb(0.95, 0.1, 0.1));
    }
    for (_, motion) in &balls {
        if motion.velocity != DVec2::ZERO {
            let start = spec.ball_world_position(motion.position) + lift;
            let end = start + world_velocity(motion) * METRES_PER_MPS;
            gizmos.arrow(start, end, Color::srgb(0.15, 0.35, 1.0));
        }
    }
}

fn hide_cue(mut cue: Query<&mut Visibility, With<CueStick>>) {
    for mut visibility in &mut cue {
        visibility.set_if_neq(Visibility::Hidden);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const R: f32 = 0.028_575;

    #[test]
    fn a_clear_line_keeps_the_cue_low() {
        let e = cue_elevation(
            DVec2::ZERO,
            DVec2::X,
            [DVec2::new(0.5, 0.0)].into_iter(),
            R,
            0.02,
        );
        assert_eq!(e, ELEVATION);
        let beside = [DVec2::new(-0.3, 0.2)];
        assert_eq!(
            cue_elevation(DVec2::ZERO, DVec2::X, beside.into_iter(), R, 0.02),
            ELEVATION
        );
    }

    #[test]
    fn a_ball_behind_the_cue_ball_raises_the_butt_over_it() {
        let behind = DVec2::new(-0.3, 0.0);
        let gap = 0.05;
        let e = cue_elevation(DVec2::ZERO, DVec2::X, [behind].into_iter(), R, gap);
        assert!(e > ELEVATION);
        // Over the ball's near side the stick's axis is a ball radius plus the butt above
        // its centre.
        let near = 0.3 - R - BUTT_RADIUS;
        let height = (near - R - gap) * e.tan();
        assert!(height >= R + BUTT_RADIUS - 1e-4, "{height}");
        // A ball right behind needs a steeper cue, up to the limit.
        let close = [DVec2::new(-2.1 * f64::from(R), 0.0)];
        let steep = cue_elevation(DVec2::ZERO, DVec2::X, close.into_iter(), R, gap);
        assert!(steep > e && steep <= MAX_ELEVATION);
    }
}
