//! Criterion benchmarks of the solver: a break run to rest, and event throughput against the
//! number of balls.

use billiards_physics::racks;
use billiards_physics::*;
use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

/// A 15-ball break struck at `speed`, ready to run.
fn struck_break(speed: f64) -> Simulation {
    let table = Table::wpa_8ft();
    let params = Params::default();
    let mut sim = Simulation::new(
        table,
        params,
        &Rack::FifteenBall.layout(&table, &params.ball),
    )
    .unwrap();
    sim.strike(0, Shot::new(0.0, speed)).unwrap();
    sim
}

/// The 9-ball break of issue 4: spin model, cue ball on the head string aimed at the 1-ball.
fn nine_ball_spin_break(speed: f64) -> Simulation {
    let table = Table::wpa_8ft();
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let mut balls = Rack::NineBall.layout(&table, &params.ball);
    balls[0].position = Vec2::new(-0.25 * table.length, 0.1);
    let aim = (balls[1].position - balls[0].position).angle();
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    sim.strike(0, Shot::new(aim, speed)).unwrap();
    sim
}

fn break_to_rest(c: &mut Criterion) {
    let mut g = c.benchmark_group("break_to_rest");
    let scenes = [
        ("paper_15_ball_8mps", struck_break(8.0)),
        ("paper_15_ball_11mps", struck_break(11.0)),
        ("spin_9_ball_8mps", nine_ball_spin_break(8.0)),
    ];
    for (name, sim) in scenes {
        let mut probe = sim.clone();
        probe.run_to_rest().unwrap();
        g.throughput(Throughput::Elements(probe.history().events().len() as u64));
        g.bench_function(name, |b| {
            b.iter_batched(
                || sim.clone(),
                |mut s| black_box(s.run_to_rest().unwrap()),
                BatchSize::SmallInput,
            )
        });
    }
    g.finish();
}

/// The frictionless gas of [`racks::frictionless_gas`], ready to run.
fn gas(n: usize) -> Simulation {
    let (table, params, balls) = racks::frictionless_gas(n);
    Simulation::new(table, params, &balls).unwrap()
}

fn event_throughput(c: &mut Criterion) {
    const EVENTS: usize = 2000;
    let mut g = c.benchmark_group("event_throughput");
    g.throughput(Throughput::Elements(EVENTS as u64));
    for n in [16, 100, 1000] {
        let mut sim = gas(n);
        // Warm up so the measured events are typical, not the first few.
        for _ in 0..EVENTS {
            sim.step_event();
        }
        g.bench_function(format!("gas_{n}_balls"), |b| {
            b.iter_batched(
                || sim.clone(),
                |mut s| {
                    for _ in 0..EVENTS {
                        black_box(s.step_event());
                    }
                    s
                },
                BatchSize::LargeInput,
            )
        });
    }
    g.finish();
}

mod group {
    //! The criterion group (its generated function has no doc comment of its own).
    #![allow(missing_docs)]
    use super::*;
    criterion_group!(benches, break_to_rest, event_throughput);
}
use group::benches;
criterion_main!(benches);
