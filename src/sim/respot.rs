//! The cue ball in hand: placed where the rules allow, or slid along the head string.

use bevy::{math::DVec2, prelude::*};

use billiards_rules::{CueBall, PlacementError};

use super::{messages::*, solver::*};
use crate::{table::balls::BallMotion, table::geometry::TableSpec};

/// Why the cue ball in hand cannot go there.
#[derive(Debug, Clone, PartialEq)]
pub enum HandError {
    /// The pool rules refuse it (off the table, on a ball, in front of the head string).
    Rules(PlacementError),
    /// Snooker: outside the D (WPBSA 3.4).
    OutsideD,
}

impl std::fmt::Display for HandError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            HandError::Rules(error) => error.fmt(f),
            HandError::OutsideD => f.write_str("the cue ball in hand must be in the D (WPBSA 3.4)"),
        }
    }
}

impl From<PlacementError> for HandError {
    fn from(error: PlacementError) -> Self {
        HandError::Rules(error)
    }
}

/// Puts the cue ball in hand at `at` if the rules allow it there
/// ([`billiards_rules::check_placement`]: on the table, behind the head string when it must
/// be, on no other ball); a refused spot leaves it where it was. The edit reaches the solver
/// (and the recording) like any placement. Free play's [`CueBall::Respot`] slides it along
/// the head string instead ([`move_ball_in_hand`]).
pub fn place_ball_in_hand(
    solver: &Solver,
    spec: &TableSpec,
    motion: &mut BallMotion,
    at: DVec2,
    rule: HandRule,
) -> Result<(), HandError> {
    let rule = match rule {
        HandRule::Respot => {
            move_ball_in_hand(spec, motion, at.y);
            return Ok(());
        }
        HandRule::Anywhere => CueBall::InHandAnywhere,
        HandRule::BehindHeadString => CueBall::InHandBehindHeadString,
        HandRule::InD => {
            let marks = billiards_physics::SnookerMarks::of(solver.simulation().table())
                .map_err(|_| HandError::OutsideD)?;
            if !marks.in_d(to_vec2(at)) {
                return Err(HandError::OutsideD);
            }
            CueBall::InHandAnywhere
        }
    };
    let cue = solver.cue_ball().ok_or(PlacementError::NotInHand)?;
    billiards_rules::check_placement(solver.simulation(), cue, to_vec2(at), rule)?;
    if motion.position != at {
        motion.position = at;
        motion.velocity = DVec2::ZERO;
    }
    Ok(())
}

/// Moves the cue ball in hand to `y` on the head string, clamped between the side cushions.
/// Goes through the same component edit as any placement, so the solver (and the recording)
/// gets it; a spot on another ball is refused there, with a note.
pub fn move_ball_in_hand(spec: &TableSpec, motion: &mut BallMotion, y: f64) {
    let limit = spec.width / 2.0 - spec.ball_radius;
    let y = if y.is_finite() {
        y.clamp(-limit, limit)
    } else {
        0.0
    };
    let spot = DVec2::new(spec.head_spot().x, y);
    if motion.position != spot {
        motion.position = spot;
        motion.velocity = DVec2::ZERO;
    }
}
