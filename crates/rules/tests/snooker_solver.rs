//! Snooker judged on real solver runs: strokes played on the 12-ft table by a crude player
//! (straight at the centre of a ball on, seeded speeds), every verdict checked against the
//! simulation and the scores against the verdicts.

use billiards_physics::snooker::{default_cue_position, layout};
use billiards_physics::{BallSetup, Params, Shot, Simulation, SnookerMarks, Table, Vec2};
use billiards_rules::snooker::balls::{WHITE, is_colour};
use billiards_rules::snooker::{BallOn, Choice, Frame, Stroke};
use billiards_rules::{Seat, summarise};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn place_in_d(marks: &SnookerMarks, balls: &[(u8, Vec2)], r: f64) -> Vec2 {
    let base = default_cue_position(marks);
    (0..40)
        .map(|k| {
            let a = f64::from(k) * 0.7;
            base + Vec2::new(-0.02 * f64::from(k % 5), 0.1 * a.sin())
        })
        .find(|&p| {
            marks.in_d(p)
                && balls
                    .iter()
                    .all(|&(_, q)| (p - q).length() > 2.0 * r + 1e-4)
        })
        .expect("a free place in the D")
}

/// Plays up to `strokes` strokes; returns the frame and the strokes played.
fn play_frame(seed: u64, strokes: usize) -> (Frame, usize) {
    let table = Table::snooker_12ft();
    let params = Params::snooker();
    let r = params.ball.radius;
    let marks = SnookerMarks::of(&table).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let names = ["Ann".to_owned(), "Bob".to_owned()];
    let mut frame = Frame::new(names, table, &params.ball, Seat::A).unwrap();
    let mut balls: Vec<(u8, Vec2)> = layout(&table, &params.ball, default_cue_position(&marks))
        .unwrap()
        .into_iter()
        .map(|b| (b.number, b.position))
        .collect();
    let mut expected = [0u32; 2];
    let mut played = 0;
    while frame.end.is_none() && played < strokes {
        if !frame.next.choices.is_empty() {
            let choice = if frame.next.choices.contains(&Choice::Replace) && rng.random_bool(0.5) {
                Choice::Replace
            } else if let Some(&c) = frame
                .next
                .choices
                .iter()
                .find(|c| matches!(c, Choice::BlackFirst(_)))
            {
                c
            } else {
                Choice::PlayOn
            };
            if let Some(l) = frame.choose(choice).unwrap().layout {
                balls = l;
            }
        }
        if frame.next.in_hand || !balls.iter().any(|&(n, _)| n == WHITE) {
            balls.retain(|&(n, _)| n != WHITE);
            let p = place_in_d(&marks, &balls, r);
            balls.insert(0, (WHITE, p));
        }
        let on = frame.balls_on(frame.next.on);
        let targets: Vec<(u8, Vec2)> = balls
            .iter()
            .copied()
            .filter(|(n, _)| on.contains(n))
            .collect();
        let (target, tp) = targets[rng.random_range(0..targets.len())];
        let cue = balls.iter().find(|&&(n, _)| n == WHITE).unwrap().1;
        let nominated = matches!(frame.next.on, BallOn::Colour { .. }).then_some(target);
        assert!(nominated.is_none_or(is_colour));
        let setups: Vec<BallSetup> = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
        let mut sim = Simulation::new(table, params, &setups).unwrap();
        let speed = rng.random_range(1.0..4.0);
        sim.strike(0, Shot::new((tp - cue).angle(), speed)).unwrap();
        sim.run_to_rest().unwrap();
        let summary = summarise(sim.history().events(), sim.numbers());
        let after: Vec<(u8, Vec2)> = sim
            .balls()
            .zip(sim.numbers())
            .filter(|(b, _)| b.motion.on_table())
            .map(|(b, &n)| (n, b.position))
            .collect();
        let v = frame
            .play(Stroke {
                summary: &summary,
                nominated,
                before: &balls,
                after: &after,
            })
            .unwrap();
        played += 1;
        // The verdict agrees with the simulation.
        assert_eq!(v.fair(), v.fouls.is_empty());
        if v.fair() {
            assert_eq!(v.penalty, 0);
            expected[v.striker.index()] += v.points;
        } else {
            assert!(v.penalty >= 4 && v.points == 0, "{}", v.text);
            expected[v.striker.other().index()] += v.penalty;
        }
        assert_eq!(frame.scores, expected, "{}", v.text);
        assert_eq!(v.scores, expected);
        balls = after;
        for &(c, p) in &v.spots {
            balls.retain(|&(n, _)| n != c);
            balls.push((c, p));
        }
        // Every ball the frame counts on the table is on the table, and no other.
        let mut on_table: Vec<u8> = balls
            .iter()
            .map(|&(n, _)| n)
            .filter(|&n| n != WHITE)
            .collect();
        on_table.sort_unstable();
        if frame.end.is_none() {
            assert_eq!(on_table, frame.on_table, "{}", v.text);
        }
        // No two balls overlap after the spots.
        for (i, &(_, p)) in balls.iter().enumerate() {
            for &(_, q) in &balls[i + 1..] {
                assert!((p - q).length() >= 2.0 * r - 1e-9);
            }
        }
    }
    (frame, played)
}

#[test]
fn solver_strokes_are_judged_consistently_with_the_simulation() {
    let mut pots = 0;
    let mut fouls = 0;
    for seed in 0..4 {
        let (frame, played) = play_frame(seed, 150);
        assert!(played > 0);
        pots += 15 - frame.reds();
        fouls += usize::from(frame.scores.iter().any(|&s| s > 0));
    }
    assert!(
        pots + fouls > 0,
        "the crude player scored nothing in 600 strokes"
    );
}
