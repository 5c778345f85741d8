//! Headless tests of the practice tools (issue 39): a drill started as the new-game dialog
//! starts it, its attempt judged from the game's own solver as the pure crate judges the same
//! shot; a position code copied off the table and opened again; the Place tool's moves,
//! refusals and undo.

mod common;

use bevy::{math::DVec2, prelude::*};
use billiards::{
    play::game,
    practice::{
        self, DrillCommand, DrillList, DrillRequested, DrillSession, EditRequested, Placing,
        PositionRequested, Practice, drill::drill_game, placing, position::Origin,
    },
    sim::{RackRequested, ShotRequested, SimStatus, Solver},
};
use billiards_physics::{EventKind, Rack, Shot, TipOffset};
use billiards_rules::{DrillShot, Position};

use common::{layout, practice_app as app, shoot_to_rest};

fn practice_state(app: &App) -> Practice {
    *app.world().resource::<State<Practice>>().get()
}

fn at_rest(app: &App) -> bool {
    app.world().resource::<Solver>().simulation().is_at_rest()
}

/// The drill session in play: the game in play behind the interface.
fn session(app: &App) -> billiards_rules::drill_game::DrillGame {
    drill_game(app.world().resource::<game::Rules>())
        .expect("a drill session is the game in play")
        .clone()
}

/// The log of the try in play (the game in play's).
fn try_log(app: &App) -> billiards_rules::StrokeLog {
    let rules = app.world().resource::<game::Rules>();
    rules.live.as_ref().unwrap().log.clone()
}

/// Starts the drill of `file` and runs the frames that set it up: the session's drill and
/// its balls (number and centre, the cue ball first), checked to be on the table.
fn start_drill(app: &mut App, file: &str) -> (billiards_rules::Drill, Vec<(u8, DVec2)>) {
    let index = drill_index(app, file);
    app.world_mut().write_message(DrillRequested { index });
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(practice_state(app), Practice::Drill, "{file}");
    let drill = session(app).drill;
    let start: Vec<(u8, DVec2)> = drill
        .position
        .balls
        .iter()
        .map(|b| (b.number, DVec2::new(b.position.x, b.position.y)))
        .collect();
    assert_eq!(
        layout(app),
        start,
        "{file}: the drill's balls, where it has them"
    );
    (drill, start)
}

fn drill_index(app: &App, file: &str) -> usize {
    let list = app.world().resource::<DrillList>();
    list.drills.iter().position(|(f, _)| f == file).unwrap()
}

/// The stop-shot drill from the dialog's request: its balls on the table, a shot straight at
/// the 1 judged when the balls rest, exactly as `Drill::judge` judges the same shot on the
/// pure solver from the same start (the game adds nothing of its own); the session is the
/// game in play behind the interface, its try's end no verdict to read but a shot refused
/// until Next try, which puts the balls back where the drill has them; leaving is free play.
#[test]
fn a_drill_attempt_is_judged_as_the_pure_solver_judges_it() {
    let mut app = app();
    let (drill, start) = start_drill(&mut app, "01-stop-shot.json");
    let params = *app.world().resource::<Solver>().simulation().params();

    let (cue, one) = (start[0].1, start[1].1);
    let shot = Shot {
        angle: (one - cue).to_angle(),
        speed: 2.0,
        tip: TipOffset {
            side: 0.0,
            height: -0.3,
        },
        elevation: 0.0,
    };
    app.world_mut().write_message(ShotRequested::from(shot));
    app.update();
    common::update_until(&mut app, |app| at_rest(app) && session(app).try_over());
    app.update();
    let game = session(&app);
    let judged = game.last.clone().unwrap();
    assert_eq!(game.score.tries, 1);
    assert_eq!(judged.reasons.len(), drill.goals.len(), "{judged:?}");
    assert_eq!(
        *app.world().resource::<State<game::Turn>>().get(),
        game::Turn::GameOver,
        "the try is over"
    );
    let refused = app
        .world()
        .resource::<billiards::sim::Referee>()
        .refuse_shot
        .clone();
    assert_eq!(refused.as_deref(), Some("the try is over: Next try"));
    // Judged through the one interface and logged as any game's stroke: the try's end.
    let log = try_log(&app);
    assert_eq!(log.strokes.len(), 1);
    let end = log.strokes[0].judgement.end.clone().expect("the try ended");
    assert!(end.reason.starts_with("try 1 "), "{}", end.reason);

    // The same shot on the pure solver, from the drill's own start.
    let mut sim = drill.simulation(params).unwrap();
    let from = sim.history().events().len();
    sim.strike(0, shot).unwrap();
    sim.run_to_rest().unwrap();
    let expected = drill.judge(&[DrillShot::of(&sim, from)]);
    assert_eq!(judged, expected);
    // And the game's events after its strike are the pure solver's, bit for bit.
    let game_sim = app.world().resource::<Solver>().simulation();
    let game_events = game_sim.history().events();
    let strike = game_events
        .iter()
        .rposition(|e| matches!(e.kind, EventKind::Strike { .. }))
        .unwrap();
    assert_eq!(&game_events[strike..], &sim.history().events()[from..]);

    // A second shot before Next try is no attempt.
    app.world_mut().write_message(DrillCommand::NextTry);
    for _ in 0..3 {
        app.update();
    }
    let game = session(&app);
    assert!(!game.try_over());
    assert_eq!(game.score.tries, 1);
    assert_eq!(game.try_text(), "try 2 of 10");
    assert!(
        try_log(&app).strokes.is_empty(),
        "a new try, a new recording and log"
    );
    assert_eq!(layout(&app), start, "Next try: the drill's position again");
    assert_eq!(
        *app.world().resource::<State<game::Turn>>().get(),
        game::Turn::Aiming
    );

    app.world_mut().write_message(DrillCommand::Leave);
    for _ in 0..2 {
        app.update();
    }
    assert_eq!(practice_state(&app), Practice::Off);
    assert!(app.world().get_resource::<DrillSession>().is_none());
    let rules = app.world().resource::<game::Rules>();
    let free = rules.live.as_ref().filter(|g| g.rules.sandbox());
    let free = free.expect("left for free play");
    // Free play takes stock of the table the drill left: its one object ball.
    assert_eq!(free.rules.status(), vec!["balls left: 1".to_owned()]);
}

/// The table as a code and back: a standard rack, broken and at rest, copied (balls only,
/// as the panel's Copy makes it), re-racked and opened again puts every ball where the code
/// has it, bit for bit (the code keeps every centre's f64).
#[test]
fn a_copied_position_opens_where_it_was() {
    let mut app = app();
    shoot_to_rest(&mut app, 0.0, 6.0);
    let before = layout(&app);
    let code = {
        let rules = app.world().resource::<game::Rules>();
        let solver = app.world().resource::<Solver>();
        practice::position::current_position(solver, rules, false, None)
            .unwrap()
            .encode()
            .unwrap()
    };
    app.world_mut()
        .write_message(RackRequested::standard(Rack::NineBall));
    app.update();
    assert_ne!(layout(&app).len(), before.len(), "the 9-ball rack is on");
    let position = Position::decode(&code).unwrap();
    app.world_mut().write_message(PositionRequested {
        position: position.clone(),
        origin: Origin::Pasted,
        own_physics: true,
    });
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(layout(&app), before);
    let note = app.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.starts_with("position pasted:"), "{note}");
}

/// The Place tool: a ball dropped 1 cm from a free spot goes on it, onto another ball is
/// refused (the ball stays, the note says why), and undo puts it back.
#[test]
fn a_placed_ball_snaps_is_refused_on_a_ball_and_undoes() {
    let mut app = app();
    app.world_mut()
        .resource_mut::<NextState<Practice>>()
        .set(Practice::Placing);
    app.update();
    assert_eq!(practice_state(&app), Practice::Placing);
    let before = layout(&app);
    let spec = app
        .world()
        .resource::<billiards::table::geometry::TableSpec>()
        .clone();
    // The cue ball to 1 cm from the head spot (the rack sits on the foot spot).
    let head = placing::spots(&spec)
        .into_iter()
        .find(|s| before.iter().all(|(_, p)| p.distance(*s) > 0.1))
        .unwrap();
    let edit = |app: &mut App, e: EditRequested| {
        app.world_mut().write_message(e);
        for _ in 0..2 {
            app.update();
        }
    };
    edit(
        &mut app,
        EditRequested::Move {
            number: 0,
            to: head + DVec2::new(0.01, 0.0),
            free: false,
        },
    );
    let cue = |app: &App| layout(app)[0].1;
    assert_eq!(cue(&app), head, "snapped onto the spot");
    let on_the_one = before.iter().find(|b| b.0 == 1).unwrap().1;
    edit(
        &mut app,
        EditRequested::Move {
            number: 0,
            to: on_the_one + DVec2::new(0.02, 0.0),
            free: false,
        },
    );
    assert_eq!(cue(&app), head, "not onto the 1");
    let note = app.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.ends_with("on the 1 ball"), "{note}");
    edit(&mut app, EditRequested::Undo);
    assert_eq!(layout(&app), before, "undone");
    assert!(app.world().resource::<Placing>().undo.is_empty());
}

/// Issue 47: each refusal of the Place tool says why and leaves the ball where it was: off
/// the cloth, over a pocket's hole; Shift (a free move) puts a ball 1 cm from a spot
/// exactly there, not on the spot; Clear leaves the cue ball alone and Undo brings every
/// ball back.
#[test]
fn placing_refuses_off_the_cloth_and_over_a_hole_places_freely_and_clears() {
    let mut app = app();
    app.world_mut()
        .resource_mut::<NextState<Practice>>()
        .set(Practice::Placing);
    app.update();
    let before = layout(&app);
    let spec = app
        .world()
        .resource::<billiards::table::geometry::TableSpec>()
        .clone();
    let edit = |app: &mut App, e: EditRequested| {
        app.world_mut().write_message(e);
        for _ in 0..3 {
            app.update();
        }
        app.world().resource::<SimStatus>().note.clone().unwrap()
    };
    let cue = |app: &App| layout(app)[0].1;
    let start = cue(&app);
    let h = spec.half_extents();
    let note = edit(
        &mut app,
        EditRequested::Move {
            number: 0,
            to: DVec2::new(0.0, h.y + 0.05),
            free: true,
        },
    );
    assert_eq!(note, "the cue ball cannot go there: off the cloth");
    assert_eq!(cue(&app), start);
    let hole = spec
        .pocket(billiards_physics::Pocket::HeadLeft)
        .unwrap()
        .centre;
    let note = edit(
        &mut app,
        EditRequested::Move {
            number: 0,
            to: hole,
            free: true,
        },
    );
    // The hole's centre lies beyond the cloth's edge: either refusal keeps the ball.
    assert!(note.starts_with("the cue ball cannot go there: "), "{note}");
    assert_eq!(cue(&app), start);
    let head = spec.head_spot();
    let near = head + DVec2::new(0.01, 0.0);
    edit(
        &mut app,
        EditRequested::Move {
            number: 0,
            to: near,
            free: true,
        },
    );
    assert_eq!(
        cue(&app),
        near,
        "Shift: exactly where dropped, not on the spot"
    );
    let note = edit(&mut app, EditRequested::Clear);
    assert_eq!(note, "table cleared: the cue ball alone");
    assert_eq!(layout(&app), vec![(0, near)]);
    edit(&mut app, EditRequested::Undo);
    edit(&mut app, EditRequested::Undo);
    assert_eq!(layout(&app), before, "both edits undone");
}

/// A ball centred over a side pocket's hole but on the cloth's line is refused by name.
#[test]
fn a_ball_over_a_side_hole_is_refused_by_name() {
    let app = app();
    let spec = app
        .world()
        .resource::<billiards::table::geometry::TableSpec>()
        .clone();
    let sim = app.world().resource::<Solver>().simulation();
    let side = spec.pocket(billiards_physics::Pocket::SideLeft).unwrap();
    // Inward from the hole's centre, still within its radius.
    let inward = DVec2::new(0.0, -side.centre.y.signum());
    let p = side.centre + inward * 0.9 * side.radius;
    let why = placing::spot_error(sim, &spec, 5, p).unwrap_err();
    assert!(
        why == "over the left side pocket" || why == "off the cloth",
        "{why}"
    );
}

/// Every standard drill starts from the dialog's request, plays a shot at its first named
/// ball and is judged: one try counted, a score of 0 to 100 and a reason for every goal.
#[test]
fn each_standard_drill_loads_plays_and_scores() {
    let mut app = app();
    let files: Vec<String> = app
        .world()
        .resource::<DrillList>()
        .drills
        .iter()
        .filter(|(f, _)| !f.starts_with(practice::drill::USER_PREFIX))
        .map(|(f, _)| f.clone())
        .collect();
    assert_eq!(files.len(), 11, "{files:?}");
    for file in files {
        let (drill, start) = start_drill(&mut app, &file);
        let cue = start[0].1;
        let target = drill.object_balls()[0];
        let at = start.iter().find(|b| b.0 == target).unwrap().1;
        app.world_mut().write_message(ShotRequested::from(Shot {
            angle: (at - cue).to_angle(),
            speed: 2.5,
            tip: TipOffset::default(),
            elevation: 0.0,
        }));
        app.update();
        // A multi-shot drill goes on while its visit does: shoot again at the lowest ball.
        let mut shots = 1;
        loop {
            common::update_until(&mut app, |app| at_rest(app));
            app.update();
            if session(&app).try_over() {
                break;
            }
            shots += 1;
            assert!(shots <= 15, "{file}: the attempt never ended");
            let now = layout(&app);
            let (Some(&(_, cue)), Some(&(_, ball))) =
                (now.iter().find(|b| b.0 == 0), now.iter().find(|b| b.0 != 0))
            else {
                panic!("{file}: the attempt went on with no ball to shoot at");
            };
            app.world_mut().write_message(ShotRequested::from(Shot {
                angle: (ball - cue).to_angle(),
                speed: 2.5,
                tip: TipOffset::default(),
                elevation: 0.0,
            }));
            app.update();
        }
        let game = session(&app);
        let last = game.last.clone().unwrap();
        assert_eq!(game.score.tries, 1, "{file}");
        assert!((0.0..=100.0).contains(&last.score), "{file}: {last:?}");
        assert_eq!(last.reasons.len(), drill.goals.len(), "{file}: {last:?}");
        app.world_mut().write_message(DrillCommand::Leave);
        for _ in 0..2 {
            app.update();
        }
        assert_eq!(practice_state(&app), Practice::Off, "{file}");
    }
}

/// "Save as drill" writes the table, its physics and the shot with the chosen goal into the
/// player's drills folder; the list shows it at once and it plays like a standard drill.
#[test]
fn a_table_saved_as_a_drill_is_listed_and_plays() {
    let mut app = app();
    let folder = std::env::temp_dir().join(format!("billiards-drills-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    app.world_mut().resource_mut::<DrillList>().user_folder = Some(folder.clone());
    let goals = vec![
        billiards_rules::Goal::Pocket {
            ball: 3,
            pocket: Some(billiards_physics::Pocket::FootRight),
            cushions: 0,
        },
        billiards_rules::Goal::NoFoul,
    ];
    app.world_mut().write_message(practice::SaveDrillRequested {
        name: "My rack, 3 in the corner".into(),
        goals: goals.clone(),
        tries: 5,
    });
    for _ in 0..2 {
        app.update();
    }
    let note = app.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.starts_with("drill saved as "), "{note}");
    let path = folder.join("my-rack-3-in-the-corner.json");
    let saved = billiards_rules::Drill::load(&path).unwrap();
    assert_eq!(saved.goals, goals);
    assert_eq!(saved.tries, 5);
    let mut on_table: Vec<(u8, DVec2)> = saved
        .position
        .balls
        .iter()
        .map(|b| (b.number, DVec2::new(b.position.x, b.position.y)))
        .collect();
    on_table.sort_by_key(|b| b.0);
    assert_eq!(on_table, layout(&app), "the table as it stood");
    let key = "user/my-rack-3-in-the-corner.json";
    let index = drill_index(&app, key);
    app.world_mut().resource_mut::<SimStatus>().note = None;
    app.world_mut().write_message(DrillRequested { index });
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(practice_state(&app), Practice::Drill);
    assert_eq!(app.world().resource::<DrillSession>().file, key);
    // No name: refused, said so, nothing written.
    app.world_mut().write_message(DrillCommand::Leave);
    app.world_mut().write_message(practice::SaveDrillRequested {
        name: "  ".into(),
        goals,
        tries: 5,
    });
    for _ in 0..2 {
        app.update();
    }
    let note = app.world().resource::<SimStatus>().note.clone().unwrap();
    assert_eq!(note, "drill not saved: give the drill a name");
    assert_eq!(std::fs::read_dir(&folder).unwrap().count(), 1);
    let _ = std::fs::remove_dir_all(&folder);
}

/// Copy and Open through the panel's own commands: without a display the clipboard says it
/// is unavailable and the code still goes into the code field; Open sets that position up
/// after a new rack, every ball where it was; a damaged code is refused with its reason and
/// the table stays as it is.
#[test]
fn copy_and_open_through_the_panel_commands() {
    use billiards::practice::{PositionCode, PositionCommand};
    let mut app = app();
    shoot_to_rest(&mut app, 0.02, 5.0);
    let before = layout(&app);
    app.world_mut().write_message(PositionCommand::Copy {
        with_params: true,
        with_shot: true,
    });
    app.update();
    let code = app.world().resource::<PositionCode>().0.clone();
    assert_eq!(
        Position::decode(&code).unwrap().balls.len(),
        before.len(),
        "the code field holds the table"
    );
    app.world_mut()
        .write_message(RackRequested::standard(Rack::NineBall));
    app.update();
    assert_ne!(layout(&app), before);
    app.world_mut()
        .write_message(PositionCommand::Open { own_physics: true });
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(layout(&app), before, "opened where it was copied");
    // One character changed: refused by its checksum, the table unchanged.
    let mut damaged = code.clone().into_bytes();
    let k = damaged.len() / 2;
    damaged[k] = if damaged[k] == b'A' { b'B' } else { b'A' };
    app.world_mut().resource_mut::<PositionCode>().0 = String::from_utf8(damaged).unwrap();
    app.world_mut()
        .write_message(PositionCommand::Open { own_physics: true });
    for _ in 0..3 {
        app.update();
    }
    let note = app.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.starts_with("not a position: "), "{note}");
    assert_eq!(layout(&app), before, "a refused code changes nothing");
}
