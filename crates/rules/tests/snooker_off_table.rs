//! Snooker, balls forced off the table (issue 52), WPBSA Official Rules (revised November
//! 2019): 3.10 lists forcing a ball off the table among the fouls whose penalty is the value
//! of the ball on or of the ball concerned, at least four (the sub-paragraph is not confirmed
//! from the text at hand); a colour is re-spotted (3.6 spotting colours), a red is not
//! replaced, the cue ball is in hand in the D (3.5) as after an in-off (games.md, "Balls off
//! the table"). Strokes are hand-made summaries on the start layout.

mod snooker_common;

use billiards_physics::Vec2;
use billiards_rules::Seat;
use billiards_rules::snooker::balls::*;
use billiards_rules::snooker::{BallOn, Foul, Frame, Stroke, Verdict};
use snooker_common::*;

/// A stroke on the start layout: `first` hit first, `potted` down, `off` forced off the
/// table (the others do not move).
fn play_off(
    f: &mut Frame,
    first: Option<u8>,
    potted: &[u8],
    off: &[u8],
    nominated: Option<u8>,
) -> Verdict {
    let before = lay(f);
    let mut s = summary(first, potted);
    s.off_table = off.to_vec();
    let after: Vec<(u8, Vec2)> = before
        .iter()
        .copied()
        .filter(|(n, _)| !potted.contains(n) && !off.contains(n))
        .collect();
    f.play(Stroke {
        summary: &s,
        nominated,
        before: &before,
        after: &after,
    })
    .unwrap()
}

#[test]
fn rule_3_10_a_red_forced_off_the_table_is_a_foul_of_four_and_is_not_replaced() {
    let mut f = frame();
    let v = play_off(&mut f, Some(1), &[], &[2], None);
    assert_eq!(v.fouls, vec![Foul::OffTable { ball: 2 }]);
    assert_eq!(v.penalty, 4, "a red is worth 1, the penalty at least 4");
    assert_eq!(f.scores, [0, 4]);
    assert!(v.spots.is_empty());
    assert_eq!(f.reds(), 14, "the red stays off");
    assert!(!f.on_table.contains(&2));
    assert_eq!(f.next.striker, Seat::B);
    assert!(!f.next.in_hand);
    assert_eq!(
        v.fouls[0].to_string(),
        "the red was forced off the table",
        "named as the other fouls are"
    );
}

#[test]
fn rule_3_10_a_colour_forced_off_the_table_costs_its_value_and_is_re_spotted() {
    // A red on, the red hit first, the black forced off: 7, the ball concerned.
    let mut f = frame();
    let v = play_off(&mut f, Some(1), &[], &[BLACK], None);
    assert_eq!(v.fouls, vec![Foul::OffTable { ball: BLACK }]);
    assert_eq!(v.penalty, 7);
    assert_eq!(v.spots, vec![(BLACK, marks().black)]);
    assert!(f.on_table.contains(&BLACK));
    assert_eq!(f.reds(), 15);
}

#[test]
fn rule_3_10_a_pot_in_the_same_stroke_does_not_score_after_a_ball_is_forced_off() {
    // The red potted fairly would score 1 and keep Ann at the table; the yellow forced off
    // makes it a foul of 4 (the ball on, a red: 1; the yellow: 2), the red stays down.
    let mut f = frame();
    let v = play_off(&mut f, Some(1), &[1], &[YELLOW], None);
    assert_eq!(v.fouls, vec![Foul::OffTable { ball: YELLOW }]);
    assert_eq!((v.points, v.penalty), (0, 4));
    assert_eq!(f.scores, [0, 4]);
    assert_eq!(f.reds(), 14);
    assert_eq!(v.spots, vec![(YELLOW, marks().yellow)]);
    assert_eq!(f.next.striker, Seat::B);
}

#[test]
fn rule_3_10_and_3_5_the_cue_ball_forced_off_the_table_gives_ball_in_hand_in_the_d() {
    // After a red, the blue nominated and hit, the cue ball flies off: the value of the
    // ball on (5), the opponent in hand in the D as after an in-off.
    let mut f = frame();
    play_off(&mut f, Some(1), &[1], &[], None);
    let v = play_off(&mut f, Some(BLUE), &[], &[WHITE], Some(BLUE));
    assert_eq!(v.fouls, vec![Foul::OffTable { ball: WHITE }]);
    assert_eq!(v.penalty, 5);
    assert_eq!(f.scores, [1, 5]);
    assert!(f.next.in_hand);
    assert_eq!(f.next.striker, Seat::B);
    assert_eq!(f.next.on, BallOn::Red);
    assert_eq!(
        v.fouls[0].to_string(),
        "the cue ball was forced off the table"
    );
}
