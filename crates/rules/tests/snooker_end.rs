//! Snooker rules, WPBSA Official Rules (revised November 2019): the end of a frame (2.1, the
//! re-spotted black of 3.3), snookers required, a match (2.3). Named after the rule pinned.

mod snooker_common;

use billiards_rules::Seat;
use billiards_rules::snooker::balls::*;
use billiards_rules::snooker::{Choice, FrameEnd, SnookerError, SnookerMatch, Stroke};
use snooker_common::*;

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

#[test]
fn a_frame_is_a_plain_value_saved_and_restored_exactly() {
    let mut f = frame();
    play(&mut f, Some(1), &[1], None);
    play(&mut f, Some(YELLOW), &[], Some(BLACK));
    let text = serde_json::to_string(&f).unwrap();
    let back: billiards_rules::snooker::Frame = serde_json::from_str(&text).unwrap();
    assert_eq!(back, f);
    assert!(
        back.before_foul.is_some(),
        "the layout for a replace is kept"
    );
}

#[test]
fn a_frame_refuses_a_table_or_ball_it_cannot_use() {
    use billiards_physics::{BallSpec, Table};
    let names = ["Ann".to_owned(), "Bob".to_owned()];
    let short = Table {
        length: 1.0,
        ..Table::snooker_12ft()
    };
    let e =
        billiards_rules::snooker::Frame::new(names.clone(), short, &BallSpec::snooker(), Seat::A);
    assert!(matches!(e.unwrap_err(), SnookerError::Table(_)));
    let nan = BallSpec {
        radius: f64::NAN,
        ..BallSpec::snooker()
    };
    let e = billiards_rules::snooker::Frame::new(names, Table::snooker_12ft(), &nan, Seat::A);
    assert!(matches!(e.unwrap_err(), SnookerError::Table(_)));
}
