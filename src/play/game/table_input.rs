//! What needs a window: the click on a pocket, the aim lock, the confirm key, the gizmos.

use bevy::{math::DVec2, prelude::*};
use billiards_physics::Pocket;
use billiards_rules::Declaration;

use super::state::*;
use crate::{
    input::AimLocked,
    play::cue::PointerInput,
    sim::{HandRule, SimStatus},
    table::geometry::{TableSpec, d_outline, to_world},
};

/// While calling: a click near a pocket calls it, with the ball chosen (else the first
/// callable: the 8 when it is on).
pub(super) fn click_pocket(
    input: PointerInput,
    spec: Res<TableSpec>,
    rules: Res<Rules>,
    mut turn_commands: MessageWriter<TurnCommand>,
) {
    let Some(game) = &rules.live else { return };
    if !input.clicked() {
        return;
    }
    let Some(point) = input.table_point(0.0) else {
        return;
    };
    if let Some(pocket) = pocket_near(&spec, point) {
        let callable = game.rules.turn().declare.callable;
        let Some(ball) = game.call_ball.or(callable.first().copied()) else {
            return;
        };
        turn_commands.write(TurnCommand::Declare(Declaration::Pocket { ball, pocket }));
    }
}

/// The pocket whose hole is within a ball's reach of `point`, if any.
pub fn pocket_near(spec: &TableSpec, point: DVec2) -> Option<Pocket> {
    Pocket::ALL
        .into_iter()
        .filter_map(|p| spec.pocket(p).map(|hole| (p, hole)))
        .map(|(p, hole)| (p, hole.centre.distance(point), hole.radius))
        .filter(|&(_, d, radius)| d < radius + 3.0 * spec.ball_radius)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(p, _, _)| p)
}

/// While a pocket is being called, a click on the table calls it and does not also aim; on
/// the computer's turn the pointer does not aim either.
pub(super) fn lock_aim(
    turn: Option<Res<State<Turn>>>,
    rules: Res<Rules>,
    mut lock: ResMut<AimLocked>,
) {
    let calling = turn.is_some_and(|t| *t.get() == Turn::Calling);
    let computer = rules.to_play().is_some_and(|(level, _)| level.is_some());
    lock.set_if_neq(AimLocked(calling || computer));
}

/// Enter continues after a verdict with no options.
pub(super) fn confirm_key(
    keys: Res<ButtonInput<KeyCode>>,
    rules: Res<Rules>,
    mut turn_commands: MessageWriter<TurnCommand>,
) {
    let no_choice = rules.to_play().is_some_and(|(_, choosing)| !choosing);
    if keys.just_pressed(KeyCode::Enter) && no_choice {
        turn_commands.write(TurnCommand::Continue);
    }
}

/// The legal area of the cue ball in hand, the pockets while calling, the called pocket.
pub(super) fn draw_rules(
    rules: Res<Rules>,
    status: Res<SimStatus>,
    spec: Res<TableSpec>,
    turn: Option<Res<State<Turn>>>,
    mut gizmos: Gizmos,
) {
    let Some(turn) = turn.map(|t| *t.get()) else {
        return;
    };
    let lift = 0.003;
    let at = |p: DVec2| to_world(p.extend(lift));
    let flat = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    if turn == Turn::BallInHand
        && status.ball_in_hand == Some(HandRule::InD)
        && let Ok(marks) = billiards_physics::SnookerMarks::of(&spec.physics_table())
    {
        // The D (3.4): the half circle behind the baulk-line, and the line across it.
        let d: Vec<Vec3> = d_outline(&marks, 32).into_iter().map(at).collect();
        let ends = [d[0], d[d.len() - 1]];
        gizmos.linestrip(d, Color::srgb(0.3, 0.9, 1.0));
        gizmos.line(ends[0], ends[1], Color::srgb(0.3, 0.9, 1.0));
    }
    // Pool's areas (WPA 1.5, 2.3); the D is drawn above.
    if turn == Turn::BallInHand
        && let Some(rule) = status.ball_in_hand
        && rule != HandRule::InD
    {
        let h = spec.half_extents() - DVec2::splat(spec.ball_radius);
        let right = match rule {
            HandRule::BehindHeadString => spec.head_spot().x,
            _ => h.x,
        };
        let corners = [
            DVec2::new(-h.x, -h.y),
            DVec2::new(right, -h.y),
            DVec2::new(right, h.y),
            DVec2::new(-h.x, h.y),
            DVec2::new(-h.x, -h.y),
        ];
        gizmos.linestrip(corners.map(at), Color::srgb(0.3, 0.9, 1.0));
    }
    if turn == Turn::Calling {
        for hole in spec.pockets() {
            gizmos
                .circle(
                    Isometry3d::new(at(hole.centre), flat),
                    hole.radius as f32,
                    Color::srgba(1.0, 1.0, 1.0, 0.6),
                )
                .resolution(32);
        }
    }
    if let Some(game) = &rules.live
        && let Declaration::Pocket { pocket, .. } = game.declared
        && let Some(hole) = spec.pocket(pocket)
    {
        for k in [1.0, 1.15] {
            gizmos
                .circle(
                    Isometry3d::new(at(hole.centre), flat),
                    (hole.radius * k) as f32,
                    Color::srgb(1.0, 0.85, 0.1),
                )
                .resolution(48);
        }
    }
}
