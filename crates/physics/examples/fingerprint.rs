//! Prints a fingerprint (FNV-1a of every bit of every event: time, kind and the states after
//! it) of the soak scenes `FIRST..FIRST+N` and of a long frictionless gas, so that a change
//! meant to be a pure refactor or speed-up can be shown to change no result at all.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example fingerprint -- 2000 0   # N FIRST
//! cargo run --release -p billiards-physics --example fingerprint -- 2000 0 --pairwise
//! cargo run --release -p billiards-physics --example fingerprint -- 2000 0 --no-near
//! cargo run --release -p billiards-physics --example fingerprint -- 2000 0 --dump=/tmp/ev
//! cargo run --release -p billiards-physics --example fingerprint -- --gas=10000:200000
//! ```
//!
//! `--pairwise` turns the cluster impacts off (`SpinModel::cluster = None`: every contact
//! pair by pair, the solver before cluster impacts existed). `--no-near` fingerprints only
//! the scenes that never have a contact within the cluster reach of a third ball (found on
//! their pairwise run, conservatively: at every event instant, any touching pair approaching
//! faster than `CLUSTER_MIN_SPEED` with a third ball within its reach), twice: pairwise and
//! with cluster impacts; the two hashes are equal when those scenes keep every event.
//! `--dump=PATH` also writes every event of the soak scenes to PATH, a line each (seed,
//! index, time, kind, the positions after it, bit-exact), so that two solvers' runs can be
//! compared event by event (where a last-bit change first shows, and how it grows).
//! `--gas=BALLS:EVENTS` fingerprints only the frictionless gas of `BALLS` balls over `EVENTS`
//! events (`racks::frictionless_gas`; from 250 balls on, the cell lists, which the soak
//! scenes never use), so that a change to the cell lists can be shown to change no event.

use billiards_physics::soak::scenario;
use billiards_physics::*;
use std::io::Write;

struct Fnv(u64);

impl Fnv {
    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x100_0000_01b3);
        }
    }

    fn event(&mut self, e: &Event) {
        self.word(e.time.to_bits());
        // The kind's debug text names the event and its balls, cushion or pocket.
        for b in format!("{:?}", e.kind).bytes() {
            self.word(u64::from(b));
        }
        for s in &e.after {
            for x in [
                s.position.x,
                s.position.y,
                s.velocity.x,
                s.velocity.y,
                s.angular_velocity.x,
                s.angular_velocity.y,
                s.angular_velocity.z,
            ] {
                self.word(x.to_bits());
            }
        }
    }
}

/// `params` with the cluster impacts off.
fn pairwise(params: Params) -> Params {
    match params.model {
        Model::Spin(m) => Params {
            model: Model::Spin(SpinModel { cluster: None, ..m }),
            ..params
        },
        Model::Paper(_) => params,
    }
}

/// Runs soak scene `seed` under `params` (its own, or changed) and returns the simulation;
/// with `near` set, reports (conservatively) whether any contact had a third ball within its
/// cluster reach.
fn run(seed: u64, params: impl Fn(Params) -> Params, near: Option<&mut bool>) -> Simulation {
    let s = scenario(seed);
    let mut sim = Simulation::new(s.table, params(s.params), &s.balls).expect("a valid scene");
    let mut found = false;
    for shot in &s.shots {
        let Some(ball) = (0..sim.ball_count()).find(|&i| sim.ball(i).motion.on_table()) else {
            break;
        };
        sim.strike(ball, *shot).expect("a valid shot");
        // Errors (an event cap) are part of the result: the events so far still count.
        let _ = match (s.duration, near.is_some()) {
            (Some(d), false) => sim.advance_to(sim.time() + d).map(|_| ()),
            (None, false) => sim.run_to_rest().map(|_| ()),
            (d, true) => {
                let end = d.map_or(f64::INFINITY, |d| sim.time() + d);
                let mut count = 0;
                while let Some(t) = sim.next_event_time().filter(|&t| t <= end) {
                    found |= near_contact(&sim, &s.params, t);
                    count += 1;
                    if count > sim.params().max_events || sim.step_event().is_none() {
                        break;
                    }
                }
                // The clock ends where the scene's own run leaves it.
                if end.is_finite() && sim.time() < end {
                    let _ = sim.advance_to(end);
                }
                Ok::<(), SimError>(())
            }
        };
    }
    if let Some(near) = near {
        *near = found;
    }
    sim
}

/// Whether at time `t` some touching pair approaches faster than `CLUSTER_MIN_SPEED` with a
/// third ball within its cluster reach (the cluster model's own constants, in `params`).
fn near_contact(sim: &Simulation, params: &Params, t: f64) -> bool {
    let Model::Spin(SpinModel {
        cluster: Some(material),
        ..
    }) = params.model
    else {
        return false;
    };
    let r2 = 2.0 * params.ball.radius;
    let hertz = resolve::hertz::Hertz::elastic(&material, &params.ball);
    let states: Vec<Option<BallState>> = (0..sim.ball_count())
        .map(|i| {
            let s = sim.segment(i).state_at(t);
            s.motion.on_table().then_some(s)
        })
        .collect();
    for (a, sa) in states.iter().enumerate() {
        let Some(sa) = sa else { continue };
        for (b, sb) in states.iter().enumerate().skip(a + 1) {
            let Some(sb) = sb else { continue };
            let d = sb.position - sa.position;
            let approach = -(sb.velocity - sa.velocity).dot(d.normalized().unwrap_or(d));
            if (d.length() - r2).abs() > 1e-9
                || approach.is_nan()
                || approach <= sim::CLUSTER_MIN_SPEED
            {
                continue;
            }
            let reach = hertz.reach(approach);
            let third = states.iter().enumerate().any(|(c, sc)| {
                sc.is_some_and(|sc| {
                    c != a
                        && c != b
                        && ((sc.position - sa.position).length() - r2 < reach
                            || (sc.position - sb.position).length() - r2 < reach)
                })
            });
            if third {
                return true;
            }
        }
    }
    false
}

fn main() {
    let flags: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a.starts_with("--"))
        .collect();
    let args: Vec<u64> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .map(|a| {
            a.parse()
                .expect("usage: fingerprint N FIRST [--pairwise | --no-near]")
        })
        .collect();
    let (n, first) = (
        args.first().copied().unwrap_or(500),
        args.get(1).copied().unwrap_or(0),
    );
    let flag = |f: &str| flags.iter().any(|a| a == f);
    if let Some(spec) = flags.iter().find_map(|f| f.strip_prefix("--gas=")) {
        gas_only(spec);
        return;
    }
    if flag("--no-near") {
        let (mut hp, mut hc) = (Fnv(0xcbf2_9ce4_8422_2325), Fnv(0xcbf2_9ce4_8422_2325));
        let (mut scenes, mut events, mut impacts) = (0, 0, 0);
        for seed in first..first + n {
            let mut near = false;
            run(seed, pairwise, Some(&mut near));
            if near {
                continue;
            }
            let p = run(seed, pairwise, None);
            let c = run(seed, |p| p, None);
            p.history().events().iter().for_each(|e| hp.event(e));
            c.history().events().iter().for_each(|e| hc.event(e));
            scenes += 1;
            events += p.history().events().len();
            impacts += c.cluster_impacts();
        }
        println!(
            "{scenes} of {n} scenes without near contacts: pairwise {:016x}, clusters {:016x} \
             ({events} events, {impacts} cluster impacts)",
            hp.0, hc.0
        );
        return;
    }
    let pairwise_only = flag("--pairwise");
    let mut dump = flags
        .iter()
        .find_map(|f| f.strip_prefix("--dump="))
        .map(|path| std::io::BufWriter::new(std::fs::File::create(path).expect("dump file")));
    let mut h = Fnv(0xcbf2_9ce4_8422_2325);
    let (mut events, mut impacts) = (0usize, 0usize);
    for seed in first..first + n {
        let sim = if pairwise_only {
            run(seed, pairwise, None)
        } else {
            run(seed, |p| p, None)
        };
        for (k, e) in sim.history().events().iter().enumerate() {
            h.event(e);
            if let Some(out) = &mut dump {
                let p = e.states_after().map(|(_, s)| (s.position.x, s.position.y));
                let p: Vec<_> = p.map(|(x, y)| format!("{x:e} {y:e}")).collect();
                let kind = format!("{:?}", e.kind).replace(' ', "");
                writeln!(out, "{seed} {k} {:e} {kind} {}", e.time, p.join(" ")).expect("dump");
            }
        }
        events += sim.history().events().len();
        impacts += sim.cluster_impacts();
    }
    if impacts > 0 {
        eprintln!("{impacts} cluster impacts");
    }
    let (table, params, balls) = racks::frictionless_gas(16);
    let mut sim = Simulation::new(table, params, &balls).expect("the gas");
    for _ in 0..200_000 {
        sim.step_event();
    }
    for e in sim.history().events() {
        h.event(e);
    }
    events += sim.history().events().len();
    println!("{:016x} ({events} events)", h.0);
}

/// `--gas=BALLS:EVENTS`: the fingerprint of that gas's events alone.
fn gas_only(spec: &str) {
    let mut parts = spec.split(':').map(str::parse::<usize>);
    let (Some(Ok(balls)), Some(Ok(count)), None) = (parts.next(), parts.next(), parts.next())
    else {
        eprintln!("usage: fingerprint --gas=BALLS:EVENTS (two whole numbers)");
        std::process::exit(2);
    };
    let (table, params, rack) = racks::frictionless_gas(balls);
    let mut sim = match Simulation::new(table, params, &rack) {
        Ok(sim) => sim,
        Err(e) => {
            eprintln!("no gas of {balls} balls: {e}");
            std::process::exit(1);
        }
    };
    for _ in 0..count {
        sim.step_event();
    }
    let mut h = Fnv(0xcbf2_9ce4_8422_2325);
    sim.history().events().iter().for_each(|e| h.event(e));
    let events = sim.history().events().len();
    println!("gas of {balls} balls: {:016x} ({events} events)", h.0);
}
