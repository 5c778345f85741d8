//! Soak scenes on the carom table ([`Table::carom_match`], no pockets): the shots of the
//! pocketed tables' scenes played with carom balls among three (or up to sixteen) balls.

use super::scenes::{Scenario, scenario};
use crate::params::BallSpec;
use crate::racks::scattered;
use crate::table::Table;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The carom scene for `seed`: [`scenario`]`(seed)`'s model, parameters (with the carom ball,
/// [`BallSpec::carom`]), shots and duration, on [`Table::carom_match`], with three balls
/// scattered over the table (seven scenes in ten) or 1 to 16; in one scene of ten the balls
/// start moving at up to 5 m/s. A pocketed table's scene keeps its own draw: this one reads a
/// stream of its own.
pub fn carom_scenario(seed: u64) -> Scenario {
    let base = scenario(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x6361_726f_6d5f_3363);
    let table = Table::carom_match();
    let params = crate::params::Params {
        ball: BallSpec::carom(),
        ..base.params
    };
    let n = if rng.random_bool(0.7) {
        3
    } else {
        rng.random_range(1..=16)
    };
    let moving = rng.random_bool(0.1);
    let max_speed = if moving {
        rng.random_range(0.0..5.0)
    } else {
        0.0
    };
    let balls = scattered(&table, &params.ball, n, max_speed, rng.random());
    Scenario {
        kind: if moving { "carom-moving" } else { "carom" },
        table,
        params,
        balls,
        ..base
    }
}
