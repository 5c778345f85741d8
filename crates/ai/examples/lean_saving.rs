//! What the lean mode saves: the hard level's candidates on the bench's 9-ball mid-game
//! layout, sampled in one mode (`lean` or `full`), on one thread; prints simulations, events
//! and time. `yardstick` runs as many of the issue's yardstick shots instead (the bench's:
//! the resting layout cloned, a random shot run to rest with the history on). Under
//! callgrind the instruction counts of the modes compare without the noise of a shared
//! machine:
//!
//! ```sh
//! cargo build --release -p billiards-ai --example lean_saving
//! for m in full lean yardstick; do RAYON_NUM_THREADS=1 valgrind --tool=callgrind \
//!     --callgrind-out-file=/tmp/cg.$m target/release/examples/lean_saving $m 4; done
//! ```

mod fixture;

use billiards_ai::Level;
use billiards_ai::evaluate::{Mode, Search};
use billiards_ai::play::table_and_params;
use billiards_physics::Simulation;
use std::hash::{Hash, Hasher};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let yard = args.first().is_some_and(|m| m == "yardstick");
    let mode = match args.first().map(String::as_str) {
        Some("full") => Mode::Full,
        _ => Mode::Lean,
    };
    let samples: u64 = args.get(1).map_or(16, |s| s.parse().expect("samples"));
    let (table, params) = table_and_params();
    let (state, mut base) = fixture::mid_game(table, params);
    base.set_record_history(false);
    let cands = fixture::hard_candidates(&base);
    if yard {
        return yardstick(&base, cands.len() * samples as usize);
    }
    let search = Search {
        state: &state,
        base,
        cue: 0,
        noise: Level::Hard.planning_noise(),
        seed: 1,
        mode,
    };
    let start = Instant::now();
    let stats = search.evaluate(&cands, 0, 0, samples);
    let secs = start.elapsed().as_secs_f64();
    let n: usize = stats.iter().map(|s| s.n).sum();
    let events: usize = stats.iter().map(|s| s.events).sum();
    println!(
        "{mode:?}: {n} simulations, {events} events ({:.2} a simulation), {:.3} s, {:.0} a second",
        events as f64 / n as f64,
        secs,
        n as f64 / secs
    );
    // Every candidate's totals hashed: a change that keeps the search's values exact keeps it.
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for s in &stats {
        (s.n, s.value.to_bits(), s.pots, s.fouls, s.losses, s.events).hash(&mut h);
    }
    println!("stats hash {:016x}", h.finish());
}

/// `shots` of the bench's yardstick, on this thread: the same stream of random shots.
fn yardstick(base: &Simulation, shots: usize) {
    let mut x = fixture::YARDSTICK_SEED;
    // As the bench's table: built with its history on.
    let mut on = base.clone();
    on.set_record_history(true);
    let mut events = 0;
    let start = Instant::now();
    for _ in 0..shots {
        let mut s = on.clone();
        s.set_record_history(true);
        s.strike(0, fixture::yardstick_shot(&mut x))
            .expect("a shot in the contract");
        s.run_to_rest().expect("comes to rest");
        events += s.history().events().len();
    }
    let secs = start.elapsed().as_secs_f64();
    println!(
        "yardstick: {shots} shots, {events} events ({:.2} a shot), {secs:.3} s, {:.0} a second",
        events as f64 / shots as f64,
        shots as f64 / secs
    );
}
