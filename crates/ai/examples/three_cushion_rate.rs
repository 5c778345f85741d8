//! The computer's success rate at three-cushion: the opening position and 20 seeded random
//! three-ball layouts on the carom match table (the default physics with the carom ball),
//! one decision each under a level's execution noise, each decision then played 50 times
//! with that noise and judged by the UMB rules.
//!
//! ```sh
//! cargo run --release -p billiards-ai --example three_cushion_rate            # hard
//! cargo run --release -p billiards-ai --example three_cushion_rate -- easy 20 # level, layouts
//! ```

use billiards_ai::Level;
use billiards_ai::noise::stream;
use billiards_ai::three_cushion::{CaromBudget, CaromStroke, decide_three_cushion, scores};
use billiards_physics::{Params, Table, Vec2};
use billiards_rules::three_cushion::{Ball, Rules, ThreeCushionGame};
use rand::{Rng, SeedableRng};
use std::time::Instant;

/// Executions of each decision.
const TRIES: u64 = 50;

/// Layout `seed`: three balls uniformly on the cloth, at least a ball's width (plus 1 cm)
/// apart, the white to play.
fn random_layout(table: &Table, radius: f64, seed: u64) -> [Vec2; 3] {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let b = table.centre_bounds(radius);
    let mut out: Vec<Vec2> = Vec::new();
    while out.len() < 3 {
        let p = Vec2::new(rng.random_range(-b.x..b.x), rng.random_range(-b.y..b.y));
        if out.iter().all(|q| (p - *q).length() > 2.0 * radius + 0.01) {
            out.push(p);
        }
    }
    [out[0], out[1], out[2]]
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let level: Level = match args.first() {
        Some(s) => s.parse().unwrap_or_else(|e| panic!("{e}")),
        None => Level::Hard,
    };
    let layouts: u64 = match args.get(1) {
        Some(s) => s.parse().expect("the number of random layouts"),
        None => 20,
    };
    let table = Table::carom_match();
    let params = Params::carom();
    let r = params.ball.radius;
    let opening = ThreeCushionGame::new(Rules::default(), &table, r).expect("the opening");
    let mut positions = vec![(
        "opening".to_string(),
        CaromStroke {
            positions: Ball::ALL.map(|b| opening.position(b)),
            cue: Ball::White,
            opening: true,
        },
    )];
    for seed in 0..layouts {
        positions.push((
            format!("random {seed}"),
            CaromStroke {
                positions: random_layout(&table, r, seed),
                cue: Ball::White,
                opening: false,
            },
        ));
    }
    let noise = level.execution_noise();
    let budget = CaromBudget::default();
    println!(
        "level {} (execution noise x{}), {} shots tried a decision, {TRIES} executions each",
        level.name(),
        noise.magnitude,
        budget.directions * budget.speeds.len() * budget.tips.len()
    );
    let (mut made, mut total, mut found, mut seconds) = (0u64, 0u64, 0usize, 0.0);
    for (k, (name, stroke)) in positions.iter().enumerate() {
        let start = Instant::now();
        let plan = decide_three_cushion(*stroke, &table, &params, noise, &budget, k as u64)
            .expect("a decision");
        let dt = start.elapsed().as_secs_f64();
        seconds += dt;
        found += usize::from(plan.scoring > 0);
        let hits = (0..TRIES)
            .filter(|&t| {
                let mut rng = stream(0xe8ec_u64 ^ k as u64, 1, t);
                let shot = noise.apply(plan.shot, &params, &mut rng);
                scores(*stroke, &table, &params, shot) == Some(true)
            })
            .count() as u64;
        made += hits;
        total += TRIES;
        println!(
            "{name:>10}: {:4} of {} shots score without noise; plan {:.0} % under noise; \
             made {hits}/{TRIES}; {:.2} s",
            plan.scoring,
            plan.tried,
            100.0 * plan.success,
            dt
        );
    }
    println!(
        "positions with a scoring shot: {found}/{}; success rate {:.1} % ({made}/{total}); \
         {:.2} s a decision",
        positions.len(),
        100.0 * made as f64 / total as f64,
        seconds / positions.len() as f64
    );
}
