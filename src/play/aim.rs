//! The aiming aid: the cue ball's path to its first contact, the ghost ball there, and where
//! every ball set moving goes next, each up to its next N contacts or rest.
//!
//! Nothing here is geometry guessed on the side: the shot is run by the solver itself, on a
//! fresh copy of the table as it rests, so the ghost ball sits exactly where the real cue ball
//! will touch (throw, spin and friction included). It is recomputed only when the shot, the
//! settings or the table change, so an idle aim costs nothing.

use std::f32::consts::FRAC_PI_2;

use bevy::{math::DVec2, prelude::*};
use billiards_physics::{BallSetup, BallState, EventKind, Shot, Simulation};

use crate::{
    settings::{ShotSettings, ViewSettings},
    sim::{SimStatus, SimSystems, Solver, to_dvec2},
    table::geometry::{TableSpec, to_world},
};

/// Registers the prediction and its drawing.
pub fn plugin(app: &mut App) {
    app.init_resource::<AimPrediction>().add_systems(
        Update,
        (update_prediction, draw_prediction)
            .chain()
            .after(SimSystems::Commands)
            // A replay shows the recording's balls, not the live table's next shot.
            .run_if(in_state(crate::mode::GameMode::Play)),
    );
}

/// What the cue ball touches first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FirstContact {
    /// Another ball: the ghost ball is where the cue ball is at the contact.
    Ball {
        /// The object ball's number.
        number: u8,
    },
    /// A cushion or a pocket jaw.
    Cushion,
    /// The cue ball drops into a pocket before touching anything.
    Pocket,
    /// The cue ball stops before touching anything.
    Nothing,
}

/// The predicted shot, in table coordinates (metres).
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct AimPrediction {
    /// Cue-ball centre from the strike to the first contact (or to where it stops).
    pub path: Vec<DVec2>,
    /// The cue ball's height above the cloth at each point of [`AimPrediction::path`]
    /// (a jump's arc, its bounces; 0 on the cloth).
    pub path_heights: Vec<f64>,
    /// What the cue ball touches first, and the cue ball's centre there (the ghost ball).
    pub contact: Option<(FirstContact, DVec2)>,
    /// After the first contact, the path of every ball that moves (the cue ball first), each
    /// until it rests, drops or has made its next [`ViewSettings::aid_contacts`] contacts.
    pub after: Vec<BallPath>,
    /// Why there is no prediction (a miscue, say), if so.
    pub note: Option<String>,
}

/// One ball's predicted path after the first contact.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BallPath {
    /// The ball's number (0: the cue ball).
    pub number: u8,
    /// Its centre, sampled along each piece of its motion (every event it takes is a point).
    pub points: Vec<DVec2>,
    /// Its height above the cloth at each point (empty: on the cloth throughout).
    pub heights: Vec<f64>,
    /// The pocket its drawn path ends in, if it drops.
    pub pocket: Option<billiards_physics::Pocket>,
}

impl AimPrediction {
    /// The path after the first contact of ball `number`, if it moves.
    pub fn after_of(&self, number: u8) -> Option<&[DVec2]> {
        self.after
            .iter()
            .find(|p| p.number == number)
            .map(|p| p.points.as_slice())
    }
}

/// Points per piece of a path between two of its ball's events (the pieces are parabolas
/// and the curve of a spinning ball: a few points each draw them smoothly).
const SAMPLES_PER_PIECE: usize = 12;
/// Points of the path to the first contact.
const SAMPLES: usize = 32;
/// Events the prediction may take before it gives up (a long rattle, a crowded table).
const EVENT_BUDGET: usize = 4_000;
/// Simulated time the paths after the contact may span at most (a ball rolls for seconds).
const AFTER_HORIZON: f64 = 60.0;

/// Runs `shot` for the cue ball (`cue`, an index into `balls`) on a fresh simulation of the
/// resting balls and reports its first contact, the path to it, and every moving ball's path
/// after it, each up to its next `contacts` contacts (ball, cushion or jaw) or to where it
/// rests or drops.
pub fn predict(
    table: billiards_physics::Table,
    params: billiards_physics::Params,
    balls: &[(u8, BallState)],
    cue: usize,
    shot: Shot,
    contacts: u32,
) -> AimPrediction {
    // Only balls on the table take part; remember which solver ball each one is.
    let on_table: Vec<usize> = (0..balls.len())
        .filter(|&i| balls[i].1.motion.on_table())
        .collect();
    let Some(cue_id) = on_table.iter().position(|&i| i == cue) else {
        return AimPrediction::default();
    };
    let setups: Vec<BallSetup> = on_table
        .iter()
        .map(|&i| {
            let (number, state) = balls[i];
            BallSetup {
                number,
                position: state.position,
                velocity: state.velocity,
                spin: state.angular_velocity,
            }
        })
        .collect();
    let mut sim = match Simulation::new(table, params, &setups) {
        Ok(sim) => sim,
        Err(error) => return AimPrediction::with_note(error.to_string()),
    };
    if let Err(error) = sim.strike(cue_id, shot) {
        return AimPrediction::with_note(error.to_string());
    }
    let start = sim.time();
    let mut contact = None;
    // The cue ball's own events before the contact (a take-off, a landing, a bounce): the
    // path is sampled piece by piece between them, so each landing is a point of it.
    // A jump leaves the cloth at the strike itself.
    let mut flew = sim.ball(cue_id).motion == billiards_physics::Motion::Airborne;
    let mut breaks = Vec::new();
    for _ in 0..EVENT_BUDGET {
        let Some(event) = sim.step_event() else { break };
        let hit = match event.kind {
            EventKind::BallBall { a, b } if a == cue_id || b == cue_id => {
                let other = if a == cue_id { b } else { a };
                Some(FirstContact::Ball {
                    number: sim.numbers()[other],
                })
            }
            EventKind::Cushion { ball, .. } | EventKind::Jaw { ball, .. } if ball == cue_id => {
                Some(FirstContact::Cushion)
            }
            EventKind::Pocketed { ball, .. } if ball == cue_id => Some(FirstContact::Pocket),
            _ => None,
        };
        if let Some(kind) = hit {
            contact = Some((kind, event));
            break;
        }
        if event.kind.balls().any(|b| b == cue_id) {
            breaks.push(event.time);
            flew |= sim.ball(cue_id).motion == billiards_physics::Motion::Airborne;
        }
        if !sim.ball(cue_id).motion.on_table() || sim.ball(cue_id).motion.is_at_rest() {
            break;
        }
    }
    let end_of_path = contact.map_or(sim.time(), |(_, event)| event.time);
    // A path on the cloth in one piece, evenly sampled; a flight piece by piece, so each
    // landing is a point of it.
    let (path, path_heights) = if flew {
        pieces(
            &sim,
            cue_id,
            (start, end_of_path),
            &breaks,
            SAMPLES_PER_PIECE,
        )
    } else {
        pieces(&sim, cue_id, (start, end_of_path), &[], SAMPLES)
    };
    let mut prediction = AimPrediction {
        path,
        path_heights,
        ..default()
    };
    let ghost = to_dvec2(sim.history().state_at(cue_id, end_of_path).position);
    let Some((kind, event)) = contact else {
        prediction.contact = Some((FirstContact::Nothing, ghost));
        return prediction;
    };
    prediction.contact = Some((kind, ghost));
    if kind != FirstContact::Pocket {
        prediction.after = follow(&mut sim, event, contacts);
    }
    prediction
}

/// A ball's path being traced after the first contact.
struct Trace {
    /// From when (it was moving at the first contact, or was set moving later).
    from: f64,
    /// Times of its events since, the ends of the pieces of its path.
    breaks: Vec<f64>,
    /// Contacts made since the first.
    contacts: u32,
    /// When its path ends (its last counted contact, rest, a pocket), once it has.
    until: Option<f64>,
    /// The pocket, when the path ends in one.
    pocket: Option<billiards_physics::Pocket>,
}

/// Steps the simulation on from the first contact (`first`, just resolved) and returns the
/// path of every ball that moves, each until it rests, drops or has made `contacts` more
/// contacts. Stops once every traced path has ended and no untraced ball moves.
fn follow(sim: &mut Simulation, first: billiards_physics::Event, contacts: u32) -> Vec<BallPath> {
    let n = sim.ball_count();
    let t0 = first.time;
    let moving = |sim: &Simulation, id: usize| {
        let ball = sim.ball(id);
        ball.motion.on_table() && !ball.motion.is_at_rest()
    };
    let mut traces: Vec<Option<Trace>> = (0..n)
        .map(|id| {
            (moving(sim, id) || first.kind.balls().any(|b| b == id)).then(|| Trace {
                from: t0,
                breaks: Vec::new(),
                contacts: 0,
                until: None,
                pocket: None,
            })
        })
        .collect();
    let ended = |trace: &Option<Trace>| trace.as_ref().is_none_or(|t| t.until.is_some());
    for _ in 0..EVENT_BUDGET {
        if traces.iter().all(ended) {
            break;
        }
        match sim.next_event_time() {
            Some(t) if t <= t0 + AFTER_HORIZON => {}
            _ => break,
        }
        let Some(event) = sim.step_event() else { break };
        // Which of the event's balls were on a drawn path until now: only a collision with
        // one of those starts a new path (a ball set moving by motion the aid does not draw,
        // past a path's last contact, is not drawn either).
        let open = |id: usize| traces[id].as_ref().is_some_and(|t| t.until.is_none());
        let starts = match event.kind {
            EventKind::BallBall { a, b } => [open(b), open(a)],
            _ => [false, false],
        };
        for (k, id) in event.kind.balls().enumerate() {
            if traces[id].is_none() && !starts[k] {
                continue;
            }
            let trace = traces[id].get_or_insert_with(|| Trace {
                // A resting ball set moving by a ball being traced: its path starts here.
                from: event.time,
                breaks: Vec::new(),
                contacts: 0,
                until: None,
                pocket: None,
            });
            if trace.until.is_some() {
                continue;
            }
            trace.breaks.push(event.time);
            if event.kind.is_collision() {
                trace.contacts += 1;
            }
            let state = sim.ball(id);
            if let billiards_physics::Motion::Pocketed(pocket) = state.motion {
                trace.pocket = Some(pocket);
            }
            if trace.contacts >= contacts || !state.motion.on_table() || state.motion.is_at_rest() {
                trace.until = Some(event.time);
            }
        }
    }
    // Paths still open at the budget or horizon end where the simulation stopped.
    let now = sim.time();
    let mut paths: Vec<BallPath> = traces
        .into_iter()
        .enumerate()
        .filter_map(|(id, trace)| {
            let trace = trace?;
            let until = trace.until.unwrap_or(now);
            let (points, heights) = pieces(
                sim,
                id,
                (trace.from, until),
                &trace.breaks,
                SAMPLES_PER_PIECE,
            );
            let moved = points.windows(2).any(|w| w[0] != w[1]);
            moved.then(|| BallPath {
                number: sim.numbers()[id],
                points,
                heights,
                pocket: trace.pocket,
            })
        })
        .collect();
    // The cue ball first, then by number.
    paths.sort_by_key(|p| p.number);
    paths
}

impl AimPrediction {
    fn with_note(note: String) -> Self {
        Self {
            note: Some(note),
            ..default()
        }
    }
}

/// Ball `id`'s centre and height over `[from, to]` from the exact history, sampled piece by
/// piece between the times `breaks` (its events: each is a point of the path), `samples`
/// samples a piece, each piece starting where the last ended; a piece of no length (two
/// events at one instant) adds no point. The heights are empty when the ball never left the
/// cloth.
fn pieces(
    sim: &Simulation,
    id: usize,
    (from, to): (f64, f64),
    breaks: &[f64],
    samples: usize,
) -> (Vec<DVec2>, Vec<f64>) {
    let (mut points, mut heights) = (Vec::new(), Vec::new());
    let mut start = from;
    for end in breaks.iter().copied().filter(|&t| t < to).chain([to]) {
        if end <= start && !points.is_empty() {
            continue;
        }
        let skip = usize::from(!points.is_empty());
        for k in skip..=samples {
            let t = start + (end - start) * k as f64 / samples as f64;
            let state = sim.history().state_at(id, t.min(sim.time()));
            points.push(to_dvec2(state.position));
            heights.push(state.height);
        }
        start = end;
    }
    if heights.iter().all(|&h| h <= 0.0) {
        heights.clear();
    }
    (points, heights)
}

/// Recomputes the prediction when the shot, the settings or the table changed.
fn update_prediction(
    shot: Res<ShotSettings>,
    view: Res<ViewSettings>,
    status: Res<SimStatus>,
    solver: Option<Res<Solver>>,
    mut prediction: ResMut<AimPrediction>,
) {
    let Some(solver) = solver else { return };
    if !view.show_aim || !status.at_rest {
        if !prediction.path.is_empty() || prediction.note.is_some() {
            *prediction = AimPrediction::default();
        }
        return;
    }
    let fresh = prediction.path.is_empty() && prediction.note.is_none();
    if !(fresh || shot.is_changed() || solver.is_changed() || view.is_changed()) {
        return;
    }
    let sim = solver.simulation();
    let Some(cue) = solver.cue_ball() else {
        *prediction = AimPrediction::default();
        return;
    };
    let balls: Vec<(u8, BallState)> = sim.numbers().iter().copied().zip(sim.balls()).collect();
    *prediction = predict(
        *sim.table(),
        *sim.params(),
        &balls,
        cue,
        shot.shot(),
        view.aid_contacts,
    );
}

/// Draws the path, the ghost ball and the paths after the contact, just above the cloth.
fn draw_prediction(
    view: Res<ViewSettings>,
    spec: Res<TableSpec>,
    prediction: Res<AimPrediction>,
    mut gizmos: Gizmos,
) {
    if !view.show_aim {
        return;
    }
    let radius = spec.ball_radius;
    let at = |p: DVec2, lift: f64| to_world(p.extend(lift));
    // Just above the cloth, or at the ball's height in flight; drawn straight from the
    // stored points, nothing allocated per frame.
    fn line<'a>(points: &'a [DVec2], heights: &'a [f64]) -> impl Iterator<Item = Vec3> + 'a {
        let height = |k: usize| heights.get(k).copied().unwrap_or(0.0);
        (0..points.len()).map(move |k| to_world(points[k].extend(0.002 + height(k))))
    }
    let flat = Quat::from_rotation_x(FRAC_PI_2);
    // A path at its heights, each landing (a bounce, the last one) ringed on the cloth.
    let mut path = |points: &[DVec2], heights: &[f64], colour: Color| {
        gizmos.linestrip(line(points, heights), colour);
        for k in landings_in(heights) {
            let ring = Isometry3d::new(at(points[k], 0.002), flat);
            gizmos
                .circle(ring, radius as f32 * 0.6, colour)
                .resolution(24);
        }
    };
    let white = Color::srgba(1.0, 1.0, 1.0, 0.85);
    path(&prediction.path, &prediction.path_heights, white);
    for after in &prediction.after {
        let colour = if after.number == 0 {
            Color::srgba(0.8, 0.9, 1.0, 0.7)
        } else {
            Color::srgba(1.0, 0.85, 0.2, 0.8)
        };
        path(&after.points, &after.heights, colour);
    }
    if let Some((kind, ghost)) = prediction.contact {
        let colour = match kind {
            FirstContact::Ball { .. } => white,
            FirstContact::Cushion | FirstContact::Nothing => Color::srgb(0.9, 0.9, 0.5),
            FirstContact::Pocket => Color::srgb(1.0, 0.3, 0.2),
        };
        // The ghost ball: its outline at the equator and its footprint on the cloth.
        gizmos
            .circle(
                Isometry3d::new(at(ghost, radius), flat),
                radius as f32,
                colour,
            )
            .resolution(48);
        gizmos
            .sphere(
                Isometry3d::from_translation(at(ghost, radius)),
                radius as f32,
                colour.with_alpha(0.35),
            )
            .resolution(16);
    }
}

/// Where a sampled flight comes down: the indices at which the height, above the cloth at
/// the point before, is back on it (each bounce and the last landing).
pub fn landings_in(heights: &[f64]) -> impl Iterator<Item = usize> + '_ {
    /// Under this the ball is on the cloth (the solver's resting hop is 1e-7 m).
    const ON_CLOTH: f64 = 1e-6;
    (1..heights.len()).filter(|&k| heights[k - 1] > ON_CLOTH && heights[k] <= ON_CLOTH)
}

#[cfg(test)]
#[path = "aim_tests.rs"]
mod tests;
