//! Ball in hand: whether the player may put the cue ball here (WPA 1.5; behind the head
//! string on the break and after a scratch on the 8-ball break, 2.3 / 3.3).

use crate::game::CueBall;
use billiards_physics::{BallId, Simulation, Table, Vec2, sim::PLACEMENT_TOLERANCE};

/// Why the cue ball cannot go there.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PlacementError {
    /// The cue ball is not in hand for this shot.
    #[error("the cue ball is not in hand")]
    NotInHand,
    /// Outside the area a ball's centre may occupy.
    #[error("the cue ball must be on the table")]
    OffTable,
    /// In front of the head string when it must be behind it.
    #[error("the cue ball must be behind the head string")]
    InFrontOfHeadString,
    /// On top of another ball.
    #[error("the cue ball would overlap the {0}")]
    Overlaps(u8),
}

/// Checks a ball-in-hand placement of ball `cue` of `sim` at `at` under `rule` (the next
/// shot's [`crate::NextShot::cue_ball`]). Behind the head string means the ball's centre
/// (its base) is not in front of the string.
pub fn check_placement(
    sim: &Simulation,
    cue: BallId,
    at: Vec2,
    rule: CueBall,
) -> Result<(), PlacementError> {
    let numbers = sim.numbers();
    let others: Vec<(u8, Vec2)> = sim
        .balls()
        .enumerate()
        .filter(|&(id, state)| id != cue && state.motion.on_table())
        .map(|(id, state)| (numbers[id], state.position))
        .collect();
    check_place(sim.table(), sim.params().ball.radius, at, &others, rule)
}

/// [`check_placement`] on plain data: the cue ball of radius `radius` at `at` on `table`,
/// the other balls on the table at `others` (number and centre).
pub fn check_place(
    table: &Table,
    radius: f64,
    at: Vec2,
    others: &[(u8, Vec2)],
    rule: CueBall,
) -> Result<(), PlacementError> {
    match rule {
        CueBall::AsItLies | CueBall::Respot => return Err(PlacementError::NotInHand),
        CueBall::InHandBehindHeadString if at.x > table.head_spot().x => {
            return Err(PlacementError::InFrontOfHeadString);
        }
        CueBall::InHandAnywhere | CueBall::InHandBehindHeadString => {}
    }
    let bounds = table.centre_bounds(radius);
    if !at.is_finite() || at.x.abs() > bounds.x || at.y.abs() > bounds.y {
        return Err(PlacementError::OffTable);
    }
    match others
        .iter()
        .find(|&&(_, p)| (p - at).length() < 2.0 * radius - PLACEMENT_TOLERANCE)
    {
        Some(&(n, _)) => Err(PlacementError::Overlaps(n)),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::{BallSetup, Params};

    #[test]
    fn wpa_1_5_ball_in_hand_refuses_overlaps_the_cushions_and_the_kitchen_line() {
        let table = Table::wpa_8ft();
        let balls = [
            BallSetup::at(0, Vec2::new(-0.8, 0.0)),
            BallSetup::at(5, Vec2::new(0.2, 0.1)),
        ];
        let sim = Simulation::new(table, Params::default(), &balls).unwrap();
        let anywhere = CueBall::InHandAnywhere;
        let kitchen = CueBall::InHandBehindHeadString;
        assert_eq!(
            check_placement(&sim, 0, Vec2::new(0.3, -0.2), anywhere),
            Ok(())
        );
        assert_eq!(
            check_placement(&sim, 0, Vec2::new(0.22, 0.1), anywhere),
            Err(PlacementError::Overlaps(5))
        );
        assert_eq!(
            check_placement(&sim, 0, Vec2::new(0.3, 0.6), anywhere),
            Err(PlacementError::OffTable)
        );
        assert_eq!(
            check_placement(&sim, 0, Vec2::new(0.0, 0.0), kitchen),
            Err(PlacementError::InFrontOfHeadString)
        );
        assert_eq!(check_placement(&sim, 0, table.head_spot(), kitchen), Ok(()));
        // Its own place does not count as an overlap; no hand, no placement.
        assert_eq!(
            check_placement(&sim, 0, Vec2::new(-0.8, 0.0), anywhere),
            Ok(())
        );
        assert_eq!(
            check_placement(&sim, 0, Vec2::new(-0.8, 0.0), CueBall::AsItLies),
            Err(PlacementError::NotInHand)
        );
    }
}
