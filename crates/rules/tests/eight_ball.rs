//! 8-ball scenarios from hand-made shot summaries, each named after the WPA rule it pins
//! (Rules of Play, 2008 numbering: 1 general, 3 eight ball, 6 fouls).

mod common;

use billiards_physics::Pocket::*;
use billiards_rules::*;
use common::{after_break, shot};

fn rack() -> GameState {
    GameState::new(Game::EightBall, Seat::A)
}

fn call(ball: u8, pocket: billiards_physics::Pocket) -> Call {
    Call::Ball { ball, pocket }
}

/// B at the table with stripes, A with solids; only `solids` and `stripes` (and the 8)
/// remain, cleared by B's legal shots.
fn groups(solids: &[u8], stripes: &[u8]) -> GameState {
    let mut g = after_break(Game::EightBall);
    let v = g
        .play(&shot(Some(10), &[], &[(10, FootLeft)]), call(10, FootLeft))
        .unwrap();
    assert_eq!(v.assigned, Some(Group::Stripes));
    // One shot: a stripe first, then every unwanted ball down (solids stay down too).
    let mut gone: Vec<u8> = g
        .on_table
        .iter()
        .copied()
        .filter(|b| *b != 8 && !solids.contains(b) && !stripes.contains(b))
        .collect();
    gone.sort_by_key(|&b| Group::of(b) != Some(Group::Stripes));
    let pocketed: Vec<_> = gone.iter().map(|&b| (b, FootRight)).collect();
    let v = g
        .play(&shot(Some(gone[0]), &[], &pocketed), Call::None)
        .unwrap();
    assert_eq!(v.outcome, Outcome::Continues);
    assert_eq!(g.next.shooter, Seat::B);
    g
}

#[test]
fn wpa_3_3_a_break_that_pockets_a_ball_keeps_the_breaker_on_an_open_table() {
    let mut g = rack();
    assert_eq!(g.next.cue_ball, CueBall::InHandBehindHeadString);
    let v = g
        .play(
            &shot(Some(1), &[2], &[(3, FootLeft), (12, SideLeft)]),
            Call::None,
        )
        .unwrap();
    assert!(v.legal() && v.break_shot);
    assert_eq!(v.outcome, Outcome::Continues);
    assert_eq!(
        v.assigned, None,
        "WPA 3.5: the table is open after the break"
    );
    assert_eq!(g.group_a, None);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert!(!next.legal_first.contains(&8) && next.legal_first.contains(&1));
    assert_eq!(next.call, CallRule::Optional);
}

#[test]
fn wpa_3_3_a_break_with_four_balls_to_a_rail_and_no_pocket_passes() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(5), &[2, 3, 9, 11], &[]), Call::None)
        .unwrap();
    assert!(v.legal(), "WPA 3.3 needs no particular ball first");
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!((next.shooter, next.cue_ball), (Seat::B, CueBall::AsItLies));
    assert!(next.choices.is_empty());
}

#[test]
fn wpa_3_3_an_illegal_break_offers_the_table_or_a_re_rack() {
    let mut g = rack();
    let v = g.play(&shot(Some(1), &[2, 3], &[]), Call::None).unwrap();
    assert_eq!(v.fouls, vec![Foul::IllegalBreak { to_rail: 2 }]);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(
        next.choices,
        vec![
            Choice::ShootFromHere,
            Choice::RerackAndBreak,
            Choice::RerackOpponentBreaks
        ]
    );
    assert!(matches!(
        g.play(&shot(Some(1), &[1], &[]), Call::None),
        Err(RuleError::ChoicePending(_))
    ));
}

#[test]
fn wpa_3_3_accepting_an_illegal_break_shoots_the_table_as_it_lies() {
    let mut g = rack();
    g.play(&shot(Some(1), &[2], &[]), Call::None).unwrap();
    let next = g.choose(Choice::ShootFromHere).unwrap();
    assert_eq!((next.shooter, next.cue_ball), (Seat::B, CueBall::AsItLies));
    assert!(!next.break_shot && !next.rerack);
}

#[test]
fn wpa_3_3_accepting_an_illegal_break_with_a_scratch_is_behind_the_head_string() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2], &[(0, FootLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::Scratch, Foul::IllegalBreak { to_rail: 1 }]
    );
    let next = g.choose(Choice::ShootFromHere).unwrap();
    assert_eq!(next.cue_ball, CueBall::InHandBehindHeadString);
}

#[test]
fn wpa_3_3_after_an_illegal_break_the_offender_may_be_made_to_break_again() {
    let mut g = rack();
    g.play(&shot(Some(1), &[2], &[]), Call::None).unwrap();
    let next = g.choose(Choice::RerackOpponentBreaks).unwrap();
    assert!(next.rerack && next.break_shot);
    assert_eq!(next.shooter, Seat::A);
    assert_eq!(next.cue_ball, CueBall::InHandBehindHeadString);
    assert_eq!(g.breaker, Seat::A);
    assert_eq!(g.on_table.len(), 15);
}

#[test]
fn wpa_3_3_after_an_illegal_break_the_incoming_player_may_break_a_new_rack() {
    let mut g = rack();
    g.play(&shot(Some(1), &[2], &[]), Call::None).unwrap();
    let next = g.choose(Choice::RerackAndBreak).unwrap();
    assert!(next.rerack && next.break_shot);
    assert_eq!((next.shooter, g.breaker), (Seat::B, Seat::B));
}

#[test]
fn wpa_3_3_the_8_on_the_break_lets_the_breaker_spot_it_and_continue() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2, 3], &[(8, SideRight)]), Call::None)
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Continues);
    assert_eq!(g.over, None, "the 8 on the break neither wins nor loses");
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert_eq!(
        next.choices,
        vec![Choice::SpotEightAndShoot, Choice::RerackAndBreak]
    );
    let next = g.choose(Choice::SpotEightAndShoot).unwrap();
    assert_eq!(next.spot, vec![8]);
    assert_eq!((next.shooter, next.cue_ball), (Seat::A, CueBall::AsItLies));
    assert!(g.on_table.contains(&8));
}

#[test]
fn wpa_3_3_the_8_on_the_break_lets_the_breaker_break_again() {
    let mut g = rack();
    g.play(&shot(Some(1), &[2, 3], &[(8, SideRight)]), Call::None)
        .unwrap();
    let next = g.choose(Choice::RerackAndBreak).unwrap();
    assert!(next.rerack && next.break_shot);
    assert_eq!(next.shooter, Seat::A);
}

#[test]
fn wpa_3_3_the_8_and_a_scratch_on_the_break_give_the_opponent_the_choice() {
    let mut g = rack();
    let v = g
        .play(
            &shot(Some(1), &[2], &[(8, FootLeft), (0, HeadLeft)]),
            Call::None,
        )
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    assert_eq!(g.over, None, "not a loss on the break");
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(
        next.choices,
        vec![Choice::SpotEightAndShoot, Choice::RerackAndBreak]
    );
    let next = g.choose(Choice::SpotEightAndShoot).unwrap();
    assert_eq!(next.cue_ball, CueBall::InHandBehindHeadString);
    assert_eq!((next.shooter, next.spot.clone()), (Seat::B, vec![8]));
}

#[test]
fn wpa_3_3_a_scratch_on_a_legal_break_is_ball_in_hand_behind_the_head_string() {
    let mut g = rack();
    let v = g
        .play(
            &shot(Some(1), &[2, 3, 4, 5], &[(9, FootLeft), (0, SideLeft)]),
            Call::None,
        )
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    assert_eq!(v.reason(), "foul: the cue ball was pocketed");
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.cue_ball, CueBall::InHandBehindHeadString);
    assert!(next.choices.is_empty());
    assert_eq!(g.group_a, None, "the table stays open");
    assert!(
        !g.on_table.contains(&9),
        "balls pocketed on the break stay down"
    );
}

#[test]
fn wpa_3_5_the_8_first_on_an_open_table_is_a_foul() {
    let mut g = after_break(Game::EightBall);
    let v = g.play(&shot(Some(8), &[8], &[]), Call::None).unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBallFirst {
            hit: 8,
            on: BallOn::AnyButEight
        }]
    );
    assert_eq!(v.reason(), "foul: the 8 was hit first on an open table");
}

#[test]
fn wpa_3_5_on_an_open_table_a_solid_may_be_hit_to_pocket_a_called_stripe() {
    let mut g = after_break(Game::EightBall);
    let v = g
        .play(&shot(Some(2), &[], &[(12, FootRight)]), call(12, FootRight))
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.assigned, Some(Group::Stripes));
    assert_eq!(v.outcome, Outcome::Continues);
    assert_eq!(g.group(Seat::B), Some(Group::Stripes));
    assert_eq!(g.group(Seat::A), Some(Group::Solids));
    let next = v.next.unwrap();
    assert_eq!(next.legal_first, vec![9, 10, 11, 13, 14, 15]);
}

#[test]
fn wpa_3_5_an_obvious_shot_without_a_call_assigns_the_group_of_the_ball() {
    let mut g = after_break(Game::EightBall);
    let v = g
        .play(&shot(Some(3), &[], &[(3, SideLeft)]), Call::None)
        .unwrap();
    assert_eq!(v.assigned, Some(Group::Solids));
    assert_eq!(g.group(Seat::B), Some(Group::Solids));
}

#[test]
fn wpa_3_5_slop_on_an_open_table_ends_the_turn_and_leaves_it_open() {
    let mut g = after_break(Game::EightBall);
    // The 3 was called in the foot-left corner; the 11 dropped in a side pocket instead.
    let v = g
        .play(&shot(Some(3), &[3], &[(11, SideLeft)]), call(3, FootLeft))
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(v.assigned, None);
    assert_eq!(g.group_a, None);
    assert!(!g.on_table.contains(&11), "the 11 stays down");
}

#[test]
fn wpa_3_5_a_ball_pocketed_on_a_foul_assigns_no_group() {
    let mut g = after_break(Game::EightBall);
    let v = g
        .play(
            &shot(Some(3), &[], &[(3, SideLeft), (0, FootLeft)]),
            call(3, SideLeft),
        )
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    assert_eq!(v.assigned, None);
    assert_eq!(g.group_a, None);
}

#[test]
fn wpa_3_6_6_2_hitting_the_other_group_first_is_a_foul() {
    let mut g = groups(&[1, 2], &[9, 11]);
    // B (stripes) is at the table.
    let v = g.play(&shot(Some(2), &[2], &[]), Call::None).unwrap();
    assert_eq!(v.reason(), "foul: the 2 was hit first, stripes were on");
    let next = v.next.unwrap();
    assert_eq!(
        (next.shooter, next.cue_ball),
        (Seat::A, CueBall::InHandAnywhere)
    );
    assert_eq!(next.legal_first, vec![1, 2]);
}

#[test]
fn wpa_3_6_a_called_ball_in_another_pocket_ends_the_turn() {
    let mut g = groups(&[1, 2], &[9, 11]);
    let v = g
        .play(&shot(Some(9), &[], &[(9, SideLeft)]), call(9, FootLeft))
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Passes);
    assert!(!g.on_table.contains(&9));
}

#[test]
fn wpa_1_6_a_called_safety_ends_the_turn_even_if_a_ball_drops() {
    let mut g = groups(&[1, 2], &[9, 11]);
    let v = g
        .play(&shot(Some(9), &[], &[(9, SideLeft)]), Call::Safety)
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(v.next.unwrap().shooter, Seat::A);
}

#[test]
fn wpa_3_8_pocketing_the_8_before_the_group_is_cleared_loses() {
    let mut g = groups(&[1, 2], &[9, 11]);
    let v = g
        .play(&shot(Some(9), &[], &[(8, FootLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason: WinReason::EightEarly
        }
    );
}

#[test]
fn wpa_3_8_pocketing_the_8_with_the_last_group_ball_loses() {
    let mut g = groups(&[1, 2], &[11]);
    let v = g
        .play(
            &shot(Some(11), &[], &[(11, SideLeft), (8, FootLeft)]),
            call(11, SideLeft),
        )
        .unwrap();
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason: WinReason::EightEarly
        }
    );
}

#[test]
fn wpa_3_8_pocketing_the_8_early_on_an_open_table_loses() {
    let mut g = after_break(Game::EightBall);
    let v = g
        .play(&shot(Some(3), &[], &[(8, FootLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason: WinReason::EightEarly
        }
    );
}

#[test]
fn wpa_3_6_on_the_8_the_call_is_required_and_only_the_8_is_legal() {
    let g = groups(&[1, 2], &[]);
    assert_eq!(g.next.legal_first, vec![8]);
    assert_eq!(g.next.call, CallRule::EightPocket);
}

#[test]
fn wpa_3_6_the_8_in_the_called_pocket_wins() {
    let mut g = groups(&[1, 2], &[]);
    let v = g
        .play(&shot(Some(8), &[], &[(8, HeadLeft)]), call(8, HeadLeft))
        .unwrap();
    assert!(v.legal());
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::B,
            reason: WinReason::EightPocketed
        }
    );
}

#[test]
fn wpa_3_8_the_8_in_another_pocket_than_the_called_one_loses() {
    let mut g = groups(&[1, 2], &[]);
    let v = g
        .play(&shot(Some(8), &[], &[(8, FootRight)]), call(8, HeadLeft))
        .unwrap();
    let reason = WinReason::EightWrongPocket {
        called: Some(HeadLeft),
        went: FootRight,
    };
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason
        }
    );
}

#[test]
fn wpa_3_8_the_8_without_a_call_loses() {
    let mut g = groups(&[1, 2], &[]);
    let v = g
        .play(&shot(Some(8), &[], &[(8, FootRight)]), Call::None)
        .unwrap();
    assert!(matches!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason: WinReason::EightWrongPocket { called: None, .. }
        }
    ));
}

#[test]
fn wpa_3_8_the_8_with_a_scratch_loses() {
    let mut g = groups(&[1, 2], &[]);
    let v = g
        .play(
            &shot(Some(8), &[], &[(8, HeadLeft), (0, SideRight)]),
            call(8, HeadLeft),
        )
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason: WinReason::EightOnFoul
        }
    );
}

#[test]
fn wpa_3_7_a_foul_gives_ball_in_hand_anywhere() {
    let mut g = groups(&[1, 2], &[9, 11]);
    let v = g.play(&shot(Some(9), &[], &[]), Call::None).unwrap();
    assert_eq!(v.fouls, vec![Foul::NoRail]);
    let next = v.next.unwrap();
    assert_eq!(
        (next.shooter, next.cue_ball),
        (Seat::A, CueBall::InHandAnywhere)
    );
}

#[test]
fn wpa_6_14_eight_ball_has_no_three_foul_loss() {
    let mut g = after_break(Game::EightBall);
    for _ in 0..3 {
        let v = g.play(&shot(None, &[], &[]), Call::None).unwrap(); // B fouls
        assert_eq!(v.outcome, Outcome::Passes);
        g.play(&shot(Some(1), &[1], &[]), Call::None).unwrap(); // A misses legally
    }
    assert_eq!(g.fouls[1], 3, "counted for the HUD, never a loss");
    assert_eq!(g.over, None);
}

#[test]
fn wpa_1_6_a_call_naming_a_ball_off_the_table_is_refused() {
    let mut g = groups(&[1, 2], &[9, 11]);
    assert_eq!(
        g.play(&shot(Some(10), &[], &[]), call(10, FootLeft)),
        Err(RuleError::BallNotOnTable(10))
    );
}

#[test]
fn wpa_3_6_a_call_of_the_other_group_or_the_early_8_is_refused() {
    let mut g = groups(&[1, 2], &[9, 11]);
    assert!(matches!(
        g.play(&shot(Some(1), &[], &[]), call(1, FootLeft)),
        Err(RuleError::IllegalCall { ball: 1, .. })
    ));
    assert!(matches!(
        g.play(&shot(Some(8), &[], &[]), call(8, FootLeft)),
        Err(RuleError::IllegalCall { ball: 8, .. })
    ));
    assert_eq!(
        g.play(&shot(Some(9), &[], &[]), Call::PushOut),
        Err(RuleError::CallNotUsed(Game::EightBall, "push out"))
    );
}

/// Issue 48: the verdict says what went in and where, and whether a called ball went where
/// it was called (WPA 1.6): a made call, a call that missed, a ball in another pocket and a
/// shot that hit nothing read differently.
#[test]
fn what_happened_names_the_balls_the_pockets_and_the_call() {
    let made = shot(Some(7), &[], &[(7, SideRight)]);
    assert_eq!(
        what_happened(&made, call(7, SideRight), &[]),
        "the 7 in the right side pocket"
    );
    let missed = shot(Some(7), &[7], &[]);
    assert_eq!(
        what_happened(&missed, call(7, SideRight), &[]),
        "the 7 missed the called right side pocket; nothing pocketed"
    );
    let elsewhere = shot(Some(7), &[], &[(7, FootLeft), (0, HeadRight)]);
    assert_eq!(
        what_happened(&elsewhere, call(7, SideRight), &[]),
        "the 7 went in the foot-left corner, not the called right side pocket; \
         the 7 in the foot-left corner, the cue ball in the head-right corner"
    );
    // A cue ball that hit nothing pocketed nothing: said once.
    assert_eq!(
        what_happened(&shot(None, &[], &[]), Call::None, &[]),
        "no ball hit"
    );
}

/// Issue 48: what a shot did leaves out what its fouls already say (WPA 6.2, 2.3 / 3.3).
#[test]
fn what_happened_does_not_repeat_the_fouls() {
    let nothing = shot(None, &[], &[]);
    assert_eq!(what_happened(&nothing, Call::None, &[Foul::NoBallHit]), "");
    let illegal_break = [Foul::IllegalBreak { to_rail: 0 }];
    assert_eq!(
        what_happened(&nothing, Call::None, &illegal_break),
        "no ball hit"
    );
    let soft = shot(Some(1), &[], &[]);
    assert_eq!(what_happened(&soft, Call::None, &illegal_break), "");
    assert_eq!(what_happened(&soft, Call::None, &[Foul::NoRail]), "");
    // A foul that says nothing of pocketing keeps "nothing pocketed".
    let wrong = [Foul::WrongBallFirst {
        hit: 5,
        on: BallOn::Lowest(1),
    }];
    assert_eq!(
        what_happened(&soft, call(7, SideRight), &wrong),
        "the 7 missed the called right side pocket; nothing pocketed"
    );
}
