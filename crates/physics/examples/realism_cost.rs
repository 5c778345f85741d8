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
//!
//! `--spread` runs 64 breaks instead of the one (the cue ball at eight places across the
//! head string, at 7, 8, 9 and 10 m/s, aimed at the 1-ball's centre and half a radius beside it), each
//! `BREAKS / 64` times a round: a break is chaotic, so one break's events (and with them its
//! cost) differ between cushion models by chance; 64 give the cost of a typical break.

use billiards_physics::*;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let only = args
        .iter()
        .position(|a| a == "--only")
        .map(|i| args.get(i + 1).cloned().unwrap_or_default());
    let spread = args.iter().any(|a| a == "--spread");
    let usage = || -> ! {
        eprintln!(
            "usage: realism_cost [BREAKS] [--only han|reflection|mathavan|alciatore] \
             [--spread], BREAKS a positive integer"
        );
        std::process::exit(2);
    };
    let n: usize = match args
        .first()
        .filter(|a| !a.starts_with("--"))
        .map(|s| s.parse())
    {
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
    // (cue ball across the head string in metres, speed m/s, aim
    // off the 1-ball's centre in radii): the one break, or 64.
    let breaks: Vec<(f64, f64, f64)> = if spread {
        let mut v = Vec::new();
        for i in 0..8 {
            for speed in [7.0, 8.0, 9.0, 10.0] {
                for off in [0.0, 0.5] {
                    v.push(((-0.7 + 0.2 * f64::from(i)) * 0.5 * table.width, speed, off));
                }
            }
        }
        v
    } else {
        vec![(0.1, 8.0, 0.0)]
    };
    let sims: Vec<Vec<Simulation>> = variants
        .iter()
        .map(|&(_, model)| {
            let params = Params {
                model: Model::Spin(model),
                ..Params::default()
            };
            breaks
                .iter()
                .map(|&(y, speed, off)| {
                    let radius = params.ball.radius;
                    let mut balls = Rack::NineBall.layout(&table, &params.ball);
                    balls[0].position = Vec2::new(-0.25 * table.length, y);
                    let to = balls[1].position - balls[0].position;
                    // `off` radii beside the centre: `off R / |to|` radians (small-angle).
                    let aim = to.angle() + off * radius / to.length();
                    let mut sim = Simulation::new(table, params, &balls).expect("a valid break");
                    sim.strike(0, Shot::new(aim, speed)).expect("a valid shot");
                    sim
                })
                .collect()
        })
        .collect();
    // Rounds interleave the variants and each keeps its fastest round, so a busy machine's
    // load (shared cores) slows every variant alike or is filtered out.
    const ROUNDS: usize = 5;
    let per_round = n.div_ceil(ROUNDS).div_ceil(breaks.len());
    let mut best = vec![f64::INFINITY; sims.len()];
    let mut counts = vec![(0.0, 0.0); sims.len()];
    for _ in 0..ROUNDS {
        for (k, set) in sims.iter().enumerate() {
            if !chosen.contains(&k) {
                continue;
            }
            let start = Instant::now();
            let (mut events, mut cushions) = (0, 0);
            for sim in (0..per_round).flat_map(|_| set) {
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
            let runs = per_round * set.len();
            let us = start.elapsed().as_secs_f64() / runs as f64 * 1e6;
            best[k] = best[k].min(us);
            counts[k] = (events as f64 / runs as f64, cushions as f64 / runs as f64);
        }
    }
    for (k, (name, _)) in variants.iter().enumerate() {
        if !chosen.contains(&k) {
            continue;
        }
        let (us, (events, cushions)) = (best[k], counts[k]);
        println!(
            "{name:<38} {us:>8.1} us per break ({:.2}x), {:>5.0} ns per event, {events:.1} events and {cushions:.1} cushion contacts a break",
            us / if best[0].is_finite() { best[0] } else { us },
            us * 1e3 / events,
        );
    }
}
