//! A soak of random elevated shots into a nine-ball rack: every invariant the monitor checks
//! (no overlap in space, energy never grows, no ball outside the table, momentum of contacts
//! on the cloth, no runaway event chains) holds on every shot. 2,000 shots here; the issue's
//! 200,000 with `FLIGHT_SOAK=200000 cargo test --release -p billiards-physics --test
//! flight_soak -- --ignored` (another seed with `FLIGHT_SOAK_SEED`). Any shot of a seed can be replayed alone (`shot_of`), as the
//! one that once looped is below.

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

/// The scene and shot of the soak's shot `i`: the cue ball placed at random behind a nine-ball
/// rack, and a random elevated shot. Draws the same numbers from `rng` whether or not the
/// shot is then played, so any shot of a seed can be replayed alone ([`shot_of`]).
fn draw(rng: &mut Rng, i: usize, table: &Table, p: &Params) -> (Vec<BallSetup>, Shot) {
    let mut balls = Rack::NineBall.layout(table, &p.ball);
    balls[0].position = Vec2::new(rng.range(-1.0, -0.5), rng.range(-0.5, 0.5));
    let (side, height) = (rng.range(-0.35, 0.35), rng.range(-0.35, 0.35));
    // Every other shot at the rack's head ball (give or take), the rest anywhere.
    let aim = (balls[1].position - balls[0].position).angle();
    let angle = if i.is_multiple_of(2) {
        aim + rng.range(-0.1, 0.1)
    } else {
        rng.range(-3.2, 3.2)
    };
    let shot = Shot {
        tip: TipOffset { side, height },
        elevation: rng.range(0.0, limits::MAX_ELEVATION),
        ..Shot::new(angle, rng.range(0.3, 8.0))
    };
    (balls, shot)
}

fn params() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

/// Shot `i` of `seed` alone (the numbers of the shots before it drawn and dropped).
fn shot_of(seed: u64, i: usize) -> (Vec<BallSetup>, Shot) {
    let (table, p) = (Table::wpa_8ft(), params());
    let mut rng = Rng(seed.max(1));
    for k in 0..i {
        draw(&mut rng, k, &table, &p);
    }
    draw(&mut rng, i, &table, &p)
}

/// Plays one shot under the monitor: the simulation at rest, or the violation.
fn play(balls: &[BallSetup], shot: Shot) -> Result<Simulation, String> {
    let sim = Simulation::new(Table::wpa_8ft(), params(), balls);
    let mut sim = sim.map_err(|e| format!("scene refused: {e}"))?;
    let mut monitor = Monitor::new(&sim, Tolerances::default()).map_err(|v| v.to_string())?;
    monitor
        .strike(&mut sim, 0, shot)
        .map_err(|e| format!("refused: {e}"))?;
    monitor.run_to_rest(&mut sim).map_err(|v| v.to_string())?;
    Ok(sim)
}

/// Plays `n` random elevated shots from `seed`; returns the failures, how many shots flew and
/// how many events they had and how many ball-ball contacts in the air.
fn soak(seed: u64, n: usize) -> (Vec<String>, usize, usize, usize) {
    let (table, p) = (Table::wpa_8ft(), params());
    let mut rng = Rng(seed.max(1));
    let (mut failures, mut flew, mut events, mut air_contacts) = (Vec::new(), 0, 0, 0);
    for i in 0..n {
        let (balls, shot) = draw(&mut rng, i, &table, &p);
        let sim = match play(&balls, shot) {
            Ok(sim) => sim,
            Err(e) => {
                failures.push(format!("shot {i} {shot:?}: {e}"));
                continue;
            }
        };
        let struck = |e: &&Event| matches!(e.kind, EventKind::Strike { .. });
        let strike = sim.history().events().iter().find(struck);
        if strike.is_some_and(|e| e.after[0].motion == Motion::Airborne) {
            flew += 1;
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
    let seed = std::env::var("FLIGHT_SOAK_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(5151);
    let (failures, flew, events, air) = soak(seed, n);
    let f = failures.len();
    println!(
        "seed {seed}: {n} shots, {flew} flew, {events} events, {air} contacts in the air, {f} failures"
    );
    assert!(f == 0, "{f} failures: {:#?}", &failures[..f.min(5)]);
}

/// The shot that once looped (seed 5151, shot 17,622): the cue ball lands on ball 8 of the
/// rack, which the slate lifts (upward speed, height 0) while it is frozen against its
/// neighbours. Its contacts with them are level (`detect::LEVEL`), so they are resolved in
/// the plane inside one cluster impact with ball 8 in it, rather than pair by pair in space
/// without end (the solver stopped at `max_events`); the shot ends in a few dozen events.
#[test]
fn a_ball_lifted_inside_a_frozen_rack_is_part_of_its_cluster_impact() {
    let (balls, shot) = shot_of(5151, 17_622);
    let sim = play(&balls, shot).unwrap_or_else(|e| panic!("shot 17,622 of seed 5151: {e}"));
    let h = sim.history();
    let events = h.events();
    assert!(events.len() < 200, "{} events", events.len());
    let lifted = |e: &Event| {
        matches!(e.kind, EventKind::BallBall { a: 0, b: 8 })
            && e.after[1].motion == Motion::Airborne
            && e.after[1].height == 0.0
    };
    let landing = events.iter().position(lifted);
    let landing = landing.expect("the cue ball lands on ball 8 and the slate lifts it");
    // The next contact of ball 8 with a neighbour is in a cluster impact, ball 8 flying on.
    let next = (landing + 1..events.len())
        .find(|&k| matches!(events[k].kind, EventKind::BallBall { a, b } if a == 8 || b == 8))
        .expect("ball 8 is pressed against its neighbours");
    assert!(h.impact_of(next).is_some(), "{:?}", events[next]);
}

/// A ball in the air leaning on another's side (seed 51, shot 1,084: ball 2, lifted 5 mm by
/// the slate, slides down ball 1 as ball 1 rolls away): a resting contact in space, elastic
/// with the cloth's minimum hop, so the shot ends in a hundred-odd events; with the pair's
/// restitution alone its bounces shrank to an accumulation point (a million events, the cap).
#[test]
fn a_ball_leaning_in_the_air_on_another_hops_instead_of_collapsing() {
    let (balls, shot) = shot_of(51, 1_084);
    let sim = play(&balls, shot).unwrap_or_else(|e| panic!("shot 1,084 of seed 51: {e}"));
    let events = sim.history().events();
    let leaning = |e: &&Event| {
        matches!(e.kind, EventKind::BallBall { a: 1, b: 2 }) && e.after[1].height > 1e-3
    };
    let n = events.iter().filter(leaning).count();
    assert!(n >= 10, "ball 2 leans on ball 1 in the air: {n} contacts");
    assert!(events.len() < 1_000, "{} events", events.len());
}
