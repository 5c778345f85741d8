//! Standard layouts. Ball 0 is always the cue ball, on the head spot (a quarter of the length
//! from the head cushion, centred: the paper's figure 1).

use crate::math::Vec2;
use crate::params::BallSpec;
use crate::sim::BallSetup;
use crate::table::{INCH, Table};
use rand::{Rng, SeedableRng};

/// The paper's gap between racked balls (figure 2): 1/10 in.
pub const PAPER_RACK_GAP: f64 = 0.1 * INCH;

/// The paper's default layout: the cue ball alone on the head spot.
pub fn paper_default(table: &Table) -> Vec<BallSetup> {
    vec![BallSetup::at(0, table.head_spot())]
}

/// Balls of a triangular or diamond rack with `rows[k]` the numbers in row `k` from the apex
/// (on the foot spot) towards the foot cushion, centre spacing `2R + gap`.
fn rack(table: &Table, ball: &BallSpec, gap: f64, rows: &[&[u8]]) -> Vec<BallSetup> {
    let d = 2.0 * ball.radius + gap;
    let mut balls = paper_default(table);
    let apex = table.foot_spot();
    for (k, row) in rows.iter().enumerate() {
        let x = apex.x + k as f64 * d * 3f64.sqrt() / 2.0;
        let n = row.len() as f64;
        for (i, &number) in row.iter().enumerate() {
            // Left to right as seen from the head: +y first.
            let y = ((n - 1.0) / 2.0 - i as f64) * d;
            balls.push(BallSetup::at(number, Vec2::new(x, y)));
        }
    }
    balls
}

/// Number order of an 8-ball rack: 1 at the apex, 8 in the middle, a solid and a stripe in
/// the back corners.
const FIFTEEN: [&[u8]; 5] = [
    &[1],
    &[9, 2],
    &[10, 8, 3],
    &[11, 7, 14, 4],
    &[5, 13, 15, 6, 12],
];

/// The 15-ball rack of the paper (figure 2): 1/10 in between balls, apex on the foot spot.
pub fn fifteen_ball(table: &Table, ball: &BallSpec) -> Vec<BallSetup> {
    rack(table, ball, PAPER_RACK_GAP, &FIFTEEN)
}

/// A tight 15-ball rack: neighbouring balls exactly touching.
pub fn tight_rack(table: &Table, ball: &BallSpec) -> Vec<BallSetup> {
    rack(table, ball, 0.0, &FIFTEEN)
}

/// A 9-ball diamond, tight: 1 on the foot spot, 9 in the centre.
pub fn nine_ball(table: &Table, ball: &BallSpec) -> Vec<BallSetup> {
    rack(
        table,
        ball,
        0.0,
        &[&[1], &[2, 3], &[4, 9, 5], &[6, 7], &[8]],
    )
}

/// A named standard layout (for scene files and the game's rack buttons).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Rack {
    /// [`paper_default`].
    PaperDefault,
    /// [`fifteen_ball`].
    FifteenBall,
    /// [`tight_rack`].
    Tight,
    /// [`nine_ball`].
    NineBall,
}

impl Rack {
    /// The layout.
    pub fn layout(self, table: &Table, ball: &BallSpec) -> Vec<BallSetup> {
        match self {
            Rack::PaperDefault => paper_default(table),
            Rack::FifteenBall => fifteen_ball(table, ball),
            Rack::Tight => tight_rack(table, ball),
            Rack::NineBall => nine_ball(table, ball),
        }
    }
}

/// `count` balls on a jittered grid filling the table (never overlapping, clear of the
/// cushions), each moving in a random direction at a speed up to `max_speed`; reproducible
/// from `seed`. For benchmarks and stress tests.
pub fn scattered(
    table: &Table,
    ball: &BallSpec,
    count: usize,
    max_speed: f64,
    seed: u64,
) -> Vec<BallSetup> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let b = table.centre_bounds(ball.radius);
    // Grid cells of equal aspect to the table, enough for `count` balls.
    let cols = ((count as f64 * b.x / b.y).sqrt().ceil() as usize).max(1);
    let rows = count.div_ceil(cols).max(1);
    let (cw, ch) = (2.0 * b.x / cols as f64, 2.0 * b.y / rows as f64);
    // Each ball may move within its cell by the slack left after its diameter.
    let (jx, jy) = (
        (cw - 2.0 * ball.radius).max(0.0) * 0.5,
        (ch - 2.0 * ball.radius).max(0.0) * 0.5,
    );
    (0..count)
        .map(|i| {
            let (c, r) = (i % cols, i / cols);
            let centre = Vec2::new(-b.x + (c as f64 + 0.5) * cw, -b.y + (r as f64 + 0.5) * ch);
            let jitter = Vec2::new(
                rng.random_range(-1.0..=1.0) * jx,
                rng.random_range(-1.0..=1.0) * jy,
            );
            let v = Vec2::from_angle(rng.random_range(0.0..std::f64::consts::TAU))
                * (max_speed * rng.random::<f64>());
            BallSetup::moving((i % 16) as u8, centre + jitter, v)
        })
        .collect()
}

/// A benchmark scene: `n` balls moving without friction (up to 2 m/s) on a table scaled so the
/// density stays that of 16 balls on the 8-ft table, with pockets too small to swallow
/// anything, so every event is a collision and the scene never comes to rest.
pub fn frictionless_gas(n: usize) -> (Table, crate::params::Params, Vec<BallSetup>) {
    let k = (n as f64 / 16.0).sqrt();
    let table = Table {
        corner_mouth: 1e-6,
        side_mouth: 1e-6,
        ..Table::scaled(k)
    };
    let model = crate::params::PaperModel {
        mu_slide: 0.0,
        mu_roll: 0.0,
        ..Default::default()
    };
    let params = crate::params::Params {
        model: crate::params::Model::Paper(model),
        ..Default::default()
    };
    let balls = scattered(&table, &params.ball, n, 2.0, 7);
    (table, params, balls)
}
