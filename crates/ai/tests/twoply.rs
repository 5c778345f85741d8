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

#[test]
fn explore() {
    let (state, balls) = mirror_pair();
    let sim = table(&balls);
    for seed in 0..4 {
        for only in [1u8, 2] {
            let mut s = state.clone();
            s.next.legal_first = vec![only];
            let one = shoot(
                decide_planned(
                    &s,
                    &sim,
                    Level::Hard.planning_noise(),
                    &Level::one_ply(),
                    seed,
                    Mode::Lean,
                )
                .unwrap(),
            );
            let two = shoot(decide(&s, &sim, Level::Hard, seed).unwrap());
            eprintln!(
                "seed {seed} only {only}: one {:?} {:.3} two {:?} {:.3}",
                one.kind, one.value, two.kind, two.value
            );
        }
        let one = shoot(
            decide_planned(
                &state,
                &sim,
                Level::Hard.planning_noise(),
                &Level::one_ply(),
                seed,
                Mode::Lean,
            )
            .unwrap(),
        );
        let two = shoot(decide(&state, &sim, Level::Hard, seed).unwrap());
        eprintln!(
            "seed {seed} both: one {:?} {:.3} two {:?} {:.3}",
            first_ball(one.kind),
            one.value,
            first_ball(two.kind),
            two.value
        );
    }
}
