//! Headless games through the game's states: whole racks of 9-ball with scripted shots, the
//! turns, the cue ball in hand, the winner of each rack and of the match, and the rules log
//! saved beside the recording (re-judged against it).

mod common;

use std::path::Path;

use bevy::{math::DVec2, prelude::*};
use billiards::{
    input::AimLocked,
    play::game::{self, LiveGame, NewGameRequested, Rules, Turn, TurnCommand},
    recording::{Autosave, RecordingsFolder},
    replay::OpenRecording,
    sim::{self, HandError, HandRule, ShotRequested, SimStatus, Solver},
    table::geometry::TableSpec,
};
use billiards_physics::recording::Recording;
use billiards_rules::{
    Declaration, Foul, Game, PlacementError, RulesLog, Seat, StrokeLog, WinReason, pool::PoolMatch,
};

/// A headless game saving into `folder`, with a new match of `game` started.
fn start(folder: &Path, game: Game, race_to: u32) -> App {
    let mut app = common::headless(game::plugin);
    app.insert_resource(RecordingsFolder(Some(folder.to_path_buf())));
    app.update();
    app.world_mut().write_message(NewGameRequested {
        game: game.into(),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        race_to,
        seed: 7,
        computer: [None, None],
        setup: Default::default(),
    });
    app.update();
    app.update();
    app
}

fn turn(app: &App) -> Turn {
    *app.world().resource::<State<Turn>>().get()
}

/// The match in play, behind the one interface.
fn rules(app: &App) -> &LiveGame {
    app.world().resource::<Rules>().live.as_ref().unwrap()
}

/// The pool match behind the interface (its rack and next shot in pool's own words).
fn pool(app: &App) -> &PoolMatch {
    rules(app)
        .rules
        .as_any()
        .downcast_ref::<PoolMatch>()
        .expect("a pool match")
}

/// The log beside the recording in play, read back as any game's log.
fn log_beside(recording: &Path) -> StrokeLog {
    match RulesLog::beside(recording) {
        Some((_, Ok(RulesLog::Strokes(log)))) => log,
        other => panic!("no stroke log beside {recording:?}: {other:?}"),
    }
}

fn command(app: &mut App, command: TurnCommand) {
    app.world_mut().write_message(command);
    app.update();
    app.update();
}

/// Shoots and runs frames until every ball rests and the verdict is shown.
fn shoot(app: &mut App, angle: f64, speed: f64) {
    app.world_mut().write_message(ShotRequested {
        angle,
        speed,
        tip: Default::default(),
        elevation: 0.0,
    });
    // The strike (commands), the turn follows (flow), the state changes (transition).
    for _ in 0..3 {
        app.update();
    }
    let note = app.world().resource::<SimStatus>().note.clone();
    assert_eq!(
        turn(app),
        Turn::ShotInPlay,
        "the shot was not taken: {note:?}"
    );
    for _ in 0..3000 {
        app.update();
        if app.world().resource::<SimStatus>().at_rest {
            app.update();
            return;
        }
    }
    panic!("balls still moving");
}

/// The balls on the table: (solver id, number, position).
fn balls(app: &mut App) -> Vec<(usize, u8, DVec2)> {
    let solver = app.world().resource::<Solver>();
    let sim = solver.simulation();
    (0..sim.ball_count())
        .map(|id| (id, sim.numbers()[id], sim.ball(id)))
        .filter(|(_, _, state)| state.motion.on_table())
        .map(|(id, n, state)| (id, n, DVec2::new(state.position.x, state.position.y)))
        .collect()
}

use common::place;

/// A shot that touches no ball: with the cue ball in hand, put it far from every ball first;
/// then a soft roll away from the nearest ball (WPA 6.2: a foul).
fn miss(app: &mut App) {
    if app.world().resource::<SimStatus>().ball_in_hand.is_some() {
        let others: Vec<DVec2> = balls(app)
            .into_iter()
            .filter(|&(_, n, _)| n != 0)
            .map(|(_, _, p)| p)
            .collect();
        let spot = (0..200)
            .map(|k| {
                DVec2::new(
                    -1.0 + 0.1 * f64::from(k % 20),
                    -0.5 + 0.1 * f64::from(k / 20),
                )
            })
            .filter(|p| p.y.abs() < 0.5)
            .find(|p| others.iter().all(|o| o.distance(*p) > 0.2))
            .expect("a clear spot");
        place(app, spot).unwrap();
        assert_eq!(
            balls(app).into_iter().find(|b| b.1 == 0).unwrap().2,
            spot,
            "the placement reached the solver"
        );
    }
    let all = balls(app);
    let cue = all.iter().find(|b| b.1 == 0).unwrap().2;
    let nearest = all
        .iter()
        .filter(|b| b.1 != 0)
        .min_by(|a, b| a.2.distance(cue).total_cmp(&b.2.distance(cue)))
        .unwrap()
        .2;
    shoot(app, (cue - nearest).to_angle(), 0.05);
}

/// Plays one rack in which every shot after the break is a miss: the player who fouls first
/// after the break reaches three fouls first and loses (WPA 2.8). Returns the rack's winner.
fn play_rack_of_misses(app: &mut App, breaker: Seat) -> Seat {
    assert_eq!(
        turn(app),
        Turn::BallInHand,
        "the break is taken from the hand"
    );
    let next = pool(app).play.next().clone();
    assert!(next.break_shot);
    assert_eq!(next.shooter, breaker);
    assert_eq!(
        app.world().resource::<SimStatus>().ball_in_hand,
        Some(HandRule::BehindHeadString)
    );
    // WPA 2.3: the cue ball must stay behind the head string for the break.
    let spec = app.world().resource::<TableSpec>().clone();
    assert_eq!(
        place(app, spec.foot_spot()),
        Err(HandError::Rules(PlacementError::InFrontOfHeadString))
    );
    let head = spec.head_spot();
    place(app, head + DVec2::new(-0.05, 0.02)).unwrap();
    shoot(app, 0.0, 9.0);
    let mut shots = 1;
    loop {
        assert!(matches!(turn(app), Turn::Verdict | Turn::GameOver));
        let verdict = rules(app).last.clone().unwrap();
        if let Some(end) = &verdict.end {
            assert_eq!(turn(app), Turn::GameOver);
            let lines = rules(app).hud_lines(Turn::GameOver, &[]).join("\n");
            assert!(lines.contains("wins the rack"), "{lines}");
            let (winner, reason) = pool(app).rack().over.unwrap();
            assert_eq!(winner, end.winner);
            if reason == WinReason::ThreeFouls {
                assert_eq!(winner, verdict.striker.other());
            }
            return winner;
        }
        // A shot refused while the verdict is shown.
        app.world_mut().write_message(ShotRequested {
            angle: 0.0,
            speed: 1.0,
            tip: Default::default(),
            elevation: 0.0,
        });
        app.update();
        assert_eq!(turn(app), Turn::Verdict);
        command(app, TurnCommand::Continue);
        let next = pool(app).play.next().clone();
        assert!(next.choices.is_empty(), "no push out is declared");
        let expected_hand = if verdict.fair {
            None
        } else {
            // WPA 2.7: ball in hand anywhere after a foul.
            Some(HandRule::Anywhere)
        };
        assert_eq!(
            app.world().resource::<SimStatus>().ball_in_hand,
            expected_hand
        );
        assert_eq!(
            turn(app),
            if expected_hand.is_some() {
                Turn::BallInHand
            } else {
                Turn::Aiming
            }
        );
        let shooter = next.shooter;
        let fouls_before = pool(app).rack().fouls[shooter.index()];
        miss(app);
        shots += 1;
        assert!(shots < 20, "the rack does not end");
        let verdict = rules(app).last.clone().unwrap();
        assert_eq!(verdict.striker, shooter);
        assert!(
            verdict.fouls.contains(&Foul::NoBallHit.to_string()),
            "{verdict:?}"
        );
        let lines = rules(app).hud_lines(turn(app), &[]).join("\n");
        assert!(
            lines.contains("last foul: the cue ball hit no ball"),
            "{lines}"
        );
        if fouls_before == 2 {
            assert_eq!(
                verdict.end.as_ref().map(|e| e.winner),
                Some(shooter.other())
            );
            assert_eq!(
                pool(app).rack().over,
                Some((shooter.other(), WinReason::ThreeFouls))
            );
        } else {
            assert!(verdict.end.is_none() && !verdict.continues, "{verdict:?}");
            assert_eq!(rules(app).rules.turn().striker, shooter.other());
        }
    }
}

#[test]
fn a_nine_ball_match_is_played_through_the_turns_to_its_winner() {
    let folder = std::env::temp_dir().join(format!("billiards-game-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, Game::NineBall, 2);
    let lines = rules(&app).hud_lines(turn(&app), &[]);
    assert_eq!(lines[0], "9-ball, race to 2: Ann 0 - 0 Bob");
    assert!(lines[1].starts_with("Ann to break: ball in hand behind the head string"));
    assert!(lines.contains(&"balls left: 9".to_owned()), "{lines:?}");
    // Balls the shot in play has dropped are counted off at once, before the verdict
    // updates the rack (issue 28, item 10: "balls left" stayed stale while balls moved).
    let moving = rules(&app).hud_lines(Turn::ShotInPlay, &[3, 7]);
    assert!(moving.contains(&"balls left: 7".to_owned()), "{moving:?}");
    let mut breaker = Seat::A;
    let mut racks = 0;
    loop {
        let winner = play_rack_of_misses(&mut app, breaker);
        racks += 1;
        let play = pool(&app).play.clone();
        assert_eq!(play.score[0] + play.score[1], racks);
        // The rack's rules log lies beside its recording and re-judges it.
        let recording = app.world().resource::<Autosave>().file.clone().unwrap();
        let log = log_beside(&recording);
        let recorded = Recording::load(&recording).unwrap();
        assert_eq!(log.check(&recorded), Ok(log.strokes.len()));
        assert_eq!(log.players, ["Ann".to_owned(), "Bob".to_owned()]);
        assert_eq!(log.game, "9-ball");
        // The replay reads the log: each shot's verdict on the timeline, re-judged by Verify.
        let open = OpenRecording::new(&recording, recorded.clone()).unwrap();
        assert_eq!(open.check_verdicts(), Some(Ok(log.strokes.len())));
        let break_line = open.game_line(open.shots.span(1).unwrap().0).unwrap();
        let breaker_name = ["Ann", "Bob"][breaker.index()];
        assert_eq!(
            break_line,
            format!(
                "stroke 1, {breaker_name}: {}",
                log.strokes[0].judgement.text
            )
        );
        assert_eq!(log.strokes[0].judgement.striker, breaker);
        if let Some(champion) = play.winner() {
            assert_eq!(champion, winner);
            assert_eq!(play.score[champion.index()], 2);
            let lines = rules(&app).hud_lines(Turn::GameOver, &[]).join("\n");
            assert!(lines.contains("wins the rack and the match"), "{lines}");
            break;
        }
        assert!(racks < 3);
        // Alternate break.
        command(&mut app, TurnCommand::NextRack);
        breaker = breaker.other();
    }
    // A new game of free play ends the match.
    app.world_mut().write_message(NewGameRequested {
        game: Game::FreePlay.into(),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        race_to: 1,
        seed: 0,
        computer: [None, None],
        setup: Default::default(),
    });
    app.update();
    app.update();
    // Free play is the sandbox behind the same interface: no match, the table the player's.
    let rules_now = app.world().resource::<Rules>();
    assert!(!rules_now.in_match());
    assert!(rules_now.live.as_ref().is_some_and(|g| g.rules.sandbox()));
    assert!(app.world().resource::<billiards::sim::Referee>().edits);
    assert_eq!(turn(&app), Turn::Aiming);
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn eight_ball_needs_a_call_on_the_eight_and_the_dialog_pauses_the_turn() {
    let folder = std::env::temp_dir().join(format!("billiards-game8-{}", std::process::id()));
    let mut app = start(&folder, Game::EightBall, 1);
    let lines = rules(&app).hud_lines(turn(&app), &[]);
    assert_eq!(lines[0], "8-ball, race to 1: Ann 0 - 0 Bob");
    assert!(lines.iter().any(|l| l == "open table"), "{lines:?}");
    // The new-game dialog stops the turn; closing it gives the turn back.
    command(&mut app, TurnCommand::OpenDialog);
    assert_eq!(turn(&app), Turn::NewGame);
    command(&mut app, TurnCommand::CloseDialog);
    assert_eq!(turn(&app), Turn::BallInHand);
    // No call on the break.
    command(&mut app, TurnCommand::StartCalling);
    assert_eq!(turn(&app), Turn::BallInHand);
    shoot(&mut app, 0.0, 9.0);
    assert_eq!(rules(&app).log.strokes.len(), 1, "the break was judged");
    assert!(matches!(turn(&app), Turn::Verdict | Turn::GameOver));
    if turn(&app) == Turn::GameOver {
        return;
    }
    // WPA 3.3: after an illegal break or the 8 on the break, the options; take the first.
    match rules(&app).rules.turn().choices.first() {
        Some(_) => command(&mut app, TurnCommand::ChooseOption(0)),
        None => command(&mut app, TurnCommand::Continue),
    }
    assert!(matches!(turn(&app), Turn::Aiming | Turn::BallInHand));
    // Calling (WPA 1.6): a click on a pocket calls it (here the command the click sends).
    command(&mut app, TurnCommand::StartCalling);
    assert_eq!(turn(&app), Turn::Calling);
    // The click that calls a pocket does not also aim the cue at it.
    assert_eq!(*app.world().resource::<AimLocked>(), AimLocked(true));
    let ball = rules(&app).call_ball.unwrap();
    assert!(pool(&app).play.next().legal_first.contains(&ball));
    let call = Declaration::Pocket {
        ball,
        pocket: billiards_physics::Pocket::FootLeft,
    };
    command(&mut app, TurnCommand::Declare(call));
    assert!(matches!(turn(&app), Turn::Aiming | Turn::BallInHand));
    assert_eq!(*app.world().resource::<AimLocked>(), AimLocked(false));
    assert_eq!(rules(&app).declared, call);
    let lines = rules(&app).hud_lines(turn(&app), &[]).join("\n");
    assert!(lines.contains("call: the "), "{lines}");
    let _ = std::fs::remove_dir_all(&folder);
}

/// Undo is for practice: in a match the shot stands and the player is told why.
#[test]
fn a_match_refuses_undo() {
    let folder = std::env::temp_dir().join(format!("billiards-game-undo-{}", std::process::id()));
    let mut app = start(&folder, Game::NineBall, 1);
    shoot(&mut app, 0.0, 9.0);
    let after = balls(&mut app);
    app.world_mut().write_message(sim::UndoRequested);
    app.update();
    assert_eq!(balls(&mut app), after);
    let note = app.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.contains("practice"), "{note}");
    let _ = std::fs::remove_dir_all(&folder);
}

/// Issue 48: after a shot the HUD's last-shot line says what the shot did (the balls that
/// dropped and where, or "nothing pocketed") after the verdict, and the verdict alone is
/// never the whole line; the computer's seat is marked from the first line on.
#[test]
fn the_last_shot_says_what_went_in_and_the_computer_seat_is_marked() {
    let folder = std::env::temp_dir().join(format!("billiards-what-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, Game::NineBall, 1);
    // The break, straight at the rack.
    shoot(&mut app, 0.0, 7.0);
    let game = rules(&app);
    let verdict = game.last.clone().unwrap();
    // What went in, or that nothing did, unless a foul of the verdict already says so
    // (the cue ball hit no ball, no ball pocketed on an illegal break or without a rail).
    let fouls_say_it = verdict.fouls.iter().any(|f| f.contains("no ball"));
    let what = &verdict.text;
    assert!(
        what.contains("nothing pocketed") || what.contains(" in the ") || fouls_say_it,
        "{what} after {verdict:?}"
    );
    assert_ne!(what, "legal", "the verdict alone is never the whole line");
    let lines = game.hud_lines(turn(&app), &[]);
    let expected = format!("last stroke: Ann: {what}");
    assert!(lines.contains(&expected), "{expected:?} not in {lines:?}");
    let _ = std::fs::remove_dir_all(&folder);

    let mut app = common::headless(game::plugin);
    app.insert_resource(RecordingsFolder(None));
    app.update();
    app.world_mut().write_message(NewGameRequested {
        game: Game::NineBall.into(),
        players: ["Ann".to_owned(), "Bob".to_owned()],
        race_to: 1,
        seed: 7,
        computer: [None, Some(billiards_ai::Level::Easy)],
        setup: Default::default(),
    });
    app.update();
    app.update();
    let lines = rules(&app).hud_lines(turn(&app), &[]);
    assert_eq!(
        lines[0],
        "9-ball, race to 1: Ann 0 - 0 Bob (computer)",
        "{:?}",
        rules(&app).seats
    );
}

/// 10-ball (WPA section 9): the dialog's game plays through the same turns; a rack of misses
/// ends on the third foul (9.11, no win is possible on the break, 9.9), its log re-judges the
/// recording, and after the break a ball and a pocket are called (9.5), any ball on the
/// table, the 10 too.
#[test]
fn a_ten_ball_rack_is_called_and_played_to_its_winner() {
    assert!(game::GameChoice::ALL.contains(&Game::TenBall.into()));
    assert_eq!(game::GameChoice::from(Game::TenBall).label(), "10-ball");
    let folder = std::env::temp_dir().join(format!("billiards-game10-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, Game::TenBall, 1);
    let lines = rules(&app).hud_lines(turn(&app), &[]);
    assert_eq!(lines[0], "10-ball, race to 1: Ann 0 - 0 Bob");
    assert!(lines.contains(&"balls left: 10".to_owned()), "{lines:?}");
    assert_eq!(balls(&mut app).iter().filter(|b| b.1 != 0).count(), 10);
    let winner = play_rack_of_misses(&mut app, Seat::A);
    assert_eq!(
        pool(&app).rack().over,
        Some((winner, WinReason::ThreeFouls))
    );
    let recording = app.world().resource::<Autosave>().file.clone().unwrap();
    let log = log_beside(&recording);
    assert_eq!(log.game, "10-ball");
    let recorded = Recording::load(&recording).unwrap();
    assert_eq!(log.check(&recorded), Ok(log.strokes.len()));
    let _ = std::fs::remove_dir_all(&folder);

    let mut app = start(&folder, Game::TenBall, 1);
    // No call on the break (WPA 9).
    command(&mut app, TurnCommand::StartCalling);
    assert_eq!(turn(&app), Turn::BallInHand);
    let head = app.world().resource::<TableSpec>().head_spot();
    place(&mut app, head + DVec2::new(-0.05, 0.02)).unwrap();
    shoot(&mut app, 0.0, 9.0);
    assert_eq!(pool(&app).rack().over, None, "no win on the break (9.9)");
    match rules(&app).rules.turn().choices.first() {
        Some(_) => command(&mut app, TurnCommand::ChooseOption(0)),
        None => command(&mut app, TurnCommand::Continue),
    }
    command(&mut app, TurnCommand::StartCalling);
    assert_eq!(turn(&app), Turn::Calling);
    let call = Declaration::Pocket {
        ball: 10,
        pocket: billiards_physics::Pocket::FootLeft,
    };
    command(&mut app, TurnCommand::Declare(call));
    assert!(matches!(turn(&app), Turn::Aiming | Turn::BallInHand));
    assert_eq!(rules(&app).declared, call);
    let lines = rules(&app).hud_lines(turn(&app), &[]).join("\n");
    assert!(
        lines.contains("call: the 10 in the foot-left corner"),
        "{lines}"
    );
    let _ = std::fs::remove_dir_all(&folder);
}

/// Issue 52 with WPA 6.1 ("Cue Ball Scratch or off the Table"): in a 9-ball match the break
/// is jumped off the table (6 m/s with the cue at 60 degrees, 30 cm from the head cushion,
/// the physics' own case of a ball leaving the table); the verdict names it a foul, the
/// opponent has ball in hand anywhere, the cue ball is back on the table where the rules
/// accept it, and the recording's log re-judges the stroke.
#[test]
fn a_cue_ball_jumped_off_the_table_is_a_foul_and_comes_back_in_hand() {
    let folder = std::env::temp_dir().join(format!("billiards-game-off-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let mut app = start(&folder, Game::NineBall, 1);
    let spec = app.world().resource::<TableSpec>().clone();
    let from = DVec2::new(-spec.half_extents().x + 0.3, 0.1);
    place(&mut app, from).unwrap();
    app.world_mut()
        .write_message(ShotRequested::from(billiards_physics::Shot {
            elevation: 60f64.to_radians(),
            ..billiards_physics::Shot::new(std::f64::consts::PI, 6.0)
        }));
    common::update_until(&mut app, |app| turn(app) == Turn::Verdict);
    let verdict = rules(&app).last.clone().unwrap();
    assert!(!verdict.fair, "{verdict:?}");
    assert!(
        verdict
            .fouls
            .contains(&"the cue ball was driven off the table".to_owned()),
        "{verdict:?}"
    );
    command(&mut app, TurnCommand::Continue);
    assert_eq!(turn(&app), Turn::BallInHand);
    assert_eq!(rules(&app).rules.turn().striker, Seat::B);
    assert_eq!(
        app.world().resource::<SimStatus>().ball_in_hand,
        Some(HandRule::Anywhere)
    );
    let cue = balls(&mut app).into_iter().find(|b| b.1 == 0);
    assert!(cue.is_some(), "the cue ball is back on the table");
    let recording = app.world().resource::<Autosave>().file.clone().unwrap();
    let log = log_beside(&recording);
    assert_eq!(log.check(&Recording::load(&recording).unwrap()), Ok(1));
    let _ = std::fs::remove_dir_all(&folder);
}
