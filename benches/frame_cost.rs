//! The solver's cost per frame during a break, as the game runs it: a headless app
//! (`MinimalPlugins` + the game's simulation plugins), a 15-ball break at 9 m/s and a 9-ball
//! break at 8 m/s under the default spin model, advanced in 60 Hz frames until every ball
//! rests. Prints, per break, the mean, 99th-percentile and worst wall time of the exclusive
//! solver system per frame (as the HUD shows it) and of the whole `App::update`, and their ratio
//! to the 16.7 ms frame budget (target: the solver under 5 %).
//!
//! `cargo build --workspace --release --bench frame_cost`, then
//! `target/release/deps/frame_cost-* --bench` (see the README's Performance section).

use std::time::{Duration, Instant};

use bevy::{prelude::*, time::TimeUpdateStrategy};
use billiards::{
    mode, settings,
    sim::{self, RackRequested, ShotRequested, SimStatus},
};
use billiards_physics::{Rack, TipOffset};

const FRAME: Duration = Duration::from_micros(16_667);

fn game(rack: Rack) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, mode::plugin, settings::plugin, sim::plugin));
    app.insert_resource(TimeUpdateStrategy::ManualDuration(FRAME));
    app.update();
    app.world_mut().write_message(RackRequested::standard(rack));
    app.update();
    app
}

/// Solver and whole-update seconds of every frame of one break.
fn break_frames(rack: Rack, angle: f64, speed: f64) -> (Vec<f64>, Vec<f64>, usize) {
    let mut app = game(rack);
    app.world_mut().write_message(ShotRequested {
        angle,
        speed,
        tip: TipOffset::default(),
        elevation: 0.0,
    });
    let (mut solver, mut update) = (Vec::new(), Vec::new());
    for _ in 0..100_000 {
        let started = Instant::now();
        app.update();
        update.push(started.elapsed().as_secs_f64());
        let status = app.world().resource::<SimStatus>();
        solver.push(status.solver_seconds_last_frame);
        if status.at_rest && status.shots > 0 {
            return (solver, update, status.events_this_shot);
        }
    }
    panic!("the break did not come to rest");
}

fn stats(mut v: Vec<f64>) -> (f64, f64, f64) {
    v.sort_by(f64::total_cmp);
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let p99 = v[((v.len() - 1) as f64 * 0.99) as usize];
    (mean, p99, *v.last().unwrap())
}

fn main() {
    // `cargo bench` passes `--bench`; nothing to parse.
    let budget = FRAME.as_secs_f64();
    println!(
        "load: {}",
        std::fs::read_to_string("/proc/loadavg")
            .unwrap_or_default()
            .trim()
    );
    for (name, rack, angle, speed) in [
        ("15-ball break, 9 m/s", Rack::FifteenBall, 0.012, 9.0),
        ("9-ball break, 8 m/s", Rack::NineBall, 0.004, 8.0),
    ] {
        // Warm up once (allocations, caches), then keep the worst of five runs per frame slot.
        let _ = break_frames(rack, angle, speed);
        let runs: Vec<_> = (0..5).map(|_| break_frames(rack, angle, speed)).collect();
        let (solver, update, events) = runs.into_iter().fold(
            (Vec::new(), Vec::new(), 0),
            |(mut s, mut u, _), (s1, u1, e)| {
                s.extend(s1);
                u.extend(u1);
                (s, u, e)
            },
        );
        let frames = solver.len() / 5;
        let (s_mean, s_p99, s_max) = stats(solver);
        let (u_mean, u_p99, u_max) = stats(update);
        println!("{name}: {events} events over {frames} frames of 60 Hz (5 runs)");
        println!(
            "  solver per frame: mean {:.1} us ({:.2} % of the frame), p99 {:.1} us ({:.2} %), worst {:.1} us ({:.2} %)",
            s_mean * 1e6,
            100.0 * s_mean / budget,
            s_p99 * 1e6,
            100.0 * s_p99 / budget,
            s_max * 1e6,
            100.0 * s_max / budget,
        );
        println!(
            "  whole headless update: mean {:.1} us, p99 {:.1} us, worst {:.1} us",
            u_mean * 1e6,
            u_p99 * 1e6,
            u_max * 1e6,
        );
    }
}
