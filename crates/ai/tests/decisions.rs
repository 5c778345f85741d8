//! The computer opponent's decisions: it pots what a player must pot, never aims at an
//! illegal ball, never places the cue ball on another, decides the same on one thread and
//! on four, and plays safe when nothing can be potted.

mod common;

use billiards_ai::candidates::{combo_aims, direct_aims, rail_aims};
use billiards_ai::{Decision, Layout, Level, Plan, ShotKind, decide};
use billiards_physics::{Pocket, Vec2};
use billiards_rules::{Call, Choice, CueBall, Game, GameState, Seat, ShotSummary, check_placement};
use common::*;

fn shoot(d: Decision) -> Plan {
    match d {
        Decision::Shoot(plan) => plan,
        other => panic!("expected a shot, got {other:?}"),
    }
}

/// The ball the plan means to hit first.
fn first_ball(kind: ShotKind) -> Option<u8> {
    match kind {
        ShotKind::Pot { ball, .. }
        | ShotKind::Bank { ball, .. }
        | ShotKind::Kick { ball, .. }
        | ShotKind::Safety { ball } => Some(ball),
        ShotKind::Combo { first, .. } => Some(first),
        ShotKind::Break | ShotKind::PushOut => None,
    }
}

/// A ball `d` metres from the foot-left pocket on its diagonal, and the cue ball `back`
/// metres behind it at `cut` degrees.
fn cut_layout(cut: f64) -> Vec<(u8, Vec2)> {
    let (table, _) = billiards_ai::play::table_and_params();
    let corner = Vec2::new(table.length / 2.0, table.width / 2.0);
    let dir = corner.normalized().unwrap();
    let ball = corner - dir * 0.5;
    let ghost = ball - dir * (2.0 * 0.028575);
    let cue = ghost - dir.rotated(cut.to_radians()) * 0.6;
    vec![(0, cue), (3, ball), (9, Vec2::new(-0.6, -0.4))]
}

#[test]
fn the_noiseless_player_pots_a_straight_in_ball_and_a_30_degree_cut() {
    for cut in [0.0, 30.0] {
        let state = nine_ball(&[3, 9], CueBall::AsItLies);
        let mut sim = table(&cut_layout(cut));
        let plan = shoot(decide(&state, &sim, Level::Perfect, 7).unwrap());
        let summary = run(&mut sim, &plan);
        assert_eq!(
            summary.pocket_of(3),
            Some(Pocket::FootLeft),
            "cut {cut}: {plan:?} {summary:?}"
        );
        assert!(!summary.scratch(), "cut {cut}");
        assert!(plan.success > 0.9, "cut {cut}: {plan:?}");
        let mut after = state.clone();
        assert!(after.play(&summary, plan.call).unwrap().legal());
    }
}

#[test]
fn it_never_aims_first_at_an_illegal_ball() {
    for seed in 0..12 {
        let nine = nine_ball(&[4, 5, 6, 7, 9], CueBall::AsItLies);
        let eight = {
            let mut s = eight_ball(&[1, 2, 8, 11, 12, 13], CueBall::AsItLies);
            s.group_a = Some(billiards_rules::Group::Stripes);
            s.next.legal_first = vec![11, 12, 13];
            s
        };
        for (state, numbers) in [
            (nine, vec![4, 5, 6, 7, 9]),
            (eight, vec![1, 2, 8, 11, 12, 13]),
        ] {
            let sim = table(&scattered(&numbers, seed));
            let level = if seed % 2 == 0 {
                Level::Hard
            } else {
                Level::Easy
            };
            let plan = shoot(decide(&state, &sim, level, seed).unwrap());
            let first = first_ball(plan.kind).expect("a ball is aimed at");
            assert!(
                state.next.legal_first.contains(&first),
                "seed {seed}: {plan:?}"
            );
            if let Call::Ball { ball, .. } = plan.call {
                assert!(
                    state.next.legal_first.contains(&ball),
                    "seed {seed}: {plan:?}"
                );
            }
        }
    }
}

#[test]
fn ball_in_hand_never_puts_the_cue_ball_on_another_ball() {
    let numbers: Vec<u8> = (1..=15).collect();
    for seed in 0..10 {
        let state = eight_ball(&numbers, CueBall::InHandAnywhere);
        let sim = table(&scattered(&numbers, 100 + seed));
        let plan = shoot(decide(&state, &sim, Level::Medium, seed).unwrap());
        let at = plan.place.expect("a place for the cue ball in hand");
        assert_eq!(
            check_placement(&sim, 0, at, CueBall::InHandAnywhere),
            Ok(())
        );
        for (n, p) in sim
            .balls()
            .zip(sim.numbers())
            .skip(1)
            .map(|(s, &n)| (n, s.position))
        {
            assert!((p - at).length() >= 2.0 * 0.028575 - 1e-9, "on the {n}");
        }
    }
}

/// The decision does not depend on how rayon splits the search: a one-thread pool and a
/// four-thread pool (four whatever the machine's cores, so the work really is split and
/// interleaved even on one CPU) give the same plan for the same seed.
#[test]
fn the_same_seed_decides_the_same_on_one_thread_and_on_four() {
    let pool = |n| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap()
    };
    let (one, all) = (pool(1), pool(4));
    assert_eq!(
        (one.current_num_threads(), all.current_num_threads()),
        (1, 4)
    );
    for seed in 0..4 {
        let numbers = [2, 3, 5, 8, 9];
        let state = nine_ball(
            &numbers,
            if seed % 2 == 0 {
                CueBall::AsItLies
            } else {
                CueBall::InHandAnywhere
            },
        );
        let sim = table(&scattered(&numbers, 50 + seed));
        let a = one.install(|| decide(&state, &sim, Level::Hard, seed).unwrap());
        let b = all.install(|| decide(&state, &sim, Level::Hard, seed).unwrap());
        assert_eq!(a, b, "seed {seed}");
        let c = all.install(|| decide(&state, &sim, Level::Hard, seed + 1000).unwrap());
        // Another seed draws other noise: the estimates differ even if the shot does not.
        assert_ne!(shoot(a).value, shoot(c).value, "seed {seed}");
    }
}

/// The 1 in a half ring of four balls, 1 mm off it, every 60 degrees from -90 to 90, the
/// open side facing the cue ball: every path of the 1 to a pocket, straight or off a
/// cushion, runs into the ring.
fn hidden_one() -> Vec<(u8, Vec2)> {
    let r = 0.028575;
    let centre = Vec2::new(0.3, 0.1);
    let mut balls = vec![(0, Vec2::new(-0.5, 0.1)), (1, centre)];
    for (k, n) in [2u8, 3, 4, 9].into_iter().enumerate() {
        let a = (60.0 * k as f64 - 90.0).to_radians();
        balls.push((n, centre + Vec2::from_angle(a) * (2.0 * r + 1e-3)));
    }
    balls
}

#[test]
fn a_safety_is_chosen_when_every_pot_is_blocked() {
    let balls = hidden_one();
    let numbers: Vec<u8> = balls.iter().skip(1).map(|b| b.0).collect();
    let state = nine_ball(&numbers, CueBall::AsItLies);
    let sim = table(&balls);
    let layout = Layout::of(&sim, None).unwrap();
    assert!(direct_aims(&layout, &[1]).is_empty());
    assert!(rail_aims(&layout, &[1]).is_empty());
    assert!(combo_aims(&layout, &[1], &numbers).is_empty());
    for level in [Level::Medium, Level::Hard] {
        let plan = shoot(decide(&state, &sim, level, 3).unwrap());
        assert!(
            matches!(plan.kind, ShotKind::Safety { ball: 1 }),
            "{level}: {plan:?}"
        );
        assert!(plan.foul < 0.5, "{level}: {plan:?}");
    }
}

/// A 9-ball rack after A's legal break and B's push out (WPA 2.4), `balls` on the table: A
/// chooses to shoot the table or to pass it back.
fn after_push_out(balls: &[u8]) -> GameState {
    let mut g = GameState::new(Game::NineBall, Seat::A);
    let to_rail = vec![2, 3, 4, 5];
    let break_shot = ShotSummary {
        first_contact: Some(1),
        rails_after_contact: to_rail.clone(),
        rails: to_rail,
        ..ShotSummary::default()
    };
    assert!(g.play(&break_shot, Call::None).unwrap().legal());
    let push = g.play(&ShotSummary::default(), Call::PushOut).unwrap();
    assert!(push.legal() && push.push_out);
    g.on_table = balls.to_vec();
    g.on_table.sort_unstable();
    assert_eq!(
        g.next.choices,
        vec![Choice::ShootFromHere, Choice::PassBack]
    );
    g
}

/// The 1 in a full ring of six balls, 1 mm off it: no path of the cue ball reaches it, so
/// whoever shoots fouls.
fn walled_one() -> Vec<(u8, Vec2)> {
    let r = 0.028575;
    let centre = Vec2::new(0.3, 0.1);
    let mut balls = vec![(0, Vec2::new(-0.5, 0.1)), (1, centre)];
    for (k, n) in [2u8, 3, 4, 5, 6, 9].into_iter().enumerate() {
        let a = (60.0 * k as f64 + 30.0).to_radians();
        balls.push((n, centre + Vec2::from_angle(a) * (2.0 * r + 1e-3)));
    }
    balls
}

/// The choice after a push out is searched like a shot: a straight-in ball is shot, and so
/// is a hidden 1 with an open side (a safety is there to play), but a 1 walled in on every
/// side is passed back (whoever shoots it fouls).
#[test]
fn after_a_push_out_it_shoots_what_it_can_play_and_passes_back_a_walled_in_one() {
    for (balls, want) in [
        (cut_layout(0.0), Choice::ShootFromHere),
        (hidden_one(), Choice::ShootFromHere),
        (walled_one(), Choice::PassBack),
    ] {
        let numbers: Vec<u8> = balls.iter().skip(1).map(|b| b.0).collect();
        let state = after_push_out(&numbers);
        let sim = table(&balls);
        match decide(&state, &sim, Level::Hard, 5).unwrap() {
            Decision::Choose { choice, estimate } => {
                assert_eq!(choice, want, "{numbers:?}: estimate {estimate}");
                assert!((0.0..=1.0).contains(&estimate), "{estimate}");
            }
            other => panic!("expected a choice, got {other:?}"),
        }
    }
}

/// The break (WPA 9-ball 2.3, 1.5): on each table size every searching player breaks from a
/// legal place on the head string, at one of its own places, speeds and tip heights, full
/// on the 1; the one-ply baseline keeps the break it had before the two-ply levels (three
/// places each side, 8 to 12 m/s, stun or a little draw), so it stays the same yardstick.
#[test]
fn every_searching_player_breaks_legally_from_its_own_break_set() {
    use billiards_ai::{Breaks, Player, play::table_and_params_on};
    use billiards_physics::TableChoice;
    use billiards_rules::RackStyle;
    let narrow = Level::one_ply().breaks;
    assert_eq!(
        (narrow.places, narrow.speeds, narrow.heights),
        (
            &[0.0, 0.25, 0.75][..],
            &[8.0, 10.0, 12.0][..],
            &[0.0, -0.2][..]
        )
    );
    assert_eq!((narrow.samples, narrow.rounds), (8, &[(3, 32)][..]));
    let players: [(Player, Breaks); 3] = [
        (Player::OnePly, narrow),
        (Player::Computer(Level::Hard), Level::Hard.budget().breaks),
        (
            Player::Computer(Level::Expert),
            Level::Expert.budget().breaks,
        ),
    ];
    for choice in ["7ft", "8ft", "9ft"] {
        let choice: TableChoice = choice.parse().unwrap();
        let (t, params) = table_and_params_on(choice);
        let balls = Game::NineBall.rack_styled(&t, &params.ball, 5, RackStyle::Template);
        let sim = billiards_physics::Simulation::new(t, params, &balls).unwrap();
        let state = GameState::new(Game::NineBall, Seat::A);
        let one = balls.iter().find(|b| b.number == 1).unwrap().position;
        let half = t.centre_bounds(params.ball.radius).y;
        for (player, breaks) in players {
            let plan = shoot(player.decide(&state, &sim, 11).unwrap());
            assert_eq!(plan.kind, ShotKind::Break, "{choice:?} {player}");
            let p = plan.place.expect("the breaker places the cue ball");
            let cue = sim.numbers().iter().position(|&n| n == 0).unwrap();
            assert!(
                check_placement(&sim, cue, p, CueBall::InHandBehindHeadString).is_ok(),
                "{choice:?} {player}: {p:?}"
            );
            let f = ((p - t.head_spot()).y / half).abs();
            assert!(
                breaks.places.iter().any(|&q| (q - f).abs() < 1e-9),
                "{choice:?} {player}: place {f} not in {:?}",
                breaks.places
            );
            assert!(breaks.speeds.contains(&plan.shot.speed), "{player}");
            assert!(breaks.heights.contains(&plan.shot.tip.height), "{player}");
            // Full on the 1: the aim passes through its centre.
            let aim = Vec2::new(plan.shot.angle.cos(), plan.shot.angle.sin());
            let to_one = one - p;
            assert!(aim.perp_dot(to_one).abs() < 1e-9, "{choice:?} {player}");
        }
    }
}
