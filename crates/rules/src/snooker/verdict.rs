//! What a judged snooker stroke returns: the ball on, the fouls, the points, the colours to
//! spot, who plays next and the choices of the incoming player, with a sentence to read.

use super::balls::name;
use crate::game::Seat;
use billiards_physics::Vec2;
use serde::{Deserialize, Serialize};
use std::fmt;

/// What the striker had to hit first (2.11 "ball on").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum BallOn {
    /// Any red (3.3(a)).
    Red,
    /// After a red, a colour: the nominated one (2.12, 3.3(b)); `None` before nomination.
    Colour {
        /// The colour nominated.
        nominated: Option<u8>,
    },
    /// No red left: the colours in order (3.3(c)); this one is next.
    Next {
        /// The colour on.
        colour: u8,
    },
}

impl fmt::Display for BallOn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            BallOn::Red => write!(f, "a red"),
            BallOn::Colour { nominated: None } => write!(f, "a colour"),
            BallOn::Colour { nominated: Some(c) } | BallOn::Next { colour: c } => {
                write!(f, "the {}", name(c))
            }
        }
    }
}

/// One foul of a stroke (3.10); a stroke can commit several.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Foul {
    /// 3.10: the cue ball hit no ball.
    NoBallHit,
    /// 3.10: the first ball hit was not on.
    WrongBallFirst {
        /// The ball hit first.
        hit: u8,
        /// What was on.
        on: BallOn,
    },
    /// 3.10: a ball not on was potted.
    PottedNotOn {
        /// The ball.
        ball: u8,
    },
    /// 3.10: the cue ball was potted ("in-off").
    InOff,
    /// 3.10: a ball (the cue ball included) was forced off the table; the penalty is the
    /// value of the ball on or of the ball concerned, at least four. A colour is re-spotted,
    /// a red is not replaced, the cue ball is in hand in the D as after an in-off (games.md,
    /// "Balls off the table"; the sub-paragraph of 3.10 that lists it is not confirmed here).
    OffTable {
        /// The ball forced off the table.
        ball: u8,
    },
    /// 3.12: the striker on a free ball left the opponent snookered behind it.
    SnookeredByFreeBall {
        /// The free ball.
        free_ball: u8,
    },
}

impl fmt::Display for Foul {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Foul::NoBallHit => write!(f, "the cue ball hit no ball"),
            Foul::WrongBallFirst { hit, on } => {
                write!(f, "the {} was hit first, {on} was on", name(hit))
            }
            Foul::PottedNotOn { ball } => write!(f, "the {} was potted, it was not on", name(ball)),
            Foul::InOff => write!(f, "the cue ball went in-off"),
            Foul::OffTable { ball } => write!(f, "the {} was forced off the table", name(ball)),
            Foul::SnookeredByFreeBall { free_ball } => {
                write!(
                    f,
                    "the free ball (the {}) snookered the opponent",
                    name(free_ball)
                )
            }
        }
    }
}

/// What the incoming player may choose after a foul.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Choice {
    /// Play from where the balls lie (with a free ball if it is offered, 3.12).
    PlayOn,
    /// 3.10(c): have the offender play again from where the balls lie (no free ball).
    PutBack,
    /// 3.14: a miss: the balls replaced as they were before the stroke, the offender to play
    /// it again.
    Replace,
    /// 3.3(d): the re-spotted black; this player (the winner of the toss's pick) plays first.
    BlackFirst(Seat),
}

/// The next stroke.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NextShot {
    /// Who plays (or, with `choices`, who chooses first).
    pub striker: Seat,
    /// What is on.
    pub on: BallOn,
    /// The cue ball is in hand: placed in the D (3.4).
    pub in_hand: bool,
    /// The striker may nominate a free ball (3.12): the cue ball is snookered after a foul.
    pub free_ball: bool,
    /// Choices the striker must make (one of them) before playing; empty: play.
    pub choices: Vec<Choice>,
}

/// How a frame ended (2.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FrameEnd {
    /// 2.1(c): the final pot or foul with the black alone: more points.
    Points,
    /// 2.1(a): the loser conceded during his turn.
    Conceded,
    /// 2.1(b): the winner claimed it, the black alone and more than 7 ahead.
    Claimed,
    /// 3.3(d): the first score or foul on the re-spotted black after a tie.
    RespottedBlack,
    /// 3.14: the loser missed three times in a row with a full view of a ball on.
    ThreeMisses,
}

impl fmt::Display for FrameEnd {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FrameEnd::Points => "on points",
            FrameEnd::Conceded => "conceded",
            FrameEnd::Claimed => "claimed with only the black left",
            FrameEnd::RespottedBlack => "on the re-spotted black",
            FrameEnd::ThreeMisses => "after three misses in a row with a full view of the ball on",
        })
    }
}

/// The verdict on one stroke.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Verdict {
    /// Who played.
    pub striker: Seat,
    /// What was on.
    pub on: BallOn,
    /// The free ball nominated (3.12), if one was played.
    pub free_ball: Option<u8>,
    /// The fouls (empty: a fair stroke).
    pub fouls: Vec<Foul>,
    /// Points scored by the striker (0 on a foul).
    pub points: u32,
    /// Penalty points given to the opponent (0 on a fair stroke; at least 4 on a foul).
    pub penalty: u32,
    /// 3.14: the foul is also a miss; the incoming player may have the balls replaced.
    pub miss: bool,
    /// Colours to put back on the table and where (3.6), highest value first.
    pub spots: Vec<(u8, Vec2)>,
    /// The frame's scores after the stroke.
    pub scores: [u32; 2],
    /// The frame ended: the winner and how.
    pub end: Option<(Seat, FrameEnd)>,
    /// The next stroke (`None` when the frame is over).
    pub next: Option<NextShot>,
    /// The verdict as a sentence naming the players.
    pub text: String,
}

impl Verdict {
    /// A fair stroke?
    pub fn fair(&self) -> bool {
        self.fouls.is_empty()
    }
}
