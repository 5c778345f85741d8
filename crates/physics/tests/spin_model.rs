//! The spin model against the reference's analytic checks (Leckie & Greenspan's equations of
//! motion; Alciatore's technical proofs for the collision rules).

mod common;
use billiards_physics::*;
use common::*;
use std::f64::consts::PI;

fn spin(m: SpinModel) -> Params {
    Params {
        model: Model::Spin(m),
        ..Params::default()
    }
}

/// Elastic, frictionless ball–ball collisions (the idealisation the analytic rules assume).
fn ideal_balls() -> SpinModel {
    SpinModel {
        e_ball: 1.0,
        mu_ball: 0.0,
        ..SpinModel::default()
    }
}

/// Spin of a ball rolling with velocity `v`: `w x z = v / R`.
fn rolling_spin(v: Vec2, r: f64) -> Vec3 {
    Vec3::new(-v.y / r, v.x / r, 0.0)
}

fn first_transition(sim: &mut Simulation, ball: BallId, to: Motion) -> Event {
    loop {
        let e = sim.step_event().expect("an event");
        if matches!(e.kind, EventKind::Transition { ball: b, to: t, .. } if b == ball && t == to) {
            return e;
        }
    }
}

#[test]
fn centre_hit_slides_then_rolls_at_five_sevenths_of_its_speed() {
    // t = 2 v0 / (7 mu_s g), v = 5/7 v0, slide distance 12 v0^2 / (49 mu_s g).
    let m = SpinModel::default();
    let p = spin(m);
    let v0 = 3.0;
    let mut sim = Simulation::new(huge_table(), p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    sim.strike(0, Shot::new(0.4, v0)).unwrap();
    assert_eq!(sim.ball(0).motion, Motion::Sliding);
    let e = first_transition(&mut sim, 0, Motion::Rolling);
    let mu_g = m.mu_slide * p.gravity;
    assert!(rel(e.time, 2.0 * v0 / (7.0 * mu_g)) < 1e-12);
    assert!(rel(e.after[0].velocity.length(), 5.0 / 7.0 * v0) < 1e-12);
    assert!(rel(e.after[0].position.length(), 12.0 * v0 * v0 / (49.0 * mu_g)) < 1e-12);
    // Rolling: the spin is locked to the velocity exactly.
    let s = e.after[0];
    assert_eq!(s.angular_velocity, rolling_spin(s.velocity, p.ball.radius));
}

#[test]
fn rolling_ball_stops_after_v_over_mu_r_g_and_v_squared_over_two_mu_r_g() {
    let m = SpinModel::default();
    let p = spin(m);
    let v = Vec2::new(0.0, 1.2);
    let ball = BallSetup {
        spin: rolling_spin(v, p.ball.radius),
        ..BallSetup::moving(0, Vec2::ZERO, v)
    };
    let mut sim = Simulation::new(huge_table(), p, &[ball]).unwrap();
    assert_eq!(sim.ball(0).motion, Motion::Rolling);
    sim.run_to_rest().unwrap();
    let a = m.mu_roll * p.gravity;
    assert!(rel(sim.time(), 1.2 / a) < 1e-12);
    assert!(rel(sim.ball(0).position.y, 1.2 * 1.2 / (2.0 * a)) < 1e-12);
    assert_eq!(sim.ball(0).motion, Motion::Stationary);
}

#[test]
fn spin_about_the_vertical_decays_at_five_mu_sp_g_over_two_r() {
    let m = SpinModel::default();
    let p = spin(m);
    let w = 25.0;
    let ball = BallSetup {
        spin: Vec3::new(0.0, 0.0, w),
        ..BallSetup::at(0, Vec2::ZERO)
    };
    let mut sim = Simulation::new(huge_table(), p, &[ball]).unwrap();
    assert_eq!(sim.ball(0).motion, Motion::Spinning);
    let decel = 5.0 * m.mu_spin * p.gravity / (2.0 * p.ball.radius);
    sim.advance(0.1).unwrap();
    assert!(rel(sim.ball(0).angular_velocity.z, w - decel * 0.1) < 1e-12);
    let e = first_transition(&mut sim, 0, Motion::Stationary);
    assert!(rel(e.time, w / decel) < 1e-12);
    assert!(sim.is_at_rest());
}

#[test]
fn stun_shot_leaves_cue_and_object_ball_at_ninety_degrees() {
    // No spin at contact, elastic, frictionless: speeds v sin(phi) and v cos(phi).
    let m = SpinModel {
        mu_slide: 0.0,
        mu_roll: 0.0,
        ..ideal_balls()
    };
    let p = spin(m);
    let r = p.ball.radius;
    for phi in [0.2f64, 0.5, 0.9] {
        let b = 2.0 * r * phi.sin();
        let balls = [
            BallSetup::moving(0, Vec2::new(-0.3, -b), Vec2::new(2.0, 0.0)),
            BallSetup::at(1, Vec2::ZERO),
        ];
        let mut sim = Simulation::new(Table::wpa_8ft(), p, &balls).unwrap();
        let e = sim.step_event().unwrap();
        let (c, o) = (e.after[0].velocity, e.after[1].velocity);
        assert!(c.dot(o).abs() < 1e-12, "phi {phi}: {c:?} {o:?}");
        assert!((o.length() - 2.0 * phi.cos()).abs() < 1e-12);
        assert!((c.length() - 2.0 * phi.sin()).abs() < 1e-12);
    }
}

#[test]
fn rolling_cue_ball_follows_the_thirty_degree_rule() {
    // Rolling cue ball, elastic frictionless collision: once it rolls again it has turned by
    // theta = atan(sin(phi) cos(phi) / (sin^2(phi) + 2/5)) (Alciatore, TP A-4), the "30-degree
    // rule" (theta near 30 degrees over a wide range of cuts).
    let p = spin(ideal_balls());
    let r = p.ball.radius;
    for deg in (10..=60).step_by(5) {
        let phi = f64::from(deg).to_radians();
        let v = Vec2::new(1.5, 0.0);
        let b = 2.0 * r * phi.sin();
        let cue = BallSetup {
            spin: rolling_spin(v, r),
            ..BallSetup::moving(0, Vec2::new(-0.2, -b), v)
        };
        let mut sim =
            Simulation::new(huge_table(), p, &[cue, BallSetup::at(1, Vec2::ZERO)]).unwrap();
        assert!(matches!(
            sim.step_event().unwrap().kind,
            EventKind::BallBall { .. }
        ));
        let e = first_transition(&mut sim, 0, Motion::Rolling);
        let turned = e.after[0].velocity.angle().abs();
        let expect = (phi.sin() * phi.cos() / (phi.sin().powi(2) + 0.4)).atan();
        // The model gives the closed form exactly, up to rounding: measured within 1.9e-15 rad
        // (1.1e-13 degrees, at 60 degrees), bounded at 1e-13 rad (6e-12 degrees).
        assert!(
            (turned - expect).abs() < 1e-13,
            "phi {deg}: {} vs {}",
            turned.to_degrees(),
            expect.to_degrees()
        );
    }
}

/// A full hit on an object ball 0.6 m ahead with the tip at `height` (radii).
fn full_hit(height: f64) -> Simulation {
    let p = spin(SpinModel::default());
    let balls = [
        BallSetup::at(0, Vec2::new(-0.6, 0.0)),
        BallSetup::at(1, Vec2::ZERO),
    ];
    let mut sim = Simulation::new(huge_table(), p, &balls).unwrap();
    sim.strike(
        0,
        Shot {
            tip: TipOffset { side: 0.0, height },
            ..Shot::new(0.0, 3.0)
        },
    )
    .unwrap();
    sim
}

#[test]
fn draw_reverses_the_cue_ball_after_a_full_hit_and_follow_carries_it_forward() {
    for (height, forward) in [(-0.45, false), (0.45, true)] {
        let mut sim = full_hit(height);
        sim.run_to_rest().unwrap();
        let x = sim.ball(0).position.x;
        // The cue ball stopped where the object ball was hit (x ~ -2R) unless spin moved it.
        let contact_x = -2.0 * sim.params().ball.radius;
        assert_eq!(
            x > contact_x + 0.05,
            forward,
            "height {height}: cue ball ends at x = {x}"
        );
        assert_eq!(
            x < contact_x - 0.05,
            !forward,
            "height {height}: cue ball ends at x = {x}"
        );
    }
}

#[test]
fn tip_at_two_fifths_of_the_radius_above_centre_rolls_at_once() {
    let p = spin(SpinModel::default());
    let mut sim = Simulation::new(huge_table(), p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    sim.strike(
        0,
        Shot {
            tip: TipOffset {
                side: 0.0,
                height: 0.4,
            },
            ..Shot::new(1.0, 2.0)
        },
    )
    .unwrap();
    assert_eq!(sim.ball(0).motion, Motion::Rolling);
}

#[test]
fn miscue_beyond_the_limit_is_an_error() {
    let p = spin(SpinModel::default());
    let mut sim = Simulation::new(huge_table(), p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    let shot = Shot {
        tip: TipOffset {
            side: 0.4,
            height: 0.4,
        },
        ..Shot::new(0.0, 2.0)
    };
    assert!(matches!(sim.strike(0, shot), Err(SetupError::Miscue(_))));
    assert!(sim.is_at_rest(), "a miscue leaves the ball alone");
}

#[test]
fn frictional_collision_conserves_momentum_and_never_gains_energy() {
    let p = spin(SpinModel::default());
    let r = p.ball.radius;
    for (side, height, offset) in [(0.3, 0.0, 0.3), (-0.3, 0.2, -0.7), (0.0, -0.4, 0.5)] {
        let balls = [
            BallSetup::at(0, Vec2::new(-0.4, offset * r)),
            BallSetup::at(1, Vec2::ZERO),
        ];
        let mut sim = Simulation::new(huge_table(), p, &balls).unwrap();
        sim.strike(
            0,
            Shot {
                tip: TipOffset { side, height },
                ..Shot::new(0.0, 2.0)
            },
        )
        .unwrap();
        let e = loop {
            let e = sim.step_event().unwrap();
            if matches!(e.kind, EventKind::BallBall { .. }) {
                break e;
            }
        };
        let h = sim.history();
        let track = h.track(0);
        let before = track.iter().rev().find(|s| s.start < e.time).unwrap();
        let (v0, w0) = (
            before.velocity_at(e.time),
            before.angular_velocity_at(e.time),
        );
        let (a, b) = (e.after[0], e.after[1]);
        assert!((a.velocity + b.velocity - v0).length() < 1e-14);
        let energy = |v: Vec2, w: Vec3| 0.5 * v.length_squared() + 0.5 * 0.4 * r * r * w.dot(w);
        let after = energy(a.velocity, a.angular_velocity) + energy(b.velocity, b.angular_velocity);
        assert!(
            after <= energy(v0, w0) * (1.0 + 1e-12),
            "energy rose: {after} > {}",
            energy(v0, w0)
        );
    }
}

#[test]
fn cut_shot_with_ball_friction_throws_the_object_ball_off_the_line_of_centres() {
    let p = spin(SpinModel::default());
    let r = p.ball.radius;
    let phi: f64 = 0.5;
    let balls = [
        BallSetup::moving(
            0,
            Vec2::new(-0.1, -2.0 * r * phi.sin()),
            Vec2::new(2.0, 0.0),
        ),
        BallSetup::at(1, Vec2::ZERO),
    ];
    let mut sim = Simulation::new(huge_table(), p, &balls).unwrap();
    let e = loop {
        let e = sim.step_event().unwrap();
        if matches!(e.kind, EventKind::BallBall { .. }) {
            break e;
        }
    };
    let line = (e.after[1].position - e.after[0].position).angle();
    let object = e.after[1].velocity.angle();
    // Cut-induced throw turns the object ball towards the cue ball's direction (smaller angle).
    assert!(
        object < line - 1e-3,
        "object ball at {object} rad, line of centres {line} rad"
    );
}

/// Rebound angle from the normal after a rolling ball meets the left cushion at 45 degrees
/// with side spin `wz`, moving along +x (`dir = 1`) or -x (`dir = -1`).
fn rebound_angle(wz: f64, dir: f64) -> f64 {
    let p = spin(SpinModel::default());
    let r = p.ball.radius;
    let v = Vec2::new(dir * 1.0, 1.0);
    let mut w = rolling_spin(v, r);
    w.z = wz;
    let y = p.ball.radius + 0.3;
    let start = BallSetup {
        spin: w,
        ..BallSetup::moving(0, Vec2::new(dir * 0.4, y), v)
    };
    let mut sim = Simulation::new(Table::wpa_8ft(), p, &[start]).unwrap();
    let e = loop {
        let e = sim.step_event().unwrap();
        if matches!(e.kind, EventKind::Cushion { .. }) {
            break e;
        }
    };
    let out = e.after[0].velocity;
    assert!(out.y < 0.0, "the ball comes back off the cushion");
    (out.x.abs() / -out.y).atan()
}

#[test]
fn running_english_widens_the_rebound_and_reverse_english_narrows_it_in_both_directions() {
    for dir in [1.0, -1.0] {
        let plain = rebound_angle(0.0, dir);
        // Running english turns the ball the way it rolls along the rail: w_z with the sign of
        // its motion along +x on the left cushion.
        let running = rebound_angle(dir * 30.0, dir);
        let reverse = rebound_angle(-dir * 30.0, dir);
        assert!(
            running > plain + 0.01,
            "dir {dir}: running {running} vs plain {plain}"
        );
        assert!(
            reverse < plain - 0.01,
            "dir {dir}: reverse {reverse} vs plain {plain}"
        );
    }
}

#[test]
fn nine_ball_break_with_spin_comes_to_rest_without_overlap_or_escape() {
    for speed in [8.0, 11.0] {
        let table = Table::wpa_8ft();
        let p = spin(SpinModel::default());
        let mut balls = Rack::NineBall.layout(&table, &p.ball);
        // Cue ball on the head string, aimed at the 1-ball.
        balls[0].position = Vec2::new(-0.25 * table.length, 0.1);
        let aim = (balls[1].position - balls[0].position).angle();
        let mut sim = Simulation::new(table, p, &balls).unwrap();
        sim.strike(0, Shot::new(aim, speed)).unwrap();
        sim.run_to_rest().unwrap();
        assert!(sim.history().events().len() > 30);
        assert_no_overlap_or_escape(&sim, 1e-9);
        // Friction turns spin into speed (draw, throw), so the invariant is the total kinetic
        // energy, translational plus rotational (I = 2/5 m R^2).
        let h = sim.history();
        let r = p.ball.radius;
        let total = |t: f64| -> f64 {
            h.states_at(t)
                .iter()
                .filter(|s| s.motion.on_table())
                .map(|s| {
                    0.5 * p.ball.mass
                        * (s.velocity.length_squared()
                            + 0.4 * r * r * s.angular_velocity.dot(s.angular_velocity))
                })
                .sum()
        };
        let mut last = f64::INFINITY;
        for e in h
            .events()
            .iter()
            .filter(|e| !matches!(e.kind, EventKind::Strike { .. }))
        {
            let ke = total(e.time);
            assert!(
                ke <= last * (1.0 + 1e-9) + 1e-15,
                "kinetic energy rose at {e:?}"
            );
            last = ke;
        }
    }
}

#[test]
fn spin_model_trajectory_does_not_depend_on_time_slicing() {
    let p = spin(SpinModel::default());
    let run = |slices: usize| {
        let mut sim = break_shot(Rack::FifteenBall, 9.0, p);
        for k in 1..=slices {
            sim.advance_to(0.5 * k as f64 / slices as f64).unwrap();
        }
        sim
    };
    let (a, b) = (run(1), run(37));
    assert_eq!(a.history().events(), b.history().events());
    assert_eq!(a.history().states_at(0.5), b.history().states_at(0.5));
}

#[test]
fn right_english_spins_the_ball_counter_clockwise_seen_from_above() {
    // The tip right of centre pushes that side forward: w = r x J / I has w_z > 0.
    let p = spin(SpinModel::default());
    let mut sim = Simulation::new(huge_table(), p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    sim.strike(
        0,
        Shot {
            tip: TipOffset {
                side: 0.3,
                height: 0.0,
            },
            ..Shot::new(PI / 2.0, 2.0)
        },
    )
    .unwrap();
    assert!(sim.ball(0).angular_velocity.z > 0.0);
}
