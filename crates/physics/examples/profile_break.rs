//! Runs many 15-ball breaks to rest, or a frictionless gas of `n` balls, and prints the cost
//! per event; for profiling the solver (`perf record`, `valgrind --tool=callgrind`).
//!
//! ```text
//! profile_break [breaks]          # 15-ball breaks at 9 m/s (paper model)
//! profile_break spin9 [breaks]    # 9-ball breaks at 8 m/s (spin model)
//! profile_break spin15 [breaks]   # frozen 15-ball breaks at 11 m/s (spin model)
//! ... --pairwise                   # spin model with every contact pair by pair (no clusters)
//! profile_break gas [EVENTS [N..]] # 16, 100, 1000 (or N..) balls, no friction: cost per event
//! ```

use billiards_physics::*;
use std::time::Instant;

fn main() {
    let pairwise = std::env::args().any(|a| a == "--pairwise");
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--pairwise")
        .collect();
    if args.first().map(String::as_str) == Some("gas") {
        // Per-event cost for 16, 100 and 1000 balls on proportionally larger tables, measured
        // in one run so the ratios are comparable on a noisy machine.
        let events: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(100_000);
        // Ball counts after the event count (one at a time under callgrind).
        let sizes: Vec<usize> = args[2.min(args.len())..]
            .iter()
            .filter_map(|s| s.parse().ok())
            .collect();
        let sizes = if sizes.is_empty() {
            vec![16, 100, 1000]
        } else {
            sizes
        };
        let mut base = None;
        for n in sizes {
            let ns = gas_ns_per_event(n, events);
            let b = *base.get_or_insert(ns);
            println!(
                "gas of {n:>4} balls: {ns:>7.0} ns per event ({:.2}x the 16-ball cost), {:.0} events/s",
                ns / b,
                1e9 / ns
            );
        }
        return;
    }
    let mode = args.first().map(String::as_str);
    let spin = matches!(mode, Some("spin9" | "spin15"));
    let n: usize = args
        .get(usize::from(spin))
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000);
    let table = Table::wpa_8ft();
    let sim = if spin {
        // Issue 4's break: spin model, cue ball on the head string aimed at the 1-ball, 8 m/s;
        // or a frozen 15-ball rack broken at 11 m/s.
        let cluster = if pairwise {
            None
        } else {
            SpinModel::default().cluster
        };
        let params = Params {
            model: Model::Spin(SpinModel {
                cluster,
                ..SpinModel::default()
            }),
            ..Params::default()
        };
        let (rack, speed) = if mode == Some("spin9") {
            (Rack::NineBall, 8.0)
        } else {
            (Rack::Tight, 11.0)
        };
        let mut balls = rack.layout(&table, &params.ball);
        balls[0].position = Vec2::new(-0.25 * table.length, 0.1);
        let aim = (balls[1].position - balls[0].position).angle();
        let mut sim = Simulation::new(table, params, &balls).unwrap();
        sim.strike(0, Shot::new(aim, speed)).unwrap();
        sim
    } else {
        let params = Params::default();
        let balls = Rack::FifteenBall.layout(&table, &params.ball);
        let mut sim = Simulation::new(table, params, &balls).unwrap();
        sim.strike(0, Shot::new(0.0, 9.0)).unwrap();
        sim
    };
    let start = Instant::now();
    let (mut events, mut impacts) = (0, 0);
    for _ in 0..n {
        let mut s = sim.clone();
        s.run_to_rest().unwrap();
        events += s.history().events().len();
        impacts += s.cluster_impacts();
    }
    let el = start.elapsed().as_secs_f64();
    println!(
        "{n} breaks, {events} events ({:.1} a break, {:.1} cluster impacts), {:.1} us per break, \
         {:.0} ns per event",
        events as f64 / n as f64,
        impacts as f64 / n as f64,
        el / n as f64 * 1e6,
        el / events as f64 * 1e9
    );
}

/// Nanoseconds per event of a frictionless gas of `n` balls (pockets closed), after a warm-up.
fn gas_ns_per_event(n: usize, events: usize) -> f64 {
    let (table, params, balls) = racks::frictionless_gas(n);
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    for _ in 0..events / 10 {
        sim.step_event();
    }
    let start = Instant::now();
    for _ in 0..events {
        sim.step_event();
    }
    start.elapsed().as_secs_f64() / events as f64 * 1e9
}
