//! Scenes that once broke the solver, each named after what it broke; the newer ones are
//! checked event by event (see `billiards_physics::check`).

mod common;
use billiards_physics::*;
use common::*;

fn r() -> f64 {
    BallSpec::default().radius
}

/// What a soak seed drew when its regression was found: the model, the kind of scene, the
/// balls, the shots, the jaws' radius (`None`: mouths), the first shot's speed and angle and
/// ball 0's starting position, the numbers bit for bit (as `{:?}` prints them).
type Drawn = (
    &'static str,
    &'static str,
    usize,
    usize,
    Option<f64>,
    f64,
    f64,
    [f64; 2],
);

/// The scenes the seeds below replay, as they were drawn: a change of the generator's draws
/// would give a seed another scene and silently test that one instead.
const DRAWN: [(u64, Drawn); 11] = [
    (
        10288,
        (
            "spin",
            "break",
            16,
            2,
            Some(0.02830668168294122),
            6.734567317747242,
            -0.040357288787553985,
            HEAD_SPOT,
        ),
    ),
    (
        61081,
        (
            "spin",
            "break",
            16,
            3,
            Some(0.008352190582754422),
            8.639417514606139,
            0.0,
            HEAD_SPOT,
        ),
    ),
    (
        78761,
        (
            "spin",
            "break",
            16,
            3,
            Some(0.028012778582397264),
            9.457643018041265,
            0.034247652627017275,
            HEAD_SPOT,
        ),
    ),
    (
        110421,
        (
            "paper",
            "shot",
            15,
            3,
            Some(0.006858888166351186),
            2.44196336771248,
            -2.774236313927041,
            [-0.9406028145934108, -0.38954313609031566],
        ),
    ),
    (
        38383,
        (
            "spin",
            "break",
            16,
            2,
            Some(0.019827923132331983),
            7.986164088456265,
            0.0026176983511056115,
            HEAD_SPOT,
        ),
    ),
    (
        43317,
        (
            "spin",
            "break",
            16,
            4,
            Some(0.014047375981124106),
            12.005631505720624,
            -0.029940713430167156,
            HEAD_SPOT,
        ),
    ),
    (
        16706,
        (
            "spin",
            "break",
            16,
            4,
            None,
            7.522463382095732,
            -0.005173581697180206,
            HEAD_SPOT,
        ),
    ),
    (
        30230,
        (
            "spin",
            "break",
            10,
            4,
            Some(0.01365127899343892),
            6.622939760436512,
            0.0,
            HEAD_SPOT,
        ),
    ),
    (
        38390,
        (
            "spin",
            "shot",
            15,
            3,
            Some(0.015407407638065636),
            5.935028751759814e-9,
            -0.705832758279981,
            [-0.8135857941017923, -0.28203956430042193],
        ),
    ),
    (
        349173,
        (
            "spin",
            "break",
            16,
            2,
            Some(0.009562638412937058),
            12.0646379208403,
            0.03373083673358479,
            HEAD_SPOT,
        ),
    ),
    (
        260383,
        (
            "spin",
            "break",
            16,
            3,
            Some(0.01564044038272478),
            4.064339410343656,
            -0.014258048078906294,
            HEAD_SPOT,
        ),
    ),
];

/// The cue ball of a break, on the head string.
const HEAD_SPOT: [f64; 2] = [-0.5841999999999999, 0.0];

/// Runs soak scene `seed` with every event checked; its figures, or a panic naming the seed.
/// First checks that the seed still draws the scene of [`DRAWN`].
fn soak_scene(seed: u64) -> soak::SceneStats {
    let s = soak::scenario(seed);
    let (_, want) = DRAWN
        .iter()
        .find(|d| d.0 == seed)
        .unwrap_or_else(|| panic!("seed {seed} is not in DRAWN"));
    let jaws = match s.table.pockets {
        PocketShape::Jaws { radius } => Some(radius),
        PocketShape::Mouth | PocketShape::Pocketless => None,
    };
    let p = s.balls[0].position;
    let got: Drawn = (
        s.model,
        s.kind,
        s.balls.len(),
        s.shots.len(),
        jaws,
        s.shots[0].speed,
        s.shots[0].angle,
        [p.x, p.y],
    );
    assert_eq!(&got, want, "seed {seed} draws another scene");
    soak::run_scenario(&s, check::Tolerances::default())
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
