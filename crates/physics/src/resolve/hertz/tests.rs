//! The Hertz contact against its closed forms and the restitution it is damped to.

use super::*;

fn hertz(e: f64) -> Hertz {
    Hertz::new(&HertzContact::default(), &BallSpec::default(), e)
}

/// `int_0^1 dx / sqrt(1 - x^(5/2))`: a Hertz impact lasts `2 I d_max / v` (Landau &
/// Lifshitz, section 9). Midpoint rule after `x = 1 - s^2`, which takes
/// away the end's singularity: `int_0^1 2 s / sqrt(1 - (1 - s^2)^(5/2)) ds`.
fn hertz_integral() -> f64 {
    let n = 200_000;
    (0..n)
        .map(|i| {
            let s = (i as f64 + 0.5) / n as f64;
            2.0 * s / (1.0 - (1.0 - s * s).powf(2.5)).sqrt()
        })
        .sum::<f64>()
        / n as f64
}

/// Against Hertz's closed forms from the material (E, nu), the radius and the mass alone:
/// `d_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5)` with `m* = m / 2`, `R* = R / 2`,
/// `E* = E / (2 (1 - nu^2))`, to rounding (1e-13); the duration `2.9432 d_max / v` to the
/// 2.6e-5 its constant is cut to (the exact constant is `2 I`, [`hertz_integral`]);
/// the integrated elastic impact's duration to within its last step (6 %), exchanging the
/// velocities to 1e-4 (the integrator's tolerance). At break speed (10 m/s) that is
/// a contact of a quarter millisecond compressing under a millimetre, as measured for
/// pool balls.
#[test]
fn a_break_speed_contact_lasts_a_quarter_millisecond_and_compresses_under_a_millimetre() {
    let (ball, material) = (BallSpec::default(), HertzContact::default());
    let m_star = 0.5 * ball.mass;
    let r_star = 0.5 * ball.radius;
    let e_star = material.young / (2.0 * (1.0 - material.poisson.powi(2)));
    let exact_time = 2.0 * hertz_integral();
    // 2 I = 4/5 Gamma(2/5) Gamma(1/2) / Gamma(9/10) = 2.943_275_184_324_705.
    assert!(
        (exact_time - 2.943_275_184_324_705).abs() < 1e-9,
        "{exact_time}"
    );
    let h = hertz(1.0);
    for v in [0.01, 1.0, 10.0] {
        let d = (15.0 * m_star * v * v / (16.0 * e_star * r_star.sqrt())).powf(0.4);
        let got = h.max_compression(v);
        assert!((got - d).abs() < 1e-13 * d, "v {v}: {got} vs {d}");
        let t = exact_time * d / v;
        let got = h.duration(v);
        assert!((got - t).abs() < 2.6e-5 * t, "v {v}: {got} vs {t}");
        // The integrator's own contact.
        let mut vel = [Vec2::new(v, 0.0), Vec2::ZERO];
        let edges = [Edge {
            a: 0,
            b: 1,
            n: Vec2::new(1.0, 0.0),
            gap: 0.0,
        }];
        let out = impact(&h, &mut vel, &edges);
        // It ends at its first step past the separation: never early, 5.56 % late here
        // at every speed (the impact only scales with v), in 19 steps.
        assert!(
            (t..1.06 * t).contains(&out.duration),
            "v {v}: {} vs {t}",
            out.duration
        );
        assert!((vel[1].x - v).abs() < 1e-4 * v && vel[0].x.abs() < 1e-4 * v);
    }
    let (d, t) = (h.max_compression(10.0), h.duration(10.0));
    assert!((7.0e-4..9.0e-4).contains(&d), "{d}");
    assert!((2.0e-4..2.8e-4).contains(&t), "{t}");
}

#[test]
fn the_damping_reproduces_the_restitution_at_every_speed() {
    for e in [1.0, 0.95, 0.8, 0.5] {
        let h = hertz(e);
        assert!((dimensionless_restitution(h.alpha) - e).abs() < 1e-9, "{e}");
        for v in [0.01, 1.0, 12.0] {
            let mut vel = [Vec2::new(v, 0.0), Vec2::ZERO];
            let edges = [Edge {
                a: 0,
                b: 1,
                n: Vec2::new(1.0, 0.0),
                gap: 0.0,
            }];
            let out = impact(&h, &mut vel, &edges);
            let got = (vel[1].x - vel[0].x) / v;
            assert!((got - e).abs() < 1e-4, "e {e} v {v}: {got}");
            assert!(((vel[0] + vel[1]).x - v).abs() < 1e-14 * v);
            assert!(out.steps > 10 && out.duration > 0.5 * h.duration(v));
        }
    }
}

#[test]
fn a_gap_the_contact_closes_makes_the_middle_ball_pass_the_load_on() {
    // Three balls in a line, the second touching the third, the first arriving: with
    // elastic balls nearly all the momentum ends in the third.
    let h = hertz(1.0);
    let x = Vec2::new(1.0, 0.0);
    let mut vel = [Vec2::new(2.0, 0.0), Vec2::ZERO, Vec2::ZERO];
    let edges = [
        Edge {
            a: 0,
            b: 1,
            n: x,
            gap: 0.0,
        },
        Edge {
            a: 1,
            b: 2,
            n: x,
            gap: 1e-5,
        },
    ];
    let out = impact(&h, &mut vel, &edges);
    assert!(vel[2].x > 1.8, "{vel:?}");
    assert!((vel.iter().map(|v| v.x).sum::<f64>() - 2.0).abs() < 1e-14);
    assert!(out.impulse.iter().all(|&j| j > 0.0));
    assert!(out.onset[0] == 0.0 || out.onset[0] < out.onset[1]);
}

const R: f64 = 0.028575;

fn friction(mu: f64) -> Option<(crate::resolve::friction::PairFriction, f64)> {
    Some((crate::resolve::friction::PairFriction::constant(mu), R))
}

/// Two balls alone in an impact with friction against the exact impulse law of an isolated
/// pair ([`crate::resolve::frictional_spheres`]): a stun cut at 30 degrees (the contact
/// slides throughout, and the regularised law gives `1 - v_eps^2 / (2 s^2)` of Coulomb's
/// force: the throw within 0.5 %), at 3 degrees and at 30 degrees with side spin (the slip
/// stops during the contact: within 1e-4); with follow at 15 degrees within
/// 6 %: there the slip has a vertical part, which the integrated law stops at its own rate
/// (5 F_z / m, the cloth taking the vertical force) while the pair law stops the whole slip
/// along its first direction at the horizontal rate 7 F / m. The normal impulse within the
/// restitution's 1e-4 in every case.
#[test]
fn a_lone_pair_with_friction_throws_as_the_exact_impulse_law() {
    use crate::ball::BallState;
    let h = hertz(0.95);
    let law = crate::resolve::friction::PairFriction::constant(0.05);
    for (deg, spin, tol) in [
        (30.0f64, Vec3::ZERO, 5e-3),
        (3.0, Vec3::ZERO, 1e-4),
        (30.0, Vec3::new(0.0, 0.0, 60.0), 1e-4),
        (15.0, Vec3::new(0.0, 3.0 / R, 0.0), 6e-2),
    ] {
        let n = Vec2::new(deg.to_radians().cos(), deg.to_radians().sin());
        let state = |v: Vec2, w: Vec3| BallState {
            velocity: v,
            angular_velocity: w,
            ..BallState::default()
        };
        let (a, b) = (
            state(Vec2::new(3.0, 0.0), spin),
            state(Vec2::ZERO, Vec3::ZERO),
        );
        let (ea, eb) = crate::resolve::frictional_spheres(&a, &b, n, 0.95, law, R).unwrap();
        let mut vel = [a.velocity, b.velocity];
        let mut spins = [a.angular_velocity, b.angular_velocity];
        let edges = [Edge {
            a: 0,
            b: 1,
            n,
            gap: 0.0,
        }];
        impact_with_friction(&h, friction(0.05), &mut vel, &mut spins, &edges);
        let t = n.perp();
        let (jt, exact) = (vel[1].dot(t), eb.velocity.dot(t));
        assert!(exact.abs() > 1e-3, "{deg}: a throw to compare");
        assert!(
            (jt - exact).abs() <= tol * exact.abs(),
            "{deg} deg {spin:?}: throw {jt} vs {exact}"
        );
        assert!((vel[1].dot(n) - eb.velocity.dot(n)).abs() < 1e-4 * 3.0);
        let dw = spins[0] - ea.angular_velocity;
        assert!(R * dw.dot(dw).sqrt() <= tol * 3.0 + 2.0 * (jt - exact).abs());
    }
}

/// Twice the kinetic energy over the mass: `v^2 + (2/5) R^2 w^2`.
fn energy(v: &[Vec2], w: &[Vec3]) -> f64 {
    v.iter()
        .zip(w)
        .map(|(v, w)| v.length_squared() + 0.4 * R * R * w.dot(*w))
        .sum()
}

/// Random clusters of 3 to 12 balls on a lattice, gaps of 0 to 50 micrometres, moving at
/// 1e-4 to 10 m/s with spins up to 100 rad/s (so some impacts carry far more spin than
/// linear energy) and friction 0.03 to 0.12: no impact raises the kinetic energy
/// (rotational included), and each keeps the linear momentum to rounding (16 n ulps of the
/// balls' summed speeds before or after, whichever is more: friction turns spin into speed).
#[test]
fn no_impact_with_friction_gains_energy_and_each_keeps_its_momentum() {
    let h = hertz(0.95);
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut rand = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut with_friction = 0;
    for trial in 0..400 {
        let n = 3 + trial % 10;
        let speed = 10f64.powf(-4.0 + 5.0 * rand());
        let d = 2.0 * R;
        let mut pos = Vec::new();
        let mut vel = Vec::new();
        let mut spins = Vec::new();
        for i in 0..n {
            let (row, col) = ((i / 4) as f64, (i % 4) as f64);
            let gap = 5e-5 * rand() * rand();
            pos.push(Vec2::new(
                (col + 0.5 * row) * (d + gap),
                row * 0.75f64.sqrt() * (d + gap),
            ));
            vel.push(Vec2::new(rand() - 0.5, rand() - 0.5) * (2.0 * speed));
            let w = 100.0 * rand() * rand();
            spins.push(Vec3::new(rand() - 0.5, rand() - 0.5, rand() - 0.5) * (2.0 * w));
        }
        let mut edges = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                let dp = pos[j] - pos[i];
                if dp.length() < d + 1e-4 {
                    edges.push(Edge {
                        a: i,
                        b: j,
                        n: dp.normalized().unwrap(),
                        gap: dp.length() - d,
                    });
                }
            }
        }
        let (v0, w0) = (vel.clone(), spins.clone());
        let mu = 0.03 + 0.09 * rand();
        let out = impact_with_friction(&h, friction(mu), &mut vel, &mut spins, &edges);
        if out.impulse.iter().any(|&j| j > 0.0) && spins != w0 {
            with_friction += 1;
        }
        let (e0, e1) = (energy(&v0, &w0), energy(&vel, &spins));
        assert!(e1 <= e0, "trial {trial}: energy {e0} -> {e1}");
        let p = |v: &[Vec2]| v.iter().fold(Vec2::ZERO, |s, v| s + *v);
        let sum = |v: &[Vec2]| v.iter().map(|v| v.length()).sum::<f64>();
        let speeds = sum(&v0).max(sum(&vel));
        assert!(
            (p(&vel) - p(&v0)).length() <= 16.0 * f64::EPSILON * n as f64 * speeds,
            "trial {trial}: momentum {:?} -> {:?}",
            p(&v0),
            p(&vel)
        );
    }
    assert!(with_friction > 200, "{with_friction} impacts with friction");
}
