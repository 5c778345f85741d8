//! Prints a fingerprint (FNV-1a of every bit of every event: time, kind and the states after
//! it) of the soak scenes `FIRST..FIRST+N` and of a long frictionless gas, so that a change
//! meant to be a pure refactor or speed-up can be shown to change no result at all.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example fingerprint -- 2000 0   # N FIRST
//! ```

use billiards_physics::soak::scenario;
use billiards_physics::*;

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

fn main() {
    let args: Vec<u64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("usage: fingerprint N FIRST"))
        .collect();
    let (n, first) = (
        args.first().copied().unwrap_or(500),
        args.get(1).copied().unwrap_or(0),
    );
    let mut h = Fnv(0xcbf2_9ce4_8422_2325);
    let mut events = 0usize;
    for seed in first..first + n {
        let s = scenario(seed);
        let mut sim = Simulation::new(s.table, s.params, &s.balls).expect("a valid scene");
        for shot in &s.shots {
            let Some(ball) = (0..sim.ball_count()).find(|&i| sim.ball(i).motion.on_table()) else {
                break;
            };
            sim.strike(ball, *shot).expect("a valid shot");
            // Errors (an event cap) are part of the result: the events so far still count.
            let _ = match s.duration {
                Some(d) => sim.advance_to(sim.time() + d).map(|_| ()),
                None => sim.run_to_rest().map(|_| ()),
            };
        }
        for e in sim.history().events() {
            h.event(e);
        }
        events += sim.history().events().len();
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
