//! Scenes that once broke the solver, each named after what it broke.

use billiards_physics::*;

#[test]
fn slow_ball_pressing_a_nearly_resting_one_does_not_collide_a_million_times() {
    // A 9 mm/s ball rolling past a nearly resting one while its deceleration pressed it into
    // it re-collided every 1.5e-9 s (960,054 events in this break) until the approach had to
    // exceed sqrt(2 a depth) to count as a collision (detect::PRESSING_DEPTH).
    let table = Table::wpa_8ft().with_jaws(0.015);
    let p = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let balls = Rack::FifteenBall.layout(&table, &p.ball);
    let mut sim = Simulation::new(table, p, &balls).unwrap();
    sim.strike(0, Shot::new(0.003, 8.0)).unwrap();
    sim.run_to_rest().unwrap();
    let n = sim.history().events().len();
    assert!(n < 1000, "{n} events");
}
