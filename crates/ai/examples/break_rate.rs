//! How a player's breaks end, and how often the breaker runs out: 9-ball racks on the chosen
//! table, each broken by `PLAYER` and played by it alone until its turn passes. Prints the
//! fouls, dry breaks, legal pots and break-and-run rates with Wilson 95 % intervals.
//!
//! ```sh
//! RAYON_NUM_THREADS=1 cargo run --release -p billiards-ai --example break_rate -- hard 200 3001 9ft
//! ```

use billiards_ai::noise::stream;
use billiards_ai::play::{execute, spot_balls, table_and_params_on};
use billiards_ai::{Decision, Plan, Player};
use billiards_physics::{Simulation, TableChoice};
use billiards_rules::{Game, GameState, Outcome, RackStyle, Seat};
use rand::Rng;

fn wilson(k: usize, n: usize) -> (f64, f64) {
    let (k, n, z) = (k as f64, n.max(1) as f64, 1.96);
    let p = k / n;
    let c = (p + z * z / (2.0 * n)) / (1.0 + z * z / n);
    let h = z * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt() / (1.0 + z * z / n);
    (c - h, c + h)
}

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: break_rate PLAYER RACKS SEED [7ft|8ft|9ft]";
    if args.len() < 3 {
        return Err(usage.into());
    }
    let player: Player = args[0].parse().map_err(|e| format!("{e}"))?;
    let n: u64 = args[1].parse().map_err(|_| usage)?;
    let tseed: u64 = args[2].parse().map_err(|_| usage)?;
    let (choice, style) = match args.get(3) {
        Some(t) => (
            t.parse::<TableChoice>().map_err(|e| e.to_string())?,
            RackStyle::Template,
        ),
        None => (TableChoice::default(), RackStyle::default()),
    };
    let game = Game::NineBall;
    let (mut fouls, mut dry, mut pots, mut runs) = (0, 0, 0, 0);
    // The breaks chosen: (place as a fraction of the way to a long cushion, speed, tip height).
    let mut chosen: std::collections::BTreeMap<String, usize> = Default::default();
    for g in 0..n {
        let seed: u64 = stream(tseed, 3, g).random();
        let (table, params) = table_and_params_on(choice);
        let rack_seed: u64 = stream(seed, 0, 0).random();
        let balls = game.rack_styled(&table, &params.ball, rack_seed, style);
        let mut sim = Simulation::new(table, params, &balls).map_err(|e| e.to_string())?;
        sim.set_record_history(false);
        let mut state = GameState::new(game, Seat::A);
        let mut shots = 0u64;
        loop {
            let next = state.next.clone();
            spot_balls(&mut sim, &next.spot)?;
            state.next.spot.clear();
            let plan = match player
                .decide(&state, &sim, stream(seed, 1, shots).random())
                .map_err(|e| e.to_string())?
            {
                Decision::Choose { choice, .. } => {
                    state.choose(choice).map_err(|e| e.to_string())?;
                    continue;
                }
                Decision::Shoot(plan) => plan,
            };
            if shots == 0 {
                *chosen.entry(break_key(&sim, &plan)).or_default() += 1;
            }
            let summary = execute(
                &mut sim,
                &plan,
                player.execution_noise(),
                stream(seed, 2, shots).random(),
            )?;
            let verdict = state.play(&summary, plan.call).map_err(|e| e.to_string())?;
            if shots == 0 {
                if !verdict.legal() {
                    fouls += 1;
                } else if verdict.outcome == Outcome::Continues {
                    pots += 1;
                } else if !matches!(verdict.outcome, Outcome::GameOver { .. }) {
                    dry += 1;
                }
            }
            shots += 1;
            match verdict.outcome {
                Outcome::Continues => {}
                Outcome::GameOver { winner, .. } => {
                    if winner == Seat::A && verdict.legal() {
                        runs += 1;
                        if shots == 1 {
                            pots += 1;
                        }
                    }
                    break;
                }
                _ => break,
            }
            if shots > 60 {
                break;
            }
        }
    }
    print_rates(&chosen, [fouls, dry, pots, runs], n as usize);
    Ok(())
}

/// The break a player chose, as the tally's key: the cue ball's place as a fraction of the way
/// to a long cushion, the speed and the tip height, the three things a break varies.
fn break_key(sim: &Simulation, plan: &Plan) -> String {
    let half = sim.table().centre_bounds(sim.params().ball.radius).y;
    let f = plan
        .place
        .map_or(f64::NAN, |p| ((p - sim.table().head_spot()).y / half).abs());
    format!(
        "place {f:.2} speed {:4.1} height {:+.2}",
        plan.shot.speed, plan.shot.tip.height
    )
}

/// The breaks chosen, then each outcome's count over `n` racks with its Wilson 95 % interval,
/// so small samples are read with their uncertainty.
fn print_rates(
    chosen: &std::collections::BTreeMap<String, usize>,
    [fouls, dry, pots, runs]: [usize; 4],
    n: usize,
) {
    for (k, c) in chosen {
        println!("{k}: {c}");
    }
    for (name, k) in [
        ("foul", fouls),
        ("dry", dry),
        ("legal pot", pots),
        ("break and run", runs),
    ] {
        let (lo, hi) = wilson(k, n);
        println!(
            "{name:>14}: {k:>4} of {n} = {:5.1} % ({:.1} to {:.1})",
            100.0 * k as f64 / n as f64,
            100.0 * lo,
            100.0 * hi
        );
    }
}
