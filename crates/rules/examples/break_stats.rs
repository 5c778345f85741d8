//! Break statistics: many breaks of the seeded 9-ball and 8-ball racks from random places
//! behind the head string, at firm speeds, aimed at the head ball; judged by the rules.
//!
//! ```text
//! cargo run --release -p billiards-rules --example break_stats -- --breaks 1000 --seed 1
//! ```
//!
//! Options: `--breaks N` (default 1000), `--seed S` (default 1), `--game nine|eight|both`,
//! `--table 8ft|7ft` (default 8ft, the game's), `--speed MIN:MAX` (default 7:10 m/s),
//! `--gap-mm G` (rack lattice slack, default 0.05 mm), `--cue kitchen|string` (anywhere
//! behind the head string, the default, or on it as pooltool's break script places it),
//! `--mouths-in C:S` (corner and side pocket mouths in inches, after `--table`).
//! Physics: the game's defaults (spin model, Han 2005 cushion, 8-ft table with 15 mm jaws).

use billiards_physics::{
    BallSetup, Model, Params, Shot, Simulation, SpinModel, Table, Vec2, table::INCH,
};
use billiards_rules::{Call, Game, GameState, Seat, racks, summarise};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

struct Options {
    breaks: usize,
    seed: u64,
    games: Vec<Game>,
    table: Table,
    table_name: &'static str,
    speed: (f64, f64),
    gap: f64,
    on_string: bool,
}

fn options() -> Result<Options, String> {
    let mut o = Options {
        breaks: 1000,
        seed: 1,
        games: vec![Game::NineBall, Game::EightBall],
        table: Table::wpa_8ft(),
        table_name: "8-ft",
        speed: (7.0, 10.0),
        gap: billiards_rules::racks::RACK_GAP,
        on_string: false,
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let value = it.next().ok_or(format!("{flag} needs a value"))?;
        let bad = |e: &dyn std::fmt::Display| format!("{flag} {value}: {e}");
        match flag.as_str() {
            "--breaks" => o.breaks = value.parse().map_err(|e| bad(&e))?,
            "--seed" => o.seed = value.parse().map_err(|e| bad(&e))?,
            "--game" => {
                o.games = match value.as_str() {
                    "nine" | "nine-ball" => vec![Game::NineBall],
                    "eight" | "eight-ball" => vec![Game::EightBall],
                    "both" => vec![Game::NineBall, Game::EightBall],
                    _ => return Err(bad(&"expected nine, eight or both")),
                }
            }
            "--table" => {
                (o.table, o.table_name) = match value.as_str() {
                    "8ft" => (Table::wpa_8ft(), "8-ft"),
                    // WPA 7-ft playing surface: 78 x 39 in, the same pocket mouths.
                    "7ft" => (
                        Table {
                            length: 78.0 * INCH,
                            width: 39.0 * INCH,
                            ..Table::wpa_8ft()
                        },
                        "7-ft",
                    ),
                    _ => return Err(bad(&"expected 8ft or 7ft")),
                }
            }
            "--speed" => {
                let (a, b) = value.split_once(':').ok_or(bad(&"expected MIN:MAX"))?;
                o.speed = (
                    a.parse().map_err(|e| bad(&e))?,
                    b.parse().map_err(|e| bad(&e))?,
                );
            }
            "--mouths-in" => {
                let (a, b) = value.split_once(':').ok_or(bad(&"expected CORNER:SIDE"))?;
                o.table.corner_mouth = a.parse::<f64>().map_err(|e| bad(&e))? * INCH;
                o.table.side_mouth = b.parse::<f64>().map_err(|e| bad(&e))? * INCH;
            }
            "--gap-mm" => o.gap = value.parse::<f64>().map_err(|e| bad(&e))? * 1e-3,
            "--cue" => {
                o.on_string = match value.as_str() {
                    "kitchen" => false,
                    "string" => true,
                    _ => return Err(bad(&"expected kitchen or string")),
                }
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(o)
}

#[derive(Default)]
struct Stats {
    breaks: usize,
    with_ball: usize,
    balls: usize,
    scratches: usize,
    legal: usize,
    money_ball: usize,
    events: usize,
}

fn main() {
    let o = match options() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    // The game's defaults (src/sim.rs `table_for`, `params_from` of the default settings).
    let table = o.table.with_jaws(0.015);
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let r = params.ball.radius;
    println!(
        "{} breaks per game, seed {}, {} table ({:.3} in corner, {:.3} in side mouths) with jaws, \
         spin model, {}-{} m/s, centre ball, rack gap {} mm, cue ball {}",
        o.breaks,
        o.seed,
        o.table_name,
        o.table.corner_mouth / INCH,
        o.table.side_mouth / INCH,
        o.speed.0,
        o.speed.1,
        o.gap * 1e3,
        if o.on_string {
            "on the head string"
        } else {
            "behind the head string"
        }
    );
    for &game in &o.games {
        let mut rng = ChaCha8Rng::seed_from_u64(o.seed);
        let mut s = Stats::default();
        let start = Instant::now();
        for _ in 0..o.breaks {
            let seed = rng.random();
            let mut balls: Vec<BallSetup> = match game {
                Game::NineBall => racks::nine_ball_spaced(&table, &params.ball, seed, o.gap),
                _ => racks::eight_ball_spaced(&table, &params.ball, seed, o.gap),
            };
            // Anywhere behind the head string (the kitchen), clear of the cushions.
            let b = table.centre_bounds(r);
            let x = rng.random_range(-b.x..=table.head_spot().x);
            let cue = Vec2::new(
                if o.on_string { table.head_spot().x } else { x },
                rng.random_range(-b.y..=b.y),
            );
            balls[0].position = cue;
            let aim = (balls[1].position - cue).angle();
            let speed = rng.random_range(o.speed.0..=o.speed.1);
            let mut sim = Simulation::new(table, params, &balls).expect("valid layout");
            sim.strike(0, Shot::new(aim, speed)).expect("valid shot");
            sim.run_to_rest().expect("comes to rest");
            let summary = summarise(sim.history().events(), sim.numbers());
            let verdict = GameState::new(game, Seat::A)
                .play(&summary, Call::None)
                .expect("a break is always judged");
            let down = summary.pocketed_object_balls().count();
            s.breaks += 1;
            s.with_ball += usize::from(down > 0);
            s.balls += down;
            s.scratches += usize::from(summary.scratch());
            s.legal += usize::from(verdict.legal());
            let money = if game == Game::NineBall { 9 } else { 8 };
            s.money_ball += usize::from(summary.pocket_of(money).is_some());
            s.events += sim.history().events().len();
        }
        let n = s.breaks.max(1) as f64;
        let pct = |k: usize| 100.0 * k as f64 / n;
        println!(
            "{:<9} pocket >= 1: {:5.1} %  balls/break: {:.2}  scratch: {:4.1} %  legal: {:5.1} %  \
             {} on the break: {:3.1} %  events/break: {:.0}  ({:.1} s)",
            match game {
                Game::NineBall => "9-ball",
                Game::EightBall => "8-ball",
                Game::FreePlay => "free play",
            },
            pct(s.with_ball),
            s.balls as f64 / n,
            pct(s.scratches),
            pct(s.legal),
            if game == Game::NineBall { 9 } else { 8 },
            pct(s.money_ball),
            s.events as f64 / n,
            start.elapsed().as_secs_f64()
        );
    }
}
