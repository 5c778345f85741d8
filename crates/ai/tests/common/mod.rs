//! Shared set-ups: a rules state in the middle of a rack and a resting table.

#![allow(dead_code)]

use billiards_ai::play::table_and_params;
use billiards_physics::{BallSetup, Simulation, Vec2};
use billiards_rules::{CueBall, Game, GameState, Seat, ShotSummary};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A 9-ball rack after its break with `balls` (numbers) on the table, A to shoot.
pub fn nine_ball(balls: &[u8], cue_ball: CueBall) -> GameState {
    let mut state = GameState::new(Game::NineBall, Seat::A);
    state.on_table = balls.to_vec();
    state.on_table.sort_unstable();
    state.next.break_shot = false;
    state.next.cue_ball = cue_ball;
    state.next.legal_first = vec![state.on_table[0]];
    state
}

/// An 8-ball rack after its break, the table open, `balls` on it, A to shoot.
pub fn eight_ball(balls: &[u8], cue_ball: CueBall) -> GameState {
    let mut state = GameState::new(Game::EightBall, Seat::A);
    state.on_table = balls.to_vec();
    state.on_table.sort_unstable();
    state.next.break_shot = false;
    state.next.cue_ball = cue_ball;
    state.next.legal_first = state.on_table.iter().copied().filter(|&b| b != 8).collect();
    state.next.call = billiards_rules::CallRule::Optional;
    state
}

/// The game's table with these balls (number, centre) at rest.
pub fn table(balls: &[(u8, Vec2)]) -> Simulation {
    let (table, params) = table_and_params();
    let setups: Vec<BallSetup> = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
    Simulation::new(table, params, &setups).expect("a valid layout")
}

/// The cue ball and `numbers` scattered at random (seeded), clear of each other by 1 cm.
pub fn scattered(numbers: &[u8], seed: u64) -> Vec<(u8, Vec2)> {
    let (table, params) = table_and_params();
    let r = params.ball.radius;
    let b = table.centre_bounds(r);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out: Vec<(u8, Vec2)> = Vec::new();
    for &n in std::iter::once(&0).chain(numbers) {
        loop {
            let p = Vec2::new(
                rng.random_range(-b.x..b.x) * 0.95,
                rng.random_range(-b.y..b.y) * 0.95,
            );
            if out.iter().all(|q| (q.1 - p).length() > 2.0 * r + 0.01) {
                out.push((n, p));
                break;
            }
        }
    }
    out
}

/// Strikes `plan` noiselessly (placing the cue ball first) and runs the table to rest.
pub fn run(sim: &mut Simulation, plan: &billiards_ai::Plan) -> ShotSummary {
    let cue = sim.numbers().iter().position(|&n| n == 0).unwrap();
    if let Some(p) = plan.place {
        sim.place(cue, p, Vec2::ZERO, billiards_physics::Vec3::ZERO)
            .unwrap();
    }
    sim.set_record_history(false);
    sim.strike(cue, plan.shot).unwrap();
    let mut summary = ShotSummary::default();
    while let Some(e) = sim.step_event() {
        summary.record(&e.kind, sim.numbers());
    }
    summary
}
