//! The break changes continuously with the rack's gaps (issue 23): 9-ball on a 9-ft table,
//! the default break (cue ball in the break box, 10–12 m/s, full on the 1), the same 300
//! seeded breaks of a frozen rack and of racks with gaps of up to 2e-9 m and 0.02 mm. With
//! cluster impacts the shares of breaks that pocket a ball have overlapping 95 % intervals
//! (Wilson); resolved pair by pair they do not (73 % frozen, 46 % at 0.1 mm in
//! `break_stats`).
//!
//! Since the cluster impact integrates the contacts' friction with their normal forces
//! (issue 49) the break is continuous at zero gap but not flat beyond it: gaps of 20 to 100
//! micrometres (a slack of 1e-5 to 5e-5 m), a tenth of a break contact's compression,
//! change which contacts are loaded while others slip, and the rate falls from 64–67 % to
//! 44–50 % (`break_stats --cushion han --gaps-mm 0,0.01,0.02,0.05,0.1`, 1,000 breaks a row,
//! the same at every regularisation speed from 3e-3 to 3e-2 of the approach). Before, when
//! the friction was applied pair by pair after the normal impulses, it was flat to 0.05 mm.

use billiards_physics::{Model, Params, Shot, Simulation, SpinModel, Table, Vec2};
use billiards_rules::racks::nine_ball_spaced;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Breaks (of 300) that pocket at least one object ball, for racks of lattice slack `gap`.
fn breaks_with_a_ball(gap: f64, cluster: bool) -> usize {
    let table = Table::wpa_9ft().with_jaws(0.015);
    let m = SpinModel::default();
    let params = Params {
        model: Model::Spin(SpinModel {
            cluster: if cluster { m.cluster } else { None },
            ..m
        }),
        ..Params::default()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(23);
    let mut made = 0;
    for _ in 0..300 {
        let mut balls = nine_ball_spaced(&table, &params.ball, rng.random(), gap);
        let string = table.head_spot().x;
        let cue = Vec2::new(
            rng.random_range(string - table.length / 8.0..=string),
            rng.random_range(-table.width / 4.0..=table.width / 4.0),
        );
        balls[0].position = cue;
        let mut sim = Simulation::new(table, params, &balls).unwrap();
        let aim = (balls[1].position - cue).angle();
        sim.strike(0, Shot::new(aim, rng.random_range(10.0..=12.0)))
            .unwrap();
        sim.run_to_rest().unwrap();
        made += usize::from((1..sim.ball_count()).any(|i| !sim.ball(i).motion.on_table()));
    }
    made
}

/// Wilson 95 % interval of `k` of 300.
fn interval(k: usize) -> (f64, f64) {
    let (n, z) = (300.0, 1.96);
    let p = k as f64 / n;
    let d = 1.0 + z * z / n;
    let c = (p + z * z / (2.0 * n)) / d;
    let h = z * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt() / d;
    (c - h, c + h)
}

fn overlap(a: usize, b: usize) -> bool {
    let (x, y) = (interval(a), interval(b));
    x.0 <= y.1 && y.0 <= x.1
}

#[test]
fn frozen_and_gapped_racks_pocket_a_ball_as_often_within_sampling_noise() {
    let made: Vec<usize> = [0.0, 1e-9, 1e-5]
        .iter()
        .map(|&g| breaks_with_a_ball(g, true))
        .collect();
    for a in &made {
        for b in &made {
            assert!(overlap(*a, *b), "breaks with a ball of 300: {made:?}");
        }
    }
    // Pair by pair the same breaks differ by far more: the test can tell the two apart.
    let frozen = breaks_with_a_ball(0.0, false);
    let gapped = breaks_with_a_ball(0.05e-3, false);
    assert!(
        !overlap(frozen, gapped),
        "pair by pair: {frozen} against {gapped}"
    );
}
