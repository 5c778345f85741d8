//! The second ply: position valued by a search of the next shot (crates/ai/src/twoply.rs).

mod common;

use billiards_ai::{Decision, Level, Mode, Plan, ShotKind, decide, decide_planned};
use billiards_physics::Vec2;
use billiards_rules::{CallRule, CueBall, Game, GameState, Group, Seat};
use common::table;

fn shoot(d: Decision) -> Plan {
    match d {
        Decision::Shoot(p) => p,
        other => panic!("expected a shot, got {other:?}"),
    }
}

fn first_ball(kind: ShotKind) -> Option<u8> {
    match kind {
        ShotKind::Pot { ball, .. } | ShotKind::Bank { ball, .. } => Some(ball),
        _ => None,
    }
}

/// 8-ball, A on the solids with the 1 and the 2 left, then the 8: the cue ball in the middle
/// of the table, the 1 and the 2 straight in to the two bottom corners, mirror images of each
/// other across the middle of the table, so a stun shot on either leaves the other as the
/// mirror image of the same cut. The 8 lies towards the top left corner: clearing the 2 and
/// then the 1 (a cut leftwards) leaves the cue ball near it, the other order far from it.
fn mirror_pair() -> (GameState, Vec<(u8, Vec2)>) {
    let corner = Vec2::new(1.168, -0.584);
    let at = |f: f64| corner * f;
    let mirror = |p: Vec2| Vec2::new(-p.x, p.y);
    let balls = vec![
        (0, Vec2::ZERO),
        (1, mirror(at(0.45))),
        (2, at(0.45)),
        (8, Vec2::new(-0.75, 0.35)),
    ];
    let mut state = GameState::new(Game::EightBall, Seat::A);
    state.group_a = Some(Group::Solids);
    state.on_table = vec![1, 2, 8];
    state.next.break_shot = false;
    state.next.cue_ball = CueBall::AsItLies;
    state.next.legal_first = vec![1, 2];
    state.next.call = CallRule::Optional;
    (state, balls)
}

/// The one-ply search (the baseline's) with only `ball` legal: its best plan.
fn one_ply_on(state: &GameState, sim: &billiards_physics::Simulation, ball: u8, seed: u64) -> Plan {
    let mut s = state.clone();
    s.next.legal_first = vec![ball];
    let noise = Level::Hard.planning_noise();
    shoot(decide_planned(&s, sim, noise, &Level::one_ply(), seed, Mode::Lean).unwrap())
}

/// In [`mirror_pair`] one ply sees the same chance on the ball left either way (the mirror
/// image of one cut): its values of potting the 1 and of potting the 2 agree to 0.01, and
/// over four seeds it chooses each ball at least once (sampling noise decides). Two plies
/// see the 8 after the second pot: hard pots the 2 first on every seed, valued at least 0.05
/// above the 1.
#[test]
fn two_plies_pot_the_ball_that_leaves_an_easy_next_ball() {
    let (state, balls) = mirror_pair();
    let sim = table(&balls);
    let mut one_ply_choices = Vec::new();
    for seed in 0..4 {
        let (one, two) = (
            one_ply_on(&state, &sim, 1, seed),
            one_ply_on(&state, &sim, 2, seed),
        );
        assert_eq!(
            (first_ball(one.kind), first_ball(two.kind)),
            (Some(1), Some(2))
        );
        assert!(
            (one.value - two.value).abs() < 0.01,
            "seed {seed}: {} {}",
            one.value,
            two.value
        );
        let noise = Level::Hard.planning_noise();
        let baseline = shoot(
            decide_planned(&state, &sim, noise, &Level::one_ply(), seed, Mode::Lean).unwrap(),
        );
        one_ply_choices.push(first_ball(baseline.kind));
        let hard = shoot(decide(&state, &sim, Level::Hard, seed).unwrap());
        assert_eq!(first_ball(hard.kind), Some(2), "seed {seed}: {hard:?}");
        let mut only_one = state.clone();
        only_one.next.legal_first = vec![1];
        let other = shoot(decide(&only_one, &sim, Level::Hard, seed).unwrap());
        assert!(
            hard.value > other.value + 0.05,
            "seed {seed}: {} {}",
            hard.value,
            other.value
        );
    }
    assert!(
        one_ply_choices.contains(&Some(1)) && one_ply_choices.contains(&Some(2)),
        "{one_ply_choices:?}"
    );
}

/// The second ply's searches are seeded by the shot and the draw, so hard and expert decide
/// the same (the plan, its value and its simulation count) on one thread and on two, as they
/// lie and with ball in hand (after running more simulations than one ply: the second ply
/// ran).
#[test]
fn two_plies_decide_the_same_on_one_thread_and_on_two() {
    let pool = |n| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap()
    };
    let (one, two) = (pool(1), pool(2));
    for (k, level) in [Level::Hard, Level::Expert, Level::Hard]
        .into_iter()
        .enumerate()
    {
        let seed = 70 + k as u64;
        let numbers = [3, 4, 6, 9];
        let cue_ball = if k == 2 {
            CueBall::InHandAnywhere
        } else {
            CueBall::AsItLies
        };
        let state = common::nine_ball(&numbers, cue_ball);
        let sim = table(&common::scattered(&numbers, seed));
        let a = one.install(|| decide(&state, &sim, level, seed).unwrap());
        let b = two.install(|| decide(&state, &sim, level, seed).unwrap());
        assert_eq!(a, b, "{level} seed {seed}");
        // The second ply ran: more simulations than the one-ply search alone.
        let noise = level.planning_noise();
        let base = decide_planned(&state, &sim, noise, &Level::one_ply(), seed, Mode::Lean);
        assert!(
            shoot(a).simulations > shoot(base.unwrap()).simulations,
            "{level}"
        );
    }
}
