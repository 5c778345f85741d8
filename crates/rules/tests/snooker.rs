//! Snooker rules, WPBSA Official Rules (revised November 2019): the strokes of a frame (3.3,
//! 3.10, 3.12, 3.14). Each test is named after the rule it pins; strokes are hand-made
//! summaries with the caller's layouts.

mod snooker_common;

use billiards_physics::Vec2;
use billiards_rules::Seat;
use billiards_rules::ShotSummary;
use billiards_rules::snooker::balls::*;
use billiards_rules::snooker::{BallOn, Choice, Foul, Frame, SnookerError, Stroke};
use snooker_common::*;

#[test]
fn rule_3_3_a_a_frame_starts_with_a_red_on_from_the_d_and_147_on_the_table() {
    let f = frame();
    assert_eq!(f.next.on, BallOn::Red);
    assert!(f.next.in_hand);
    assert_eq!(f.reds(), 15);
    assert_eq!(f.points_remaining(), 147);
}

#[test]
fn rule_3_3_a_a_potted_red_scores_1_and_a_colour_is_on() {
    let mut f = frame();
    let v = play(&mut f, Some(3), &[3], None);
    assert!(v.fair());
    assert_eq!(v.points, 1);
    assert_eq!(f.scores, [1, 0]);
    assert_eq!(f.next.striker, Seat::A);
    assert_eq!(f.next.on, BallOn::Colour { nominated: None });
    assert_eq!(v.text, "Ann pots a red: 1 point, break 1");
    assert_eq!(f.points_remaining(), 14 * 8 + 7 + 27);
}

#[test]
fn rule_3_3_a_two_reds_in_one_stroke_score_2() {
    let mut f = frame();
    let v = play(&mut f, Some(1), &[1, 2], None);
    assert_eq!(v.points, 2);
    assert_eq!(f.reds(), 13);
    assert_eq!(v.text, "Ann pots 2 reds: 2 points, break 2");
}

#[test]
fn rule_3_3_b_the_nominated_colour_scores_its_value_and_is_respotted() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(BLACK), &[BLACK], Some(BLACK));
    assert!(v.fair());
    assert_eq!(v.points, 7);
    assert_eq!(f.current_break, 8);
    assert_eq!(v.spots, vec![(BLACK, marks().black)]);
    assert!(f.on_table.contains(&BLACK));
    assert_eq!(v.text, "Ann pots the black: 7 points, break 8");
}

#[test]
fn rule_3_3_b_after_the_colour_a_red_is_on_again() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    play(&mut f, Some(BLUE), &[BLUE], Some(BLUE));
    assert_eq!(f.next.on, BallOn::Red);
    assert_eq!(f.next.striker, Seat::A);
}

#[test]
fn rule_2_12_an_obvious_colour_hit_first_counts_as_nominated() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(PINK), &[PINK], None);
    assert!(v.fair());
    assert_eq!(v.points, 6);
    assert_eq!(
        v.on,
        BallOn::Colour {
            nominated: Some(PINK)
        }
    );
}

#[test]
fn rule_3_3_no_pot_ends_the_turn_and_the_break() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(GREEN), &[], Some(GREEN));
    assert!(v.fair());
    assert_eq!(f.current_break, 0);
    assert_eq!(f.highest_break, [1, 0]);
    assert_eq!(f.next.striker, Seat::B);
    assert_eq!(f.next.on, BallOn::Red);
    assert_eq!(v.text, "Ann pots nothing: Bob to play");
}

#[test]
fn rule_3_3_c_after_the_last_red_and_its_colour_the_colours_in_order() {
    let mut f = frame();
    f.on_table = std::iter::once(7).chain(COLOURS).collect();
    play(&mut f, Some(7), &[7], None);
    assert_eq!(f.next.on, BallOn::Colour { nominated: None });
    let v = play(&mut f, Some(BROWN), &[BROWN], Some(BROWN));
    assert_eq!(v.spots.len(), 1, "the colour after the last red is spotted");
    assert_eq!(f.next.on, BallOn::Next { colour: YELLOW });
    assert_eq!(f.points_remaining(), 27);
}

#[test]
fn rule_3_3_c_colours_potted_in_order_stay_down() {
    let mut f = colours_from(YELLOW);
    let v = play(&mut f, Some(YELLOW), &[YELLOW], None);
    assert!(v.fair() && v.spots.is_empty());
    assert_eq!(v.points, 2);
    assert!(!f.on_table.contains(&YELLOW));
    assert_eq!(f.next.on, BallOn::Next { colour: GREEN });
}

#[test]
fn rule_3_10_the_blue_hit_first_with_a_red_on_costs_5() {
    let mut f = frame();
    let v = play(&mut f, Some(BLUE), &[], None);
    assert_eq!(v.penalty, 5);
    assert_eq!(f.scores, [0, 5]);
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBallFirst {
            hit: BLUE,
            on: BallOn::Red
        }]
    );
    assert!(
        v.text.starts_with("foul")
            && v.text
                .ends_with("the blue was hit first, a red was on: 5 points to Bob"),
        "{}",
        v.text
    );
}

#[test]
fn rule_3_10_the_penalty_is_at_least_4() {
    let mut f = frame();
    let v = play(&mut f, Some(YELLOW), &[], None);
    assert_eq!(v.penalty, 4);
    let mut f = frame();
    let v = play(&mut f, None, &[], None);
    assert_eq!(v.fouls, vec![Foul::NoBallHit]);
    assert_eq!(v.penalty, 4);
}

#[test]
fn rule_3_10_potting_a_ball_not_on_costs_its_value() {
    let mut f = frame();
    let v = play(&mut f, Some(1), &[1, BLACK], None);
    assert_eq!(v.fouls, vec![Foul::PottedNotOn { ball: BLACK }]);
    assert_eq!(v.penalty, 7);
    assert_eq!(v.points, 0, "no points on a foul");
    assert_eq!(f.scores, [0, 7]);
    assert!(
        !f.on_table.contains(&1),
        "a red potted on a foul stays down"
    );
    assert_eq!(v.spots, vec![(BLACK, marks().black)]);
}

#[test]
fn rule_3_10_the_highest_ball_involved_sets_the_penalty() {
    let mut f = frame();
    let v = play(&mut f, Some(GREEN), &[PINK], None);
    assert_eq!(v.fouls.len(), 2);
    assert_eq!(v.penalty, 6);
}

#[test]
fn rule_3_10_an_in_off_costs_the_value_of_the_ball_on_and_gives_ball_in_hand() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(BLUE), &[WHITE], Some(BLUE));
    assert_eq!(v.fouls, vec![Foul::InOff]);
    assert_eq!(v.penalty, 5);
    assert!(f.next.in_hand);
    assert_eq!(f.next.striker, Seat::B);
    assert_eq!(
        f.next.on,
        BallOn::Red,
        "a foul ends the colour after the red"
    );
}

#[test]
fn rule_3_10_the_nominated_colour_is_the_ball_on_for_the_penalty() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(YELLOW), &[], Some(BLACK));
    assert_eq!(v.penalty, 7);
    assert!(
        v.text
            .contains("the yellow was hit first, the black was on"),
        "{}",
        v.text
    );
}

#[test]
fn rule_3_10_b_a_red_hit_first_after_a_nominated_colour_costs_the_ball_on_at_least_4() {
    // 3.10(b): the value of the ball on (the green, 3) or of the ball concerned (a red, 1),
    // at least 4; a colour was nominated, so none of 3.10(d)'s 7-point cases applies.
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(2), &[], Some(GREEN));
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBallFirst {
            hit: 2,
            on: BallOn::Colour {
                nominated: Some(GREEN)
            }
        }]
    );
    assert_eq!(v.penalty, 4);
    assert_eq!(f.scores, [1, 4]);
    assert!(
        v.text
            .ends_with("the red was hit first, the green was on: 4 points to Bob"),
        "{}",
        v.text
    );
    // With the pink nominated the ball on is worth 6, and sets the penalty.
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    assert_eq!(play(&mut f, Some(2), &[], Some(PINK)).penalty, 6);
}

#[test]
fn rule_3_10_d_i_a_foul_after_a_red_before_nominating_a_colour_costs_7() {
    // 3.10(d)(i): no colour named and none hit first (2.12), the cue ball touching nothing.
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, None, &[], None);
    assert_eq!(v.fouls, vec![Foul::NoBallHit]);
    assert_eq!(v.penalty, 7);
    // The same stroke with the yellow nominated costs the value of the ball on, at least 4.
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    assert_eq!(play(&mut f, None, &[], Some(YELLOW)).penalty, 4);
}

#[test]
fn rule_3_10_d_iii_playing_at_reds_in_successive_strokes_costs_7() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(2), &[], None);
    assert_eq!(v.penalty, 7);
    assert!(
        v.text.contains("the red was hit first, a colour was on"),
        "{}",
        v.text
    );
    // Potting that red as well changes nothing: still 7, and the red stays down.
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(2), &[2], None);
    assert_eq!(v.penalty, 7);
    assert!(!f.on_table.contains(&2));
}

#[test]
fn rule_2_12_a_colour_hit_first_is_nominated_so_a_foul_after_it_is_not_7() {
    // The yellow hit first counts as nominated (2.12, obvious): potting the green with it is
    // a foul at the value of the green (3), at least 4, not 3.10(d)(i)'s 7.
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(YELLOW), &[GREEN], None);
    assert_eq!(v.fouls, vec![Foul::PottedNotOn { ball: GREEN }]);
    assert_eq!(v.penalty, 4);
}

// 3.10(d)(ii) (a ball off the table used for any purpose) and (d)(iv) (a ball other than the
// white used as the cue ball) cannot be played here: a stroke always strikes the white, and
// no ball is ever off the table, so `Stroke` has no way to express either.

#[test]
fn rule_3_10_c_after_a_foul_the_incoming_player_plays_or_puts_the_offender_back() {
    let mut f = frame();
    play(&mut f, Some(YELLOW), &[], None);
    assert_eq!(f.next.striker, Seat::B);
    assert!(f.next.choices.contains(&Choice::PlayOn));
    assert!(f.next.choices.contains(&Choice::PutBack));
    let s = summary(Some(1), &[]);
    let l = lay(&f);
    let err = f
        .play(Stroke {
            summary: &s,
            nominated: None,
            before: &l,
            after: &l,
        })
        .unwrap_err();
    assert!(matches!(err, SnookerError::ChoicePending(_)));
    let chosen = f.choose(Choice::PutBack).unwrap();
    assert_eq!(chosen.next.striker, Seat::A);
    assert!(chosen.layout.is_none());
    assert!(f.choose(Choice::PlayOn).is_err(), "the choice is made once");
}

#[test]
fn rule_3_10_colours_potted_on_a_foul_are_respotted_even_in_the_colours() {
    let mut f = colours_from(YELLOW);
    let v = play(&mut f, Some(YELLOW), &[YELLOW, GREEN], None);
    assert_eq!(v.penalty, 4);
    assert_eq!(v.spots.len(), 2);
    assert!(f.on_table.contains(&YELLOW) && f.on_table.contains(&GREEN));
    assert_eq!(f.next.on, BallOn::Next { colour: YELLOW });
}

/// Ann fouls (no ball hit) leaving Bob's cue ball behind the blue; one red left.
fn free_ball_frame() -> Frame {
    let mut f = frame();
    f.on_table = std::iter::once(1).chain(COLOURS).collect();
    f.next.in_hand = false;
    let l = hidden_red();
    let v = play_on(&mut f, &l, None, &[], None);
    assert!(!v.fair());
    f
}

#[test]
fn rule_3_12_a_foul_that_leaves_a_snooker_gives_a_free_ball() {
    let mut f = free_ball_frame();
    assert!(f.next.free_ball);
    assert_eq!(f.next.striker, Seat::B);
    f.choose(Choice::PlayOn).unwrap();
    assert!(f.next.free_ball);
    // Not snookered: no free ball.
    let mut g = frame();
    play(&mut g, Some(YELLOW), &[], None);
    assert!(!g.next.free_ball);
}

#[test]
fn rule_3_12_a_potted_free_ball_counts_as_a_red_and_is_spotted() {
    let mut f = free_ball_frame();
    f.choose(Choice::PlayOn).unwrap();
    let l = hidden_red();
    let v = play_on(&mut f, &l, Some(BLUE), &[BLUE], Some(BLUE));
    assert!(v.fair(), "{:?}", v.fouls);
    assert_eq!(v.free_ball, Some(BLUE));
    assert_eq!(v.points, 1);
    assert_eq!(v.spots, vec![(BLUE, marks().blue)]);
    assert_eq!(f.next.on, BallOn::Colour { nominated: None });
    assert_eq!(f.scores, [0, 5]);
}

#[test]
fn rule_3_12_in_the_colours_a_free_ball_takes_the_value_of_the_ball_on() {
    let mut f = colours_from(GREEN);
    f.next.free_ball = true;
    let v = play(&mut f, Some(BLACK), &[BLACK], Some(BLACK));
    assert!(v.fair());
    assert_eq!(v.points, 3, "the green's value");
    assert_eq!(v.spots, vec![(BLACK, marks().black)]);
    assert_eq!(f.next.on, BallOn::Next { colour: GREEN });
}

#[test]
fn rule_3_12_hitting_another_ball_than_the_free_ball_first_is_a_foul() {
    let mut f = free_ball_frame();
    f.choose(Choice::PlayOn).unwrap();
    let l = hidden_red();
    let v = play_on(&mut f, &l, Some(PINK), &[], Some(BLUE));
    assert_eq!(v.fouls.len(), 1);
    assert_eq!(v.penalty, 6);
}

#[test]
fn rule_3_12_a_red_hit_before_the_nominated_free_ball_is_a_foul() {
    let mut f = free_ball_frame();
    f.choose(Choice::PlayOn).unwrap();
    let l = hidden_red();
    let v = play_on(&mut f, &l, Some(1), &[1], Some(BLUE));
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBallFirst {
            hit: 1,
            on: BallOn::Red
        }]
    );
    assert_eq!(v.points, 0);
    // Without nominating a free ball, the red is simply on.
    let mut g = free_ball_frame();
    g.choose(Choice::PlayOn).unwrap();
    let v = play_on(&mut g, &l, Some(1), &[1], None);
    assert!(v.fair() && v.points == 1);
}

#[test]
fn rule_3_12_snookering_the_opponent_behind_the_free_ball_is_a_foul() {
    let mut f = free_ball_frame();
    f.choose(Choice::PlayOn).unwrap();
    let l = hidden_red();
    // The cue ball touches the blue and comes back to rest behind it.
    let v = play_on(&mut f, &l, Some(BLUE), &[], Some(BLUE));
    assert_eq!(v.fouls, vec![Foul::SnookeredByFreeBall { free_ball: BLUE }]);
    assert_eq!(v.penalty, 4);
}

#[test]
fn rule_3_12_putting_the_offender_back_withdraws_the_free_ball() {
    let mut f = free_ball_frame();
    let c = f.choose(Choice::PutBack).unwrap();
    assert_eq!(c.next.striker, Seat::A);
    assert!(!c.next.free_ball);
    let l = hidden_red();
    let s = summary(Some(BLUE), &[]);
    let err = f.play(Stroke {
        summary: &s,
        nominated: Some(BLUE),
        before: &l,
        after: &l,
    });
    // Without a free ball the blue cannot be nominated with a red on.
    assert_eq!(err.unwrap_err(), SnookerError::BadNomination(BLUE));
}

#[test]
fn rule_3_14_a_miss_with_the_ball_on_in_view_can_be_replaced_exactly() {
    let mut f = frame();
    let before = lay(&f);
    let v = play_on(&mut f, &before, None, &[], None);
    assert!(v.miss, "{}", v.text);
    assert!(
        v.text
            .starts_with("foul and a miss: the cue ball hit no ball: 4 points to Bob")
    );
    assert!(f.next.choices.contains(&Choice::Replace));
    let c = f.choose(Choice::Replace).unwrap();
    assert_eq!(c.layout.as_deref(), Some(&before[..]));
    assert_eq!(c.next.striker, Seat::A);
    assert!(c.next.in_hand, "the break is replayed from the D");
    assert_eq!(f.scores, [0, 4], "the penalty stands");
}

#[test]
fn rule_3_14_replace_puts_back_the_balls_potted_on_the_miss() {
    let mut f = frame();
    f.next.in_hand = false;
    let before = lay(&f);
    let v = play_on(&mut f, &before, Some(YELLOW), &[YELLOW, 4], None);
    assert!(v.miss);
    assert!(!f.on_table.contains(&4));
    f.choose(Choice::Replace).unwrap();
    assert!(f.on_table.contains(&4) && f.on_table.contains(&YELLOW));
    assert_eq!(f.reds(), 15);
}

#[test]
fn rule_3_14_no_miss_when_snookered() {
    let f = free_ball_frame();
    assert!(!f.next.choices.contains(&Choice::Replace));
}

#[test]
fn rule_3_14_no_miss_when_snookers_are_required() {
    let mut f = frame();
    f.on_table = std::iter::once(1).chain(COLOURS).collect();
    f.scores = [0, 60];
    assert!(f.snookers_required(Seat::A) > 0);
    let v = play(&mut f, None, &[], None);
    assert!(!v.fair() && !v.miss);
    assert!(!f.next.choices.contains(&Choice::Replace));
}

#[test]
fn rule_3_14_an_in_off_alone_is_no_miss() {
    let mut f = frame();
    let v = play(&mut f, Some(1), &[WHITE], None);
    assert!(!v.miss);
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let mut f = frame();
    let l = lay(&f);
    fn stroke<'a>(s: &'a ShotSummary, nominated: Option<u8>, l: &'a [(u8, Vec2)]) -> Stroke<'a> {
        Stroke {
            summary: s,
            nominated,
            before: l,
            after: l,
        }
    }
    let s = summary(Some(30), &[]);
    assert_eq!(
        f.play(stroke(&s, None, &l)).unwrap_err(),
        SnookerError::UnknownBall(30)
    );
    let mut g = colours_from(PINK);
    let s = summary(Some(PINK), &[1]);
    assert!(matches!(
        g.play(stroke(&s, None, &l)).unwrap_err(),
        SnookerError::NotOnTable(..)
    ));
    play(&mut f, Some(1), &[1], None);
    let s = summary(Some(2), &[]);
    assert_eq!(
        f.play(stroke(&s, Some(2), &l)).unwrap_err(),
        SnookerError::BadNomination(2)
    );
    let s = summary(Some(2), &[]);
    let empty: Vec<(u8, Vec2)> = Vec::new();
    let e = f.play(Stroke {
        summary: &s,
        nominated: None,
        before: &empty,
        after: &empty,
    });
    assert_eq!(e.unwrap_err(), SnookerError::NoCueBall);
    assert!(f.choose(Choice::Replace).is_err());
}

#[test]
fn rule_3_14_three_misses_in_a_row_with_a_full_view_lose_the_frame() {
    let mut f = frame();
    f.next.in_hand = false;
    // The cue ball in full view of the last red.
    let m = billiards_physics::SnookerMarks::of(&billiards_physics::Table::snooker_12ft()).unwrap();
    f.on_table = std::iter::once(1).chain(COLOURS).collect();
    let mut l = vec![(WHITE, Vec2::new(0.0, 0.5)), (1, Vec2::new(0.5, 0.5))];
    l.extend(COLOURS.iter().map(|&c| (c, m.spot(c).unwrap())));
    for k in 1..=3 {
        let v = play_on(&mut f, &l, None, &[], None);
        assert!(v.miss, "miss {k}");
        if k < 3 {
            assert_eq!(v.end, None);
            f.choose(Choice::Replace).unwrap();
        } else {
            assert_eq!(
                v.end,
                Some((Seat::B, billiards_rules::snooker::FrameEnd::ThreeMisses))
            );
            assert!(
                v.text.contains("Bob wins the frame after three misses"),
                "{}",
                v.text
            );
        }
    }
    // Playing on instead of replacing ends the count.
    let mut g = frame();
    g.next.in_hand = false;
    g.on_table = f.on_table.clone();
    for _ in 0..4 {
        let v = play_on(&mut g, &l, None, &[], None);
        assert!(v.miss && v.end.is_none());
        g.choose(Choice::PlayOn).unwrap();
    }
}

#[test]
fn rule_3_4_the_cue_ball_in_hand_is_played_from_the_d() {
    let mut f = frame();
    let s = summary(Some(1), &[]);
    let mut l = lay(&f);
    l[0].1 = Vec2::new(0.0, 0.5);
    let e = f.play(Stroke {
        summary: &s,
        nominated: None,
        before: &l,
        after: &l,
    });
    assert!(matches!(e.unwrap_err(), SnookerError::NotInD(..)));
}
