//! Regression: a ball re-predicted twice in one round of `repredict` lost its dependency link,
//! so its cached pair event outlived its partner's next change and fired while the balls were
//! apart (an impulse across a 56 µm gap in the 15-ball break, found by the compare benchmark).

use billiards_physics::{EventKind, Params, Rack, Simulation, Table, Vec2};

#[test]
fn every_ball_ball_collision_of_a_break_is_resolved_at_touching() {
    let table = Table::wpa_8ft();
    let params = Params::default();
    let mut balls = Rack::FifteenBall.layout(&table, &params.ball);
    // Moving from the start (not struck), so every resting ball predicts its contact with the
    // cue ball and depends on it: the case that lost links.
    balls[0].velocity = Vec2::from_angle(0.002) * 11.0;
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    sim.run_to_rest().unwrap();
    let r = params.ball.radius;
    for e in sim.history().events() {
        if let EventKind::BallBall { a, b } = e.kind {
            let gap = (e.after[1].position - e.after[0].position).length() - 2.0 * r;
            assert!(
                gap.abs() < 1e-9,
                "{a}-{b} at t = {} s resolved {gap:e} m from touching",
                e.time
            );
        }
    }
}
