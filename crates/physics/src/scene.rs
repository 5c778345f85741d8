//! Scene files: a table, balls (or a standard rack), parameters, optional shots and how long to
//! run, as JSON. The format is documented in the crate's README section "Scene files".

use crate::ball::BallState;
use crate::event::{Event, Shot};
use crate::limits;
use crate::math::Vec2;
use crate::params::Params;
use crate::racks::Rack;
use crate::sim::{BallSetup, SetupError, SimError, Simulation};
use crate::table::Table;
use serde::{Deserialize, Serialize};

/// Where the balls come from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Layout {
    /// A standard rack by name.
    Rack {
        /// Which rack.
        rack: Rack,
    },
    /// Explicit balls.
    Balls {
        /// The balls.
        balls: Vec<BallSetup>,
    },
}

/// How long to run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Duration {
    /// Until every ball rests (bounded by `params.max_events`).
    UntilRest,
    /// This many seconds of simulated time.
    Seconds(f64),
}

/// A scene: everything needed to run a simulation from a file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// Table geometry (default: the WPA 8-ft table).
    #[serde(default)]
    pub table: Table,
    /// Parameters (default: the paper's model with default constants).
    #[serde(default)]
    pub params: Params,
    /// The balls.
    #[serde(flatten)]
    pub layout: Layout,
    /// Balls in the air at time 0 (set before the shots are played).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub flights: Vec<SceneFlight>,
    /// Shots played at time 0, in order: `(ball, shot)`.
    #[serde(default)]
    pub shots: Vec<SceneShot>,
    /// How long to run.
    #[serde(default = "until_rest")]
    pub duration: Duration,
}

fn until_rest() -> Duration {
    Duration::UntilRest
}

/// A shot in a scene file.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneShot {
    /// Ball struck (default the cue ball, 0).
    #[serde(default)]
    pub ball: usize,
    /// The strike.
    #[serde(flatten)]
    pub shot: Shot,
}

/// A ball of a scene in the air at time 0 ([`Simulation::launch`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneFlight {
    /// The ball (its index among the scene's balls).
    pub ball: usize,
    /// Height of its centre above its height on the cloth, metres.
    pub height: f64,
    /// Upward speed, m/s (negative: falling).
    #[serde(default)]
    pub vertical: f64,
}

/// The outcome of running a scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneResult {
    /// Simulation time at the end, seconds.
    pub time: f64,
    /// Every event, in order.
    pub events: Vec<Event>,
    /// Final state of each ball.
    pub balls: Vec<BallState>,
    /// Set if the run stopped at the event cap.
    pub error: Option<String>,
}

/// Why a scene could not be run.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The JSON is malformed or has the wrong shape.
    #[error("scene file is not valid: {0}")]
    Parse(#[from] serde_json::Error),
    /// The scene is physically invalid.
    #[error("scene is invalid: {0}")]
    Setup(#[from] SetupError),
    /// A duration that is negative, not finite, or past [`crate::limits::MAX_TIME`].
    #[error("duration {0} s is out of range: from 0 to {max} s", max = crate::limits::MAX_TIME)]
    BadDuration(f64),
}

impl Scene {
    /// Parses a scene from JSON text.
    pub fn from_json(text: &str) -> Result<Self, SceneError> {
        Ok(serde_json::from_str(text)?)
    }

    /// The balls of this scene.
    pub fn balls(&self) -> Vec<BallSetup> {
        match &self.layout {
            Layout::Rack { rack } => rack.layout(&self.table, &self.params.ball),
            Layout::Balls { balls } => balls.clone(),
        }
    }

    /// Builds the simulation and plays the shots (at time 0).
    pub fn build(&self) -> Result<Simulation, SceneError> {
        let mut sim = Simulation::new(self.table, self.params, &self.balls())?;
        for f in &self.flights {
            sim.launch(f.ball, f.height, f.vertical)?;
        }
        for s in &self.shots {
            sim.strike(s.ball, s.shot)?;
        }
        Ok(sim)
    }

    /// Runs the scene; hitting the event cap is reported in the result, not as an error, so the
    /// events up to it are kept.
    pub fn run(&self) -> Result<SceneResult, SceneError> {
        let mut sim = self.build()?;
        let outcome = match self.duration {
            Duration::UntilRest => sim.run_to_rest().map(|_| ()),
            Duration::Seconds(s) if limits::check_clock(s).is_ok() => sim.advance(s).map(|_| ()),
            Duration::Seconds(s) => return Err(SceneError::BadDuration(s)),
        };
        Ok(SceneResult {
            time: sim.time(),
            events: sim.history().events().to_vec(),
            balls: sim.balls().collect(),
            error: outcome.err().map(|e: SimError| e.to_string()),
        })
    }
}

impl Default for Scene {
    fn default() -> Self {
        Self {
            table: Table::default(),
            params: Params::default(),
            layout: Layout::Balls {
                balls: vec![BallSetup::at(0, Vec2::ZERO)],
            },
            flights: Vec::new(),
            shots: Vec::new(),
            duration: Duration::UntilRest,
        }
    }
}
