//! A soak of random elevated shots into a nine-ball rack: every invariant the monitor checks
//! (no overlap in space, energy never grows, no ball outside the table, momentum of contacts
//! on the cloth, no runaway event chains) holds on every shot. 2,000 shots here; the issue's
//! 200,000 with `FLIGHT_SOAK=200000 cargo test --release -p billiards-physics --test
//! flight_soak -- --ignored`. Known open failure of the full soak: shot 17,622 of seed 5151
//! (a cue ball landing in a frozen rack lifts one ball 0.7 um; its 3D contacts with its
//! touching neighbours, resolved pair by pair without the cluster impact, repeat without end
//! at one instant). Seed 5151's first 17,622 shots pass.

use billiards_physics::check::{Monitor, Tolerances};
use billiards_physics::*;

/// A small deterministic generator (xorshift64*), so a failing shot can be replayed.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// Plays `n` random elevated shots from `seed`; returns the failures, how many shots flew and
/// how many events they had and how many ball-ball contacts in the air.
fn soak(seed: u64, n: usize) -> (Vec<String>, usize, usize, usize) {
    let p = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let table = Table::wpa_8ft();
    let mut rng = Rng(seed.max(1));
    let (mut failures, mut flew, mut events, mut air_contacts) = (Vec::new(), 0, 0, 0);
    for i in 0..n {
        let mut balls = Rack::NineBall.layout(&table, &p.ball);
        balls[0].position = Vec2::new(rng.range(-1.0, -0.5), rng.range(-0.5, 0.5));
        let mut sim = Simulation::new(table, p, &balls).expect("the cue ball clear of the rack");
        let (side, height) = (rng.range(-0.35, 0.35), rng.range(-0.35, 0.35));
        // Every other shot at the rack's head ball (give or take), the rest anywhere.
        let aim = (balls[1].position - balls[0].position).angle();
        let angle = if i % 2 == 0 {
            aim + rng.range(-0.1, 0.1)
        } else {
            rng.range(-3.2, 3.2)
        };
        let shot = Shot {
            tip: TipOffset { side, height },
            elevation: rng.range(0.0, limits::MAX_ELEVATION),
            ..Shot::new(angle, rng.range(0.3, 8.0))
        };
        let mut monitor = Monitor::new(&sim, Tolerances::default()).unwrap();
        if let Err(e) = monitor.strike(&mut sim, 0, shot) {
            failures.push(format!("shot {i} {shot:?}: refused: {e}"));
            continue;
        }
        if sim.ball(0).motion == Motion::Airborne {
            flew += 1;
        }
        if let Err(v) = monitor.run_to_rest(&mut sim) {
            failures.push(format!("shot {i} {shot:?}: {v}"));
        }
        events += sim.event_count();
        let in_air = |e: &&Event| {
            matches!(e.kind, EventKind::BallBall { .. })
                && (e.after[0].height > 0.0 || e.after[1].height > 0.0)
        };
        air_contacts += sim.history().events().iter().filter(in_air).count();
    }
    (failures, flew, events, air_contacts)
}

#[test]
fn two_thousand_random_elevated_shots_keep_every_invariant() {
    let (failures, flew, events, air) = soak(51, 2000);
    println!("2000 shots, {flew} flew, {events} events, {air} contacts in the air");
    let f = failures.len();
    assert!(f == 0, "{f} failures: {:#?}", &failures[..f.min(5)]);
    // Most shots are steep and fast enough to leave the cloth; half go into the rack.
    assert!(flew > 400, "only {flew} of 2000 shots flew");
    assert!(
        events > 2000 * 20,
        "over 20 events a shot (racks break): {events}"
    );
    assert!(air > 100, "contacts in the air are exercised: {air}");
}

#[test]
#[ignore = "the issue's 200,000 shots: minutes"]
fn the_full_soak_of_random_elevated_shots() {
    let n = std::env::var("FLIGHT_SOAK")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200_000);
    let (failures, flew, events, air) = soak(5151, n);
    let f = failures.len();
    println!("{n} shots, {flew} flew, {events} events, {air} contacts in the air, {f} failures");
    assert!(f == 0, "{f} failures: {:#?}", &failures[..f.min(5)]);
}
