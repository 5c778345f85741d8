//! The simulation: `billiards-physics` inside the ECS.
//!
//! One frame, in [`Update`]:
//! 1. [`SimSystems::Step`]: one exclusive system advances the solver by the frame's virtual
//!    time (so pause and time scale apply), or by exactly one event when the paused player
//!    asks for a step. It writes back only the balls whose state changed and turns the
//!    solver's events into messages ([`BallContact`], [`CushionHit`], [`BallPocketed`],
//!    [`ShotFinished`]). When every ball rests it does nothing at all.
//! 2. [`SimSystems::Flow`]: the game's reaction to a finished shot (respotting after a scratch).
//! 3. [`SimSystems::Commands`]: requests for the next frame: rack, settings changes, edited
//!    balls (found by change detection, so only those are re-predicted), the shot.
//!
//! Running the requests after the step means a shot starts with the next frame's delta, not
//! with whatever idle time the reactive window accumulated before the key press.

use std::{
    ops::Range,
    time::{Instant, SystemTime},
};

use bevy::{math::DVec2, prelude::*, window::RequestRedraw};
use billiards_physics::{
    self as physics, BallState, CushionModel, EventKind, Model, Motion, PaperModel, Params, Rack,
    Shot, Simulation, SpinModel, recording::Recorder,
};

use billiards_rules::{CueBall, PlacementError};

use crate::{
    balls::{Ball, BallMotion, MotionState, Pocketed},
    geometry::TableSpec,
    mode::GameMode,
    settings::{CushionChoice, PhysicsModel, PhysicsSettings},
};

/// Registers the solver, its messages and the game-flow systems. Needs no rendering, so it
/// runs headless under `MinimalPlugins` too (together with [`crate::settings::plugin`]).
pub fn plugin(app: &mut App) {
    app.add_message::<RackRequested>()
        .add_message::<LayoutRequested>()
        .add_message::<ShotRequested>()
        .add_message::<StepRequested>()
        .add_message::<CueStruck>()
        .add_message::<UndoRequested>()
        .add_message::<ShotUndone>()
        .add_message::<BallContact>()
        .add_message::<CushionHit>()
        .add_message::<BallPocketed>()
        .add_message::<ShotFinished>()
        .add_message::<RequestRedraw>()
        .init_resource::<TableSpec>()
        .init_resource::<SimStatus>()
        .init_resource::<Referee>()
        .configure_sets(
            Update,
            (SimSystems::Step, SimSystems::Flow, SimSystems::Commands).chain(),
        )
        // The live solver neither advances nor takes commands while a recording is shown.
        .configure_sets(Update, SimSystems::Step.run_if(in_state(GameMode::Play)))
        .configure_sets(Update, SimSystems::Flow.run_if(in_state(GameMode::Play)))
        .configure_sets(
            Update,
            SimSystems::Commands.run_if(in_state(GameMode::Play)),
        )
        // A rack's new balls get their meshes in the frame the old ones are despawned, so no
        // frame shows an empty table.
        .configure_sets(
            Update,
            crate::balls::BallSystems::Visuals.after(SimSystems::Commands),
        )
        .add_systems(Startup, request_default_rack)
        .add_systems(
            Update,
            (
                advance_solver.in_set(SimSystems::Step),
                respot_after_scratch.in_set(SimSystems::Flow),
                (
                    apply_clock_settings,
                    rack_balls,
                    apply_physics_settings,
                    place_edited_balls,
                    undo_last_shot,
                    strike_cue_ball,
                )
                    .chain()
                    .in_set(SimSystems::Commands),
            ),
        );
}

/// The phases of the simulation within a frame, in order.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SimSystems {
    /// The exclusive solver step and its writeback.
    Step,
    /// Game flow reacting to what the step reported.
    Flow,
    /// Requests that take effect from the next step on.
    Commands,
}

/// The racks the panel offers, in its order.
pub const RACKS: [Rack; 4] = [
    Rack::PaperDefault,
    Rack::FifteenBall,
    Rack::Tight,
    Rack::NineBall,
];

/// The name of a rack shown to the player.
pub fn rack_label(rack: Rack) -> &'static str {
    match rack {
        Rack::PaperDefault => "Paper default",
        Rack::FifteenBall => "15-ball rack",
        Rack::Tight => "Tight 15",
        Rack::NineBall => "9-ball rack",
    }
}

/// The rack on the table when the game starts: the paper's 15 balls 1/10 in apart, with the
/// cue ball on the head spot.
pub const STARTING_RACK: Rack = Rack::FifteenBall;

/// A short name of a rack for file names.
pub fn rack_slug(rack: Rack) -> &'static str {
    match rack {
        Rack::PaperDefault => "paper",
        Rack::FifteenBall => "15-ball",
        Rack::Tight => "tight-15",
        Rack::NineBall => "9-ball",
    }
}

/// Asks for the table to be cleared and racked anew.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RackRequested(pub Rack);

/// Asks for the table to be cleared and set up with these balls (a rules game's seeded rack,
/// [`billiards_rules::Game::rack`]); `rack` names the recording. Wins over a
/// [`RackRequested`] of the same frame.
#[derive(Message, Debug, Clone, PartialEq)]
pub struct LayoutRequested {
    /// The balls, the cue ball first.
    pub balls: Vec<physics::BallSetup>,
    /// The standard rack closest to it (names the recording file).
    pub rack: Rack,
}

/// What a rules game (`crate::game`) asks of the simulation: it takes over the cue ball after
/// a scratch (so the free-play respot stays out of its way) and may refuse a shot (a choice
/// or a call is pending). The default is free play: no referee.
#[derive(Resource, Debug, Clone, Default, PartialEq, Eq)]
pub struct Referee {
    /// A rules game is in play: a scratch is the referee's to handle.
    pub active: bool,
    /// Why the next shot may not be taken yet, if it may not.
    pub refuse_shot: Option<String>,
}

/// Asks for the cue ball to be struck. Only honoured while every ball rests.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ShotRequested {
    /// Direction in the table plane, radians counter-clockwise from +x.
    pub angle: f64,
    /// Cue-ball speed given by the cue, m/s.
    pub speed: f64,
    /// Where the tip strikes (spin model).
    pub tip: physics::TipOffset,
}

impl ShotRequested {
    /// The request for the shot the settings describe.
    pub fn from_settings(shot: &crate::settings::ShotSettings) -> Self {
        Self {
            angle: shot.angle,
            speed: shot.power,
            tip: shot.tip,
        }
    }
}

/// Asks for the last shot to be taken back (practice: free play only). Every ball goes back to
/// where it rested before the strike through placements the recorder logs, so a recording
/// with undos replays and verifies bit for bit like any other. Also while balls still move.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct UndoRequested;

/// A shot was taken back; carries it, so the panel can line it up again (retry).
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ShotUndone {
    /// The shot taken back.
    pub shot: ShotRequested,
}

/// The table just before a strike: what an undo goes back to.
#[derive(Debug, Clone, PartialEq)]
struct BeforeShot {
    balls: Vec<BallState>,
    shot: ShotRequested,
    shots: u32,
    ball_in_hand: Option<CueBall>,
}

/// Asks the paused simulation to advance exactly to its next event.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StepRequested;

/// The cue struck a ball.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct CueStruck {
    /// The ball.
    pub ball: Entity,
    /// The speed the cue gave it, m/s.
    pub speed: f64,
    /// Simulation time, seconds.
    pub time: f64,
}

/// Two balls collided.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct BallContact {
    /// The ball with the lower solver index.
    pub a: Entity,
    /// The other ball.
    pub b: Entity,
    /// Their relative speed just after the contact, m/s (how hard it sounds).
    pub speed: f64,
    /// Simulation time of the contact, seconds.
    pub time: f64,
}

/// What part of the table's edge a ball hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CushionPart {
    /// The straight nose of a cushion.
    Cushion(physics::Cushion),
    /// The rounded jaw at the mouth of a pocket.
    Jaw(physics::Pocket),
}

/// A ball hit a cushion or a pocket jaw.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct CushionHit {
    /// The ball.
    pub ball: Entity,
    /// What it hit.
    pub part: CushionPart,
    /// The ball's speed just after the hit, m/s.
    pub speed: f64,
    /// Simulation time of the hit, seconds.
    pub time: f64,
}

/// A ball dropped into a pocket.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct BallPocketed {
    /// The ball.
    pub ball: Entity,
    /// Its number.
    pub number: u8,
    /// The pocket.
    pub pocket: physics::Pocket,
    /// Simulation time, seconds.
    pub time: f64,
}

/// Every ball has come to rest after a shot.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShotFinished {
    /// Whether the cue ball went into a pocket.
    pub scratch: bool,
}

/// What the simulation reports to the HUD and to the game flow.
#[derive(Resource, Debug, Clone, PartialEq, Default)]
pub struct SimStatus {
    /// Whether every ball is at rest (a shot may be taken).
    pub at_rest: bool,
    /// Shots taken since the last rack.
    pub shots: u32,
    /// Simulated time since the last rack, seconds.
    pub sim_time: f64,
    /// Events the solver resolved since the last strike (the strike itself not counted).
    pub events_this_shot: usize,
    /// Wall time the solver took in the last frame that ran it, seconds.
    pub solver_seconds_last_frame: f64,
    /// A message for the player about the simulation's state, if any.
    pub note: Option<String>,
    /// Until the next shot, the cue ball is in hand: after a free-play scratch
    /// ([`CueBall::Respot`]: it slides along the head string), or under the rules behind the
    /// head string or anywhere.
    pub ball_in_hand: Option<CueBall>,
}

/// The solver and the entity of each of its balls. Every input goes through a [`Recorder`],
/// so the game since the last rack is always an exact recording.
#[derive(Resource, Debug)]
pub struct Solver {
    rec: Recorder,
    entities: Vec<Entity>,
    rack: Rack,
    started: SystemTime,
    /// The table before each shot since the rack, newest last (undo goes back one at a time).
    undo: Vec<BeforeShot>,
}

impl Solver {
    /// The simulation, for reading.
    pub fn simulation(&self) -> &Simulation {
        self.rec.sim()
    }

    /// The recorder: the game since the last rack, inputs and history.
    pub fn recorder(&self) -> &Recorder {
        &self.rec
    }

    /// The rack this game started from.
    pub fn rack(&self) -> Rack {
        self.rack
    }

    /// When this game was racked (wall clock; names its recording).
    pub fn started(&self) -> SystemTime {
        self.started
    }

    /// The entity of solver ball `id`.
    pub fn entity(&self, id: usize) -> Option<Entity> {
        self.entities.get(id).copied()
    }

    /// Shots that [`UndoRequested`] can take back, one at a time.
    pub fn undoable_shots(&self) -> usize {
        self.undo.len()
    }

    /// The solver index of the cue ball, if it is in the layout.
    pub fn cue_ball(&self) -> Option<usize> {
        self.simulation().numbers().iter().position(|&n| n == 0)
    }
}

/// Radius of the rounded cushion ends at the pocket mouths (about the nose's own rounding).
pub const JAW_RADIUS: f64 = 0.015;

/// The solver's table for the table's dimensions and the player's settings.
pub fn table_for(spec: &TableSpec, settings: &PhysicsSettings) -> physics::Table {
    let table = spec.physics_table();
    if settings.jaws {
        table.with_jaws(JAW_RADIUS)
    } else {
        table
    }
}

/// The solver's parameters for the player's settings.
pub fn params_from(settings: &PhysicsSettings) -> Params {
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
        ..Params::default()
    }
}

/// A solver vector as a Bevy one.
pub fn to_dvec2(v: physics::Vec2) -> DVec2 {
    DVec2::new(v.x, v.y)
}

fn to_vec2(v: DVec2) -> physics::Vec2 {
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
            Motion::Rolling => MotionState::Rolling,
            // Spinning in place: the centre does not move, so nothing to roll.
            Motion::Stationary | Motion::Spinning | Motion::Pocketed(_) => MotionState::Stationary,
        },
    }
}

/// Applies the pause and time-scale settings to the virtual clock the solver advances by.
fn apply_clock_settings(settings: Res<PhysicsSettings>, mut time: ResMut<Time<Virtual>>) {
    if !settings.is_changed() {
        return;
    }
    time.set_relative_speed_f64(settings.time_scale);
    if settings.paused {
        time.pause();
    } else {
        time.unpause();
    }
}

fn request_default_rack(mut racks: MessageWriter<RackRequested>) {
    racks.write(RackRequested(STARTING_RACK));
}

/// The solver step (see the module docs). Exclusive: it needs the solver, the ball
/// components and the message queues at once, and nothing else may run beside it anyway.
fn advance_solver(world: &mut World) {
    let step_requested = world
        .resource_mut::<Messages<StepRequested>>()
        .drain()
        .count()
        > 0;
    if !world.contains_resource::<Solver>() {
        return;
    }
    let dt = world.resource::<Time>().delta_secs_f64();
    let paused = world.resource::<Time<Virtual>>().is_paused();
    world.resource_scope(|world, mut solver: Mut<Solver>| {
        if solver.simulation().is_at_rest() {
            return;
        }
        let started = Instant::now();
        let outcome: Result<Range<usize>, String> = if paused {
            if !step_requested {
                return;
            }
            let before = solver.simulation().history().events().len();
            solver.rec.step_event();
            Ok(before..solver.simulation().history().events().len())
        } else if dt > 0.0 {
            solver
                .rec
                .advance(dt)
                .map(|advance| advance.events)
                .map_err(|error| error.to_string())
        } else {
            return;
        };
        let cost = started.elapsed().as_secs_f64();
        write_back(world, &solver);
        let events = match outcome {
            Ok(range) => range,
            Err(error) => {
                // The solver's state is valid where it stopped; show why it stopped.
                world.resource_mut::<SimStatus>().note = Some(format!("solver: {error}"));
                0..0
            }
        };
        send_event_messages(world, &solver, events.clone());
        let at_rest = solver.simulation().is_at_rest();
        {
            let mut status = world.resource_mut::<SimStatus>();
            status.at_rest = at_rest;
            status.sim_time = solver.simulation().time();
            status.events_this_shot += events.len();
            status.solver_seconds_last_frame = cost;
        }
        if let Some(mut shown) = world.get_resource_mut::<crate::balls::ShownTime>() {
            shown.0 = solver.simulation().time();
        }
        if at_rest {
            let scratch = solver
                .cue_ball()
                .is_some_and(|id| !solver.simulation().ball(id).motion.on_table());
            world.write_message(ShotFinished { scratch });
        } else {
            // The window only redraws on demand; moving balls demand it.
            world.write_message(RequestRedraw);
        }
    });
}

/// Copies changed solver states to the ball components (`set_if_neq`: a ball at rest is not
/// touched, so change detection downstream sees only what moved).
fn write_back(world: &mut World, solver: &Solver) {
    for (id, &entity) in solver.entities.iter().enumerate() {
        let state = solver.simulation().ball(id);
        let Ok(mut ball) = world.get_entity_mut(entity) else {
            continue;
        };
        if let Some(mut motion) = ball.get_mut::<BallMotion>() {
            motion.set_if_neq(ball_motion(&state));
        }
        if let Motion::Pocketed(pocket) = state.motion
            && !ball.contains::<Pocketed>()
        {
            ball.insert(Pocketed { pocket });
        }
    }
}

fn send_event_messages(world: &mut World, solver: &Solver, events: Range<usize>) {
    let entity = |id: usize| solver.entities[id];
    for event in &solver.simulation().history().events()[events] {
        let time = event.time;
        match event.kind {
            EventKind::BallBall { a, b } => {
                world.write_message(BallContact {
                    a: entity(a),
                    b: entity(b),
                    speed: (event.after[0].velocity - event.after[1].velocity).length(),
                    time,
                });
            }
            EventKind::Cushion { ball, cushion } => {
                world.write_message(CushionHit {
                    ball: entity(ball),
                    part: CushionPart::Cushion(cushion),
                    speed: event.after[0].velocity.length(),
                    time,
                });
            }
            EventKind::Jaw { ball, pocket } => {
                world.write_message(CushionHit {
                    ball: entity(ball),
                    part: CushionPart::Jaw(pocket),
                    speed: event.after[0].velocity.length(),
                    time,
                });
            }
            EventKind::Strike { ball, shot } => {
                world.write_message(CueStruck {
                    ball: entity(ball),
                    speed: shot.speed,
                    time,
                });
            }
            EventKind::Pocketed { ball, pocket } => {
                world.write_message(BallPocketed {
                    ball: entity(ball),
                    number: solver.simulation().numbers()[ball],
                    pocket,
                    time,
                });
            }
            EventKind::Placed { .. } | EventKind::ParamsChanged | EventKind::Transition { .. } => {}
        }
    }
}

/// Clears the table and racks anew: a new solver and new ball entities.
fn rack_balls(
    mut commands: Commands,
    mut requests: MessageReader<RackRequested>,
    mut layouts: MessageReader<LayoutRequested>,
    spec: Res<TableSpec>,
    settings: Res<PhysicsSettings>,
    balls: Query<Entity, With<Ball>>,
    mut status: ResMut<SimStatus>,
) {
    let rack_request = requests.read().last().copied();
    let layout_request = layouts.read().last().cloned();
    let table = table_for(&spec, &settings);
    let params = params_from(&settings);
    let (layout, rack) = match (layout_request, rack_request) {
        (Some(LayoutRequested { balls, rack }), _) => (balls, rack),
        (None, Some(RackRequested(rack))) => (rack.layout(&table, &params.ball), rack),
        (None, None) => return,
    };
    let rec = match Recorder::new(table, params, layout) {
        Ok(rec) => rec,
        Err(error) => {
            status.note = Some(format!("cannot rack: {error}"));
            return;
        }
    };
    for entity in &balls {
        commands.entity(entity).despawn();
    }
    let sim = rec.sim();
    let entities = sim
        .balls()
        .zip(sim.numbers())
        .enumerate()
        .map(|(id, (state, &number))| {
            let motion = ball_motion(&state);
            commands
                .spawn((
                    Ball { id, number },
                    motion,
                    Transform::from_translation(spec.ball_world_position(motion.position)),
                    Name::new(format!("Ball {number}")),
                ))
                .id()
        })
        .collect();
    commands.insert_resource(Solver {
        rec,
        entities,
        rack,
        started: SystemTime::now(),
        undo: Vec::new(),
    });
    *status = SimStatus {
        at_rest: true,
        ..default()
    };
}

/// A settings change reaches the solver: moving balls continue under the new parameters.
fn apply_physics_settings(
    settings: Res<PhysicsSettings>,
    solver: Option<ResMut<Solver>>,
    mut status: ResMut<SimStatus>,
) {
    let Some(mut solver) = solver else { return };
    let params = params_from(&settings);
    // Compare with what the solver has rather than trusting change detection alone: the
    // clock settings (pause, time scale) change the resource too but not the physics.
    if !settings.is_changed() || *solver.simulation().params() == params {
        return;
    }
    if let Err(error) = solver.rec.set_params(params) {
        status.note = Some(format!("settings not applied: {error}"));
    }
}

/// Balls whose [`BallMotion`] was edited outside the solver (respot, ball in hand, tools)
/// are placed in the solver; only they are re-predicted. An edit the solver rejects (off the
/// table, overlapping) is undone.
fn place_edited_balls(
    solver: Option<ResMut<Solver>>,
    mut balls: Query<(&Ball, &mut BallMotion), Changed<BallMotion>>,
    mut status: ResMut<SimStatus>,
) {
    let Some(mut solver) = solver else { return };
    for (ball, mut motion) in &mut balls {
        if ball.id >= solver.simulation().ball_count() {
            continue;
        }
        let state = solver.simulation().ball(ball.id);
        // The solver's own writeback also marks the component changed; it matches exactly.
        let current = ball_motion(&state);
        if motion.position == current.position && motion.velocity == current.velocity {
            continue;
        }
        // A ball put down by hand carries no spin.
        let result = solver.rec.place(
            ball.id,
            to_vec2(motion.position),
            to_vec2(motion.velocity),
            physics::Vec3::ZERO,
        );
        if let Err(error) = result {
            status.note = Some(format!("ball {} not moved: {error}", ball.number));
        }
        // Either way the component now says what the solver has; already marked changed.
        *motion.bypass_change_detection() = ball_motion(&solver.simulation().ball(ball.id));
        status.at_rest = solver.simulation().is_at_rest();
    }
}

/// Strikes the cue ball when every ball rests.
fn strike_cue_ball(
    mut shots: MessageReader<ShotRequested>,
    solver: Option<ResMut<Solver>>,
    mut balls: Query<&mut BallMotion>,
    mut status: ResMut<SimStatus>,
    referee: Res<Referee>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    let Some(&request) = shots.read().last() else {
        return;
    };
    let Some(mut solver) = solver else { return };
    if let Some(why) = &referee.refuse_shot {
        status.note = Some(why.clone());
        return;
    }
    if !solver.simulation().is_at_rest() {
        status.note = Some("wait until every ball rests".to_owned());
        return;
    }
    let Some(cue_ball) = solver.cue_ball() else {
        status.note = Some("there is no cue ball in this layout".to_owned());
        return;
    };
    let shot = Shot {
        angle: request.angle,
        speed: request.speed,
        tip: request.tip,
    };
    let before = BeforeShot {
        balls: solver.simulation().balls().collect(),
        shot: request,
        shots: status.shots,
        ball_in_hand: status.ball_in_hand,
    };
    match solver.rec.strike(cue_ball, shot) {
        Ok(()) => {
            solver.undo.push(before);
            // Show the struck ball's new velocity now rather than after the next step.
            if let Ok(mut motion) = balls.get_mut(solver.entities[cue_ball]) {
                *motion = ball_motion(&solver.simulation().ball(cue_ball));
            }
            status.shots += 1;
            status.events_this_shot = 0;
            status.ball_in_hand = None;
            status.at_rest = solver.simulation().is_at_rest();
            status.note = None;
            redraw.write(RequestRedraw);
        }
        Err(error) => status.note = Some(format!("no shot: {error}")),
    }
}

/// Takes the last shot back ([`UndoRequested`]): each ball goes back where it was before the
/// strike, by placements the recorder logs; the panel gets the shot back ([`ShotUndone`]).
#[allow(clippy::too_many_arguments)]
fn undo_last_shot(
    mut commands: Commands,
    mut requests: MessageReader<UndoRequested>,
    solver: Option<ResMut<Solver>>,
    referee: Res<Referee>,
    spec: Res<TableSpec>,
    mut balls: Query<&mut BallMotion>,
    mut status: ResMut<SimStatus>,
    mut undone: MessageWriter<ShotUndone>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    if requests.read().count() == 0 {
        return;
    }
    let Some(mut solver) = solver else { return };
    if referee.active {
        status.note = Some("undo is for practice (free play): a match's shots stand".to_owned());
        return;
    }
    let Some(before) = solver.undo.pop() else {
        status.note = Some("no shot to undo since the rack".to_owned());
        return;
    };
    if let Err(error) = restore(&mut solver.rec, &spec, &before.balls) {
        status.note = Some(format!("undo incomplete: {error}"));
    } else {
        status.note = None;
    }
    for (id, &entity) in solver.entities.iter().enumerate() {
        let state = solver.simulation().ball(id);
        if let Ok(mut motion) = balls.get_mut(entity) {
            motion.set_if_neq(ball_motion(&state));
        }
        if state.motion.on_table() {
            commands.entity(entity).remove::<Pocketed>();
        }
    }
    status.at_rest = solver.simulation().is_at_rest();
    status.shots = before.shots;
    status.ball_in_hand = before.ball_in_hand;
    status.events_this_shot = 0;
    undone.write(ShotUndone { shot: before.shot });
    redraw.write(RequestRedraw);
}

/// Puts every ball back in `target` (its state before a shot) by recorded placements. A ball
/// whose old spot is taken by another not yet moved back waits; when every waiting ball is
/// blocked (two balls swapped places), one of the blockers is first set down on a free spot.
fn restore(rec: &mut Recorder, spec: &TableSpec, target: &[BallState]) -> Result<(), String> {
    let differs = |rec: &Recorder, id: usize| {
        let now = rec.sim().ball(id);
        let want = &target[id];
        want.motion.on_table()
            && (!now.motion.on_table()
                || now.position != want.position
                || now.velocity != want.velocity
                || now.angular_velocity != want.angular_velocity)
    };
    let mut pending: Vec<usize> = (0..target.len()).filter(|&id| differs(rec, id)).collect();
    // Each round places at least one ball for good, or parks one blocker: bounded.
    for _ in 0..4 * target.len() + 4 {
        if pending.is_empty() {
            return Ok(());
        }
        let placed = pending.iter().position(|&id| {
            let want = target[id];
            rec.place(id, want.position, want.velocity, want.angular_velocity)
                .is_ok()
        });
        if let Some(k) = placed {
            pending.remove(k);
            continue;
        }
        // Every waiting ball is blocked by another waiting one: park the first blocker.
        let id = pending[0];
        let r = rec.sim().params().ball.radius;
        let blocker = pending
            .iter()
            .copied()
            .find(|&j| {
                j != id
                    && rec.sim().ball(j).motion.on_table()
                    && (rec.sim().ball(j).position - target[id].position).length() < 2.0 * r
            })
            .ok_or_else(|| format!("ball {id} cannot go back"))?;
        let spot = free_spot(rec.sim(), spec, target).ok_or("no free spot on the table")?;
        rec.place(blocker, spot, physics::Vec2::ZERO, physics::Vec3::ZERO)
            .map_err(|error| error.to_string())?;
    }
    Err("the balls could not all be put back".to_owned())
}

/// A spot on the cloth clear of every ball on the table and of every spot in `target`.
fn free_spot(sim: &Simulation, spec: &TableSpec, target: &[BallState]) -> Option<physics::Vec2> {
    let r = spec.ball_radius;
    let clear = 2.0 * r + 0.005;
    let (hx, hy) = (spec.length / 2.0 - 2.0 * r, spec.width / 2.0 - 2.0 * r);
    let taken: Vec<physics::Vec2> = sim
        .balls()
        .filter(|b| b.motion.on_table())
        .map(|b| b.position)
        .chain(
            target
                .iter()
                .filter(|b| b.motion.on_table())
                .map(|b| b.position),
        )
        .collect();
    let steps = 24;
    (0..=steps)
        .flat_map(|i| (0..=steps / 2).map(move |j| (i, j)))
        .map(|(i, j)| {
            physics::Vec2::new(
                -hx + 2.0 * hx * f64::from(i) / f64::from(steps),
                -hy + 2.0 * hy * f64::from(j) / f64::from(steps / 2),
            )
        })
        .find(|&p| taken.iter().all(|&q| (p - q).length() >= clear))
}

/// Free play: after a scratch the cue ball goes back on the head string, where
/// [`billiards_rules::cue_ball_spot`] says (the rule the command line plays by too). The edit
/// reaches the solver like any other (change detection). In a rules game the [`Referee`]
/// handles the scratch instead.
pub fn respot_after_scratch(
    mut commands: Commands,
    mut finished: MessageReader<ShotFinished>,
    solver: Option<Res<Solver>>,
    referee: Res<Referee>,
    mut balls: Query<&mut BallMotion>,
    mut status: ResMut<SimStatus>,
) {
    if !finished.read().any(|shot| shot.scratch) || referee.active {
        return;
    }
    let Some(solver) = solver else { return };
    let Some(cue) = solver.cue_ball() else { return };
    if respot_ball(&mut commands, &solver, cue, &mut balls, &mut status) {
        status.note = Some(
            "scratch: the cue ball is back on the head string (ball in hand: drag it, or \
             the slider moves it along the string)"
                .to_owned(),
        );
        status.ball_in_hand = Some(CueBall::Respot);
    }
}

/// Puts ball `id` back on the table by an edit of its [`BallMotion`] (so the solver and the
/// recording get it): the cue ball on the head string ([`billiards_rules::cue_ball_spot`]),
/// an object ball on the foot string ([`billiards_rules::object_ball_spot`], WPA 1.4).
/// Returns whether a free spot was found (if not, a note says so).
pub fn respot_ball(
    commands: &mut Commands,
    solver: &Solver,
    id: usize,
    balls: &mut Query<&mut BallMotion>,
    status: &mut SimStatus,
) -> bool {
    let number = solver.simulation().numbers()[id];
    let spot = if number == 0 {
        billiards_rules::cue_ball_spot(solver.simulation(), id)
    } else {
        billiards_rules::object_ball_spot(solver.simulation(), id)
    };
    let Some(spot) = spot else {
        status.note = Some(format!("no free spot for the ball {number}"));
        return false;
    };
    let entity = solver.entities[id];
    let Ok(mut motion) = balls.get_mut(entity) else {
        return false;
    };
    *motion = BallMotion {
        position: to_dvec2(spot),
        velocity: DVec2::ZERO,
        state: MotionState::Stationary,
        spin: bevy::math::DVec3::ZERO,
    };
    commands.entity(entity).remove::<Pocketed>();
    true
}

/// Puts the cue ball in hand at `at` if the rules allow it there
/// ([`billiards_rules::check_placement`]: on the table, behind the head string when it must
/// be, on no other ball); a refused spot leaves it where it was. The edit reaches the solver
/// (and the recording) like any placement. Free play's [`CueBall::Respot`] slides it along
/// the head string instead ([`move_ball_in_hand`]).
pub fn place_ball_in_hand(
    solver: &Solver,
    spec: &TableSpec,
    motion: &mut BallMotion,
    at: DVec2,
    rule: CueBall,
) -> Result<(), PlacementError> {
    if rule == CueBall::Respot {
        move_ball_in_hand(spec, motion, at.y);
        return Ok(());
    }
    let cue = solver.cue_ball().ok_or(PlacementError::NotInHand)?;
    billiards_rules::check_placement(solver.simulation(), cue, to_vec2(at), rule)?;
    if motion.position != at {
        motion.position = at;
        motion.velocity = DVec2::ZERO;
    }
    Ok(())
}

/// Moves the cue ball in hand to `y` on the head string, clamped between the side cushions.
/// Goes through the same component edit as any placement, so the solver (and the recording)
/// gets it; a spot on another ball is refused there, with a note.
pub fn move_ball_in_hand(spec: &TableSpec, motion: &mut BallMotion, y: f64) {
    let limit = spec.width / 2.0 - spec.ball_radius;
    let y = if y.is_finite() {
        y.clamp(-limit, limit)
    } else {
        0.0
    };
    let spot = DVec2::new(spec.head_spot().x, y);
    if motion.position != spot {
        motion.position = spot;
        motion.velocity = DVec2::ZERO;
    }
}
