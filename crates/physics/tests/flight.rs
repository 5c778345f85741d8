//! A ball in the air: the strike's take-off, the parabola, the landing and the bounces
//! against their closed forms (pooltool's airborne state and `frictional_inelastic` slate;
//! `resolve/slate.rs`, `motion/flight.rs`).

mod common;
use billiards_physics::*;
use common::*;

const E: f64 = 0.5;

fn spin() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

/// A centre-ball strike along +x at `speed` and `degrees` of elevation, played to rest.
fn jumped(speed: f64, degrees: f64) -> Simulation {
    let mut sim = Simulation::new(huge_table(), spin(), &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    let shot = Shot {
        elevation: degrees.to_radians(),
        ..Shot::new(0.0, speed)
    };
    sim.strike(0, shot).unwrap();
    sim.run_to_rest().unwrap();
    sim
}

/// The events at which ball 0 meets the slate (a transition out of the air).
fn landings(sim: &Simulation) -> Vec<Event> {
    let from_air = |e: &&Event| {
        matches!(
            e.kind,
            EventKind::Transition {
                from: Motion::Airborne,
                ..
            }
        )
    };
    sim.history()
        .events()
        .iter()
        .filter(from_air)
        .copied()
        .collect()
}

/// Mechanical energy per unit mass: `v^2 / 2 + (1/5) R^2 w^2 + g h` (solid sphere).
fn energy(s: &BallState, p: &Params) -> f64 {
    let r = p.ball.radius;
    let v2 = s.velocity.length_squared() + s.vertical * s.vertical;
    let w = s.angular_velocity;
    0.5 * v2 + 0.2 * r * r * (w.x * w.x + w.y * w.y + w.z * w.z) + p.gravity * s.height
}

/// 3 m/s at 45 degrees, centre: it takes off at `v_z = e v sin(theta)` rolling at
/// `(5/7) v cos(theta)` (the slate grips above 43.6 degrees), flies `T = 2 v_z / g`, peaks at
/// `v_z^2 / 2g` at `T / 2` and lands `(5/7) v cos(theta) T` away, all to 1e-12.
#[test]
fn the_first_flight_is_the_closed_form_parabola() {
    let p = spin();
    let sim = jumped(3.0, 45.0);
    let theta = 45f64.to_radians();
    let (vz, vx) = (E * 3.0 * theta.sin(), 5.0 / 7.0 * 3.0 * theta.cos());
    let g = p.gravity;
    let t = 2.0 * vz / g;
    let first = landings(&sim)[0];
    assert!((first.time - t).abs() < 1e-12, "{} vs {t}", first.time);
    let at = first.after[0].position;
    assert!(
        (at.x - vx * t).abs() < 1e-12 && at.y.abs() < 1e-15,
        "{at:?}"
    );
    let apex = sim.history().state_at(0, t / 2.0);
    assert_eq!(apex.motion, Motion::Airborne);
    assert!(
        (apex.height - vz * vz / (2.0 * g)).abs() < 1e-12,
        "{}",
        apex.height
    );
    assert!(apex.vertical.abs() < 1e-12);
    // About one ball's height (57 mm) and a third of a metre, as the reference derives.
    assert!((apex.height - 0.0573).abs() < 1e-4 && (at.x - 0.33).abs() < 0.01);
}

/// Each bounce returns `e` of the landing speed, so each rise is `e^2` of the one before, and
/// the bouncing stops at the first rebound that would rise under 5 mm.
#[test]
fn bounce_heights_follow_e_squared_down_to_five_millimetres() {
    let p = spin();
    for (speed, degrees) in [(3.0, 45.0), (6.0, 60.0), (4.0, 30.0)] {
        let sim = jumped(speed, degrees);
        let rise = |e: &Event| e.after[0].vertical.powi(2) / (2.0 * p.gravity);
        let strike = sim.history().events()[0];
        let mut rises = vec![rise(&strike)];
        let lands = landings(&sim);
        rises.extend(lands.iter().map(rise));
        let last = rises.pop().unwrap();
        assert_eq!(last, 0.0, "the last landing stays on the cloth");
        assert!(rises.len() >= 2, "{speed} m/s at {degrees}: {rises:?}");
        for w in rises.windows(2) {
            assert!((w[1] / w[0] - E * E).abs() < 1e-12, "{rises:?}");
        }
        let smallest = rises[rises.len() - 1];
        assert!(smallest >= 0.005 && smallest * E * E < 0.005, "{rises:?}");
        let after = lands.last().unwrap().after[0].motion;
        assert!(
            matches!(after, Motion::Sliding | Motion::Rolling),
            "{after:?}"
        );
    }
}

/// Energy never grows: constant along each flight (sampled), and not more after each landing.
#[test]
fn energy_never_grows_in_flight_or_at_a_bounce() {
    let p = spin();
    for (speed, degrees, side) in [(3.0, 45.0, 0.0), (5.0, 70.0, 0.3), (4.0, 25.0, -0.2)] {
        let mut sim = Simulation::new(huge_table(), p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
        let shot = Shot {
            elevation: f64::to_radians(degrees),
            tip: TipOffset { side, height: 0.1 },
            ..Shot::new(1.0, speed)
        };
        sim.strike(0, shot).unwrap();
        sim.run_to_rest().unwrap();
        let h = sim.history();
        let events = h.events();
        let mut flights = 0;
        for pair in events.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let e0 = energy(&a.after[0], &p);
            assert!(energy(&b.after[0], &p) <= e0 * (1.0 + 1e-12), "{b:?}");
            if a.after[0].motion == Motion::Airborne {
                flights += 1;
                for f in [0.25, 0.5, 0.75, 1.0 - 1e-9] {
                    let s = h.state_at(0, a.time + f * (b.time - a.time));
                    assert!((energy(&s, &p) - e0).abs() <= 1e-12 * e0, "at {f}: {s:?}");
                }
            }
        }
        assert!(flights >= 1, "{speed} m/s at {degrees} flies");
    }
}
