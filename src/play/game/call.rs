//! The call proposed from the aim (issues 28, 48): the ball and pocket the aiming aid sends
//! a callable ball into, and the ball the call dialog opens on.

use billiards_rules::{Call, CallRule, NextShot};

use crate::play::aim::AimPrediction;

/// The ball the call dialog opens on (issue 48: it chose the 1 while the aim was on the 6):
/// the proposed call's ball, else the 8 when it must be called, else the ball the aim hits
/// first if it may be called, else the lowest legal ball.
pub(super) fn preselected_ball(
    next: &NextShot,
    proposed: Option<Call>,
    aim: Option<&AimPrediction>,
) -> Option<u8> {
    if let Some(Call::Ball { ball, .. }) = proposed {
        return Some(ball);
    }
    if next.call == CallRule::EightPocket {
        return Some(8);
    }
    let aimed = aim.and_then(|aim| match aim.contact {
        Some((crate::play::aim::FirstContact::Ball { number }, _)) => Some(number),
        _ => None,
    });
    aimed
        .filter(|n| next.legal_first.contains(n))
        .or_else(|| next.legal_first.first().copied())
}

/// The call the aim proposes: the first callable ball (the 8 when it is on, in 10-ball any
/// ball, else a legal first ball) whose drawn path ends in a pocket.
pub(super) fn proposed_call(next: &NextShot, aim: &AimPrediction) -> Option<Call> {
    let callable = |n: u8| match next.call {
        CallRule::EightPocket => n == 8,
        CallRule::Optional => next.legal_first.contains(&n),
        // 10-ball: any ball the aim sends into a pocket (a combination on the 10 too).
        CallRule::BallAndPocket => true,
        CallRule::NotUsed => false,
    };
    aim.after
        .iter()
        .filter(|path| path.number != 0 && callable(path.number))
        .find_map(|path| {
            path.pocket.map(|pocket| Call::Ball {
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
    use billiards_rules::{Call, CallRule, CueBall, NextShot, Seat};

    fn next(call: CallRule, legal_first: Vec<u8>) -> NextShot {
        NextShot {
            shooter: Seat::A,
            cue_ball: CueBall::AsItLies,
            legal_first,
            call,
            break_shot: false,
            push_out_allowed: false,
            choices: Vec::new(),
            spot: Vec::new(),
            rerack: false,
            fouls_in_a_row: 0,
        }
    }

    fn path(number: u8, pocket: Option<Pocket>) -> BallPath {
        BallPath {
            number,
            points: Vec::new(),
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
        let solids = next(CallRule::Optional, vec![1, 2, 3, 4, 5, 6, 7]);
        assert_eq!(
            proposed_call(&solids, &aim),
            Some(Call::Ball {
                ball: 3,
                pocket: Pocket::FootRight
            })
        );
        let stripes = next(CallRule::Optional, vec![9, 10]);
        assert_eq!(
            proposed_call(&stripes, &aim),
            Some(Call::Ball {
                ball: 9,
                pocket: Pocket::SideRight
            })
        );
        assert_eq!(
            proposed_call(&next(CallRule::EightPocket, vec![8]), &aim),
            None
        );
        assert_eq!(proposed_call(&next(CallRule::NotUsed, vec![3]), &aim), None);
    }

    /// Issue 48: with no pocket in the aim's paths, the dialog opens on the ball the aim
    /// hits first (the 6), not the lowest (the 1); a ball that may not be called is passed
    /// over for the lowest; the 8 when it must be called.
    #[test]
    fn the_call_dialog_opens_on_the_ball_aimed_at() {
        use crate::play::aim::FirstContact;
        let solids = next(CallRule::Optional, vec![1, 2, 3, 4, 5, 6, 7]);
        let on = |number| AimPrediction {
            contact: Some((FirstContact::Ball { number }, DVec2::ZERO)),
            ..Default::default()
        };
        assert_eq!(preselected_ball(&solids, None, Some(&on(6))), Some(6));
        assert_eq!(preselected_ball(&solids, None, Some(&on(12))), Some(1));
        assert_eq!(preselected_ball(&solids, None, None), Some(1));
        let proposed = Some(Call::Ball {
            ball: 3,
            pocket: Pocket::FootRight,
        });
        assert_eq!(preselected_ball(&solids, proposed, Some(&on(6))), Some(3));
        let eight = next(CallRule::EightPocket, vec![8]);
        assert_eq!(preselected_ball(&eight, None, Some(&on(6))), Some(8));
    }
}
