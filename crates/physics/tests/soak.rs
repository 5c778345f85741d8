//! A quick soak in CI: a fixed range of random scenes (breaks, shots, follow-up shots, every
//! model, random parameters), every event of every shot checked by `billiards_physics::check`.
//! About half a minute on the 2-core CI machine. The long run is
//! `cargo run --release -p billiards-physics --example soak -- --scenes 1000000`
//! (see the crate README, "Stress testing"); `SOAK_SCENES` and `SOAK_FIRST_SEED` change the
//! range here.

use billiards_physics::check::Tolerances;
use billiards_physics::soak::{SoakConfig, soak};

/// The variable `name` as a number, `default` when it is unset; a value that is not a number
/// is refused rather than silently replaced.
fn env(name: &str, default: u64) -> u64 {
    match std::env::var(name) {
        Ok(v) => v
            .parse()
            .unwrap_or_else(|_| panic!("{name}={v} is not a number")),
        Err(_) => default,
    }
}

#[test]
fn quick_soak_breaks_no_invariant() {
    let scenes = env("SOAK_SCENES", 2_000);
    assert!(scenes > 0, "SOAK_SCENES=0 would check nothing");
    let cfg = SoakConfig {
        scenes,
        first_seed: env("SOAK_FIRST_SEED", 0),
        threads: 0,
        tolerances: Tolerances::default(),
        clusters: false,
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
    // Shots were played and the monitor saw their events.
    assert!(
        r.shots > 0 && c.events > 0,
        "{} shots, {} events",
        r.shots,
        c.events
    );
    assert_no_failures(&r, "");
}

/// Fails with every failing scene of `r`, each with the command that replays it (the soak
/// example with `flags` before `--seed N`).
fn assert_no_failures(r: &billiards_physics::soak::SoakReport, flags: &str) {
    let list: Vec<String> = r
        .failures
        .iter()
        .map(|f| format!("seed {} ({} {}): {}", f.seed, f.kind, f.model, f.what))
        .collect();
    assert!(
        list.is_empty(),
        "{} failing scenes (replay each with `cargo run --release -p billiards-physics \
         --example soak -- {flags}--seed N`):\n{}",
        list.len(),
        list.join("\n")
    );
}

/// Frozen and near-frozen racks broken at break speeds and at a crawl, some spinning
/// ([`billiards_physics::soak::cluster_scenario`]): `SOAK_CLUSTER_SCENES` (default 300) scenes
/// without a violation, and cluster impacts among them.
#[test]
fn quick_cluster_soak_breaks_no_invariant() {
    let scenes = env("SOAK_CLUSTER_SCENES", 300);
    assert!(scenes > 0, "SOAK_CLUSTER_SCENES=0 would check nothing");
    let cfg = SoakConfig {
        scenes,
        first_seed: 0,
        threads: 0,
        tolerances: Tolerances::default(),
        clusters: true,
    };
    let r = soak(&cfg, None);
    assert_eq!(r.scenes, cfg.scenes);
    assert!(r.check.events > 0);
    // The scenes are what they say: most of their first shots make cluster impacts.
    let with_clusters = (0..20)
        .filter(|&seed| {
            let s = billiards_physics::soak::cluster_scenario(seed);
            let mut sim = billiards_physics::Simulation::new(s.table, s.params, &s.balls)
                .expect("a valid scene");
            sim.strike(0, s.shots[0]).expect("a valid shot");
            sim.run_to_rest().expect("it comes to rest");
            sim.cluster_impacts() > 0
        })
        .count();
    assert!(with_clusters >= 14, "{with_clusters} of 20 first shots");
    assert_no_failures(&r, "--clusters ");
}
