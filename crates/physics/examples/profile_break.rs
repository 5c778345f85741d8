//! Runs many 15-ball breaks to rest, or a frictionless gas of `n` balls, and prints the cost
//! per event; for profiling the solver (`perf record`, `valgrind --tool=callgrind`).
//!
//! ```text
//! profile_break [breaks]          # 15-ball breaks at 9 m/s
//! profile_break gas N EVENTS      # N balls, no friction, EVENTS events
//! ```

use billiards_physics::*;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("gas") {
        let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(16);
        let events: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
        let k = (n as f64 / 16.0).sqrt();
        let table = Table {
            corner_mouth: 1e-6,
            side_mouth: 1e-6,
            ..Table::scaled(k)
        };
        let params = Params {
            model: Model::Paper(PaperModel {
                mu_slide: 0.0,
                mu_roll: 0.0,
                ..PaperModel::default()
            }),
            ..Params::default()
        };
        let balls = racks::scattered(&table, &params.ball, n, 2.0, 7);
        let mut sim = Simulation::new(table, params, &balls).unwrap();
        let start = Instant::now();
        for _ in 0..events {
            sim.step_event();
        }
        let el = start.elapsed().as_secs_f64();
        println!(
            "gas of {n}: {events} events, {:.0} ns per event",
            el / events as f64 * 1e9
        );
        return;
    }
    let n: usize = args.first().and_then(|s| s.parse().ok()).unwrap_or(2000);
    let table = Table::wpa_8ft();
    let params = Params::default();
    let mut sim = Simulation::new(
        table,
        params,
        &Rack::FifteenBall.layout(&table, &params.ball),
    )
    .unwrap();
    sim.strike(0, Shot::new(0.0, 9.0)).unwrap();
    let start = Instant::now();
    let mut events = 0;
    for _ in 0..n {
        let mut s = sim.clone();
        s.run_to_rest().unwrap();
        events += s.history().events().len();
    }
    let el = start.elapsed().as_secs_f64();
    println!(
        "{n} breaks, {events} events, {:.1} us per break, {:.0} ns per event",
        el / n as f64 * 1e6,
        el / events as f64 * 1e9
    );
}
