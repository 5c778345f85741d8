//! The paper's model against closed forms (the reference's analytic checks that apply to it).

mod common;
use billiards_physics::*;
use common::*;

const V0: f64 = 2.0;

#[test]
fn single_ball_stops_at_the_closed_form_distance_and_time() {
    // Slides at mu_s g down to the threshold, then rolls at mu_r g to rest:
    // d = (v0^2 - vt^2)/(2 mu_s g) + vt^2/(2 mu_r g), t = (v0 - vt)/(mu_s g) + vt/(mu_r g).
    let m = PaperModel::default();
    let p = paper(m);
    let (as_, ar, vt) = (
        m.mu_slide * p.gravity,
        m.mu_roll * p.gravity,
        m.slide_roll_speed,
    );
    let mut sim = one_ball(huge_table(), p, Vec2::new(V0, 0.0));
    sim.run_to_rest().unwrap();
    let d = (V0 * V0 - vt * vt) / (2.0 * as_) + vt * vt / (2.0 * ar);
    let t = (V0 - vt) / as_ + vt / ar;
    let s = sim.ball(0);
    assert!(rel(s.position.x, d) < 1e-12, "{} vs {d}", s.position.x);
    assert_eq!(s.position.y, 0.0);
    assert!(rel(sim.time(), t) < 1e-12, "{} vs {t}", sim.time());
    assert_eq!(s.motion, Motion::Stationary);
}

#[test]
fn slide_to_roll_transition_fires_once_at_the_threshold_time_with_the_threshold_speed() {
    let m = PaperModel::default();
    let p = paper(m);
    let mut sim = one_ball(huge_table(), p, Vec2::from_angle(0.3) * V0);
    sim.run_to_rest().unwrap();
    let ev = sim.history().events();
    assert_eq!(ev.len(), 2, "{ev:?}");
    assert!(matches!(
        ev[0].kind,
        EventKind::Transition {
            from: Motion::Sliding,
            to: Motion::Rolling,
            ..
        }
    ));
    assert!(matches!(
        ev[1].kind,
        EventKind::Transition {
            from: Motion::Rolling,
            to: Motion::Stationary,
            ..
        }
    ));
    let t1 = (V0 - m.slide_roll_speed) / (m.mu_slide * p.gravity);
    assert!(rel(ev[0].time, t1) < 1e-12);
    assert!(rel(ev[0].after[0].velocity.length(), m.slide_roll_speed) < 1e-15);
    // Direction is kept exactly through the transition.
    assert!((ev[0].after[0].velocity.angle() - 0.3).abs() < 1e-15);
}

#[test]
fn slow_ball_rolls_from_the_start_and_stops_after_v_over_mu_r_g() {
    let m = PaperModel::default();
    let p = paper(m);
    let v = 0.3;
    let mut sim = one_ball(huge_table(), p, Vec2::new(0.0, v));
    assert_eq!(sim.ball(0).motion, Motion::Rolling);
    sim.run_to_rest().unwrap();
    let a = m.mu_roll * p.gravity;
    assert!(rel(sim.time(), v / a) < 1e-12);
    assert!(rel(sim.ball(0).position.y, v * v / (2.0 * a)) < 1e-12);
}

/// Ball 0 at the origin moving +x at `v`, ball 1 at rest at `x = gap + 2R`.
fn two_in_line(params: Params, v: f64, gap: f64) -> Simulation {
    let r = params.ball.radius;
    let balls = [
        BallSetup::moving(0, Vec2::ZERO, Vec2::new(v, 0.0)),
        BallSetup::at(1, Vec2::new(2.0 * r + gap, 0.0)),
    ];
    Simulation::new(huge_table(), params, &balls).unwrap()
}

#[test]
fn ball_ball_contact_time_is_the_root_of_the_decelerating_motion() {
    // Gap s closed under deceleration a: s = v t - a t^2 / 2, t = (v - sqrt(v^2 - 2 a s)) / a.
    let m = PaperModel::default();
    let p = paper(m);
    let (v, s) = (3.0, 0.5);
    let mut sim = two_in_line(p, v, s);
    let ev = sim.step_event().unwrap();
    assert!(
        matches!(ev.kind, EventKind::BallBall { a: 0, b: 1 }),
        "{ev:?}"
    );
    let a = m.mu_slide * p.gravity;
    let t = (v - (v * v - 2.0 * a * s).sqrt()) / a;
    assert!(rel(ev.time, t) < 1e-12, "{} vs {t}", ev.time);
}

#[test]
fn head_on_equal_masses_exchange_velocities_exactly() {
    let mut sim = two_in_line(paper(PaperModel::default()), 3.0, 0.5);
    let before = sim.segment(0).velocity_at(sim.next_event_time().unwrap());
    let ev = sim.step_event().unwrap();
    assert_eq!(ev.after[0].velocity, Vec2::ZERO);
    assert_eq!(ev.after[0].motion, Motion::Stationary);
    assert_eq!(ev.after[1].velocity, before);
}

#[test]
fn inelastic_head_on_collision_keeps_momentum_and_splits_by_restitution() {
    let e = 0.9;
    let mut sim = two_in_line(
        paper(PaperModel {
            e_ball: e,
            ..PaperModel::default()
        }),
        3.0,
        0.5,
    );
    let t = sim.next_event_time().unwrap();
    let v = sim.segment(0).velocity_at(t).x;
    let ev = sim.step_event().unwrap();
    let (a, b) = (ev.after[0].velocity.x, ev.after[1].velocity.x);
    assert!((a + b - v).abs() <= 4.0 * f64::EPSILON * v);
    assert!(rel(a, 0.5 * (1.0 - e) * v) < 1e-14 && rel(b, 0.5 * (1.0 + e) * v) < 1e-14);
}

#[test]
fn stun_cut_shot_leaves_at_ninety_degrees() {
    // Equal masses, elastic, frictionless, no spin: object ball along the line of centres,
    // cue ball along the tangent; speeds v cos(phi) and v sin(phi).
    let p = frictionless();
    let r = p.ball.radius;
    let phi: f64 = 0.5;
    // Aim so that the line of centres at contact makes angle phi with the velocity.
    let b = 2.0 * r * phi.sin();
    let balls = [
        BallSetup::moving(0, Vec2::new(-0.5, -b), Vec2::new(1.0, 0.0)),
        BallSetup::at(1, Vec2::ZERO),
    ];
    let mut sim = Simulation::new(Table::wpa_8ft(), p, &balls).unwrap();
    let ev = sim.step_event().unwrap();
    let (ca, ob) = (ev.after[0].velocity, ev.after[1].velocity);
    assert!(ca.dot(ob).abs() < 1e-14, "not perpendicular: {ca:?} {ob:?}");
    assert!((ob.length() - phi.cos()).abs() < 1e-12);
    assert!((ca.length() - phi.sin()).abs() < 1e-12);
    assert!((ob.angle() - phi).abs() < 1e-12);
}

#[test]
fn cushion_reflection_mirrors_the_angle_of_incidence() {
    let p = paper(PaperModel::default());
    let angle: f64 = 1.1;
    let mut sim = one_ball(Table::wpa_8ft(), p, Vec2::from_angle(angle) * 2.0);
    let ev = sim.step_event().unwrap();
    assert_eq!(
        ev.kind,
        EventKind::Cushion {
            ball: 0,
            cushion: Cushion::Left
        }
    );
    let out = ev.after[0].velocity;
    assert!(
        (out.angle() + angle).abs() < 1e-15,
        "{} vs {}",
        out.angle(),
        -angle
    );
}

#[test]
fn cushion_contact_time_is_the_root_of_the_quadratic() {
    // Distance s to the cushion line under deceleration a along +y: s = v t - a t^2/2.
    let m = PaperModel::default();
    let p = paper(m);
    let v = 2.0;
    let mut sim = one_ball(Table::wpa_8ft(), p, Vec2::new(0.0, v));
    let s = sim.table().centre_bounds(p.ball.radius).y;
    let a = m.mu_slide * p.gravity;
    let t = (v - (v * v - 2.0 * a * s).sqrt()) / a;
    let ev = sim.step_event().unwrap();
    assert!(rel(ev.time, t) < 1e-12);
    assert!(rel(ev.after[0].position.y, s) < 1e-15);
}

#[test]
fn cushion_restitution_scales_the_normal_speed() {
    let e = 0.85;
    let p = paper(PaperModel {
        e_cushion: e,
        mu_slide: 0.0,
        mu_roll: 0.0,
        ..PaperModel::default()
    });
    let mut sim = one_ball(Table::wpa_8ft(), p, Vec2::new(0.3, 1.0));
    let ev = sim.step_event().unwrap();
    let v = ev.after[0].velocity;
    assert_eq!(v.x, 0.3);
    assert!((v.y + e).abs() <= 2.0 * f64::EPSILON, "{v:?}");
}

#[test]
fn exact_prediction_touches_where_the_paper_linear_prediction_stops_short() {
    // The paper's linear prediction ignores deceleration: it reports the contact too early,
    // while the balls are still apart (slip 4).
    let r = PaperModel::default();
    let exact = two_in_line(paper(r), 3.0, 0.5);
    let linear = two_in_line(
        Params {
            prediction: Prediction::PaperLinear,
            ..paper(r)
        },
        3.0,
        0.5,
    );
    for (mut sim, gap_is_zero) in [(exact, true), (linear, false)] {
        let ev = sim.step_event().unwrap();
        let d =
            (ev.after[1].position - ev.after[0].position).length() - 2.0 * sim.params().ball.radius;
        assert_eq!(d.abs() < 1e-12, gap_is_zero, "gap {d}");
    }
}

#[test]
fn randomization_with_zero_spread_is_bit_identical_to_none() {
    let off = Params::default();
    let zero = Params {
        randomization: Some(Randomization {
            spread: 0.0,
            seed: 7,
        }),
        ..off
    };
    let mut a = break_shot(Rack::FifteenBall, 9.0, off);
    let mut b = break_shot(Rack::FifteenBall, 9.0, zero);
    a.run_to_rest().unwrap();
    b.run_to_rest().unwrap();
    assert_eq!(a.history().events(), b.history().events());
}

#[test]
fn seeded_randomization_is_reproducible_and_differs_across_seeds() {
    let run = |seed| {
        let p = Params {
            randomization: Some(Randomization { spread: 0.01, seed }),
            ..Params::default()
        };
        let mut s = break_shot(Rack::FifteenBall, 9.0, p);
        s.run_to_rest().unwrap();
        s.balls().map(|b| b.position).collect::<Vec<_>>()
    };
    assert_eq!(run(1), run(1));
    assert_ne!(run(1), run(2));
    let mut plain = break_shot(Rack::FifteenBall, 9.0, Params::default());
    plain.run_to_rest().unwrap();
    assert_ne!(
        run(1),
        plain.balls().map(|b| b.position).collect::<Vec<_>>()
    );
}
