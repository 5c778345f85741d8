//! The benchmark: every solver on every scene, timed and measured against the exact
//! solution.

use crate::analytic::Solution;
use crate::exact::{self, Slicing};
use crate::fixed_step::{self, Collisions, FixedStep};
use crate::measure::{self, ContactMatch, Errors};
use crate::rapier::RapierWorld;
use crate::scene::{self, Reference, Scene};
use crate::trace::{Diagnostics, Sample, Trace, kinetic_energy};
use billiards_physics::{Prediction, Simulation};
use std::error::Error;

/// The solvers compared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Solver {
    /// The exact event-driven solver (`Prediction::Exact`), the reference.
    Exact,
    /// The paper's own linear prediction (`Prediction::PaperLinear`).
    PaperLinear,
    /// Semi-implicit Euler with discrete overlap detection and push-apart.
    EulerDiscrete,
    /// Semi-implicit Euler with swept (continuous) collision detection.
    EulerSwept,
    /// Rapier with CCD, on frictionless scenes.
    Rapier,
}

impl Solver {
    /// Every solver, in plotting order.
    pub const ALL: [Solver; 5] = [
        Solver::Exact,
        Solver::PaperLinear,
        Solver::EulerDiscrete,
        Solver::EulerSwept,
        Solver::Rapier,
    ];

    /// Name in the CSV and the plot's legend.
    pub fn name(self) -> &'static str {
        match self {
            Solver::Exact => "exact",
            Solver::PaperLinear => "paper-linear",
            Solver::EulerDiscrete => "euler-discrete",
            Solver::EulerSwept => "euler-swept",
            Solver::Rapier => "rapier",
        }
    }
}

/// One solver configuration on one scene.
#[derive(Clone, Debug)]
pub struct Row {
    /// Scene name.
    pub scene: &'static str,
    /// Solver.
    pub solver: Solver,
    /// The solver's parameter in words (time step, or how the exact solver was called).
    pub parameter: String,
    /// Fixed time step, seconds, if the solver has one.
    pub dt: Option<f64>,
    /// Median run time over the timed span, seconds.
    pub runtime: f64,
    /// Timed runs the median is taken over.
    pub reps: usize,
    /// Simulated seconds the timed runs cover (the error horizon).
    pub horizon: f64,
    /// Errors against the reference.
    pub errors: Errors,
    /// Contacts matched against the reference's up to the horizon.
    pub contacts: ContactMatch,
    /// Simulated seconds over which failures were counted (the scene's end, unless a
    /// diagnostic run that long would take minutes).
    pub checked: f64,
    /// Failures over the checked span.
    pub diagnostics: Diagnostics,
    /// What the error is measured against, when that is not the exact solver.
    pub note: String,
}

/// What was learnt about a scene before the solvers ran.
#[derive(Clone, Debug)]
pub struct SceneSummary {
    /// Scene name.
    pub name: &'static str,
    /// One line for the README.
    pub description: &'static str,
    /// Balls.
    pub balls: usize,
    /// End of the run, seconds.
    pub end: f64,
    /// Horizon of the error measurement (and of the timed runs), seconds.
    pub horizon: f64,
    /// Collisions (ball–ball and cushion) of the exact solution up to the horizon and to the
    /// end.
    pub collisions: (usize, usize),
}

/// Everything the benchmark measured.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// One row per solver configuration and scene.
    pub rows: Vec<Row>,
    /// One summary per scene.
    pub scenes: Vec<SceneSummary>,
}

impl Report {
    /// The largest error the exact solver showed anywhere, metres: its position error up to
    /// a horizon, or the distance from touching at which it resolved a collision.
    pub fn exact_max_error(&self) -> f64 {
        self.rows
            .iter()
            .filter(|r| r.solver == Solver::Exact)
            .map(|r| r.errors.position.max(r.diagnostics.max_contact_gap))
            .fold(0.0, f64::max)
    }
}

/// How much to run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// The CI mode: short scenes, a few configurations, little repetition.
    pub quick: bool,
    /// Seconds of repeated runs to aim for per timing.
    pub budget: f64,
    /// Fewest timed runs per configuration.
    pub min_reps: usize,
}

impl Settings {
    /// The full benchmark.
    pub fn full() -> Self {
        Self {
            quick: false,
            budget: 0.3,
            min_reps: 3,
        }
    }

    /// The quick CI mode.
    pub fn quick() -> Self {
        Self {
            quick: true,
            budget: 0.02,
            min_reps: 1,
        }
    }
}

/// The exact solver's error limit the quick mode enforces, metres.
pub const EXACT_ERROR_LIMIT: f64 = 1e-9;

/// A chaotic scene's horizon is the last sample time at which the exact solution's rounding
/// uncertainty (estimated from runs whose start differs by one rounding error) is at most
/// this, metres: up to there the exact solution is meaningful to well under
/// [`EXACT_ERROR_LIMIT`].
pub const HORIZON_ERROR: f64 = 1e-10;

/// Frame length of the game's per-frame `advance` calls.
pub const FRAME: f64 = 1.0 / 60.0;

/// The fixed time steps of the full sweep, seconds, with their labels.
pub fn time_steps(quick: bool) -> Vec<(f64, &'static str)> {
    if quick {
        return vec![(1.0 / 60.0, "1/60"), (1e-3, "1e-3")];
    }
    vec![
        (1.0 / 30.0, "1/30"),
        (1.0 / 60.0, "1/60"),
        (1.0 / 120.0, "1/120"),
        (1.0 / 240.0, "1/240"),
        (1e-3, "1e-3"),
        (1e-4, "1e-4"),
        (1e-5, "1e-5"),
        (1e-6, "1e-6"),
    ]
}

/// The scenes of a run.
pub fn scenes(quick: bool) -> Vec<Scene> {
    vec![
        scene::stop(),
        scene::cut(),
        scene::billiard(if quick { 5.0 } else { 20.0 }),
        scene::break_shot(),
        scene::elastic_break(if quick { 2.0 } else { 10.0 }),
    ]
}

/// A scene with its reference solution and horizon.
struct Prepared {
    scene: Scene,
    end: f64,
    horizon: f64,
    horizon_index: usize,
    reference: Trace,
    /// Rounding uncertainty of the exact solution at each sample time, metres (zero for the
    /// closed-form scenes, whose error is measured directly).
    rounding: Vec<f64>,
    /// The same for the kinetic energy, relative to the starting energy.
    rounding_energy: Vec<f64>,
    /// Last sample index of the energy comparison: the horizon, or the whole run when energy
    /// is conserved (then the reference is the constant starting energy, chaos or not).
    energy_index: usize,
    summary: SceneSummary,
}

fn prepare(scene: Scene) -> Result<Prepared, Box<dyn Error>> {
    let si = scene.sample_interval;
    let end = match scene.end {
        Some(end) => end,
        None => {
            let mut sim = Simulation::new(scene.table, scene.params, &scene.balls)?;
            sim.run_to_rest()?;
            // Rest, plus a little, rounded up to a sample time.
            ((sim.time() + 0.05) / si).ceil() * si
        }
    };
    let (_, reference) = exact::run(&scene, Prediction::Exact, Slicing::Single, end, false)?;
    let last = reference.samples.len() - 1;
    // Rounding uncertainty per sample: the largest divergence from the reference of runs
    // with one ball moved by one rounding error, each ball in turn.
    let mut rounding = vec![0.0; last + 1];
    let mut rounding_energy = vec![0.0; last + 1];
    if scene.reference == Reference::Chaotic {
        let m = scene.mass();
        let e0 = kinetic_energy(&reference.samples[0], m);
        for id in 0..scene.balls.len() {
            let nudged = scene.nudged(id);
            let (_, t) = exact::run(&nudged, Prediction::Exact, Slicing::Single, end, false)?;
            for (k, (a, b)) in reference.samples.iter().zip(&t.samples).enumerate() {
                let e = measure::errors(std::slice::from_ref(a), std::slice::from_ref(b), 0, 0, m);
                rounding[k] = f64::max(rounding[k], e.position);
                let mut de = (kinetic_energy(a, m) - kinetic_energy(b, m)).abs() / e0;
                if scene.frictionless {
                    // Energy is conserved: any change from the start is an error too.
                    de = de.max((kinetic_energy(a, m) - e0).abs() / e0);
                }
                rounding_energy[k] = f64::max(rounding_energy[k], de);
            }
        }
    }
    let horizon_index = rounding
        .iter()
        .position(|&e| e > HORIZON_ERROR)
        .map_or(last, |k| k.saturating_sub(1));
    let horizon = horizon_index as f64 * si;
    let collisions = |until: f64| {
        reference
            .contacts
            .iter()
            .filter(|c| c.time <= until && !matches!(c.key, crate::trace::ContactKey::Pocket(_)))
            .count()
    };
    let summary = SceneSummary {
        name: scene.name,
        description: scene.description,
        balls: scene.balls.len(),
        end,
        horizon,
        collisions: (collisions(horizon), collisions(end)),
    };
    let energy_index = if scene.frictionless {
        last
    } else {
        horizon_index
    };
    Ok(Prepared {
        scene,
        energy_index,
        end,
        horizon,
        horizon_index,
        reference,
        rounding,
        rounding_energy,
        summary,
    })
}

/// Runs the benchmark, calling `progress` with one line per configuration.
pub fn run(settings: &Settings, mut progress: impl FnMut(&str)) -> Result<Report, Box<dyn Error>> {
    let mut report = Report::default();
    for scene in scenes(settings.quick) {
        let p = prepare(scene)?;
        progress(&format!(
            "scene {}: {} balls, end {:.1} s, horizon {:.1} s, {} collisions to the horizon",
            p.summary.name, p.summary.balls, p.end, p.horizon, p.summary.collisions.0
        ));
        let mut rows = exact_rows(&p, settings)?;
        rows.push(paper_linear_row(&p, settings)?);
        for row in &rows {
            progress(&describe(row));
        }
        for (dt, label) in time_steps(settings.quick) {
            if settings.quick && dt < 1e-3 && p.scene.reference == Reference::Chaotic {
                continue;
            }
            for collisions in [Collisions::Discrete, Collisions::Swept] {
                if settings.quick && collisions == Collisions::Swept && dt < FRAME {
                    continue;
                }
                let solver = match collisions {
                    Collisions::Discrete => Solver::EulerDiscrete,
                    Collisions::Swept => Solver::EulerSwept,
                };
                let row = stepper_row(&p, settings, solver, dt, label, || {
                    FixedStep::new(&p.scene, dt, collisions)
                });
                progress(&describe(&row));
                rows.push(row);
            }
            if p.scene.frictionless && dt >= rapier_min_dt(settings.quick) {
                let row = stepper_row(&p, settings, Solver::Rapier, dt, label, || {
                    RapierWorld::new(&p.scene, dt)
                });
                progress(&describe(&row));
                rows.push(row);
            }
        }
        report.rows.extend(rows);
        report.scenes.push(p.summary);
    }
    Ok(report)
}

/// Smallest Rapier time step run: below it a run takes minutes.
fn rapier_min_dt(quick: bool) -> f64 {
    if quick { FRAME } else { 1e-4 }
}

/// One line about a row, for the progress log.
pub fn describe(r: &Row) -> String {
    format!(
        "  {:<15} {:<12} {:>10.3e} s  pos err {:>9.2e} m  energy err {:>9.2e}  missed {:>3}/{:<3} tunnelled {:>3} overlaps {:>4} gap contacts {:>3} off {:>2} pockets {:>2}",
        r.solver.name(),
        r.parameter,
        r.runtime,
        r.errors.position,
        r.errors.energy,
        r.contacts.missed,
        r.contacts.reference,
        r.diagnostics.tunnelled,
        r.diagnostics.overlaps,
        r.diagnostics.gap_contacts,
        r.diagnostics.off_table,
        r.errors.pocket_differences,
    )
}

/// Time span of the timed runs: the whole run for the closed-form scenes, the horizon for
/// the chaotic ones (beyond it no solver's positions mean anything).
fn timed_end(p: &Prepared) -> f64 {
    match p.scene.reference {
        Reference::Analytic => p.end,
        Reference::Chaotic => p.horizon,
    }
}

/// The exact solver's rows: one `advance_to` call, and per-frame `advance` calls as in the
/// game. Its error is measured against the closed form where one exists; in chaotic scenes it
/// is estimated from a run started one unit in the last place away (and, for elastic
/// frictionless scenes, from running to the horizon and back).
fn exact_rows(p: &Prepared, settings: &Settings) -> Result<Vec<Row>, Box<dyn Error>> {
    let s = &p.scene;
    let end = timed_end(p);
    let (_, diag) = exact::run(s, Prediction::Exact, Slicing::Single, p.end, true)?;
    let (errors, note) = match s.reference {
        Reference::Analytic => {
            let sol = Solution::of(s).ok_or("scene has no closed form")?;
            let analytic: Vec<Vec<Sample>> = (0..p.reference.samples.len())
                .map(|k| sol.at(k as f64 * s.sample_interval))
                .collect();
            let e = measure::errors(
                &analytic,
                &p.reference.samples,
                p.horizon_index,
                p.energy_index,
                s.mass(),
            );
            (e, "error against the closed form".to_string())
        }
        Reference::Chaotic => {
            // No closed form: the error is at least what one rounding error at the start
            // does, and (elastic, frictionless) half of what is left after running to the
            // horizon and back.
            let mut e = Errors {
                position: p.rounding[..=p.horizon_index]
                    .iter()
                    .copied()
                    .fold(0.0, f64::max),
                energy: p.rounding_energy[..=p.energy_index]
                    .iter()
                    .copied()
                    .fold(0.0, f64::max),
                final_position: p.rounding.last().copied().unwrap_or(0.0),
                ..Errors::default()
            };
            let mut note = format!(
                "error estimated from starts one rounding error away: {:.1e} m",
                e.position
            );
            if s.frictionless {
                let back = reversal_error(s, p.horizon)?;
                note = format!("{note}; half of there-and-back-again: {:.1e} m", 0.5 * back);
                e.position = e.position.max(0.5 * back);
            }
            (e, note)
        }
    };
    let contacts =
        measure::match_contacts(&p.reference.contacts, &diag.contacts, 1e-9, 0.0, p.horizon);
    let (runtime, reps, _) = measure::median_time(settings.budget, settings.min_reps, || {
        exact::run(s, Prediction::Exact, Slicing::Single, end, false).map(|r| r.1.samples.len())
    });
    let single = Row {
        scene: s.name,
        solver: Solver::Exact,
        parameter: "one call".into(),
        dt: None,
        runtime,
        reps,
        horizon: end,
        checked: p.end,
        errors,
        contacts,
        diagnostics: diag.diagnostics,
        note,
    };
    // Per-frame slicing gives the same trajectory bit for bit; its measured difference from
    // the one-call run is added to the error, so a slicing dependence would show.
    let (_, framed) = exact::run(s, Prediction::Exact, Slicing::Frames(FRAME), p.end, false)?;
    let slicing = measure::errors(
        &p.reference.samples,
        &framed.samples,
        p.horizon_index,
        p.energy_index,
        s.mass(),
    );
    let (runtime, reps, _) = measure::median_time(settings.budget, settings.min_reps, || {
        exact::run(s, Prediction::Exact, Slicing::Frames(FRAME), end, false)
            .map(|r| r.1.samples.len())
    });
    let mut framed_errors = errors;
    framed_errors.position += slicing.position;
    framed_errors.final_position += slicing.final_position;
    let framed = Row {
        parameter: "frames 1/60".into(),
        runtime,
        reps,
        errors: framed_errors,
        note: format!(
            "as one call, plus its difference from one call: {:.1e} m",
            slicing.position.max(slicing.final_position)
        ),
        ..single.clone()
    };
    Ok(vec![single, framed])
}

/// Runs an elastic, frictionless scene to `horizon`, reverses every velocity, runs it for
/// `horizon` again, and returns the largest distance of a ball from where it started. An
/// exact solver returns every ball home; the distance is twice its error, roughly.
fn reversal_error(s: &Scene, horizon: f64) -> Result<f64, Box<dyn Error>> {
    let mut sim = Simulation::new(s.table, s.params, &s.balls)?;
    sim.advance_to(horizon)?;
    let turned: Vec<_> = sim
        .balls()
        .zip(&s.balls)
        .map(|(state, setup)| {
            billiards_physics::BallSetup::moving(setup.number, state.position, -state.velocity)
        })
        .collect();
    let mut back = Simulation::new(s.table, s.params, &turned)?;
    back.advance_to(horizon)?;
    Ok(back
        .balls()
        .zip(&s.balls)
        .map(|(state, setup)| (state.position - setup.position).length())
        .fold(0.0, f64::max))
}

fn paper_linear_row(p: &Prepared, settings: &Settings) -> Result<Row, Box<dyn Error>> {
    let s = &p.scene;
    let end = timed_end(p);
    let (_, trace) = exact::run(s, Prediction::PaperLinear, Slicing::Single, p.end, true)?;
    let (runtime, reps, _) = measure::median_time(settings.budget, settings.min_reps, || {
        exact::run(s, Prediction::PaperLinear, Slicing::Single, end, false)
            .map(|r| r.1.samples.len())
    });
    Ok(Row {
        scene: s.name,
        solver: Solver::PaperLinear,
        parameter: "one call".into(),
        dt: None,
        runtime,
        reps,
        horizon: end,
        checked: p.end,
        errors: measure::errors(
            &p.reference.samples,
            &trace.samples,
            p.horizon_index,
            p.energy_index,
            s.mass(),
        ),
        contacts: measure::match_contacts(
            &p.reference.contacts,
            &trace.contacts,
            CONTACT_WINDOW,
            0.0,
            p.horizon,
        ),
        diagnostics: trace.diagnostics,
        note: String::new(),
    })
}

/// Slack of the contact matching beyond the solver's own time step, seconds.
const CONTACT_WINDOW: f64 = 0.01;

/// Most steps a diagnostic run of a fixed-step solver may take (it checks every pair every
/// step); longer runs are diagnosed only over their first part.
fn diagnostic_steps(solver: Solver) -> f64 {
    match solver {
        // Rapier's steps cost about a hundred times more than the integrators' here.
        Solver::Rapier => 5e4,
        _ => 5e5,
    }
}

fn stepper_row<S: fixed_step::Stepper>(
    p: &Prepared,
    settings: &Settings,
    solver: Solver,
    dt: f64,
    label: &str,
    make: impl Fn() -> S,
) -> Row {
    let s = &p.scene;
    let end = timed_end(p);
    let si = s.sample_interval;
    let checked = p
        .end
        .min((diagnostic_steps(solver) * dt / si).floor() * si)
        .max(si);
    let diagnosed = fixed_step::run(&mut make(), s, checked, true);
    let (runtime, reps, timed) = measure::median_time(settings.budget, settings.min_reps, || {
        fixed_step::run(&mut make(), s, end, false)
    });
    // Errors and contacts from whichever run covers more of the scene.
    let trace = if diagnosed.samples.len() >= timed.samples.len() {
        &diagnosed
    } else {
        &timed
    };
    let compared = (trace.samples.len() - 1) as f64 * si;
    Row {
        scene: s.name,
        solver,
        parameter: format!("dt {label}"),
        dt: Some(dt),
        runtime,
        reps,
        horizon: end,
        checked,
        errors: measure::errors(
            &p.reference.samples,
            &trace.samples,
            p.horizon_index,
            p.energy_index,
            s.mass(),
        ),
        contacts: measure::match_contacts(
            &p.reference.contacts,
            &trace.contacts,
            2.0 * dt + CONTACT_WINDOW,
            // Only Rapier reports one contact over several steps (soft contacts); the
            // integrators here report each resolved contact once.
            if solver == Solver::Rapier {
                1.5 * dt
            } else {
                0.0
            },
            p.horizon,
        ),
        diagnostics: diagnosed.diagnostics,
        note: if compared < p.end - 1e-9 {
            format!("outcomes compared at {compared:.1} s, failures counted to {checked:.1} s")
        } else {
            String::new()
        },
    }
}
