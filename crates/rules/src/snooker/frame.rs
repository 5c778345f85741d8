//! One frame of snooker: the scores, the ball on, the break, the choices after a foul, the
//! end of the frame (WPBSA 2.1, 3.3). [`Frame::play`] (in `judge.rs`) judges a stroke.

use super::balls::{BLACK, COLOURS, WHITE, is_colour, is_red, value};
use super::geometry::SpotError;
use super::verdict::{BallOn, Choice, FrameEnd, NextShot};
use crate::game::Seat;
use billiards_physics::{BallSpec, SnookerMarks, Table, Vec2};
use serde::{Deserialize, Serialize};

/// Why a call on a frame was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SnookerError {
    /// The frame is over.
    #[error("the frame is over")]
    Over,
    /// A choice must be made first ([`NextShot::choices`]).
    #[error("a choice is pending: {0:?}")]
    ChoicePending(Vec<Choice>),
    /// This choice is not offered now.
    #[error("{0:?} is not offered now")]
    NotOffered(Choice),
    /// A ball number that is not one of the 22.
    #[error("ball {0} is not a snooker ball (0 to 21)")]
    UnknownBall(u8),
    /// A ball reported potted or hit that was not on the table.
    #[error("the {0} ({1}) was not on the table")]
    NotOnTable(&'static str, u8),
    /// A nomination of something else than a colour on the table.
    #[error("ball {0} cannot be nominated: a colour on the table is nominated (2.12)")]
    BadNomination(u8),
    /// The layout before the stroke has no cue ball.
    #[error("the layout before the stroke has no cue ball")]
    NoCueBall,
    /// 3.4: the cue ball in hand must be played from the D.
    #[error("the cue ball in hand is at ({0:.3}, {1:.3}), outside the D")]
    NotInD(f64, f64),
    /// The table cannot carry the snooker marks.
    #[error("{0}")]
    Table(String),
    /// A colour could not be spotted.
    #[error(transparent)]
    Spot(#[from] SpotError),
    /// Only the striker may concede or claim, during his turn (2.1).
    #[error("only the striker may do this, during his turn")]
    NotTheStriker,
    /// 2.1(b): a claim needs the black alone and more than 7 points ahead.
    #[error("a frame is claimed only with the black alone and more than 7 points ahead")]
    CannotClaim,
    /// A match must be the best of an odd number of frames.
    #[error("a match is the best of an odd number of frames, got {0}")]
    BestOf(u32),
}

/// The state before a foul, kept for 3.14's replace.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Snapshot {
    /// Every ball on the table before the stroke (the cue ball included).
    pub layout: Vec<(u8, Vec2)>,
    /// The object balls then on the table.
    pub on_table: Vec<u8>,
    /// A colour was on after a red.
    pub after_red: bool,
    /// The offender's stroke as it was.
    pub next: NextShot,
}

/// What [`Frame::choose`] returns: the next stroke and, after a replace, the balls to set.
#[derive(Clone, Debug, PartialEq)]
pub struct Chosen {
    /// The next stroke.
    pub next: NextShot,
    /// 3.14: put every ball here (the cue ball included) before the stroke.
    pub layout: Option<Vec<(u8, Vec2)>>,
}

/// A frame of snooker.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Frame {
    /// The players' names, for the verdicts' sentences.
    pub players: [String; 2],
    /// The table (for spotting towards the top cushion).
    pub table: Table,
    /// The balls' radius.
    pub radius: f64,
    /// The table's marks.
    pub marks: SnookerMarks,
    /// Points of A and B.
    pub scores: [u32; 2],
    /// The striker's current break (2.8).
    pub current_break: u32,
    /// The highest break of each player in the frame.
    pub highest_break: [u32; 2],
    /// Object balls on the table.
    pub on_table: Vec<u8>,
    /// A colour is on after a red (3.3(b)).
    pub after_red: bool,
    /// The next stroke.
    pub next: NextShot,
    /// The end of the frame: winner and how.
    pub end: Option<(Seat, FrameEnd)>,
    /// The black has been re-spotted after a tie (3.3(d)).
    pub respotted_black: bool,
    /// The state before the last foul (3.14).
    pub before_foul: Option<Snapshot>,
    /// 3.14: misses in a row by the striker with a full view of a ball on (the third
    /// awards the frame to the opponent).
    #[serde(default)]
    pub full_view_misses: u8,
}

impl Frame {
    /// A frame from the start (3.2): `breaker` plays first from the D.
    pub fn new(
        players: [String; 2],
        table: Table,
        ball: &BallSpec,
        breaker: Seat,
    ) -> Result<Self, SnookerError> {
        let marks = SnookerMarks::of(&table).map_err(SnookerError::Table)?;
        if !(ball.radius.is_finite() && ball.radius > 0.0 && 4.0 * ball.radius < table.width) {
            return Err(SnookerError::Table(format!(
                "a ball of radius {} m does not fit the table",
                ball.radius
            )));
        }
        Ok(Self {
            players,
            table,
            radius: ball.radius,
            marks,
            scores: [0, 0],
            current_break: 0,
            highest_break: [0, 0],
            on_table: (1..=BLACK).collect(),
            after_red: false,
            next: NextShot {
                striker: breaker,
                on: BallOn::Red,
                in_hand: true,
                free_ball: false,
                choices: Vec::new(),
            },
            end: None,
            respotted_black: false,
            before_foul: None,
            full_view_misses: 0,
        })
    }

    /// A player's name.
    pub fn name(&self, seat: Seat) -> &str {
        &self.players[seat.index()]
    }

    /// Reds on the table.
    pub fn reds(&self) -> usize {
        self.on_table.iter().filter(|&&n| is_red(n)).count()
    }

    /// What is on now, from the balls on the table (3.3).
    pub fn ball_on(&self) -> BallOn {
        if self.after_red {
            BallOn::Colour { nominated: None }
        } else if self.reds() > 0 {
            BallOn::Red
        } else {
            let colour = COLOURS
                .into_iter()
                .find(|c| self.on_table.contains(c))
                .unwrap_or(BLACK);
            BallOn::Next { colour }
        }
    }

    /// The balls that are on (a nominated colour counts alone).
    pub fn balls_on(&self, on: BallOn) -> Vec<u8> {
        match on {
            BallOn::Red => self
                .on_table
                .iter()
                .copied()
                .filter(|&n| is_red(n))
                .collect(),
            BallOn::Colour { nominated: Some(c) } => vec![c],
            BallOn::Colour { nominated: None } => self
                .on_table
                .iter()
                .copied()
                .filter(|&n| is_colour(n))
                .collect(),
            BallOn::Next { colour } => vec![colour],
        }
    }

    /// Points left on the table: 8 a red (with the black after it), 7 more if a colour is on
    /// after a red, and the colours on the table.
    pub fn points_remaining(&self) -> u32 {
        let colours: u32 = self
            .on_table
            .iter()
            .filter(|&&n| is_colour(n))
            .filter_map(|&n| value(n))
            .sum();
        8 * self.reds() as u32 + if self.after_red { 7 } else { 0 } + colours
    }

    /// "Snookers required": how many 4-point fouls `seat` needs from the opponent to draw
    /// level, when clearing the table would not do it (0 otherwise).
    pub fn snookers_required(&self, seat: Seat) -> u32 {
        let behind = self.scores[seat.other().index()].saturating_sub(self.scores[seat.index()]);
        behind.saturating_sub(self.points_remaining()).div_ceil(4)
    }

    /// The incoming player chooses (after a foul: play on, put the offender back in, or have
    /// the balls replaced after a miss; after a tie: who plays the re-spotted black first).
    pub fn choose(&mut self, choice: Choice) -> Result<Chosen, SnookerError> {
        if self.end.is_some() {
            return Err(SnookerError::Over);
        }
        if !self.next.choices.contains(&choice) {
            return Err(SnookerError::NotOffered(choice));
        }
        let mut layout = None;
        match choice {
            Choice::PlayOn => {
                self.full_view_misses = 0;
                self.next.choices.clear();
            }
            Choice::PutBack => {
                self.full_view_misses = 0;
                // 3.10(c): the offender plays again; the free ball call is withdrawn.
                self.next.striker = self.next.striker.other();
                self.next.free_ball = false;
                self.next.choices.clear();
            }
            Choice::Replace => {
                let snap = self
                    .before_foul
                    .take()
                    .ok_or(SnookerError::NotOffered(choice))?;
                self.on_table = snap.on_table;
                self.after_red = snap.after_red;
                self.next = snap.next;
                self.next.choices.clear();
                layout = Some(snap.layout);
            }
            Choice::BlackFirst(seat) => {
                self.next.striker = seat;
                self.next.choices.clear();
            }
        }
        Ok(Chosen {
            next: self.next.clone(),
            layout,
        })
    }

    /// 2.1(a): the striker concedes the frame during his turn.
    pub fn concede(&mut self, seat: Seat) -> Result<(Seat, FrameEnd), SnookerError> {
        self.check_striker(seat)?;
        let end = (seat.other(), FrameEnd::Conceded);
        self.end = Some(end);
        Ok(end)
    }

    /// 2.1(b): the striker claims the frame, only the black left and more than 7 ahead.
    pub fn claim(&mut self, seat: Seat) -> Result<(Seat, FrameEnd), SnookerError> {
        self.check_striker(seat)?;
        let lead =
            i64::from(self.scores[seat.index()]) - i64::from(self.scores[seat.other().index()]);
        if self.on_table != [BLACK] || lead <= 7 {
            return Err(SnookerError::CannotClaim);
        }
        let end = (seat, FrameEnd::Claimed);
        self.end = Some(end);
        Ok(end)
    }

    fn check_striker(&self, seat: Seat) -> Result<(), SnookerError> {
        if self.end.is_some() {
            return Err(SnookerError::Over);
        }
        if seat != self.next.striker || !self.next.choices.is_empty() {
            return Err(SnookerError::NotTheStriker);
        }
        Ok(())
    }

    /// The winner of the frame, if it is over.
    pub fn winner(&self) -> Option<Seat> {
        self.end.map(|(s, _)| s)
    }

    pub(super) fn check_ball(&self, n: u8) -> Result<(), SnookerError> {
        if n > BLACK {
            return Err(SnookerError::UnknownBall(n));
        }
        if n != WHITE && !self.on_table.contains(&n) {
            return Err(SnookerError::NotOnTable(super::balls::name(n), n));
        }
        Ok(())
    }
}
