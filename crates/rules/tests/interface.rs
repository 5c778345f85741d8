//! The one game interface (issue 50): every game of the catalog is played through
//! [`GameRules`] alone by a caller that knows no game, on the solver, and the interface's
//! promises hold stroke after stroke; pool's adapter says what the WPA rules say.

use billiards_physics::{BallSetup, Params, Pocket, Shot, Simulation, Vec2};
use billiards_rules::catalog::{GAMES, MatchSettings, find};
use billiards_rules::{
    Call, CueBallPlace, Declaration, GameRules, GameState, Need, Seat, Setup, StrokeRecord,
    summarise,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

mod interface_common;
use interface_common::{hand_place, id_of, layout_of};

fn players() -> [String; 2] {
    ["Ann".to_owned(), "Bob".to_owned()]
}

/// A fresh solver on `balls` with the game's table and balls.
fn solver(game: &dyn GameRules, balls: &[BallSetup]) -> Simulation {
    let params = Params {
        ball: game.ball(),
        ..Params::default()
    };
    Simulation::new(game.table(), params, balls).unwrap()
}

/// Sets the table as `setup` says.
fn apply(game: &dyn GameRules, sim: &mut Simulation, setup: Setup) {
    match setup {
        Setup::Keep => {}
        Setup::Put { balls } => put(sim, &balls),
        Setup::Layout { balls } => {
            let balls: Vec<BallSetup> = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
            *sim = solver(game, &balls);
        }
        Setup::Rack { balls } => *sim = solver(game, &balls),
    }
}

fn put(sim: &mut Simulation, balls: &[(u8, Vec2)]) {
    for &(n, p) in balls {
        let id = id_of(sim, n);
        sim.place(id, p, Vec2::ZERO, Default::default())
            .unwrap_or_else(|e| {
                panic!("the rules put the {n} at {p:?}, which the solver refuses: {e}")
            });
    }
}

/// The counts of one run through the interface.
#[derive(Debug, Default)]
struct Run {
    strokes: usize,
    /// Strokes by seat.
    strikers: [usize; 2],
    fouls: usize,
    games_ended: usize,
    match_over: bool,
}

/// Plays `strokes` strokes of `game` with a plain seeded player that knows only the
/// interface: each promise of the interface is asserted on the way.
fn play(game: &mut dyn GameRules, strokes: usize, seed: u64) -> Run {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut sim = solver(game, &game.layout().unwrap());
    let mut run = Run::default();
    while run.strokes < strokes {
        let mut turn = game.turn();
        while !turn.choices.is_empty() {
            let pick = rng.random_range(0..turn.choices.len());
            let setup = game.choose(pick, &layout_of(&sim)).unwrap();
            apply(game, &mut sim, setup);
            turn = game.turn();
        }
        let cue = id_of(&sim, turn.cue_ball);
        if let CueBallPlace::InHand { .. } = turn.place {
            let here = sim.ball(cue);
            let others: Vec<(u8, Vec2)> = layout_of(&sim)
                .into_iter()
                .filter(|&(n, _)| n != turn.cue_ball)
                .collect();
            if !(here.motion.on_table() && game.check_hand(here.position, &others).is_ok()) {
                let at = hand_place(game, &sim, turn.cue_ball);
                sim.place(cue, at, Vec2::ZERO, Default::default()).unwrap();
            }
        }
        assert!(
            sim.ball(cue).motion.on_table(),
            "{}: the striker's cue ball is off the table at a stroke",
            game.name()
        );
        // Aim at a legal ball (or anywhere), a little off its centre.
        let from = sim.ball(cue).position;
        let layout = layout_of(&sim);
        let target = layout
            .iter()
            .filter(|(n, _)| turn.legal_first.contains(n))
            .min_by(|a, b| (a.1 - from).length().total_cmp(&(b.1 - from).length()))
            .copied();
        let angle = match target {
            Some((_, p)) => (p.y - from.y).atan2(p.x - from.x) + rng.random_range(-0.05..0.05),
            None => rng.random_range(-3.1..3.1),
        };
        let speed = if turn.opening {
            6.0
        } else {
            rng.random_range(0.8..3.0)
        };
        let declared = match (target, turn.declare.pocket) {
            (Some((ball, at)), Need::Required | Need::Optional) => Declaration::Pocket {
                ball,
                pocket: *Pocket::ALL
                    .iter()
                    .min_by(|a, b| {
                        let t = game.table();
                        (t.pocket_position(**a) - at)
                            .length()
                            .total_cmp(&(t.pocket_position(**b) - at).length())
                    })
                    .unwrap(),
            },
            (Some((ball, _)), _) if turn.declare.nominate.contains(&ball) => {
                Declaration::Nominate { ball }
            }
            _ => Declaration::None,
        };
        let before = layout_of(&sim);
        let first = sim.history().events().len();
        sim.strike(cue, Shot::new(angle, speed)).unwrap();
        sim.run_to_rest().unwrap();
        let after = layout_of(&sim);
        let events = sim.history().events()[first..].to_vec();
        let judgement = game
            .judge(&StrokeRecord {
                events: &events,
                numbers: sim.numbers(),
                before: &before,
                after: &after,
                declared,
            })
            .unwrap_or_else(|e| panic!("{}: stroke {} refused: {e}", game.name(), run.strokes));
        run.strokes += 1;
        run.strikers[turn.striker.index()] += 1;
        // The promises of the interface.
        assert_eq!(
            judgement.striker, turn.striker,
            "the verdict names the striker"
        );
        assert_eq!(
            judgement.fair,
            judgement.fouls.is_empty(),
            "fair means no foul"
        );
        assert!(!judgement.text.is_empty(), "every verdict is said in words");
        if !judgement.fair {
            run.fouls += 1;
            assert!(
                judgement.text.contains(&judgement.fouls[0]) || game.name() == "snooker",
                "{}: the verdict {:?} says its foul {:?}",
                game.name(),
                judgement.text,
                judgement.fouls[0]
            );
        }
        put(&mut sim, &judgement.put);
        match &judgement.end {
            Some(end) => {
                run.games_ended += 1;
                assert_eq!(game.end().as_ref(), Some(end), "the game's end is kept");
                if end.match_over {
                    assert_eq!(game.match_winner(), Some(end.winner));
                    run.match_over = true;
                    break;
                }
                let balls = game.next_game().unwrap();
                sim = solver(game, &balls);
            }
            None => {
                let next = game.turn();
                if judgement.continues {
                    assert_eq!(next.striker, turn.striker, "a continuing striker stays");
                } else if game.name() != "free play" {
                    assert_ne!(next.striker, turn.striker, "the turn passes");
                }
            }
        }
    }
    run
}

#[test]
fn every_game_of_the_catalog_is_played_through_the_interface_alone() {
    for (k, entry) in GAMES.iter().enumerate() {
        let settings = MatchSettings::new(players(), 3, 7 + k as u64);
        let mut game = entry.start(&settings).unwrap();
        assert_eq!(game.name(), entry.label);
        let run = play(game.as_mut(), 300, k as u64);
        // Seeded: 9-ball's race to 3 is played to its end, racks re-racked through
        // `next_game`.
        if entry.id == "nine-ball" {
            assert!(run.match_over && run.games_ended >= 3, "{run:?}");
        }
        assert!(run.strokes > 0, "{}: {run:?}", entry.label);
        // Free play has no fouls and one player; in a two-player game both strike, and a
        // plain player fouls at pool and snooker (at carom a miss is no foul).
        if entry.id == "free-play" {
            assert_eq!(run.fouls, 0, "free play has no fouls: {run:?}");
        } else {
            assert!(
                run.strikers.iter().all(|&n| n > 0),
                "{}: {run:?}",
                entry.label
            );
        }
        if ["nine-ball", "eight-ball", "snooker"].contains(&entry.id) {
            assert!(
                run.fouls > 0,
                "{}: no foul in 300 strokes: {run:?}",
                entry.label
            );
        }
    }
}

#[test]
fn games_are_found_by_their_command_line_ids_and_labels() {
    assert_eq!(find("nine-ball").unwrap().label, "9-ball");
    assert_eq!(find("9-ball").unwrap().id, "nine-ball");
    assert_eq!(find("Snooker").unwrap().id, "snooker");
    assert_eq!(find("free play").unwrap().id, "free-play");
    let e = find("pinball").unwrap_err().to_string();
    assert!(e.contains("nine-ball") && e.contains("snooker"), "{e}");
    // A match of no length, and snooker's even best-of (2.1), refused with a reason.
    let zero = MatchSettings::new(players(), 0, 1);
    assert!(find("nine-ball").unwrap().start(&zero).is_err());
    let even = MatchSettings::new(players(), 2, 1);
    let e = find("snooker")
        .unwrap()
        .start(&even)
        .unwrap_err()
        .to_string();
    assert!(e.contains('2'), "{e}");
}

/// Pool behind the interface says what the WPA rules say: the same shots judged by
/// [`GameState::play`] directly and through the interface give the same verdict and turn.
#[test]
fn pool_through_the_interface_judges_as_the_wpa_rules_do() {
    let entry = find("nine-ball").unwrap();
    let mut game = entry.start(&MatchSettings::new(players(), 2, 3)).unwrap();
    let mut direct = GameState::new(billiards_rules::Game::NineBall, Seat::A);
    let mut sim = solver(game.as_ref(), &game.layout().unwrap());
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for k in 0..25 {
        let turn = game.turn();
        if !turn.choices.is_empty() || direct.over.is_some() {
            break;
        }
        if matches!(turn.place, CueBallPlace::InHand { .. }) && !sim.ball(0).motion.on_table() {
            let at = hand_place(game.as_ref(), &sim, 0);
            sim.place(0, at, Vec2::ZERO, Default::default()).unwrap();
        }
        assert_eq!(
            turn.striker, direct.next.shooter,
            "shot {k}: the same shooter"
        );
        assert_eq!(turn.legal_first, direct.next.legal_first, "shot {k}");
        let before = layout_of(&sim);
        let first = sim.history().events().len();
        let speed = if turn.opening {
            7.0
        } else {
            rng.random_range(1.0..3.0)
        };
        let shot = Shot::new(rng.random_range(-0.3..0.3), speed);
        sim.strike(0, shot).unwrap();
        sim.run_to_rest().unwrap();
        let after = layout_of(&sim);
        let events = sim.history().events()[first..].to_vec();
        let summary = summarise(&events, sim.numbers());
        let verdict = direct.play(&summary, Call::None).unwrap();
        let judged = game
            .judge(&StrokeRecord {
                events: &events,
                numbers: sim.numbers(),
                before: &before,
                after: &after,
                declared: Declaration::None,
            })
            .unwrap();
        assert_eq!(judged.fair, verdict.legal(), "shot {k}");
        assert!(
            judged.text.starts_with(&verdict.reason()),
            "shot {k}: {}",
            judged.text
        );
        assert_eq!(
            judged.fouls,
            verdict
                .fouls
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
        );
        // WPA 2.6: a 9 pocketed on a foul is spotted; the interface says where.
        for &(n, p) in &judged.put {
            assert!(
                direct.next.spot.contains(&n) || n == 0,
                "shot {k}: put the {n}"
            );
            sim.place(id_of(&sim, n), p, Vec2::ZERO, Default::default())
                .unwrap();
        }
    }
}

#[test]
fn snooker_concession_ends_the_frame_and_the_next_frame_changes_breaker() {
    let entry = find("snooker").unwrap();
    let mut game = entry.start(&MatchSettings::new(players(), 3, 0)).unwrap();
    assert_eq!(game.turn().striker, Seat::A);
    assert!(
        game.turn().opening,
        "3.2: the first stroke is the break-off"
    );
    // 2.1(a): the striker concedes; the frame goes to the opponent, the match goes on.
    let end = game.concede().unwrap();
    assert_eq!(end.winner, Seat::B);
    assert!(!end.match_over);
    assert_eq!(game.match_winner(), None);
    let balls = game.next_game().unwrap();
    assert_eq!(balls.len(), 22, "3.2: 15 reds, 6 colours and the cue ball");
    // 2.1: the players break off in turn.
    assert_eq!(game.turn().striker, Seat::B);
    // Pool has no concession: refused with a reason.
    let mut pool = find("eight-ball")
        .unwrap()
        .start(&MatchSettings::new(players(), 1, 0))
        .unwrap();
    assert!(pool.concede().unwrap_err().to_string().contains("8-ball"));
}

/// Events without their strike would read as a stroke that hit nothing: every game refuses
/// them rather than judge a foul that never happened.
#[test]
fn a_stroke_without_its_strike_event_is_refused() {
    for entry in GAMES {
        let mut game = entry.start(&MatchSettings::new(players(), 1, 0)).unwrap();
        let sim = solver(game.as_ref(), &game.layout().unwrap());
        let layout = layout_of(&sim);
        let r = game.judge(&StrokeRecord {
            events: &[],
            numbers: sim.numbers(),
            before: &layout,
            after: &layout,
            declared: Declaration::None,
        });
        assert!(r.is_err(), "{}: judged without a strike", entry.label);
    }
}

/// A table seen without its game (a replay, the HUD's pocketed list) names its balls as the
/// game whose own table it is: pool's by number (issue 48: "pocketed: 12" read as a count),
/// snooker's reds counted and colours named (WPBSA 3.1's numbering: 11 a red, 20 the pink),
/// carom's by colour (UMB: white, yellow, red).
#[test]
fn balls_are_named_by_the_game_whose_table_it_is() {
    use billiards_physics::Table;
    use billiards_rules::catalog::of_table;
    let pool = of_table(&Table::wpa_8ft());
    assert_eq!(pool.id, "nine-ball");
    assert_eq!(pool.list_words(&[]), "none");
    assert_eq!(pool.list_words(&[12]), "the 12");
    assert_eq!(pool.list_words(&[0, 3, 12]), "the 3, the 12, the cue ball");
    assert_eq!(
        ((pool.ball_word)(0), (pool.ball_word)(3)),
        ("cue ball".into(), "ball 3".into())
    );
    let snooker = of_table(&Table::snooker_12ft());
    assert_eq!(snooker.id, "snooker");
    assert_eq!(snooker.list_words(&[11]), "a red");
    assert_eq!(snooker.list_words(&[2, 11, 20]), "2 reds, the pink");
    assert_eq!((snooker.ball_word)(20), "pink");
    let carom = of_table(&Table::carom_match());
    assert_eq!(carom.id, "three-cushion");
    assert_eq!((carom.ball_word)(1), "yellow");
    assert_eq!(carom.list_words(&[0, 2]), "the white, the red");
}

/// A judgement's words name the striker once: prefixed when they do not open with the name,
/// as they are when they do (snooker's "Ann pots a red"), and prefixed when the name appears
/// only later, as the opponent's ("4 points to Ann" said of Bob's foul).
#[test]
fn a_judgement_names_its_striker_once() {
    use billiards_rules::{Judgement, Seat};
    let judged = |text: &str| Judgement {
        striker: Seat::B,
        fair: false,
        fouls: Vec::new(),
        text: text.to_owned(),
        put: Vec::new(),
        continues: false,
        end: None,
    };
    assert_eq!(
        judged("Bob pots a red: 1 point").text_by("Bob"),
        "Bob pots a red: 1 point"
    );
    assert_eq!(
        judged("legal: the 3 in the left side pocket").text_by("Bob"),
        "Bob: legal: the 3 in the left side pocket"
    );
    assert_eq!(
        judged("foul: the cue ball went in-off: 4 points to Ann").text_by("Ann"),
        "Ann: foul: the cue ball went in-off: 4 points to Ann"
    );
}
