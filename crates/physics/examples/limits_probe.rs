//! The experiment behind `limits.rs`: sweeps a shot's speed (and the clock a break starts at)
//! over decades and reports where the solver stops honouring them, judged by the invariant
//! monitor (`check`) and by the closed-form time to rest of a lone ball.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example limits_probe
//! ```

use billiards_physics::check::{Monitor, Tolerances};
use billiards_physics::soak::scale_friction;
use billiards_physics::*;

fn spin() -> (Table, Params) {
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    (Table::wpa_8ft().with_jaws(0.015), params)
}

fn paper() -> (Table, Params) {
    (Table::wpa_8ft(), Params::default())
}

/// Runs `shot` on the cue ball of `rack` under the monitor, from clock `start`.
fn checked(
    (table, params): (Table, Params),
    rack: Rack,
    start: f64,
    shot: Shot,
) -> Result<(usize, f64), String> {
    let balls = rack.layout(&table, &params.ball);
    let mut sim = Simulation::new(table, params, &balls).map_err(|e| e.to_string())?;
    sim.advance_to(start).map_err(|e| e.to_string())?;
    sim.strike(0, shot).map_err(|e| e.to_string())?;
    let mut m = Monitor::new(&sim, Tolerances::default()).map_err(|e| e.to_string())?;
    m.run_to_rest(&mut sim).map_err(|e| e.to_string())?;
    Ok((sim.history().events().len(), sim.time() - start))
}

/// Relative error of a lone paper-model ball's time to rest on a table too long to reach a
/// cushion: slides to the threshold speed at `mu_s g`, rolls to rest at `mu_r g`.
fn lone_ball_error(speed: f64) -> f64 {
    let table = Table::scaled(1e9);
    let params = Params::default();
    let Model::Paper(m) = params.model else {
        unreachable!()
    };
    let mut sim = Simulation::new(table, params, &[BallSetup::at(0, Vec2::ZERO)]).unwrap();
    sim.strike(0, Shot::new(0.0, speed)).unwrap();
    if sim.run_to_rest().is_err() {
        return f64::NAN;
    }
    let g = params.gravity;
    let exact = if speed > m.slide_roll_speed {
        (speed - m.slide_roll_speed) / (m.mu_slide * g) + m.slide_roll_speed / (m.mu_roll * g)
    } else {
        speed / (m.mu_roll * g)
    };
    ((sim.time() - exact) / exact).abs()
}

/// The ranges the soak scenes `0..n` use: shot speeds, setup speeds, the clock at each strike.
fn soak_ranges(n: u64) {
    let (mut lo, mut hi, mut setup, mut clock) = (f64::INFINITY, 0.0f64, 0.0f64, 0.0f64);
    for seed in 0..n {
        let s = soak::scenario(seed);
        for b in &s.balls {
            setup = setup.max(b.velocity.length());
        }
        let mut sim = Simulation::new(s.table, s.params, &s.balls).unwrap();
        for shot in &s.shots {
            let Some(ball) = (0..sim.ball_count()).find(|&i| sim.ball(i).motion.on_table()) else {
                break;
            };
            if shot.speed > 0.0 {
                lo = lo.min(shot.speed);
            }
            hi = hi.max(shot.speed);
            clock = clock.max(sim.time());
            sim.strike(ball, *shot).unwrap();
            let _ = match s.duration {
                Some(d) => sim.advance_to(sim.time() + d).map(|_| ()),
                None => sim.run_to_rest().map(|_| ()),
            };
        }
    }
    println!(
        "soak 0..{n}: shot speeds {lo:e}..{hi:e} m/s, setup speeds <= {setup:e} m/s, clock at a strike <= {clock:e} s"
    );
}

fn main() {
    if let Some(n) = std::env::args().nth(1) {
        return soak_ranges(n.parse().unwrap());
    }
    println!("# shot speed sweep: 9-ball break (spin, jaws) and 15-ball (paper), straight on");
    for k in (-320..=308).filter(|k| k % 20 == 0 || (-12..=6).contains(k)) {
        let v: f64 = format!("1e{k}").parse().unwrap();
        let shot = Shot::new(0.0, v);
        let s = checked(spin(), Rack::NineBall, 0.0, shot);
        let p = checked(paper(), Rack::FifteenBall, 0.0, shot);
        println!("{v:9.1e} m/s  spin: {s:?}  paper: {p:?}");
    }
    println!("# fine sweep near the top, friction x1, x0.02 (the soak's least)");
    for v in [
        30.0, 50.0, 100.0, 200.0, 300.0, 500.0, 1e3, 2e3, 5e3, 1e4, 3e4, 1e5,
    ] {
        let shot = Shot::new(0.0, v);
        let low = |(t, p): (Table, Params)| (t, scale_friction(p, 0.02));
        let r = [
            checked(spin(), Rack::NineBall, 0.0, shot),
            checked(paper(), Rack::FifteenBall, 0.0, shot),
            checked(low(spin()), Rack::NineBall, 0.0, shot),
            checked(low(paper()), Rack::FifteenBall, 0.0, shot),
        ];
        let ok: Vec<String> = r
            .iter()
            .map(|x| match x {
                Ok((n, t)) => format!("ok {n} ev {t:.3e} s"),
                Err(e) => format!("FAIL {}", &e[..e.len().min(90)]),
            })
            .collect();
        println!("{v:9.1e} m/s  {ok:?}");
    }
    println!("# first failing speed of the spin 9-ball break (bisection on the exponent)");
    let fails = |v: f64| checked(spin(), Rack::NineBall, 0.0, Shot::new(0.0, v)).is_err();
    let (mut lo, mut hi) = (6.0f64, 20.0f64);
    while hi - lo > 0.01 {
        let mid = 0.5 * (lo + hi);
        if fails(10f64.powf(mid)) {
            hi = mid
        } else {
            lo = mid
        }
    }
    println!("passes at 1e{lo:.2}, fails at 1e{hi:.2} m/s");
    println!("# every decade from 1e6 to 1e20: spin break, paper break");
    for k in 6..=20 {
        let v = 10f64.powi(k);
        let s = checked(spin(), Rack::NineBall, 0.0, Shot::new(0.0, v)).is_ok();
        let p = checked(paper(), Rack::FifteenBall, 0.0, Shot::new(0.0, v)).is_ok();
        println!("{v:7.0e} m/s  spin ok {s}  paper ok {p}");
    }
    println!("# lone ball, paper model: relative error of the time to rest");
    for k in (-300..=7).filter(|k| k % 20 == 0 || (-160..=-150).contains(k) || *k > -14) {
        let v: f64 = format!("1e{k}").parse().unwrap();
        let err = lone_ball_error(v);
        println!("{v:9.1e} m/s  {err:.1e}");
    }
    println!("# 12 m/s spin-model 9-ball break starting at clock T");
    for k in 0..=16 {
        let t = 10f64.powi(k);
        let r = checked(spin(), Rack::NineBall, t, Shot::new(0.0, 12.0));
        println!("T = {t:7.0e} s  {r:?}");
    }
    println!("# 100 m/s spin 9-ball and paper 15-ball breaks starting at clock T");
    for t in [1e3, 1e4, 3e4, 1e5, 3e5, 1e6, 3e6, 1e7] {
        let s = checked(spin(), Rack::NineBall, t, Shot::new(0.0, 100.0));
        let p = checked(paper(), Rack::FifteenBall, t, Shot::new(0.0, 100.0));
        println!("T = {t:7.0e} s  spin {s:?}  paper {p:?}");
    }
}
