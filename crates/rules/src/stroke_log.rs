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
use billiards_physics::recording::{Action, Recording};
use billiards_physics::{Simulation, Vec2};
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

/// A stroke in flight in the check: its number, the layout at the strike and its first event.
type InFlight = (usize, Vec<(u8, Vec2)>, usize);

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

    /// The line of stroke `k` (from 1) for a timeline: "stroke 3, Ann (the 7 in the
    /// foot-left corner): foul: ...".
    pub fn line(&self, k: usize) -> Option<String> {
        let entry = self.strokes.get(k.checked_sub(1)?)?;
        let who = &self.players[entry.judgement.striker.index()];
        let declared = restore(&self.start)
            .ok()
            .and_then(|g| entry.declared.text(&|b| g.ball_name(b)))
            .map_or(String::new(), |d| format!(" ({d})"));
        Some(format!(
            "stroke {k}, {who}{declared}: {}",
            entry.judgement.text
        ))
    }

    /// Replays `recording` and re-judges each stroke from the game saved at its start:
    /// the number of judgements confirmed, or the first difference (or why the recording
    /// cannot be judged: another count of strikes, a stroke not of the cue ball, an input
    /// before the balls rested).
    pub fn check(&self, recording: &Recording) -> Result<usize, String> {
        if self.version != STROKE_LOG_VERSION {
            return Err(format!("stroke log version {}", self.version));
        }
        let strikes = recording
            .inputs
            .iter()
            .filter(|i| matches!(i.action, Action::Strike { .. }))
            .count();
        if strikes != self.strokes.len() {
            return Err(format!(
                "the log has {} strokes, the recording {strikes} strikes",
                self.strokes.len()
            ));
        }
        let mut game = restore(&self.start).map_err(|e| e.0)?;
        let mut sim = recording.start().map_err(|e| format!("setup: {e}"))?;
        let mut pending: Option<InFlight> = None;
        let mut k = 0;
        for (i, input) in recording.inputs.iter().enumerate() {
            let replay =
                |e: &dyn std::fmt::Display| format!("input {i} at t = {}: {e}", input.time);
            sim.advance_to(input.time).map_err(|e| replay(&e))?;
            if let Some(p) = pending.take() {
                self.judge(game.as_mut(), &sim, p)?;
            }
            match input.action {
                Action::Strike { ball, shot } => {
                    k += 1;
                    let entry = &self.strokes[k - 1];
                    for &index in &entry.choices {
                        game.choose(index, &layout(&sim))
                            .map_err(|e| format!("stroke {k}: option {index}: {e}"))?;
                    }
                    let cue = game.turn().cue_ball;
                    let struck = sim.numbers().get(ball).copied();
                    if struck != Some(cue) {
                        return Err(format!(
                            "stroke {k}: the strike is of ball {struck:?}, not of the cue ball {cue}"
                        ));
                    }
                    let before = layout(&sim);
                    let first = sim.history().events().len();
                    sim.strike(ball, shot).map_err(|e| replay(&e))?;
                    pending = Some((k, before, first));
                }
                Action::Place {
                    ball,
                    position,
                    velocity,
                    spin,
                } => sim
                    .place(ball, position, velocity, spin)
                    .map_err(|e| replay(&e))?,
                Action::SetParams { params } => sim.set_params(params).map_err(|e| replay(&e))?,
            }
        }
        if let Some(p) = pending.take() {
            sim.advance_to(recording.end_time)
                .map_err(|e| format!("to the end: {e}"))?;
            if !sim.is_at_rest() {
                // Saved while the balls were moving: the rest follows from the physics.
                sim.run_to_rest().map_err(|e| format!("to rest: {e}"))?;
            }
            self.judge(game.as_mut(), &sim, p)?;
        }
        Ok(self.strokes.len())
    }

    /// Judges stroke `k` on the table the replay reached, against the logged judgement.
    fn judge(
        &self,
        game: &mut dyn GameRules,
        sim: &Simulation,
        (k, before, first): InFlight,
    ) -> Result<(), String> {
        if !sim.is_at_rest() {
            return Err(format!(
                "stroke {k}: the next input came before its balls rested"
            ));
        }
        let entry = &self.strokes[k - 1];
        let after = layout(sim);
        let judgement = game
            .judge(&StrokeRecord {
                events: &sim.history().events()[first..],
                numbers: sim.numbers(),
                before: &before,
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

/// Every ball on the table by number.
fn layout(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}
