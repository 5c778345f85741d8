//! Snooker decision time of a level on a full 22-ball table: the break-off (cue ball in hand
//! in the D), the table the break-off leaves (22 balls, as they lie), and every decision of
//! seeded frames between two players of the level; mean and max, on all cores.
//!
//! ```sh
//! cargo run --release -p billiards-ai --example snooker_time -- hard 3
//! RAYON_NUM_THREADS=1 cargo run --release -p billiards-ai --example snooker_time -- hard 1
//! ```

use billiards_ai::match_record::{Between, play_between};
use billiards_ai::play::MAX_SHOTS;
use billiards_ai::snooker::play::snooker_table;
use billiards_ai::{Level, Player, SnookerDecision, decide_snooker};
use billiards_physics::snooker::{default_cue_position, layout};
use billiards_physics::{Simulation, SnookerMarks, Vec2, Vec3};
use billiards_rules::snooker::rules::SnookerGame;
use billiards_rules::snooker::{Frame, Stroke};
use billiards_rules::{GameRules, Seat, summarise};
use std::time::Instant;

/// The balls of `sim` on the table, by number.
fn on_table(sim: &Simulation) -> Vec<(u8, billiards_physics::Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let level: Level = args.first().map_or(Ok(Level::Hard), |s| s.parse()).unwrap();
    let frames: u64 = args.get(1).map_or(2, |s| s.parse().unwrap());
    println!("{level}, {} threads", rayon::current_num_threads());
    let (table, params) = snooker_table();
    let marks = SnookerMarks::of(&table).unwrap();
    let balls = layout(&table, &params.ball, default_cue_position(&marks)).unwrap();
    let sim = Simulation::new(table, params, &balls).unwrap();
    let names = ["A".to_owned(), "B".to_owned()];
    let frame = Frame::new(names.clone(), table, &params.ball, Seat::A).unwrap();
    let mut times = Vec::new();
    for seed in 0..3 {
        let start = Instant::now();
        let d = decide_snooker(&frame, &sim, level, seed).unwrap();
        times.push(start.elapsed().as_secs_f64());
        if let SnookerDecision::Shoot(p) = d {
            println!(
                "break-off seed {seed}: {:?} at {:?}, value {:.2}, foul {:.2}, {} simulations",
                p.kind, p.place, p.value, p.foul, p.simulations
            );
        }
    }
    let mean = times.iter().sum::<f64>() / times.len() as f64;
    let max = times.iter().copied().fold(0.0, f64::max);
    println!("break-off: mean {mean:.3} s, max {max:.3} s");
    // The table the break-off leaves (22 balls, the cue ball as it lies): the next decision.
    let mut times = Vec::new();
    for seed in 0..frames.max(3) {
        let Some((frame, sim, left)) = after_break_off(&frame, &sim, level, seed) else {
            continue;
        };
        if frame.end.is_some() || !frame.next.choices.is_empty() {
            continue;
        }
        let start = Instant::now();
        let d = decide_snooker(&frame, &sim, level, seed + 100).unwrap();
        times.push(start.elapsed().as_secs_f64());
        if let SnookerDecision::Shoot(p) = d {
            println!(
                "after the break-off, seed {seed}: {} balls, {:?}, {} simulations",
                left, p.kind, p.simulations
            );
        }
    }
    if !times.is_empty() {
        let mean = times.iter().sum::<f64>() / times.len() as f64;
        let max = times.iter().copied().fold(0.0, f64::max);
        println!("after the break-off: mean {mean:.3} s, max {max:.3} s");
    }
    let (mut all, mut worst, mut n) = (0.0, 0.0f64, 0usize);
    for seed in 0..frames {
        let began = Instant::now();
        let between = Between {
            players: [Player::Computer(level); 2],
            params,
            seed,
            max_strokes: MAX_SHOTS,
        };
        let start = |names: [String; 2]| {
            SnookerGame::new(names, 1, table, params.ball)
                .map(|g| Box::new(g) as Box<dyn GameRules>)
                .map_err(|e| e.0)
        };
        let (r, _) = play_between(seed, 0, &between, &start).unwrap();
        for t in &r.players {
            all += t.decision_secs;
            worst = worst.max(t.max_decision_secs);
            n += t.decisions;
        }
        println!(
            "frame {seed}: {}-{} in {} strokes ({}), breaks {:?} / {:?}, {:.1} s",
            r.points[0],
            r.points[1],
            r.strokes,
            r.reason,
            r.players[0].runs,
            r.players[1].runs,
            began.elapsed().as_secs_f64()
        );
    }
    if n > 0 {
        println!(
            "in frames: {n} decisions, mean {:.3} s, max {worst:.3} s",
            all / n as f64
        );
    }
}

/// Plays the break-off of seed `seed` and judges it, giving the frame, the table and the count
/// of balls left as they lie: the next decision is the one timed, on the full table the
/// break-off leaves. `None` when the decision was not a shot.
fn after_break_off(
    frame: &Frame,
    sim: &Simulation,
    level: Level,
    seed: u64,
) -> Option<(Frame, Simulation, usize)> {
    let mut frame = frame.clone();
    let mut sim = sim.clone();
    let SnookerDecision::Shoot(p) = decide_snooker(&frame, &sim, level, seed).unwrap() else {
        return None;
    };
    sim.place(0, p.place.unwrap(), Vec2::ZERO, Vec3::ZERO)
        .unwrap();
    let before = on_table(&sim);
    let shot = p.executed(level.execution_noise(), sim.params(), seed);
    sim.strike(0, shot).unwrap();
    sim.run_to_rest().unwrap();
    let summary = summarise(sim.history().events(), sim.numbers());
    let after = on_table(&sim);
    let v = frame
        .play(Stroke {
            summary: &summary,
            nominated: p.nominated,
            before: &before,
            after: &after,
        })
        .unwrap();
    for &(c, at) in &v.spots {
        sim.place(usize::from(c), at, Vec2::ZERO, Vec3::ZERO)
            .unwrap();
    }
    Some((frame, sim, after.len()))
}
