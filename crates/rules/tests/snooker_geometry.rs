//! Snooker rules, WPBSA Official Rules (revised November 2019): values (3.1), spotting (3.6)
//! and the snookered geometry (2.16). Each test is named after the rule it pins.

mod snooker_common;

use billiards_physics::{Table, Vec2};
use billiards_rules::snooker::balls::*;
use billiards_rules::snooker::geometry::{clear_path, respot, respot_all, snookered};
use snooker_common::*;

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
