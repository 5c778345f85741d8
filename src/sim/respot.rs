//! Balls put back on the table: respots after a scratch, the cue ball in hand.

use bevy::{math::DVec2, prelude::*};

use billiards_rules::{CueBall, PlacementError};

use super::{messages::*, solver::*};
use crate::{
    table::balls::{BallMotion, MotionState, Pocketed},
    table::geometry::TableSpec,
};

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

/// A table without a game (a drill session, which judges its own strokes): after a scratch
/// the cue ball goes back on the head string, where [`billiards_rules::cue_ball_spot`] says
/// (the rule the command line plays by too). The edit reaches the solver like any other
/// (change detection). With a game in play, free play's sandbox included, the game's
/// judgement puts it back instead ([`Referee::active`]).
pub fn respot_after_scratch(
    mut commands: Commands,
    mut finished: MessageReader<ShotFinished>,
    solver: Option<Res<Solver>>,
    referee: Res<Referee>,
    mut balls: Query<&mut BallMotion>,
    mut status: ResMut<SimStatus>,
) {
    if !finished.read().any(|shot| shot.scratch) || referee.active {
        return;
    }
    let Some(solver) = solver else { return };
    let Some(cue) = solver.cue_ball() else { return };
    // Over a cushion (issue 52) or into a pocket: said as it happened.
    let how = if solver.simulation().ball(cue).motion == billiards_physics::Motion::OffTable {
        "the cue ball flew off the table"
    } else {
        "scratch"
    };
    if respot_ball(&mut commands, &solver, cue, &mut balls, &mut status) {
        status.note = Some(format!(
            "{how}: the cue ball is back on the head string (ball in hand: drag it, or the \
             slider moves it along the string)"
        ));
        status.ball_in_hand = Some(HandRule::Respot);
    }
}

/// Puts ball `id` back on the table by an edit of its [`BallMotion`] (so the solver and the
/// recording get it): the cue ball on the head string ([`billiards_rules::cue_ball_spot`]),
/// an object ball on the foot string ([`billiards_rules::object_ball_spot`], WPA 1.4).
/// Returns whether a free spot was found (if not, a note says so).
pub fn respot_ball(
    commands: &mut Commands,
    solver: &Solver,
    id: usize,
    balls: &mut Query<&mut BallMotion>,
    status: &mut SimStatus,
) -> bool {
    let number = solver.simulation().numbers()[id];
    let spot = if number == 0 {
        billiards_rules::cue_ball_spot(solver.simulation(), id)
    } else {
        billiards_rules::object_ball_spot(solver.simulation(), id)
    };
    let Some(spot) = spot else {
        status.note = Some(format!("no free spot for the ball {number}"));
        return false;
    };
    let entity = solver.entities[id];
    let Ok(mut motion) = balls.get_mut(entity) else {
        return false;
    };
    *motion = BallMotion {
        position: to_dvec2(spot),
        velocity: DVec2::ZERO,
        state: MotionState::Stationary,
        spin: bevy::math::DVec3::ZERO,
        height: 0.0,
    };
    commands.entity(entity).remove::<Pocketed>();
    true
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
