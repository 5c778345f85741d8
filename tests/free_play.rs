//! Free play behind the one game interface (issue 50): the sandbox game, its table the
//! player's, its strokes judged and logged like any game's.

mod common;

use bevy::{math::DVec2, prelude::*};
use billiards::{
    practice::{EditRequested, Practice},
    sim::{RackRequested, SimStatus, Solver},
};
use billiards_physics::Rack;

use common::{layout, practice_app as app, shoot_to_rest};

/// Issue 50: free play is a game behind the one interface, the sandbox. Its table is the
/// player's (a ball moved by hand, a shot taken back); a scratch is judged and the rules put
/// the cue ball back on the head string with no verdict to read; each stroke is logged beside
/// its recording and re-judges; a rack from the panel starts a new recording and a new log.
#[test]
fn free_play_is_the_sandbox_behind_the_interface() {
    use billiards::{
        play::game::{Rules, Turn},
        recording::{Autosave, RecordingsFolder},
        sim::{HandRule, Referee, UndoRequested},
        table::geometry::TableSpec,
    };
    use billiards_physics::recording::Recording;
    let folder = std::env::temp_dir().join(format!("billiards-free-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = app();
    app.insert_resource(RecordingsFolder(Some(folder.clone())));
    let sandbox = |app: &App| {
        let rules = app.world().resource::<Rules>();
        !rules.in_match() && rules.live.as_ref().is_some_and(|g| g.rules.sandbox())
    };
    assert!(sandbox(&app), "free play at launch is the sandbox game");
    assert!(app.world().resource::<Referee>().edits);
    // The cue ball moved by hand 0.4 m in from the foot-right corner on its diagonal.
    let spec = app.world().resource::<TableSpec>().clone();
    let corner = spec.half_extents();
    let from = corner - DVec2::splat(0.4 / 2f64.sqrt());
    app.world_mut()
        .resource_mut::<NextState<Practice>>()
        .set(Practice::Placing);
    app.update();
    app.world_mut().write_message(EditRequested::Move {
        number: 0,
        to: from,
        free: true,
    });
    app.update();
    app.update();
    assert_eq!(layout(&app)[0].1, from, "the cue ball placed by hand");
    let before = layout(&app);
    // Straight into the corner: a scratch.
    shoot_to_rest(&mut app, std::f64::consts::FRAC_PI_4, 1.5);
    for _ in 0..3 {
        app.update();
    }
    let turn = *app.world().resource::<State<Turn>>().get();
    assert_eq!(turn, Turn::Aiming, "free play's strokes need no reading");
    let cue = layout(&app)[0];
    assert_eq!(cue.0, 0);
    assert!(
        (cue.1.x - spec.head_spot().x).abs() < 1e-9,
        "the rules put the cue ball on the head string: {cue:?}"
    );
    let status = app.world().resource::<SimStatus>().clone();
    let note = status.note.unwrap_or_default();
    assert!(
        note.contains("the cue ball is on the head string"),
        "{note}"
    );
    let last = app
        .world()
        .resource::<Rules>()
        .live
        .as_ref()
        .unwrap()
        .last
        .clone();
    let said = last.map(|j| j.text).unwrap_or_default();
    assert!(
        said.contains("scratch: the cue ball is back on the head string"),
        "{said}"
    );
    assert_eq!(status.ball_in_hand, Some(HandRule::Respot), "it may slide");
    // Slid along the head string; beyond the side cushion it is held at the cushion. The
    // solver and the recording get the placement.
    for (wanted_y, expected_y) in [(0.2, 0.2), (5.0, spec.width / 2.0 - spec.ball_radius)] {
        let mut query = app.world_mut().query::<(
            &billiards::table::balls::Ball,
            &mut billiards::table::balls::BallMotion,
        )>();
        let (_, mut motion) = query
            .iter_mut(app.world_mut())
            .find(|(ball, _)| ball.number == 0)
            .unwrap();
        billiards::sim::move_ball_in_hand(&spec, &mut motion, wanted_y);
        app.update();
        let cue = app.world().resource::<Solver>().simulation().ball(0);
        assert_eq!(
            (cue.position.x, cue.position.y),
            (spec.head_spot().x, expected_y)
        );
    }
    let placed = &app
        .world()
        .resource::<Solver>()
        .recorder()
        .recording()
        .inputs;
    assert!(matches!(
        placed.last().unwrap().action,
        billiards_physics::recording::Action::Place { .. }
    ));
    let first = app.world().resource::<Autosave>().file.clone().unwrap();
    let log = |file: &std::path::Path| match billiards_rules::RulesLog::beside(file) {
        Some((_, Ok(billiards_rules::RulesLog::Strokes(log)))) => log,
        other => panic!("no stroke log beside {file:?}: {other:?}"),
    };
    assert_eq!(log(&first).check(&Recording::load(&first).unwrap()), Ok(1));
    // A shot taken back: allowed in the sandbox, the table as it was.
    app.world_mut().write_message(UndoRequested);
    app.update();
    app.update();
    assert_eq!(layout(&app), before, "the shot undone");
    // A rack from the panel: a new recording, judged and logged on its own.
    app.world_mut()
        .write_message(RackRequested::standard(Rack::NineBall));
    app.update();
    app.update();
    shoot_to_rest(&mut app, 0.0, 5.0);
    for _ in 0..3 {
        app.update();
    }
    assert!(sandbox(&app));
    let second = app.world().resource::<Autosave>().file.clone().unwrap();
    assert_ne!(first, second, "a new rack is a new recording");
    let log2 = log(&second);
    assert_eq!(log2.check(&Recording::load(&second).unwrap()), Ok(1));
    assert_eq!(
        log(&first).strokes.len(),
        1,
        "the first log kept its stroke"
    );
    let _ = std::fs::remove_dir_all(&folder);
}
