//! The history stores each event's after-states, not the segments: a ball's segment is rebuilt
//! from the after-state and the parameters in force. These tests pin that the rebuilt segment
//! is, bit for bit, the one the solver followed.

use billiards_physics::*;

/// Every segment the history gives for the balls an event changed equals the solver's own,
/// after every event of the first shots of 300 soak scenes (both models, every variation of
/// friction, restitution, randomization and prediction mode the soak draws), and after a
/// change of parameters in the middle of each shot.
#[test]
fn rebuilt_segments_equal_the_solvers_after_every_event() {
    let mut checked = 0;
    for seed in 0..300 {
        let s = soak::scenario(seed);
        let mut sim = Simulation::new(s.table, s.params, &s.balls).unwrap();
        let Some(ball) = (0..sim.ball_count()).find(|&i| sim.ball(i).motion.on_table()) else {
            continue;
        };
        sim.strike(ball, s.shots[0]).unwrap();
        for k in 0..3000 {
            if k == 500 {
                // Half the friction from here on: moving balls continue on new segments.
                let p = soak::scale_friction(*sim.params(), 0.5);
                sim.set_params(p).unwrap();
                let h = sim.history();
                for id in 0..sim.ball_count() {
                    assert_eq!(h.segment(id, h.track_len(id) - 1), *sim.segment(id));
                }
            }
            let Some(e) = sim.step_event() else { break };
            let h = sim.history();
            for id in e.kind.balls() {
                let last = h.segment(id, h.track_len(id) - 1);
                assert_eq!(last, *sim.segment(id), "seed {seed}, {e:?}");
                checked += 1;
            }
        }
    }
    assert!(checked > 50_000, "only {checked} segments checked");
}

/// Sampling the history between events gives the states the solver reports at that time.
#[test]
fn sampled_states_equal_the_solvers_between_events() {
    let table = Table::wpa_8ft();
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let balls = Rack::NineBall.layout(&table, &params.ball);
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    sim.strike(0, Shot::new(0.01, 7.0)).unwrap();
    for _ in 0..400 {
        sim.advance(1.0 / 120.0).unwrap();
        let t = sim.time();
        let live: Vec<BallState> = sim.balls().collect();
        assert_eq!(sim.history().states_at(t), live, "t = {t}");
    }
}

/// The lean mode of a search (no history) processes the very same events: every event that
/// `step_event` returns without a history equals, bit for bit, the one the history records
/// with it on, through a change of parameters; the clone of a lean simulation carries no
/// history, and turning it back on starts one at the current state.
#[test]
fn without_a_history_the_events_are_the_same_and_none_is_stored() {
    let mut compared = 0;
    for seed in 0..100 {
        let s = soak::scenario(seed);
        let mut full = Simulation::new(s.table, s.params, &s.balls).unwrap();
        let Some(ball) = (0..full.ball_count()).find(|&i| full.ball(i).motion.on_table()) else {
            continue;
        };
        let mut lean = full.clone();
        lean.set_record_history(false);
        assert!(!lean.records_history() && lean.clone().history().ball_count() == 0);
        full.strike(ball, s.shots[0]).unwrap();
        lean.strike(ball, s.shots[0]).unwrap();
        let p = soak::scale_friction(*full.params(), 0.5);
        // Index of the next event step_event hands out (a cluster impact records several at
        // once and hands them out one a call).
        let mut next = full.history().events().len();
        for k in 0..2000 {
            if k == 300 {
                full.set_params(p).unwrap();
                lean.set_params(p).unwrap();
                next += 1;
            }
            let e = lean.step_event();
            assert_eq!(e, full.step_event(), "seed {seed}");
            let Some(e) = e else { break };
            assert_eq!(Some(&e), full.history().events().get(next), "seed {seed}");
            next += 1;
            compared += 1;
        }
        assert_eq!(lean.event_count(), full.history().events().len());
        assert!(lean.history().events().is_empty());
        lean.set_record_history(true);
        assert_eq!(lean.history().ball_count(), lean.ball_count());
    }
    assert!(compared > 1000, "{compared}");
}
