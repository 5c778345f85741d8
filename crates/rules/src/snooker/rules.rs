//! Snooker behind the one game interface ([`GameRules`], issue 50): a [`SnookerGame`] is a
//! match of frames ([`SnookerMatch`]) with the frame in play ([`Frame`]), and turns the
//! WPBSA rules' own words into the interface's.

use super::balls::{WHITE, name};
use super::frame::{Frame, SnookerError};
use super::judge::Stroke;
use super::matches::SnookerMatch;
use super::verdict::{BallOn, Choice, NextShot};
use crate::hand::check_place;
use crate::interface::{
    CueBallPlace, Declaration, Declarations, GameEnd, GameRules, HandRegion, Judgement, RulesError,
    Setup, StrokeRecord, Turn,
};
use crate::turn::CueBall;
use crate::turn::Seat;
use billiards_physics::snooker::{default_cue_position, layout};
use billiards_physics::{BallSetup, BallSpec, SnookerMarks, Table, Vec2};

/// A snooker match in play: the frames won and the frame in play.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SnookerGame {
    /// Frames won and the best-of (2.1).
    pub frames: SnookerMatch,
    /// The frame in play.
    pub frame: Frame,
    /// The balls.
    pub ball: BallSpec,
    /// Strokes played in the frame (the first is the break-off, 3.2).
    pub strokes: u32,
}

fn err(e: SnookerError) -> RulesError {
    RulesError::from_display(e)
}

impl SnookerGame {
    /// A match of `best_of` frames (odd) between `players` on `table`; A breaks off the
    /// first frame.
    pub fn new(
        players: [String; 2],
        best_of: u32,
        table: Table,
        ball: BallSpec,
    ) -> Result<Self, RulesError> {
        let frames = SnookerMatch::new(best_of, Seat::A).map_err(err)?;
        let frame = Frame::new(players, table, &ball, Seat::A).map_err(err)?;
        Ok(Self {
            frames,
            frame,
            ball,
            strokes: 0,
        })
    }

    fn next(&self) -> &NextShot {
        &self.frame.next
    }

    /// The frame's end as the interface says it.
    fn frame_end(&self) -> Option<GameEnd> {
        self.frame.end.map(|(winner, how)| GameEnd {
            winner,
            reason: format!("frame won {how}"),
            match_over: self.frames.winner().is_some(),
        })
    }

    /// Counts a finished frame in the match.
    fn record_end(&mut self) -> Result<(), RulesError> {
        if let Some(winner) = self.frame.winner() {
            self.frames.record(winner).map_err(err)?;
        }
        Ok(())
    }

    /// The words for a choice: "play on", "put Ann back in", "replace the balls, Ann plays
    /// again", "Bob plays the black first".
    pub fn choice_label(&self, choice: Choice) -> String {
        let offender = self.frame.name(self.next().striker.other());
        match choice {
            Choice::PlayOn => "play on".to_owned(),
            Choice::PutBack => format!("put {offender} back in"),
            Choice::Replace => format!("replace the balls, {offender} plays again"),
            Choice::BlackFirst(seat) => format!("{} plays the black first", self.frame.name(seat)),
        }
    }
}

/// The nomination of a stroke: the player's, or else the ball hit first when that is the
/// obvious one (2.12: a colour after a red; 3.12: a free ball that is not otherwise on).
pub fn nomination(frame: &Frame, chosen: Option<u8>, first: Option<u8>) -> Option<u8> {
    chosen.or(match frame.next.on {
        BallOn::Colour { .. } => first.filter(|&c| super::balls::is_colour(c)),
        on if frame.next.free_ball => {
            first.filter(|n| !frame.balls_on(on).contains(n) && frame.on_table.contains(n))
        }
        _ => None,
    })
}

/// What is on in words: "a red", "a colour (the one hit first is nominated)", "the blue",
/// with a free ball if one may be nominated (2.12, 3.12).
pub fn on_text(next: &NextShot) -> String {
    let on = match next.on {
        BallOn::Colour { nominated: None } => {
            "a colour (the one hit first is nominated)".to_owned()
        }
        on => on.to_string(),
    };
    if next.free_ball {
        format!("{on}, or a free ball (any ball hit first is nominated)")
    } else {
        on
    }
}

impl GameRules for SnookerGame {
    fn name(&self) -> &'static str {
        "snooker"
    }

    fn players(&self) -> &[String; 2] {
        &self.frame.players
    }

    fn table(&self) -> Table {
        self.frame.table
    }

    fn ball(&self) -> BallSpec {
        self.ball
    }

    fn layout(&self) -> Result<Vec<BallSetup>, RulesError> {
        layout(
            &self.frame.table,
            &self.ball,
            default_cue_position(&self.frame.marks),
        )
        .map_err(RulesError)
    }

    fn turn(&self) -> Turn {
        let next = self.next();
        let on = self.frame.balls_on(next.on);
        // 3.12: with a free ball, any ball may be hit first (and is nominated).
        let legal_first = if next.free_ball {
            self.frame.on_table.clone()
        } else {
            on.clone()
        };
        let nominate = match next.on {
            _ if next.free_ball => self.frame.on_table.clone(),
            BallOn::Colour { nominated: None } => on,
            _ => Vec::new(),
        };
        Turn {
            striker: next.striker,
            cue_ball: WHITE,
            place: if next.in_hand {
                CueBallPlace::InHand {
                    region: HandRegion::D,
                }
            } else {
                CueBallPlace::AsItLies
            },
            legal_first,
            ball_on: on_text(next),
            declare: Declarations {
                nominate,
                ..Declarations::default()
            },
            opening: self.strokes == 0,
            choices: next.choices.iter().map(|&c| self.choice_label(c)).collect(),
        }
    }

    fn ball_name(&self, ball: u8) -> String {
        format!("the {}", name(ball))
    }

    fn choose(&mut self, index: usize, _layout: &[(u8, Vec2)]) -> Result<Setup, RulesError> {
        let choice = *self.next().choices.get(index).ok_or_else(|| {
            RulesError(format!(
                "option {index} is not offered ({} offered)",
                self.next().choices.len()
            ))
        })?;
        let chosen = self.frame.choose(choice).map_err(err)?;
        Ok(match chosen.layout {
            // 3.14: every ball back where it was before the foul.
            Some(balls) => Setup::Layout { balls },
            None => Setup::Keep,
        })
    }

    fn check_hand(&self, at: Vec2, others: &[(u8, Vec2)]) -> Result<(), RulesError> {
        if !(at.is_finite() && self.frame.marks.in_d(at)) {
            return Err(RulesError(
                "the cue ball in hand must be placed in the D (3.4)".to_owned(),
            ));
        }
        // Inside the D, the rest is pool's placement check: on the cloth, clear of balls.
        check_place(
            &self.frame.table,
            self.ball.radius,
            at,
            others,
            CueBall::InHandAnywhere,
        )
        .map_err(RulesError::from_display)
    }

    fn judge(&mut self, stroke: &StrokeRecord<'_>) -> Result<Judgement, RulesError> {
        let declared = match stroke.declared {
            Declaration::None => None,
            Declaration::Nominate { ball } => Some(ball),
            other => {
                return Err(RulesError(format!(
                    "snooker has no such declaration: {other:?}"
                )));
            }
        };
        let summary = stroke.summary()?;
        let nominated = nomination(&self.frame, declared, summary.first_contact);
        let verdict = self
            .frame
            .play(Stroke {
                summary: &summary,
                nominated,
                before: stroke.before,
                after: stroke.after,
            })
            .map_err(err)?;
        self.strokes += 1;
        self.record_end()?;
        let continues = verdict
            .next
            .as_ref()
            .is_some_and(|n| n.striker == verdict.striker && n.choices.is_empty());
        Ok(Judgement {
            striker: verdict.striker,
            fair: verdict.fair(),
            fouls: verdict.fouls.iter().map(ToString::to_string).collect(),
            text: verdict.text.clone(),
            put: verdict.spots.clone(),
            continues,
            end: self.frame_end(),
        })
    }

    fn score_line(&self) -> String {
        let f = &self.frame;
        format!(
            "snooker, best of {}: {} {} ({}) - ({}) {} {}",
            self.frames.best_of,
            f.name(Seat::A),
            f.scores[0],
            self.frames.frames[0],
            self.frames.frames[1],
            f.scores[1],
            f.name(Seat::B),
        )
    }

    fn points(&self) -> [u32; 2] {
        self.frame.scores
    }

    fn status(&self) -> Vec<String> {
        let f = &self.frame;
        if f.end.is_some() {
            return Vec::new();
        }
        let mut lines = vec![
            format!("ball on: {}", on_text(self.next())),
            format!(
                "break: {}, points remaining: {}",
                f.current_break,
                f.points_remaining()
            ),
        ];
        for seat in [Seat::A, Seat::B] {
            let needed = f.snookers_required(seat);
            if needed > 0 {
                lines.push(format!(
                    "{} needs {needed} snooker{}",
                    f.name(seat),
                    if needed == 1 { "" } else { "s" }
                ));
            }
        }
        lines
    }

    fn end(&self) -> Option<GameEnd> {
        self.frame_end()
    }

    fn match_winner(&self) -> Option<Seat> {
        self.frames.winner()
    }

    fn next_game(&mut self) -> Result<Vec<BallSetup>, RulesError> {
        if self.frame.end.is_none() || self.frames.winner().is_some() {
            return Err(RulesError(
                "the next frame starts once this one is over and the match is not".to_owned(),
            ));
        }
        // 2.1: the players break off in turn.
        let breaker = self.frames.next_breaker();
        self.frame = Frame::new(
            self.frame.players.clone(),
            self.frame.table,
            &self.ball,
            breaker,
        )
        .map_err(err)?;
        self.strokes = 0;
        let marks = SnookerMarks::of(&self.frame.table).map_err(RulesError)?;
        layout(&self.frame.table, &self.ball, default_cue_position(&marks)).map_err(RulesError)
    }

    /// 2.1(a): while the frame is in play.
    fn concedes(&self) -> bool {
        self.frame.end.is_none()
    }

    fn concede(&mut self) -> Result<GameEnd, RulesError> {
        let striker = self.next().striker;
        self.frame.concede(striker).map_err(err)?;
        self.record_end()?;
        self.frame_end()
            .ok_or_else(|| RulesError("the frame did not end".to_owned()))
    }

    fn boxed_clone(&self) -> Box<dyn GameRules> {
        Box::new(self.clone())
    }

    fn save(&self) -> Result<serde_json::Value, RulesError> {
        crate::interface::saved("snooker", self)
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
