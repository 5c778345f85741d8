//! The log of any game (issue 50): every game of the catalog saved and restored behind the
//! interface, a recorded stretch of each game logged stroke by stroke and re-judged from its
//! recording, and an edited judgement or a missing stroke found.

use billiards_physics::recording::{Recorder, Recording};
use billiards_physics::{Params, Shot, Vec2};
use billiards_rules::catalog::{GAMES, MatchSettings, restore};
use billiards_rules::{
    CueBallPlace, GameRules, RulesLog, Setup, StrokeEntry, StrokeLog, StrokeRecord,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

mod interface_common;
use interface_common::{hand_place, id_of, layout_of};

/// Records up to `strokes` strokes of `game` from its start, each logged as the game does:
/// options taken at random, the cue ball in hand placed, random shots. Stops where the table
/// would be laid out anew (a new recording) or the game ends.
fn record(game: &mut dyn GameRules, strokes: usize, seed: u64) -> (StrokeLog, Recording) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let params = Params {
        ball: game.ball(),
        ..Params::default()
    };
    let mut rec = Recorder::new(game.table(), params, game.layout().unwrap()).unwrap();
    let mut log = StrokeLog::new(game).unwrap();
    'strokes: while log.strokes.len() < strokes {
        let mut choices = Vec::new();
        let mut turn = game.turn();
        while !turn.choices.is_empty() {
            let pick = rng.random_range(0..turn.choices.len());
            match game.choose(pick, &layout_of(rec.sim())).unwrap() {
                Setup::Keep => {}
                Setup::Put { balls } => {
                    for (n, p) in balls {
                        let id = id_of(rec.sim(), n);
                        rec.place(id, p, Vec2::ZERO, Default::default()).unwrap();
                    }
                }
                Setup::Layout { .. } | Setup::Rack { .. } => break 'strokes,
            }
            choices.push(pick);
            turn = game.turn();
        }
        let cue = id_of(rec.sim(), turn.cue_ball);
        if let CueBallPlace::InHand { .. } = turn.place {
            let at = hand_place(game, rec.sim(), turn.cue_ball);
            rec.place(cue, at, Vec2::ZERO, Default::default()).unwrap();
        }
        let before = layout_of(rec.sim());
        let first = rec.sim().history().events().len();
        let shot = Shot::new(rng.random_range(0.0..std::f64::consts::TAU), 2.5);
        rec.strike(cue, shot).unwrap();
        rec.run_to_rest().unwrap();
        let after = layout_of(rec.sim());
        let judgement = game
            .judge(&StrokeRecord {
                events: &rec.sim().history().events()[first..],
                numbers: rec.sim().numbers(),
                before: &before,
                after: &after,
                declared: Default::default(),
            })
            .unwrap();
        for &(n, p) in &judgement.put {
            let id = id_of(rec.sim(), n);
            rec.place(id, p, Vec2::ZERO, Default::default()).unwrap();
        }
        let end = judgement.end.is_some();
        log.strokes.push(StrokeEntry {
            choices,
            declared: Default::default(),
            judgement,
        });
        if end {
            break;
        }
    }
    (log, rec.recording())
}

fn settings() -> MatchSettings {
    MatchSettings::new(["Ann".to_owned(), "Bob".to_owned()], 3, 5)
}

/// A saved game restores to the same game: the same turn, score and status, and it saves
/// again to the same JSON; JSON that is no saved game is refused with a reason.
#[test]
fn every_game_saves_and_restores_behind_the_interface() {
    for entry in GAMES {
        let game = entry.start(&settings()).unwrap();
        let saved = game.save().unwrap();
        let back = restore(&saved).unwrap();
        assert_eq!(back.name(), game.name(), "{}", entry.id);
        assert_eq!(back.turn(), game.turn(), "{}", entry.id);
        assert_eq!(back.status(), game.status(), "{}", entry.id);
        assert_eq!(back.save().unwrap(), saved, "{}", entry.id);
    }
    let err = restore(&serde_json::json!({"kind": "croquet", "state": {}})).unwrap_err();
    assert!(err.0.starts_with("not a saved game"), "{err}");
}

/// Each game's recorded strokes re-judge to the logged judgements from the game saved at
/// the recording's start; the log reads back as a rules log of its own kind; an edited
/// judgement and a dropped stroke are each found.
#[test]
fn a_stroke_log_rejudges_its_recording_in_every_game() {
    for (k, entry) in GAMES.iter().enumerate() {
        let mut game = entry.start(&settings()).unwrap();
        let (log, recording) = record(game.as_mut(), 12, 40 + k as u64);
        assert!(!log.strokes.is_empty(), "{}", entry.id);
        assert_eq!(log.check(&recording), Ok(log.strokes.len()), "{}", entry.id);
        let text = serde_json::to_string(&log).unwrap();
        assert_eq!(
            RulesLog::from_json(&text),
            Ok(RulesLog::Strokes(log.clone()))
        );
        let line = log.lines()[0].clone();
        assert!(line.starts_with("stroke 1, Ann"), "{line}");

        let mut edited = log.clone();
        edited.strokes[0].judgement.text.push_str(" (edited)");
        let err = edited.check(&recording).unwrap_err();
        assert!(err.starts_with("stroke 1: logged"), "{}: {err}", entry.id);

        let mut short = log.clone();
        short.strokes.pop();
        let err = short.check(&recording).unwrap_err();
        assert!(err.contains("strokes, the recording"), "{err}");
    }
}

/// A game says it may be conceded exactly when a concession is taken: at the start of every
/// game of the catalog (snooker's frame, WPBSA 2.1(a); no other game has one), and not once
/// the frame is over.
#[test]
fn a_game_offers_a_concession_exactly_when_it_takes_one() {
    for entry in GAMES {
        let game = entry.start(&settings()).unwrap();
        let mut copy = game.boxed_clone();
        assert_eq!(game.concedes(), copy.concede().is_ok(), "{}", entry.id);
        assert_eq!(game.concedes(), entry.id == "snooker", "{}", entry.id);
        assert!(
            !copy.concedes(),
            "{}: conceded, then offered again",
            entry.id
        );
    }
}
