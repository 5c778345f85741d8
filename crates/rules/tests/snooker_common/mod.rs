//! Helpers shared by the snooker rule tests: a frame, its layout, hand-made strokes.
#![allow(dead_code)]

use billiards_physics::snooker::{default_cue_position, layout};
use billiards_physics::{BallSpec, Pocket, SnookerMarks, Table, Vec2};
use billiards_rules::Seat;
use billiards_rules::ShotSummary;
use billiards_rules::snooker::balls::*;
use billiards_rules::snooker::{Frame, Stroke, Verdict};

pub const R: f64 = 0.02625;

pub fn frame() -> Frame {
    let names = ["Ann".to_owned(), "Bob".to_owned()];
    Frame::new(names, Table::snooker_12ft(), &BallSpec::snooker(), Seat::A).unwrap()
}

pub fn marks() -> SnookerMarks {
    SnookerMarks::of(&Table::snooker_12ft()).unwrap()
}

/// The starting positions of the balls now on the table (and the cue ball).
pub fn lay(f: &Frame) -> Vec<(u8, Vec2)> {
    let t = Table::snooker_12ft();
    layout(&t, &BallSpec::snooker(), default_cue_position(&marks()))
        .unwrap()
        .into_iter()
        .filter(|b| b.number == WHITE || f.on_table.contains(&b.number))
        .map(|b| (b.number, b.position))
        .collect()
}

pub fn summary(first: Option<u8>, potted: &[u8]) -> ShotSummary {
    ShotSummary {
        first_contact: first,
        pocketed: potted.iter().map(|&n| (n, Pocket::FootLeft)).collect(),
        ..ShotSummary::default()
    }
}

/// Plays a stroke on the start layout: the balls do not move, the potted ones drop.
pub fn play(f: &mut Frame, first: Option<u8>, potted: &[u8], nominated: Option<u8>) -> Verdict {
    let before = lay(f);
    play_on(f, &before, first, potted, nominated)
}

pub fn play_on(
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
pub fn colours_from(from: u8) -> Frame {
    let mut f = frame();
    f.on_table = (from..=BLACK).collect();
    f.next.on = f.ball_on();
    f.next.in_hand = false;
    f
}

/// A layout hiding the only red (1) behind the blue from a cue ball on the centre line.
pub fn hidden_red() -> Vec<(u8, Vec2)> {
    let m = marks();
    let mut l = vec![(WHITE, Vec2::new(-0.8, 0.0)), (1, Vec2::new(0.3, 0.0))];
    l.extend(COLOURS.iter().map(|&c| (c, m.spot(c).unwrap())));
    l
}
