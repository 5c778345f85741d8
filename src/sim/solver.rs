//! The solver resource and the conversions between the solver and the ECS.

use std::time::SystemTime;

use bevy::{math::DVec2, prelude::*};
use billiards_physics::{
    self as physics, BallFriction, BallState, CushionModel, Model, Motion, PaperModel, Params,
    Rack, Simulation, SpinModel, recording::Recorder,
};

use super::messages::*;
use crate::{
    settings::{BallFrictionChoice, CushionChoice, PhysicsModel, PhysicsSettings},
    table::balls::{BallMotion, MotionState},
    table::geometry::{TableKind, TableSpec},
};

/// The table just before a strike: what an undo goes back to.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct BeforeShot {
    pub(super) balls: Vec<BallState>,
    /// The game's simulated time at the strike ([`Solver::game_time`]).
    pub(super) game_time: f64,
    pub(super) shot: ShotRequested,
    pub(super) shots: u32,
    pub(super) ball_in_hand: Option<HandRule>,
}

/// The solver and the entity of each of its balls. Every input goes through a [`Recorder`],
/// so the game since the last rack is always an exact recording.
#[derive(Resource, Debug)]
pub struct Solver {
    pub(super) rec: Recorder,
    pub(super) entities: Vec<Entity>,
    pub(super) rack: Rack,
    /// What names the recording: the slug of the rack or of the game.
    pub(super) name: &'static str,
    pub(super) started: SystemTime,
    /// The table before each shot since the rack, newest last (undo goes back one at a time).
    pub(super) undo: Vec<BeforeShot>,
    /// Simulated seconds taken back by undos: the recorder's clock runs on through an undone
    /// shot (its strike stays in the recording), the game's time does not.
    pub(super) undone_time: f64,
    /// A whole scene ([`SceneRequested`]): its own table and parameters, which the Physics
    /// settings do not change.
    pub(super) scene: bool,
    /// The number of the ball the next stroke strikes: 0 (the white) but in a game whose
    /// players each have their own cue ball (three-cushion's yellow, UMB 3.3).
    pub(super) cue_number: u8,
}

impl Solver {
    /// The simulation, for reading.
    pub fn simulation(&self) -> &Simulation {
        self.rec.sim()
    }

    /// The game's simulated time since the rack, as the HUD shows it ([`SimStatus::sim_time`]):
    /// the simulation's clock less the time of the shots taken back by Undo, so that an undo
    /// shows the time of the table it restored.
    pub fn game_time(&self) -> f64 {
        self.simulation().time() - self.undone_time
    }

    /// The recorder: the game since the last rack, inputs and history.
    pub fn recorder(&self) -> &Recorder {
        &self.rec
    }

    /// The rack this game started from.
    pub fn rack(&self) -> Rack {
        self.rack
    }

    /// The short name of this rack for file names: "9-ball", "8-ball", "15-ball".
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// When this game was racked (wall clock; names its recording).
    pub fn started(&self) -> SystemTime {
        self.started
    }

    /// The entity of solver ball `id`.
    pub fn entity(&self, id: usize) -> Option<Entity> {
        self.entities.get(id).copied()
    }

    /// Puts ball `id` at rest at `at` (a spotted colour, a replace): recorded as any
    /// placement. The ball's component is the caller's to update.
    pub fn place_at_rest(
        &mut self,
        id: usize,
        at: physics::Vec2,
    ) -> Result<(), physics::SetupError> {
        self.rec
            .place(id, at, physics::Vec2::ZERO, physics::Vec3::ZERO)
    }

    /// Whether this is a whole scene with its own table and parameters ([`SceneRequested`]).
    pub fn is_scene(&self) -> bool {
        self.scene
    }

    /// Whether anything has happened since the rack (a new rack or game then asks first).
    pub fn in_progress(&self) -> bool {
        !self.simulation().history().events().is_empty()
    }

    /// Shots that [`UndoRequested`] can take back, one at a time.
    pub fn undoable_shots(&self) -> usize {
        self.undo.len()
    }

    /// The solver index of the cue ball, if it is in the layout.
    pub fn cue_ball(&self) -> Option<usize> {
        let cue = self.cue_number;
        self.simulation().numbers().iter().position(|&n| n == cue)
    }

    /// The number of the ball the next stroke strikes ([`Solver::cue_ball`]).
    pub fn cue_number(&self) -> u8 {
        self.cue_number
    }

    /// Makes ball `number` the one the next stroke strikes (the rules say whose turn it is).
    pub fn set_cue_number(&mut self, number: u8) {
        self.cue_number = number;
    }
}

/// Radius of the rounded cushion ends at the pocket mouths (about the nose's own rounding).
pub const JAW_RADIUS: f64 = 0.015;

/// The solver's table for the table's dimensions and the player's settings.
pub fn table_for(spec: &TableSpec, settings: &PhysicsSettings) -> physics::Table {
    let table = spec.physics_table();
    match spec.kind {
        TableKind::Pool if settings.jaws => table.with_jaws(JAW_RADIUS),
        // The snooker table's rounded knuckles are part of the table, not a setting; the
        // carom table has no pockets to give jaws to.
        TableKind::Pool | TableKind::Snooker | TableKind::Carom => table,
    }
}

/// The solver's parameters for the player's settings and the table's balls. On the carom
/// table this is [`Params::carom`] for the default settings: it differs from the pool
/// parameters only in its ball, and the cushion's height is a fraction of the ball's
/// diameter, so it follows the 61.5 mm ball.
pub fn params_for(spec: &TableSpec, settings: &PhysicsSettings) -> Params {
    let model = match settings.model {
        PhysicsModel::Paper => Model::Paper(PaperModel {
            mu_slide: settings.mu_slide,
            mu_roll: settings.mu_roll,
            slide_roll_speed: settings.slide_roll_speed,
            e_ball: settings.e_ball,
            e_cushion: settings.e_cushion,
        }),
        PhysicsModel::Spin => {
            let cushion = match settings.cushion {
                CushionChoice::Han2005 => CushionModel::Han2005 {
                    e: settings.e_cushion,
                    mu: settings.mu_cushion,
                },
                CushionChoice::Reflect => CushionModel::Reflect {
                    e: settings.e_cushion,
                },
                CushionChoice::Mathavan2010 => CushionModel::Mathavan2010 {
                    e: settings.e_cushion,
                    mu: settings.mu_cushion,
                },
            };
            Model::Spin(SpinModel {
                mu_slide: settings.mu_slide,
                mu_roll: settings.mu_roll,
                mu_spin: settings.mu_spin,
                e_ball: settings.e_ball,
                mu_ball: settings.mu_ball,
                cushion,
                cushion_height: settings.cushion_height,
                cue_mass: settings.cue_mass,
                ball_friction: match settings.ball_friction {
                    BallFrictionChoice::Constant => BallFriction::Constant,
                    BallFrictionChoice::SpeedDependent => BallFriction::ALCIATORE,
                },
                end_mass: settings.shaft.end_mass(),
                ..SpinModel::default()
            })
        }
    };
    Params {
        model,
        prediction: settings.prediction,
        randomization: settings
            .randomization
            .enabled
            .then(|| physics::Randomization {
                spread: settings.randomization.spread_degrees.to_radians(),
                seed: settings.randomization.seed,
            }),
        ball: spec.ball(),
        ..Params::default()
    }
}

/// The balls on the table now, by number, as setups at rest (what a layout edit starts
/// from: the Place tool, a launch script's `move`).
pub fn layout_now(sim: &physics::Simulation) -> Vec<physics::BallSetup> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| physics::BallSetup::at(n, b.position))
        .collect()
}

/// A solver vector as a Bevy one.
pub fn to_dvec2(v: physics::Vec2) -> DVec2 {
    DVec2::new(v.x, v.y)
}

pub(super) fn to_vec2(v: DVec2) -> physics::Vec2 {
    physics::Vec2::new(v.x, v.y)
}

/// The component form of a solver ball state.
pub fn ball_motion(state: &BallState) -> BallMotion {
    BallMotion {
        position: to_dvec2(state.position),
        velocity: to_dvec2(state.velocity),
        spin: {
            let w = state.angular_velocity;
            bevy::math::DVec3::new(w.x, w.y, w.z)
        },
        state: match state.motion {
            Motion::Sliding => MotionState::Sliding,
            Motion::Airborne => MotionState::Airborne,
            Motion::Rolling => MotionState::Rolling,
            Motion::OffTable => MotionState::OffTable,
            // Spinning in place: the centre does not move, so nothing to roll.
            Motion::Stationary | Motion::Spinning | Motion::Pocketed(_) => MotionState::Stationary,
        },
        height: state.height,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_carom_table_gets_the_carom_table_and_parameters() {
        let spec = TableSpec::carom();
        // Jaws on (the default) must not give the pocketless table pocket jaws.
        let settings = PhysicsSettings::default();
        assert!(settings.jaws);
        let table = table_for(&spec, &settings);
        assert_eq!(table, physics::Table::carom_match());
        assert!(table.jaws().is_empty());
        // As Params::carom is the default parameters with the carom ball (61.5 mm, 210 g),
        // the carom table's parameters are the pool table's with that ball.
        let params = params_for(&spec, &settings);
        assert_eq!(params.ball, physics::BallSpec::carom());
        assert_eq!(params.ball, Params::carom().ball);
        let pool = params_for(&TableSpec::default(), &settings);
        assert_eq!(
            Params {
                ball: pool.ball,
                ..params
            },
            pool
        );
        // The pool table keeps its jaws.
        let pool_table = table_for(&TableSpec::default(), &settings);
        assert_eq!(pool_table.jaws().len(), 12);
    }
}
