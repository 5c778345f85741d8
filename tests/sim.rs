//! Headless tests of the simulation plugin: `MinimalPlugins` plus the game's settings and
//! simulation plugins, with time advanced by hand.

use std::time::Duration;

use bevy::{math::DVec2, prelude::*, time::TimeUpdateStrategy};
use billiards::{
    mode,
    settings::{self, PhysicsSettings},
    sim::{
        self, BallPocketed, RackRequested, ShotFinished, ShotRequested, SimStatus, Solver,
        params_for, table_for,
    },
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
};
use billiards_physics::{Motion, Rack, Shot, Simulation, TipOffset};
use billiards_rules::Shots;

/// A headless game with the given rack on the table.
fn game(rack: Rack) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, mode::plugin, settings::plugin, sim::plugin));
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(
        16,
    )));
    app.update();
    app.world_mut().write_message(RackRequested::standard(rack));
    app.update();
    app
}

/// Runs frames with durations from `frame` until every ball rests (at most `limit` frames);
/// returns how many frames ran.
fn run_to_rest(app: &mut App, mut frame: impl FnMut(usize) -> Duration, limit: usize) -> usize {
    for i in 0..limit {
        app.insert_resource(TimeUpdateStrategy::ManualDuration(frame(i)));
        app.update();
        if i > 0 && app.world().resource::<SimStatus>().at_rest {
            return i + 1;
        }
    }
    panic!("balls still moving after {limit} frames");
}

/// The balls as the ECS has them, by solver index: position, pocketed or not.
fn ecs_balls(app: &mut App) -> Vec<(usize, DVec2, bool)> {
    let mut balls: Vec<_> = app
        .world_mut()
        .query::<(&Ball, &BallMotion, Has<Pocketed>)>()
        .iter(app.world())
        .map(|(ball, motion, pocketed)| (ball.id, motion.position, pocketed))
        .collect();
    balls.sort_by_key(|&(id, _, _)| id);
    balls
}

fn shoot(app: &mut App, angle: f64, speed: f64) {
    shoot_with_tip(app, angle, speed, TipOffset::default());
}

fn shoot_with_tip(app: &mut App, angle: f64, speed: f64, tip: TipOffset) {
    app.world_mut().write_message(ShotRequested {
        angle,
        speed,
        tip,
        elevation: 0.0,
    });
}

/// The duration of frame `i`.
type FramePattern = fn(usize) -> Duration;

#[test]
fn a_break_ends_bit_identical_to_the_library_however_frames_are_sliced() {
    let (angle, speed) = (0.012, 9.0);
    // The library alone, run to rest.
    let spec = TableSpec::default();
    let settings = PhysicsSettings::default();
    let params = params_for(&spec, &settings);
    let table = table_for(&spec, &settings);
    let layout = Rack::FifteenBall.layout(&table, &params.ball);
    let mut reference = Simulation::new(table, params, &layout).unwrap();
    reference.strike(0, Shot::new(angle, speed)).unwrap();
    reference.run_to_rest().unwrap();
    let expected: Vec<(usize, DVec2, bool)> = reference
        .balls()
        .enumerate()
        .map(|(id, s)| {
            let pocketed = matches!(s.motion, Motion::Pocketed(_));
            (id, DVec2::new(s.position.x, s.position.y), pocketed)
        })
        .collect();

    let patterns: [(&str, FramePattern); 4] = [
        ("60 Hz", |_| Duration::from_micros(16_667)),
        ("slow 7 Hz", |_| Duration::from_millis(143)),
        ("alternating", |i| {
            Duration::from_micros(if i % 2 == 0 { 1_000 } else { 200_000 })
        }),
        ("jittery", |i| {
            Duration::from_micros(3_000 + (i as u64 * 7_919) % 90_000)
        }),
    ];
    for (name, pattern) in patterns {
        let mut app = game(Rack::FifteenBall);
        // The same path as the Space key and the panel: a ShotRequested message.
        shoot(&mut app, angle, speed);
        run_to_rest(&mut app, pattern, 100_000);
        let got = ecs_balls(&mut app);
        assert_eq!(got, expected, "frame pattern {name}");
        let status = app.world().resource::<SimStatus>();
        assert_eq!(status.shots, 1);
        assert!(status.events_this_shot > 15, "{name}: {status:?}");
    }
}

/// Runs frames until every ball rests, collecting the numbers of pocketed balls and whether a
/// finished shot was a scratch.
fn run_collecting(app: &mut App) -> (Vec<u8>, bool) {
    let mut pocketed = Vec::new();
    let mut scratch = false;
    for i in 0..5_000 {
        app.update();
        let world = app.world();
        pocketed.extend(
            world
                .resource::<Messages<BallPocketed>>()
                .iter_current_update_messages()
                .map(|m| m.number),
        );
        scratch |= world
            .resource::<Messages<ShotFinished>>()
            .iter_current_update_messages()
            .any(|m| m.scratch);
        if i > 0 && world.resource::<SimStatus>().at_rest {
            return (pocketed, scratch);
        }
    }
    panic!("balls still moving");
}

#[test]
fn a_pocketed_ball_leaves_play() {
    let mut app = game(Rack::NineBall);
    let spec = TableSpec::default();
    // Put the 1 between the cue ball and the foot-left corner, through the same component
    // edit any tool would use, then shoot it in with draw, so that the cue ball (which the
    // default spin model lets follow) does not go in after it.
    let head = spec.head_spot();
    let corner = DVec2::new(spec.length / 2.0, spec.width / 2.0);
    let line = (corner - head).normalize();
    let mut query = app.world_mut().query::<(&Ball, &mut BallMotion)>();
    for (ball, mut motion) in query.iter_mut(app.world_mut()) {
        if ball.number == 1 {
            motion.position = corner - 0.3 * line;
        }
    }
    app.update();
    let draw = TipOffset {
        side: 0.0,
        height: -0.4,
    };
    shoot_with_tip(&mut app, line.to_angle(), 4.0, draw);
    let (pocketed, scratch) = run_collecting(&mut app);
    assert_eq!(pocketed, vec![1]);
    assert!(!scratch);
    let (one, pocketed_component) = app
        .world_mut()
        .query::<(&Ball, Has<Pocketed>)>()
        .iter(app.world())
        .find(|(ball, _)| ball.number == 1)
        .map(|(ball, pocketed)| (*ball, pocketed))
        .unwrap();
    assert!(pocketed_component);
    let solver = app.world().resource::<Solver>();
    assert!(!solver.simulation().ball(one.id).motion.on_table());
}

/// The simulation alone reports a scratch and leaves the cue ball in the pocket: putting it
/// back is the rules' (every game's judgement, free play's included: `tests/practice.rs`).
#[test]
fn a_scratch_is_reported_and_left_to_the_rules() {
    let mut app = game(Rack::PaperDefault);
    let spec = TableSpec::default();
    // From the head spot straight into the foot-left corner pocket.
    let head = spec.head_spot();
    let corner = DVec2::new(spec.length / 2.0, spec.width / 2.0);
    shoot(&mut app, (corner - head).to_angle(), 3.0);
    let (pocketed, scratch) = run_collecting(&mut app);
    assert_eq!(pocketed, vec![0]);
    assert!(scratch, "no scratch reported");
    app.update();
    let solver = app.world().resource::<Solver>();
    assert!(!solver.simulation().ball(0).motion.on_table());
    assert!(app.world().resource::<SimStatus>().ball_in_hand.is_none());
}

#[test]
fn a_friction_change_reaches_the_solver() {
    let mut app = game(Rack::NineBall);
    app.world_mut().resource_mut::<PhysicsSettings>().mu_roll = 0.013;
    app.update();
    let solver = app.world().resource::<Solver>();
    assert_eq!(solver.simulation().params().model.friction().1, 0.013);
}

#[test]
fn nothing_runs_while_every_ball_rests() {
    let mut app = game(Rack::NineBall);
    let events = |app: &App| {
        app.world()
            .resource::<Solver>()
            .simulation()
            .history()
            .events()
            .len()
    };
    let before = events(&app);
    let time_before = app.world().resource::<Solver>().simulation().time();
    for _ in 0..30 {
        app.update();
    }
    assert_eq!(events(&app), before);
    assert_eq!(
        app.world().resource::<Solver>().simulation().time(),
        time_before
    );
    // No ball component was written either.
    let changed = app
        .world_mut()
        .query_filtered::<(), (With<Ball>, Changed<BallMotion>)>()
        .iter(app.world())
        .count();
    assert_eq!(changed, 0);
}

#[test]
fn a_ball_edited_through_its_component_is_placed_in_the_solver() {
    let mut app = game(Rack::PaperDefault);
    let target = DVec2::new(0.3, -0.2);
    let mut query = app.world_mut().query::<(&Ball, &mut BallMotion)>();
    for (ball, mut motion) in query.iter_mut(app.world_mut()) {
        assert_eq!(ball.id, 0);
        motion.position = target;
    }
    app.update();
    let solver = app.world().resource::<Solver>();
    let position = solver.simulation().ball(0).position;
    assert_eq!(DVec2::new(position.x, position.y), target);
}

/// Undo (practice): every ball goes back exactly where it rested before the shot, whether the
/// shot is over or still running; the undo is placements in the recording, so the game with
/// its undos replays and verifies bit for bit, also after a save and a load.
#[test]
fn an_undo_puts_every_ball_back_and_the_recording_verifies_bit_for_bit() {
    use billiards::sim::UndoRequested;
    use billiards_physics::recording::{Recording, Verdict};

    let mut app = game(Rack::FifteenBall);
    let frame = |_| Duration::from_millis(16);
    let before_break = ecs_balls(&mut app);
    shoot(&mut app, 0.0, 9.0);
    run_to_rest(&mut app, frame, 20_000);
    let after_break = ecs_balls(&mut app);
    assert_ne!(before_break, after_break, "the break moved the balls");

    let break_time = app.world().resource::<SimStatus>().sim_time;
    assert!(break_time > 1.0, "the break ran {break_time} s");

    app.world_mut().write_message(UndoRequested);
    app.update();
    assert_eq!(ecs_balls(&mut app), before_break, "undo of a finished shot");
    assert!(app.world().resource::<SimStatus>().at_rest);
    // The HUD's "simulated N s" goes back with the table: the undone break's time is gone.
    assert_eq!(
        app.world().resource::<SimStatus>().sim_time,
        0.0,
        "the simulated time of the rack, before the break"
    );

    // The break again, taken back while the balls still run.
    shoot(&mut app, 0.02, 9.0);
    for _ in 0..20 {
        app.update();
    }
    assert!(!app.world().resource::<SimStatus>().at_rest);
    let running = app.world().resource::<SimStatus>().sim_time;
    assert!(running > 0.0, "the break runs");
    app.world_mut().write_message(UndoRequested);
    app.update();
    assert_eq!(ecs_balls(&mut app), before_break, "undo of a running shot");
    assert!(app.world().resource::<SimStatus>().at_rest);
    assert_eq!(app.world().resource::<SimStatus>().sim_time, 0.0);

    // A last shot that stands, then nothing left to undo after two undos.
    shoot(&mut app, 0.01, 7.0);
    run_to_rest(&mut app, frame, 20_000);
    let solver = app.world().resource::<Solver>();
    assert_eq!(solver.undoable_shots(), 1);
    // The game's clock counts only the shot that stands; the recorder's ran through all three.
    let shown = app.world().resource::<SimStatus>().sim_time;
    assert_eq!(shown, solver.game_time());
    assert!(shown > 0.0 && shown < solver.simulation().time() - break_time + 1e-9);
    let recording = solver.recorder().recording();
    let strikes = Shots::of(&recording).len();
    assert_eq!(strikes, 3, "every strike stays in the recording");
    assert!(matches!(recording.verify(), Ok(Verdict::Reproduced { .. })));
    let path = std::env::temp_dir().join(format!("billiards-undo-{}.json", std::process::id()));
    recording.save(&path).unwrap();
    let loaded = Recording::load(&path).unwrap();
    let _ = std::fs::remove_file(&path);
    assert_eq!(loaded, recording);
    assert!(matches!(loaded.verify(), Ok(Verdict::Reproduced { .. })));
}

/// Issue 28: a fresh rack from the panel differs from the last (its own seed), so the same
/// break does not give the same result twice; the same seed racks alike; the standard rack is
/// the same every time. A free-play table change replaces the table and racks on it.
#[test]
fn fresh_racks_differ_and_another_table_is_racked_on() {
    let mut app = game(Rack::FifteenBall);
    let layout = |app: &mut App, request: RackRequested| {
        app.world_mut().write_message(request);
        app.update();
        let solver = app.world().resource::<Solver>();
        solver
            .simulation()
            .balls()
            .map(|b| b.position)
            .collect::<Vec<_>>()
    };
    let standard = layout(&mut app, RackRequested::standard(Rack::FifteenBall));
    assert_eq!(
        standard,
        layout(&mut app, RackRequested::standard(Rack::FifteenBall))
    );
    let one = layout(&mut app, RackRequested::fresh(Rack::FifteenBall, 1));
    let two = layout(&mut app, RackRequested::fresh(Rack::FifteenBall, 2));
    assert_ne!(one, two);
    assert_ne!(one, standard);
    assert_eq!(
        one,
        layout(&mut app, RackRequested::fresh(Rack::FifteenBall, 1))
    );
    // The 9-ft table from the panel: the table and the rack follow.
    let nine_ft: billiards_physics::TableChoice = "9ft".parse().unwrap();
    app.world_mut().resource_mut::<settings::TableSetup>().table = nine_ft;
    app.update();
    app.update();
    assert_eq!(*app.world().resource::<TableSpec>(), TableSpec::of(nine_ft));
    let table = *app.world().resource::<Solver>().simulation().table();
    assert_eq!(table.length, 100.0 * 0.0254);
}

/// The carom table through a scene (as a recording on it opens): the table drawn is the
/// carom one, and a hard shot straight into a corner, which a pool table would pocket, comes
/// back off both cushions of the corner (UMB Art. 11: no pockets); nothing leaves play. A
/// free-play rack on that table lays out the three-cushion opening (UMB Art. 23).
#[test]
fn the_carom_table_pockets_nothing_and_racks_three_balls() {
    let mut app = game(Rack::FifteenBall);
    let spec = TableSpec::carom();
    let settings = PhysicsSettings::default();
    let (table, params) = (table_for(&spec, &settings), params_for(&spec, &settings));
    let balls = sim::carom_layout(&table, &params.ball).unwrap();
    let white = balls[0].position;
    app.world_mut().write_message(sim::SceneRequested {
        table,
        params,
        balls,
        name: "three-cushion",
    });
    app.update();
    assert_eq!(*app.world().resource::<TableSpec>(), spec);
    assert_eq!(spec.kind, billiards::table::geometry::TableKind::Carom);
    assert_eq!(ecs_balls(&mut app).len(), 3);
    let corner = DVec2::new(spec.length / 2.0, spec.width / 2.0);
    let aim = corner - DVec2::new(white.x, white.y);
    shoot(&mut app, aim.y.atan2(aim.x), 5.0);
    let (pocketed, scratch) = run_collecting(&mut app);
    assert!(pocketed.is_empty() && !scratch, "{pocketed:?}");
    assert!(ecs_balls(&mut app).iter().all(|&(_, _, gone)| !gone));
    let sim = app.world().resource::<Solver>().simulation();
    assert_eq!(*sim.table(), billiards_physics::Table::carom_match());
    assert!(sim.balls().all(|b| b.motion.on_table()));
    let cushions: Vec<billiards_physics::Cushion> = sim
        .history()
        .events()
        .iter()
        .filter_map(|e| match e.kind {
            billiards_physics::EventKind::Cushion { ball: 0, cushion } => Some(cushion),
            _ => None,
        })
        .collect();
    for side in [
        billiards_physics::Cushion::Foot,
        billiards_physics::Cushion::Left,
    ] {
        assert!(cushions.contains(&side), "{side:?} not hit: {cushions:?}");
    }

    // A layout on the carom table (a position set on it) leaves the scene but keeps the
    // table; a free-play rack there is the three balls, not a pool rack.
    let two_balls = vec![
        billiards_physics::BallSetup::at(0, white),
        billiards_physics::BallSetup::at(2, billiards_physics::Vec2::ZERO),
    ];
    app.world_mut().write_message(sim::LayoutRequested {
        balls: two_balls,
        rack: Rack::PaperDefault,
        name: "position",
    });
    app.update();
    assert!(!app.world().resource::<Solver>().is_scene());
    assert_eq!(*app.world().resource::<TableSpec>(), spec);
    app.world_mut()
        .write_message(RackRequested::standard(Rack::NineBall));
    app.update();
    let sim = app.world().resource::<Solver>().simulation();
    assert_eq!(sim.numbers(), &[0, 1, 2]);
    assert_eq!(*sim.table(), billiards_physics::Table::carom_match());
    assert_eq!(sim.params().ball, billiards_physics::BallSpec::carom());
}
