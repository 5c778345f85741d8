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
        if !sim.ball(cue_id).motion.on_table() || sim.ball(cue_id).motion.is_at_rest() {
            break;
        }
    }
    let end_of_path = contact.map_or(sim.time(), |(_, event)| event.time);
    let mut prediction = AimPrediction {
        path: sample(&sim, cue_id, start, end_of_path, SAMPLES),
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
            let mut points = Vec::new();
            let mut from = trace.from;
            for to in trace.breaks.iter().copied().chain([until]) {
                if to > from || points.is_empty() {
                    let piece = sample(sim, id, from, to, SAMPLES_PER_PIECE);
                    // Each piece starts where the last one ended.
                    let skip = usize::from(!points.is_empty());
                    points.extend(piece.into_iter().skip(skip));
                }
                from = to;
                if to >= until {
                    break;
                }
            }
            let moved = points.windows(2).any(|w| w[0] != w[1]);
            moved.then(|| BallPath {
                number: sim.numbers()[id],
                points,
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

/// Ball `id`'s centre at `samples + 1` evenly spaced times over `[from, to]`, from the exact
/// history.
fn sample(sim: &Simulation, id: usize, from: f64, to: f64, samples: usize) -> Vec<DVec2> {
    (0..=samples)
        .map(|k| from + (to - from) * k as f64 / samples as f64)
        .map(|t| to_dvec2(sim.history().state_at(id, t.min(sim.time())).position))
        .collect()
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
    // Just above the cloth; drawn straight from the stored points, nothing allocated per frame.
    fn line(points: &[DVec2]) -> impl Iterator<Item = Vec3> + '_ {
        points.iter().map(|&p| to_world(p.extend(0.002)))
    }
    let white = Color::srgba(1.0, 1.0, 1.0, 0.85);
    gizmos.linestrip(line(&prediction.path), white);
    if let Some((kind, ghost)) = prediction.contact {
        let colour = match kind {
            FirstContact::Ball { .. } => white,
            FirstContact::Cushion | FirstContact::Nothing => Color::srgb(0.9, 0.9, 0.5),
            FirstContact::Pocket => Color::srgb(1.0, 0.3, 0.2),
        };
        // The ghost ball: its outline at the equator and its footprint on the cloth.
        let flat = Quat::from_rotation_x(FRAC_PI_2);
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
    for path in &prediction.after {
        let colour = if path.number == 0 {
            Color::srgba(0.8, 0.9, 1.0, 0.7)
        } else {
            Color::srgba(1.0, 0.85, 0.2, 0.8)
        };
        gizmos.linestrip(line(&path.points), colour);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::{Params, Table, Vec2};

    fn resting(number: u8, x: f64, y: f64) -> (u8, BallState) {
        let setup = BallSetup::at(number, Vec2::new(x, y));
        let sim = Simulation::new(Table::wpa_8ft(), Params::default(), &[setup]).unwrap();
        (number, sim.ball(0))
    }

    #[test]
    fn ghost_ball_touches_the_object_ball_on_a_straight_shot() {
        let balls = [resting(0, -0.5, 0.0), resting(1, 0.3, 0.0)];
        let params = Params::default();
        let p = predict(Table::wpa_8ft(), params, &balls, 0, Shot::new(0.0, 2.0), 1);
        let (kind, ghost) = p.contact.unwrap();
        assert_eq!(kind, FirstContact::Ball { number: 1 });
        // Centre to centre 2R at contact, on the line of the shot.
        let two_r = 2.0 * params.ball.radius;
        assert!((ghost.x - (0.3 - two_r)).abs() < 1e-9, "{ghost:?}");
        assert!(ghost.y.abs() < 1e-12);
        // Head on with equal masses: the object ball goes straight on.
        let last = *p.after_of(1).unwrap().last().unwrap();
        assert!(last.x > 0.3 && last.y.abs() < 1e-9);
    }

    #[test]
    fn a_cut_sends_the_object_ball_along_the_line_of_centres() {
        let balls = [resting(0, -0.5, 0.0), resting(1, 0.3, 0.03)];
        let params = Params::default();
        let p = predict(Table::wpa_8ft(), params, &balls, 0, Shot::new(0.0, 2.0), 1);
        let (_, ghost) = p.contact.unwrap();
        let centres = (DVec2::new(0.3, 0.03) - ghost).normalize();
        let moved =
            (p.after_of(1).unwrap()[SAMPLES_PER_PIECE / 2] - DVec2::new(0.3, 0.03)).normalize();
        // The paper's model has no ball friction: no throw, so exactly the line of centres.
        assert!(centres.angle_to(moved).abs() < 1e-9);
    }

    #[test]
    fn a_miscue_is_reported_not_drawn() {
        let balls = [resting(0, -0.5, 0.0)];
        let params = Params {
            model: billiards_physics::Model::Spin(Default::default()),
            ..Params::default()
        };
        let shot = Shot {
            tip: billiards_physics::TipOffset {
                side: 0.6,
                height: 0.0,
            },
            ..Shot::new(0.0, 2.0)
        };
        let p = predict(Table::wpa_8ft(), params, &balls, 0, shot, 1);
        assert!(p.note.unwrap().contains("miscue"));
        assert!(p.path.is_empty());
    }

    #[test]
    fn a_lone_cue_ball_hits_a_cushion() {
        let balls = [resting(0, 0.0, 0.0)];
        let p = predict(
            Table::wpa_8ft(),
            Params::default(),
            &balls,
            0,
            Shot::new(0.0, 3.0),
            1,
        );
        let (kind, ghost) = p.contact.unwrap();
        assert_eq!(kind, FirstContact::Cushion);
        let radius = Params::default().ball.radius;
        assert!((ghost.x - (Table::wpa_8ft().length / 2.0 - radius)).abs() < 1e-9);
    }

    /// A full-draw stop shot: the object ball goes on and the cue ball comes back by more
    /// than a metre; the aid shows all of that, not a centimetre of it.
    #[test]
    fn a_draw_shot_shows_the_cue_ball_coming_back() {
        let balls = [resting(0, -0.6, 0.0), resting(1, 0.0, 0.0)];
        let params = Params {
            model: billiards_physics::Model::Spin(Default::default()),
            ..Params::default()
        };
        let shot = Shot {
            tip: billiards_physics::TipOffset {
                side: 0.0,
                height: -0.45,
            },
            ..Shot::new(0.0, 6.0)
        };
        let p = predict(Table::wpa_8ft(), params, &balls, 0, shot, 2);
        assert_eq!(p.contact.unwrap().0, FirstContact::Ball { number: 1 });
        let cue = p.after_of(0).expect("the cue ball moves after the contact");
        let ghost = p.contact.unwrap().1;
        let back = cue.iter().map(|q| ghost.x - q.x).fold(0.0, f64::max);
        assert!(back > 1.0, "the cue ball comes back {back} m");
        // The same shot run by the solver to rest: the cue ball's path reaches where it
        // really goes (its next two contacts or rest), so the drawn end is a real position.
        assert!(p.after_of(1).unwrap().len() > SAMPLES_PER_PIECE);
    }

    /// An elevated cue with right english: the drawn path curves right of the cue line
    /// (swerve, the cue ball alone on the table), where a level cue's stays on it.
    #[test]
    fn an_elevated_cue_with_english_draws_a_curved_path() {
        let balls = [resting(0, -0.8, 0.0)];
        let params = Params {
            model: billiards_physics::Model::Spin(Default::default()),
            ..Params::default()
        };
        let shot = |elevation: f64| Shot {
            tip: billiards_physics::TipOffset {
                side: 0.3,
                height: 0.0,
            },
            elevation: elevation.to_radians(),
            ..Shot::new(0.0, 2.0)
        };
        let off_line = |p: &AimPrediction| p.path.iter().map(|q| q.y).fold(0.0, f64::min);
        let level = predict(Table::wpa_8ft(), params, &balls, 0, shot(0.0), 2);
        let raised = predict(Table::wpa_8ft(), params, &balls, 0, shot(20.0), 2);
        assert!(off_line(&level).abs() < 1e-9, "{}", off_line(&level));
        // Right english (+side) curves toward -y (right of a cue pointing +x).
        assert!(off_line(&raised) < -0.01, "{}", off_line(&raised));
    }

    /// Each ball's path ends at its N-th contact after the first: more contacts, longer paths.
    #[test]
    fn paths_end_after_the_chosen_number_of_contacts() {
        let balls = [resting(0, -0.5, 0.05), resting(1, 0.3, 0.0)];
        let params = Params::default();
        let length = |p: &AimPrediction, n| {
            p.after_of(n)
                .unwrap()
                .windows(2)
                .map(|w| w[0].distance(w[1]))
                .sum::<f64>()
        };
        let shot = Shot::new(0.0, 4.0);
        let one = predict(Table::wpa_8ft(), params, &balls, 0, shot, 1);
        let three = predict(Table::wpa_8ft(), params, &balls, 0, shot, 3);
        // The object ball takes three cushions; the cue ball drops in a corner pocket (its
        // path ends there however many contacts are asked for).
        let (a, b) = (length(&one, 1), length(&three, 1));
        assert!(b > a + 1.0, "{a} m after one contact, {b} m after three");
        assert_eq!(length(&one, 0), length(&three, 0));
    }

    /// A ball hit after a drawn path has ended (here: the object ball's path ends at its first
    /// cushion, then it rolls on into the 2) is not drawn: the aid would show a ball set moving
    /// by nothing it shows (issue 28, item 10).
    #[test]
    fn a_ball_hit_past_the_end_of_a_drawn_path_is_not_drawn() {
        let params = Params::default();
        let shot = Shot::new(0.0, 3.0);
        let two = [resting(0, -0.5, 0.05), resting(1, 0.3, 0.0)];
        let free = predict(Table::wpa_8ft(), params, &two, 0, shot, 3);
        let cushion = *predict(Table::wpa_8ft(), params, &two, 0, shot, 1)
            .after_of(1)
            .unwrap()
            .last()
            .unwrap();
        // A point of the object ball's free path 0.3 m past its first cushion.
        let path = free.after_of(1).unwrap();
        let at = path.iter().position(|p| *p == cushion).unwrap();
        let mut run = 0.0;
        let beyond = path[at..]
            .windows(2)
            .find(|w| {
                run += w[0].distance(w[1]);
                run > 0.3
            })
            .unwrap()[1];
        let three = [two[0], two[1], resting(2, beyond.x, beyond.y)];
        let open = predict(Table::wpa_8ft(), params, &three, 0, shot, 2);
        assert!(open.after_of(2).is_some(), "the 2 is hit on a drawn path");
        let ended = predict(Table::wpa_8ft(), params, &three, 0, shot, 1);
        assert!(ended.after_of(1).is_some());
        assert!(
            ended.after_of(2).is_none(),
            "the 2 is hit after the 1's drawn path ended"
        );
    }
}
