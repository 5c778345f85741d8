//! Snooker in the game: a match of N frames under the WPBSA Official Rules (November 2019,
//! [`billiards_rules::snooker`]) on the 12-ft table.
//!
//! The flow is pool's with snooker's own state: [`flow`]'s `judge_stroke` judges a finished
//! stroke ([`Frame::play`]), logs it, spots the colours where the verdict says and puts a cue
//! ball in hand into the D; the game's commands take the incoming player's choices (play on,
//! put back, replace, who plays the re-spotted black), a concession and the next frame. A
//! colour after a red is nominated by the player, or is the one hit first (2.12: an obvious
//! ball needs no nomination); a free ball likewise (3.12).

use bevy::prelude::*;
use billiards_ai::Level;
use billiards_physics::{SnookerMarks, Vec2, snooker::default_cue_position};
use billiards_rules::Seat;
use billiards_rules::snooker::{
    self, BallOn, Choice, Frame, FrameEnd, FrameLog, NextShot, SnookerMatch, Verdict,
    balls::{is_colour, name},
};

pub mod flow;

pub(crate) use super::put::{layout_at, set_balls};
use super::turn::Turn;

/// A snooker match in play: the frames won, the frame in play, the players and what the
/// incoming player did since the last stroke.
#[derive(Debug, Clone)]
pub struct SnookerInPlay {
    /// Frames won and the best-of (2.1, a match of N frames).
    pub frames: SnookerMatch,
    /// The frame in play.
    pub frame: Frame,
    /// Each seat's computer level; `None`: a human.
    pub seats: [Option<Level>; 2],
    /// The frame's number from the match's seed: each frame takes the next.
    pub seed: u64,
    /// The colour (or free ball) nominated for the next stroke.
    pub nominated: Option<u8>,
    /// The last verdict.
    pub last: Option<Verdict>,
    /// The last verdict waits for the player.
    pub verdict_shown: bool,
    /// The last foul in words, kept until a later foul.
    pub last_foul: Option<String>,
    /// Choices taken since the last stroke.
    pub choices: Vec<Choice>,
    /// 3.14: a replace chosen: every ball to put where it was before the foul.
    pub pending_layout: Option<Vec<(u8, Vec2)>>,
    /// The frame's end has been counted in [`SnookerInPlay::frames`].
    pub recorded: bool,
    /// The frame's log (choices, nominations, verdicts), saved beside its recording.
    pub log: FrameLog,
}

/// Why a snooker match could not start.
#[derive(Debug, Clone, PartialEq)]
pub struct SnookerStartError(pub String);

impl SnookerInPlay {
    /// A match of `best_of` frames (odd) between `players`; A breaks the first frame.
    pub fn new(
        players: [String; 2],
        best_of: u32,
        seats: [Option<Level>; 2],
        seed: u64,
        table: &billiards_physics::Table,
        ball: &billiards_physics::BallSpec,
    ) -> Result<Self, SnookerStartError> {
        let err = |e: snooker::SnookerError| SnookerStartError(e.to_string());
        let frames = SnookerMatch::new(best_of, Seat::A).map_err(err)?;
        let log = FrameLog::new(players.clone(), Seat::A);
        let frame = Frame::new(players, *table, ball, Seat::A).map_err(err)?;
        Ok(Self {
            frames,
            frame,
            seats,
            seed,
            nominated: None,
            last: None,
            verdict_shown: false,
            last_foul: None,
            choices: Vec::new(),
            pending_layout: None,
            recorded: false,
            log,
        })
    }

    /// Counts a finished frame in the match, once.
    pub fn count_the_frame(&mut self) {
        if let Some(winner) = self.frame.winner()
            && !self.recorded
        {
            self.recorded = true;
            if let Err(error) = self.frames.record(winner) {
                warn!("frame not counted: {error}");
            }
        }
    }

    /// The next frame of the match, broken by the player whose turn it is (2.1), with its
    /// layout asked of the simulation.
    pub fn next_frame(
        &mut self,
        spec: &crate::table::geometry::TableSpec,
        settings: &crate::settings::PhysicsSettings,
        layouts: &mut MessageWriter<crate::sim::LayoutRequested>,
    ) -> Result<(), String> {
        let (table, ball) = equipment(spec, settings);
        let breaker = self.frames.next_breaker();
        let frame = Frame::new(self.frame.players.clone(), table, &ball, breaker)
            .map_err(|e| e.to_string())?;
        let request = rack_request(spec, settings)?;
        self.log = FrameLog::new(self.frame.players.clone(), breaker);
        self.frame = frame;
        self.seed = self.seed.wrapping_add(1);
        self.nominated = None;
        self.last = None;
        self.verdict_shown = false;
        self.last_foul = None;
        self.choices.clear();
        self.pending_layout = None;
        self.recorded = false;
        layouts.write(request);
        Ok(())
    }

    /// The next stroke.
    pub fn next(&self) -> &NextShot {
        &self.frame.next
    }

    /// The name of `seat`.
    pub fn name(&self, seat: Seat) -> &str {
        self.frame.name(seat)
    }

    /// The computer's level at `seat`, `None` for a human.
    pub fn computer(&self, seat: Seat) -> Option<Level> {
        self.seats[seat.index()]
    }

    /// Whether a human plays in this match.
    pub fn has_human(&self) -> bool {
        self.seats.iter().any(Option::is_none)
    }

    /// Which turn this is: the frame, the strokes and the choices so far.
    pub fn turn_key(&self) -> (u64, usize, usize) {
        (self.seed, self.log.strokes.len(), self.choices.len())
    }

    /// The turn's phase (with the balls at rest and no dialog open).
    pub fn phase(&self) -> Turn {
        if self.frame.end.is_some() {
            Turn::GameOver
        } else if self.verdict_shown || !self.next().choices.is_empty() {
            Turn::Verdict
        } else if self.next().in_hand {
            Turn::BallInHand
        } else {
            Turn::Aiming
        }
    }

    /// The HUD's lines: the match and the frame's score, the break, who plays and what is
    /// on, the points remaining and snookers required, the last verdict and foul.
    pub fn hud_lines(&self, turn: Turn) -> Vec<String> {
        let f = &self.frame;
        let next = self.next();
        let striker = self.name(next.striker);
        // The computer's seat marked from the start (issue 48), not only on its turn.
        let seat = |s: Seat| match self.computer(s) {
            Some(_) => format!("{} (computer)", self.name(s)),
            None => self.name(s).to_owned(),
        };
        let mut lines = vec![
            format!(
                "snooker, best of {}: frames {} {} - {} {}",
                self.frames.best_of,
                seat(Seat::A),
                self.frames.frames[0],
                self.frames.frames[1],
                seat(Seat::B),
            ),
            format!(
                "score: {} {} - {} {}",
                self.name(Seat::A),
                f.scores[0],
                f.scores[1],
                self.name(Seat::B)
            ),
        ];
        let doing = match turn {
            Turn::NewGame => "new game: choose the game and the players".to_owned(),
            Turn::ShotInPlay => format!("{striker} plays: balls moving"),
            Turn::GameOver => match (f.end, self.frames.winner()) {
                (Some((winner, end)), Some(_)) => {
                    format!("{} wins the frame ({end}) and the match", self.name(winner))
                }
                (Some((winner, end)), None) => {
                    format!("{} wins the frame ({end})", self.name(winner))
                }
                (None, _) => "the frame is over".to_owned(),
            },
            Turn::Verdict if !next.choices.is_empty() => format!(
                "{striker} to choose: {}",
                next.choices
                    .iter()
                    .map(|&c| choice_label(c, self))
                    .collect::<Vec<_>>()
                    .join(" or ")
            ),
            Turn::Verdict => format!("{striker} to play next: continue"),
            Turn::BallInHand | Turn::Aiming if let Some(level) = self.computer(next.striker) => {
                format!("{striker} (computer, {level}) to play")
            }
            Turn::BallInHand => {
                format!("{striker} to play: ball in hand in the D, drag the cue ball, aim, shoot")
            }
            Turn::Aiming | Turn::Calling => format!("{striker} to play: aim and shoot"),
        };
        lines.push(doing);
        if f.end.is_none() {
            lines.push(format!("ball on: {}", on_text(next, self.nominated)));
            lines.push(format!(
                "break: {}, points remaining: {}",
                f.current_break,
                f.points_remaining()
            ));
            for seat in [Seat::A, Seat::B] {
                let needed = f.snookers_required(seat);
                if needed > 0 {
                    lines.push(format!(
                        "{} needs {needed} snooker{}",
                        self.name(seat),
                        if needed == 1 { "" } else { "s" }
                    ));
                }
            }
        }
        if let Some(verdict) = &self.last {
            lines.push(format!("last stroke: {}", verdict.text));
        }
        if let Some(foul) = &self.last_foul {
            lines.push(format!("last foul: {foul}"));
        }
        lines
    }
}

/// The solver's table and ball of `spec` (the snooker table) under `settings`.
pub fn equipment(
    spec: &crate::table::geometry::TableSpec,
    settings: &crate::settings::PhysicsSettings,
) -> (billiards_physics::Table, billiards_physics::BallSpec) {
    let table = crate::sim::table_for(spec, settings);
    (table, crate::sim::params_for(spec, settings).ball)
}

/// A frame's 22 balls (WPBSA 3.2) as asked of the simulation; the recording is named
/// "snooker".
pub fn rack_request(
    spec: &crate::table::geometry::TableSpec,
    settings: &crate::settings::PhysicsSettings,
) -> Result<crate::sim::LayoutRequested, String> {
    let (table, ball) = equipment(spec, settings);
    Ok(crate::sim::LayoutRequested {
        balls: crate::sim::snooker_layout(&table, &ball)?,
        rack: billiards_physics::Rack::FifteenBall,
        name: "snooker",
    })
}

/// What is on, for the HUD: "a red", "a colour (the one hit first counts as nominated)",
/// "the blue", with a free ball if one may be nominated.
fn on_text(next: &NextShot, nominated: Option<u8>) -> String {
    let on = match (next.on, nominated) {
        (BallOn::Colour { .. }, Some(c)) => format!("the {} (nominated)", name(c)),
        (BallOn::Colour { .. }, None) => "a colour (the one hit first is nominated)".to_owned(),
        (on, _) => on.to_string(),
    };
    if next.free_ball {
        format!("{on}, or a free ball (any ball hit first is nominated)")
    } else {
        on
    }
}

/// The words for a choice: "play on", "put Ann back in", "replace the balls", "Bob plays
/// the black first".
pub fn choice_label(choice: Choice, game: &SnookerInPlay) -> String {
    let offender = game.name(game.next().striker.other());
    match choice {
        Choice::PlayOn => "play on".to_owned(),
        Choice::PutBack => format!("put {offender} back in"),
        Choice::Replace => format!("replace the balls, {offender} plays again"),
        Choice::BlackFirst(seat) => format!("{} plays the black first", game.name(seat)),
    }
}

/// The nomination for a stroke: the player's, or else the ball hit first when that is the
/// obvious one (2.12: a colour after a red; 3.12: a free ball that is not otherwise on).
pub(crate) fn nomination(frame: &Frame, chosen: Option<u8>, first: Option<u8>) -> Option<u8> {
    chosen.or(match frame.next.on {
        BallOn::Colour { .. } => first.filter(|&c| is_colour(c)),
        on if frame.next.free_ball => {
            first.filter(|n| !frame.balls_on(on).contains(n) && frame.on_table.contains(n))
        }
        _ => None,
    })
}

/// A free place for the cue ball in hand in the D: the usual one between the brown and the
/// yellow, else the first clear one of a sweep of the D.
pub fn free_place_in_d(sim: &billiards_physics::Simulation) -> Option<Vec2> {
    let marks = SnookerMarks::of(sim.table()).ok()?;
    let r = sim.params().ball.radius;
    let clear = |p: Vec2| {
        sim.balls()
            .zip(sim.numbers())
            .filter(|(s, n)| **n != 0 && s.motion.on_table())
            .all(|(s, _)| (s.position - p).length() > 2.0 * r + 1e-4)
    };
    let base = default_cue_position(&marks);
    std::iter::once(base)
        .chain((1..12).flat_map(|ring| {
            (0..12).map(move |k| {
                let a = std::f64::consts::TAU * f64::from(k) / 12.0;
                let d = f64::from(ring) * 0.02;
                base + Vec2::new(d * a.cos(), d * a.sin())
            })
        }))
        .find(|&p| marks.in_d(p) && clear(p))
}

/// The ends of a frame in words ("Ann wins the frame on points").
pub fn end_text(game: &SnookerInPlay, (winner, end): (Seat, FrameEnd)) -> String {
    format!("{} wins the frame {end}", game.name(winner))
}
