//! The aiming aid: the cue ball's path to its first contact, the ghost ball there, and where
//! both balls go next.
//!
//! Nothing here is geometry guessed on the side: the shot is run by the solver itself, on a
//! fresh copy of the table as it rests, so the ghost ball sits exactly where the real cue ball
//! will touch (throw, spin and friction included). It is recomputed only when the shot, the
//! settings or the table change, so an idle aim costs nothing.

use std::f32::consts::FRAC_PI_2;

use bevy::{math::DVec2, prelude::*};
use billiards_physics::{BallSetup, BallState, EventKind, Shot, Simulation};

use crate::{
    geometry::{TableSpec, to_world},
    settings::{ShotSettings, ViewSettings},
    sim::{SimStatus, SimSystems, Solver, to_dvec2},
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
    /// The cue ball's path after the first contact, up to its next collision or a horizon.
    pub cue_after: Vec<DVec2>,
    /// The object ball's path after the contact, over the same time.
    pub object_after: Vec<DVec2>,
    /// Why there is no prediction (a miscue, say), if so.
    pub note: Option<String>,
}

/// How long after the first contact the paths are drawn, at most (seconds of simulated time).
const AFTER_HORIZON: f64 = 1.5;
/// Points per drawn path.
const SAMPLES: usize = 32;
/// Events the prediction may take before it gives up (a long rattle, a crowded table).
const EVENT_BUDGET: usize = 2_000;

/// Runs `shot` for the cue ball (`cue`, an index into `balls`) on a fresh simulation of the
/// resting balls and reports its first contact and the paths around it.
pub fn predict(
    table: billiards_physics::Table,
    params: billiards_physics::Params,
    balls: &[(u8, BallState)],
    cue: usize,
    shot: Shot,
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
                Some((
                    FirstContact::Ball {
                        number: sim.numbers()[other],
                    },
                    Some(other),
                ))
            }
            EventKind::Cushion { ball, .. } | EventKind::Jaw { ball, .. } if ball == cue_id => {
                Some((FirstContact::Cushion, None))
            }
            EventKind::Pocketed { ball, .. } if ball == cue_id => {
                Some((FirstContact::Pocket, None))
            }
            _ => None,
        };
        if let Some((kind, other)) = hit {
            contact = Some((kind, event.time, other));
            break;
        }
        if !sim.ball(cue_id).motion.on_table() || sim.ball(cue_id).motion.is_at_rest() {
            break;
        }
    }
    let end_of_path = contact.map_or(sim.time(), |(_, time, _)| time);
    let mut prediction = AimPrediction {
        path: sample(&sim, cue_id, start, end_of_path),
        ..default()
    };
    let ghost = to_dvec2(sim.history().state_at(cue_id, end_of_path).position);
    let Some((kind, time, other)) = contact else {
        prediction.contact = Some((FirstContact::Nothing, ghost));
        return prediction;
    };
    prediction.contact = Some((kind, ghost));
    let Some(other) = other else {
        return prediction;
    };
    // Follow both balls until either collides again (or the horizon), then sample exactly.
    let horizon = time + AFTER_HORIZON;
    let mut until = horizon;
    for _ in 0..EVENT_BUDGET {
        match sim.next_event_time() {
            Some(t) if t <= horizon => {}
            _ => break,
        }
        let Some(event) = sim.step_event() else { break };
        let involved = event.kind.balls().any(|b| b == cue_id || b == other);
        if involved && event.kind.is_collision() {
            until = event.time;
            break;
        }
    }
    if sim.time() < until {
        // Nothing more to resolve before `until`: the segments already run there.
        let _ = sim.advance_to(until);
    }
    prediction.cue_after = sample(&sim, cue_id, time, until);
    prediction.object_after = sample(&sim, other, time, until);
    prediction
}

impl AimPrediction {
    fn with_note(note: String) -> Self {
        Self {
            note: Some(note),
            ..default()
        }
    }
}

/// Ball `id`'s centre at evenly spaced times over `[from, to]`, from the exact history.
fn sample(sim: &Simulation, id: usize, from: f64, to: f64) -> Vec<DVec2> {
    (0..=SAMPLES)
        .map(|k| from + (to - from) * k as f64 / SAMPLES as f64)
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
    *prediction = predict(*sim.table(), *sim.params(), &balls, cue, shot.shot());
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
    gizmos.linestrip(
        line(&prediction.cue_after),
        Color::srgba(0.8, 0.9, 1.0, 0.6),
    );
    gizmos.linestrip(
        line(&prediction.object_after),
        Color::srgba(1.0, 0.85, 0.2, 0.8),
    );
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
        let p = predict(Table::wpa_8ft(), params, &balls, 0, Shot::new(0.0, 2.0));
        let (kind, ghost) = p.contact.unwrap();
        assert_eq!(kind, FirstContact::Ball { number: 1 });
        // Centre to centre 2R at contact, on the line of the shot.
        let two_r = 2.0 * params.ball.radius;
        assert!((ghost.x - (0.3 - two_r)).abs() < 1e-9, "{ghost:?}");
        assert!(ghost.y.abs() < 1e-12);
        // Head on with equal masses: the object ball goes straight on.
        let last = *p.object_after.last().unwrap();
        assert!(last.x > 0.3 && last.y.abs() < 1e-9);
    }

    #[test]
    fn a_cut_sends_the_object_ball_along_the_line_of_centres() {
        let balls = [resting(0, -0.5, 0.0), resting(1, 0.3, 0.03)];
        let params = Params::default();
        let p = predict(Table::wpa_8ft(), params, &balls, 0, Shot::new(0.0, 2.0));
        let (_, ghost) = p.contact.unwrap();
        let centres = (DVec2::new(0.3, 0.03) - ghost).normalize();
        let moved = (p.object_after[SAMPLES / 2] - DVec2::new(0.3, 0.03)).normalize();
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
        let p = predict(Table::wpa_8ft(), params, &balls, 0, shot);
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
        );
        let (kind, ghost) = p.contact.unwrap();
        assert_eq!(kind, FirstContact::Cushion);
        let radius = Params::default().ball.radius;
        assert!((ghost.x - (Table::wpa_8ft().length / 2.0 - radius)).abs() < 1e-9);
    }
}
