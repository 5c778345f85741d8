//! Drills: the standard files load, bad files are refused with their reason, and the judge
//! reads the solver's record of an attempt (solver shots and hand-made summaries).

use billiards_physics::{Params, Pocket, Shot, Vec2};
use billiards_rules::drill::{DrillError, hidden};
use billiards_rules::{Attempt, Drill, DrillScore, DrillShot, Game, Goal, ShotSummary, Zone};
use std::path::PathBuf;

fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets/drills")
}

/// A free-play drill: the cue ball and the 1 straight in to the foot right corner.
fn straight_drill(goals: &str) -> String {
    format!(
        r#"{{ "name": "t", "position": {{ "game": "free_play",
        "table": {{ "length": 2.54, "width": 1.27, "corner_mouth": 0.1143, "side_mouth": 0.127,
                    "pockets": {{ "kind": "jaws", "radius": 0.015 }} }},
        "balls": [ {{ "number": 0, "position": {{ "x": 0.0, "y": 0.0 }} }},
                   {{ "number": 1, "position": {{ "x": 0.6, "y": -0.3 }} }} ] }},
        "goals": {goals} }}"#
    )
}

fn shot(first: Option<u8>, pocketed: &[(u8, Pocket)], rest: &[(u8, (f64, f64))]) -> DrillShot {
    DrillShot {
        summary: ShotSummary {
            first_contact: first,
            pocketed: pocketed.to_vec(),
            // A rail after contact, so that a 9-ball shot pocketing nothing is no foul.
            rails_after_contact: vec![0],
            ..Default::default()
        },
        rest: rest
            .iter()
            .map(|&(n, (x, y))| (n, Vec2::new(x, y)))
            .collect(),
        ..Default::default()
    }
}

#[test]
fn every_standard_drill_loads_and_checks() {
    let all = Drill::load_dir(&assets()).unwrap();
    assert!(all.len() >= 10, "{} drills", all.len());
    let mut names = Vec::new();
    for (file, d) in &all {
        let d = d.as_ref().unwrap_or_else(|e| panic!("{file}: {e}"));
        assert!(d.tries >= 1 && !d.description.is_empty(), "{file}");
        d.simulation(Params::default()).unwrap();
        names.push(d.name.clone());
    }
    names.sort();
    names.dedup();
    assert_eq!(names.len(), all.len(), "drill names are unique");
}

#[test]
fn bad_drill_files_are_refused_with_their_reason() {
    let pot = r#"[{ "kind": "pocket", "ball": 1 }]"#;
    let err = |text: &str| Drill::from_json(text).unwrap_err();
    assert!(matches!(err("{ not json"), DrillError::Json(_)));
    assert!(matches!(err(r#"{ "name": "x" }"#), DrillError::Json(_)));
    assert!(matches!(err(&straight_drill("[]")), DrillError::NoGoal));
    let e = err(&straight_drill(r#"[{ "kind": "pocket", "ball": 5 }]"#));
    assert!(matches!(e, DrillError::NoSuchBall { ball: 5, .. }), "{e}");
    assert!(e.to_string().contains("the 5"), "{e}");
    let e = err(&straight_drill(r#"[{ "kind": "hide", "ball": 0 }]"#));
    assert!(matches!(e, DrillError::NoSuchBall { ball: 0, .. }), "{e}");
    let zero = straight_drill(pot).replace(r#""goals""#, r#""tries": 0, "goals""#);
    assert!(matches!(err(&zero), DrillError::Count(_)));
    let many = straight_drill(pot).replace(r#""goals""#, r#""shots": 99, "goals""#);
    assert!(matches!(err(&many), DrillError::Count(_)));
    // The 1 off the table, then on top of the cue ball.
    let off = straight_drill(pot).replace(r#""x": 0.6"#, r#""x": 3.0"#);
    assert!(
        matches!(err(&off), DrillError::Position(_)),
        "{}",
        err(&off)
    );
    let on = straight_drill(pot).replace(r#""x": 0.6, "y": -0.3"#, r#""x": 0.01, "y": 0.0"#);
    assert!(matches!(err(&on), DrillError::Position(_)));
    let no_cue = straight_drill(pot).replace(r#""number": 0"#, r#""number": 2"#);
    assert!(matches!(err(&no_cue), DrillError::NoCueBall));
    let zone = r#"[{ "kind": "cue_ball_in", "zone": { "shape": "circle", "centre": { "x": 0, "y": 0 }, "radius": 0 } }]"#;
    assert!(matches!(err(&straight_drill(zone)), DrillError::BadZone(_)));
    let both = r#"[{ "kind": "pocket", "ball": 1 }, { "kind": "no_pocket" }]"#;
    assert!(matches!(
        err(&straight_drill(both)),
        DrillError::Contradiction(_)
    ));
    Drill::from_json(&straight_drill(pot)).unwrap();
}

/// The solver's own shot, judged: a straight pot succeeds, the cue ball into a pocket fails.
#[test]
fn the_judge_reads_solver_shots() {
    let d = Drill::from_json(&straight_drill(
        r#"[{ "kind": "pocket", "ball": 1, "pocket": "foot_right" }, { "kind": "no_foul" }]"#,
    ))
    .unwrap();
    let play = |angle: f64, speed: f64| -> Attempt {
        let mut sim = d.simulation(Params::default()).unwrap();
        let first = sim.history().events().len();
        sim.strike(0, Shot::new(angle, speed)).unwrap();
        sim.run_to_rest().unwrap();
        d.judge(&[DrillShot::of(&sim, first)])
    };
    // At the ghost ball of the 1 for the corner (the line from the 1 to the pocket).
    let table = d.position.table;
    let corner = Vec2::new(table.length / 2.0, -table.width / 2.0);
    let one = Vec2::new(0.6, -0.3);
    let u = (corner - one).normalized().unwrap();
    let ghost = one - u * (2.0 * Params::default().ball.radius);
    let pot = play(ghost.angle(), 2.0);
    assert!(pot.success, "{pot:?}");
    assert_eq!(pot.score, 100.0);
    // Straight at the head right corner, away from the 1: a scratch, nothing potted.
    let head = Vec2::new(-table.length / 2.0, -table.width / 2.0);
    let scratch = play(head.angle(), 3.0);
    assert!(!scratch.success);
    assert_eq!(scratch.score, 0.0);
    assert!(
        scratch.reasons[0].contains("stayed on the table"),
        "{scratch:?}"
    );
    assert!(
        scratch.reasons[1].contains("cue ball was pocketed"),
        "{scratch:?}"
    );
    // Nothing played: nothing met.
    assert!(!d.judge(&[]).success);
    // The 1 in the foot-left corner, not the foot-right the goal names: the reason says
    // where it went and where it should have gone (issue 47).
    let wrong = d.judge(&[shot(Some(1), &[(1, Pocket::FootLeft)], &[(0, (0.5, 0.0))])]);
    assert!(!wrong.success);
    assert_eq!(
        wrong.reasons[0],
        "missed: pocket the 1 in the foot-right corner \
         (the 1 went in the foot-left corner, not the foot-right corner)"
    );
}

#[test]
fn the_zone_is_judged_and_scored_by_closeness() {
    let zone = r#"[{ "kind": "pocket", "ball": 1 },
        { "kind": "cue_ball_in", "zone": { "shape": "circle", "centre": { "x": 0.5, "y": 0.0 }, "radius": 0.1 } }]"#;
    let d = Drill::from_json(&straight_drill(zone)).unwrap();
    let down = [(1, Pocket::FootRight)];
    let at = |x: f64| d.judge(&[shot(Some(1), &down, &[(0, (x, 0.0))])]);
    let centre = at(0.5);
    assert!(centre.success);
    assert_eq!(centre.score, 100.0);
    let edge = at(0.59);
    assert!(edge.success && (edge.score - 77.5).abs() < 1e-9, "{edge:?}");
    let out = at(0.65);
    assert!(!out.success && out.score == 50.0, "{out:?}");
    assert!(out.reasons[1].contains("15 cm"), "{out:?}");
    // A scratch leaves no cue ball to judge.
    let scratch = d.judge(&[shot(
        Some(1),
        &[(1, Pocket::FootRight), (0, Pocket::FootRight)],
        &[],
    )]);
    assert!(!scratch.success && scratch.reasons[1].contains("pocketed"));
    // Rectangles: inside, its edge, outside.
    let r = Zone::Rect {
        min: Vec2::new(-0.2, -0.1),
        max: Vec2::new(0.2, 0.1),
    };
    assert!(r.contains(Vec2::new(0.2, 0.0)) && !r.contains(Vec2::new(0.0, 0.11)));
    assert_eq!(r.closeness(Vec2::ZERO), 1.0);
    assert!((r.closeness(Vec2::new(0.1, 0.05)) - 0.5).abs() < 1e-12);
}

/// 9-ball 7-8-9: the legal order, one visit, shots that pocket nothing.
#[test]
fn the_run_out_needs_every_ball_in_order_in_one_visit() {
    let text = std::fs::read_to_string(assets().join("08-run-out-789.json")).unwrap();
    let d = Drill::from_json(&text).unwrap();
    assert_eq!(d.position.game, Game::NineBall);
    assert_eq!(d.goals, vec![Goal::RunOut]);
    let rest = [(0, (0.0, 0.0))];
    let seven = shot(Some(7), &[(7, Pocket::FootLeft)], &rest);
    let eight = shot(Some(8), &[(8, Pocket::SideRight)], &rest);
    let nine = shot(Some(9), &[(9, Pocket::HeadRight)], &rest);
    assert!(d.continues(&[]));
    assert!(d.continues(std::slice::from_ref(&seven)));
    let all = [seven.clone(), eight.clone(), nine.clone()];
    assert!(!d.continues(&all), "three shots are the drill's most");
    let a = d.judge(&all);
    assert!(a.success && a.score == 100.0, "{a:?}");
    // The 8 hit first with the 7 on the table: a foul (WPA 6.2), the visit ends.
    let wrong = shot(Some(8), &[(8, Pocket::SideRight)], &rest);
    assert!(!d.continues(std::slice::from_ref(&wrong)));
    let a = d.judge(&[wrong]);
    assert!(
        !a.success && a.score == 0.0 && a.reasons[0].contains("foul"),
        "{a:?}"
    );
    // Two balls, then a miss: two thirds of the table.
    let miss = shot(Some(9), &[], &rest);
    let a = d.judge(&[seven.clone(), eight.clone(), miss.clone()]);
    assert!(
        !a.success && a.reasons[0].contains("shot 3 pocketed nothing"),
        "{a:?}"
    );
    assert!((a.score - 200.0 / 3.0).abs() < 1e-9);
    assert!(!d.continues(&[seven, miss]));
}

#[test]
fn a_hidden_ball_is_one_behind_another() {
    let r = Params::default().ball.radius;
    let rest = |b: (f64, f64)| {
        vec![
            (0, Vec2::ZERO),
            (1, Vec2::new(1.0, 0.0)),
            (2, Vec2::new(b.0, b.1)),
        ]
    };
    assert_eq!(hidden(&rest((0.5, 0.0)), 1, r), Some(true));
    assert_eq!(hidden(&rest((0.5, 1.9 * r)), 1, r), Some(true));
    assert_eq!(hidden(&rest((0.5, 2.1 * r)), 1, r), Some(false));
    assert_eq!(hidden(&rest((1.5, 0.0)), 1, r), Some(false), "beyond the 1");
    assert_eq!(hidden(&rest((0.5, 0.0)), 3, r), None);
    // The safety drill: the ball on (9-ball, the lowest) hidden, nothing pocketed, no foul.
    let text = std::fs::read_to_string(assets().join("09-safety.json")).unwrap();
    let d = Drill::from_json(&text).unwrap();
    let mut layout: Vec<(u8, (f64, f64))> = d
        .position
        .balls
        .iter()
        .map(|b| (b.number, (b.position.x, b.position.y)))
        .collect();
    let seen = d.judge(&[shot(Some(1), &[], &layout)]);
    assert!(
        !seen.success && seen.reasons[2].contains("can be seen"),
        "{seen:?}"
    );
    // The cue ball behind the wall of balls at x = -0.1, on the line to the 1.
    layout[0].1 = (-0.5, -0.2);
    let safe = d.judge(&[shot(Some(1), &[], &layout)]);
    assert!(safe.success, "{safe:?}");
    let potted = d.judge(&[shot(Some(1), &[(1, Pocket::FootRight)], &layout)]);
    assert!(!potted.success);
}

#[test]
fn a_score_keeps_tries_successes_and_the_best() {
    let ok = Attempt {
        success: true,
        score: 90.0,
        reasons: vec![],
        shots: 1,
    };
    let bad = Attempt {
        success: false,
        score: 40.0,
        ..ok.clone()
    };
    let mut s = DrillScore::default();
    for a in [&bad, &ok, &bad] {
        s.add(a);
    }
    assert_eq!((s.tries, s.successes, s.best), (3, 1, 90.0));
    let better = DrillScore {
        tries: 10,
        successes: 5,
        best: 80.0,
    };
    assert_eq!(s.better(better), better);
    assert_eq!(better.better(s), better);
    let json = serde_json::to_string(&s).unwrap();
    assert_eq!(serde_json::from_str::<DrillScore>(&json).unwrap(), s);
}

/// A bank counts cushions, not jaws; a kick counts the cue ball's cushions before contact.
#[test]
fn cushions_are_counted_per_ball_jaws_apart() {
    use billiards_physics::{Cushion, EventKind};
    let numbers = [0, 1];
    let mut s = DrillShot::default();
    let cushion = |ball| EventKind::Cushion {
        ball,
        cushion: Cushion::Left,
    };
    s.record(&cushion(0), &numbers);
    s.record(&EventKind::BallBall { a: 0, b: 1 }, &numbers);
    s.record(&cushion(0), &numbers);
    s.record(
        &EventKind::Jaw {
            ball: 1,
            pocket: Pocket::SideLeft,
        },
        &numbers,
    );
    s.record(
        &EventKind::Pocketed {
            ball: 1,
            pocket: Pocket::SideLeft,
        },
        &numbers,
    );
    assert_eq!(s.cue_cushions_before_contact, 1);
    assert_eq!((s.cushions_of(0), s.cushions_of(1)), (2, 0));
    assert_eq!(s.summary.first_contact, Some(1));
    let bank = r#"[{ "kind": "pocket", "ball": 1, "cushions": 1 }, { "kind": "first_contact", "ball": 1, "cushions": 1 }]"#;
    let d = Drill::from_json(&straight_drill(bank)).unwrap();
    let a = d.judge(&[s.clone()]);
    assert!(!a.success, "the jaw is no bank: {a:?}");
    assert!(
        a.reasons[0].contains("0 cushion(s)") && a.reasons[1].starts_with("met"),
        "{a:?}"
    );
    s.cushions.push((1, 1));
    assert!(d.judge(&[s]).success);
}

/// A drill's rules state: the cue ball as it lies, the ball on by the game (WPA 6.2, 3.4).
#[test]
fn a_drill_position_is_a_rack_in_progress() {
    use billiards_rules::{CueBall, GameState, Seat};
    let nine = GameState::in_progress(Game::NineBall, Seat::B, vec![9, 7, 8]);
    assert_eq!(nine.on_table, vec![7, 8, 9]);
    assert_eq!(nine.next.legal_first, vec![7]);
    assert_eq!(
        (nine.next.shooter, nine.next.cue_ball),
        (Seat::B, CueBall::AsItLies)
    );
    assert!(!nine.next.break_shot);
    let eight = GameState::in_progress(Game::EightBall, Seat::A, vec![3, 8, 12]);
    assert_eq!(eight.next.legal_first, vec![3, 12], "open table: not the 8");
    let free = GameState::in_progress(Game::FreePlay, Seat::A, vec![2, 1]);
    assert_eq!(free.next.legal_first, vec![1, 2]);
    // A drill round-trips through its JSON.
    let text = std::fs::read_to_string(assets().join("10-position-zone.json")).unwrap();
    let d = Drill::from_json(&text).unwrap();
    assert_eq!(
        Drill::from_json(&serde_json::to_string(&d).unwrap()).unwrap(),
        d
    );
    assert_eq!(d.game_state().next.legal_first, vec![1, 2]);
}

/// A drill session is a one-player game behind the interface ([`GameRules::solo`]); a try
/// given up after its first shot ([`GameRules::concede`]) ends as a miss, counted in the
/// tally, and the next try starts from the drill's position; before a shot there is nothing
/// to give up (refused, nothing counted).
#[test]
fn a_try_given_up_is_a_miss_of_a_one_player_game() {
    use billiards_rules::GameRules;
    use billiards_rules::drill_game::DrillGame;
    let drill = Drill::load(&assets().join("01-stop-shot.json")).unwrap();
    let tries = drill.tries;
    let layout = drill.position.balls.len();
    let mut game = DrillGame::new(drill, "Ann".to_owned(), Default::default()).unwrap();
    assert!(game.solo(), "a drill is one player's");
    assert!(!game.concedes());
    assert!(game.concede().is_err(), "no shot yet: nothing to give up");
    assert_eq!(game.score.tries, 0);
    assert_eq!(game.try_text(), format!("try 1 of {tries}"));

    // One shot of the try in play, then given up.
    game.shots
        .push(shot(Some(1), &[], &[(0, (0.0, 0.0)), (1, (0.5, 0.2))]));
    assert!(game.concedes());
    let end = game.concede().unwrap();
    assert_eq!(
        end.winner,
        billiards_rules::Seat::B,
        "the drill takes the try"
    );
    assert!(
        end.reason.contains("given up after 1 shot"),
        "{}",
        end.reason
    );
    assert_eq!(end.match_over, tries == 1);
    assert_eq!((game.score.tries, game.score.successes), (1, 0));
    assert_eq!(game.end(), Some(end));
    assert!(!game.concedes(), "the try is over");
    assert_eq!(
        game.try_text(),
        format!("try 1 of {tries}"),
        "the last try's"
    );
    assert_eq!(
        game.next_game().unwrap().len(),
        layout,
        "the drill's position"
    );
    assert_eq!(game.try_text(), format!("try 2 of {tries}"));
    assert_eq!(game.end(), None, "the next try in play");
}
