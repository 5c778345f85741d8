//! A drill as its file defines it ([`Drill`]): reading, checking, and the simulation and
//! rules' state it starts from.

use super::goal::Goal;
use crate::game::{GameState, Seat};
use crate::position::Position;
use crate::shot::CUE;
use billiards_physics::{BallSetup, Params, Simulation};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Most shots one attempt may take (a run-out of fifteen balls).
pub const MAX_SHOTS: u32 = 15;

fn one() -> u32 {
    1
}

fn ten() -> u32 {
    10
}

/// A drill: a position, its goals and the tries a session gives.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Drill {
    /// Its name in the drills list.
    pub name: String,
    /// What to do, in a sentence or two.
    #[serde(default)]
    pub description: String,
    /// The position it starts from (the cue ball, number 0, on the table).
    pub position: Position,
    /// Every goal must be met.
    pub goals: Vec<Goal>,
    /// Tries in a session (default 10).
    #[serde(default = "ten")]
    pub tries: u32,
    /// Most shots one attempt takes (default 1; a run-out takes several, one visit).
    #[serde(default = "one")]
    pub shots: u32,
}

/// A file of a drills folder: its name and its drill, or why it was refused.
pub type Loaded = (String, Result<Drill, DrillError>);

/// Why a drill file was refused.
#[derive(Debug, thiserror::Error)]
pub enum DrillError {
    /// The file could not be read.
    #[error("{0}")]
    Io(String),
    /// Not JSON, or not a drill's fields.
    #[error("not a drill: {0}")]
    Json(String),
    /// The position is not one a simulation starts from.
    #[error("the drill's position is not valid: {0}")]
    Position(String),
    /// No cue ball.
    #[error("the drill's position has no cue ball (number 0)")]
    NoCueBall,
    /// No goal.
    #[error("the drill has no goal")]
    NoGoal,
    /// A goal names a ball that is not on the table.
    #[error("the goal \"{goal}\" names the {ball}, which is not on the table")]
    NoSuchBall {
        /// The goal in words.
        goal: String,
        /// The ball.
        ball: u8,
    },
    /// A zone of no area, or not finite.
    #[error("the goal \"{0}\" has an empty or invalid zone")]
    BadZone(String),
    /// Zero tries, or zero or too many shots.
    #[error("the drill needs {0}")]
    Count(String),
    /// Goals no attempt can meet together.
    #[error("the drill's goals contradict each other: {0}")]
    Contradiction(String),
}

impl Drill {
    /// A drill from its JSON text, checked ([`Drill::check`]).
    pub fn from_json(text: &str) -> Result<Self, DrillError> {
        let d: Drill = serde_json::from_str(text).map_err(|e| DrillError::Json(e.to_string()))?;
        d.check()?;
        Ok(d)
    }

    /// The drill in the file `path`.
    pub fn load(path: &Path) -> Result<Self, DrillError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| DrillError::Io(format!("{}: {e}", path.display())))?;
        Self::from_json(&text)
    }

    /// Every `*.json` drill in `dir`, by file name; a bad file is reported with its name.
    pub fn load_dir(dir: &Path) -> Result<Vec<Loaded>, DrillError> {
        let mut names: Vec<_> = std::fs::read_dir(dir)
            .map_err(|e| DrillError::Io(format!("{}: {e}", dir.display())))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "json"))
            .collect();
        names.sort();
        Ok(names
            .into_iter()
            .map(|p| {
                let name = p
                    .file_name()
                    .unwrap_or_default()
                    .to_string_lossy()
                    .into_owned();
                (name, Self::load(&p))
            })
            .collect())
    }

    /// The drill is playable: a valid position with a cue ball, at least one goal, each
    /// naming balls on the table and zones of some area, tries and shots in range.
    pub fn check(&self) -> Result<(), DrillError> {
        self.position
            .check()
            .map_err(|e| DrillError::Position(e.to_string()))?;
        let on = |n: u8| self.position.balls.iter().any(|b| b.number == n);
        if !on(CUE) {
            return Err(DrillError::NoCueBall);
        }
        if self.goals.is_empty() {
            return Err(DrillError::NoGoal);
        }
        if self.tries == 0 {
            return Err(DrillError::Count("at least one try".into()));
        }
        if self.shots == 0 || self.shots > MAX_SHOTS {
            return Err(DrillError::Count(format!(
                "1 to {MAX_SHOTS} shots an attempt"
            )));
        }
        for g in &self.goals {
            let ball = match *g {
                Goal::Pocket { ball, .. }
                | Goal::FirstContact { ball, .. }
                | Goal::Hide { ball: Some(ball) } => Some(ball),
                _ => None,
            };
            if let Some(ball) = ball
                && (ball == CUE || !on(ball))
            {
                return Err(DrillError::NoSuchBall {
                    goal: g.text(),
                    ball,
                });
            }
            if let Goal::CueBallIn { zone } = g
                && !zone.valid()
            {
                return Err(DrillError::BadZone(g.text()));
            }
        }
        let pots = self
            .goals
            .iter()
            .any(|g| matches!(g, Goal::Pocket { .. } | Goal::RunOut));
        if pots && self.goals.contains(&Goal::NoPocket) {
            return Err(DrillError::Contradiction(
                "a ball must be pocketed and none may be".into(),
            ));
        }
        if self.goals.contains(&Goal::RunOut) && self.object_balls().is_empty() {
            return Err(DrillError::Contradiction(
                "a run-out with no object ball".into(),
            ));
        }
        Ok(())
    }

    /// The object balls of the position, ascending.
    pub fn object_balls(&self) -> Vec<u8> {
        let mut v: Vec<u8> = self
            .position
            .balls
            .iter()
            .map(|b| b.number)
            .filter(|&n| n != CUE)
            .collect();
        v.sort_unstable();
        v
    }

    /// A simulation of the position under `params` (the drill's own, if it carries them).
    pub fn simulation(&self, params: Params) -> Result<Simulation, DrillError> {
        let setups: Vec<BallSetup> = self
            .position
            .balls
            .iter()
            .map(|b| BallSetup::at(b.number, b.position))
            .collect();
        Simulation::new(
            self.position.table,
            self.position.params.unwrap_or(params),
            &setups,
        )
        .map_err(|e| DrillError::Position(e.to_string()))
    }

    /// The rules' state of the position: player A at the table, the cue ball as it lies.
    pub fn game_state(&self) -> GameState {
        GameState::in_progress(self.position.game, Seat::A, self.object_balls())
    }
}
