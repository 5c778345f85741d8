//! The computer's success rate at three-cushion: the opening position and 20 seeded random
//! three-ball layouts on the carom match table (the default physics with the carom ball),
//! one decision each by the search every game shares ([`billiards_ai::any_game`], through
//! the game interface: `ThreeCushionMatch`), each decision then played 50 times under the
//! level's execution noise and judged by the UMB rules.
//!
//! ```sh
//! cargo run --release -p billiards-ai --example three_cushion_rate            # hard
//! cargo run --release -p billiards-ai --example three_cushion_rate -- easy 20 # level, layouts
//! ```

use billiards_ai::Level;
use billiards_ai::any_game::{Move, decide_any, layout_of};
use billiards_ai::noise::stream;
use billiards_physics::{BallSetup, Params, Shot, Simulation, Table, Vec2};
use billiards_rules::three_cushion::Ball;
use billiards_rules::three_cushion::rules::ThreeCushionMatch;
use billiards_rules::{Declaration, GameRules, Seat, StrokeRecord};
use rand::{Rng, SeedableRng};
use std::time::Instant;

/// Executions of each decision.
const TRIES: u64 = 50;

/// Layout `seed`: three balls uniformly on the cloth, at least a ball's width (plus 1 cm)
/// apart, the white to play.
fn random_layout(table: &Table, radius: f64, seed: u64) -> [Vec2; 3] {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let b = table.centre_bounds(radius);
    let mut out: Vec<Vec2> = Vec::new();
    while out.len() < 3 {
        let p = Vec2::new(rng.random_range(-b.x..b.x), rng.random_range(-b.y..b.y));
        if out.iter().all(|q| (p - *q).length() > 2.0 * radius + 0.01) {
            out.push(p);
        }
    }
    [out[0], out[1], out[2]]
}

/// Whether `shot` by the striker scores a point from the game's layout: played in the
/// solver and judged by a copy of the game.
fn scores(game: &ThreeCushionMatch, sim: &Simulation, shot: Shot) -> bool {
    let (mut sim, mut game) = (sim.clone(), game.clone());
    let cue = usize::from(game.turn().cue_ball);
    let before = layout_of(&sim);
    sim.set_record_history(true);
    if sim.strike(cue, shot).is_err() || sim.run_to_rest().is_err() {
        return false;
    }
    let events = sim.history().events().to_vec();
    let points = game.points();
    let striker = game.turn().striker.index();
    let judged = game.judge(&StrokeRecord {
        events: &events,
        numbers: sim.numbers(),
        before: &before,
        after: &layout_of(&sim),
        declared: Declaration::None,
    });
    judged.is_ok() && game.points()[striker] > points[striker]
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let level: Level = match args.first() {
        Some(s) => s.parse().unwrap_or_else(|e| panic!("{e}")),
        None => Level::Hard,
    };
    let layouts: u64 = match args.get(1) {
        Some(s) => s.parse().expect("the number of random layouts"),
        None => 20,
    };
    let table = Table::carom_match();
    let params = Params::carom();
    let r = params.ball.radius;
    let players = ["A".to_owned(), "B".to_owned()];
    let opening =
        ThreeCushionMatch::new(players.clone(), 40, table, params.ball).expect("the opening");
    let mut positions = vec![("opening".to_string(), opening)];
    for seed in 0..layouts {
        let at = random_layout(&table, r, seed);
        let game =
            ThreeCushionMatch::in_progress(players.clone(), 40, (table, params.ball), at, Seat::A)
                .expect("a layout");
        positions.push((format!("random {seed}"), game));
    }
    let noise = level.execution_noise();
    println!(
        "level {} (execution noise x{}), {TRIES} executions each",
        level.name(),
        noise.magnitude,
    );
    let (mut made, mut total, mut seconds) = (0u64, 0u64, 0.0);
    for (k, (name, game)) in positions.iter().enumerate() {
        let balls: Vec<BallSetup> = game.layout().expect("the layout");
        let sim = Simulation::new(table, params, &balls).expect("the table");
        let start = Instant::now();
        let Ok(Move::Strike(stroke)) = decide_any(game, &sim, level, k as u64) else {
            panic!("{name}: no stroke");
        };
        let dt = start.elapsed().as_secs_f64();
        seconds += dt;
        let hits = (0..TRIES)
            .filter(|&t| {
                let mut rng = stream(0xe8ec_u64 ^ k as u64, 1, t);
                scores(game, &sim, noise.apply(stroke.shot, &params, &mut rng))
            })
            .count() as u64;
        made += hits;
        total += TRIES;
        let cue = Ball::ALL[usize::from(game.turn().cue_ball)].name();
        println!(
            "{name:>10} ({cue}): plan's value {:.2}; made {hits}/{TRIES}; {dt:.2} s",
            stroke.value
        );
    }
    println!(
        "success rate {:.1} % ({made}/{total}); {:.2} s a decision",
        100.0 * made as f64 / total as f64,
        seconds / positions.len() as f64
    );
}
