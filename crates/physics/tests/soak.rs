//! A quick soak in CI: a fixed range of random scenes (breaks, shots, follow-up shots, every
//! model, random parameters), every event of every shot checked by `billiards_physics::check`.
//! About half a minute on the 2-core CI machine. The long run is
//! `cargo run --release -p billiards-physics --example soak -- --scenes 1000000`
//! (see the crate README, "Stress testing"); `SOAK_SCENES` and `SOAK_FIRST_SEED` change the
//! range here.

use billiards_physics::check::Tolerances;
use billiards_physics::soak::{SoakConfig, soak};

fn env(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
fn quick_soak_breaks_no_invariant() {
    let cfg = SoakConfig {
        scenes: env("SOAK_SCENES", 2_000),
        first_seed: env("SOAK_FIRST_SEED", 0),
        threads: 0,
        tolerances: Tolerances::default(),
    };
    let r = soak(&cfg, None);
    let c = &r.check;
    println!(
        "quick soak: {} scenes, {} shots, {} events in {:.1} s ({:.0} shots/s); worst overlap \
         {:e} m, worst energy gain {:e}, longest burst {}, most events in a shot {} (seed {})",
        r.scenes,
        r.shots,
        c.events,
        r.seconds,
        r.shots as f64 / r.seconds,
        c.worst_overlap,
        c.worst_energy_gain,
        c.longest_burst,
        r.most_events,
        r.most_events_seed
    );
    assert_eq!(r.scenes, cfg.scenes);
    let list: Vec<String> = r
        .failures
        .iter()
        .map(|f| format!("seed {} ({} {}): {}", f.seed, f.kind, f.model, f.what))
        .collect();
    assert!(
        list.is_empty(),
        "{} failing scenes (replay each with `cargo run --release -p billiards-physics \
         --example soak -- --seed N`):\n{}",
        list.len(),
        list.join("\n")
    );
}
