//! 10-ball scenarios from hand-made shot summaries, each named after the WPA rule it pins
//! (Rules of Play, section 9 ten ball, in force from 1 January 2009; 6 fouls).

mod common;

use billiards_physics::Pocket::*;
use billiards_rules::*;
use common::{after_break, shot};

fn rack() -> GameState {
    GameState::new(Game::TenBall, Seat::A)
}

fn called(ball: u8, pocket: billiards_physics::Pocket) -> Call {
    Call::Ball { ball, pocket }
}

/// After a legal break by A and a push-out-free first shot by B that made nothing: A at the
/// table, no push out allowed any more.
fn in_play() -> GameState {
    let mut g = after_break(Game::TenBall);
    let v = g
        .play(&shot(Some(1), &[1], &[]), called(1, FootLeft))
        .unwrap();
    assert!(v.legal());
    assert_eq!(g.next.shooter, Seat::A);
    g
}

#[test]
fn wpa_9_2_9_3_the_break_is_behind_the_head_string_at_the_1_with_ten_balls() {
    let g = rack();
    assert!(g.next.break_shot);
    assert_eq!(g.next.cue_ball, CueBall::InHandBehindHeadString);
    assert_eq!(g.next.legal_first, vec![1]);
    assert_eq!(
        g.next.call,
        CallRule::NotUsed,
        "WPA 9: no call on the break"
    );
    assert_eq!(g.on_table, (1..=10).collect::<Vec<u8>>());
    assert_eq!(Game::TenBall.object_balls().len(), 10);
}

#[test]
fn wpa_9_no_ball_may_be_called_on_the_break() {
    let mut g = rack();
    let r = g.play(
        &shot(Some(1), &[2, 3], &[(4, FootLeft)]),
        called(4, FootLeft),
    );
    assert_eq!(
        r,
        Err(RuleError::CallNotUsed(Game::TenBall, "call on the break"))
    );
    assert_eq!(g, rack(), "a refused shot changes nothing");
}

#[test]
fn wpa_9_3_9_4_a_break_that_pockets_a_ball_keeps_the_breaker_with_a_push_out_allowed() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2, 3], &[(4, FootLeft)]), Call::None)
        .unwrap();
    assert!(v.legal() && v.break_shot);
    assert_eq!(v.outcome, Outcome::Continues);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert!(next.push_out_allowed);
    assert_eq!(next.call, CallRule::BallAndPocket, "WPA 9.5: called shots");
    assert_eq!(next.legal_first, vec![1]);
    assert!(!g.on_table.contains(&4));
}

#[test]
fn wpa_9_3_a_break_with_four_balls_to_a_rail_passes_with_a_push_out_allowed() {
    let g = after_break(Game::TenBall);
    assert_eq!(g.next.shooter, Seat::B);
    assert!(g.next.push_out_allowed);
    assert_eq!(g.next.cue_ball, CueBall::AsItLies);
}

#[test]
fn wpa_9_3_9_10_a_break_with_three_balls_to_a_rail_is_a_foul_ball_in_hand_anywhere() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2, 3, 0, 5], &[]), Call::None)
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::IllegalBreak { to_rail: 3 }]);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert!(!next.push_out_allowed, "WPA 9.4: no push out after a foul");
    assert_eq!(g.fouls, [1, 0]);
}

#[test]
fn wpa_9_3_6_2_a_break_that_hits_the_2_first_is_a_foul() {
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
    assert_eq!(v.outcome, Outcome::Passes);
    assert!(!g.on_table.contains(&6), "WPA 9.9: only the 10 is spotted");
}

#[test]
fn wpa_9_9_the_10_on_a_legal_break_is_spotted_and_the_breaker_continues() {
    let mut g = rack();
    let v = g
        .play(&shot(Some(1), &[2], &[(10, FootRight)]), Call::None)
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Continues, "no win on the break");
    assert_eq!(g.over, None);
    assert!(g.on_table.contains(&10));
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert_eq!(next.spot, vec![10]);
    assert!(next.push_out_allowed);
}

#[test]
fn wpa_9_9_9_10_the_10_on_a_foul_break_is_spotted_and_the_opponent_has_ball_in_hand() {
    let mut g = rack();
    let v = g
        .play(
            &shot(Some(1), &[2], &[(10, FootRight), (0, SideLeft)]),
            Call::None,
        )
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch]);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert_eq!(next.spot, vec![10]);
    assert!(g.on_table.contains(&10));
}

#[test]
fn wpa_9_4_a_push_out_hands_the_choice_over_and_spots_a_10_made_on_it() {
    let mut g = after_break(Game::TenBall);
    // A push out needs no contact with the lowest ball and no rail (6.2, 6.3 suspended).
    let v = g
        .play(&shot(Some(7), &[], &[(10, SideRight)]), Call::PushOut)
        .unwrap();
    assert!(v.legal() && v.push_out);
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A, "the other player chooses");
    assert_eq!(next.choices, vec![Choice::ShootFromHere, Choice::PassBack]);
    assert_eq!(next.spot, vec![10]);
    assert_eq!(g.over, None);
    let mut pass = g.clone();
    let back = pass.choose(Choice::PassBack).unwrap();
    assert_eq!(back.shooter, Seat::B, "the pusher shoots again");
    assert_eq!(back.call, CallRule::BallAndPocket);
    let here = g.choose(Choice::ShootFromHere).unwrap();
    assert_eq!(here.shooter, Seat::A);
    assert_eq!(here.call, CallRule::BallAndPocket);
    assert!(!here.push_out_allowed);
}

#[test]
fn wpa_9_4_a_push_out_is_only_the_shot_right_after_the_break() {
    let mut g = in_play();
    assert_eq!(
        g.play(&shot(Some(3), &[], &[]), Call::PushOut),
        Err(RuleError::PushOutNotAllowed)
    );
}

#[test]
fn wpa_9_5_the_called_ball_in_the_called_pocket_continues_and_others_stay_down() {
    let mut g = in_play();
    let v = g
        .play(
            &shot(Some(1), &[], &[(1, FootLeft), (6, SideRight)]),
            called(1, FootLeft),
        )
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Continues);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert!(next.choices.is_empty());
    assert_eq!(next.legal_first, vec![2]);
    assert!(!g.on_table.contains(&1) && !g.on_table.contains(&6));
}

#[test]
fn wpa_9_5_the_called_10_made_on_a_combination_wins() {
    let mut g = in_play();
    let v = g
        .play(
            &shot(Some(1), &[], &[(10, FootRight)]),
            called(10, FootRight),
        )
        .unwrap();
    assert!(v.legal());
    assert_eq!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::A,
            reason: WinReason::TenPocketed
        }
    );
    assert_eq!(g.over, Some((Seat::A, WinReason::TenPocketed)));
    assert_eq!(
        WinReason::TenPocketed.to_string(),
        "the called 10 was pocketed in the called pocket"
    );
}

#[test]
fn wpa_9_5_9_9_the_10_made_beside_the_called_ball_is_spotted_and_the_shooter_continues() {
    let mut g = in_play();
    let v = g
        .play(
            &shot(Some(1), &[], &[(1, SideLeft), (10, FootRight)]),
            called(1, SideLeft),
        )
        .unwrap();
    assert_eq!(v.outcome, Outcome::Continues);
    assert_eq!(g.over, None);
    assert!(g.on_table.contains(&10));
    assert_eq!(v.next.unwrap().spot, vec![10]);
}

#[test]
fn wpa_9_5_a_call_of_a_ball_off_the_table_is_refused() {
    let mut g = rack();
    g.play(&shot(Some(1), &[2], &[(4, FootLeft)]), Call::None)
        .unwrap();
    assert_eq!(
        g.play(&shot(Some(1), &[], &[]), called(4, FootLeft)),
        Err(RuleError::BallNotOnTable(4))
    );
}

#[test]
fn wpa_9_7_an_uncalled_ball_made_passes_the_turn_with_the_option_to_hand_it_back() {
    let mut g = in_play();
    let v = g
        .play(&shot(Some(1), &[], &[(5, SideLeft)]), called(1, FootLeft))
        .unwrap();
    assert!(v.legal(), "WPA 9.7: not a foul");
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.choices, vec![Choice::ShootFromHere, Choice::PassBack]);
    assert!(next.spot.is_empty());
    assert!(!g.on_table.contains(&5), "the 5 stays down");
    assert_eq!(
        g.play(&shot(Some(1), &[1], &[]), called(1, FootLeft)),
        Err(RuleError::ChoicePending(vec![
            Choice::ShootFromHere,
            Choice::PassBack
        ]))
    );
    let mut keep = g.clone();
    let here = keep.choose(Choice::ShootFromHere).unwrap();
    assert_eq!(here.shooter, Seat::B);
    assert_eq!(here.cue_ball, CueBall::AsItLies);
    let back = g.choose(Choice::PassBack).unwrap();
    assert_eq!(back.shooter, Seat::A, "handed back to the shooter");
    assert_eq!(back.call, CallRule::BallAndPocket);
}

#[test]
fn wpa_9_7_the_called_ball_in_another_pocket_gives_the_option_and_stays_down() {
    let mut g = in_play();
    let v = g
        .play(&shot(Some(1), &[], &[(1, FootRight)]), called(1, FootLeft))
        .unwrap();
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(
        v.next.unwrap().choices,
        vec![Choice::ShootFromHere, Choice::PassBack]
    );
    assert!(!g.on_table.contains(&1));
    assert_eq!(
        what_happened(
            &shot(Some(1), &[], &[(1, FootRight)]),
            called(1, FootLeft),
            &[]
        ),
        "the 1 went in the foot-right corner, not the called foot-left corner; \
         the 1 in the foot-right corner"
    );
}

#[test]
fn wpa_9_7_9_9_the_10_made_uncalled_on_a_legal_shot_is_spotted_with_the_option() {
    let mut g = in_play();
    let v = g
        .play(&shot(Some(1), &[], &[(10, SideLeft)]), called(1, FootLeft))
        .unwrap();
    assert!(v.legal());
    assert_eq!(g.over, None, "an uncalled 10 does not win");
    assert!(g.on_table.contains(&10));
    let next = v.next.unwrap();
    assert_eq!(next.spot, vec![10]);
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.choices, vec![Choice::ShootFromHere, Choice::PassBack]);
}

#[test]
fn wpa_9_7_a_shot_without_a_call_pockets_nothing_legally() {
    let mut g = in_play();
    let v = g
        .play(&shot(Some(1), &[], &[(1, FootLeft)]), Call::None)
        .unwrap();
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(
        v.next.unwrap().choices,
        vec![Choice::ShootFromHere, Choice::PassBack]
    );
}

#[test]
fn wpa_9_7_a_called_ball_missed_with_nothing_made_passes_without_a_choice() {
    let mut g = in_play();
    let v = g
        .play(&shot(Some(1), &[1], &[]), called(1, FootLeft))
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert!(next.choices.is_empty());
}

#[test]
fn wpa_9_6_9_7_a_called_safety_passes_and_a_ball_made_on_it_gives_the_option() {
    // Nothing made: the turn passes, no choice.
    let mut quiet = in_play();
    let v = quiet.play(&shot(Some(1), &[1], &[]), Call::Safety).unwrap();
    assert!(v.legal());
    let next = v.next.unwrap();
    assert_eq!((v.outcome, next.shooter), (Outcome::Passes, Seat::B));
    assert!(next.choices.is_empty());
    // Balls made on it: they stay down but the 10, and B shoots or hands it back.
    let mut g = in_play();
    let v = g
        .play(
            &shot(Some(1), &[], &[(3, SideLeft), (10, FootLeft)]),
            Call::Safety,
        )
        .unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.choices, vec![Choice::ShootFromHere, Choice::PassBack]);
    assert_eq!(next.spot, vec![10]);
    assert!(!g.on_table.contains(&3) && g.on_table.contains(&10));
}

#[test]
fn wpa_9_10_6_2_a_foul_gives_ball_in_hand_and_the_called_10_made_on_it_is_spotted() {
    let mut g = in_play();
    // The 10 called and made, but the 2 was hit first with the 1 on: a foul, no win.
    let v = g
        .play(
            &shot(Some(2), &[], &[(10, FootRight), (2, SideLeft)]),
            called(10, FootRight),
        )
        .unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBallFirst {
            hit: 2,
            on: BallOn::Lowest(1)
        }]
    );
    assert_eq!(g.over, None);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert!(next.choices.is_empty(), "no option after a foul");
    assert_eq!(next.spot, vec![10]);
    assert!(g.on_table.contains(&10) && !g.on_table.contains(&2));
}

#[test]
fn wpa_9_11_6_14_three_fouls_in_a_row_lose_the_rack() {
    let mut g = in_play();
    // A fouls, B shoots legally with ball in hand but misses, twice; A's third foul loses.
    for round in 1..=3u8 {
        let v = g.play(&shot(None, &[], &[]), called(1, FootLeft)).unwrap();
        assert_eq!(v.fouls, vec![Foul::NoBallHit]);
        assert_eq!(g.fouls[0], round);
        if round == 3 {
            assert_eq!(
                v.outcome,
                Outcome::GameOver {
                    winner: Seat::B,
                    reason: WinReason::ThreeFouls
                }
            );
            break;
        }
        assert_eq!(v.next.unwrap().fouls_in_a_row, 0);
        let v = g
            .play(&shot(Some(1), &[1], &[]), called(1, FootLeft))
            .unwrap();
        assert!(v.legal());
        assert_eq!(v.next.unwrap().fouls_in_a_row, round, "A on {round}");
    }
    assert_eq!(g.over, Some((Seat::B, WinReason::ThreeFouls)));
}

#[test]
fn wpa_9_11_a_legal_shot_clears_the_fouls_in_a_row() {
    let mut g = in_play();
    g.play(&shot(None, &[], &[]), Call::None).unwrap();
    g.play(&shot(Some(1), &[1], &[]), called(1, FootLeft))
        .unwrap();
    assert_eq!(g.fouls, [1, 0]);
    g.play(&shot(Some(1), &[1], &[]), called(1, FootLeft))
        .unwrap();
    assert_eq!(g.fouls, [0, 0]);
}

#[test]
fn a_ten_ball_rack_in_progress_is_on_the_lowest_with_a_call() {
    let g = GameState::in_progress(Game::TenBall, Seat::B, vec![10, 4, 7]);
    assert_eq!(g.on_table, vec![4, 7, 10]);
    assert_eq!(g.next.legal_first, vec![4]);
    assert_eq!(g.next.call, CallRule::BallAndPocket);
    assert!(!g.next.break_shot);
}
