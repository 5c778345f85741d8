//! Where the 9 goes when a 9-ball break from the head spot makes it: by pocket, and how many
//! cushions it touched first, for an aim error of each standard deviation given (the physics of
//! the game's defaults; `--pairwise` resolves the rack pair by pair instead).
//!
//! ```text
//! cargo run --release -p billiards-rules --example money_ball -- [BREAKS] [--aim-sd-deg D,..] [--pairwise]
//! ```
//!
//! The break: 8-ft table, the seeded triangle rack (`racks::RACK_GAP`), the cue ball on the
//! head spot at 10 m/s, centre ball, aimed at the 1-ball's centre with a Gaussian error
//! (default 0, 0.125 (FastFiz's reference), 0.5, 1 and 2 degrees), seed 1.

use billiards_physics::{EventKind, Pocket};
use billiards_rules::Game;
use billiards_rules::breaks::{BreakSpec, Cue, break_run, params, wilson};
use billiards_rules::racks::RACK_GAP;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = |why: &str| -> ! {
        eprintln!("money_ball: {why}\nusage: money_ball [BREAKS] [--aim-sd-deg D,..] [--pairwise]");
        std::process::exit(2)
    };
    let breaks: usize = match args.first().filter(|a| !a.starts_with("--")) {
        Some(n) => match n.parse() {
            Ok(n) if n > 0 => n,
            _ => usage("BREAKS is a positive integer"),
        },
        None => 2000,
    };
    let pairwise = args.iter().any(|a| a == "--pairwise");
    let sds: Vec<f64> = match args.iter().position(|a| a == "--aim-sd-deg") {
        Some(i) => match args.get(i + 1).map(|v| {
            v.split(',')
                .map(|d| d.trim().parse::<f64>())
                .collect::<Result<Vec<_>, _>>()
        }) {
            Some(Ok(v)) if v.iter().all(|d| (0.0..=10.0).contains(d)) => v,
            _ => usage("--aim-sd-deg takes degrees from 0 to 10, comma-separated"),
        },
        None => vec![0.0, 0.125, 0.5, 1.0, 2.0],
    };
    let params = params(pairwise, &[]).unwrap_or_else(|e| usage(&e));
    println!(
        "{breaks} breaks a row, 8-ft table, head spot, 10 m/s, {}",
        if pairwise {
            "pair by pair"
        } else {
            "cluster impacts"
        }
    );
    println!("| aim sd | 9 down (95 %) | head corners | side | foot corners | no cushion first |");
    println!("|---|---|---|---|---|---|");
    for sd in sds {
        let spec = BreakSpec {
            game: Game::NineBall,
            table: "8ft".parse().expect("a table"),
            gap: RACK_GAP,
            cue: Cue::Across(0.0),
            speed: (10.0, 10.0),
            aim_sd: sd.to_radians(),
            tip_height: 0.0,
            elevation: 0.0,
            nine_on_spot: false,
        };
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let (mut down, mut head, mut side, mut foot, mut direct) = (0, 0, 0, 0, 0);
        for _ in 0..breaks {
            let sim = break_run(&spec, &params, &mut rng).unwrap_or_else(|e| usage(&e.0));
            let Some(nine) = sim.numbers().iter().position(|&n| n == 9) else {
                continue;
            };
            let mut cushions = 0;
            for e in sim.history().events() {
                match e.kind {
                    EventKind::Cushion { ball, .. } if ball == nine => cushions += 1,
                    EventKind::Pocketed { ball, pocket } if ball == nine => {
                        down += 1;
                        direct += usize::from(cushions == 0);
                        match pocket {
                            Pocket::HeadLeft | Pocket::HeadRight => head += 1,
                            Pocket::SideLeft | Pocket::SideRight => side += 1,
                            Pocket::FootLeft | Pocket::FootRight => foot += 1,
                        }
                    }
                    _ => {}
                }
            }
        }
        let (lo, hi) = wilson(down, breaks);
        println!(
            "| {sd}° | {:.1} % ({:.1}–{:.1}) | {head} | {side} | {foot} | {direct} |",
            100.0 * down as f64 / breaks as f64,
            lo,
            hi
        );
    }
}
