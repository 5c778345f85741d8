//! Soak scenes made for cluster impacts: frozen and near-frozen racks broken at break speeds
//! and at a crawl, some with every ball spinning, under the spin model with cluster impacts.

use super::scenes::{SOAK_EVENT_CAP, Scenario, log_uniform, scenario, tip};
use crate::event::Shot;
use crate::math::{Vec2, Vec3};
use crate::params::{Model, Params, SpinModel};
use crate::racks::Rack;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The cluster scene for `seed`: [`scenario`]`(seed)`'s table, parameters (the spin model
/// with cluster impacts on; the default spin model for a paper-model scene) and follow-up
/// shots, with a 9-ball or 15-ball rack whose gaps are all zero (a quarter of the scenes)
/// or `g` log-uniform in 1 nm to 1 mm, each ball then moved by up to `g / 4` (so no pair
/// overlaps); in three scenes of ten every racked ball spins at up to 40 rad/s about every
/// axis and creeps at up to 1 mm/s. The first shot is at the apex (dead straight a quarter
/// of the time, otherwise up to 0.05 rad off), at 3 to 14 m/s or, half the time, at 1 mm/s
/// to 3 m/s log-uniform: near-zero energies into frozen clusters.
pub fn cluster_scenario(seed: u64) -> Scenario {
    let base = scenario(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x636c_7573_7465_7273);
    let params = match base.params.model {
        Model::Spin(m) => Params {
            model: Model::Spin(SpinModel {
                cluster: Some(m.cluster.unwrap_or_default()),
                ..m
            }),
            ..base.params
        },
        Model::Paper(_) => Params {
            model: Model::Spin(SpinModel::default()),
            max_events: SOAK_EVENT_CAP,
            ..Params::default()
        },
    };
    let rack = [Rack::NineBall, Rack::Tight][rng.random_range(0..2)];
    let mut balls = rack.layout(&base.table, &params.ball);
    let apex = base.table.foot_spot();
    let gap = if rng.random_bool(0.25) {
        0.0
    } else {
        log_uniform(&mut rng, 1e-9, 1e-3)
    };
    let spread = 1.0 + gap / (2.0 * params.ball.radius);
    let spinning = rng.random_bool(0.3);
    for b in balls.iter_mut().skip(1) {
        let a = rng.random_range(0.0..std::f64::consts::TAU);
        let jitter = Vec2::new(a.cos(), a.sin()) * (0.25 * gap * rng.random::<f64>());
        b.position = apex + (b.position - apex) * spread + jitter;
        if spinning {
            let mut w = || rng.random_range(-40.0..40.0);
            b.spin = Vec3::new(w(), w(), w());
            let a = rng.random_range(0.0..std::f64::consts::TAU);
            b.velocity = Vec2::new(a.cos(), a.sin()) * rng.random_range(0.0..1e-3);
        }
    }
    let aim = apex - balls[0].position;
    let first = Shot {
        angle: aim.angle()
            + match rng.random_range(0..4) {
                0 => 0.0,
                _ => rng.random_range(-0.05..0.05),
            },
        speed: if rng.random_bool(0.5) {
            rng.random_range(3.0..14.0)
        } else {
            log_uniform(&mut rng, 1e-3, 3.0)
        },
        tip: tip(&mut rng),
        elevation: 0.0,
    };
    let mut shots = vec![first];
    shots.extend(base.shots.iter().skip(1).copied());
    Scenario {
        kind: "cluster",
        params,
        balls,
        shots,
        ..base
    }
}
