//! Newton's cradle on the cloth with no cloth friction: a ball driven at `V0` into a line of
//! 2 or 4 resting balls, frozen (touching) or with 0.02 mm gaps. The line is one cluster, so
//! the solver resolves it as one impact of Hertz contacts with restitution-matched damping
//! (`resolve::hertz`). What that model predicts is computed here independently: the same
//! one-dimensional chain `m x_i'' = F(i-1, i) - F(i, i+1)`, `F = k d^1.5 + c d^0.25 d'`,
//! integrated with classical RK4 at 1/20000 of a contact time.

use billiards_physics::resolve::hertz::{Hertz, damping_for_restitution};
use billiards_physics::*;

const V0: f64 = 2.0;
const GAP: f64 = 2e-5;

fn params(e_ball: f64) -> Params {
    Params {
        model: Model::Spin(SpinModel {
            mu_slide: 0.0,
            mu_roll: 0.0,
            mu_spin: 0.0,
            mu_ball: 0.0,
            e_ball,
            ..SpinModel::default()
        }),
        ..Params::default()
    }
}

/// Final velocities of the chain of `n` balls, ball 0 arriving at `V0`, under the model.
fn reference(n: usize, gap: f64, e_ball: f64) -> Vec<f64> {
    let p = params(e_ball);
    let h = Hertz::new(&HertzContact::default(), &p.ball, e_ball);
    let c = damping_for_restitution(e_ball) * (0.5 * h.mass * h.stiffness).sqrt();
    let force = |d: f64, rate: f64| {
        if d <= 0.0 {
            0.0
        } else {
            (h.stiffness * d.powf(1.5) + c * d.powf(0.25) * rate).max(0.0)
        }
    };
    let acc = |x: &[f64], v: &[f64]| {
        let mut a = vec![0.0; n];
        for i in 0..n - 1 {
            let f = force(x[i] - x[i + 1] - gap, v[i] - v[i + 1]) / h.mass;
            a[i] -= f;
            a[i + 1] += f;
        }
        a
    };
    let dt = h.duration(V0) / 20000.0;
    let (mut x, mut v) = (vec![0.0; n], vec![0.0; n]);
    v[0] = V0;
    for _ in 0..20000 * 200 {
        let k1v = acc(&x, &v);
        let k1x = v.clone();
        let mid = |y: &[f64], k: &[f64], s: f64| -> Vec<f64> {
            y.iter().zip(k).map(|(a, b)| a + s * b).collect()
        };
        let (x2, v2) = (mid(&x, &k1x, 0.5 * dt), mid(&v, &k1v, 0.5 * dt));
        let (k2x, k2v) = (v2.clone(), acc(&x2, &v2));
        let (x3, v3) = (mid(&x, &k2x, 0.5 * dt), mid(&v, &k2v, 0.5 * dt));
        let (k3x, k3v) = (v3.clone(), acc(&x3, &v3));
        let (x4, v4) = (mid(&x, &k3x, dt), mid(&v, &k3v, dt));
        let (k4x, k4v) = (v4.clone(), acc(&x4, &v4));
        for i in 0..n {
            x[i] += dt / 6.0 * (k1x[i] + 2.0 * k2x[i] + 2.0 * k3x[i] + k4x[i]);
            v[i] += dt / 6.0 * (k1v[i] + 2.0 * k2v[i] + 2.0 * k3v[i] + k4v[i]);
        }
        let open = (0..n - 1).all(|i| force(x[i] - x[i + 1] - gap, v[i] - v[i + 1]) == 0.0);
        if open && (0..n - 1).all(|i| v[i] <= v[i + 1]) {
            return v;
        }
    }
    panic!("the reference chain never came apart");
}

/// The solver's velocities (along x) of the `n` balls just after the cradle's impact.
fn solver(n: usize, gap: f64, e_ball: f64) -> (Vec<f64>, usize) {
    let p = params(e_ball);
    let r = p.ball.radius;
    let table = Table::wpa_8ft();
    let x0 = -0.3;
    let mut balls = vec![BallSetup::at(0, Vec2::new(x0 - 0.2, 0.0))];
    for i in 1..n {
        let x = x0 + (i - 1) as f64 * (2.0 * r + gap);
        balls.push(BallSetup::at(i as u8, Vec2::new(x, 0.0)));
    }
    let mut sim = Simulation::new(table, p, &balls).unwrap();
    sim.strike(0, Shot::new(0.0, V0)).unwrap();
    let mut monitor = check::Monitor::new(&sim, check::Tolerances::default()).unwrap();
    // Up to the first cushion: the impact and nothing after it.
    loop {
        let e = monitor.step(&mut sim).unwrap().expect("an event");
        if matches!(e.kind, EventKind::Cushion { .. }) {
            break;
        }
    }
    let t = sim.time();
    let h = sim.history();
    let first_cushion = h.events().len() - 1;
    let before = h.states_at(h.events()[first_cushion].time - 1e-9);
    let _ = t;
    (
        before.iter().map(|s| s.velocity.x).collect(),
        sim.cluster_impacts(),
    )
}

fn check_cradle(n: usize, e_ball: f64) {
    let ke = |v: &[f64]| v.iter().map(|v| v * v).sum::<f64>();
    let mut last = Vec::new();
    for gap in [0.0, GAP] {
        let want = reference(n, gap, e_ball);
        let (got, impacts) = solver(n, gap, e_ball);
        eprintln!("{n} balls, gap {gap:e} m, e {e_ball}: solver {got:?}, model {want:?}");
        assert_eq!(impacts, 1, "the line is one cluster impact");
        // Momentum: kept to rounding.
        let p: f64 = got.iter().sum();
        assert!((p - V0).abs() < 1e-12 * V0, "momentum {p}");
        // Energy: never gained; kept to the integrator's error when elastic.
        let (k0, k1) = (V0 * V0, ke(&got));
        assert!(k1 <= k0, "energy rose: {k1} > {k0}");
        if e_ball == 1.0 {
            assert!(
                k1 > k0 * (1.0 - 1e-5),
                "elastic energy lost: {}",
                1.0 - k1 / k0
            );
        } else {
            assert!(
                k1 < k0 * (1.0 - 1e-3),
                "damped energy kept: {}",
                1.0 - k1 / k0
            );
        }
        // Every ball as the model predicts; the last one leaves fastest.
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() < 1e-4 * V0, "solver {got:?} model {want:?}");
        }
        assert!(got[n - 1] > 0.8 * V0 && got.iter().all(|&v| v <= got[n - 1]));
        last.push(got[n - 1]);
    }
    let change = (last[1] - last[0]).abs() / last[0];
    assert!(
        change < 0.02,
        "frozen {} vs gapped {}: {change}",
        last[0],
        last[1]
    );
}

#[test]
fn three_ball_elastic_cradle_frozen_and_gapped_leave_as_the_hertz_chain_predicts() {
    check_cradle(3, 1.0);
}

#[test]
fn five_ball_elastic_cradle_frozen_and_gapped_leave_as_the_hertz_chain_predicts() {
    check_cradle(5, 1.0);
}

#[test]
fn three_ball_damped_cradle_frozen_and_gapped_leave_as_the_hertz_chain_predicts() {
    check_cradle(3, 0.95);
}

#[test]
fn five_ball_damped_cradle_frozen_and_gapped_leave_as_the_hertz_chain_predicts() {
    check_cradle(5, 0.95);
}
