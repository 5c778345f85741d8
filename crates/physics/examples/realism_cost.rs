//! The cost of the realism models beside today's, in one run (issue 24): the spin model's
//! 9-ball break (cue ball on the head string, 8 m/s at the 1-ball) run to rest with each
//! cushion model and ball friction, per break and per event: the variants interleaved in five
//! rounds, each variant's fastest round reported.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example realism_cost -- [BREAKS] [--only NAME]
//! ```
//!
//! `--only han|reflection|mathavan|alciatore` runs that variant alone, for an instruction
//! count that a loaded machine cannot disturb (`valgrind --tool=callgrind`: run 5 and 55
//! breaks, the difference over 50 is one break's count).

use billiards_physics::*;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let only = args
        .iter()
        .position(|a| a == "--only")
        .map(|i| args.get(i + 1).cloned().unwrap_or_default());
    let usage = || -> ! {
        eprintln!(
            "usage: realism_cost [BREAKS] [--only han|reflection|mathavan|alciatore], \
             BREAKS a positive integer"
        );
        std::process::exit(2);
    };
    let n: usize = match args.first().filter(|a| *a != "--only").map(|s| s.parse()) {
        None => 300,
        Some(Ok(n)) if n > 0 => n,
        Some(_) => usage(),
    };
    let base = SpinModel::default();
    let variants = [
        ("Han 2005, constant mu_ball (default)", base),
        (
            "reflection",
            SpinModel {
                cushion: CushionModel::Reflect { e: 0.85 },
                ..base
            },
        ),
        (
            "Mathavan 2010",
            SpinModel {
                cushion: CushionModel::MATHAVAN_2010,
                ..base
            },
        ),
        (
            "Han 2005, speed-dependent mu_ball",
            SpinModel {
                ball_friction: BallFriction::ALCIATORE,
                ..base
            },
        ),
    ];
    let keys = ["han", "reflection", "mathavan", "alciatore"];
    let chosen: Vec<usize> = match &only {
        None => (0..variants.len()).collect(),
        Some(name) => match keys.iter().position(|k| k == name) {
            Some(k) => vec![k],
            None => usage(),
        },
    };
    let table = Table::wpa_8ft();
    let sims: Vec<Simulation> = variants
        .iter()
        .map(|&(_, model)| {
            let params = Params {
                model: Model::Spin(model),
                ..Params::default()
            };
            let mut balls = Rack::NineBall.layout(&table, &params.ball);
            balls[0].position = Vec2::new(-0.25 * table.length, 0.1);
            let aim = (balls[1].position - balls[0].position).angle();
            let mut sim = Simulation::new(table, params, &balls).expect("a valid break");
            sim.strike(0, Shot::new(aim, 8.0)).expect("a valid shot");
            sim
        })
        .collect();
    // Rounds interleave the variants and each keeps its fastest round, so a busy machine's
    // load (shared cores) slows every variant alike or is filtered out.
    const ROUNDS: usize = 5;
    let per_round = n.div_ceil(ROUNDS);
    let mut best = vec![f64::INFINITY; sims.len()];
    let mut counts = vec![(0, 0); sims.len()];
    for _ in 0..ROUNDS {
        for (k, sim) in sims.iter().enumerate() {
            if !chosen.contains(&k) {
                continue;
            }
            let start = Instant::now();
            let (mut events, mut cushions) = (0, 0);
            for _ in 0..per_round {
                let mut s = sim.clone();
                s.run_to_rest().expect("the break comes to rest");
                events += s.history().events().len();
                cushions += s
                    .history()
                    .events()
                    .iter()
                    .filter(|e| matches!(e.kind, EventKind::Cushion { .. }))
                    .count();
            }
            let us = start.elapsed().as_secs_f64() / per_round as f64 * 1e6;
            best[k] = best[k].min(us);
            counts[k] = (events / per_round, cushions / per_round);
        }
    }
    for (k, (name, _)) in variants.iter().enumerate() {
        if !chosen.contains(&k) {
            continue;
        }
        let (us, (events, cushions)) = (best[k], counts[k]);
        println!(
            "{name:<38} {us:>8.1} us per break ({:.2}x), {:>5.0} ns per event, {events} events and {cushions} cushion contacts a break",
            us / if best[0].is_finite() { best[0] } else { us },
            us * 1e3 / events as f64,
        );
    }
}
