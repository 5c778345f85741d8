//! Snooker rules, WPBSA Official Rules (revised November 2019): each test is named after the
//! rule (section.rule) it pins. Strokes are hand-made summaries with the caller's layouts.

use billiards_physics::snooker::{default_cue_position, layout};
use billiards_physics::{BallSpec, Pocket, SnookerMarks, Table, Vec2};
use billiards_rules::Seat;
use billiards_rules::ShotSummary;
use billiards_rules::snooker::balls::*;
use billiards_rules::snooker::geometry::{clear_path, respot, respot_all, snookered};
use billiards_rules::snooker::{
    BallOn, Choice, Foul, Frame, FrameEnd, SnookerError, SnookerMatch, Stroke, Verdict,
};

const R: f64 = 0.02625;

fn frame() -> Frame {
    let names = ["Ann".to_owned(), "Bob".to_owned()];
    Frame::new(names, Table::snooker_12ft(), &BallSpec::snooker(), Seat::A).unwrap()
}

fn marks() -> SnookerMarks {
    SnookerMarks::of(&Table::snooker_12ft()).unwrap()
}

/// The starting positions of the balls now on the table (and the cue ball).
fn lay(f: &Frame) -> Vec<(u8, Vec2)> {
    let t = Table::snooker_12ft();
    layout(&t, &BallSpec::snooker(), default_cue_position(&marks()))
        .unwrap()
        .into_iter()
        .filter(|b| b.number == WHITE || f.on_table.contains(&b.number))
        .map(|b| (b.number, b.position))
        .collect()
}

fn summary(first: Option<u8>, potted: &[u8]) -> ShotSummary {
    ShotSummary {
        first_contact: first,
        pocketed: potted.iter().map(|&n| (n, Pocket::FootLeft)).collect(),
        ..ShotSummary::default()
    }
}

/// Plays a stroke on the start layout: the balls do not move, the potted ones drop.
fn play(f: &mut Frame, first: Option<u8>, potted: &[u8], nominated: Option<u8>) -> Verdict {
    let before = lay(f);
    play_on(f, &before, first, potted, nominated)
}

fn play_on(
    f: &mut Frame,
    before: &[(u8, Vec2)],
    first: Option<u8>,
    potted: &[u8],
    nominated: Option<u8>,
) -> Verdict {
    let s = summary(first, potted);
    let after: Vec<(u8, Vec2)> = before
        .iter()
        .copied()
        .filter(|(n, _)| !potted.contains(n))
        .collect();
    f.play(Stroke {
        summary: &s,
        nominated,
        before,
        after: &after,
    })
    .unwrap()
}

/// A frame with only the colours from `from` on.
fn colours_from(from: u8) -> Frame {
    let mut f = frame();
    f.on_table = (from..=BLACK).collect();
    f.next.on = f.ball_on();
    f.next.in_hand = false;
    f
}

/// A layout hiding the only red (1) behind the blue from a cue ball on the centre line.
fn hidden_red() -> Vec<(u8, Vec2)> {
    let m = marks();
    let mut l = vec![(WHITE, Vec2::new(-0.8, 0.0)), (1, Vec2::new(0.3, 0.0))];
    l.extend(COLOURS.iter().map(|&c| (c, m.spot(c).unwrap())));
    l
}

#[test]
fn rule_3_1_values_red_1_yellow_2_to_black_7() {
    assert_eq!(value(1), Some(1));
    assert_eq!(value(15), Some(1));
    let vals: Vec<u32> = COLOURS.iter().map(|&c| value(c).unwrap()).collect();
    assert_eq!(vals, vec![2, 3, 4, 5, 6, 7]);
    assert_eq!(value(WHITE), None);
    assert_eq!(value(22), None);
    assert_eq!(next_colour(YELLOW), Some(GREEN));
    assert_eq!(next_colour(BLACK), None);
}

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
fn rule_3_10_d_playing_at_a_red_after_a_red_costs_7() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    let v = play(&mut f, Some(2), &[], None);
    assert_eq!(v.penalty, 7);
    assert!(
        v.text.contains("the red was hit first, a colour was on"),
        "{}",
        v.text
    );
}

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

#[test]
fn rule_3_6_a_colour_goes_back_on_its_own_spot_when_free() {
    let m = marks();
    let t = Table::snooker_12ft();
    assert_eq!(
        respot(PINK, &m, &t, R, &[(WHITE, Vec2::new(0.0, 0.5))]).unwrap(),
        m.pink
    );
}

#[test]
fn rule_3_6_an_occupied_own_spot_sends_it_to_the_highest_free_spot() {
    let m = marks();
    let t = Table::snooker_12ft();
    // The cue ball sits on the pink spot.
    let balls = [(WHITE, m.pink + Vec2::new(0.01, 0.0))];
    assert_eq!(respot(PINK, &m, &t, R, &balls).unwrap(), m.black);
    // Black spot taken too: the blue's.
    let balls = [balls[0], (1, m.black)];
    assert_eq!(respot(PINK, &m, &t, R, &balls).unwrap(), m.blue);
}

#[test]
fn rule_3_6_all_spots_taken_it_goes_towards_the_top_cushion() {
    let m = marks();
    let t = Table::snooker_12ft();
    let mut balls: Vec<(u8, Vec2)> = COLOURS
        .iter()
        .filter(|&&c| c != PINK)
        .map(|&c| (c, m.spot(c).unwrap()))
        .collect();
    balls.push((WHITE, m.pink));
    let p = respot(PINK, &m, &t, R, &balls).unwrap();
    assert_eq!(p.y, m.pink.y);
    assert!(p.x > m.pink.x);
    assert!(
        (p.x - m.pink.x - 2.0 * R).abs() < 1e-4,
        "as near as possible: {p:?}"
    );
}

#[test]
fn rule_3_6_no_room_towards_the_top_it_goes_towards_the_bottom() {
    let m = marks();
    let t = Table::snooker_12ft();
    let hx = t.length / 2.0;
    // Every spot taken and a line of reds from the black to the top cushion.
    let mut balls: Vec<(u8, Vec2)> = COLOURS
        .iter()
        .filter(|&&c| c != BLACK)
        .map(|&c| (c, m.spot(c).unwrap()))
        .collect();
    let mut x = m.black.x;
    let mut n = 1;
    while x < hx - R {
        balls.push((n, Vec2::new(x, 0.0)));
        x += 2.0 * R;
        n += 1;
    }
    let p = respot(BLACK, &m, &t, R, &balls).unwrap();
    assert!(p.x < m.black.x, "{p:?}");
    assert!((m.black.x - p.x - 2.0 * R).abs() < 1e-4, "{p:?}");
}

#[test]
fn rule_3_6_several_colours_the_highest_value_first() {
    let m = marks();
    let t = Table::snooker_12ft();
    // The black spot and the pink spot are both covered; black and pink to spot.
    let balls = [(1, m.black), (2, m.pink)];
    let spots = respot_all(&[PINK, BLACK], &m, &t, R, &balls).unwrap();
    assert_eq!(
        spots[0],
        (BLACK, m.blue),
        "the black takes the highest free spot"
    );
    assert_eq!(spots[1], (PINK, m.brown), "then the pink the next one");
    assert!(respot(3, &m, &t, R, &[]).is_err(), "reds are never spotted");
}

#[test]
fn rule_2_16_not_snookered_when_both_edges_of_a_ball_on_are_clear() {
    let l = hidden_red();
    let objs: Vec<_> = l.iter().copied().filter(|&(n, _)| n != WHITE).collect();
    assert!(!snookered(Vec2::new(-0.8, 0.4), &[1], &objs, R));
    assert!(clear_path(Vec2::new(-0.8, 0.4), &[1], &objs, R));
}

#[test]
fn rule_2_16_snookered_when_a_ball_not_on_hides_the_ball_on() {
    let l = hidden_red();
    let objs: Vec<_> = l.iter().copied().filter(|&(n, _)| n != WHITE).collect();
    assert!(snookered(Vec2::new(-0.8, 0.0), &[1], &objs, R));
    assert!(!clear_path(Vec2::new(-0.8, 0.0), &[1], &objs, R));
    // Once the blue is the ball on itself it is no obstacle.
    assert!(!snookered(Vec2::new(-0.8, 0.0), &[BLUE], &objs, R));
}

#[test]
fn rule_2_16_one_edge_hidden_is_a_snooker_but_leaves_a_path() {
    let l = hidden_red();
    let objs: Vec<_> = l.iter().copied().filter(|&(n, _)| n != WHITE).collect();
    // Off the line by less than two radii: the blue hides one edge of the red only.
    let cue = Vec2::new(-0.8, 0.06);
    assert!(snookered(cue, &[1], &objs, R));
    assert!(clear_path(cue, &[1], &objs, R));
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
fn rule_2_1_c_the_last_black_ends_the_frame_on_points() {
    let mut f = colours_from(BLACK);
    f.scores = [50, 40];
    let v = play(&mut f, Some(BLACK), &[BLACK], None);
    assert_eq!(v.end, Some((Seat::A, FrameEnd::Points)));
    assert_eq!(f.scores, [57, 40]);
    assert!(v.next.is_none());
    assert!(
        v.text.ends_with("Ann wins the frame on points (57-40)"),
        "{}",
        v.text
    );
    assert_eq!(
        f.play(Stroke {
            summary: &summary(None, &[]),
            nominated: None,
            before: &lay(&f),
            after: &[]
        })
        .unwrap_err(),
        SnookerError::Over
    );
}

#[test]
fn rule_2_1_c_a_foul_on_the_last_black_ends_the_frame() {
    let mut f = colours_from(BLACK);
    f.scores = [44, 40];
    let v = play(&mut f, None, &[], None);
    assert_eq!(v.penalty, 7);
    assert_eq!(v.end, Some((Seat::B, FrameEnd::Points)), "47 to 44");
}

#[test]
fn rule_3_3_d_a_tie_re_spots_the_black_and_the_toss_decides_who_plays() {
    let mut f = colours_from(BLACK);
    f.scores = [40, 47];
    let v = play(&mut f, Some(BLACK), &[BLACK], None);
    assert_eq!(v.end, None);
    assert_eq!(f.scores, [47, 47]);
    assert_eq!(v.spots, vec![(BLACK, marks().black)]);
    assert!(
        v.text.contains("level at 47-47: the black is re-spotted"),
        "{}",
        v.text
    );
    assert!(f.next.in_hand);
    let c = f.choose(Choice::BlackFirst(Seat::B)).unwrap();
    assert_eq!(c.next.striker, Seat::B);
    // A safety, then Ann pots it.
    play(&mut f, Some(BLACK), &[], None);
    let v = play(&mut f, Some(BLACK), &[BLACK], None);
    assert_eq!(v.end, Some((Seat::A, FrameEnd::RespottedBlack)));
}

#[test]
fn rule_3_3_d_a_foul_on_the_re_spotted_black_loses_the_frame() {
    let mut f = colours_from(BLACK);
    f.scores = [40, 47];
    play(&mut f, Some(BLACK), &[BLACK], None);
    f.choose(Choice::BlackFirst(Seat::A)).unwrap();
    let v = play(&mut f, Some(BLACK), &[WHITE], None);
    assert_eq!(v.end, Some((Seat::B, FrameEnd::RespottedBlack)));
    assert_eq!(f.scores, [47, 54]);
}

#[test]
fn rule_2_1_a_only_the_striker_concedes_during_his_turn() {
    let mut f = frame();
    assert_eq!(f.concede(Seat::B).unwrap_err(), SnookerError::NotTheStriker);
    assert_eq!(f.concede(Seat::A).unwrap(), (Seat::B, FrameEnd::Conceded));
    assert_eq!(f.winner(), Some(Seat::B));
    assert_eq!(f.concede(Seat::A).unwrap_err(), SnookerError::Over);
}

#[test]
fn rule_2_1_b_a_claim_needs_the_black_alone_and_more_than_7_ahead() {
    let mut f = colours_from(BLACK);
    f.scores = [47, 40];
    assert_eq!(f.claim(Seat::A).unwrap_err(), SnookerError::CannotClaim);
    f.scores = [48, 40];
    assert_eq!(f.claim(Seat::A).unwrap(), (Seat::A, FrameEnd::Claimed));
    let mut g = colours_from(PINK);
    g.scores = [80, 0];
    assert_eq!(g.claim(Seat::A).unwrap_err(), SnookerError::CannotClaim);
}

#[test]
fn snookers_required_counts_4_point_fouls_beyond_the_points_left() {
    let mut f = colours_from(PINK);
    assert_eq!(f.points_remaining(), 13);
    f.scores = [0, 13];
    assert_eq!(f.snookers_required(Seat::A), 0, "a tie is still possible");
    f.scores = [0, 14];
    assert_eq!(f.snookers_required(Seat::A), 1);
    f.scores = [0, 22];
    assert_eq!(f.snookers_required(Seat::A), 3);
    assert_eq!(f.snookers_required(Seat::B), 0);
}

#[test]
fn rule_2_3_a_match_is_the_best_of_an_odd_number_of_frames_alternating_breaks() {
    assert_eq!(
        SnookerMatch::new(4, Seat::A).unwrap_err(),
        SnookerError::BestOf(4)
    );
    let mut m = SnookerMatch::new(5, Seat::A).unwrap();
    assert_eq!(m.to_win(), 3);
    assert_eq!(m.next_breaker(), Seat::A);
    assert_eq!(m.record(Seat::B).unwrap(), None);
    assert_eq!(m.next_breaker(), Seat::B);
    m.record(Seat::B).unwrap();
    m.record(Seat::A).unwrap();
    assert_eq!(m.record(Seat::B).unwrap(), Some(Seat::B));
    assert!(m.record(Seat::A).is_err());
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
fn a_maximum_147_scores_every_red_with_the_black_then_the_colours() {
    let mut f = frame();
    for red in 1..=15 {
        let v = play(&mut f, Some(red), &[red], None);
        assert!(v.fair());
        let v = play(&mut f, Some(BLACK), &[BLACK], Some(BLACK));
        assert_eq!(v.spots.len(), 1);
    }
    let mut last = None;
    for c in COLOURS {
        last = Some(play(&mut f, Some(c), &[c], None));
    }
    let v = last.unwrap();
    assert_eq!(f.scores, [147, 0]);
    assert_eq!(f.highest_break, [147, 0]);
    assert_eq!(v.end, Some((Seat::A, FrameEnd::Points)));
    assert_eq!(f.points_remaining(), 0);
}
