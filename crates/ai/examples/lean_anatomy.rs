//! Where the events of a lean sample go, against the yardstick's shots: the hard level's
//! candidates on the bench's 9-ball mid-game layout, `samples` noisy runs each read event by
//! event as the lean mode reads them (stopped on a settled verdict or by the quiet
//! shortcut), counted by kind and by how each sample ended and was judged; then as many of
//! the bench's yardstick shots (random, run to rest), counted by kind.
//!
//! ```sh
//! cargo run --release -p billiards-ai --example lean_anatomy -- 8
//! ```

use billiards_ai::candidates::{combo_aims, direct_aims, expand, rail_aims, safeties};
use billiards_ai::evaluate::settled;
use billiards_ai::noise::stream;
use billiards_ai::play::table_and_params;
use billiards_ai::quiet::final_layout;
use billiards_ai::{Layout, Level};
use billiards_physics::{BallSetup, EventKind, Motion, Shot, Simulation, Vec2};
use billiards_rules::{CueBall, Game, GameState, Seat, ShotSummary};
use std::collections::BTreeMap;

/// A name for the kind of `e` (transitions by their states).
fn kind(e: &EventKind) -> String {
    let m = |m: Motion| match m {
        Motion::Sliding => "slide",
        Motion::Rolling => "roll",
        Motion::Spinning => "spin",
        Motion::Stationary => "rest",
        Motion::Pocketed(_) => "pocketed",
    };
    match *e {
        EventKind::Transition { from, to, .. } => format!("transition {} to {}", m(from), m(to)),
        EventKind::Cushion { .. } => "cushion".into(),
        EventKind::Jaw { .. } => "jaw".into(),
        EventKind::Pocketed { .. } => "pocketed".into(),
        EventKind::BallBall { .. } => "ball-ball".into(),
        EventKind::Strike { .. } => "strike".into(),
        _ => "other".into(),
    }
}

fn print(title: &str, kinds: &BTreeMap<String, usize>, n: usize) {
    let all: usize = kinds.values().sum();
    println!(
        "{title}: {n} runs, {:.2} events each",
        all as f64 / n as f64
    );
    for (k, v) in kinds {
        println!("  {k:28} {:6.2}", *v as f64 / n as f64);
    }
}

fn main() {
    let samples: u64 = std::env::args()
        .nth(1)
        .map_or(8, |s| s.parse().expect("samples"));
    let balls = [
        (0, Vec2::new(-0.35, 0.05)),
        (2, Vec2::new(0.25, 0.30)),
        (3, Vec2::new(0.62, -0.21)),
        (5, Vec2::new(-0.71, -0.38)),
        (6, Vec2::new(0.05, -0.44)),
        (8, Vec2::new(0.88, 0.12)),
        (9, Vec2::new(0.45, 0.02)),
    ];
    let (table, params) = table_and_params();
    let setups: Vec<BallSetup> = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
    let mut base = Simulation::new(table, params, &setups).expect("layout");
    base.set_record_history(false);
    let mut state = GameState::new(Game::NineBall, Seat::A);
    state.on_table = vec![2, 3, 5, 6, 8, 9];
    state.next.break_shot = false;
    state.next.cue_ball = CueBall::AsItLies;
    state.next.legal_first = vec![2];
    let layout = Layout::of(&base, None).expect("cue ball");
    let budget = Level::Hard.budget();
    let mut aims = direct_aims(&layout, &[2]);
    aims.extend(rail_aims(&layout, &[2]));
    aims.extend(combo_aims(&layout, &[2], &[3, 5, 6, 8, 9]));
    let mut cands = expand(&aims, budget.speeds, budget.tips, false, None);
    cands.extend(safeties(&layout, &[2], budget.safeties, None));
    let noise = Level::Hard.planning_noise();
    let mut kinds: BTreeMap<String, usize> = BTreeMap::new();
    let mut ends: BTreeMap<String, (usize, usize)> = BTreeMap::new();
    let mut n = 0;
    for (i, c) in cands.iter().enumerate() {
        for k in 0..samples {
            let mut sim = base.clone();
            let shot = noise.apply(c.shot, sim.params(), &mut stream(1, i as u64, k));
            sim.strike(0, shot).expect("a shot in the contract");
            *kinds.entry("strike".into()).or_default() += 1;
            let (mut summary, mut events, mut end) = (ShotSummary::default(), 1, "at rest");
            while let Some(e) = sim.step_event() {
                events += 1;
                *kinds.entry(kind(&e.kind)).or_default() += 1;
                summary.record(&e.kind, sim.numbers());
                if settled(&state, c.call, &summary) {
                    end = "settled";
                    break;
                }
                if matches!(e.kind, EventKind::Transition { .. }) && final_layout(&sim).is_some() {
                    end = "quiet shortcut";
                    break;
                }
            }
            let verdict = match state.clone().play(&summary, c.call) {
                Ok(v) if !v.legal() => "foul".to_string(),
                Ok(v) => format!("legal, {:?}", v.outcome),
                Err(e) => format!("refused: {e}"),
            };
            let e = ends.entry(format!("{end}, {verdict}")).or_default();
            e.0 += 1;
            e.1 += events;
            n += 1;
        }
    }
    print("lean samples (the strike counted as an event)", &kinds, n);
    for (k, (m, e)) in &ends {
        println!(
            "  {k:50} {m:5} samples, {:.1} events each",
            *e as f64 / *m as f64
        );
    }
    // The bench's yardstick: the same stream of random shots, run to rest.
    let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut uniform = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut kinds: BTreeMap<String, usize> = BTreeMap::new();
    for _ in 0..n {
        let mut s = base.clone();
        s.set_record_history(true);
        let shot = Shot::new(uniform() * std::f64::consts::TAU, 0.1 + 7.9 * uniform());
        s.strike(0, shot).expect("a shot in the contract");
        s.run_to_rest().expect("comes to rest");
        for e in s.history().events() {
            *kinds.entry(kind(&e.kind)).or_default() += 1;
        }
    }
    print("yardstick shots (its history)", &kinds, n);
}
