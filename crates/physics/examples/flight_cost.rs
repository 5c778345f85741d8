//! The cost of flight beside the cloth's events, in one run (issue 51): every event of random
//! elevated shots into a nine-ball rack (as in `tests/flight_soak.rs`) timed on its own as
//! `step_event` hands it out, by kind, against the ball-ball pairs on the cloth of the same
//! shots and of 32 level 9-ball breaks of the spin model. Each event's fastest of five rounds
//! is kept (the runs are deterministic), dropping what a loaded machine's preemption added.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example flight_cost -- [SHOTS] [--hash]
//! ```
//!
//! `--hash` times nothing: it prints one hash (FNV-1a of the `Debug` text of every event: time,
//! kind, the states after it) of the shots run to rest, so that a speed-up can be shown to
//! change no result, or which shots it moves (crates/physics/README.md, "Balls in the air:
//! cost").
//!
//! A cluster impact is resolved at its first event and recorded as one event a pair: its
//! cost is shared by them, a kind of its own. Whether a level break costs what it did before
//! flight is an instruction count against the earlier build (`profile_break spin9` under
//! callgrind; crates/physics/README.md, "Balls in the air: cost").

use billiards_physics::*;
use std::time::Instant;

/// A small deterministic generator (xorshift64*), as the flight soak's.
struct Rng(u64);

impl Rng {
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let unit = (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

/// The kinds of event timed.
const KINDS: [&str; 7] = [
    "ball-ball on the cloth, a pair",
    "ball-ball in space (a ball in the air), a pair",
    "ball-ball in a cluster impact (its cost shared by its pairs)",
    "bounce (landing, rising again)",
    "landing (onto the cloth)",
    "other on the cloth (transitions, cushions, pockets)",
    "other from the air (off the table, into a pocket)",
];

/// The kind of `e`, event `index` of `h`.
fn kind_of(e: &Event, h: &History, index: usize) -> usize {
    let flying = |s: &BallState| s.motion == Motion::Airborne || s.height > 0.0;
    match e.kind {
        EventKind::BallBall { .. } if h.impact_of(index).is_some() => 2,
        EventKind::BallBall { .. } if flying(&e.after[0]) || flying(&e.after[1]) => 1,
        EventKind::BallBall { .. } => 0,
        EventKind::Transition {
            from: Motion::Airborne,
            to,
            ..
        } => match to {
            Motion::Airborne => 3,
            Motion::Sliding | Motion::Rolling => 4,
            _ => 6,
        },
        _ => 5,
    }
}

/// Every shot's simulation, struck and ready to run.
fn shots(n: usize) -> Vec<Simulation> {
    let p = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let table = Table::wpa_8ft();
    let mut rng = Rng(51);
    (0..n)
        .map(|i| {
            let mut balls = Rack::NineBall.layout(&table, &p.ball);
            balls[0].position = Vec2::new(rng.range(-1.0, -0.5), rng.range(-0.5, 0.5));
            let aim = (balls[1].position - balls[0].position).angle();
            let angle = if i % 2 == 0 {
                aim + rng.range(-0.1, 0.1)
            } else {
                rng.range(-3.2, 3.2)
            };
            let shot = Shot {
                tip: TipOffset {
                    side: rng.range(-0.3, 0.3),
                    height: rng.range(-0.3, 0.3),
                },
                elevation: rng.range(30f64, 80.0).to_radians(),
                ..Shot::new(angle, rng.range(1.0, 8.0))
            };
            let mut sim =
                Simulation::new(table, p, &balls).expect("the cue ball clear of the rack");
            sim.strike(0, shot).expect("a valid shot");
            sim
        })
        .collect()
}

/// Every event of one round in order: its kind and nanoseconds.
fn round(sims: &[Simulation]) -> Vec<(usize, f64)> {
    let mut out = Vec::new();
    for sim in sims {
        let mut sim = sim.clone();
        // Every recorded event is handed out once, in order: the next one's index.
        let mut index = sim.history().events().len();
        loop {
            let t = Instant::now();
            let Some(e) = sim.step_event() else { break };
            let ns = t.elapsed().as_nanos() as f64;
            out.push((kind_of(&e, sim.history(), index), ns));
            index += 1;
        }
    }
    out
}

/// 32 level 9-ball breaks of the spin model, struck: the cue ball at eight places across
/// the head string, at 7, 8, 9 and 10 m/s at the 1-ball.
fn level_breaks() -> Vec<Simulation> {
    let p = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let table = Table::wpa_8ft();
    let mut out = Vec::new();
    for i in 0..8 {
        for speed in [7.0, 8.0, 9.0, 10.0] {
            let mut balls = Rack::NineBall.layout(&table, &p.ball);
            let y = (-0.7 + 0.2 * f64::from(i)) * 0.5 * table.width;
            balls[0].position = Vec2::new(-0.25 * table.length, y);
            let aim = (balls[1].position - balls[0].position).angle();
            let mut sim = Simulation::new(table, p, &balls).expect("a valid break");
            sim.strike(0, Shot::new(aim, speed)).expect("a valid shot");
            out.push(sim);
        }
    }
    out
}

/// Each kind's count and mean nanoseconds over `sims` run to rest, each event's fastest of
/// `rounds` rounds (the runs are deterministic: event k is the same every round, so its
/// fastest round drops what a loaded machine's preemption added to it).
fn timed(sims: &[Simulation], rounds: usize) -> [(f64, usize); KINDS.len()] {
    let mut fastest = round(sims);
    for _ in 1..rounds {
        for (f, (kind, ns)) in fastest.iter_mut().zip(round(sims)) {
            assert_eq!(f.0, kind, "the same event every round");
            f.1 = f.1.min(ns);
        }
    }
    let mut sum = [(0.0, 0); KINDS.len()];
    for (kind, ns) in fastest {
        sum[kind].0 += ns;
        sum[kind].1 += 1;
    }
    sum.map(|(ns, count)| (ns / count.max(1) as f64, count))
}

/// FNV-1a of the `Debug` text of every event of `sims` run to rest, and the event count.
fn hash(sims: Vec<Simulation>) -> (u64, usize) {
    let (mut h, mut events) = (0xcbf2_9ce4_8422_2325u64, 0);
    for mut sim in sims {
        while let Some(e) = sim.step_event() {
            for b in format!("{e:?}").bytes() {
                h = (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3);
            }
            events += 1;
        }
    }
    (h, events)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let hashing = args.iter().any(|a| a == "--hash");
    let n: usize = match args.iter().find(|a| *a != "--hash").map(|s| s.parse()) {
        None => 2000,
        Some(Ok(n)) if n > 0 => n,
        Some(_) => {
            eprintln!("usage: flight_cost [SHOTS] [--hash], SHOTS a positive integer");
            std::process::exit(2);
        }
    };
    if hashing {
        let (h, events) = hash(shots(n));
        println!("{h:016x} ({events} events)");
        return;
    }
    const ROUNDS: usize = 5;
    let flights = timed(&shots(n), ROUNDS);
    let breaks = timed(&level_breaks(), ROUNDS);
    let (pair, rack_pair) = (flights[0].0, breaks[0].0);
    println!(
        "{n} random elevated shots into a nine-ball rack (each event its fastest of {ROUNDS} rounds),"
    );
    println!("against a pair on the cloth of the same shots and of 32 level 9-ball breaks:");
    println!(
        "| event | count | ns an event | against a pair, these shots | against a pair, level breaks |"
    );
    println!("|---|---|---|---|---|");
    let row = |name: &str, (ns, count): (f64, usize)| {
        println!(
            "| {name} | {count} | {ns:.0} | {:.2}x | {:.2}x |",
            ns / pair,
            ns / rack_pair
        );
    };
    for (name, t) in KINDS.iter().zip(flights) {
        if t.1 > 0 {
            row(name, t);
        }
    }
    let air = [1, 3, 4, 6].map(|k| flights[k]);
    let count: usize = air.iter().map(|t| t.1).sum();
    let ns = air.iter().map(|t| t.0 * t.1 as f64).sum::<f64>() / count as f64;
    row(
        "any event of a ball in the air (pairs in space, bounces, landings, leaving)",
        (ns, count),
    );
    let count: usize = breaks.iter().map(|t| t.1).sum();
    let ns = breaks.iter().map(|t| t.0 * t.1 as f64).sum::<f64>() / count as f64;
    row("level breaks: ball-ball on the cloth, a pair", breaks[0]);
    row("level breaks: any event", (ns, count));
}
