//! Which 9-ball break the search should offer: every place on the head string (a fraction of
//! the way to a long cushion), speed and tip height, struck under hard's noise on the racks
//! of a tournament's first games (8-ft, triangle), scored as the search scores a break.
//! Prints, per candidate, the rate of breaks that keep the table (a legal pot), the foul rate
//! and the mean value, best first.
//!
//! ```sh
//! RAYON_NUM_THREADS=1 cargo run --release -p billiards-ai --example break_study -- 12 8 1001
//! ```

use billiards_ai::evaluate::{Mode, Search, Stats};
use billiards_ai::noise::stream;
use billiards_ai::play::table_and_params_on;
use billiards_ai::{Candidate, Level, ShotKind};
use billiards_physics::{Shot, Simulation, TableChoice, TipOffset, Vec2};
use billiards_rules::{Call, Game, GameState, RackStyle, Seat};
use rand::Rng;

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: break_study RACKS SAMPLES SEED";
    let [racks, samples, seed] = &args[..] else {
        return Err(usage.into());
    };
    let racks: u64 = racks.parse().map_err(|_| usage)?;
    let samples: u64 = samples.parse().map_err(|_| usage)?;
    let tseed: u64 = seed.parse().map_err(|_| usage)?;
    let game = Game::NineBall;
    let places = [0.0, 0.25, 0.5, 0.65, 0.75, 0.85, 0.95];
    let speeds = [7.0, 8.5, 10.0, 11.5, 13.0];
    let heights = [0.2, 0.0, -0.2, -0.4];
    let mut keys = Vec::new();
    for &f in &places {
        for &v in &speeds {
            for &h in &heights {
                keys.push((f, v, h));
            }
        }
    }
    let mut totals = vec![Stats::default(); keys.len()];
    for g in 0..racks {
        let seed: u64 = stream(tseed, 3, g).random();
        let (table, params) = table_and_params_on(TableChoice::default());
        let rack_seed: u64 = stream(seed, 0, 0).random();
        let balls = game.rack_styled(&table, &params.ball, rack_seed, RackStyle::default());
        let mut sim = Simulation::new(table, params, &balls).map_err(|e| e.to_string())?;
        sim.set_record_history(false);
        let state = GameState::new(game, Seat::A);
        let spot = sim.table().head_spot();
        let half = sim.table().centre_bounds(sim.params().ball.radius).y;
        let one = sim.numbers().iter().position(|&n| n == 1).ok_or("no 1")?;
        let at1 = sim.ball(one).position;
        let at1 = Vec2::new(at1.x, at1.y);
        let cands: Vec<Candidate> = keys
            .iter()
            .map(|&(f, v, h)| {
                let p = spot + Vec2::new(0.0, f * half);
                Candidate {
                    kind: ShotKind::Break,
                    shot: Shot {
                        angle: (at1 - p).angle(),
                        speed: v,
                        tip: TipOffset {
                            side: 0.0,
                            height: h,
                        },
                        elevation: 0.0,
                    },
                    call: Call::None,
                    place: Some(p),
                    object: None,
                }
            })
            .collect();
        let search = Search {
            state: &state,
            base: sim.clone(),
            cue: sim.numbers().iter().position(|&n| n == 0).ok_or("no cue")?,
            noise: Level::Hard.planning_noise(),
            seed,
            mode: Mode::Lean,
        };
        // Common draws: every candidate from the stream 0.
        let stats: Vec<Stats> = cands
            .iter()
            .map(|c| search.evaluate(std::slice::from_ref(c), 0, 0, samples)[0])
            .collect();
        for (t, s) in totals.iter_mut().zip(stats) {
            *t = t.merged(s);
        }
        eprintln!("rack {g} done");
    }
    let mut order: Vec<usize> = (0..keys.len()).collect();
    order.sort_by(|&a, &b| totals[b].mean().total_cmp(&totals[a].mean()));
    println!("place speed height | n  keep  foul  mean");
    for i in order {
        let (f, v, h) = keys[i];
        let s = totals[i];
        println!(
            "{f:5.2} {v:5.1} {h:5.1} | {} {:.3} {:.3} {:+.3}",
            s.n,
            s.pot_rate(),
            s.fouls as f64 / s.n as f64,
            s.mean()
        );
    }
    Ok(())
}
