//! Which balls of a 9-ball box break go down, and where: for each place in the diamond, how
//! often its ball is pocketed, in the head corners, the sides or the foot corners, and how
//! often without touching a cushion first (docs/realism.md, "The break").
//!
//! ```text
//! cargo run --release -p billiards-rules --example break_where -- [--rack template|triangle] \
//!     [--cue box|y:F|..] [--speed MIN:MAX] [--aim-sd-deg D] [--breaks N] [--seed S] \
//!     [--set NAME=VALUE]..
//! ```
//!
//! Defaults: 9-ft table, triangle rack, the cue ball in the box, 10–12 m/s, no aim error,
//! 4000 breaks from seed 9137 (one stream), the game's physics (Mathavan 2010 cushion).

use billiards_physics::{EventKind, Pocket};
use billiards_rules::breaks::{BreakSpec, Cue, break_run, params};
use billiards_rules::{Game, RackStyle};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The diamond's places, in the rack's lattice order (left is +y, the table's left seen
/// from the head).
const PLACES: [&str; 9] = [
    "apex (the 1)",
    "row 2 left",
    "row 2 right",
    "left wing",
    "centre (the 9)",
    "right wing",
    "row 4 left",
    "row 4 right",
    "back",
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = |why: &str| -> ! {
        eprintln!(
            "break_where: {why}\nusage: break_where [--rack R] [--cue C] [--speed MIN:MAX] \
             [--aim-sd-deg D] [--breaks N] [--seed S] [--set NAME=VALUE]"
        );
        std::process::exit(2)
    };
    let (mut rack, mut speed, mut aim_sd, mut breaks, mut seed) =
        (RackStyle::Triangle, (10.0, 12.0), 0.0, 4000usize, 9137u64);
    let mut set = Vec::new();
    let mut cue = Cue::Box;
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let v = it
            .next()
            .unwrap_or_else(|| usage(&format!("{flag} needs a value")));
        let bad = || -> ! { usage(&format!("{flag} {v}: not understood")) };
        let num = |x: &str| x.parse::<f64>().unwrap_or_else(|_| bad());
        match flag.as_str() {
            "--cue" => cue = v.parse().unwrap_or_else(|e: String| usage(&e)),
            "--rack" => rack = v.parse().unwrap_or_else(|e: String| usage(&e)),
            "--speed" => {
                let (a, b) = v.split_once(':').unwrap_or_else(|| usage("MIN:MAX"));
                speed = (num(a), num(b));
            }
            "--aim-sd-deg" => aim_sd = num(v).to_radians(),
            "--breaks" => breaks = v.parse().unwrap_or_else(|_| bad()),
            "--seed" => seed = v.parse().unwrap_or_else(|_| bad()),
            "--set" => {
                let (k, x) = v.split_once('=').unwrap_or_else(|| usage("NAME=VALUE"));
                set.push((k.to_string(), num(x)));
            }
            _ => usage(&format!("unknown option {flag}")),
        }
    }
    let params = params(false, &set).unwrap_or_else(|e| usage(&e));
    let spec = BreakSpec {
        game: Game::NineBall,
        table: "9ft".parse().expect("a table"),
        gap: rack.gap(),
        cue,
        speed,
        aim_sd,
        tip_height: 0.0,
        elevation: 0.0,
        nine_on_spot: false,
    };
    // Per place: pocketed, head corners, sides, foot corners, with no cushion first.
    let mut n = [[0usize; 5]; 9];
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..breaks {
        let sim = break_run(&spec, &params, &mut rng).unwrap_or_else(|e| usage(&e.0));
        let mut cushions = [0usize; 10];
        for e in sim.history().events() {
            match e.kind {
                EventKind::Cushion { ball, .. } | EventKind::Jaw { ball, .. } if ball < 10 => {
                    cushions[ball] += 1
                }
                EventKind::Pocketed { ball, pocket } if (1..10).contains(&ball) => {
                    let c = &mut n[ball - 1];
                    c[0] += 1;
                    c[match pocket {
                        Pocket::HeadLeft | Pocket::HeadRight => 1,
                        Pocket::SideLeft | Pocket::SideRight => 2,
                        Pocket::FootLeft | Pocket::FootRight => 3,
                    }] += 1;
                    c[4] += usize::from(cushions[ball] == 0);
                }
                _ => {}
            }
        }
    }
    println!(
        "{breaks} breaks, seed {seed}, 9-ft, {} rack, cue ball {cue}, {}–{} m/s, aim sd {:.3}°, \
         {set:?}",
        rack.name(),
        speed.0,
        speed.1,
        aim_sd.to_degrees()
    );
    println!("| place | pocketed | head corners | sides | foot corners | no cushion first |");
    println!("|---|---|---|---|---|---|");
    let pct = |k: usize| 100.0 * k as f64 / breaks as f64;
    for (place, c) in PLACES.iter().zip(n) {
        println!(
            "| {place} | {:.1} % | {:.1} % | {:.1} % | {:.1} % | {:.1} % |",
            pct(c[0]),
            pct(c[1]),
            pct(c[2]),
            pct(c[3]),
            pct(c[4])
        );
    }
}
