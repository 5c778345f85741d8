//! Requests that take effect from the next step: rack, settings, edited balls, the shot.

use std::time::SystemTime;

use bevy::{prelude::*, window::RequestRedraw};
use billiards_physics::{self as physics, Params, Rack, recording::Recorder};
use billiards_rules::Game;

use super::{messages::*, solver::*};
use crate::{
    settings::{PhysicsSettings, TableSetup},
    table::balls::{Ball, BallMotion},
    table::geometry::{TableKind, TableSpec},
};

/// Free play: another table chosen in the panel ([`TableSetup`]) replaces the table and racks
/// the same rack on it, fresh. A match changes its table only through a new game, which sets
/// both at once.
pub(super) fn follow_table_setup(
    setup: Res<TableSetup>,
    mut spec: ResMut<TableSpec>,
    referee: Res<Referee>,
    solver: Option<Res<Solver>>,
    mut racks: MessageWriter<RackRequested>,
) {
    // Added is not chosen: the kept table reaches the spec as the settings load, and a game
    // started at launch (snooker's own table) must not be laid over by it.
    if !setup.is_changed() || setup.is_added() || !referee.edits {
        return;
    }
    if spec.set_if_neq(TableSpec::of(setup.table)) {
        let rack = solver.map_or(STARTING_RACK, |s| s.rack());
        racks.write(RackRequested::fresh(rack, clock_seed()));
    }
}

/// Clears the table and racks anew: a new solver and new ball entities.
#[allow(clippy::too_many_arguments)]
pub(super) fn rack_balls(
    mut commands: Commands,
    (mut requests, mut layouts, mut scenes): (
        MessageReader<RackRequested>,
        MessageReader<LayoutRequested>,
        MessageReader<SceneRequested>,
    ),
    mut spec: ResMut<TableSpec>,
    (settings, setup): (Res<PhysicsSettings>, Res<TableSetup>),
    solver: Option<Res<Solver>>,
    balls: Query<Entity, With<Ball>>,
    mut status: ResMut<SimStatus>,
) {
    let rack_request = requests.read().last().copied();
    let layout_request = layouts.read().last().cloned();
    let scene_request = scenes.read().last().cloned();
    if scene_request.is_none() && layout_request.is_none() && rack_request.is_none() {
        return;
    }
    if let Some(scene) = scene_request {
        let Ok(rec) = Recorder::new(scene.table, scene.params, scene.balls)
            .inspect_err(|error| status.note = Some(format!("cannot rack: {error}")))
        else {
            return;
        };
        spec.set_if_neq(TableSpec::fitting(&scene.table));
        install(
            &mut commands,
            rec,
            &spec,
            (Rack::PaperDefault, scene.name),
            true,
            &balls,
            &mut status,
        );
        return;
    }
    // Leaving a scene's own table: back to the player's (a rules game sets its own first).
    if solver.is_some_and(|s| s.scene) && layout_request.is_none() {
        spec.set_if_neq(TableSpec::of(setup.table));
    }
    let table = table_for(&spec, &settings);
    let params = params_for(&spec, &settings);
    let (layout, rack) = match (layout_request, rack_request) {
        (Some(LayoutRequested { balls, rack, name }), _) => (balls, (rack, name)),
        // Free play on the snooker table (after a frame): the 22 snooker balls.
        (None, Some(_)) if spec.is_snooker() => match snooker_layout(&table, &params.ball) {
            Ok(balls) => (balls, (Rack::FifteenBall, "snooker")),
            Err(error) => {
                status.note = Some(format!("cannot rack: {error}"));
                return;
            }
        },
        // Free play on the carom table: the three balls on their opening spots.
        (None, Some(_)) if spec.kind == TableKind::Carom => {
            match carom_layout(&table, &params.ball) {
                Ok(balls) => (balls, (Rack::PaperDefault, "three-cushion")),
                Err(error) => {
                    status.note = Some(format!("cannot rack: {error}"));
                    return;
                }
            }
        }
        (None, Some(RackRequested { rack, seed })) => {
            let game = match rack {
                Rack::FifteenBall => Some(Game::EightBall),
                Rack::NineBall => Some(Game::NineBall),
                Rack::PaperDefault | Rack::Tight => None,
            };
            let balls = match (game, seed) {
                (Some(game), Some(seed)) => {
                    game.rack_styled(&table, &params.ball, seed, setup.rack_style)
                }
                _ => rack.layout(&table, &params.ball),
            };
            (balls, (rack, rack_slug(rack)))
        }
        (None, None) => return,
    };
    let rec = match Recorder::new(table, params, layout) {
        Ok(rec) => rec,
        Err(error) => {
            status.note = Some(format!("cannot rack: {error}"));
            return;
        }
    };
    install(&mut commands, rec, &spec, rack, false, &balls, &mut status);
}

/// Replaces the ball entities and the solver with `rec`'s; `rack` is the standard rack closest
/// to it and the recording's name.
fn install(
    commands: &mut Commands,
    rec: Recorder,
    spec: &TableSpec,
    rack: (Rack, &'static str),
    scene: bool,
    balls: &Query<Entity, With<Ball>>,
    status: &mut SimStatus,
) {
    for entity in balls {
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
        rack: rack.0,
        name: rack.1,
        started: SystemTime::now(),
        undo: Vec::new(),
        undone_time: 0.0,
        scene,
        cue_number: 0,
    });
    *status = SimStatus {
        at_rest: true,
        ..default()
    };
}

/// The 22 balls of a snooker frame (WPBSA 3.2), the cue ball in the D.
pub fn snooker_layout(
    table: &physics::Table,
    ball: &physics::BallSpec,
) -> Result<Vec<physics::BallSetup>, String> {
    let marks = physics::SnookerMarks::of(table)?;
    physics::snooker::layout(table, ball, physics::snooker::default_cue_position(&marks))
}

/// The three balls of a three-cushion opening (UMB Art. 23, `billiards_rules::three_cushion`):
/// the red (2) on the top spot, the yellow (1) on the bottom spot, the white (0), the cue
/// ball, on the left starting spot.
pub fn carom_layout(
    table: &physics::Table,
    ball: &physics::BallSpec,
) -> Result<Vec<physics::BallSetup>, String> {
    use billiards_rules::three_cushion::{Ball, Side, Spots};
    let spots = Spots::of(table, ball.radius).map_err(|e| e.to_string())?;
    let at = spots.opening(Ball::White, Side::Left);
    Ok(Ball::ALL
        .map(|b| physics::BallSetup::at(b.index() as u8, at[b.index()]))
        .to_vec())
}

/// A settings change reaches the solver: moving balls continue under the new parameters. A
/// whole scene keeps its own; a physics edit there is noted, not applied.
pub(super) fn apply_physics_settings(
    settings: Res<PhysicsSettings>,
    spec: Res<TableSpec>,
    solver: Option<ResMut<Solver>>,
    mut status: ResMut<SimStatus>,
    mut asked: Local<Option<Params>>,
) {
    let Some(mut solver) = solver else { return };
    if !settings.is_changed() {
        return;
    }
    let params = params_for(&spec, &settings);
    // The clock settings (pause, time scale) change the resource too but not the physics.
    let edited = asked.replace(params).is_some_and(|before| before != params);
    if solver.scene {
        if edited {
            status.note = Some(
                "this table keeps its own physics: the settings apply from the next rack".into(),
            );
        }
        return;
    }
    // Compare with what the solver has rather than trusting change detection alone.
    if *solver.simulation().params() == params {
        return;
    }
    if let Err(error) = solver.rec.set_params(params) {
        status.note = Some(format!("settings not applied: {error}"));
    }
}

/// Balls whose [`BallMotion`] was edited outside the solver (respot, ball in hand, tools)
/// are placed in the solver; only they are re-predicted. An edit the solver rejects (off the
/// table, overlapping) is undone.
pub(super) fn place_edited_balls(
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
pub(super) fn strike_cue_ball(
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
    let shot = request.shot();
    let before = BeforeShot {
        balls: solver.simulation().balls().collect(),
        game_time: solver.game_time(),
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
