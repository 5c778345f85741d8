//! The Mathavan 2010 integration impact by impact: steps, rate evaluations, time and error
//! (each set's largest and rms, relative to the incoming speed) against a reference with
//! 100 times smaller steps, over the 18 cushion impacts of the
//! spin model's 9-ball break (`realism_cost`'s, with Mathavan's cushion) and shots over
//! angle and spin (the module's tests').
//!
//! ```sh
//! cargo run --release -p billiards-physics --example mathavan_probe -- [REPEATS] [-v]
//! ```
//!
//! `-v` lists each impact (steps kept and rejected, rate evaluations, steps with a slip
//! slaved, longest step, error, time); `TOL=1e-7` integrates at another tolerance; `ONLY=K`
//! runs impact K alone;
//! `NOREF=1` skips the reference (for profiling); `RANDOM=3000` adds that many random impacts
//! (0.3–4 m/s, 0–85 degrees, any spin up to the speed's rolling spin; fixed seed) against a
//! reference at 1e-9 a step and steps of 1e-3 of the impulse, which no integrator's
//! tolerance or step choice shares with the default. The constants are the game's (e 0.98,
//! mu 0.14, cloth 0.2, nose at 0.635 of the diameter).

use billiards_physics::math::{Vec2, Vec3};
use billiards_physics::resolve::mathavan_2010::{Accuracy, Mathavan2010, mathavan_2010_with};
use std::time::Instant;

/// The break's impacts: vx, vy, wx, wy, wz, nx, ny (the game's ball, R = 0.028575 m).
#[rustfmt::skip]
const BREAK: [[f64; 7]; 18] = [
    [-0.26110742946377924, -0.7656568097633183, 26.794639011839656, -9.137617829003648, 0.0, 0.0, 1.0],
    [-0.312452915316477, 0.8598022373441583, -30.08931714240274, -10.934485225423517, 0.0, 0.0, -1.0],
    [-0.46575804902575585, -0.09193959282273895, 3.217483563350444, -16.299494279116566, 0.0, 1.0, 0.0],
    [-0.4876349202426535, 0.01901133327939536, -0.6653135005912636, -17.06508907235883, 0.0, 1.0, 0.0],
    [-0.5643785025536143, 0.5861150917860619, -20.511464279477234, -19.750778742033745, 0.0, 0.0, -1.0],
    [-0.6392222283005984, 0.5009859801163402, -17.532317764351365, -22.36998174280309, 0.0, 0.0, -1.0],
    [-0.6490628582633605, -0.7051530867569065, 24.677273377319562, -22.7143607441246, 0.0, 0.0, 1.0],
    [-0.7394627899169322, -0.2378076233380136, 8.322226538513162, -25.87796290172991, 0.0, 1.0, 0.0],
    [-0.7583495431587486, -0.06284102009343612, 2.199160808169243, -26.538916645975455, 0.0, 1.0, 0.0],
    [-0.7649841939996462, 0.0688636478640934, -2.409926434438964, -26.771100402437312, 0.0, 1.0, 0.0],
    [-0.9413523310635498, 0.48071458983380605, -16.822907780710622, -32.94321368551355, 0.0, 0.0, -1.0],
    [1.1559516978356714, -2.297275499217776, 0.5929908003406599, 22.139796477842225, 45.11304814563738, -1.0, 0.0],
    [1.3044865454123202, -1.125441483756014, -10.967156722184612, 35.524789881161524, 5.88311705355558, -1.0, 0.0],
    [1.3145903629471696, 0.9790132219975305, -13.11757809329702, 8.598851610975647, -64.44262374469645, -1.0, 0.0],
    [1.3348857818765933, 2.83816389185096, 2.17482480889713, 21.995118244399105, -51.88395684889586, -1.0, 0.0],
    [1.9430324969022381, 2.6987851139581607, -23.932900549003453, 16.923153190063356, 0.0, 0.0, -1.0],
    [2.2633552214994674, -3.310295097972143, 20.14622286328162, 13.45314596685842, 0.0, 0.0, 1.0],
    [2.832994814260015, 0.2179726782131441, -1.5971878608936256, 20.70347910295988, 0.0, -1.0, 0.0],
];

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000);
    let verbose = std::env::args().any(|a| a == "-v");
    let acc = Accuracy {
        tol: std::env::var("TOL")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(Accuracy::DEFAULT.tol),
        ..Accuracy::DEFAULT
    };
    let only: Option<usize> = std::env::var("ONLY").ok().and_then(|s| s.parse().ok());
    let r = 0.028575;
    let game = Mathavan2010 {
        e: 0.98,
        mu_cushion: 0.14,
        mu_table: 0.2,
        height: 2.0 * r * 0.635,
    };
    let mut cases: Vec<(Vec2, Vec3, Vec2)> = BREAK
        .iter()
        .map(|c| {
            (
                Vec2::new(c[0], c[1]),
                Vec3::new(c[2], c[3], c[4]),
                Vec2::new(c[5], c[6]),
            )
        })
        .collect();
    let n_break = cases.len();
    for alpha in [5.0f64, 20.0, 45.0, 60.0, 85.0, 90.0] {
        for (top, side) in [
            (0.0, 0.0),
            (1.0, 0.0),
            (-1.0, 0.0),
            (1.0, 1.0),
            (0.5, -0.5),
            (0.0, -2.0),
        ] {
            let a = alpha.to_radians();
            let speed = 1.3;
            let v = Vec2::new(speed * a.cos(), speed * a.sin());
            let axis = Vec2::new(-a.sin(), a.cos());
            let w = (axis * (top * speed / r)).extend() + Vec3::new(0.0, 0.0, side * speed / r);
            cases.push((v, w, Vec2::new(0.0, -1.0)));
        }
    }
    let (mut total_ns, mut total_evals, mut worst) = ([0.0; 2], [0usize; 2], [0.0f64; 2]);
    let mut squares = [0.0f64; 2];
    for (k, &(v, w, n)) in cases.iter().enumerate() {
        if only.is_some_and(|o| o != k) {
            continue;
        }
        let set = usize::from(k >= n_break);
        let (a, aw, stats) = mathavan_2010_with(v, w, n, &game, r, acc).unwrap();
        let reference = Accuracy {
            tol: acc.tol / 100.0,
            max_step: stats.longest / 100.0,
        };
        let (b, bw) = if std::env::var_os("NOREF").is_some() {
            (a, aw)
        } else {
            let (b, bw, _) = mathavan_2010_with(v, w, n, &game, r, reference).unwrap();
            (b, bw)
        };
        let speed = v.length() + r * w.length();
        let err = (a - b).length().max(r * (aw - bw).length()) / speed;
        let start = Instant::now();
        for _ in 0..repeats {
            std::hint::black_box(mathavan_2010_with(
                std::hint::black_box(v),
                w,
                n,
                &game,
                r,
                acc,
            ));
        }
        let ns = start.elapsed().as_secs_f64() * 1e9 / repeats as f64;
        total_ns[set] += ns;
        total_evals[set] += stats.evaluations;
        worst[set] = worst[set].max(err);
        squares[set] += err * err;
        if verbose {
            println!(
                "{k:>2} steps {:>3} rejected {:>3} evals {:>4} slaved {:>3} longest {:.3} err {err:.1e} {ns:>7.0} ns",
                stats.steps, stats.rejected, stats.evaluations, stats.slaved, stats.longest
            );
        }
    }
    for (set, name, count) in [(0, "break", n_break), (1, "shots", cases.len() - n_break)] {
        println!(
            "{name}: {count} impacts, {:.0} ns and {:.1} rate evaluations an impact, largest error {:.3e}, rms {:.3e}",
            total_ns[set] / count as f64,
            total_evals[set] as f64 / count as f64,
            worst[set],
            (squares[set] / count as f64).sqrt()
        );
    }
    if let Some(n) = std::env::var("RANDOM").ok().and_then(|s| s.parse().ok()) {
        random_impacts(n, &game, r, acc);
    }
}

/// `n` random impacts at `acc` against a fine reference: the largest, 99th percentile, mean
/// and rms difference relative to the incoming speed, and the rate evaluations an impact.
fn random_impacts(n: usize, game: &Mathavan2010, r: f64, acc: Accuracy) {
    let fine = Accuracy {
        tol: 1e-9,
        max_step: 1e-3,
    };
    let mut seed: u64 = 12345;
    let mut rnd = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut errs, mut evals) = (Vec::with_capacity(n), 0);
    for _ in 0..n {
        let speed = 0.3 + 3.7 * rnd();
        let a = (rnd() * 85.0).to_radians();
        let v = Vec2::new(speed * a.sin(), speed * a.cos());
        let k = speed / r;
        let mut spin = || k * (2.0 * rnd() - 1.0);
        let w = Vec3::new(spin(), spin(), spin());
        let n = Vec2::new(0.0, -1.0);
        let (a, aw, stats) = mathavan_2010_with(v, w, n, game, r, acc).unwrap();
        let (b, bw, _) = mathavan_2010_with(v, w, n, game, r, fine).unwrap();
        let scale = v.length() + r * w.length();
        errs.push((a - b).length().max(r * (aw - bw).length()) / scale);
        evals += stats.evaluations;
    }
    errs.sort_by(f64::total_cmp);
    println!(
        "random: {n} impacts, {:.1} rate evaluations an impact; difference from the fine \
         reference: largest {:.3e}, 99th percentile {:.3e}, mean {:.3e}, rms {:.3e}, {} above 2e-4",
        evals as f64 / n as f64,
        errs[n - 1],
        errs[n * 99 / 100],
        errs.iter().sum::<f64>() / n as f64,
        (errs.iter().map(|e| e * e).sum::<f64>() / n as f64).sqrt(),
        errs.iter().filter(|&&e| e > 2e-4).count()
    );
}
