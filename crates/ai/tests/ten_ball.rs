//! The computer at 10-ball (WPA section 9): it calls a ball and a pocket (or a safety, or a
//! push out) on every shot after the break, never on the break, and takes the choices the
//! rules offer after a push out (9.4) and after a ball made uncalled (9.7).

mod common;

use billiards_ai::noise::stream;
use billiards_ai::play::{execute, spot_balls, table_and_params};
use billiards_ai::{Decision, Level, Player};
use billiards_physics::{Pocket, Simulation};
use billiards_rules::{Call, Choice, Game, GameState, Seat, ShotSummary, WinReason};
use common::{scattered, table};
use rand::Rng;

/// Plays one 10-ball rack between `players` from `seed`, checking every decision's call;
/// returns how it ended and the choices taken.
fn rack(players: [Player; 2], seed: u64) -> (Option<(Seat, WinReason)>, Vec<Choice>) {
    let (t, params) = table_and_params();
    let balls = Game::TenBall.rack(&t, &params.ball, seed);
    let mut sim = Simulation::new(t, params, &balls).unwrap();
    sim.set_record_history(false);
    let mut state = GameState::new(Game::TenBall, Seat::A);
    let mut chosen = Vec::new();
    for k in 0..300u64 {
        if state.over.is_some() {
            break;
        }
        let next = state.next.clone();
        spot_balls(&mut sim, &next.spot).unwrap();
        state.next.spot.clear();
        let player = players[next.shooter.index()];
        let decision = player
            .decide(&state, &sim, stream(seed, 1, k).random())
            .unwrap();
        let plan = match decision {
            Decision::Choose { choice, .. } => {
                assert!(next.choices.contains(&choice), "{choice:?} not offered");
                state.choose(choice).unwrap();
                chosen.push(choice);
                continue;
            }
            Decision::Shoot(plan) => plan,
        };
        if next.break_shot {
            // WPA 9: no ball is called on the break.
            assert_eq!(plan.call, Call::None, "seed {seed} shot {k}: {plan:?}");
        } else {
            // WPA 9.5: a ball and a pocket, any ball on the table; or a safety (9.6), or
            // the push out when it is allowed (9.4).
            match plan.call {
                Call::Ball { ball, .. } => {
                    assert!(state.on_table.contains(&ball), "seed {seed}: {plan:?}")
                }
                Call::Safety => {}
                Call::PushOut => assert!(next.push_out_allowed, "seed {seed}: {plan:?}"),
                Call::None => panic!("seed {seed} shot {k}: no call: {plan:?}"),
            }
        }
        let noise = player.execution_noise();
        let summary = execute(&mut sim, &plan, noise, stream(seed, 2, k).random()).unwrap();
        state.play(&summary, plan.call).unwrap();
    }
    (state.over, chosen)
}

#[test]
fn wpa_9_5_every_shot_after_the_break_is_called_and_racks_end_with_the_called_10() {
    let mut tens = 0;
    for seed in 0..3 {
        let players = [Player::Computer(Level::Easy), Player::Greedy];
        let (over, _) = rack(players, seed);
        let (_, reason) = over.expect("the rack ends");
        assert!(
            matches!(reason, WinReason::TenPocketed | WinReason::ThreeFouls),
            "{reason:?}"
        );
        tens += usize::from(reason == WinReason::TenPocketed);
    }
    assert!(tens > 0, "no rack won on the called 10");
}

#[test]
fn wpa_9_4_9_7_the_computer_takes_the_push_out_and_hand_back_choices() {
    let numbers = [1, 2, 3, 5, 10];
    for seed in 0..2 {
        let sim = table(&scattered(&numbers, 40 + seed));
        // 9.7: A called the 1 in a corner and made the 4 instead: B shoots or hands back.
        let mut state = GameState::in_progress(Game::TenBall, Seat::A, vec![1, 2, 3, 4, 5, 10]);
        let shot = ShotSummary {
            first_contact: Some(1),
            pocketed: vec![(4, Pocket::SideLeft)],
            ..ShotSummary::default()
        };
        let call = Call::Ball {
            ball: 1,
            pocket: Pocket::FootLeft,
        };
        state.play(&shot, call).unwrap();
        assert_eq!(
            state.next.choices,
            [Choice::ShootFromHere, Choice::PassBack]
        );
        let level = [Level::Easy, Level::Hard][seed as usize];
        match billiards_ai::decide(&state, &sim, level, seed).unwrap() {
            Decision::Choose { choice, estimate } => {
                assert!(state.next.choices.contains(&choice));
                assert!((0.0..=1.0).contains(&estimate), "{estimate}");
            }
            other => panic!("a choice was offered, got {other:?}"),
        }
        // 9.4: after a push out, the same two options for the other player.
        let mut state = GameState::new(Game::TenBall, Seat::A);
        let broke = ShotSummary {
            first_contact: Some(1),
            rails: vec![2, 3, 4, 6],
            rails_after_contact: vec![2, 3, 4, 6],
            pocketed: vec![(4, Pocket::FootRight)],
            ..ShotSummary::default()
        };
        state.play(&broke, Call::None).unwrap();
        let push = ShotSummary {
            first_contact: Some(5),
            ..ShotSummary::default()
        };
        state.play(&push, Call::PushOut).unwrap();
        assert_eq!(state.next.shooter, Seat::B);
        let decision = billiards_ai::decide(&state, &sim, level, seed).unwrap();
        assert!(
            matches!(decision, Decision::Choose { choice, .. } if state.next.choices.contains(&choice)),
            "{decision:?}"
        );
    }
}
