//! Headless snooker through the game's states (issue 26): the 12-ft table and its balls, the
//! cue ball in hand in the D (WPBSA 3.4), a foul and a miss with the balls replaced (3.14),
//! scores that add up to the verdicts.

mod common;

use std::path::Path;

use bevy::{math::DVec2, prelude::*};
use billiards::{
    play::game::{self, GameChoice, LiveGame, NewGameRequested, Rules, Turn, TurnCommand},
    recording::RecordingsFolder,
    replay::OpenRecording,
    sim::{HandError, HandRule, ShotRequested, SimStatus, Solver},
    table::geometry::TableSpec,
};
use billiards_physics::recording::Recording;
use billiards_physics::snooker::{BLUE, PINK, SNOOKER_BALL_DIAMETER, YELLOW};
use billiards_rules::snooker::FrameLog;
use billiards_rules::snooker::rules::SnookerGame;
use billiards_rules::{RulesLog, Seat};

/// A fresh folder of this test's own for the recordings.
fn folder(test: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-snooker-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn start(folder: &Path) -> App {
    let mut app = common::headless(game::plugin);
    app.insert_resource(RecordingsFolder(Some(folder.to_path_buf())));
    app.update();
    app.world_mut().write_message(NewGameRequested {
        game: GameChoice::Catalog("snooker"),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        // Best of 3 frames (WPBSA 2.1).
        race_to: 3,
        seed: 11,
        computer: [None, None],
        setup: Default::default(),
    });
    for _ in 0..3 {
        app.update();
    }
    app
}

fn turn(app: &App) -> Turn {
    *app.world().resource::<State<Turn>>().get()
}

/// The match behind the interface, as the game holds it.
fn live(app: &App) -> &LiveGame {
    app.world().resource::<Rules>().live.as_ref().unwrap()
}

/// The snooker match itself, for what only snooker has (frames, scores).
fn snooker(app: &App) -> &SnookerGame {
    live(app)
        .rules
        .as_any()
        .downcast_ref::<SnookerGame>()
        .expect("a snooker match")
}

/// Takes the offered option whose words start with `words`.
fn choose(app: &mut App, words: &str) {
    let choices = live(app).rules.turn().choices;
    let index = choices
        .iter()
        .position(|c| c.starts_with(words))
        .unwrap_or_else(|| panic!("{words:?} not among {choices:?}"));
    app.world_mut()
        .write_message(TurnCommand::ChooseOption(index));
    for _ in 0..3 {
        app.update();
    }
}

fn balls(app: &App) -> Vec<(u8, DVec2)> {
    let sim = app.world().resource::<Solver>().simulation();
    sim.balls()
        .zip(sim.numbers())
        .filter(|(s, _)| s.motion.on_table())
        .map(|(s, &n)| (n, DVec2::new(s.position.x, s.position.y)))
        .collect()
}

fn position(app: &App, n: u8) -> DVec2 {
    balls(app).into_iter().find(|b| b.0 == n).unwrap().1
}

use common::place;

fn shoot(app: &mut App, angle: f64, speed: f64) {
    app.world_mut().write_message(ShotRequested {
        angle,
        speed,
        tip: Default::default(),
        elevation: 0.0,
    });
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(turn(app), Turn::ShotInPlay, "the stroke was not taken");
    for _ in 0..5000 {
        app.update();
        if app.world().resource::<SimStatus>().at_rest {
            app.update();
            return;
        }
    }
    panic!("balls still moving");
}

/// The frame starts on the 12-ft table with 52.5 mm balls (WPBSA 1.1, 1.2), the 22 balls
/// (3.2), the cue ball in hand: it goes anywhere in the D and nowhere else (3.4).
#[test]
fn a_frame_starts_on_the_snooker_table_with_the_cue_ball_in_the_d() {
    let dir = folder("start");
    let mut app = start(&dir);
    let spec = app.world().resource::<TableSpec>();
    assert!(spec.is_snooker());
    assert_eq!(spec.length, 3.569);
    let sim = app.world().resource::<Solver>().simulation();
    assert_eq!(sim.params().ball.radius, SNOOKER_BALL_DIAMETER / 2.0);
    assert_eq!(sim.table().length, 3.569);
    assert_eq!(balls(&app).len(), 22);
    assert_eq!(turn(&app), Turn::BallInHand);
    assert_eq!(
        app.world().resource::<SimStatus>().ball_in_hand,
        Some(HandRule::InD)
    );
    // The baulk-line is 737 mm from the bottom cushion; the D's radius is 292 mm.
    let baulk = -3.569 / 2.0 + 0.737;
    assert_eq!(
        place(&mut app, DVec2::new(baulk + 0.05, 0.1)),
        Err(HandError::OutsideD),
        "in front of the baulk-line"
    );
    assert_eq!(
        place(&mut app, DVec2::new(baulk - 0.25, 0.2)),
        Err(HandError::OutsideD),
        "behind the line but outside the half circle"
    );
    let inside = DVec2::new(baulk - 0.2, 0.1);
    place(&mut app, inside).unwrap();
    assert_eq!(position(&app, 0), inside);
}

/// 3.14: a foul that is a miss (the pink hit first, a red on, a clear view of the reds)
/// gives 6 points (3.10: the value of the ball hit, at least 4) and the opponent may have the
/// balls replaced: every ball goes back exactly where it was and the offender plays again.
#[test]
fn a_miss_on_the_break_is_replaced_exactly() {
    let dir = folder("replace");
    let mut app = start(&dir);
    let before = balls(&app);
    let cue = position(&app, 0);
    let pink = position(&app, PINK);
    shoot(&mut app, (pink - cue).to_angle(), 2.0);
    let verdict = live(&app).last.clone().unwrap();
    assert!(!verdict.fair, "{}", verdict.text);
    assert!(verdict.text.contains("miss"), "{}", verdict.text);
    assert_eq!(snooker(&app).frame.scores, [0, 6], "{}", verdict.text);
    let next = live(&app).rules.turn();
    assert_eq!(next.striker, Seat::B);
    assert_eq!(turn(&app), Turn::Verdict);
    choose(&mut app, "replace the balls");
    let mut after = balls(&app);
    let mut expected = before.clone();
    after.sort_by_key(|b| b.0);
    expected.sort_by_key(|b| b.0);
    assert_eq!(after, expected, "every ball back where it was");
    assert_eq!(
        live(&app).rules.turn().striker,
        Seat::A,
        "the offender plays again"
    );
    assert_eq!(snooker(&app).frame.scores, [0, 6], "the penalty stands");
    assert_eq!(turn(&app), Turn::BallInHand);
    // The offender plays again, softly at the blue this time (another foul, 5).
    let cue = position(&app, 0);
    let blue = position(&app, BLUE);
    shoot(&mut app, (blue - cue).to_angle(), 1.0);
    assert_eq!(snooker(&app).frame.scores, [0, 11]);
    // The recording and its frame log re-judge alike: the replace, the spots, the D.
    let file = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            name.ends_with("_snooker.json")
        })
        .expect("the frame's recording");
    let recording = Recording::load(&file).unwrap();
    // Saved under the one name every game's log has, as any game's log.
    let log_file = FrameLog::path_beside(&file);
    assert!(log_file.to_string_lossy().ends_with("_snooker.game.json"));
    let text = std::fs::read_to_string(&log_file).unwrap();
    let RulesLog::Strokes(log) = RulesLog::from_json(&text).unwrap() else {
        panic!("not the interface's log: {text}")
    };
    assert_eq!(log.strokes.len(), 2);
    assert_eq!(log.strokes[1].choices.len(), 1, "the replace");
    assert_eq!(log.check(&recording), Ok(2));
    // The replay viewer reads the frame's log: each stroke's verdict under the timeline, the
    // verdicts re-judged, and the balls named by colour.
    let open = OpenRecording::new(&file, recording).unwrap();
    assert_eq!(open.check_verdicts(), Some(Ok(2)));
    let first = open.shots.span(1).unwrap();
    let line = open.game_line(first.0 + 1e-3).unwrap();
    assert!(line.starts_with("stroke 1, Ann: foul and a miss"), "{line}");
    let hit = open
        .events()
        .iter()
        .find(|e| matches!(e.kind, billiards_physics::EventKind::BallBall { .. }))
        .unwrap();
    assert_eq!(open.describe(hit), "cue ball hit pink");
    // A frame saved by an older build, its log as `NAME.snooker.json`: the viewer still
    // reads it.
    std::fs::rename(&log_file, FrameLog::old_path_beside(&file)).unwrap();
    let old = OpenRecording::new(&file, Recording::load(&file).unwrap()).unwrap();
    assert_eq!(old.check_verdicts(), Some(Ok(2)));
}

/// A fair stroke that pots nothing passes the turn; a stroke that hits nothing is a foul of
/// 4 (3.10); every verdict's scores are the frame's and add up to the points and penalties.
#[test]
fn scores_add_up_to_the_verdicts() {
    let dir = folder("scores");
    let mut app = start(&dir);
    // Straight up the table at the reds' far corner: a red first.
    let cue = position(&app, 0);
    let red = balls(&app)
        .into_iter()
        .filter(|b| (1..=15).contains(&b.0))
        .max_by(|a, b| (a.1.x - a.1.y).total_cmp(&(b.1.x - b.1.y)))
        .unwrap()
        .1;
    shoot(&mut app, (red - cue).to_angle(), 3.0);
    let v = live(&app).last.clone().unwrap();
    let scores = snooker(&app).frame.scores;
    if v.fair {
        // A fair stroke scores for the striker only.
        assert_eq!(scores[v.striker.other().index()], 0, "{}", v.text);
    } else {
        assert_eq!(scores[v.striker.index()], 0, "{}", v.text);
        assert!(scores[v.striker.other().index()] >= 4, "{}", v.text);
    }
    let expected = scores;
    // The next striker rolls the cue ball softly away from every ball: no ball hit.
    app.world_mut().write_message(TurnCommand::Continue);
    for _ in 0..3 {
        app.update();
    }
    if !live(&app).rules.turn().choices.is_empty() {
        choose(&mut app, "play on");
    }
    let cue = position(&app, 0);
    let nearest = balls(&app)
        .into_iter()
        .filter(|b| b.0 != 0)
        .min_by(|a, b| a.1.distance(cue).total_cmp(&b.1.distance(cue)))
        .unwrap()
        .1;
    shoot(&mut app, (cue - nearest).to_angle(), 0.05);
    let v = live(&app).last.clone().unwrap();
    assert!(!v.fair, "{}", v.text);
    // 3.10: no ball hit, at least 4 to the opponent and nothing to the striker.
    let scores = snooker(&app).frame.scores;
    assert_eq!(scores[v.striker.index()], expected[v.striker.index()]);
    let gained = scores[v.striker.other().index()] - expected[v.striker.other().index()];
    assert!((4..=7).contains(&gained), "{gained}: {}", v.text);
    // The colours still stand on their spots.
    let blue = position(&app, BLUE);
    assert_eq!(blue, DVec2::ZERO);
    assert!(balls(&app).iter().any(|b| b.0 == YELLOW));
}

/// 2.1(a): the striker concedes; the frame goes to the opponent and counts in the match (best
/// of 3 here); the next frame is laid out afresh with the other player breaking off; the
/// match ends when one player has two frames.
#[test]
fn conceded_frames_decide_a_best_of_three() {
    let dir = folder("concede");
    let mut app = start(&dir);
    let command = |app: &mut App, c: TurnCommand| {
        app.world_mut().write_message(c);
        for _ in 0..3 {
            app.update();
        }
    };
    assert_eq!(snooker(&app).frames.best_of, 3);
    assert_eq!(live(&app).rules.turn().striker, Seat::A);
    command(&mut app, TurnCommand::Concede);
    assert_eq!(turn(&app), Turn::GameOver);
    let game = snooker(&app);
    assert_eq!(game.frame.winner(), Some(Seat::B));
    assert_eq!(game.frames.frames, [0, 1]);
    assert_eq!(game.frames.winner(), None);
    // Frame 2: a fresh table, B breaks off from the D (2.1: the break-off alternates).
    command(&mut app, TurnCommand::NextRack);
    assert_eq!(turn(&app), Turn::BallInHand);
    assert_eq!(balls(&app).len(), 22);
    let game = snooker(&app);
    assert_eq!(game.frame.scores, [0, 0]);
    assert_eq!(live(&app).rules.turn().striker, Seat::B);
    assert!(live(&app).log.strokes.is_empty());
    command(&mut app, TurnCommand::Concede);
    let game = snooker(&app);
    assert_eq!(game.frames.frames, [1, 1]);
    command(&mut app, TurnCommand::NextRack);
    assert_eq!(live(&app).rules.turn().striker, Seat::A);
    command(&mut app, TurnCommand::Concede);
    let game = snooker(&app);
    assert_eq!(game.frames.frames, [1, 2]);
    assert_eq!(game.frames.winner(), Some(Seat::B));
    // The match is over: no further frame.
    command(&mut app, TurnCommand::NextRack);
    assert_eq!(turn(&app), Turn::GameOver);
    assert_eq!(snooker(&app).frames.frames, [1, 2]);
}
