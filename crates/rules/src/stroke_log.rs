//! The rules log of any game, through the one interface ([`GameRules`], issue 50): the game
//! as it stood when the recording started ([`GameRules::save`]), and per stroke the options
//! taken before it, the declaration and the judgement. Saved beside a recording as every
//! game's log is (`NAME.game.json` next to `NAME.json`); [`StrokeLog::check`] replays the
//! recording, re-judges every stroke with [`GameRules::judge`] from the layouts the replay
//! rebuilds, and compares the judgements. The older pool and snooker logs ([`crate::GameLog`],
//! [`crate::snooker::FrameLog`]) are still read beside it ([`crate::RulesLog`]).
//!
//! What the recording holds between two strikes (as `Action::Place` inputs) is whatever the
//! game put back after the last judgement ([`Judgement::put`]) or after an option; the check
//! reads the table as it is at each strike, so a recording whose balls were moved by hand
//! between strokes is judged on the table it shows.

use crate::catalog::restore;
use crate::interface::{Declaration, GameRules, Judgement, StrokeRecord};
use crate::replay_strokes::{Replayed, StrokeJudge, layout, replay_strokes, strikes};
use billiards_physics::Simulation;
use billiards_physics::recording::Recording;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The format version this build writes.
pub const STROKE_LOG_VERSION: u32 = 1;

/// One stroke of the log.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StrokeEntry {
    /// The options taken before the stroke ([`GameRules::choose`]), by index, in order.
    #[serde(default)]
    pub choices: Vec<usize>,
    /// What the striker declared.
    #[serde(default)]
    pub declared: Declaration,
    /// The judgement given.
    pub judgement: Judgement,
}

/// The log of one recording of any game.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StrokeLog {
    /// [`STROKE_LOG_VERSION`] when written.
    pub version: u32,
    /// The game's name ([`GameRules::name`]).
    pub game: String,
    /// The players' names.
    pub players: [String; 2],
    /// The game when the recording started ([`GameRules::save`]).
    pub start: serde_json::Value,
    /// The strokes, in order.
    #[serde(default)]
    pub strokes: Vec<StrokeEntry>,
}

impl StrokeLog {
    /// An empty log of `game` as it stands now.
    pub fn new(game: &dyn GameRules) -> Result<Self, crate::RulesError> {
        Ok(Self {
            version: STROKE_LOG_VERSION,
            game: game.name().to_owned(),
            players: game.players().clone(),
            start: game.save()?,
            strokes: Vec::new(),
        })
    }

    /// The log's path beside the recording at `recording`: `NAME.game.json`.
    pub fn path_beside(recording: &Path) -> PathBuf {
        crate::GameLog::path_beside(recording)
    }

    /// Reads a log from its JSON text; another version or another file is refused, with why.
    pub fn from_json(text: &str) -> Result<Self, String> {
        let log: StrokeLog =
            serde_json::from_str(text).map_err(|e| format!("not a stroke log: {e}"))?;
        if log.version != STROKE_LOG_VERSION {
            return Err(format!(
                "stroke log version {} (this build reads {STROKE_LOG_VERSION})",
                log.version
            ));
        }
        Ok(log)
    }

    /// The timeline's line of every stroke, in order: "stroke 3, Ann (the 7 in the
    /// foot-left corner): foul: ...". The game is restored once, for its balls' names.
    pub fn lines(&self) -> Vec<String> {
        let game = restore(&self.start).ok();
        self.strokes
            .iter()
            .enumerate()
            .map(|(i, entry)| {
                let who = &self.players[entry.judgement.striker.index()];
                let declared = game
                    .as_ref()
                    .and_then(|g| entry.declared.text(&|b| g.ball_name(b)))
                    .map_or(String::new(), |d| format!(" ({d})"));
                format!(
                    "stroke {}, {who}{declared}: {}",
                    i + 1,
                    entry.judgement.text
                )
            })
            .collect()
    }

    /// Replays `recording` and re-judges each stroke from the game saved at its start:
    /// the number of judgements confirmed, or the first difference (or why the recording
    /// cannot be judged: another count of strikes, a stroke not of the cue ball, an input
    /// before the balls rested).
    pub fn check(&self, recording: &Recording) -> Result<usize, String> {
        if self.version != STROKE_LOG_VERSION {
            return Err(format!("stroke log version {}", self.version));
        }
        let strikes = strikes(recording);
        if strikes != self.strokes.len() {
            return Err(format!(
                "the log has {} strokes, the recording {strikes} strikes",
                self.strokes.len()
            ));
        }
        let game = restore(&self.start).map_err(|e| e.0)?;
        replay_strokes(recording, &mut Checker { log: self, game })
    }
}

/// The game re-judging a log's strokes as the recording replays.
struct Checker<'a> {
    log: &'a StrokeLog,
    game: Box<dyn GameRules>,
}

impl StrokeJudge for Checker<'_> {
    type Error = String;

    fn replay_error(&self, what: String) -> String {
        what
    }

    /// The logged options taken on the table as it is, then the struck ball checked.
    fn strike(&mut self, k: usize, sim: &Simulation, ball: usize) -> Result<(), String> {
        for &index in &self.log.strokes[k - 1].choices {
            self.game
                .choose(index, &layout(sim))
                .map_err(|e| format!("stroke {k}: option {index}: {e}"))?;
        }
        let cue = self.game.turn().cue_ball;
        let struck = sim.numbers().get(ball).copied();
        if struck != Some(cue) {
            return Err(format!(
                "stroke {k}: the strike is of ball {struck:?}, not of the cue ball {cue}"
            ));
        }
        Ok(())
    }

    /// Stroke `k` judged on the table the replay reached, against the logged judgement.
    fn rest(&mut self, sim: &Simulation, stroke: Replayed) -> Result<(), String> {
        let k = stroke.k;
        if !sim.is_at_rest() {
            return Err(format!(
                "stroke {k}: the next input came before its balls rested"
            ));
        }
        let entry = &self.log.strokes[k - 1];
        let after = layout(sim);
        let judgement = self
            .game
            .judge(&StrokeRecord {
                events: &sim.history().events()[stroke.first..],
                numbers: sim.numbers(),
                before: &stroke.before,
                after: &after,
                declared: entry.declared,
            })
            .map_err(|e| format!("stroke {k}: {e}"))?;
        if judgement != entry.judgement {
            return Err(format!(
                "stroke {k}: logged \"{}\", re-judged \"{}\"",
                entry.judgement.text, judgement.text
            ));
        }
        Ok(())
    }
}
