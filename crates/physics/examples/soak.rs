//! Soak test: runs many random scenes (breaks, shots, follow-up shots; every model, random
//! parameters) on all cores with every event checked, then reports. Exits non-zero on any
//! failure; each failure prints the seed that replays it.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example soak -- --scenes 100000
//! cargo run --release -p billiards-physics --example soak -- --seed 1234   # replay one
//! cargo run --release -p billiards-physics --example soak -- --clusters --scenes 100000
//! ```
//!
//! Options: `--scenes N` (default 10000), `--first-seed S` (default 0), `--threads T`
//! (default: all cores), `--seed S` (run only scene S and print it in full), `--clusters`
//! (frozen and near-frozen racks broken at break speeds and at a crawl instead:
//! [`billiards_physics::soak::cluster_scenario`]; with `--seed`, replays that scene).

use billiards_physics::check::Tolerances;
use billiards_physics::soak::{SoakConfig, cluster_scenario, run_scenario_traced, scenario, soak};
use std::io::Write;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::{Duration, Instant};

fn arg(args: &[String], name: &str) -> Option<u64> {
    let i = args.iter().position(|a| a == name)?;
    let v = args
        .get(i + 1)
        .unwrap_or_else(|| usage(&format!("{name} needs a value")));
    Some(
        v.parse()
            .unwrap_or_else(|_| usage(&format!("{name}: not a number: {v}"))),
    )
}

fn usage(msg: &str) -> ! {
    eprintln!(
        "{msg}\nusage: soak [--clusters] [--scenes N] [--first-seed S] [--threads T] | --seed S"
    );
    std::process::exit(2)
}

fn replay(seed: u64, clusters: bool) -> ! {
    let s = if clusters {
        cluster_scenario(seed)
    } else {
        scenario(seed)
    };
    println!("seed {seed}: {} scene, model {}", s.kind, s.model);
    println!("table {:?}", s.table);
    println!("params {:?}", s.params);
    println!("duration per shot {:?}", s.duration);
    for (i, b) in s.balls.iter().enumerate() {
        println!("ball {i}: {b:?}");
    }
    for shot in &s.shots {
        println!("shot {shot:?}");
    }
    // Keep the last events, printed if the scene fails.
    let keep = 40;
    let mut last = std::collections::VecDeque::new();
    let result = run_scenario_traced(&s, Tolerances::default(), &mut |e| {
        if last.len() == keep {
            last.pop_front();
        }
        last.push_back(*e);
    });
    match result {
        Ok(st) => {
            println!("ok: {st:?}");
            std::process::exit(0)
        }
        Err(v) => {
            println!("last {} events:", last.len());
            for e in &last {
                println!("  t = {:.17e} {:?} after {:?}", e.time, e.kind, e.after);
            }
            println!("FAILED: {v}");
            std::process::exit(1)
        }
    }
}

fn bar(done: u64, total: u64, start: Instant) -> String {
    const WIDTH: usize = 40;
    let frac = if total == 0 {
        1.0
    } else {
        done as f64 / total as f64
    };
    let filled = (frac * WIDTH as f64) as usize;
    let el = start.elapsed().as_secs_f64();
    let rate = done as f64 / el.max(1e-9);
    let eta = if rate > 0.0 {
        (total - done) as f64 / rate
    } else {
        0.0
    };
    format!(
        "\r[{}{}] {done}/{total} scenes  {rate:.0}/s  eta {eta:.0} s ",
        "#".repeat(filled),
        "-".repeat(WIDTH - filled)
    )
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    for a in &args {
        if a.starts_with("--")
            && ![
                "--scenes",
                "--first-seed",
                "--threads",
                "--seed",
                "--clusters",
            ]
            .contains(&a.as_str())
        {
            usage(&format!("unknown option {a}"));
        }
    }
    let clusters = args.iter().any(|a| a == "--clusters");
    if let Some(seed) = arg(&args, "--seed") {
        replay(seed, clusters);
    }
    let cfg = SoakConfig {
        scenes: arg(&args, "--scenes").unwrap_or(10_000),
        first_seed: arg(&args, "--first-seed").unwrap_or(0),
        threads: arg(&args, "--threads").unwrap_or(0) as usize,
        tolerances: Tolerances::default(),
        clusters,
    };
    let done = AtomicU64::new(0);
    let finished = AtomicBool::new(false);
    let start = Instant::now();
    let report = std::thread::scope(|s| {
        s.spawn(|| {
            while !finished.load(Ordering::Relaxed) {
                eprint!("{}", bar(done.load(Ordering::Relaxed), cfg.scenes, start));
                let _ = std::io::stderr().flush();
                std::thread::sleep(Duration::from_millis(250));
            }
            eprintln!("{}", bar(done.load(Ordering::Relaxed), cfg.scenes, start));
        });
        let r = soak(&cfg, Some(&done));
        finished.store(true, Ordering::Relaxed);
        r
    });
    let c = &report.check;
    println!(
        "soak: seeds {}..{}",
        cfg.first_seed,
        cfg.first_seed + cfg.scenes
    );
    println!("scenes              {}", report.scenes);
    println!("shots               {}", report.shots);
    println!("events              {}", c.events);
    println!("wall time           {:.1} s", report.seconds);
    println!(
        "throughput          {:.0} shots/s, {:.0} events/s",
        report.shots as f64 / report.seconds,
        c.events as f64 / report.seconds
    );
    println!("worst overlap       {:e} m", c.worst_overlap);
    println!(
        "worst energy gain   {:e} (relative; seed {})",
        c.worst_energy_gain, report.worst_energy_gain_seed
    );
    println!("worst momentum err  {:e} (relative)", c.worst_momentum);
    println!("longest burst       {} events within 1 ns", c.longest_burst);
    println!(
        "most events/shot    {} (seed {})",
        report.most_events, report.most_events_seed
    );
    println!("failures            {}", report.failures.len());
    for f in report.failures.iter().take(50) {
        println!(
            "  seed {} ({} {}): {}   replay: --seed {}",
            f.seed, f.kind, f.model, f.what, f.seed
        );
    }
    if !report.failures.is_empty() {
        std::process::exit(1);
    }
}
