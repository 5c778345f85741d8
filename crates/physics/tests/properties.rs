//! Property tests: random layouts, shots, parameters and seeds, every event checked by
//! `billiards_physics::check`. A failure shrinks to a small scene; keep it as a named
//! regression test (see `regressions.rs`).

mod common;
use billiards_physics::check::{Monitor, Tolerances};
use billiards_physics::soak::{Variation, has_friction, vary};
use billiards_physics::*;
use common::*;
use proptest::prelude::*;

/// Most events one property case may take: a Zeno cascade fails fast instead of stalling.
/// Perfectly inelastic balls in a tight rack (a saved case: e_ball = 0, friction 0.03) press
/// against each other through 50,000 to 100,000 resting contacts before they rest, with
/// predictions no longer going stale (tests/stale_predictions.rs); the cap leaves room for that.
const CASE_EVENT_CAP: usize = 200_000;

#[derive(Clone, Debug)]
enum Layout {
    Rack(Rack),
    Scattered { n: usize, max_speed: f64, seed: u64 },
}

fn layout() -> impl Strategy<Value = Layout> {
    prop_oneof![
        prop_oneof![
            Just(Rack::FifteenBall),
            Just(Rack::Tight),
            Just(Rack::NineBall),
            Just(Rack::PaperDefault),
        ]
        .prop_map(Layout::Rack),
        (1usize..=16, prop_oneof![Just(0.0), 0.0..5.0], any::<u64>())
            .prop_map(|(n, max_speed, seed)| Layout::Scattered { n, max_speed, seed }),
    ]
}

/// 10^x for x uniform in `lo..hi`: speeds and factors over many decades.
fn decades(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi).prop_map(|x| 10f64.powf(x))
}

fn restitution() -> impl Strategy<Value = f64> {
    prop_oneof![Just(1.0), Just(0.0), 0.0..=1.0]
}

fn variation() -> impl Strategy<Value = Option<Variation>> {
    let v = (
        // None, or a fiftieth to fifty times the model's (see soak::scenario).
        prop_oneof![Just(0.0), Just(1.0), decades(-1.7, 1.7)],
        restitution(),
        restitution(),
        decades(-3.0, 1.0),
        proptest::option::of((0.0..0.1, any::<u64>())),
    )
        .prop_map(|(friction, e_ball, e_cushion, threshold, rnd)| Variation {
            friction,
            e_ball,
            e_cushion,
            threshold,
            randomization: rnd.map(|(spread, seed)| Randomization { spread, seed }),
        });
    proptest::option::of(v)
}

#[derive(Clone, Debug)]
struct Scene {
    model: usize,
    variation: Option<Variation>,
    layout: Layout,
    angle: f64,
    speed: f64,
}

fn scene() -> impl Strategy<Value = Scene> {
    (
        0..models().len(),
        variation(),
        layout(),
        -std::f64::consts::PI..std::f64::consts::PI,
        decades(-9.0, 2.0),
    )
        .prop_map(|(model, variation, layout, angle, speed)| Scene {
            model,
            variation,
            layout,
            angle,
            speed,
        })
}

fn build(s: &Scene) -> Simulation {
    let base = Params {
        max_events: CASE_EVENT_CAP,
        ..models()[s.model].1
    };
    let params = s.variation.map_or(base, |v| vary(base, &v));
    let table = Table::wpa_8ft();
    let balls = match s.layout {
        Layout::Rack(rack) => rack.layout(&table, &params.ball),
        Layout::Scattered { n, max_speed, seed } => {
            racks::scattered(&table, &params.ball, n, max_speed, seed)
        }
    };
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    sim.strike(0, Shot::new(s.angle, s.speed)).unwrap();
    sim
}

/// Runs to rest, or for 2 s if nothing can ever rest, with every event checked.
fn run_checked(sim: &mut Simulation) -> Result<check::Stats, check::Violation> {
    let mut m = Monitor::new(sim, Tolerances::default())?;
    if has_friction(sim.params()) {
        m.run_to_rest(sim)
    } else {
        m.run_until(sim, 2.0)
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// Every invariant of `check` holds after every event of any scene.
    #[test]
    fn every_invariant_holds_after_every_event(s in scene()) {
        let mut sim = build(&s);
        if let Err(v) = run_checked(&mut sim) {
            prop_assert!(false, "{v}");
        }
    }

    /// Advancing in random slices processes exactly the events of a run in one call.
    ///
    /// The event cap counts per call, so one call to the end meets it no later than any slice:
    /// both runs may hit it (then they end alike and the case says nothing more), or the whole
    /// run alone (then its events are the first of the sliced run's), never the sliced run
    /// alone.
    #[test]
    fn slicing_time_does_not_change_the_events(
        s in scene(),
        slices in proptest::collection::vec(decades(-6.0, 0.0), 1..40),
    ) {
        let mut whole = build(&s);
        let mut sliced = whole.clone();
        let end = 2.0;
        let mut t = 0.0;
        let mut sliced_err = None;
        for dt in slices.iter().cycle() {
            if t >= end {
                break;
            }
            t = (t + dt).min(end);
            if let Err(e) = sliced.advance_to(t) {
                sliced_err = Some(e);
                break;
            }
        }
        let whole_err = whole.advance_to(end).err();
        match (&whole_err, &sliced_err) {
            (Some(w), Some(s)) => {
                prop_assert_eq!(std::mem::discriminant(w), std::mem::discriminant(s));
                return Ok(()); // Both at the event cap: the other property's business.
            }
            (None, Some(s)) => prop_assert!(false, "only the sliced run failed: {}", s),
            (Some(_), None) => {
                let (w, s) = (whole.history().events(), sliced.history().events());
                prop_assert!(w.len() <= s.len());
                prop_assert_eq!(w, &s[..w.len()]);
                return Ok(());
            }
            (None, None) => {}
        }
        prop_assert_eq!(whole.history().events(), sliced.history().events());
        prop_assert_eq!(whole.history().states_at(end), sliced.history().states_at(end));
    }
}
