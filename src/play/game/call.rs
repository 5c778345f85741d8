//! The call proposed from the aim (issues 28, 48): the ball and pocket the aiming aid sends
//! a callable ball into, and the ball the call window opens on, for any game whose turn
//! lets a ball and pocket be called ([`Declarations::callable`](billiards_rules::Declarations)).

use billiards_rules::{Declaration, Turn};

use crate::play::aim::AimPrediction;

/// The ball the call window opens on (issue 48: it chose the 1 while the aim was on the 6):
/// the proposed call's ball, else the only callable ball (the 8 when it is on), else the
/// ball the aim hits first if it may be called, else the first callable ball.
pub(super) fn preselected_ball(
    turn: &Turn,
    proposed: Option<Declaration>,
    aim: Option<&AimPrediction>,
) -> Option<u8> {
    if let Some(Declaration::Pocket { ball, .. }) = proposed {
        return Some(ball);
    }
    let callable = &turn.declare.callable;
    if let [only] = callable.as_slice() {
        return Some(*only);
    }
    let aimed = aim.and_then(|aim| match aim.contact {
        Some((crate::play::aim::FirstContact::Ball { number }, _)) => Some(number),
        _ => None,
    });
    aimed
        .filter(|n| callable.contains(n))
        .or_else(|| callable.first().copied())
}

/// The call the aim proposes: the first callable ball (the 8 when it is on, in 10-ball any
/// ball, else the striker's legal balls) whose drawn path ends in a pocket.
pub(super) fn proposed_call(turn: &Turn, aim: &AimPrediction) -> Option<Declaration> {
    aim.after
        .iter()
        .filter(|path| path.number != turn.cue_ball && turn.declare.callable.contains(&path.number))
        .find_map(|path| {
            path.pocket.map(|pocket| Declaration::Pocket {
                ball: path.number,
                pocket,
            })
        })
}

#[cfg(test)]
mod tests {
    use crate::play::{
        aim::{AimPrediction, BallPath},
        game::call::{preselected_ball, proposed_call},
    };
    use bevy::math::DVec2;
    use billiards_physics::Pocket;
    use billiards_rules::{CueBallPlace, Declaration, Declarations, Need, Seat, Turn};

    /// A turn whose balls `callable` may be called (none: no call on this stroke).
    fn turn(callable: Vec<u8>) -> Turn {
        Turn {
            striker: Seat::A,
            cue_ball: 0,
            place: CueBallPlace::AsItLies,
            legal_first: callable.clone(),
            ball_on: String::new(),
            declare: Declarations {
                pocket: if callable.is_empty() {
                    Need::NotUsed
                } else {
                    Need::Optional
                },
                callable,
                ..Declarations::default()
            },
            opening: false,
            choices: Vec::new(),
        }
    }

    fn path(number: u8, pocket: Option<Pocket>) -> BallPath {
        BallPath {
            number,
            points: Vec::new(),
            heights: Vec::new(),
            pocket,
        }
    }

    /// Issue 28: the call follows the aim: the first ball of the player's that the aiming aid
    /// sends into a pocket, with that pocket; not the cue ball, not a ball the player may not
    /// call, nothing when no ball drops; the 8 only when it is on.
    #[test]
    fn the_proposed_call_is_the_ball_the_aim_pockets() {
        let aim = AimPrediction {
            after: vec![
                path(0, Some(Pocket::FootLeft)),
                path(2, None),
                path(9, Some(Pocket::SideRight)),
                path(3, Some(Pocket::FootRight)),
            ],
            ..Default::default()
        };
        let solids = turn(vec![1, 2, 3, 4, 5, 6, 7]);
        assert_eq!(
            proposed_call(&solids, &aim),
            Some(Declaration::Pocket {
                ball: 3,
                pocket: Pocket::FootRight
            })
        );
        let stripes = turn(vec![9, 10]);
        assert_eq!(
            proposed_call(&stripes, &aim),
            Some(Declaration::Pocket {
                ball: 9,
                pocket: Pocket::SideRight
            })
        );
        assert_eq!(proposed_call(&turn(vec![8]), &aim), None);
        assert_eq!(proposed_call(&turn(vec![]), &aim), None);
    }

    /// Issue 48: with no pocket in the aim's paths, the dialog opens on the ball the aim
    /// hits first (the 6), not the lowest (the 1); a ball that may not be called is passed
    /// over for the lowest; the 8 when it must be called.
    #[test]
    fn the_call_dialog_opens_on_the_ball_aimed_at() {
        use crate::play::aim::FirstContact;
        let solids = turn(vec![1, 2, 3, 4, 5, 6, 7]);
        let on = |number| AimPrediction {
            contact: Some((FirstContact::Ball { number }, DVec2::ZERO)),
            ..Default::default()
        };
        assert_eq!(preselected_ball(&solids, None, Some(&on(6))), Some(6));
        assert_eq!(preselected_ball(&solids, None, Some(&on(12))), Some(1));
        assert_eq!(preselected_ball(&solids, None, None), Some(1));
        let proposed = Some(Declaration::Pocket {
            ball: 3,
            pocket: Pocket::FootRight,
        });
        assert_eq!(preselected_ball(&solids, proposed, Some(&on(6))), Some(3));
        let eight = turn(vec![8]);
        assert_eq!(preselected_ball(&eight, None, Some(&on(6))), Some(8));
    }
}
