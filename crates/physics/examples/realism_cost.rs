//! The cost of the realism models beside today's, in one run (issue 24): the spin model's
//! 9-ball break (cue ball on the head string, 8 m/s at the 1-ball) run to rest with each
//! cushion model and ball friction, per break and per event.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example realism_cost -- [BREAKS]
//! ```

use billiards_physics::*;
use std::time::Instant;

fn main() {
    let n: usize = match std::env::args().nth(1).map(|s| s.parse()) {
        None => 300,
        Some(Ok(n)) if n > 0 => n,
        Some(_) => {
            eprintln!("usage: realism_cost [BREAKS], BREAKS a positive integer");
            std::process::exit(2);
        }
    };
    let base = SpinModel::default();
    let variants = [
        ("Han 2005, constant mu_ball (default)", base),
        (
            "reflection",
            SpinModel {
                cushion: CushionModel::Reflect { e: 0.85 },
                ..base
            },
        ),
        (
            "Mathavan 2010",
            SpinModel {
                cushion: CushionModel::MATHAVAN_2010,
                ..base
            },
        ),
        (
            "Han 2005, speed-dependent mu_ball",
            SpinModel {
                ball_friction: BallFriction::ALCIATORE,
                ..base
            },
        ),
    ];
    let table = Table::wpa_8ft();
    let mut first = None;
    for (name, model) in variants {
        let params = Params {
            model: Model::Spin(model),
            ..Params::default()
        };
        let mut balls = Rack::NineBall.layout(&table, &params.ball);
        balls[0].position = Vec2::new(-0.25 * table.length, 0.1);
        let aim = (balls[1].position - balls[0].position).angle();
        let mut sim = Simulation::new(table, params, &balls).expect("a valid break");
        sim.strike(0, Shot::new(aim, 8.0)).expect("a valid shot");
        let start = Instant::now();
        let (mut events, mut cushions) = (0, 0);
        for _ in 0..n {
            let mut s = sim.clone();
            s.run_to_rest().expect("the break comes to rest");
            events += s.history().events().len();
            cushions += s
                .history()
                .events()
                .iter()
                .filter(|e| matches!(e.kind, EventKind::Cushion { .. }))
                .count();
        }
        let us = start.elapsed().as_secs_f64() / n as f64 * 1e6;
        let base = *first.get_or_insert(us);
        println!(
            "{name:<38} {us:>8.1} us per break ({:.2}x), {:>5.0} ns per event, {} events and {} cushion contacts a break",
            us / base,
            us * 1e3 / (events as f64 / n as f64),
            events / n,
            cushions / n
        );
    }
}
