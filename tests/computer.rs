//! The computer at the table, headless (issue 16): two computer seats play a rack of 9-ball
//! to its end through the game's states; the recording of that rack verifies bit for bit and
//! its rules log re-judges alike, as a human's game does.

mod common;

use std::{path::Path, time::Duration};

use bevy::prelude::*;
use billiards::{
    input::AimLocked,
    play::computer::{self, Computer, ComputerPace, Hint, HintRequested},
    play::game::{self, NewGameRequested, Rules, Turn},
    recording::{Autosave, RecordingsFolder},
    settings::ShotSettings,
    view::camera::OrbitCamera,
};
use billiards_ai::Level;
use billiards_physics::recording::{Recording, Verdict};
use billiards_rules::{Game, RulesLog, pool::PoolMatch};

fn start(folder: &Path, game: Game) -> App {
    let mut app = common::headless((game::plugin, computer::plugin));
    app.insert_resource(RecordingsFolder(Some(folder.to_path_buf())));
    // A short pace, not zero: what is shown must survive the frames it is shown for.
    app.insert_resource(ComputerPace(Duration::from_millis(20)));
    app.update();
    app.world_mut().write_message(NewGameRequested {
        game: game.into(),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        race_to: 1,
        seed: 11,
        computer: [Some(Level::Easy), Some(Level::Easy)],
        setup: Default::default(),
    });
    app.update();
    app.update();
    app
}

fn turn(app: &App) -> Turn {
    *app.world().resource::<State<Turn>>().get()
}

/// The match in play.
fn live(app: &App) -> &game::LiveGame {
    app.world().resource::<Rules>().live.as_ref().unwrap()
}

/// The pool match behind the interface.
fn pool(app: &App) -> &PoolMatch {
    live(app)
        .rules
        .as_any()
        .downcast_ref::<PoolMatch>()
        .unwrap()
}

#[test]
fn two_computers_play_a_rack_of_nine_ball_to_its_end() {
    play_a_rack_between_computers(Game::NineBall, "nine");
}

/// Issue 50: 10-ball (WPA section 9, every shot after the break called) is played to its end
/// between two computers in the game, as 9-ball is; its log re-judges the rack.
#[test]
fn two_computers_play_a_rack_of_ten_ball_to_its_end() {
    play_a_rack_between_computers(Game::TenBall, "ten");
}

/// Two easy computers play a rack of `game` to its end through the game's states; the rack's
/// recording verifies and its log re-judges every shot.
fn play_a_rack_between_computers(game: Game, tag: &str) {
    let folder =
        std::env::temp_dir().join(format!("billiards-computer-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, game);
    // Bounded by what was asked, not by the clock: a rack between two computers
    // ends within this many shots (each shot is a decision thread waited for to its end).
    const MAX_SHOTS: usize = 300;
    while turn(&app) != Turn::GameOver {
        let shots = live(&app).log.strokes.len();
        assert!(
            shots <= MAX_SHOTS,
            "the rack did not end: {:?} after {shots} shots",
            turn(&app),
        );
        app.update();
        // Both seats are the computer's: the pointer never aims for it, and the HUD gives
        // no instructions meant for a human at the mouse.
        if matches!(turn(&app), Turn::Aiming | Turn::BallInHand) {
            assert_eq!(*app.world().resource::<AimLocked>(), AimLocked(true));
            let line = &live(&app).hud_lines(turn(&app), &[])[1];
            assert!(line.contains("(computer, easy) to "), "{line}");
            assert!(!line.contains("aim and shoot"), "{line}");
        }
    }
    let game = live(&app);
    let (winner, reason) = pool(&app).rack().over.unwrap();
    let shots = game.log.strokes.len();
    println!("{} won in {shots} shots: {reason}", game.name(winner));
    assert!(shots >= 1);
    // The computer's shots went through the recording like a human's.
    let file = app.world().resource::<Autosave>().file.clone().unwrap();
    let recorded = Recording::load(&file).unwrap();
    assert!(matches!(recorded.verify(), Ok(Verdict::Reproduced { .. })));
    let (_, log) = RulesLog::beside(&file).expect("the log beside the recording");
    let log = log.unwrap();
    assert!(matches!(log, RulesLog::Strokes(_)), "{log:?}");
    assert_eq!(log.check(&recorded), Ok(shots));
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn a_hint_aims_the_humans_cue_at_the_computers_choice_and_the_pointer_is_locked_on_its_turn() {
    let folder = std::env::temp_dir().join(format!("billiards-hint-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, Game::NineBall);
    // Seat A a human: the hint is for them; seat B stays the computer.
    app.world_mut()
        .resource_mut::<Rules>()
        .live
        .as_mut()
        .unwrap()
        .seats[0] = None;
    app.update();
    assert_eq!(turn(&app), Turn::BallInHand);
    assert_eq!(*app.world().resource::<AimLocked>(), AimLocked(false));
    let before = *app.world().resource::<ShotSettings>();
    app.world_mut().write_message(HintRequested);
    // The hint's search runs on its own thread: wait for its answer, however long it takes.
    common::update_until(&mut app, |app| {
        app.world()
            .resource::<Computer>()
            .hint
            .as_ref()
            .is_some_and(|(_, hint)| *hint != Hint::Thinking)
    });
    let (_, hint) = app.world().resource::<Computer>().hint.clone().unwrap();
    let rules = app.world().resource::<Rules>();
    let game = rules.live.as_ref().map(|g| g.rules.as_ref());
    let text = hint.text(game, &OrbitCamera::default());
    assert!(text.starts_with("hint: the break"), "{text}");
    // The hint is shown as the aim: the break speed and direction, not the settings before.
    let after = *app.world().resource::<ShotSettings>();
    assert_ne!(after, before);
    assert!(after.power > 3.0, "a break at {} m/s", after.power);
    // Nothing was shot for the human.
    assert_eq!(turn(&app), Turn::BallInHand);
    let _ = std::fs::remove_dir_all(&folder);
}

/// Issue 28: the verdict on a human's shot stays until the human continues, when the computer
/// shoots next: it does not flash by. It names what the computer may then do.
#[test]
fn a_verdict_before_the_computers_turn_waits_for_the_human() {
    let folder = std::env::temp_dir().join(format!("billiards-verdict-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = common::headless((game::plugin, computer::plugin));
    app.insert_resource(RecordingsFolder(Some(folder.clone())));
    app.insert_resource(ComputerPace(Duration::ZERO));
    app.update();
    app.world_mut().write_message(NewGameRequested {
        game: Game::NineBall.into(),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        race_to: 1,
        seed: 3,
        computer: [None, Some(Level::Easy)],
        setup: Default::default(),
    });
    common::update_until(&mut app, |app| turn(app) == Turn::BallInHand);
    // Ann's break barely rolls: no ball reaches the rack, a foul (WPA 2.3), Bob to shoot.
    app.world_mut()
        .write_message(billiards::sim::ShotRequested {
            angle: 0.0,
            speed: 0.2,
            tip: Default::default(),
            elevation: 0.0,
        });
    common::update_until(&mut app, |app| turn(app) == Turn::Verdict);
    let shots = |app: &App| live(app).log.strokes.len();
    assert_eq!(shots(&app), 1);
    let next = live(&app).next_text();
    assert!(
        next.starts_with("Bob (computer) plays the cue ball next, with ball in hand"),
        "{next}"
    );
    // However many frames go by, the verdict stays and the computer does not shoot.
    for _ in 0..300 {
        app.update();
    }
    assert_eq!(turn(&app), Turn::Verdict);
    assert_eq!(shots(&app), 1);
    // Continue: the computer plays.
    app.world_mut().write_message(game::TurnCommand::Continue);
    common::update_until(&mut app, |app| shots(app) == 2);
    let _ = std::fs::remove_dir_all(&folder);
}

/// Issue 26: two computer seats play snooker through the game's states: strokes with their
/// nominations, the colours spotted, the cue ball in the D. After a dozen strokes the
/// recording verifies bit for bit and the frame's log re-judges every stroke alike.
#[test]
fn two_computers_play_snooker_and_the_frame_log_rejudges() {
    use billiards::play::game::GameChoice;
    use billiards_rules::snooker::rules::SnookerGame;
    let folder = std::env::temp_dir().join(format!("billiards-snooker-cc-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = common::headless((game::plugin, computer::plugin));
    app.insert_resource(RecordingsFolder(Some(folder.clone())));
    app.insert_resource(ComputerPace(Duration::from_millis(20)));
    app.update();
    app.world_mut().write_message(NewGameRequested {
        game: GameChoice::Catalog("snooker"),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        race_to: 1,
        seed: 5,
        computer: [Some(Level::Easy), Some(Level::Easy)],
        setup: Default::default(),
    });
    let strokes = |app: &App| {
        let rules = app.world().resource::<Rules>();
        let game = rules.live.as_ref().unwrap();
        (game.log.strokes.len(), game.rules.end().is_some())
    };
    // Counted in strokes, not time: each is a decision thread waited for to its end.
    const STROKES: usize = 12;
    common::update_until(&mut app, |app| {
        app.world().resource::<Rules>().live.is_some() && {
            let (n, over) = strokes(app);
            (n >= STROKES || over) && turn(app) != Turn::ShotInPlay
        }
    });
    let rules = app.world().resource::<Rules>();
    let game = rules.live.as_ref().unwrap();
    let frame = &game
        .rules
        .as_any()
        .downcast_ref::<SnookerGame>()
        .expect("snooker")
        .frame;
    // The computer played snooker's own search (its strokes are judged by the frame): the
    // score is the frame's, and each fair stroke left the opponent's score alone.
    let (mut fair, mut fouls) = (0, 0);
    for stroke in &game.log.strokes {
        if stroke.judgement.fair {
            fair += 1
        } else {
            fouls += 1
        }
    }
    println!(
        "{fair} fair strokes, {fouls} fouls, scores {:?}",
        frame.scores
    );
    assert_eq!(game.rules.points(), frame.scores);
    assert!(fair + fouls >= 1);
    let file = app.world().resource::<Autosave>().file.clone().unwrap();
    let recorded = Recording::load(&file).unwrap();
    assert!(matches!(recorded.verify(), Ok(Verdict::Reproduced { .. })));
    let (_, log) = billiards_rules::RulesLog::beside(&file).unwrap();
    assert_eq!(log.unwrap().check(&recorded), Ok(game.log.strokes.len()));
    let _ = std::fs::remove_dir_all(&folder);
}
