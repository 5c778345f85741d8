//! Adversarial scenes, one test each, run for every model configuration with every event
//! checked by `billiards_physics::check` (no overlap beyond 1e-9 m, no escape, energy never
//! rising except at a strike, momentum kept at ball–ball contacts, time monotone, no NaN, rest
//! within the event cap).

mod common;
use billiards_physics::*;
use common::*;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

fn r() -> f64 {
    BallSpec::default().radius
}

fn sim(table: Table, params: Params, balls: &[BallSetup]) -> Simulation {
    Simulation::new(table, params, balls).expect("a valid scene")
}

fn moving(number: u8, position: Vec2, velocity: Vec2) -> BallSetup {
    BallSetup {
        velocity,
        ..BallSetup::at(number, position)
    }
}

#[test]
fn tight_rack_with_every_ball_exactly_touching_breaks_without_overlap() {
    // Neighbours at exactly 2R (to rounding): the first contact starts a cascade of contacts
    // at one instant, which must resolve without overlap, energy gain or an endless chain.
    for (name, p) in models() {
        for rack in [Rack::Tight, Rack::NineBall] {
            for speed in [0.3, 2.0, 8.0, 14.0] {
                for angle in [0.0, 1e-9, 0.01] {
                    let t = Table::wpa_8ft();
                    let balls = rack.layout(&t, &p.ball);
                    let mut s = sim(t, p, &balls);
                    s.strike(0, Shot::new(angle, speed)).unwrap();
                    checked_to_rest(&mut s, &format!("{name} {rack:?} {speed} m/s {angle} rad"));
                }
            }
        }
    }
}

#[test]
fn newtons_cradle_lines_of_2_to_15_balls_pass_the_velocity_along() {
    // A line of touching balls hit head-on: with elastic balls and no friction the last ball
    // leaves with the striker's velocity and every other ball stops (exchange of normal
    // velocities, chained at one instant).
    for (name, p) in models() {
        for n in 2..=15 {
            for friction in [0.0, 1.0] {
                let p = with_friction(p, friction);
                let x0 = -0.5;
                let mut balls: Vec<BallSetup> = (0..n)
                    .map(|i| BallSetup::at(i as u8, Vec2::new(x0 + 2.0 * r() * i as f64, 0.0)))
                    .collect();
                balls[0].position.x -= 0.3;
                let what = format!("{name}, {n} balls, friction x{friction}");
                let mut s = sim(Table::wpa_8ft(), p, &balls);
                s.strike(0, Shot::new(0.0, 1.0)).unwrap();
                if friction == 0.0 {
                    // Up to just before the last ball reaches the foot cushion.
                    checked_for(&mut s, 0.5, &what);
                    // The paper's exact exchange (the spin model's balls slide and throw).
                    if matches!(p.model, Model::Paper(m) if m.e_ball == 1.0) {
                        let v: Vec<f64> = s.balls().map(|b| b.velocity.x).collect();
                        let mut want = vec![0.0; n];
                        want[n - 1] = 1.0;
                        assert_eq!(v, want, "{what}");
                    }
                } else {
                    checked_to_rest(&mut s, &what);
                }
            }
        }
    }
}

#[test]
fn grazing_contacts_at_2r_plus_or_minus_1e_12_are_decided_by_the_sign_of_the_gap() {
    // A ball passing a resting one with its line of centres offset by 2R + d: a hit iff d < 0,
    // at every speed, and the same whether the run is stepped event by event or sliced.
    for (name, p) in models() {
        for d in [-1e-12, 1e-12, -1e-11, 1e-11] {
            for speed in [0.01, 0.6, 3.0, 30.0] {
                let balls = [
                    moving(0, Vec2::new(-0.2, 2.0 * r() + d), Vec2::new(speed, 0.0)),
                    BallSetup::at(1, Vec2::ZERO),
                ];
                let what = format!("{name}, offset {d}, {speed} m/s");
                let mut stepped = sim(Table::wpa_8ft(), p, &balls);
                checked_to_rest(&mut stepped, &what);
                let hit = stepped
                    .history()
                    .events()
                    .iter()
                    .any(|e| matches!(e.kind, EventKind::BallBall { .. }));
                // Slow balls stop before reaching the other one.
                let reaches = stepped.history().events().iter().any(|e| e.time > 0.0)
                    && speed * speed / (2.0 * G * 0.2) > 0.2 + 0.01;
                if reaches {
                    assert_eq!(hit, d < 0.0, "{what}");
                }
                let mut sliced = sim(Table::wpa_8ft(), p, &balls);
                while !sliced.is_at_rest() {
                    sliced.advance(0.013).unwrap();
                }
                assert_eq!(
                    stepped.history().events(),
                    sliced.history().events(),
                    "{what}"
                );
            }
        }
    }
}

#[test]
fn ball_hitting_two_touching_balls_at_exactly_the_same_time() {
    // Two touching balls side by side, struck exactly between them: two contacts at one
    // instant (and the pair's own contact), resolved in a fixed order without overlap.
    for (name, p) in models() {
        for speed in [0.5, 3.0, 12.0] {
            let balls = [
                BallSetup::at(0, Vec2::new(-0.5, 0.0)),
                BallSetup::at(1, Vec2::new(0.2, r())),
                BallSetup::at(2, Vec2::new(0.2, -r())),
            ];
            let mut s = sim(Table::wpa_8ft(), p, &balls);
            s.strike(0, Shot::new(0.0, speed)).unwrap();
            checked_to_rest(&mut s, &format!("{name} {speed} m/s"));
            let first: Vec<&Event> = s
                .history()
                .events()
                .iter()
                .filter(|e| matches!(e.kind, EventKind::BallBall { .. }))
                .take(2)
                .collect();
            // The same instant to rounding (the second root is found from the first contact).
            assert!(
                (first[0].time - first[1].time).abs() < 1e-12,
                "{name}: both contacts at once: {first:?}"
            );
        }
    }
}

#[test]
fn symmetric_breaks_dead_straight_into_every_rack() {
    // Struck exactly along the axis of symmetry: many contacts at equal times.
    for (name, p) in models() {
        for rack in [Rack::FifteenBall, Rack::Tight, Rack::NineBall] {
            for speed in [4.0, 9.0, 13.0] {
                let t = Table::wpa_8ft();
                let mut s = sim(t, p, &rack.layout(&t, &p.ball));
                s.strike(0, Shot::new(0.0, speed)).unwrap();
                let st = checked_to_rest(&mut s, &format!("{name} {rack:?} {speed} m/s"));
                assert!(st.events > 20);
            }
        }
    }
}

#[test]
fn ball_rolling_along_a_cushion_stays_on_the_table() {
    // Centre exactly on the cushion line (touching it), moving along it, a hair into it or a
    // hair away from it: never beyond the cushion, pocketed or stopped in the end.
    let t = Table::wpa_8ft();
    for (name, p) in models() {
        let b = t.centre_bounds(p.ball.radius);
        for tilt in [0.0, 1e-12, -1e-12, 1e-6, -1e-6] {
            for speed in [0.05, 0.4, 2.0, 8.0] {
                for (pos, angle) in [
                    (Vec2::new(-0.8, b.y), 0.0 + tilt),
                    (Vec2::new(0.8, -b.y), PI - tilt),
                    (Vec2::new(b.x, 0.2), FRAC_PI_2 - tilt),
                    (Vec2::new(-b.x, -0.2), -FRAC_PI_2 + tilt),
                ] {
                    let mut s = sim(t, p, &[BallSetup::at(0, pos)]);
                    s.strike(0, Shot::new(angle, speed)).unwrap();
                    checked_to_rest(
                        &mut s,
                        &format!("{name} at {pos:?} angle {angle} {speed} m/s"),
                    );
                }
            }
        }
    }
}

#[test]
fn pocket_jaws_hit_at_every_angle_never_let_a_ball_escape() {
    // Aim at each end of every pocket mouth (where `pocket_at` changes its answer), a hair
    // either side of it, from every direction that reaches it: the ball is pocketed or
    // rebounds, never leaves the table.
    let t = Table::wpa_8ft();
    let (hx, hy) = (0.5 * t.length, 0.5 * t.width);
    let leg = t.corner_leg();
    let half_side = 0.5 * t.side_mouth;
    for (name, p) in models() {
        let b = t.centre_bounds(p.ball.radius);
        // (contact point of the centre on the cushion line, inward normal)
        let mut targets = Vec::new();
        for sx in [-1.0, 1.0] {
            for sy in [-1.0, 1.0] {
                targets.push((Vec2::new(sx * b.x, sy * (hy - leg)), Vec2::new(-sx, 0.0)));
                targets.push((Vec2::new(sx * (hx - leg), sy * b.y), Vec2::new(0.0, -sy)));
                targets.push((Vec2::new(sx * half_side, sy * b.y), Vec2::new(0.0, -sy)));
            }
        }
        for (edge, n) in targets {
            for off in [-1e-9, -1e-12, 0.0, 1e-12, 1e-9] {
                let along = n.perp();
                let target = edge + along * off;
                // Directions into the cushion, 1 degree apart.
                for k in 1..180 {
                    let into = n.rotated(PI + (k as f64 - 90.0).to_radians());
                    let start = target - into * 0.25;
                    if start.x.abs() > b.x || start.y.abs() > b.y {
                        continue;
                    }
                    let mut s = sim(t, p, &[BallSetup::at(0, start)]);
                    s.strike(0, Shot::new(into.angle(), 2.5)).unwrap();
                    checked_to_rest(&mut s, &format!("{name} jaw {edge:?}+{off} dir {k}"));
                }
            }
        }
    }
}

#[test]
fn speeds_from_1e_9_to_100_metres_per_second() {
    // Eleven decades of cue speed into a rack and across an empty table.
    let t = Table::wpa_8ft();
    for (name, p) in models() {
        for k in -9..=2 {
            for mantissa in [1.0, 3.0] {
                let speed = mantissa * 10f64.powi(k);
                if speed > 100.0 {
                    continue;
                }
                for rack in [Rack::FifteenBall, Rack::Tight, Rack::PaperDefault] {
                    let mut s = sim(t, p, &rack.layout(&t, &p.ball));
                    s.strike(0, Shot::new(0.003, speed)).unwrap();
                    checked_to_rest(&mut s, &format!("{name} {rack:?} {speed} m/s"));
                }
            }
        }
    }
}

#[test]
fn friction_zero_and_friction_large() {
    // Without friction nothing ever rests: run 10 s of a break and check every event. With
    // friction 100 times the usual, every ball stops within millimetres.
    let t = Table::wpa_8ft();
    for (name, p) in models() {
        for rack in [Rack::FifteenBall, Rack::Tight] {
            let mut s = sim(t, with_friction(p, 0.0), &rack.layout(&t, &p.ball));
            s.strike(0, Shot::new(0.01, 6.0)).unwrap();
            let st = checked_for(&mut s, 10.0, &format!("{name} frictionless {rack:?}"));
            assert!(st.events > 50, "{name} {rack:?}: {st:?}");
            let mut s = sim(t, with_friction(p, 100.0), &rack.layout(&t, &p.ball));
            s.strike(0, Shot::new(0.01, 30.0)).unwrap();
            checked_to_rest(&mut s, &format!("{name} friction x100 {rack:?}"));
        }
    }
}

#[test]
fn balls_within_1e_15_m_of_a_cushion() {
    // Balls on, and a femtometre either side of, each cushion line, struck into it, along it
    // and away from it, and hit by another ball into it.
    let t = Table::wpa_8ft();
    for (name, p) in models() {
        let b = t.centre_bounds(p.ball.radius);
        for eps in [-1e-15, 0.0, 1e-15] {
            for (pos, n) in [
                (Vec2::new(0.3, b.y + eps), Vec2::new(0.0, -1.0)),
                (Vec2::new(-0.3, -b.y - eps), Vec2::new(0.0, 1.0)),
                (Vec2::new(b.x + eps, 0.1), Vec2::new(-1.0, 0.0)),
                (Vec2::new(-b.x - eps, -0.1), Vec2::new(1.0, 0.0)),
            ] {
                for k in 0..12 {
                    let angle = k as f64 * TAU / 12.0;
                    let mut s = sim(t, p, &[BallSetup::at(0, pos)]);
                    s.strike(0, Shot::new(angle, 1.5)).unwrap();
                    checked_to_rest(&mut s, &format!("{name} {pos:?} angle {angle}"));
                }
                // Another ball drives it into the cushion, head-on and obliquely.
                for slant in [0.0, 0.3 * r(), 1.2 * r()] {
                    let other = pos + n * 0.3 + n.perp() * slant;
                    let mut s = sim(t, p, &[BallSetup::at(0, other), BallSetup::at(1, pos)]);
                    s.strike(0, Shot::new((-n).angle(), 3.0)).unwrap();
                    checked_to_rest(&mut s, &format!("{name} {pos:?} hit with slant {slant}"));
                }
            }
        }
    }
}

#[test]
fn a_thousand_balls_on_a_large_table() {
    // 1000 balls moving at once on a table 8 times the usual size, for 1 s (hundreds of
    // contacts, many of them near-simultaneous), then a quarter of them all the way to rest.
    let t = Table::scaled(8.0);
    let tol = check::Tolerances {
        interior_samples: 0,
        ..check::Tolerances::default()
    };
    for (name, p) in models() {
        let balls = racks::scattered(&t, &p.ball, 1000, 2.0, 7);
        let mut s = sim(t, p, &balls);
        let mut m = check::Monitor::new(&s, tol).unwrap();
        let st = m
            .run_until(&mut s, 1.0)
            .unwrap_or_else(|v| panic!("{name}: {v}"));
        assert!(st.events > 500, "{name}: {st:?}");
        let balls = racks::scattered(&t, &p.ball, 250, 2.0, 8);
        let mut s = sim(t, p, &balls);
        let mut m = check::Monitor::new(&s, tol).unwrap();
        m.run_to_rest(&mut s)
            .unwrap_or_else(|v| panic!("{name}: {v}"));
    }
}

#[test]
fn advance_in_slices_matches_run_to_rest_in_stress_scenes() {
    // Time slicing is not an approximation: the same events, bit for bit, for odd slice
    // lengths in a tight-rack break.
    let t = Table::wpa_8ft();
    for (name, p) in models() {
        let mut whole = sim(t, p, &Rack::Tight.layout(&t, &p.ball));
        whole.strike(0, Shot::new(0.0, 11.0)).unwrap();
        let mut sliced = whole.clone();
        checked_to_rest(&mut whole, name);
        for dt in [1e-4, 0.0071, 0.1] {
            let mut s = sliced.clone();
            while !s.is_at_rest() {
                s.advance(dt).unwrap();
            }
            assert_eq!(
                whole.history().events(),
                s.history().events(),
                "{name} dt {dt}"
            );
        }
        sliced.run_to_rest().unwrap();
        assert_eq!(
            whole.history().events(),
            sliced.history().events(),
            "{name}"
        );
    }
}
