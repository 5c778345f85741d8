//! Where the events of a lean sample go, against the yardstick's shots: the hard level's
//! candidates on the bench's 9-ball mid-game layout, `samples` noisy runs each read event by
//! event as the lean mode reads them (stopped on a settled verdict or by the quiet
//! shortcut), counted by kind and by how each sample ended and was judged; then as many of
//! the bench's yardstick shots (random, run to rest), counted by kind.
//!
//! ```sh
//! cargo run --release -p billiards-ai --example lean_anatomy -- 8
//! ```

mod fixture;

use billiards_ai::Level;
use billiards_ai::evaluate::settled;
use billiards_ai::noise::stream;
use billiards_ai::play::table_and_params;
use billiards_ai::quiet::final_layout;
use billiards_physics::{EventKind, Motion};
use billiards_rules::ShotSummary;
use std::collections::BTreeMap;

/// A name for the kind of `e` (transitions by their states).
fn kind(e: &EventKind) -> String {
    let m = |m: Motion| match m {
        Motion::Sliding => "slide",
        Motion::Rolling => "roll",
        Motion::Airborne => "air",
        Motion::Spinning => "spin",
        Motion::Stationary => "rest",
        Motion::Pocketed(_) => "pocketed",
        Motion::OffTable => "off",
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
    let (table, params) = table_and_params();
    let (state, mut base) = fixture::mid_game(table, params);
    base.set_record_history(false);
    let cands = fixture::hard_candidates(&base);
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
    let mut x = fixture::YARDSTICK_SEED;
    let mut kinds: BTreeMap<String, usize> = BTreeMap::new();
    for _ in 0..n {
        let mut s = base.clone();
        s.set_record_history(true);
        s.strike(0, fixture::yardstick_shot(&mut x))
            .expect("a shot in the contract");
        s.run_to_rest().expect("comes to rest");
        for e in s.history().events() {
            *kinds.entry(kind(&e.kind)).or_default() += 1;
        }
    }
    print("yardstick shots (its history)", &kinds, n);
}
