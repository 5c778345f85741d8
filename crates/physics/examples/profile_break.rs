//! Runs many 15-ball breaks to rest, for profiling the solver (`perf record`).

use billiards_physics::*;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000);
    let table = Table::wpa_8ft();
    let params = Params::default();
    let mut sim = Simulation::new(
        table,
        params,
        &Rack::FifteenBall.layout(&table, &params.ball),
    )
    .unwrap();
    sim.strike(
        0,
        Shot {
            angle: 0.0,
            speed: 9.0,
        },
    )
    .unwrap();
    let start = std::time::Instant::now();
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
