//! What the computer decided ([`Decided`]: by pool's, snooker's or the shared search) and the decision
//! in words for the hint and the status line ([`describe`]), cushions named as the view shows
//! them.

use bevy::prelude::*;
use billiards_ai::{Decision, ShotKind, SnookerDecision, any_game::Move};
use billiards_physics::{Cushion, Vec2};
use billiards_rules::snooker::{Choice as SnookerChoice, balls::name as snooker_name};
use billiards_rules::{Call, pocket_name};

use crate::view::camera::{CameraMode, OrbitCamera};

pub use billiards_ai::game::Decided;

/// The decision in words, with its success probability; cushions named as `view` shows them.
pub fn describe(decision: &Decided, view: &OrbitCamera) -> String {
    match decision {
        Decided::Pool(decision) => describe_pool(decision, view),
        Decided::Any(Move::Choose(index)) => format!("option {}", index + 1),
        Decided::Any(Move::Strike(stroke)) => format!(
            "a stroke at {:.1} degrees, {:.1} m/s (worth {:+.2})",
            stroke.shot.angle.to_degrees().rem_euclid(360.0),
            stroke.shot.speed,
            stroke.value
        ),
        Decided::Snooker(SnookerDecision::Choose { choice, estimate }) => {
            format!(
                "{} (worth {estimate:+.1} points)",
                snooker_choice_text(*choice)
            )
        }
        Decided::Snooker(SnookerDecision::Shoot(plan)) => {
            let what = match plan.kind {
                ShotKind::Break => "the break-off".to_owned(),
                kind => kind_text(kind, view, |n| snooker_name(n).to_owned()),
            };
            let nominated = plan.nominated.map_or(String::new(), |n| {
                format!(", nominating the {}", snooker_name(n))
            });
            format!(
                "{what}{nominated}, {:.0} % to pot, {:.0} % foul",
                100.0 * plan.success,
                100.0 * plan.foul
            )
        }
    }
}

fn snooker_choice_text(choice: SnookerChoice) -> String {
    match choice {
        SnookerChoice::PlayOn => "play on".to_owned(),
        SnookerChoice::PutBack => "put the offender back in".to_owned(),
        SnookerChoice::Replace => "replace the balls".to_owned(),
        SnookerChoice::BlackFirst(seat) => format!("player {} plays the black", seat.index() + 1),
    }
}

/// The decision in words, with its success probability; cushions named as `view` shows them.
fn describe_pool(decision: &Decision, view: &OrbitCamera) -> String {
    match decision {
        Decision::Choose { choice, estimate } => {
            format!("{} ({:.0} %)", choice.label(), 100.0 * estimate)
        }
        Decision::Shoot(plan) => {
            let what = kind_text(plan.kind, view, |n| n.to_string());
            let call = match plan.call {
                Call::Ball { .. } | Call::None => String::new(),
                other => other.text().map_or(String::new(), |c| format!(", {c}")),
            };
            format!(
                "{what}{call}{}, {:.0} % to succeed, {:.0} % foul",
                jump_text(plan.shot.elevation),
                100.0 * plan.success,
                100.0 * plan.foul
            )
        }
    }
}

/// A jump shot said as one: the computer raises the cue 30 to 60 degrees to fly the cue
/// ball over a blocker (`billiards_ai::jump`); a level shot (or the few degrees of a
/// swerve) says nothing.
fn jump_text(elevation: f64) -> String {
    let degrees = elevation.to_degrees();
    if degrees >= JUMP_DEGREES {
        format!(", a jump shot (cue raised {degrees:.0} degrees)")
    } else {
        String::new()
    }
}

/// The least cue elevation, degrees, named a jump shot in words (below the 30 degrees of the
/// computer's lowest jump, above any swerve or masse it plans).
const JUMP_DEGREES: f64 = 20.0;

/// A cushion's name as `view` shows it. The short ones keep the players' "head" and "foot";
/// a long one is named by where it lies on the screen: "left" or "right", and "far" or
/// "near" (in the top view "top" or "bottom"). The rules' "left" (seen from the head end)
/// read as the top rail in the top view (issue 28, item 10).
pub fn cushion_name(cushion: Cushion, view: &OrbitCamera) -> &'static str {
    match cushion {
        Cushion::Head => return "head",
        Cushion::Foot => return "foot",
        Cushion::Left | Cushion::Right => {}
    }
    let outward = -cushion.inward_normal();
    // The camera's forward and right on the table, in the solver's axes (yaw 0 looks along
    // the solver's +y, with its +x to the right).
    let yaw = f64::from(view.yaw);
    let forward = Vec2::new(-yaw.sin(), yaw.cos());
    let right = Vec2::new(yaw.cos(), yaw.sin());
    let (ahead, aside) = (outward.dot(forward), outward.dot(right));
    let top = view.mode == CameraMode::Top;
    match (aside.abs() >= ahead.abs(), aside > 0.0, ahead > 0.0, top) {
        (true, true, _, _) => "right",
        (true, false, _, _) => "left",
        (false, _, true, true) => "top",
        (false, _, true, false) => "far",
        (false, _, false, true) => "bottom",
        (false, _, false, false) => "near",
    }
}

/// A shot in words, the balls named by `name` (pool's numbers, snooker's colours).
fn kind_text(kind: ShotKind, view: &OrbitCamera, name: impl Fn(u8) -> String) -> String {
    let cushion = |c: Cushion| cushion_name(c, view);
    match kind {
        ShotKind::Break => "the break".to_owned(),
        ShotKind::Pot { ball, pocket } => {
            format!("the {} in the {}", name(ball), pocket_name(pocket))
        }
        ShotKind::Bank {
            ball,
            pocket,
            cushion: c,
        } => format!(
            "the {} off the {} cushion in the {}",
            name(ball),
            cushion(c),
            pocket_name(pocket)
        ),
        ShotKind::Kick {
            ball,
            pocket,
            cushion: c,
        } => format!(
            "a kick off the {} cushion, the {} in the {}",
            cushion(c),
            name(ball),
            pocket_name(pocket)
        ),
        ShotKind::Combo {
            first,
            ball,
            pocket,
        } => format!(
            "the {} into the {}, in the {}",
            name(first),
            name(ball),
            pocket_name(pocket)
        ),
        ShotKind::Safety { ball } => format!("a safety on the {}", name(ball)),
        ShotKind::PushOut => "a push out".to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The long cushions are named as the screen shows them: from the default view behind the
    /// head rail the rules' left cushion is on the left; in the top view (head rail on the
    /// left) it is the top one; seen from the foot end, sides swap.
    #[test]
    fn long_cushions_are_named_as_the_view_shows_them() {
        let behind_head = OrbitCamera::default();
        assert_eq!(cushion_name(Cushion::Left, &behind_head), "left");
        assert_eq!(cushion_name(Cushion::Right, &behind_head), "right");
        assert_eq!(cushion_name(Cushion::Head, &behind_head), "head");
        let top = OrbitCamera::top_view();
        assert_eq!(cushion_name(Cushion::Left, &top), "top");
        assert_eq!(cushion_name(Cushion::Right, &top), "bottom");
        assert_eq!(cushion_name(Cushion::Foot, &top), "foot");
        let behind_foot = OrbitCamera {
            yaw: behind_head.yaw + std::f32::consts::PI,
            ..behind_head
        };
        assert_eq!(cushion_name(Cushion::Left, &behind_foot), "right");
        // Looking across the table from the right long cushion, the left one is far.
        let across = OrbitCamera {
            yaw: 0.0,
            ..behind_head
        };
        assert_eq!(cushion_name(Cushion::Left, &across), "far");
        assert_eq!(cushion_name(Cushion::Right, &across), "near");
    }

    /// Issue 52: Hint says when its shot is a jump (the computer's 30 to 60 degrees), and a
    /// level shot or a swerve's few degrees is not called one.
    #[test]
    fn a_jump_shot_is_said_as_one() {
        assert_eq!(
            jump_text(45f64.to_radians()),
            ", a jump shot (cue raised 45 degrees)"
        );
        assert!(jump_text(30f64.to_radians()).contains("jump shot"));
        assert_eq!(jump_text(0.0), "");
        assert_eq!(jump_text(8f64.to_radians()), "");
    }
}
