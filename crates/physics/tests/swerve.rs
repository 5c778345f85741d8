//! Cue elevation, swerve and masse: the strike of an elevated cue (Alciatore TP A-30; pooltool's
//! `instantaneous_point`) and the sliding motion that curves the ball (Leckie & Greenspan:
//! the friction force keeps its direction in the contact-point frame, so the path is a
//! parabola until the ball rolls).

mod common;
use billiards_physics::check::{Monitor, Tolerances};
use billiards_physics::*;
use common::*;

fn spin(m: SpinModel) -> Params {
    Params {
        model: Model::Spin(m),
        ..Params::default()
    }
}

fn shot(angle: f64, speed: f64, side: f64, height: f64, degrees: f64) -> Shot {
    Shot {
        tip: TipOffset { side, height },
        elevation: degrees.to_radians(),
        ..Shot::new(angle, speed)
    }
}

fn struck(p: Params, s: Shot) -> Simulation {
    let mut sim = Simulation::new(huge_table(), p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    sim.strike(0, s).unwrap();
    sim
}

fn slide_end(sim: &mut Simulation) -> Event {
    loop {
        let e = sim.step_event().expect("an event");
        if matches!(
            e.kind,
            EventKind::Transition {
                to: Motion::Rolling,
                ..
            }
        ) {
            return e;
        }
        assert!(
            matches!(e.kind, EventKind::Strike { .. }),
            "only the slide's end may follow the strike: {e:?}"
        );
    }
}

/// A level cue gives the level strike's formula bit for bit (the one `resolve/cue.rs` had
/// before elevation existed), with and without squirt, and a level shot's file is unchanged.
#[test]
fn a_level_cue_gives_the_level_strike_bit_for_bit() {
    for end_mass in [None, Some(0.008)] {
        let m = SpinModel {
            end_mass,
            ..SpinModel::default()
        };
        let p = spin(m);
        for (angle, speed, side, height) in [
            (0.3, 2.0, 0.3, -0.2),
            (-2.9, 7.5, -0.45, 0.1),
            (1.7, 0.4, 0.0, 0.37),
        ] {
            let sim = struck(p, shot(angle, speed, side, height, 0.0));
            let s = sim.ball(0);
            // The level strike as it was: v, then w = (0, 0, k side) + perp (k height).
            let (mass, r) = (p.ball.mass, p.ball.radius);
            let dir = Vec2::from_angle(angle);
            let offset = (side * side + height * height).sqrt();
            let ratio = mass / m.cue_mass;
            let v = speed * (1.0 + ratio) / (1.0 + ratio + 2.5 * offset * offset);
            let k = 2.5 * v / r;
            let w = Vec3::new(0.0, 0.0, k * side) + dir.perp().extend() * (k * height);
            let heading = match end_mass {
                Some(e) => dir.rotated(resolve::cue::squirt_angle(side, mass / e)),
                None => dir,
            };
            assert_eq!(s.velocity, heading * v);
            assert_eq!(s.angular_velocity, w);
        }
    }
    let level = Shot::new(0.25, 3.0);
    let text = serde_json::to_string(&level).unwrap();
    assert!(!text.contains("elevation"), "{text}");
    let old = r#"{"angle":0.25,"speed":3.0,"tip":{"side":0.0,"height":0.0}}"#;
    assert_eq!(serde_json::from_str::<Shot>(old).unwrap(), level);
    let raised = shot(0.25, 3.0, 0.1, 0.0, 12.0);
    let back: Shot = serde_json::from_str(&serde_json::to_string(&raised).unwrap()).unwrap();
    assert_eq!(back, raised);
}

/// The strike, derived again in 3D: `J` along `d` (the cue tilted down by `theta`) at the
/// contact point `r` (offsets seen along the cue), `v = J / m` along `d`, `w = r x J / I`;
/// then, when the ball leaves the cloth, the slate's reaction to the downward part `v_z`
/// (pooltool's `frictional_inelastic`):
/// a friction impulse `f` against the contact point's slip `u`, the smaller of
/// `mu (1 + e) |v_z|` (Coulomb, e = 0.5) and `(2/7) |u|` (no slip), `v -= f u_hat`,
/// `w += r_c x (-f u_hat) / (I/m)` with `r_c = -R z` the slate contact.
fn expected_strike(p: &Params, s: &Shot) -> (Vec2, Vec3) {
    let Model::Spin(m) = p.model else {
        unreachable!()
    };
    let (mass, r) = (p.ball.mass, p.ball.radius);
    let (phi, theta) = (s.angle, s.elevation);
    let d = Vec3::new(
        theta.cos() * phi.cos(),
        theta.cos() * phi.sin(),
        -theta.sin(),
    );
    let right = Vec3::new(phi.sin(), -phi.cos(), 0.0);
    let up = right.cross(d);
    let (a, b) = (s.tip.side, s.tip.height);
    let depth = (1.0 - a * a - b * b).sqrt();
    let contact = (right * a + up * b - d * depth) * r;
    let ratio = mass / m.cue_mass;
    let v = s.speed * (1.0 + ratio) / (1.0 + ratio + 2.5 * (a * a + b * b));
    let w = contact.cross(d) * (mass * v / (0.4 * mass * r * r));
    let (vxy, vz) = ((d * v).xy(), (d * v).z);
    let z = Vec3::new(0.0, 0.0, 1.0);
    let u = vxy - (w.cross(z) * r).xy();
    // A rebound that would rise under 5 mm (e = 0.5): the ball stays on the cloth with the
    // planar strike's numbers, the slate taking the vertical part without friction.
    let stays_down = (0.5 * vz).powi(2) / (2.0 * p.gravity) < 0.005;
    if vz == 0.0 || u.length() == 0.0 || stays_down {
        return (vxy, w);
    }
    let f = (m.mu_slide * 1.5 * -vz).min(u.length() * 2.0 / 7.0);
    let dv = u * (-f / u.length());
    let dw = (z * -r).cross(Vec3::new(dv.x, dv.y, 0.0)) * (1.0 / (0.4 * r * r));
    (vxy + dv, w + dw)
}

#[test]
fn the_elevated_strike_is_the_impulse_at_the_contact_point() {
    let p = spin(SpinModel::default());
    for s in [
        shot(0.0, 2.0, 0.3, 0.0, 20.0),
        shot(2.1, 4.0, -0.25, 0.3, 30.0),
        shot(-0.7, 1.0, 0.1, -0.4, 7.5),
    ] {
        let (v, w) = expected_strike(&p, &s);
        let got = struck(p, s).ball(0);
        assert!((got.velocity - v).length() < 1e-14 * v.length(), "{s:?}");
        assert!(
            (got.angular_velocity - w).length() < 1e-12 * w.length(),
            "{s:?}"
        );
    }
    // The vertical part goes into the slate: a centre hit at 30 degrees (under the 43.6
    // degrees where the slate grips) loses Coulomb's mu (1 + e) v sin(theta) of its
    // v cos(theta) in the plane and gains topspin (+y spin for a ball along +x).
    let got = struck(p, shot(0.0, 2.0, 0.0, 0.0, 30.0)).ball(0);
    let (sin, cos) = 30f64.to_radians().sin_cos();
    assert!((got.velocity.x - 2.0 * (cos - 0.2 * 1.5 * sin)).abs() < 1e-15);
    assert!(got.angular_velocity.y > 0.0 && got.angular_velocity.x == 0.0);
}

/// Right english on a raised cue curves the ball right (towards the english), left english
/// left; a level cue or no english goes straight; more elevation curves more.
#[test]
fn swerve_curves_towards_the_english() {
    let p = spin(SpinModel::default());
    let bend = |side: f64, degrees: f64| {
        // 1 m/s: the slate's rebound rises under 5 mm at every elevation here (on the cloth).
        let mut sim = struck(p, shot(0.0, 1.0, side, 0.0, degrees));
        let e = slide_end(&mut sim);
        e.after[0].velocity.angle()
    };
    assert!(bend(0.3, 15.0) < 0.0, "right english turns right (-y)");
    assert!(bend(-0.3, 15.0) > 0.0, "left english turns left (+y)");
    assert_eq!(bend(0.3, 15.0), -bend(-0.3, 15.0));
    assert_eq!(bend(0.3, 0.0), 0.0, "a level cue does not swerve");
    assert_eq!(bend(0.0, 25.0), 0.0, "no english, no swerve");
    assert!(bend(0.3, 25.0) < bend(0.3, 15.0));
    assert!(bend(0.3, 15.0) < bend(0.15, 15.0));
}

/// The sliding phase against its closed form: with slip `u0 = v0 - R (w0 x z)`, the friction
/// `-mu_s g u_hat` is constant, so the path is `p(t) = v0 t - (mu_s g / 2) t^2 u_hat` (a
/// parabola) until `T = 2 |u0| / (7 mu_s g)`, and the ball leaves along `v0 - mu_s g T u_hat`.
#[test]
fn the_swerve_is_the_closed_form_parabola() {
    let m = SpinModel::default();
    let p = spin(m);
    let (r, mu_g) = (p.ball.radius, m.mu_slide * p.gravity);
    for s in [
        // Each slow enough that the slate's rebound rises under 5 mm: it stays on the cloth.
        shot(0.0, 2.0, 0.25, 0.0, 10.0),
        shot(0.0, 1.0, 0.25, 0.0, 30.0),
        shot(1.2, 1.2, -0.4, -0.2, 25.0),
        shot(-2.0, 1.5, 0.35, 0.3, 18.0),
    ] {
        let (v0, w0) = expected_strike(&p, &s);
        let u0 = v0 - (w0.cross(Vec3::new(0.0, 0.0, 1.0)) * r).xy();
        let u_hat = u0 / u0.length();
        let t_end = 2.0 * u0.length() / (7.0 * mu_g);
        let at = |t: f64| v0 * t - u_hat * (0.5 * mu_g * t * t);
        let mut sim = struck(p, s);
        let e = slide_end(&mut sim);
        assert!(rel(e.time, t_end) < 1e-12, "{s:?}: {} vs {t_end}", e.time);
        let end = e.after[0];
        assert!((end.position - at(t_end)).length() < 1e-12, "{s:?}");
        let v_end = v0 - u_hat * (mu_g * t_end);
        assert!((end.velocity - v_end).length() < 1e-12, "{s:?}");
        // The path between: sampled from the history, on the parabola.
        let h = sim.history();
        for f in [0.1, 0.37, 0.5, 0.9] {
            let q = h.state_at(0, f * t_end).position;
            assert!((q - at(f * t_end)).length() < 1e-12, "{s:?} at {f}");
        }
        // Sideways from the cue line (the squirt-free heading), the curve bends towards the
        // english: its lateral offset grows like t^2 on the english's side.
        let dir = Vec2::from_angle(s.angle);
        let lateral = end.position.perp_dot(dir);
        assert_eq!(lateral > 0.0, s.tip.side > 0.0, "{s:?}: {lateral}");
    }
}

/// The 85-degree limit is a clear error; the miscue limit holds at every elevation, on the
/// same offset seen along the cue; neither moves the ball.
#[test]
fn elevation_beyond_85_degrees_and_miscues_are_errors() {
    let p = spin(SpinModel::default());
    let mut sim = Simulation::new(huge_table(), p, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    let too_steep = sim.strike(0, shot(0.0, 2.0, 0.2, 0.0, 85.5));
    match too_steep {
        Err(SetupError::Limit(e)) => {
            assert_eq!(e.what, "cue elevation");
            assert!(e.to_string().contains("85 degrees"), "{e}");
        }
        other => panic!("expected a limit error, got {other:?}"),
    }
    for degrees in [0.0, 10.0, 30.0] {
        let miscue = sim.strike(0, shot(0.0, 2.0, 0.4, 0.31, degrees));
        assert!(matches!(miscue, Err(SetupError::Miscue(_))), "{degrees}");
        assert!(sim.is_at_rest(), "a refused shot leaves the ball alone");
    }
    assert!(sim.strike(0, shot(0.0, 2.0, 0.4, 0.29, 30.0)).is_ok());
    // The paper's model has no spin: its cue ignores the elevation as it ignores the tip.
    let paper = struck(Params::default(), shot(0.5, 2.0, 0.0, 0.0, 20.0)).ball(0);
    assert_eq!(paper.velocity, Vec2::from_angle(0.5) * 2.0);
}

/// Elevated shots with english into racks keep every invariant the monitor checks.
#[test]
fn elevated_breaks_keep_every_invariant() {
    let p = spin(SpinModel::default());
    let table = Table::wpa_8ft();
    for i in 0..24 {
        let mut balls = Rack::NineBall.layout(&table, &p.ball);
        balls[0].position = Vec2::new(-0.6, 0.05 * (i % 5) as f64 - 0.1);
        let mut sim = Simulation::new(table, p, &balls).unwrap();
        let aim = (balls[1].position - balls[0].position).angle();
        let side = 0.45 * (i as f64 / 23.0 * 2.0 - 1.0);
        let s = shot(
            aim,
            1.0 + i as f64 * 0.5,
            side,
            -0.1,
            30.0 * i as f64 / 23.0,
        );
        let mut monitor = Monitor::new(&sim, Tolerances::default()).unwrap();
        monitor.strike(&mut sim, 0, s).expect("a valid shot");
        if let Err(v) = monitor.run_to_rest(&mut sim) {
            panic!("shot {i} {s:?}: {v}");
        }
    }
}

/// The sliding phase from `e`'s state on: with slip `u0 = v0 + w0 x (-R z)` the friction
/// `-mu_s g u_hat` is constant (Leckie & Greenspan), so the centre is at `p0 + v0 t -
/// (mu_s g / 2) t^2 u_hat` until `T = 2 |u0| / (7 mu_s g)`. Returns the closed form and `T`.
fn sliding_closed_form(e: &Event, mu_g: f64, r: f64) -> (impl Fn(f64) -> Vec2, f64) {
    let s = e.after[0];
    let w = s.angular_velocity;
    let u0 = Vec2::new(s.velocity.x - r * w.y, s.velocity.y + r * w.x);
    let u_hat = u0 / u0.length();
    let (p0, v0, t0) = (s.position, s.velocity, e.time);
    let at = move |t: f64| {
        let tau = t - t0;
        p0 + v0 * tau - u_hat * (0.5 * mu_g * tau * tau)
    };
    (at, 2.0 * u0.length() / (7.0 * mu_g))
}

/// Masse: a steep cue (60 to 80 degrees) with english drives the ball into the slate, which
/// takes the vertical part; the cue's impulse at the contact point leaves a spin whose slip is
/// far off the ball's heading: the path curves by tens of degrees (a few after hops, whose landings grip).
/// Sampled from the history through its sliding phase (after the strike when it stays down,
/// after its last landing when it hops), the solver's path is the closed form of the sliding
/// motion to 1e-9 m, and the slide ends at `T` to 1e-12 s.
#[test]
fn a_masse_curves_on_the_closed_form_of_the_sliding_motion() {
    let m = SpinModel::default();
    let p = spin(m);
    let (r, mu_g) = (p.ball.radius, m.mu_slide * p.gravity);
    // Each with the least turn of its heading over the slide, degrees.
    for (s, least) in [
        (shot(0.0, 0.6, 0.4, 0.0, 70.0), 40.0),
        (shot(1.0, 0.5, -0.35, -0.2, 80.0), 90.0),
        (shot(-0.5, 0.55, 0.3, 0.2, 60.0), 20.0),
        // Hard enough to hop first: the curve starts where it comes down, and the slate's
        // grip at each landing took most of the slip (a few degrees left).
        (shot(0.3, 2.0, -0.4, -0.2, 55.0), 2.0),
    ] {
        let mut sim = struck(p, s);
        sim.run_to_rest().unwrap();
        let h = sim.history();
        let events = h.events();
        let to_cloth = |e: &&Event| {
            matches!(
                e.kind,
                EventKind::Strike { .. } | EventKind::Transition { .. }
            ) && e.after[0].motion == Motion::Sliding
        };
        let start = *events.iter().rfind(to_cloth).expect("a sliding phase");
        let end = events.iter().find(|e| {
            e.time > start.time
                && matches!(
                    e.kind,
                    EventKind::Transition {
                        from: Motion::Sliding,
                        ..
                    }
                )
        });
        let end = *end.expect("the slide ends");
        let (at, t_slide) = sliding_closed_form(&start, mu_g, r);
        assert!(
            (end.time - start.time - t_slide).abs() < 1e-12,
            "{s:?}: slides {} s, closed form {t_slide}",
            end.time - start.time
        );
        for k in 0..=20 {
            let t = start.time + t_slide * k as f64 / 20.0;
            let q = h.state_at(0, t).position;
            assert!((q - at(t)).length() < 1e-9, "{s:?} at {k}/20: {q:?}");
        }
        let turn = (end.after[0].velocity.angle() - start.after[0].velocity.angle()).abs();
        let turn = turn.min(std::f64::consts::TAU - turn).to_degrees();
        assert!(
            turn > least,
            "{s:?}: a masse curves, turned {turn:.1} degrees"
        );
    }
}
