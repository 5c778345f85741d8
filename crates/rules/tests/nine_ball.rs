//! 9-ball scenarios from hand-made shot summaries, each named after the WPA rule it pins
//! (Rules of Play, 2008 numbering: 2 nine ball, 6 fouls).

mod common;

use billiards_physics::Pocket::*;
use billiards_rules::*;
use common::{after_break, shot};

fn rack() -> GameState {
    GameState::new(Game::NineBall, Seat::A)
}

#[test]
fn wpa_2_2_2_3_the_break_is_behind_the_head_string_at_the_1() {
    let g = rack();
    assert!(g.next.break_shot);
    assert_eq!(g.next.shooter, Seat::A);
    assert_eq!(g.next.cue_ball, CueBall::InHandBehindHeadString);
    assert_eq!(g.next.legal_first, vec![1]);
    assert_eq!(g.next.call, CallRule::NotUsed);
    assert_eq!(g.on_table, (1..=9).collect::<Vec<u8>>());
}

#[test]
fn wpa_2_3_a_break_that_pockets_a_ball_keeps_the_breaker_with_a_push_out_allowed() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2, 3], &[(4, FootLeft)]), Call::None)
        .unwrap();
    assert!(v.legal() && v.break_shot);
    assert_eq!(v.outcome, Outcome::Continues);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert!(next.push_out_allowed);
    assert_eq!(next.cue_ball, CueBall::AsItLies);
    assert_eq!(next.legal_first, vec![1]);
    assert!(!g.on_table.contains(&4));
}

#[test]
fn wpa_2_3_a_break_with_four_balls_to_a_rail_passes_with_a_push_out_allowed() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2, 3, 5, 7], &[]), Call::None)
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert!(next.push_out_allowed);
}

#[test]
fn wpa_2_3_a_break_with_three_balls_to_a_rail_is_a_foul_ball_in_hand_anywhere() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2, 3, 0, 5], &[]), Call::None)
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::IllegalBreak { to_rail: 3 }]);
    assert_eq!(
        v.reason(),
        "foul: illegal break: no ball pocketed and 3 balls to a rail, 4 needed"
    );
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert!(
        !next.push_out_allowed,
        "WPA 2.4: no push out after a foul break"
    );
    assert_eq!(g.fouls, [1, 0]);
}

#[test]
fn wpa_2_3_6_2_a_break_that_hits_the_2_first_is_a_foul() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(2), &[1, 3, 4, 5], &[(6, SideLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBallFirst {
            hit: 2,
            on: BallOn::Lowest(1)
        }]
    );
    assert_eq!(
        v.reason(),
        "foul: the 2 was hit first, the 1 was the lowest ball"
    );
    assert_eq!(v.outcome, Outcome::Passes);
    assert!(!g.on_table.contains(&6), "WPA 2.6: only the 9 is spotted");
}

#[test]
fn wpa_2_3_6_1_a_scratch_on_the_break_is_ball_in_hand_anywhere_without_push_out() {
    let mut g = rack();
    let v = g
        .play(
            &shot(Some(1), &[2, 3], &[(5, FootLeft), (0, HeadRight)]),
            Call::None,
        )
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert!(!next.push_out_allowed);
}

#[test]
fn wpa_2_5_the_9_on_a_legal_break_wins() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2], &[(9, FootRight)]), Call::None)
        .unwrap();
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason: WinReason::NinePocketed
        }
    );
    assert_eq!(v.next, None);
    assert_eq!(g.over, Some((Seat::A, WinReason::NinePocketed)));
    assert_eq!(
        g.play(&shot(Some(1), &[], &[]), Call::None),
        Err(RuleError::GameOver)
    );
}

#[test]
fn wpa_2_6_the_9_on_a_foul_break_is_spotted() {
    let mut g = rack();
    let v = g
        .play(
            &shot(Some(1), &[2], &[(9, FootRight), (0, SideLeft)]),
            Call::None,
        )
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.spot, vec![9]);
    assert!(g.on_table.contains(&9));
}

#[test]
fn wpa_2_4_a_push_out_needs_no_contact_and_offers_shoot_or_pass() {
    let mut g = after_break(Game::NineBall);
    assert!(g.next.push_out_allowed);
    assert_eq!(g.next.shooter, Seat::B);
    let v = g.play(&shot(None, &[], &[]), Call::PushOut).unwrap();
    assert!(v.legal() && v.push_out);
    assert_eq!(v.reason(), "legal push out");
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert_eq!(next.choices, vec![Choice::ShootFromHere, Choice::PassBack]);
    assert!(matches!(
        g.play(&shot(Some(1), &[1], &[]), Call::None),
        Err(RuleError::ChoicePending(_))
    ));
}

#[test]
fn wpa_2_4_after_a_push_out_the_incoming_player_may_pass_it_back() {
    let mut g = after_break(Game::NineBall);
    g.play(&shot(None, &[], &[]), Call::PushOut).unwrap();
    let next = g.choose(Choice::PassBack).unwrap();
    assert_eq!(next.shooter, Seat::B, "the player who pushed shoots again");
    assert_eq!(next.cue_ball, CueBall::AsItLies);
    assert!(next.choices.is_empty() && !next.push_out_allowed);
    assert!(matches!(
        g.choose(Choice::PassBack),
        Err(RuleError::ChoiceNotOffered { .. })
    ));
}

#[test]
fn wpa_2_4_after_a_push_out_the_incoming_player_may_shoot_from_there() {
    let mut g = after_break(Game::NineBall);
    g.play(&shot(Some(5), &[], &[]), Call::PushOut).unwrap();
    let next = g.choose(Choice::ShootFromHere).unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert_eq!(next.legal_first, vec![1]);
    // The next shot is ordinary: the wrong ball first is a foul again.
    let v = g.play(&shot(Some(5), &[5], &[]), Call::None).unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBallFirst {
            hit: 5,
            on: BallOn::Lowest(1)
        }]
    );
}

#[test]
fn wpa_2_4_a_push_out_is_refused_after_the_first_shot_after_the_break() {
    let mut g = after_break(Game::NineBall);
    g.play(&shot(Some(1), &[1], &[]), Call::None).unwrap();
    assert!(!g.next.push_out_allowed);
    assert_eq!(
        g.play(&shot(None, &[], &[]), Call::PushOut),
        Err(RuleError::PushOutNotAllowed)
    );
}

#[test]
fn wpa_2_6_the_9_pocketed_on_a_push_out_is_spotted_other_balls_stay_down() {
    let mut g = after_break(Game::NineBall);
    let v = g
        .play(
            &shot(Some(6), &[], &[(9, FootLeft), (3, SideRight)]),
            Call::PushOut,
        )
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.next.unwrap().spot, vec![9]);
    assert!(g.on_table.contains(&9) && !g.on_table.contains(&3));
}

#[test]
fn wpa_2_4_6_1_a_scratch_on_a_push_out_is_a_foul() {
    let mut g = after_break(Game::NineBall);
    let v = g
        .play(&shot(None, &[], &[(0, HeadLeft)]), Call::PushOut)
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    let next = v.next.unwrap();
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert!(next.choices.is_empty());
}

#[test]
fn wpa_2_5_the_lowest_ball_first_and_a_pocket_keeps_the_shooter() {
    let mut g = after_break(Game::NineBall);
    let v = g
        .play(&shot(Some(1), &[], &[(1, FootLeft)]), Call::None)
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Continues);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.legal_first, vec![2], "the 2 is now the lowest");
}

#[test]
fn wpa_2_5_the_lowest_ball_first_and_a_rail_without_a_pocket_passes() {
    let mut g = after_break(Game::NineBall);
    let v = g.play(&shot(Some(1), &[1], &[]), Call::None).unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!((next.shooter, next.cue_ball), (Seat::A, CueBall::AsItLies));
}

#[test]
fn wpa_6_2_the_wrong_ball_first_is_a_foul_naming_both_balls() {
    let mut g = after_break(Game::NineBall);
    g.play(&shot(Some(1), &[], &[(1, FootLeft)]), Call::None)
        .unwrap();
    let v = g
        .play(&shot(Some(3), &[3], &[(3, SideLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        v.reason(),
        "foul: the 3 was hit first, the 2 was the lowest ball"
    );
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(v.next.unwrap().cue_ball, CueBall::InHandAnywhere);
    assert!(
        !g.on_table.contains(&3),
        "balls pocketed on a foul stay down"
    );
}

#[test]
fn wpa_6_2_hitting_no_ball_is_a_foul() {
    let mut g = after_break(Game::NineBall);
    let v = g.play(&shot(None, &[0], &[]), Call::None).unwrap();
    assert_eq!(v.fouls, vec![Foul::NoBallHit]);
    assert_eq!(v.reason(), "foul: the cue ball hit no ball");
    assert_eq!(v.next.unwrap().cue_ball, CueBall::InHandAnywhere);
}

#[test]
fn wpa_6_3_no_rail_after_the_contact_is_a_foul() {
    let mut g = after_break(Game::NineBall);
    let v = g.play(&shot(Some(1), &[], &[]), Call::None).unwrap();
    assert_eq!(v.fouls, vec![Foul::NoRail]);
    let next = v.next.unwrap();
    assert_eq!(
        (next.shooter, next.cue_ball),
        (Seat::A, CueBall::InHandAnywhere)
    );
}

#[test]
fn wpa_6_3_the_cue_ball_to_a_rail_after_the_contact_is_enough() {
    let mut g = after_break(Game::NineBall);
    let v = g.play(&shot(Some(1), &[0], &[]), Call::None).unwrap();
    assert!(v.legal(), "{}", v.reason());
}

#[test]
fn wpa_2_5_a_combination_on_the_9_wins() {
    let mut g = after_break(Game::NineBall);
    let v = g
        .play(&shot(Some(1), &[], &[(9, FootLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::B,
            reason: WinReason::NinePocketed
        }
    );
}

#[test]
fn wpa_2_6_the_9_pocketed_on_a_wrong_ball_foul_is_spotted() {
    let mut g = after_break(Game::NineBall);
    let v = g
        .play(
            &shot(Some(2), &[], &[(9, FootLeft), (2, SideRight)]),
            Call::None,
        )
        .unwrap();
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(v.next.unwrap().spot, vec![9]);
    assert!(g.on_table.contains(&9) && !g.on_table.contains(&2));
    assert_eq!(g.over, None);
}

#[test]
fn wpa_2_8_6_14_three_fouls_in_a_row_lose_the_rack() {
    let mut g = after_break(Game::NineBall);
    // B fouls, A plays legally (a miss), B fouls, A misses, B fouls the third time.
    for k in 1..=3u8 {
        let v = g.play(&shot(None, &[], &[]), Call::None).unwrap();
        assert_eq!(v.shooter, Seat::B);
        if k < 3 {
            assert_eq!(v.outcome, Outcome::Passes);
            assert_eq!(g.fouls[1], k);
            // A shoots with ball in hand and misses: B is back at the table.
            let v = g.play(&shot(Some(1), &[1], &[]), Call::None).unwrap();
            assert!(v.legal());
            assert_eq!(v.next.as_ref().unwrap().fouls_in_a_row, k);
        } else {
            assert_eq!(
                v.outcome,
                Outcome::GameOver {
                    winner: Seat::A,
                    reason: WinReason::ThreeFouls
                }
            );
        }
    }
}

#[test]
fn wpa_6_14_a_legal_shot_between_fouls_resets_the_count() {
    let mut g = after_break(Game::NineBall);
    g.play(&shot(None, &[], &[]), Call::None).unwrap(); // B: 1
    g.play(&shot(Some(1), &[1], &[]), Call::None).unwrap(); // A misses
    g.play(&shot(None, &[], &[]), Call::None).unwrap(); // B: 2
    g.play(&shot(Some(1), &[1], &[]), Call::None).unwrap(); // A misses
    let v = g.play(&shot(Some(1), &[1], &[]), Call::None).unwrap(); // B legal
    assert!(v.legal());
    assert_eq!(g.fouls[1], 0);
    g.play(&shot(None, &[], &[]), Call::None).unwrap(); // A: 1
    let v = g.play(&shot(None, &[], &[]), Call::None).unwrap(); // B: 1 again
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(g.fouls, [1, 1]);
}

#[test]
fn wpa_2_shots_are_not_called_in_nine_ball() {
    let mut g = after_break(Game::NineBall);
    let call = Call::Ball {
        ball: 1,
        pocket: FootLeft,
    };
    assert!(matches!(
        g.play(&shot(Some(1), &[], &[]), call),
        Err(RuleError::CallNotUsed(Game::NineBall, _))
    ));
    assert_eq!(g.next.shooter, Seat::B, "a refused shot changes nothing");
}

#[test]
fn a_summary_pocketing_a_ball_already_off_the_table_is_refused() {
    let mut g = after_break(Game::NineBall);
    g.play(&shot(Some(1), &[], &[(1, FootLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        g.play(&shot(Some(2), &[], &[(1, FootLeft)]), Call::None),
        Err(RuleError::UnknownBall(1))
    );
}
