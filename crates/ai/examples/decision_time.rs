//! Decision time of a level on random layouts of 9 and of 15 balls (as lies and in hand)
//! and on the break of seeded 9-ball and 8-ball racks, mean and max, on all cores.
//!
//! ```sh
//! cargo run --release -p billiards-ai --example decision_time -- hard 20
//! cargo run --release -p billiards-ai --example decision_time -- expert 10
//! cargo run --release -p billiards-ai --example decision_time -- hard 20 --mathavan
//! ```
//!
//! `--mathavan`: on Mathavan 2010's cushion, the game's default, instead of the tournaments'
//! Han 2005 (`billiards_ai::play::table_and_params`).

use billiards_ai::play::table_and_params;
use billiards_ai::{Decision, Level, decide};
use billiards_physics::{BallSetup, CushionModel, Model, Params, Simulation, Table, Vec2};
use billiards_rules::{CallRule, CueBall, Game, GameState, Seat};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::hash::{Hash, Hasher};
use std::time::Instant;

/// The tournaments' table and physics, with Mathavan's cushion if `mathavan`.
fn table_and_physics(mathavan: bool) -> (Table, Params) {
    let (table, mut params) = table_and_params();
    if mathavan && let Model::Spin(m) = &mut params.model {
        m.cushion = CushionModel::MATHAVAN_2010;
    }
    (table, params)
}

/// The cue ball and `n` object balls at random, 1 cm apart at least.
fn layout(n: u8, seed: u64, mathavan: bool) -> Simulation {
    let (table, params) = table_and_physics(mathavan);
    let r = params.ball.radius;
    let b = table.centre_bounds(r) * 0.95;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut balls: Vec<BallSetup> = Vec::new();
    for k in 0..=n {
        loop {
            let p = Vec2::new(rng.random_range(-b.x..b.x), rng.random_range(-b.y..b.y));
            if balls
                .iter()
                .all(|q| (q.position - p).length() > 2.0 * r + 0.01)
            {
                balls.push(BallSetup::at(k, p));
                break;
            }
        }
    }
    Simulation::new(table, params, &balls).unwrap()
}

fn state(n: u8, cue_ball: CueBall) -> GameState {
    let game = if n == 9 {
        Game::NineBall
    } else {
        Game::EightBall
    };
    let mut s = GameState::new(game, Seat::A);
    s.next.break_shot = false;
    s.next.cue_ball = cue_ball;
    if n == 9 {
        s.next.legal_first = vec![1];
    } else {
        s.next.legal_first = (1..=15).filter(|&b| b != 8).collect();
        s.next.call = CallRule::Optional;
    }
    s
}

/// The break of `game`'s rack from `seed`: its decision time and noisy simulations.
fn break_decision(game: Game, level: Level, seed: u64, mathavan: bool) -> (f64, usize) {
    let (table, params) = table_and_physics(mathavan);
    let balls = game.rack(&table, &params.ball, seed);
    let sim = Simulation::new(table, params, &balls).unwrap();
    let state = GameState::new(game, Seat::A);
    let start = Instant::now();
    let d = decide(&state, &sim, level, seed).unwrap();
    let sims = match d {
        Decision::Shoot(p) => p.simulations,
        Decision::Choose { .. } => 0,
    };
    (start.elapsed().as_secs_f64(), sims)
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mathavan = args.iter().any(|a| a == "--mathavan");
    args.retain(|a| a != "--mathavan");
    let level: Level = args.first().map_or(Ok(Level::Hard), |s| s.parse()).unwrap();
    let count: u64 = args.get(1).map_or(20, |s| s.parse().unwrap());
    println!(
        "{level}, {} threads, {} cushion",
        rayon::current_num_threads(),
        if mathavan {
            "Mathavan 2010"
        } else {
            "Han 2005"
        }
    );
    for game in [Game::NineBall, Game::EightBall] {
        let runs: Vec<(f64, usize)> = (0..count.min(5))
            .map(|seed| break_decision(game, level, seed, mathavan))
            .collect();
        let n = runs.len() as f64;
        println!(
            "{game:?} break: {:.3} s mean, {:.3} s max, {:.0} noisy simulations a decision",
            runs.iter().map(|r| r.0).sum::<f64>() / n,
            runs.iter().map(|r| r.0).fold(0.0, f64::max),
            runs.iter().map(|r| r.1 as f64).sum::<f64>() / n
        );
    }
    // Every layout's decision hashed: a change that keeps the search exact keeps it.
    let mut decisions = std::collections::hash_map::DefaultHasher::new();
    for n in [9u8, 15] {
        for cue_ball in [CueBall::AsItLies, CueBall::InHandAnywhere] {
            let (mut total, mut max, mut sims) = (0.0f64, 0.0f64, 0usize);
            for seed in 0..count {
                let sim = layout(n, seed, mathavan);
                let st = state(n, cue_ball);
                let start = Instant::now();
                let d = decide(&st, &sim, level, seed).unwrap();
                let secs = start.elapsed().as_secs_f64();
                format!("{d:?}").hash(&mut decisions);
                total += secs;
                max = max.max(secs);
                if let Decision::Shoot(p) = d {
                    sims += p.simulations;
                }
            }
            println!(
                "{n} balls, {cue_ball:?}: {:.3} s mean, {:.3} s max, {:.0} noisy simulations a decision",
                total / count as f64,
                max,
                sims as f64 / count as f64
            );
        }
    }
    println!("decisions hash {:016x}", decisions.finish());
}
