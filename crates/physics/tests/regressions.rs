//! Scenes that once broke the solver, each named after what it broke; the newer ones are
//! checked event by event (see `billiards_physics::check`).

mod common;
use billiards_physics::*;
use common::*;

fn r() -> f64 {
    BallSpec::default().radius
}

/// Runs soak scene `seed` with every event checked; its figures, or a panic naming the seed.
fn soak_scene(seed: u64) -> soak::SceneStats {
    soak::run_scenario(&soak::scenario(seed), check::Tolerances::default())
        .unwrap_or_else(|v| panic!("seed {seed}: {v}"))
}

/// Two touching rolling balls whose decelerations press them together: B ahead of A along
/// the line of centres, both moving at the same speed along it, A also drifting sideways at a
/// tenth of that. Each decelerates along its own velocity, so B slows along the line faster
/// than A (the paper's model): a pressing contact (3e-4 m/s^2, more than the centripetal pull
/// of their sliding past each other). It used to make a Zeno cascade, a contact every ~6e-7 s
/// (2 x 1e-10 m/s slack / pressing), hundreds of thousands of events before the balls stopped.
#[test]
fn pressed_rolling_pair_does_not_make_a_zeno_cascade() {
    for (name, p) in models() {
        for e_ball in [1.0, 0.5, 0.0] {
            let p = soak::vary(
                p,
                &soak::Variation {
                    friction: 1.0,
                    e_ball,
                    e_cushion: 0.8,
                    threshold: 1.0,
                    randomization: None,
                },
            );
            let balls = [
                rolling(0, Vec2::new(0.0, 0.0), Vec2::new(0.03, 0.003)),
                rolling(1, Vec2::new(2.0 * r(), 0.0), Vec2::new(0.03, 0.0)),
            ];
            let mut sim = Simulation::new(Table::wpa_8ft(), p, &balls).unwrap();
            let st = checked_to_rest(&mut sim, &format!("{name} e_ball {e_ball}"));
            // Pressed at ~3e-4 m/s^2 for ~0.3 s: a few hundred resting contacts at most.
            assert!(st.events < 2_000, "{name} e_ball {e_ball}: {st:?}");
        }
    }
}

/// The shrunk proptest case that found the pressing cascade in a rack: inelastic balls
/// (e = 0) stay in contact after the break and press each other while they decelerate.
#[test]
fn inelastic_balls_pressed_together_after_a_break_come_to_rest() {
    for (name, p) in models() {
        for (e_ball, speed) in [(0.0, 1.0), (0.05, 3.0)] {
            let p = soak::vary(
                p,
                &soak::Variation {
                    friction: 1.0,
                    e_ball,
                    e_cushion: 0.62,
                    threshold: 1.0,
                    randomization: None,
                },
            );
            let t = Table::wpa_8ft();
            let mut sim = Simulation::new(t, p, &Rack::FifteenBall.layout(&t, &p.ball)).unwrap();
            sim.strike(0, Shot::new(0.0, speed)).unwrap();
            checked_to_rest(&mut sim, &format!("{name} e_ball {e_ball} {speed} m/s"));
        }
    }
}

/// A ball touching a cushion and drifting into it slower than the resting speed (1e-10 m/s),
/// under very low friction so it runs for a long time: it used to count as resting against
/// the cushion and sink through it (1.2e-9 m after 22 s in soak seed 1068).
#[test]
fn ball_drifting_into_a_cushion_slower_than_the_resting_speed_cannot_sink() {
    let t = Table::wpa_8ft();
    for (name, p) in models() {
        let p = with_friction(p, 1.6e-3);
        let b = t.centre_bounds(p.ball.radius);
        let balls = [rolling(0, Vec2::new(0.5, b.y), Vec2::new(-0.015, 6.5e-11))];
        let mut sim = Simulation::new(t, p, &balls).unwrap();
        checked_to_rest(&mut sim, name);
        assert!(sim.time() > 50.0, "{name}: runs long enough to sink");
    }
}

/// Soak seed 334696: with no friction at all a ball has no next event of its own, and the
/// drift into a cushion at 9e-11 m/s was searched only up to the root bound of the gap
/// itself (about 1 s), never out to where it has sunk to the resting depth: 1.04e-9 m into
/// the rail 11 s later. Both models, frictionless, for 30 s.
#[test]
fn frictionless_ball_drifting_into_a_cushion_slower_than_the_resting_speed_cannot_sink() {
    let t = Table::scaled(4.0);
    for (name, p) in models() {
        let p = with_friction(p, 0.0);
        let b = t.centre_bounds(p.ball.radius);
        let balls = [rolling(0, Vec2::new(b.x, -1.0), Vec2::new(9.3e-11, 0.05))];
        let mut sim = Simulation::new(t, p, &balls).unwrap();
        checked_for(&mut sim, 30.0, name);
    }
}

/// The same drift between two balls rolling side by side at the same speed (so their
/// decelerations neither press nor part them), closing in at 5e-11 m/s.
#[test]
fn ball_drifting_into_another_slower_than_the_resting_speed_cannot_sink() {
    for (name, p) in models() {
        let p = with_friction(p, 1.6e-3);
        let balls = [
            rolling(0, Vec2::new(-0.5, 0.0), Vec2::new(0.015, 0.0)),
            rolling(1, Vec2::new(-0.5, 2.0 * r()), Vec2::new(0.015, -5e-11)),
        ];
        let mut sim = Simulation::new(Table::wpa_8ft(), p, &balls).unwrap();
        checked_to_rest(&mut sim, name);
        assert!(sim.time() > 50.0, "{name}: runs long enough to sink");
    }
}

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

/// Soak seeds 10288, 61081 and 78761 (spin-model breaks, friction a few percent of the
/// default) ended at the 1e6 event cap. In 10288 ball 8 rolls along the foot rail, pressed into
/// it by ball 2: every hop of that pair sent it into the rail at ~1e-6 m/s, Han's rebound left
/// it sliding with spin that rolled it back in, ~20 cushion and slide/roll events per hop, for
/// the ~10 s the balls take to stop. A spinning ball meeting a rail slower than
/// `resolve::SETTLE_SPEED` now settles against it; each scene rests within the cap and every
/// event passes the monitor.
#[test]
fn a_spinning_ball_pressed_into_a_rail_settles_instead_of_rebounding_forever() {
    for seed in [10288, 61081, 78761] {
        soak_scene(seed);
    }
}

/// Soak seed 110421 (paper model, no friction, jaws of radius 6.9 mm): a ball struck at
/// 11.6 m/s towards the foot-left corner went through the foot cushion's jaw and was pocketed
/// 2.4 mm deep in it. Its path crosses the jaw's circle for 3.7 ms; the closed-form entry root
/// was more than 16 ulps early and the fallback bracket reached past the exit (see
/// `poly::first_entry`).
#[test]
fn a_fast_ball_crossing_a_jaw_hits_it_instead_of_passing_through() {
    soak_scene(110421);
}

/// Soak seed 23445: a sliding ball with far more draw than speed (slip over 3.5 times its
/// velocity, along it) stops and comes back within its sliding segment. Its segment counted as
/// a straight decelerating path, so the culls bounded it by the run ahead of it, and it went
/// through the ball behind it (2.6 mm deep). Here: 5 cm/s forward, 50 rad/s of backspin, a
/// resting ball 7 cm behind (reached 0.15 s later, still sliding).
#[test]
fn a_ball_drawn_back_within_its_sliding_segment_hits_the_ball_behind_it() {
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let balls = [
        BallSetup {
            number: 0,
            position: Vec2::ZERO,
            velocity: Vec2::new(0.05, 0.0),
            spin: Vec3::new(0.0, -50.0, 0.0),
        },
        BallSetup::moving(1, Vec2::new(-0.07, 0.0), Vec2::ZERO),
    ];
    let mut sim = Simulation::new(huge_table(), params, &balls).unwrap();
    check::run_to_rest_checked(&mut sim).unwrap();
    let hit = sim
        .history()
        .events()
        .iter()
        .any(|e| e.kind == EventKind::BallBall { a: 0, b: 1 });
    assert!(hit, "the drawn ball must come back into ball 1");
}

/// Soak seeds 38383 and 43317 (spin-model breaks): balls wedged in a pocket mouth between its
/// jaws, pressed by a sliding neighbour, hopped apart by only the resting depth and touched
/// ~50,000 times a second per contact: 858,376 and 554,168 events in one shot, one of them
/// past the 1e6 cap. Resting contacts now open a gap of `detect::RESTING_HOP`; each jam rests
/// in far fewer events, every one passing the monitor.
#[test]
fn balls_wedged_in_a_pocket_mouth_rest_in_a_bounded_number_of_events() {
    for seed in [38383, 43317] {
        let st = soak_scene(seed);
        assert!(st.most_events < 200_000, "seed {seed}: {st:?}");
    }
}

/// Soak seeds 16706, 30230 and 38390 (spin-model scenes): a sliding ball with next to no roll
/// spin, driven by its cloth slip into a ball held by a rail. Neither tangential speed nor spin
/// could pay the resting hop, so the pair stayed sunk and touched again every 3e-14 s: the 1e6
/// event cap within a microsecond. The contact now removes the slip pressing the ball in
/// (`resolve::unpress`), as cloth friction would within microseconds.
#[test]
fn a_ball_slipping_into_a_ball_held_by_a_rail_stops_pressing_instead_of_a_zeno_cascade() {
    for seed in [16706, 30230, 38390] {
        let st = soak_scene(seed);
        assert!(st.most_events < 100_000, "seed {seed}: {st:?}");
    }
}

/// Soak seed 349173 (spin model, jaws, cushion restitution 0): two balls wedged in a corner
/// mouth, each against a jaw and against the other, at ~1 um/s. Resting contacts are elastic,
/// so ball 3 bounced between its jaw and ball 15 forever at one instant (the 1e6 cap at
/// t = 2.1365 s). A resting contact with the same cushion or jaw twice in one instant is now
/// plastic.
#[test]
fn a_ball_wedged_between_a_jaw_and_a_ball_does_not_bounce_forever_in_one_instant() {
    soak_scene(349173);
}

/// Soak seed 260383 (spin model, jaws of 15.6 mm, friction a quarter of the default): the one
/// failure in 1,037,877 soak shots of 6030258. Balls 1 and 10 wedged in the foot-right mouth,
/// each against a jaw and against the other, ball 1 still sliding with 29 rad/s of spin into
/// the wedge. At ~1e-9 m/s nothing paid the resting hop, so the jaws rebounded it elastically
/// and the three contacts cycled every 1.4e-9 s: the 1e6 event cap. A slow spinning ball now
/// settles against a jaw as against a rail.
#[test]
fn balls_wedged_between_two_jaws_rest_within_the_event_cap() {
    let st = soak_scene(260383);
    assert!(st.most_events < 100_000, "{st:?}");
}
