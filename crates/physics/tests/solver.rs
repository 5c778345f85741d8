//! The event loop: time slicing, invariants of a break, pockets, history, bad input.

mod common;
use billiards_physics::*;
use common::*;

fn segments(sim: &Simulation) -> Vec<Segment> {
    (0..sim.ball_count()).map(|i| *sim.segment(i)).collect()
}

#[test]
fn trajectory_does_not_depend_on_how_time_is_sliced() {
    let horizon = 0.25;
    let mut once = break_shot(Rack::FifteenBall, 9.0, Params::default());
    once.advance(horizon).unwrap();
    let mut hundredths = break_shot(Rack::FifteenBall, 9.0, Params::default());
    for _ in 0..25 {
        hundredths.advance(0.01).unwrap();
    }
    let mut random = break_shot(Rack::FifteenBall, 9.0, Params::default());
    // Deterministic pseudo-random slice ends (an LCG), ending exactly at the horizon.
    let mut x: u64 = 12345;
    let mut t = 0.0;
    while t < horizon {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        t = (t + (x >> 11) as f64 / (1u64 << 53) as f64 * 0.02).min(horizon);
        random.advance_to(t).unwrap();
    }
    assert!(once.history().events().len() > 20, "the break has started");
    for other in [&hundredths, &random] {
        assert_eq!(once.history().events(), other.history().events());
        assert_eq!(segments(&once), segments(other));
        // Sampled at the same instant, the states are bit-identical.
        assert_eq!(
            once.history().states_at(horizon),
            other.history().states_at(horizon)
        );
    }
}

#[test]
fn fifteen_ball_break_never_overlaps_or_escapes_and_comes_to_rest() {
    for speed in [8.0, 9.5, 11.0] {
        for rack in [Rack::FifteenBall, Rack::Tight, Rack::NineBall] {
            let mut sim = break_shot(rack, speed, Params::default());
            sim.run_to_rest().unwrap();
            assert!(sim.is_at_rest());
            assert!(sim.history().events().len() > 30);
            assert_no_overlap_or_escape(&sim, 1e-9);
        }
    }
}

#[test]
fn energy_never_increases_and_time_never_goes_back_in_a_break() {
    let p = Params {
        model: Model::Paper(PaperModel {
            e_ball: 0.95,
            e_cushion: 0.85,
            ..PaperModel::default()
        }),
        ..Params::default()
    };
    let mut sim = break_shot(Rack::FifteenBall, 10.0, p);
    sim.run_to_rest().unwrap();
    let h = sim.history();
    let mut last = (0.0, f64::INFINITY);
    for e in h.events() {
        assert!(e.time >= last.0);
        let ke = kinetic_energy(&h.states_at(e.time), p.ball.mass);
        assert!(ke <= last.1 * (1.0 + 1e-12), "energy rose at {e:?}");
        last = (e.time, ke);
    }
}

#[test]
fn momentum_is_conserved_by_every_ball_ball_collision() {
    let mut sim = break_shot(Rack::FifteenBall, 10.0, Params::default());
    sim.run_to_rest().unwrap();
    let h = sim.history();
    let mut checked = 0;
    for e in h.events() {
        if let EventKind::BallBall { a, b } = e.kind {
            let va = prior_velocity(h, a, e.time);
            let vb = prior_velocity(h, b, e.time);
            let sum = va + vb;
            let after = e.after[0].velocity + e.after[1].velocity;
            assert!(
                (sum - after).length() <= 1e-14 * (va.length() + vb.length()).max(1e-300),
                "{e:?}"
            );
            checked += 1;
        }
    }
    assert!(checked > 10);
}

/// Velocity of ball `id` just before time `t`, from the segment in force before the event.
fn prior_velocity(h: &History, id: BallId, t: f64) -> Vec2 {
    let track = h.track(id);
    let i = track.partition_point(|s| s.start < t).max(1) - 1;
    // Several events can share the instant: take the segment in force just before this one.
    let seg = track[..=i]
        .iter()
        .rev()
        .find(|s| s.start < t || s.start == 0.0)
        .unwrap();
    seg.velocity_at(t)
}

#[test]
fn history_samples_the_same_state_as_the_live_simulation() {
    let mut sim = break_shot(Rack::FifteenBall, 9.0, Params::default());
    for k in 1..=40 {
        sim.advance_to(k as f64 * 0.05).unwrap();
        let live: Vec<BallState> = sim.balls().collect();
        assert_eq!(live, sim.history().states_at(sim.time()));
    }
}

#[test]
fn ball_into_the_corner_pocket_is_pocketed() {
    let t = Table::wpa_8ft();
    let p = Params::default();
    let start = Vec2::new(0.5, 0.1);
    let target = t.pocket_position(Pocket::FootLeft);
    let mut sim = Simulation::new(t, p, &[BallSetup::at(0, start)]).unwrap();
    sim.strike(0, Shot::new((target - start).angle(), 3.0))
        .unwrap();
    sim.run_to_rest().unwrap();
    assert_eq!(sim.ball(0).motion, Motion::Pocketed(Pocket::FootLeft));
    assert!(sim.history().events().iter().any(|e| e.kind
        == EventKind::Pocketed {
            ball: 0,
            pocket: Pocket::FootLeft
        }));
}

#[test]
fn ball_straight_into_the_side_pocket_mouth_is_pocketed_and_beside_it_rebounds() {
    let t = Table::wpa_8ft();
    let p = Params::default();
    let half = 0.5 * t.side_mouth;
    for (x, pocketed) in [
        (0.0, true),
        (half - 1e-4, true),
        (-half + 1e-4, true),
        (half + 1e-4, false),
        (-half - 1e-3, false),
    ] {
        let mut sim = Simulation::new(t, p, &[BallSetup::at(0, Vec2::new(x, 0.0))]).unwrap();
        sim.strike(0, Shot::new(std::f64::consts::FRAC_PI_2, 2.0))
            .unwrap();
        let ev = sim.step_event().unwrap();
        let expect = if pocketed {
            EventKind::Pocketed {
                ball: 0,
                pocket: Pocket::SideLeft,
            }
        } else {
            EventKind::Cushion {
                ball: 0,
                cushion: Cushion::Left,
            }
        };
        assert_eq!(ev.kind, expect, "x = {x}");
    }
}

#[test]
fn corner_pocket_mouth_ends_where_the_cushion_starts() {
    let t = Table::wpa_8ft();
    let p = Params::default();
    let edge = 0.5 * t.width - t.corner_leg();
    for (y, pocketed) in [(edge + 1e-4, true), (edge - 1e-4, false)] {
        let mut sim = Simulation::new(t, p, &[BallSetup::at(0, Vec2::new(0.0, y))]).unwrap();
        sim.strike(0, Shot::new(0.0, 3.0)).unwrap();
        let ev = sim.step_event().unwrap();
        assert_eq!(
            matches!(
                ev.kind,
                EventKind::Pocketed {
                    pocket: Pocket::FootLeft,
                    ..
                }
            ),
            pocketed,
            "y = {y}: {ev:?}"
        );
    }
}

#[test]
fn grazing_pair_is_decided_by_the_sign_of_the_gap() {
    // Ball passes a resting ball with its line at 2R + eps (miss) or 2R - eps (hit).
    let p = frictionless();
    let r = p.ball.radius;
    for (offset, hit) in [(1e-12, false), (-1e-12, true), (1e-9, false), (-1e-9, true)] {
        let balls = [
            BallSetup::moving(0, Vec2::new(-0.5, 2.0 * r + offset), Vec2::new(1.0, 0.0)),
            BallSetup::at(1, Vec2::ZERO),
        ];
        let mut sim = Simulation::new(Table::wpa_8ft(), p, &balls).unwrap();
        let ev = sim.step_event().unwrap();
        assert_eq!(
            matches!(ev.kind, EventKind::BallBall { .. }),
            hit,
            "offset {offset}: {ev:?}"
        );
    }
}

#[test]
fn touching_balls_that_approach_collide_at_once_and_separating_ones_do_not() {
    let p = Params::default();
    let r = p.ball.radius;
    let at = |v: f64| {
        let balls = [
            BallSetup::moving(0, Vec2::ZERO, Vec2::new(v, 0.0)),
            BallSetup::at(1, Vec2::new(2.0 * r, 0.0)),
        ];
        Simulation::new(Table::wpa_8ft(), p, &balls).unwrap()
    };
    let mut approach = at(1.0);
    assert_eq!(approach.next_event_time(), Some(0.0));
    assert_eq!(
        approach.step_event().unwrap().kind,
        EventKind::BallBall { a: 0, b: 1 }
    );
    let mut separate = at(-1.0);
    assert!(!matches!(
        separate.step_event().unwrap().kind,
        EventKind::BallBall { .. }
    ));
}

#[test]
fn newtons_cradle_passes_the_velocity_down_the_line() {
    let p = frictionless();
    let r = p.ball.radius;
    let mut balls: Vec<BallSetup> = (0..6)
        .map(|i| BallSetup::at(i, Vec2::new(-0.3 + 2.0 * r * i as f64, 0.0)))
        .collect();
    balls[0].position.x -= 0.2;
    balls[0].velocity = Vec2::new(1.0, 0.0);
    let mut sim = Simulation::new(Table::wpa_8ft(), p, &balls).unwrap();
    for _ in 0..5 {
        assert!(matches!(
            sim.step_event().unwrap().kind,
            EventKind::BallBall { .. }
        ));
    }
    let v: Vec<f64> = sim.balls().map(|b| b.velocity.x).collect();
    assert_eq!(v, vec![0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn frictionless_run_to_rest_reports_the_event_cap() {
    let p = Params {
        max_events: 500,
        ..frictionless()
    };
    let mut sim = one_ball(Table::wpa_8ft(), p, Vec2::new(1.0, 0.0));
    match sim.run_to_rest() {
        Err(SimError::EventCap { cap: 500, .. }) => {}
        other => panic!("expected the cap, got {other:?}"),
    }
    assert_no_overlap_or_escape(&sim, 1e-9);
}

#[test]
fn bad_input_is_rejected_with_a_clear_error() {
    let t = Table::wpa_8ft();
    let p = Params::default();
    let r = p.ball.radius;
    let nan = Simulation::new(t, p, &[BallSetup::at(0, Vec2::new(f64::NAN, 0.0))]);
    assert!(matches!(
        nan,
        Err(SetupError::NonFinite {
            ball: 0,
            number: 0,
            what: "position"
        })
    ));
    let inf = Simulation::new(
        t,
        p,
        &[BallSetup::moving(
            0,
            Vec2::ZERO,
            Vec2::new(f64::INFINITY, 0.0),
        )],
    );
    assert!(matches!(
        inf,
        Err(SetupError::NonFinite {
            what: "velocity",
            ..
        })
    ));
    let overlap = Simulation::new(
        t,
        p,
        &[
            BallSetup::at(0, Vec2::ZERO),
            BallSetup::at(1, Vec2::new(r, 0.0)),
        ],
    );
    assert!(matches!(
        overlap,
        Err(SetupError::Overlap { a: 0, b: 1, .. })
    ));
    // Messages name balls by the number a player sees (issue 15, item 2).
    let pair = [
        BallSetup::at(0, Vec2::ZERO),
        BallSetup::at(8, Vec2::new(r, 0.0)),
    ];
    let text = Simulation::new(t, p, &pair).unwrap_err().to_string();
    assert!(
        text.starts_with("the cue ball and ball 8 (index 1) overlap by"),
        "{text}"
    );
    let outside = Simulation::new(t, p, &[BallSetup::at(0, Vec2::new(2.0, 0.0))]);
    assert!(matches!(
        outside,
        Err(SetupError::OutsideTable { ball: 0, .. })
    ));
    let outside = Simulation::new(t, p, &[BallSetup::at(5, Vec2::new(2.0, 0.0))]).unwrap_err();
    assert_eq!(
        outside.to_string(),
        "ball 5 (index 0) at (2, 0) is outside the table"
    );
    let neg = Params {
        model: Model::Paper(PaperModel {
            mu_slide: -0.1,
            ..PaperModel::default()
        }),
        ..p
    };
    let e = Simulation::new(t, neg, &[]).unwrap_err();
    assert!(e.to_string().contains("mu_slide"), "{e}");
    let bad_table = Table {
        length: f64::NAN,
        ..t
    };
    assert!(matches!(
        Simulation::new(bad_table, p, &[]),
        Err(SetupError::Table(_))
    ));
    let mut sim = Simulation::new(t, p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    assert!(sim.strike(0, Shot::new(f64::NAN, 1.0)).is_err());
    assert!(sim.strike(3, Shot::new(0.0, 1.0)).is_err());
    assert!(sim.advance(-1.0).is_err());
    assert!(sim.advance(f64::NAN).is_err());
}

#[test]
fn changing_friction_mid_shot_reaches_the_moving_balls() {
    let mut sim = one_ball(huge_table(), Params::default(), Vec2::new(1.0, 0.0));
    sim.advance(0.1).unwrap();
    let x = sim.ball(0).position.x;
    let high = Params {
        model: Model::Paper(PaperModel {
            mu_roll: 0.1,
            ..PaperModel::default()
        }),
        ..Params::default()
    };
    sim.set_params(high).unwrap();
    sim.run_to_rest().unwrap();
    let v = 1.0 - 0.2 * G * 0.1_f64.min((1.0 - 0.5) / (0.2 * G)); // speed at 0.1 s (still sliding)
    let a = 0.2 * G;
    let expect = x + (v * v - 0.25) / (2.0 * a) + 0.25 / (2.0 * 0.1 * G);
    assert!(rel(sim.ball(0).position.x, expect) < 1e-12);
}

#[test]
fn hundreds_of_balls_on_a_large_table_never_overlap_or_escape() {
    // Above 64 balls the solver tests only balls in neighbouring grid cells; a pair it failed
    // to test would show up here as an overlap.
    let n = 400;
    let table = Table::scaled((n as f64 / 16.0).sqrt());
    let p = Params::default();
    let balls = billiards_physics::racks::scattered(&table, &p.ball, n, 3.0, 11);
    let mut sim = Simulation::new(table, p, &balls).unwrap();
    sim.run_to_rest().unwrap();
    let collisions = sim
        .history()
        .events()
        .iter()
        .filter(|e| matches!(e.kind, EventKind::BallBall { .. }))
        .count();
    assert!(collisions > 100, "only {collisions} collisions");
    assert_no_overlap_or_escape(&sim, 1e-9);
}
