//! The computer at snooker (WPBSA rules): it pots the red it can and nominates a colour
//! after it (2.12), places the cue ball in hand inside the D (3.4), does not pot for nothing
//! when it needs snookers, decides the same on one thread and on two, and a whole frame
//! between two computers ends with the scores its verdicts add up to and a log that
//! re-judges its recording.

use billiards_ai::any_match::{Seating, play_match};
use billiards_ai::play::MAX_SHOTS;
use billiards_ai::snooker::play::snooker_table;
use billiards_ai::{Level, Player, ShotKind, SnookerDecision, SnookerPlan, decide_snooker};
use billiards_physics::{BallSetup, Pocket, Simulation, SnookerMarks, Vec2, Vec3};
use billiards_rules::snooker::balls::{BLACK, PINK, WHITE, is_colour};
use billiards_rules::snooker::rules::SnookerGame;
use billiards_rules::snooker::{BallOn, Frame, Stroke};
use billiards_rules::{Seat, ShotSummary};

fn names() -> [String; 2] {
    ["Ann".to_owned(), "Bob".to_owned()]
}

/// The snooker table with `balls` at rest.
fn table(balls: &[(u8, Vec2)]) -> Simulation {
    let (table, params) = snooker_table();
    let setups: Vec<BallSetup> = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
    Simulation::new(table, params, &setups).expect("a valid layout")
}

/// A frame with only `on_table` left (object balls), Ann to play.
fn frame_with(on_table: &[u8]) -> Frame {
    let (table, params) = snooker_table();
    let mut f = Frame::new(names(), table, &params.ball, Seat::A).unwrap();
    f.on_table = on_table.to_vec();
    f.on_table.sort_unstable();
    f.next.in_hand = false;
    f.next.on = f.ball_on();
    f
}

fn marks() -> SnookerMarks {
    SnookerMarks::of(&snooker_table().0).unwrap()
}

/// The colours on their spots.
fn colours() -> Vec<(u8, Vec2)> {
    let m = marks();
    (16..=21).map(|c| (c, m.spot(c).unwrap())).collect()
}

fn shoot(d: SnookerDecision) -> SnookerPlan {
    match d {
        SnookerDecision::Shoot(p) => p,
        other => panic!("expected a stroke, got {other:?}"),
    }
}

/// Balls on the table: number and centre.
type Balls = Vec<(u8, Vec2)>;

/// Plays `plan` without noise; the stroke for the rules: its summary, the balls before and
/// after.
fn strike(sim: &mut Simulation, plan: &SnookerPlan) -> (ShotSummary, Balls, Balls) {
    let layout = |s: &Simulation| -> Vec<(u8, Vec2)> {
        s.balls()
            .zip(s.numbers())
            .filter(|(b, _)| b.motion.on_table())
            .map(|(b, &n)| (n, b.position))
            .collect()
    };
    let cue = sim.numbers().iter().position(|&n| n == WHITE).unwrap();
    if let Some(p) = plan.place {
        sim.place(cue, p, Vec2::ZERO, Vec3::ZERO).unwrap();
    }
    let before = layout(sim);
    sim.set_record_history(false);
    sim.strike(cue, plan.shot).unwrap();
    let mut summary = ShotSummary::default();
    while let Some(e) = sim.step_event() {
        summary.record(&e.kind, sim.numbers());
    }
    let after = layout(sim);
    (summary, before, after)
}

/// One red, 40 cm from the top-left pocket on its diagonal, the cue ball 50 cm behind it
/// at a 10-degree cut; the colours on their spots.
fn one_red() -> Vec<(u8, Vec2)> {
    let t = snooker_table().0;
    let corner = Vec2::new(t.length / 2.0, t.width / 2.0);
    let dir = corner.normalized().unwrap();
    let red = corner - dir * 0.45;
    let ghost = red - dir * 0.0525;
    let cue = ghost - dir.rotated(10f64.to_radians()) * 0.5;
    let mut balls = vec![(WHITE, cue), (7, red)];
    balls.extend(colours());
    balls
}

#[test]
fn the_only_red_is_potted_then_a_colour_is_nominated() {
    let mut sim = table(&one_red());
    let mut frame = frame_with(&[7, 16, 17, 18, 19, 20, 21]);
    let plan = shoot(decide_snooker(&frame, &sim, Level::Perfect, 3).unwrap());
    assert!(
        matches!(plan.kind, ShotKind::Pot { ball: 7, .. }),
        "{plan:?}"
    );
    assert_eq!(plan.nominated, None, "no nomination on a red");
    assert!(plan.success > 0.8, "{plan:?}");
    let (summary, before, after) = strike(&mut sim, &plan);
    assert_eq!(summary.pocket_of(7), Some(Pocket::FootLeft), "{summary:?}");
    let v = frame
        .play(Stroke {
            summary: &summary,
            nominated: plan.nominated,
            before: &before,
            after: &after,
        })
        .unwrap();
    assert_eq!((v.points, v.fair()), (1, true), "{}", v.text);
    // A colour is on: the computer nominates the one it plays (2.12).
    assert_eq!(frame.next.on, BallOn::Colour { nominated: None });
    let next = shoot(decide_snooker(&frame, &sim, Level::Perfect, 4).unwrap());
    let c = next.nominated.expect("a colour nominated after the red");
    assert!(is_colour(c), "{next:?}");
    let first = match next.kind {
        ShotKind::Pot { ball, .. }
        | ShotKind::Bank { ball, .. }
        | ShotKind::Kick { ball, .. }
        | ShotKind::Safety { ball } => ball,
        other => panic!("{other:?}"),
    };
    assert_eq!(first, c, "the colour nominated is the one played");
}

#[test]
fn the_cue_ball_in_hand_goes_inside_the_d_clear_of_the_balls() {
    // The break-off (3.2) and a frame later on with a colour in the D.
    let (t, params) = snooker_table();
    let m = marks();
    let start = billiards_physics::snooker::layout(
        &t,
        &params.ball,
        billiards_physics::snooker::default_cue_position(&m),
    )
    .unwrap();
    let balls: Vec<(u8, Vec2)> = start.iter().map(|b| (b.number, b.position)).collect();
    let frame = Frame::new(names(), t, &params.ball, Seat::A).unwrap();
    let mut later = one_red();
    later.retain(|b| b.0 != WHITE);
    later.push((WHITE, Vec2::new(0.5, -0.5)));
    let mut in_hand = frame_with(&[7, 16, 17, 18, 19, 20, 21]);
    in_hand.next.in_hand = true;
    for (frame, balls) in [(frame, balls), (in_hand, later)] {
        let sim = table(&balls);
        let plan = shoot(decide_snooker(&frame, &sim, Level::Medium, 1).unwrap());
        let p = plan.place.expect("a place for the cue ball in hand");
        assert!(m.in_d(p), "{p:?} is outside the D");
        for &(n, q) in balls.iter().filter(|b| b.0 != WHITE) {
            assert!((p - q).length() > 2.0 * params.ball.radius, "on ball {n}");
        }
    }
}

#[test]
fn needing_snookers_it_plays_safe_instead_of_potting_for_nothing() {
    // Pink and black left (13 points), Ann 30 behind: she needs snookers. The pink sits over
    // the top-left pocket with the cue ball straight behind it: an easy pot, for nothing.
    let t = snooker_table().0;
    let corner = Vec2::new(t.length / 2.0, t.width / 2.0);
    let dir = corner.normalized().unwrap();
    let pink = corner - dir * 0.35;
    let balls = vec![
        (WHITE, pink - dir * 0.4),
        (PINK, pink),
        (BLACK, marks().black),
    ];
    let sim = table(&balls);
    let mut frame = frame_with(&[PINK, BLACK]);
    frame.scores = [10, 40];
    assert!(frame.snookers_required(Seat::A) > 0);
    let plan = shoot(decide_snooker(&frame, &sim, Level::Hard, 5).unwrap());
    // Whatever it was built as (a safety, or a bank that never drops), it does not pot.
    assert!(
        plan.success < 0.2 && !matches!(plan.kind, ShotKind::Pot { .. }),
        "needing snookers, it should not pot the pink: {plan:?}"
    );
    let (summary, _, _) = strike(&mut sim.clone(), &plan);
    assert_eq!(summary.pocket_of(PINK), None, "{plan:?}");
    // Level, the same table is a pot.
    frame.scores = [10, 10];
    let plan = shoot(decide_snooker(&frame, &sim, Level::Hard, 5).unwrap());
    assert!(
        matches!(plan.kind, ShotKind::Pot { ball: PINK, .. }),
        "{plan:?}"
    );
}

#[test]
fn the_same_seed_decides_the_same_on_one_thread_and_on_two() {
    let (t, params) = snooker_table();
    let m = marks();
    let start = billiards_physics::snooker::layout(
        &t,
        &params.ball,
        billiards_physics::snooker::default_cue_position(&m),
    )
    .unwrap();
    let full: Vec<(u8, Vec2)> = start.iter().map(|b| (b.number, b.position)).collect();
    let break_off = Frame::new(names(), t, &params.ball, Seat::A).unwrap();
    let cases = [
        (break_off, full),
        (frame_with(&[7, 16, 17, 18, 19, 20, 21]), one_red()),
    ];
    for (frame, balls) in cases {
        let sim = table(&balls);
        let on = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| decide_snooker(&frame, &sim, Level::Hard, 11).unwrap())
        };
        assert_eq!(on(1), on(2));
    }
}

#[test]
fn a_frame_between_two_computers_adds_up_and_rejudges_from_its_recording() {
    let (table, params) = snooker_table();
    let mut game = SnookerGame::new(names(), 1, table, params.ball).unwrap();
    let players = [
        Player::Computer(Level::Medium),
        Player::Computer(Level::Easy),
    ];
    let seating = Seating {
        record: true,
        ..Seating::new(players, params, 2, MAX_SHOTS)
    };
    let run = play_match(&mut game, &seating, &mut |_| {}).unwrap();
    let frame = &game.frame;
    assert!(run.strokes > 0);
    assert_eq!(run.points, frame.scores);
    // The frame ended (or reached the stroke limit).
    match frame.end {
        Some((w, _)) => assert_eq!(run.winner, Some(w)),
        None => assert_eq!(run.strokes, MAX_SHOTS),
    }
    // The points a player's own strokes scored and the penalties the other's fouls gave
    // (WPBSA 3.15: at least 4 each) make the score.
    let t = &run.tally;
    for p in 0..2 {
        let (own, given) = (t[p].points, frame.scores[p]);
        assert!(own <= given, "{own} of {given}");
        assert!(
            given - own >= 4 * t[1 - p].fouls as u32,
            "{own} potted, {given} in all, {} fouls against",
            t[1 - p].fouls
        );
    }
    // The runs the tally counts (points in a visit: breaks, 2.8) are the frame's highest
    // breaks, and add up to the points potted.
    for (tally, highest) in t.iter().zip(frame.highest_break) {
        let best = tally.runs.iter().copied().max().unwrap_or(0);
        assert_eq!(best, highest);
        assert_eq!(tally.runs.iter().sum::<u32>(), tally.points);
    }
    // The rules log re-judges the recording stroke by stroke.
    let (rec, log) = run.recorded.first().expect("recorded");
    assert_eq!(log.strokes.len(), run.strokes);
    assert_eq!(log.check(rec), Ok(run.strokes));
}
