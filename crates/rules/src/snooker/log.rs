//! The rules log of a snooker frame: the players, who broke, and per stroke the choices
//! taken before it, the colour nominated and the verdict. Saved beside a recording
//! (`NAME.game.json` next to `NAME.json`, the one name every game's log has; older builds
//! wrote `NAME.snooker.json`, still read: [`FrameLog::old_path_beside`]); [`FrameLog::check`] replays the recording,
//! rebuilds the layouts at every strike and at rest, re-judges every stroke with
//! [`Frame::play`] and compares the verdicts.
//!
//! What the recording must hold between two strikes (as `Action::Place` inputs, at the
//! time the balls rest): the colours of the last verdict on their spots (3.6, `Verdict::spots`),
//! after a replace (3.14) every ball where [`super::Chosen::layout`] puts it, and with the
//! cue ball in hand (3.4) the cue ball in the D. The check refuses a strike whose table
//! differs from what the rules left.

use super::balls::{WHITE, name};
use super::frame::{Frame, SnookerError};
use super::judge::Stroke;
use super::verdict::{Choice, Verdict};
use crate::game::Seat;
use crate::replay_strokes::{Replayed, StrokeJudge, layout, replay_strokes, strikes};
use crate::shot::summarise;
use billiards_physics::Vec2;
use billiards_physics::recording::Recording;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The format version this build writes.
pub const FRAME_LOG_VERSION: u32 = 1;

/// How far a ball may be from where the rules put it, metres (rounding only).
const PLACE_TOLERANCE: f64 = 1e-9;

/// One stroke of the log.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LoggedStroke {
    /// Choices taken before the stroke ([`Frame::choose`]), in order.
    #[serde(default)]
    pub choices: Vec<Choice>,
    /// The colour nominated (2.12) or the free ball (3.12), as passed to [`Stroke`].
    #[serde(default)]
    pub nominated: Option<u8>,
    /// The verdict given.
    pub verdict: Verdict,
}

/// The rules side of a recorded snooker frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrameLog {
    /// Format version ([`FRAME_LOG_VERSION`]).
    pub version: u32,
    /// The players' names, by [`Seat::index`] (the verdicts' sentences name them).
    pub players: [String; 2],
    /// Who broke off.
    pub breaker: Seat,
    /// The strokes, in order (one per strike of the recording).
    #[serde(default)]
    pub strokes: Vec<LoggedStroke>,
}

/// Why a frame log does not match its recording.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FrameLogError {
    /// Another format version.
    #[error("frame log version {found} (this build reads {FRAME_LOG_VERSION})")]
    Version {
        /// Version in the log.
        found: u32,
    },
    /// Not as many strokes as strikes.
    #[error("the log has {logged} strokes, the recording {recorded} strikes")]
    StrokeCount {
        /// Strokes in the log.
        logged: usize,
        /// Strikes in the recording.
        recorded: usize,
    },
    /// The recording does not replay (its setup or an input is refused).
    #[error("the recording does not replay: {0}")]
    Replay(String),
    /// The recording's table cannot carry a frame (not a snooker table).
    #[error("not a snooker recording: {0}")]
    Frame(SnookerError),
    /// A strike other than of the cue ball.
    #[error("stroke {stroke}: the strike is of ball {ball}, not of the cue ball")]
    NotTheCueBall {
        /// The stroke, from 1.
        stroke: usize,
        /// The number of the ball struck.
        ball: u8,
    },
    /// An input (a placement or the next strike) before the balls of a stroke came to rest.
    #[error("stroke {stroke}: the next input came before its balls rested")]
    NotAtRest {
        /// The stroke, from 1.
        stroke: usize,
    },
    /// The table at a strike is not the one the rules left (a colour not spotted, a replace
    /// not done, a ball that should be off the table).
    #[error("stroke {stroke}: {what}")]
    Table {
        /// The stroke, from 1.
        stroke: usize,
        /// What is wrong.
        what: String,
    },
    /// A logged choice or the stroke is refused by the rules.
    #[error("stroke {stroke}: {error}")]
    Refused {
        /// The stroke, from 1.
        stroke: usize,
        /// The rules' answer.
        error: SnookerError,
    },
    /// The rules give another verdict than the one logged.
    #[error("stroke {stroke}: logged \"{logged}\", re-judged \"{rejudged}\"")]
    Differs {
        /// The stroke, from 1.
        stroke: usize,
        /// The logged verdict's sentence.
        logged: String,
        /// The new verdict's sentence.
        rejudged: String,
    },
}

/// What the rules left on the table for the next strike.
#[derive(Default)]
struct Expected {
    /// Balls that must be at these places (spotted colours, a replaced layout).
    at: Vec<(u8, Vec2)>,
}

impl FrameLog {
    /// An empty log of a frame between `players`, `breaker` breaking off.
    pub fn new(players: [String; 2], breaker: Seat) -> Self {
        Self {
            version: FRAME_LOG_VERSION,
            players,
            breaker,
            strokes: Vec::new(),
        }
    }

    /// Where the log of the recording at `recording` is kept: `NAME.game.json` beside
    /// `NAME.json`, the name a pool game's log has too ([`crate::GameLog::path_beside`]);
    /// readers tell the two apart by content ([`crate::RulesLog::from_json`]).
    pub fn path_beside(recording: &Path) -> PathBuf {
        crate::GameLog::path_beside(recording)
    }

    /// Where builds before the one-name change kept a frame's log: `NAME.snooker.json`.
    /// Readers still look there ([`crate::RulesLog::beside`]) so that recordings saved then
    /// still open and verify with their verdicts; nothing writes it any more.
    pub fn old_path_beside(recording: &Path) -> PathBuf {
        recording.with_extension("snooker.json")
    }

    /// Reads a log from its JSON text, refusing other format versions.
    pub fn from_json(text: &str) -> Result<Self, String> {
        let log: FrameLog =
            serde_json::from_str(text).map_err(|e| format!("not a frame log: {e}"))?;
        if log.version != FRAME_LOG_VERSION {
            return Err(FrameLogError::Version { found: log.version }.to_string());
        }
        Ok(log)
    }

    /// Replays `recording` (its setup, placements and strikes), rebuilds the layout at each
    /// strike and at rest, applies the logged choices, re-judges every stroke with
    /// [`Frame::play`] and checks each verdict is the logged one and each strike's table is
    /// the one the rules left. Returns the strokes checked.
    pub fn check(&self, recording: &Recording) -> Result<usize, FrameLogError> {
        if self.version != FRAME_LOG_VERSION {
            return Err(FrameLogError::Version {
                found: self.version,
            });
        }
        let strikes = strikes(recording);
        if strikes != self.strokes.len() {
            return Err(FrameLogError::StrokeCount {
                logged: self.strokes.len(),
                recorded: strikes,
            });
        }
        let frame = Frame::new(
            self.players.clone(),
            recording.table,
            &recording.params.ball,
            self.breaker,
        )
        .map_err(FrameLogError::Frame)?;
        let mut checker = FrameChecker {
            log: self,
            frame,
            expected: Expected::default(),
        };
        replay_strokes(recording, &mut checker)?;
        Ok(self.strokes.len())
    }
}

/// The frame re-judging a log's strokes as the recording replays, with the balls the rules
/// put back after the last one.
struct FrameChecker<'a> {
    log: &'a FrameLog,
    frame: Frame,
    expected: Expected,
}

impl StrokeJudge for FrameChecker<'_> {
    type Error = FrameLogError;

    fn replay_error(&self, what: String) -> FrameLogError {
        FrameLogError::Replay(what)
    }

    /// The logged choices taken, the struck ball and the table checked against the rules.
    fn strike(
        &mut self,
        k: usize,
        sim: &billiards_physics::Simulation,
        ball: usize,
    ) -> Result<(), FrameLogError> {
        let refused = |error| FrameLogError::Refused { stroke: k, error };
        for &choice in &self.log.strokes[k - 1].choices {
            if let Some(l) = self.frame.choose(choice).map_err(refused)?.layout {
                self.expected.at = l;
            }
        }
        let n = sim.numbers().get(ball).copied().unwrap_or(u8::MAX);
        if n != WHITE {
            return Err(FrameLogError::NotTheCueBall { stroke: k, ball: n });
        }
        check_table(&self.frame, &layout(sim), &self.expected, k)
    }

    /// Judges the stroke once the balls rest and compares its verdict; the balls the rules
    /// put back (the verdict's spots) are expected at the next strike.
    fn rest(
        &mut self,
        sim: &billiards_physics::Simulation,
        stroke: Replayed,
    ) -> Result<(), FrameLogError> {
        let k = stroke.k;
        if !sim.is_at_rest() {
            return Err(FrameLogError::NotAtRest { stroke: k });
        }
        let logged = &self.log.strokes[k - 1];
        let summary = summarise(&sim.history().events()[stroke.first..], sim.numbers());
        let after = layout(sim);
        let verdict = self
            .frame
            .play(Stroke {
                summary: &summary,
                nominated: logged.nominated,
                before: &stroke.before,
                after: &after,
            })
            .map_err(|error| FrameLogError::Refused { stroke: k, error })?;
        if verdict != logged.verdict {
            let show = |v: &Verdict| {
                format!(
                    "{} (on {}, nominated {:?}, scores {}-{})",
                    v.text, v.on, v.free_ball, v.scores[0], v.scores[1]
                )
            };
            return Err(FrameLogError::Differs {
                stroke: k,
                logged: show(&logged.verdict),
                rejudged: show(&verdict),
            });
        }
        self.expected = Expected { at: verdict.spots };
        Ok(())
    }
}

/// The table at stroke `k`'s strike against the rules: the object balls on it are the
/// frame's, and the balls the rules placed are where they put them (the cue ball in hand
/// excepted: it is placed anew, in the D, which [`Frame::play`] checks).
fn check_table(
    frame: &Frame,
    before: &[(u8, Vec2)],
    expected: &Expected,
    k: usize,
) -> Result<(), FrameLogError> {
    let table_err = |what: String| FrameLogError::Table { stroke: k, what };
    let mut objects: Vec<u8> = before
        .iter()
        .map(|&(n, _)| n)
        .filter(|&n| n != WHITE)
        .collect();
    objects.sort_unstable();
    if objects != frame.on_table {
        let missing: Vec<&str> = frame
            .on_table
            .iter()
            .filter(|n| !objects.contains(n))
            .map(|&n| name(n))
            .collect();
        let extra: Vec<&str> = objects
            .iter()
            .filter(|n| !frame.on_table.contains(n))
            .map(|&n| name(n))
            .collect();
        return Err(table_err(format!(
            "the balls on the table are not the frame's (missing {missing:?}, extra {extra:?})"
        )));
    }
    for &(n, p) in &expected.at {
        if n == WHITE && frame.next.in_hand {
            continue;
        }
        let at = before.iter().find(|b| b.0 == n).map(|b| b.1);
        match at {
            Some(q) if (q - p).length() <= PLACE_TOLERANCE => {}
            _ => {
                return Err(table_err(format!(
                    "the {} ({n}) is not where the rules put it ({:.4}, {:.4})",
                    name(n),
                    p.x,
                    p.y
                )));
            }
        }
    }
    Ok(())
}
