//! Helpers shared by the integration tests.
#![allow(dead_code)]

use billiards_physics::*;

/// A table large enough that nothing reaches a cushion in the single-ball tests.
pub fn huge_table() -> Table {
    Table::scaled(20.0)
}

/// One ball at the origin with velocity `v`.
pub fn one_ball(table: Table, params: Params, v: Vec2) -> Simulation {
    Simulation::new(table, params, &[BallSetup::moving(0, Vec2::ZERO, v)]).unwrap()
}

/// Default parameters with the paper model `model`.
pub fn paper(model: PaperModel) -> Params {
    Params {
        model: Model::Paper(model),
        ..Params::default()
    }
}

/// The paper model with no friction at all.
pub fn frictionless() -> Params {
    paper(PaperModel {
        mu_slide: 0.0,
        mu_roll: 0.0,
        ..PaperModel::default()
    })
}

/// Relative difference.
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

/// Checks the two invariants after every event of `sim`'s history: no ball outside the
/// cushions (unless pocketed) and no two balls overlapping by more than `tol`.
pub fn assert_no_overlap_or_escape(sim: &Simulation, tol: f64) {
    let h = sim.history();
    let r = sim.params().ball.radius;
    let b = sim.table().centre_bounds(r);
    for e in h.events() {
        let states = h.states_at(e.time);
        for (i, s) in states.iter().enumerate() {
            assert!(
                s.position.is_finite() && s.velocity.is_finite(),
                "NaN at {e:?}"
            );
            if !s.motion.on_table() {
                continue;
            }
            assert!(
                s.position.x.abs() <= b.x + tol && s.position.y.abs() <= b.y + tol,
                "ball {i} outside at t = {}: {:?}",
                e.time,
                s.position
            );
        }
        // Sweep along x: only balls within 2R in x can overlap.
        let mut order: Vec<usize> = (0..states.len())
            .filter(|&i| states[i].motion.on_table())
            .collect();
        order.sort_by(|&i, &j| states[i].position.x.total_cmp(&states[j].position.x));
        for (k, &i) in order.iter().enumerate() {
            for &j in &order[k + 1..] {
                let (s, o) = (&states[i], &states[j]);
                if o.position.x - s.position.x > 2.0 * r {
                    break;
                }
                let overlap = 2.0 * r - (o.position - s.position).length();
                assert!(
                    overlap <= tol,
                    "balls {i},{j} overlap by {overlap} at t = {}",
                    e.time
                );
            }
        }
    }
}

/// Total translational kinetic energy of the balls in play.
pub fn kinetic_energy(states: &[BallState], mass: f64) -> f64 {
    states
        .iter()
        .filter(|s| s.motion.on_table())
        .map(|s| 0.5 * mass * s.velocity.length_squared())
        .sum()
}

/// A break: `rack` on the 8-ft table, cue ball struck towards the foot at `speed`.
pub fn break_shot(rack: Rack, speed: f64, params: Params) -> Simulation {
    let table = Table::wpa_8ft();
    let balls = rack.layout(&table, &params.ball);
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    // Slightly off the centre line so the break is not perfectly symmetric.
    sim.strike(0, Shot::new(0.002, speed)).unwrap();
    sim
}

/// Every model configuration under test, by name (one list for all stress tests and the soak:
/// see `billiards_physics::soak::models`).
pub fn models() -> Vec<(&'static str, Params)> {
    billiards_physics::soak::models()
}

/// Runs `sim` to rest with every event checked (see `billiards_physics::check`); panics with
/// the broken invariant and `what` otherwise.
pub fn checked_to_rest(sim: &mut Simulation, what: &str) -> check::Stats {
    let mut m = check::Monitor::new(sim, check::Tolerances::default())
        .unwrap_or_else(|v| panic!("{what}: bad start: {v}"));
    m.run_to_rest(sim).unwrap_or_else(|v| panic!("{what}: {v}"))
}

/// Runs `sim` for `seconds` of simulated time with every event checked.
pub fn checked_for(sim: &mut Simulation, seconds: f64, what: &str) -> check::Stats {
    let mut m = check::Monitor::new(sim, check::Tolerances::default())
        .unwrap_or_else(|v| panic!("{what}: bad start: {v}"));
    let until = sim.time() + seconds;
    m.run_until(sim, until)
        .unwrap_or_else(|v| panic!("{what}: {v}"))
}

/// `params` with every friction coefficient multiplied by `k` (0: frictionless).
pub fn with_friction(params: Params, k: f64) -> Params {
    billiards_physics::soak::scale_friction(params, k)
}

/// A ball rolling without slipping at velocity `v` (its spin matches `v`; the paper's model
/// ignores the spin and rolls it by its speed).
pub fn rolling(number: u8, position: Vec2, v: Vec2) -> BallSetup {
    let r = BallSpec::default().radius;
    BallSetup {
        velocity: v,
        spin: Vec3::new(-v.y / r, v.x / r, 0.0),
        ..BallSetup::at(number, position)
    }
}
