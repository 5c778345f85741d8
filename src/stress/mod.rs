//! The stress table (issue 37): free play with many balls on a larger table
//! ([`billiards_physics::racks::stress`]), run by the same exclusive solver step as any rack,
//! with live checks for the HUD: events a second, the solver's share of the frame, the
//! kinetic energy (it may only fall, and stays put without friction) and the deepest overlap
//! of two balls. The checks are O(n log n) a frame: the energy is one sum, the overlap a sweep
//! along x ([`billiards_physics::check::deepest_overlap`]), not a test of every pair.

use std::{collections::VecDeque, time::Instant};

use bevy::prelude::*;
use billiards_physics::{
    BallState, EventKind,
    check::{deepest_overlap, kinetic_energy},
    racks::{self, StressSpec},
};

use crate::{
    mode::GameMode,
    sim::{Referee, SceneRequested, SimStatus, SimSystems, Solver},
};

/// What names the stress table's solver and its recordings.
pub const STRESS_NAME: &str = "stress";

/// The ball counts the panel's slider offers (the physics crate takes up to
/// [`racks::STRESS_MAX_BALLS`], as the command line does).
pub const BALLS: std::ops::RangeInclusive<usize> = 16..=2000;

/// The table scales the panel offers when the size is chosen by hand (1: the 8-ft table).
pub const SCALES: std::ops::RangeInclusive<f64> = 1.0..=15.0;

/// Energy rise between two frames, relative, above which the HUD warns: rounding alone stays
/// near 1e-15 (measured: 8e-16 at 2,000 balls).
pub const ENERGY_RISE_WARNING: f64 = 1e-9;

/// Overlap of two balls, metres, above which the HUD warns (the solver's own tolerance).
pub const OVERLAP_WARNING: f64 = billiards_physics::sim::PLACEMENT_TOLERANCE;

/// Registers the stress table's settings, its request and the live checks.
pub fn plugin(app: &mut App) {
    app.init_resource::<StressSettings>()
        .init_resource::<StressMonitor>()
        .add_message::<StressRequested>()
        .add_systems(Startup, start_stress)
        .add_systems(
            Update,
            (
                watch_stress
                    .after(SimSystems::Step)
                    .before(SimSystems::Flow),
                request_stress
                    .after(SimSystems::Flow)
                    .before(crate::recording::SaveBeforeRack),
            )
                .run_if(in_state(GameMode::Play)),
        );
}

/// The stress table the panel sets up.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct StressSettings {
    /// Balls, the cue ball included.
    pub balls: usize,
    /// The paper's cloth friction (the balls come to rest) or none.
    pub friction: bool,
    /// Seed of the positions and velocities.
    pub seed: u64,
    /// `None`: the table grows with the count (the density of 16 balls on the 8-ft table);
    /// `Some(k)`: the 8-ft table scaled by `k`.
    pub scale: Option<f64>,
}

impl Default for StressSettings {
    fn default() -> Self {
        Self {
            balls: 1000,
            friction: false,
            seed: 1,
            scale: None,
        }
    }
}

impl StressSettings {
    /// The physics crate's spec for these settings.
    pub fn spec(&self) -> StressSpec {
        StressSpec {
            balls: self.balls,
            friction: self.friction,
            seed: self.seed,
            scale: self.scale,
        }
    }
}

/// Asks for the stress table of [`StressSettings`] (free play only).
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StressRequested;

/// `--stress BALLS`: start on the stress table with this many balls.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StartStress(pub usize);

/// Asks for the stress table of `--stress` (it wins over the default rack of the same frame).
fn start_stress(
    start: Option<Res<StartStress>>,
    mut settings: ResMut<StressSettings>,
    mut requests: MessageWriter<StressRequested>,
) {
    if let Some(start) = start {
        settings.balls = start.0;
        requests.write(StressRequested);
    }
}

/// The live checks of the stress table on the table now, for the HUD and the panel.
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct StressMonitor {
    /// The table on now is the stress table.
    pub active: bool,
    /// What was built: the settings at the rack.
    pub built: Option<StressSettings>,
    /// Table length and width, metres.
    pub table: (f64, f64),
    /// Why the last request was refused, until the next one.
    pub refused: Option<String>,
    /// Kinetic energy now, joules.
    pub energy: f64,
    /// Kinetic energy at the rack or the last input (strike, placement), joules.
    pub energy_start: f64,
    /// Largest relative rise of the energy from one frame to the next without an input.
    pub worst_energy_rise: f64,
    /// Deepest overlap of two balls now, metres (0: none).
    pub overlap: f64,
    /// Deepest overlap seen since the rack, metres.
    pub worst_overlap: f64,
    /// Events a second of real time, over the last second.
    pub events_per_second: f64,
    /// The solver's cost in the last frame that ran it, milliseconds.
    pub solver_ms: f64,
    /// The last frame, milliseconds of real time.
    pub frame_ms: f64,
    /// What these checks cost in the last frame, milliseconds.
    pub checks_ms: f64,
    /// Balls still on the table.
    pub on_table: usize,
}

/// Frames of events counted for the events a second: (real time, events so far).
#[derive(Default)]
struct EventWindow(VecDeque<(f64, usize)>);

/// Builds the stress table asked for, or says why not. Free play only: a match's table is its
/// own.
fn request_stress(
    mut requests: MessageReader<StressRequested>,
    settings: Res<StressSettings>,
    referee: Res<Referee>,
    mut scenes: MessageWriter<SceneRequested>,
    mut monitor: ResMut<StressMonitor>,
    mut status: ResMut<SimStatus>,
) {
    if requests.read().last().is_none() {
        return;
    }
    if !referee.edits {
        monitor.refused = Some("the stress table is free play: end the match first".into());
        return;
    }
    match racks::stress(&settings.spec()) {
        Ok(scene) => {
            monitor.refused = None;
            monitor.built = Some(*settings);
            monitor.table = (scene.table.length, scene.table.width);
            scenes.write(SceneRequested {
                table: scene.table,
                params: scene.params,
                balls: scene.balls,
                name: STRESS_NAME,
            });
        }
        Err(error) => {
            let why = format!("stress table refused: {error}");
            status.note = Some(why.clone());
            monitor.refused = Some(why);
        }
    }
}

/// The live checks, right after the solver's step: energy, overlap, events a second, costs.
fn watch_stress(
    solver: Option<Res<Solver>>,
    status: Res<SimStatus>,
    time: Res<Time<Real>>,
    mut monitor: ResMut<StressMonitor>,
    mut states: Local<Vec<BallState>>,
    mut window: Local<EventWindow>,
    mut seen: Local<Option<(std::time::SystemTime, usize)>>,
) {
    let Some(solver) = solver.filter(|s| s.is_scene() && s.name() == STRESS_NAME) else {
        if monitor.active {
            monitor.active = false;
        }
        return;
    };
    let started = Instant::now();
    let sim = solver.simulation();
    let events = sim.history().events();
    let fresh = seen.is_none_or(|(at, _)| at != solver.started());
    // Inputs since the last frame (a strike, a placement) change the energy on purpose.
    let input = seen.is_some_and(|(_, n)| {
        events[n.min(events.len())..].iter().any(|e| {
            matches!(
                e.kind,
                EventKind::Strike { .. } | EventKind::Placed { .. } | EventKind::ParamsChanged
            )
        })
    });
    *seen = Some((solver.started(), events.len()));
    states.clear();
    states.extend(sim.balls());
    let ball = sim.params().ball;
    let energy = kinetic_energy(&states, ball.mass, ball.radius);
    let overlap = deepest_overlap(&states, ball.radius).map_or(0.0, |(_, _, depth)| depth);
    let now = time.elapsed_secs_f64();
    if fresh {
        window.0.clear();
        let built = monitor.built;
        let table = monitor.table;
        let refused = monitor.refused.take();
        *monitor = StressMonitor {
            active: true,
            built,
            table,
            refused,
            energy_start: energy,
            ..default()
        };
    } else if input {
        monitor.energy_start = energy;
    } else {
        let rise = (energy - monitor.energy) / monitor.energy.max(f64::MIN_POSITIVE);
        monitor.worst_energy_rise = monitor.worst_energy_rise.max(rise);
    }
    window.0.push_back((now, events.len()));
    while window.0.len() > 2 && window.0.front().is_some_and(|&(t, _)| now - t > 1.0) {
        window.0.pop_front();
    }
    let events_per_second = match (window.0.front(), window.0.back()) {
        (Some(&(t0, n0)), Some(&(t1, n1))) if t1 > t0 => (n1 - n0) as f64 / (t1 - t0),
        _ => 0.0,
    };
    monitor.energy = energy;
    monitor.overlap = overlap;
    monitor.worst_overlap = monitor.worst_overlap.max(overlap);
    monitor.events_per_second = events_per_second;
    monitor.solver_ms = status.solver_seconds_last_frame * 1e3;
    monitor.frame_ms = time.delta_secs_f64() * 1e3;
    monitor.on_table = states.iter().filter(|s| s.motion.on_table()).count();
    monitor.checks_ms = started.elapsed().as_secs_f64() * 1e3;
}
