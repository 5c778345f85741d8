//! Recordings: everything needed to replay a game exactly, in a versioned JSON file.
//!
//! A recording is the setup (table, parameters, balls), the inputs in time order (strikes,
//! placements, parameter changes: the cue parameters, the model and all its constants, the
//! RNG seed) and the event history they produced. The solver is deterministic, so replaying
//! the inputs reproduces the history bit for bit; [`Recording::verify`] checks that, and any
//! instant can be sampled from the history without re-simulating.
//!
//! Files are written atomically (a temporary file in the same folder, synced, then renamed),
//! so a crash never leaves a half-written recording; loading checks the version, the shape and
//! the physics and reports which file and what is wrong.

use crate::ball::BallId;
use crate::ball::Segment;
use crate::event::{Event, EventKind, Shot};
use crate::history::History;
use crate::limits;
use crate::math::{Vec2, Vec3};
use crate::motion;
use crate::params::Params;
use crate::sim::{BallSetup, SetupError, SimError, Simulation};
use crate::table::Table;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The format version this build writes. Files with a newer version are refused.
pub const FORMAT_VERSION: u32 = 1;

/// What the player (or a script) did, at a simulation time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Input {
    /// Simulation time, seconds.
    pub time: f64,
    /// The action.
    pub action: Action,
}

/// An input to the simulation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Action {
    /// A cue strike.
    Strike {
        /// Ball struck.
        ball: BallId,
        /// The shot.
        shot: Shot,
    },
    /// A ball placed by hand (respot after a scratch, editor).
    Place {
        /// The ball.
        ball: BallId,
        /// New position.
        position: Vec2,
        /// New velocity.
        velocity: Vec2,
        /// New spin.
        spin: Vec3,
    },
    /// A ball set in the air ([`Simulation::launch`]: a scene file's ball in the air).
    Launch {
        /// The ball.
        ball: BallId,
        /// Height of its centre above its height on the cloth, metres.
        height: f64,
        /// Upward speed, m/s.
        vertical: f64,
    },
    /// New parameters (friction, restitution, model, randomization...).
    SetParams {
        /// The parameters.
        params: Params,
    },
}

impl Action {
    /// Gives this input to `sim` (a strike, a placement or new parameters), as the recording
    /// and every replay of it do.
    pub fn apply_to(self, sim: &mut Simulation) -> Result<(), SetupError> {
        match self {
            Action::Strike { ball, shot } => sim.strike(ball, shot),
            Action::Place {
                ball,
                position,
                velocity,
                spin,
            } => sim.place(ball, position, velocity, spin),
            Action::Launch {
                ball,
                height,
                vertical,
            } => sim.launch(ball, height, vertical),
            Action::SetParams { params } => sim.set_params(params),
        }
    }
}

/// A recorded game.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Recording {
    /// Format version ([`FORMAT_VERSION`] when written by this build).
    pub version: u32,
    /// The table.
    pub table: Table,
    /// Parameters at the start (later changes are inputs).
    pub params: Params,
    /// The balls at the start.
    pub balls: Vec<BallSetup>,
    /// Inputs in time order.
    pub inputs: Vec<Input>,
    /// Simulation time the recording ends at.
    pub end_time: f64,
    /// Every event the inputs produced, in order.
    pub events: Vec<Event>,
}

/// Why a recording could not be loaded, saved or replayed.
#[derive(Debug, thiserror::Error)]
pub enum RecordingError {
    /// The file could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The file is not a recording (malformed, truncated, wrong types).
    #[error("{path}: not a valid recording: {source}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// What serde found, with line and column.
        source: serde_json::Error,
    },
    /// Written by a newer version of the game.
    #[error("{path}: recording format version {found} is newer than this build's {supported}")]
    FutureVersion {
        /// The file.
        path: PathBuf,
        /// Version in the file.
        found: u32,
        /// Newest version this build reads.
        supported: u32,
    },
    /// The setup or an input is physically invalid (NaN, overlap, bad parameter...).
    #[error("{path}: invalid recording: {what}")]
    Invalid {
        /// The file.
        path: PathBuf,
        /// What is wrong, and where.
        what: String,
    },
}

/// Outcome of [`Recording::verify`].
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// Re-simulating the inputs reproduced every event bit for bit.
    Reproduced {
        /// Number of events compared.
        events: usize,
    },
    /// The histories differ; the first difference.
    Differs {
        /// Index of the first differing event.
        index: usize,
        /// The recorded event there, if any.
        recorded: Option<Box<Event>>,
        /// The re-simulated event there, if any.
        replayed: Option<Box<Event>>,
    },
}

impl Recording {
    /// A recording of a game that starts from this setup (no inputs yet).
    pub fn new(table: Table, params: Params, balls: Vec<BallSetup>) -> Self {
        Self {
            version: FORMAT_VERSION,
            table,
            params,
            balls,
            inputs: Vec::new(),
            end_time: 0.0,
            events: Vec::new(),
        }
    }

    /// Builds the simulation at the start of the recording.
    pub fn start(&self) -> Result<Simulation, SetupError> {
        Simulation::new(self.table, self.params, &self.balls)
    }

    /// Re-simulates the inputs from the setup, up to `end_time`.
    pub fn replay(&self) -> Result<Simulation, String> {
        let mut sim = self.start().map_err(|e| format!("setup: {e}"))?;
        for (k, input) in self.inputs.iter().enumerate() {
            let at = |e: &dyn std::fmt::Display| format!("input {k} at t = {}: {e}", input.time);
            sim.advance_to(input.time).map_err(|e: SimError| at(&e))?;
            input.action.apply_to(&mut sim).map_err(|e| at(&e))?;
        }
        sim.advance_to(self.end_time)
            .map_err(|e| format!("to the end time {}: {e}", self.end_time))?;
        Ok(sim)
    }

    /// Re-simulates the recording and compares the histories bit for bit.
    pub fn verify(&self) -> Result<Verdict, String> {
        let sim = self.replay()?;
        let replayed = sim.history().events();
        let n = replayed.len().max(self.events.len());
        for index in 0..n {
            let (a, b) = (self.events.get(index), replayed.get(index));
            // Compare the bits: -0.0 and 0.0, or two NaNs, must not pass for each other.
            if bits(a) != bits(b) {
                return Ok(Verdict::Differs {
                    index,
                    recorded: a.map(|e| Box::new(*e)),
                    replayed: b.map(|e| Box::new(*e)),
                });
            }
        }
        Ok(Verdict::Reproduced { events: n })
    }

    /// The recorded history with every ball's trajectory, rebuilt from the recorded events
    /// without re-simulating (each event's after-states start new closed-form segments), so
    /// any instant can be sampled exactly with [`History::states_at`].
    pub fn history(&self) -> Result<History, String> {
        let sim = self.start().map_err(|e| format!("setup: {e}"))?;
        let initial: Vec<Segment> = (0..sim.ball_count()).map(|i| *sim.segment(i)).collect();
        let mut history = History::new(&initial, self.params);
        let mut param_changes = self.inputs.iter().filter_map(|i| match i.action {
            Action::SetParams { params } => Some(params),
            _ => None,
        });
        for e in &self.events {
            if e.kind == EventKind::ParamsChanged {
                let params = param_changes
                    .next()
                    .ok_or("a parameter change has no recorded parameters")?;
                // Every ball continues from where its segment so far has taken it.
                let segments: Vec<Segment> = (0..history.ball_count())
                    .map(|id| {
                        let seg = history.segment(id, history.track_len(id) - 1);
                        motion::under_new_params(&params, e.time, &seg)
                    })
                    .collect();
                history.push_all(*e, &segments, params);
            } else {
                history.push(*e);
            }
        }
        Ok(history)
    }

    /// Writes the recording to `path` atomically: a temporary file next to it, flushed and
    /// synced, then renamed over `path`.
    pub fn save(&self, path: &Path) -> Result<(), RecordingError> {
        let io = |source| RecordingError::Io {
            path: path.to_path_buf(),
            source,
        };
        let text = serde_json::to_string(self).map_err(|e| RecordingError::Invalid {
            path: path.to_path_buf(),
            what: e.to_string(),
        })?;
        let dir = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        std::fs::create_dir_all(dir).map_err(io)?;
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let tmp = dir.join(format!(".{name}.tmp{}", std::process::id()));
        {
            use std::io::Write;
            let mut f = std::fs::File::create(&tmp).map_err(io)?;
            f.write_all(text.as_bytes()).map_err(io)?;
            f.sync_all().map_err(io)?;
        }
        std::fs::rename(&tmp, path).map_err(io)
    }

    /// Reads and checks a recording: its version, its shape and its physics (the setup must
    /// build a valid simulation and every number must be finite).
    pub fn load(path: &Path) -> Result<Self, RecordingError> {
        let text = std::fs::read_to_string(path).map_err(|source| RecordingError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::from_json(&text, path)
    }

    /// Parses and checks a recording from JSON text; `path` only names it in errors.
    pub fn from_json(text: &str, path: &Path) -> Result<Self, RecordingError> {
        let p = || path.to_path_buf();
        // Look at the version first, so a newer file says so instead of a shape error.
        #[derive(Deserialize)]
        struct Version {
            version: u32,
        }
        let v: Version = serde_json::from_str(text)
            .map_err(|source| RecordingError::Parse { path: p(), source })?;
        if v.version > FORMAT_VERSION {
            return Err(RecordingError::FutureVersion {
                path: p(),
                found: v.version,
                supported: FORMAT_VERSION,
            });
        }
        let rec: Recording = serde_json::from_str(text)
            .map_err(|source| RecordingError::Parse { path: p(), source })?;
        rec.check()
            .map_err(|what| RecordingError::Invalid { path: p(), what })?;
        Ok(rec)
    }

    /// Physical validity: the setup builds, inputs are within the contract ([`crate::limits`])
    /// and in time order, events are in time order and finite.
    pub fn check(&self) -> Result<(), String> {
        let sim = self.start().map_err(|e| format!("setup: {e}"))?;
        limits::check_clock(self.end_time).map_err(|e| format!("end_time: {e}"))?;
        let mut last = 0.0;
        for (k, input) in self.inputs.iter().enumerate() {
            if !(input.time.is_finite() && input.time >= last && input.time <= self.end_time) {
                return Err(format!(
                    "input {k} has time {} out of order or past the end",
                    input.time
                ));
            }
            check_action(&sim, &input.action).map_err(|e| format!("input {k}: {e}"))?;
            last = input.time;
        }
        let mut last = 0.0;
        for (k, e) in self.events.iter().enumerate() {
            let finite = e.time.is_finite()
                && e.after.iter().all(|s| {
                    s.position.is_finite()
                        && s.velocity.is_finite()
                        && s.angular_velocity.is_finite()
                });
            if !finite || e.time < last {
                return Err(format!("event {k} is not finite or out of order"));
            }
            let n = self.balls.len();
            if e.kind.balls().any(|b| b >= n) {
                return Err(format!("event {k} names a ball that does not exist"));
            }
            last = e.time;
        }
        Ok(())
    }
}

/// An input's own values against the contract, naming its ball (whether the ball is on the
/// table, or the tip within the miscue limit, only the replay can tell).
fn check_action(sim: &Simulation, action: &Action) -> Result<(), String> {
    let number = |ball: BallId| {
        sim.numbers()
            .get(ball)
            .copied()
            .ok_or_else(|| format!("there is no ball {ball}"))
    };
    match *action {
        Action::Strike { ball, shot } => {
            let n = number(ball)?;
            limits::check_shot(&shot).map_err(|e| e.for_ball(ball, n).to_string())
        }
        Action::Place {
            ball,
            velocity,
            spin,
            ..
        } => {
            let (n, r) = (number(ball)?, sim.params().ball.radius);
            limits::check_motion(velocity, spin, r).map_err(|e| e.for_ball(ball, n).to_string())
        }
        Action::Launch {
            ball,
            height,
            vertical,
        } => {
            let n = number(ball)?;
            limits::check_flight(height, vertical).map_err(|e| e.for_ball(ball, n).to_string())
        }
        Action::SetParams { params } => params.validate().map_err(|e| e.to_string()),
    }
}

fn bits(e: Option<&Event>) -> Option<String> {
    // Debug output of f64 round-trips exactly, so equal strings mean equal bits here.
    e.map(|e| format!("{e:?}"))
}

/// A simulation that records every input it is given, so the game (or a script) can save an
/// exact [`Recording`] at any moment.
#[derive(Clone, Debug)]
pub struct Recorder {
    sim: Simulation,
    recording: Recording,
}

impl Recorder {
    /// Starts a recorded game from this setup.
    pub fn new(table: Table, params: Params, balls: Vec<BallSetup>) -> Result<Self, SetupError> {
        let sim = Simulation::new(table, params, &balls)?;
        Ok(Self {
            sim,
            recording: Recording::new(table, params, balls),
        })
    }

    /// The simulation (read only: inputs go through the recorder).
    pub fn sim(&self) -> &Simulation {
        &self.sim
    }

    /// See [`Simulation::advance`].
    pub fn advance(&mut self, dt: f64) -> Result<crate::sim::Advance, SimError> {
        self.sim.advance(dt)
    }

    /// See [`Simulation::step_event`].
    pub fn step_event(&mut self) -> Option<Event> {
        self.sim.step_event()
    }

    /// See [`Simulation::run_to_rest`].
    pub fn run_to_rest(&mut self) -> Result<crate::sim::Advance, SimError> {
        self.sim.run_to_rest()
    }

    fn apply(&mut self, action: Action) -> Result<(), SetupError> {
        action.apply_to(&mut self.sim)?;
        // Only inputs the simulation accepted are recorded.
        self.recording.inputs.push(Input {
            time: self.sim.time(),
            action,
        });
        Ok(())
    }

    /// A cue strike (recorded).
    pub fn strike(&mut self, ball: BallId, shot: Shot) -> Result<(), SetupError> {
        self.apply(Action::Strike { ball, shot })
    }

    /// Places a ball (recorded).
    pub fn place(
        &mut self,
        ball: BallId,
        position: Vec2,
        velocity: Vec2,
        spin: Vec3,
    ) -> Result<(), SetupError> {
        self.apply(Action::Place {
            ball,
            position,
            velocity,
            spin,
        })
    }

    /// Sets a ball in the air (recorded; [`Simulation::launch`]).
    pub fn launch(&mut self, ball: BallId, height: f64, vertical: f64) -> Result<(), SetupError> {
        self.apply(Action::Launch {
            ball,
            height,
            vertical,
        })
    }

    /// Changes the parameters (recorded).
    pub fn set_params(&mut self, params: Params) -> Result<(), SetupError> {
        self.apply(Action::SetParams { params })
    }

    /// The recording up to now.
    pub fn recording(&self) -> Recording {
        Recording {
            end_time: self.sim.time(),
            events: self.sim.history().events().to_vec(),
            ..self.recording.clone()
        }
    }
}
