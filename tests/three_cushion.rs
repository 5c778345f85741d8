//! Three-cushion in the game (issue 50), a game played through the one interface alone: the
//! carom table without pockets, each player striking their own cue ball (UMB 3.3: the white
//! for the player who opens, the yellow for the other), the turn passing on a stroke that
//! scores nothing (Art. 41), the rules log beside the recording re-judging it, and two
//! computers playing a game to its end.

mod common;

use std::{path::Path, time::Duration};

use bevy::prelude::*;
use billiards::{
    play::computer::{self, ComputerPace},
    play::game::{self, GameChoice, NewGameRequested, Rules, Turn, TurnCommand},
    recording::{Autosave, RecordingsFolder},
    replay::OpenRecording,
    sim::{ShotRequested, SimStatus, Solver},
};
use billiards_ai::Level;
use billiards_physics::PocketShape;
use billiards_physics::recording::{Action, Recording, Verdict};
use billiards_rules::{RulesLog, Seat};

fn start(folder: &Path, length: u32, computer: [Option<Level>; 2]) -> App {
    let mut app = common::headless((game::plugin, computer::plugin));
    app.insert_resource(RecordingsFolder(Some(folder.to_path_buf())));
    app.insert_resource(ComputerPace(Duration::from_millis(20)));
    app.update();
    app.world_mut().write_message(NewGameRequested {
        game: GameChoice::Catalog("three-cushion"),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        race_to: length,
        seed: 3,
        computer,
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

fn hud(app: &App) -> Vec<String> {
    let rules = app.world().resource::<Rules>();
    rules.live.as_ref().unwrap().hud_lines(turn(app), &[])
}

/// A soft stroke toward the head cushion, away from both object balls of the opening (the
/// red on the foot spot, the other cue ball beside on the head string): it scores nothing.
fn soft_stroke(app: &mut App) {
    app.world_mut().write_message(ShotRequested {
        angle: std::f64::consts::PI,
        speed: 0.4,
        tip: Default::default(),
        elevation: 0.0,
    });
    for _ in 0..3 {
        app.update();
    }
    assert_eq!(turn(app), Turn::ShotInPlay, "the stroke was not taken");
    common::update_until(app, |app| app.world().resource::<SimStatus>().at_rest);
    app.update();
}

/// The game starts on the 2.84 x 1.42 m table without pockets with three balls; Ann strikes
/// the white; her stroke scores nothing and Bob strikes the yellow (UMB 3.3, Art. 41); the
/// recording's second strike is of the yellow; the log re-judges both strokes.
#[test]
fn each_player_strikes_their_own_ball_and_the_log_rejudges_the_game() {
    let folder = std::env::temp_dir().join(format!("billiards-3c-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, 2, [None, None]);
    let sim = app.world().resource::<Solver>().simulation();
    assert_eq!(sim.table().pockets, PocketShape::Pocketless);
    assert_eq!((sim.table().length, sim.table().width), (2.84, 1.42));
    assert_eq!(sim.numbers(), &[0, 1, 2]);
    assert_eq!(turn(&app), Turn::Aiming);
    let lines = hud(&app);
    assert!(
        lines[0].starts_with("three-cushion to 2: Ann 0"),
        "{lines:?}"
    );
    assert_eq!(lines[1], "Ann to play the white: aim and shoot");
    assert_eq!(app.world().resource::<Solver>().cue_number(), 0);

    soft_stroke(&mut app);
    assert_eq!(turn(&app), Turn::Verdict);
    let rules = app.world().resource::<Rules>();
    let game = rules.live.as_ref().unwrap();
    let last = game.last.clone().unwrap();
    assert_eq!(last.striker, Seat::A);
    assert!(!last.continues, "{}", last.text);
    assert_eq!(game.rules.turn().striker, Seat::B);
    app.world_mut().write_message(TurnCommand::Continue);
    app.update();
    app.update();
    assert_eq!(turn(&app), Turn::Aiming);
    assert_eq!(hud(&app)[1], "Bob to play the yellow: aim and shoot");
    assert_eq!(app.world().resource::<Solver>().cue_number(), 1);
    soft_stroke(&mut app);

    let file = app.world().resource::<Autosave>().file.clone().unwrap();
    let recorded = Recording::load(&file).unwrap();
    assert!(matches!(recorded.verify(), Ok(Verdict::Reproduced { .. })));
    let struck: Vec<usize> = recorded
        .inputs
        .iter()
        .filter_map(|i| match i.action {
            Action::Strike { ball, .. } => Some(ball),
            _ => None,
        })
        .collect();
    let numbers: Vec<u8> = recorded.balls.iter().map(|b| b.number).collect();
    assert_eq!(
        struck.iter().map(|&id| numbers[id]).collect::<Vec<_>>(),
        [0, 1],
        "the white, then the yellow"
    );
    let (_, log) = RulesLog::beside(&file).expect("the log beside the recording");
    let log = log.unwrap();
    assert!(matches!(log, RulesLog::Strokes(_)), "{log:?}");
    assert_eq!(log.check(&recorded), Ok(2));
    let open = OpenRecording::new(&file, recorded.clone()).unwrap();
    assert_eq!(open.check_verdicts(), Some(Ok(2)));
    let line = open.game_line(open.shots.span(1).unwrap().0).unwrap();
    assert!(line.starts_with("stroke 1, Ann: "), "{line}");
    let _ = std::fs::remove_dir_all(&folder);
}

/// Two computers play a game to 1 point to its end through the game's states; the game's
/// end names the winner and its recording's log re-judges every stroke.
#[test]
fn two_computers_play_a_three_cushion_game_to_its_end() {
    let folder = std::env::temp_dir().join(format!("billiards-3c-cc-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, 1, [Some(Level::Medium), Some(Level::Medium)]);
    // Bounded by strokes, not by the clock.
    const MAX_STROKES: usize = 60;
    common::update_until(&mut app, |app| {
        let rules = app.world().resource::<Rules>();
        let strokes = rules.live.as_ref().unwrap().log.strokes.len();
        assert!(strokes <= MAX_STROKES, "no point in {strokes} strokes");
        turn(app) == Turn::GameOver
    });
    let lines = hud(&app);
    assert!(lines[1].contains("wins the game"), "{lines:?}");
    let file = app.world().resource::<Autosave>().file.clone().unwrap();
    let recorded = Recording::load(&file).unwrap();
    let (_, log) = RulesLog::beside(&file).unwrap();
    let log = log.unwrap();
    let strokes = log.check(&recorded).unwrap();
    println!("three-cushion to 1 point between two medium computers: {strokes} strokes");
    assert!(strokes >= 1);
    let _ = std::fs::remove_dir_all(&folder);
}
