//! The solver's own states are valid inputs (issue 15, item 2): every state the solver leaves
//! the balls in is accepted back by `Simulation::new` and by `Simulation::place`, and a shot
//! from it keeps every invariant. A ball at rest in a pocket mouth (beyond a cushion line,
//! between the jaws) was once refused as "outside the table", which hid the aiming aid.

use billiards_physics::check::{Monitor, Tolerances};
use billiards_physics::soak::{Scenario, scenario};
use billiards_physics::{BallSetup, Shot, Simulation, TipOffset};

/// Plays scene `s` to its end (to rest, or for its duration when nothing stops the balls).
fn play(s: &Scenario) -> Simulation {
    let mut sim = Simulation::new(s.table, s.params, &s.balls).expect("a soak scene builds");
    for shot in &s.shots {
        let Some(ball) = (0..sim.ball_count()).find(|&i| sim.ball(i).motion.on_table()) else {
            break;
        };
        sim.strike(ball, *shot).expect("a soak shot is valid");
        let done = match s.duration {
            None => sim.run_to_rest().map(|_| ()),
            Some(d) => sim.advance(d).map(|_| ()),
        };
        if done.is_err() {
            break;
        }
    }
    sim
}

/// The balls in play as a fresh layout, their numbers kept.
fn layout(sim: &Simulation) -> Vec<BallSetup> {
    (0..sim.ball_count())
        .map(|i| (sim.numbers()[i], sim.ball(i)))
        .filter(|(_, b)| b.motion.on_table())
        .map(|(number, b)| BallSetup {
            number,
            position: b.position,
            velocity: b.velocity,
            spin: b.angular_velocity,
        })
        .collect()
}

#[test]
fn every_state_the_solver_leaves_is_a_valid_start() {
    let mut in_mouth = 0;
    for seed in 0..1_500 {
        let s = scenario(seed);
        let mut sim = play(&s);
        let balls = layout(&sim);
        let b = s.table.centre_bounds(s.params.ball.radius);
        in_mouth += balls
            .iter()
            .filter(|x| x.position.x.abs() > b.x || x.position.y.abs() > b.y)
            .count();
        let mut fresh = Simulation::new(s.table, s.params, &balls)
            .unwrap_or_else(|e| panic!("seed {seed} ({}): new refused its end state: {e}", s.kind));
        for i in 0..sim.ball_count() {
            let st = sim.ball(i);
            if st.motion.on_table() {
                sim.place(i, st.position, st.velocity, st.angular_velocity)
                    .unwrap_or_else(|e| panic!("seed {seed}: place refused ball {i}: {e}"));
            }
        }
        // A shot from the rebuilt state keeps every invariant.
        let Some(cue) = (0..fresh.ball_count()).next() else {
            continue;
        };
        let shot = Shot {
            angle: seed as f64 * 0.7,
            speed: 4.0,
            tip: TipOffset::default(),
            elevation: 0.0,
        };
        let mut monitor = Monitor::new(&fresh, Tolerances::default())
            .unwrap_or_else(|v| panic!("seed {seed}: rebuilt state breaks an invariant: {v}"));
        monitor.strike(&mut fresh, cue, shot).expect("a valid shot");
        let r = match s.duration {
            None => monitor.run_to_rest(&mut fresh).map(|_| ()),
            Some(d) => {
                let until = fresh.time() + d;
                monitor.run_until(&mut fresh, until).map(|_| ())
            }
        };
        if let Err(v) = r {
            panic!(
                "seed {seed} ({}): a shot from the rebuilt state: {v}",
                s.kind
            );
        }
    }
    // The property is only tested if some scene leaves a ball beyond a cushion line.
    assert!(in_mouth > 0, "no scene left a ball in a pocket mouth");
    println!("{in_mouth} balls ended beyond a cushion line (in a mouth)");
}
