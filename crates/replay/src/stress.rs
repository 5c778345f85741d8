//! `stress`: the physics crate's stress scene ([`billiards_physics::racks::stress`]) run
//! headless in frames of 1/60 s, as the game runs it: events, events a second, the solver's
//! cost per frame, and each frame the kinetic energy and the deepest overlap of two balls.
//! A count the table cannot hold is refused with the reason (exit status 1).

use billiards_physics::check::{deepest_overlap, kinetic_energy};
use billiards_physics::racks::{self, StressSpec};
use billiards_physics::{BallState, Simulation};
use serde::Serialize;
use std::process::ExitCode;
use std::time::Instant;

/// One frame of the game at 60 Hz, seconds.
pub const FRAME: f64 = 1.0 / 60.0;

/// `stress` options.
#[derive(clap::Args, Debug)]
pub struct StressArgs {
    /// Balls on the table, the cue ball included (1 to 10,000).
    #[arg(long, default_value_t = 1000)]
    pub balls: usize,
    /// The paper's cloth friction (the balls slow down and stop); without it they never do.
    #[arg(long)]
    pub friction: bool,
    /// Seed of the positions and velocities.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Table length and width as a multiple of the 8-ft table's (default: the density of 16
    /// balls on the 8-ft table).
    #[arg(long)]
    pub scale: Option<f64>,
    /// Simulated seconds to run (from 1/60 to 3600).
    #[arg(long, default_value_t = 10.0)]
    pub time: f64,
    /// Print the figures as JSON.
    #[arg(long)]
    pub json: bool,
}

/// What a stress run measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StressReport {
    /// Balls.
    pub balls: usize,
    /// With cloth friction.
    pub friction: bool,
    /// The seed.
    pub seed: u64,
    /// Table length and width, metres.
    pub table: (f64, f64),
    /// Frames of [`FRAME`] run.
    pub frames: usize,
    /// Simulated seconds.
    pub simulated: f64,
    /// Events resolved.
    pub events: usize,
    /// Wall seconds in the solver (the checks not included).
    pub solver_seconds: f64,
    /// Events per wall second of solver time.
    pub events_per_second: f64,
    /// Mean solver cost of one frame, milliseconds.
    pub mean_frame_ms: f64,
    /// The costliest frame, milliseconds.
    pub worst_frame_ms: f64,
    /// Which frame that was, counted from 1.
    pub worst_frame: usize,
    /// Kinetic energy at the start and at the end, joules.
    pub energy: (f64, f64),
    /// Largest rise of the kinetic energy from one frame to the next, relative.
    pub worst_energy_rise: f64,
    /// Deepest overlap of two balls seen at any frame, metres (0: none).
    pub worst_overlap: f64,
    /// Whether every ball rests at the end.
    pub at_rest: bool,
}

/// Runs `stress`; prints the report, or the reason for refusing.
pub fn run(a: StressArgs) -> ExitCode {
    match measure(&a) {
        Ok(report) => {
            if a.json {
                match serde_json::to_string_pretty(&report) {
                    Ok(text) => println!("{text}"),
                    Err(e) => {
                        eprintln!("error: {e}");
                        return ExitCode::FAILURE;
                    }
                }
            } else {
                print!("{}", describe(&report));
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The report as lines for a person.
pub fn describe(r: &StressReport) -> String {
    format!(
        "{} balls ({}), seed {}, table {:.2} x {:.2} m\n\
         {} frames of 1/60 s ({:.2} s simulated): {} events ({:.0} a simulated second), \
         {:.0} events/s of solver time\n\
         solver per frame: mean {:.3} ms, worst {:.3} ms (frame {}; a frame at 60 Hz is 16.7 ms)\n\
         energy {:.4} J -> {:.4} J, worst rise between frames {:.2e}; deepest overlap {:.2e} m{}\n",
        r.balls,
        if r.friction {
            "with friction"
        } else {
            "frictionless"
        },
        r.seed,
        r.table.0,
        r.table.1,
        r.frames,
        r.simulated,
        r.events,
        r.events as f64 / r.simulated.max(FRAME),
        r.events_per_second,
        r.mean_frame_ms,
        r.worst_frame_ms,
        r.worst_frame,
        r.energy.0,
        r.energy.1,
        r.worst_energy_rise,
        r.worst_overlap,
        if r.at_rest {
            "; every ball at rest"
        } else {
            ""
        },
    )
}

/// Builds the scene and runs it frame by frame (history kept, as in the game).
pub fn measure(a: &StressArgs) -> Result<StressReport, String> {
    if !(a.time.is_finite() && (FRAME..=3600.0).contains(&a.time)) {
        return Err(format!(
            "--time {}: simulated seconds from 1/60 to 3600",
            a.time
        ));
    }
    let scene = racks::stress(&StressSpec {
        balls: a.balls,
        friction: a.friction,
        seed: a.seed,
        scale: a.scale,
    })
    .map_err(|e| e.to_string())?;
    let mut sim =
        Simulation::new(scene.table, scene.params, &scene.balls).map_err(|e| e.to_string())?;
    let ball = scene.params.ball;
    let energy = |sim: &Simulation, states: &mut Vec<BallState>| {
        states.clear();
        states.extend(sim.balls());
        kinetic_energy(states, ball.mass, ball.radius)
    };
    let mut states = Vec::with_capacity(a.balls);
    let start_energy = energy(&sim, &mut states);
    let (mut last_energy, mut worst_rise, mut worst_overlap) = (start_energy, 0f64, 0f64);
    let frames = (a.time / FRAME).round().max(1.0) as usize;
    let (mut solver, mut worst_frame, mut worst_at, mut events) = (0.0, 0f64, 0, 0);
    for frame in 1..=frames {
        let started = Instant::now();
        let advance = sim.advance(FRAME).map_err(|e| e.to_string())?;
        let cost = started.elapsed().as_secs_f64();
        solver += cost;
        if cost > worst_frame {
            (worst_frame, worst_at) = (cost, frame);
        }
        events += advance.events.len();
        let e = energy(&sim, &mut states);
        worst_rise = worst_rise.max((e - last_energy) / last_energy.max(f64::MIN_POSITIVE));
        last_energy = e;
        if let Some((_, _, depth)) = deepest_overlap(&states, ball.radius) {
            worst_overlap = worst_overlap.max(depth);
        }
    }
    Ok(StressReport {
        balls: a.balls,
        friction: a.friction,
        seed: a.seed,
        table: (scene.table.length, scene.table.width),
        frames,
        simulated: sim.time(),
        events,
        solver_seconds: solver,
        events_per_second: events as f64 / solver.max(1e-9),
        mean_frame_ms: solver / frames as f64 * 1e3,
        worst_frame_ms: worst_frame * 1e3,
        worst_frame: worst_at,
        energy: (start_energy, last_energy),
        worst_energy_rise: worst_rise,
        worst_overlap,
        at_rest: sim.is_at_rest(),
    })
}
