//! Cluster impacts in a break: one impact for a frozen rack, the balls leaving it with no
//! pair closer than touching and no touching pair approaching, every invariant of the
//! monitor kept, and a ball with no neighbour within reach left to the exact pair law.

use billiards_physics::*;

fn spin() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

/// Index of the first ball–ball event in `sim`'s history.
fn first_contact(sim: &Simulation) -> usize {
    let events = sim.history().events();
    events
        .iter()
        .position(|e| matches!(e.kind, EventKind::BallBall { .. }))
        .expect("a contact")
}

/// The states just after the first ball–ball event's instant (the whole impact), the number
/// of events at that instant, and the simulation run on to rest under the monitor.
fn after_first_impact(balls: &[BallSetup], speed: f64) -> (Simulation, Vec<BallState>, usize) {
    let table = Table::wpa_9ft().with_jaws(0.015);
    let mut sim = Simulation::new(table, spin(), balls).unwrap();
    let aim = (balls[1].position - balls[0].position).angle();
    sim.strike(0, Shot::new(aim, speed)).unwrap();
    let mut monitor = check::Monitor::new(&sim, check::Tolerances::default()).unwrap();
    let t0 = loop {
        let e = monitor.step(&mut sim).unwrap().expect("an event");
        if matches!(e.kind, EventKind::BallBall { .. }) {
            break e.time;
        }
    };
    // A cluster impact's events are all recorded at once (step_event hands them out one a
    // call); anything else at that instant would come from a new prediction.
    while sim.next_event_time() == Some(t0) {
        monitor.step(&mut sim).unwrap();
    }
    let at_t0 = sim
        .history()
        .events()
        .iter()
        .filter(|e| e.time == t0)
        .count();
    let states = (0..sim.ball_count()).map(|i| sim.ball(i)).collect();
    monitor.run_to_rest(&mut sim).unwrap();
    (sim, states, at_t0)
}

#[test]
fn a_frozen_rack_breaks_in_one_impact_leaving_no_touching_pair_approaching() {
    let table = Table::wpa_9ft();
    let r = spin().ball.radius;
    for speed in [2.0, 11.0] {
        let mut balls = Rack::Tight.layout(&table, &spin().ball);
        balls[0].position = Vec2::new(-0.6, 0.05);
        let (sim, states, at_t0) = after_first_impact(&balls, speed);
        assert!(sim.cluster_impacts() >= 1);
        let impact = sim
            .history()
            .impact_of(first_contact(&sim))
            .expect("the first contact is an impact");
        assert_eq!(at_t0, impact.len(), "nothing else at that instant");
        for (i, a) in states.iter().enumerate() {
            for b in &states[i + 1..] {
                let d = b.position - a.position;
                let gap = d.length() - 2.0 * r;
                assert!(gap > -1e-9, "overlap {gap}");
                if gap < 1e-9 {
                    let closing = (a.velocity - b.velocity).dot(d * (1.0 / d.length()));
                    assert!(
                        closing <= 1e-12 * speed,
                        "touching pair closing at {closing}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_pair_with_no_neighbour_within_reach_keeps_the_exact_law() {
    // Cue ball into a ball whose neighbour is 5 mm away: more than the 2.4 mm one contact
    // closes at 10 m/s, so the first contact is the plain pair law (no impact), as an
    // isolated pair.
    let r = spin().ball.radius;
    let balls = [
        BallSetup::at(0, Vec2::new(-0.5, 0.0)),
        BallSetup::at(1, Vec2::new(0.0, 0.0)),
        BallSetup::at(2, Vec2::new(2.0 * r + 5e-3, 0.0)),
    ];
    let (sim, states, at_t0) = after_first_impact(&balls, 10.0);
    assert_eq!(at_t0, 1);
    assert!(sim.history().impact_of(first_contact(&sim)).is_none());
    // Head on, no spin: 1 leaves at (1 + e)/2 of the cue ball's speed at contact.
    let e = 0.95;
    let v1 = states[1].velocity.x;
    let v0 = states[0].velocity.x + v1;
    assert!((v1 / v0 - 0.5 * (1.0 + e)).abs() < 1e-12, "{}", v1 / v0);
    // The same with the neighbour at 1 mm: one impact of three balls.
    let mut near = balls;
    near[2].position.x = 2.0 * r + 1e-3;
    let (sim, _, at_t0) = after_first_impact(&near, 10.0);
    assert!(sim.history().impact_of(first_contact(&sim)).is_some() && at_t0 == 2);
}
