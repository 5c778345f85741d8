//! What the computer decided ([`Decided`]: by the game's own search) and the decision in
//! words for the hint and the status line ([`describe`]: the game's words, through the
//! interface), cushions named as the view shows them.

use bevy::prelude::*;
use billiards_physics::{Cushion, Vec2};
use billiards_rules::GameRules;

use crate::view::camera::{CameraMode, OrbitCamera};

pub use billiards_ai::game::Decided;

/// The decision in words, with its odds, in the words of `game` (the game it was decided
/// for, [`Decided::words`]); cushions named as `view` shows them.
pub fn describe(decision: &Decided, game: &dyn GameRules, view: &OrbitCamera) -> String {
    decision.words(game, &|c| cushion_name(c, view))
}

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
}
