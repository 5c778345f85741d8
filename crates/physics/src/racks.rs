//! Standard layouts. Ball 0 is always the cue ball, on the head spot (a quarter of the length
//! from the head cushion, centred: the paper's figure 1).

use crate::ball::BallSetup;
use crate::math::Vec2;
use crate::params::BallSpec;
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

/// `count` balls on a jittered grid filling the table (clear of the cushions), each moving in
/// a random direction at a speed up to `max_speed`; reproducible from `seed`. For benchmarks
/// and stress tests. Numbers repeat every 16 balls (several cue balls). Not checked: where
/// the table's grid cells are narrower than a ball the balls overlap (the simulation then
/// refuses the layout); [`stress`] refuses such a count itself, with the reason.
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

/// The most balls [`stress`] builds: ten times the game's slider, and about 25 M pair checks
/// when the simulation checks the layout.
pub const STRESS_MAX_BALLS: usize = 10_000;

/// Fastest start of a [`stress`] ball, m/s (a firm shot, as in [`frictionless_gas`]).
pub const STRESS_MAX_SPEED: f64 = 2.0;

/// Least clearance between two balls, and between a ball and a cushion, in a [`stress`]
/// layout, metres: balls start apart, not in resting contact.
pub const STRESS_CLEARANCE: f64 = 1e-3;

/// What [`stress`] builds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StressSpec {
    /// Balls on the table, the cue ball included (1 to [`STRESS_MAX_BALLS`]).
    pub balls: usize,
    /// The paper's cloth friction (the balls come to rest) or none (they never do).
    pub friction: bool,
    /// Seed of the positions and velocities.
    pub seed: u64,
    /// Length and width of the table as a multiple of the 8-ft table's; `None`: as large as
    /// keeps the density of 16 balls on the 8-ft table ([`stress_scale`]).
    pub scale: Option<f64>,
}

/// A stress scene: a table, the parameters and the balls, ready for `Simulation::new`.
#[derive(Clone, Debug, PartialEq)]
pub struct StressScene {
    /// The table: the 8-ft table scaled, with pockets closed (mouths of 1 µm), so the count
    /// stays what was asked and every event is a collision or a slow-down.
    pub table: Table,
    /// The paper's model, with its friction or without.
    pub params: crate::params::Params,
    /// Ball 0 is the cue ball; the others are numbered 1 to 15 over and over.
    pub balls: Vec<BallSetup>,
}

/// Why [`stress`] refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StressError {
    /// No balls asked for.
    #[error("a stress scene needs at least 1 ball, got 0")]
    NoBalls,
    /// More than [`STRESS_MAX_BALLS`].
    #[error("{count} balls is more than the stress scene's maximum of {max}")]
    TooMany {
        /// The count asked for.
        count: usize,
        /// [`STRESS_MAX_BALLS`].
        max: usize,
    },
    /// The scale is not a positive finite number, or makes the table too small for its pockets.
    #[error("table scale {0} must be a finite number from 0.1 to 100 (1 is the 8-ft table)")]
    BadScale(f64),
    /// The table cannot hold the balls apart.
    #[error(
        "{count} balls do not fit on a {length:.2} x {width:.2} m table (scale {scale:.2}): \
         it holds at most {fits} apart; choose fewer balls or a larger table"
    )]
    DoesNotFit {
        /// The count asked for.
        count: usize,
        /// The table's length, metres.
        length: f64,
        /// Its width, metres.
        width: f64,
        /// Its scale.
        scale: f64,
        /// How many balls it holds on the stress grid.
        fits: usize,
    },
}

/// The scale of the 8-ft table that holds `balls` at the density of 16 balls on it (never
/// below 1).
pub fn stress_scale(balls: usize) -> f64 {
    (balls as f64 / 16.0).sqrt().max(1.0)
}

/// A seeded stress scene: `spec.balls` balls on a jittered grid over a scaled 8-ft table, at
/// least [`STRESS_CLEARANCE`] apart and from the cushions, each moving in a random direction
/// at up to [`STRESS_MAX_SPEED`]. Refuses (with the reason) a count of 0 or above
/// [`STRESS_MAX_BALLS`], a bad scale, and a table that cannot hold the balls apart.
pub fn stress(spec: &StressSpec) -> Result<StressScene, StressError> {
    let count = spec.balls;
    if count == 0 {
        return Err(StressError::NoBalls);
    }
    if count > STRESS_MAX_BALLS {
        return Err(StressError::TooMany {
            count,
            max: STRESS_MAX_BALLS,
        });
    }
    let scale = spec.scale.unwrap_or_else(|| stress_scale(count));
    if !(scale.is_finite() && (0.1..=100.0).contains(&scale)) {
        return Err(StressError::BadScale(scale));
    }
    let table = Table {
        corner_mouth: 1e-6,
        side_mouth: 1e-6,
        ..Table::scaled(scale)
    };
    let model = if spec.friction {
        crate::params::PaperModel::default()
    } else {
        crate::params::PaperModel {
            mu_slide: 0.0,
            mu_roll: 0.0,
            ..Default::default()
        }
    };
    let params = crate::params::Params {
        model: crate::params::Model::Paper(model),
        ..Default::default()
    };
    let ball = params.ball;
    // Cells of one ball each, at least a diameter and the clearance wide, over the cloth
    // less half the clearance at each cushion: a ball at the edge of an outer cell is then
    // the clearance from the cushion, as from its neighbours.
    let pitch = 2.0 * ball.radius + STRESS_CLEARANCE;
    let (w, h) = (
        table.length - STRESS_CLEARANCE,
        table.width - STRESS_CLEARANCE,
    );
    let (max_cols, max_rows) = ((w / pitch).floor() as usize, (h / pitch).floor() as usize);
    let fits = max_cols * max_rows;
    if count > fits {
        return Err(StressError::DoesNotFit {
            count,
            length: table.length,
            width: table.width,
            scale,
            fits,
        });
    }
    // Cells of the table's aspect where possible, within what fits.
    let mut cols = ((count as f64 * w / h).sqrt().ceil() as usize).clamp(1, max_cols);
    if count.div_ceil(cols) > max_rows {
        cols = count.div_ceil(max_rows);
    }
    let rows = count.div_ceil(cols);
    // Each cell is at least `pitch` each way (checked above); a ball moves in its slack.
    let (cw, ch) = (w / cols as f64, h / rows as f64);
    let (jx, jy) = (0.5 * (cw - pitch), 0.5 * (ch - pitch));
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(spec.seed);
    let balls = (0..count)
        .map(|i| {
            let (c, r) = (i % cols, i / cols);
            let centre = Vec2::new(
                -0.5 * w + (c as f64 + 0.5) * cw,
                -0.5 * h + (r as f64 + 0.5) * ch,
            );
            let jitter = Vec2::new(
                rng.random_range(-1.0..=1.0) * jx,
                rng.random_range(-1.0..=1.0) * jy,
            );
            let v = Vec2::from_angle(rng.random_range(0.0..std::f64::consts::TAU))
                * (STRESS_MAX_SPEED * rng.random::<f64>());
            // One cue ball; the rest 1 to 15 over and over (numbers are looks only here).
            let number = if i == 0 { 0 } else { 1 + ((i - 1) % 15) as u8 };
            BallSetup::moving(number, centre + jitter, v)
        })
        .collect();
    Ok(StressScene {
        table,
        params,
        balls,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::Simulation;

    fn spec(balls: usize, scale: Option<f64>) -> StressSpec {
        StressSpec {
            balls,
            friction: false,
            seed: 3,
            scale,
        }
    }

    /// Every pair at least the clearance apart, every ball the clearance inside the cushions.
    fn assert_apart_and_inside(scene: &StressScene) {
        let r = scene.params.ball.radius;
        let inner = scene.table.centre_bounds(r + STRESS_CLEARANCE);
        let slop = 1e-12;
        for (i, a) in scene.balls.iter().enumerate() {
            let p = a.position;
            assert!(
                p.x.abs() <= inner.x + slop && p.y.abs() <= inner.y + slop,
                "ball {i} at {p:?} is within the clearance of a cushion"
            );
            for b in &scene.balls[i + 1..] {
                let d = (b.position - p).length();
                assert!(d >= 2.0 * r + STRESS_CLEARANCE - slop, "ball {i}: gap {d}");
            }
        }
    }

    #[test]
    fn refuses_no_balls_too_many_and_a_bad_scale() {
        assert_eq!(stress(&spec(0, None)), Err(StressError::NoBalls));
        let too_many = stress(&spec(STRESS_MAX_BALLS + 1, None)).unwrap_err();
        assert!(too_many.to_string().contains("10001 balls is more than"));
        for scale in [0.0, -1.0, f64::NAN, f64::INFINITY, 0.05, 101.0] {
            assert!(matches!(
                stress(&spec(16, Some(scale))),
                Err(StressError::BadScale(_))
            ));
        }
    }

    #[test]
    fn refuses_more_balls_than_the_table_holds_and_fills_it_to_the_limit() {
        let Err(StressError::DoesNotFit { fits, .. }) = stress(&spec(2000, Some(1.0))) else {
            panic!("2000 balls fit on the 8-ft table");
        };
        // The 8-ft table: 2.337 / 0.0582 = 40 columns, 1.168 / 0.0582 = 20 rows.
        assert_eq!(fits, 40 * 20);
        let message = stress(&spec(fits + 1, Some(1.0))).unwrap_err().to_string();
        assert!(message.contains("801 balls do not fit"), "{message}");
        assert!(message.contains("at most 800"), "{message}");
        let full = stress(&spec(fits, Some(1.0))).expect("a full table");
        assert_eq!(full.balls.len(), fits);
        assert_apart_and_inside(&full);
        Simulation::new(full.table, full.params, &full.balls).expect("a valid layout");
    }

    #[test]
    fn many_balls_apart_inside_with_one_cue_ball_and_reproducible() {
        for balls in [1, 16, 17, 1000, 2000] {
            let scene = stress(&spec(balls, None)).expect("fits");
            assert_eq!(scene.balls.len(), balls);
            assert_apart_and_inside(&scene);
            assert_eq!(scene.balls.iter().filter(|b| b.number == 0).count(), 1);
            assert!(scene.balls.iter().all(|b| b.number <= 15));
            assert!(
                (scene.table.length / Table::wpa_8ft().length - stress_scale(balls)).abs() < 1e-12
            );
            Simulation::new(scene.table, scene.params, &scene.balls).expect("a valid layout");
        }
        let a = stress(&spec(500, None)).unwrap();
        assert_eq!(a, stress(&spec(500, None)).unwrap());
        let other = stress(&StressSpec {
            seed: 4,
            ..spec(500, None)
        })
        .unwrap();
        assert_ne!(a.balls, other.balls);
    }

    #[test]
    fn frictionless_keeps_its_energy_friction_takes_it_both_checked() {
        use crate::check::{Monitor, Tolerances};
        for friction in [false, true] {
            let scene = stress(&StressSpec {
                friction,
                ..spec(200, None)
            })
            .unwrap();
            let mut sim = Simulation::new(scene.table, scene.params, &scene.balls).unwrap();
            let mut monitor = Monitor::new(&sim, Tolerances::default()).unwrap();
            let b = scene.params.ball;
            let before =
                crate::check::kinetic_energy(&sim.balls().collect::<Vec<_>>(), b.mass, b.radius);
            let stats = monitor
                .run_until(&mut sim, 3.0)
                .expect("every invariant holds");
            assert!(stats.events > 100, "{} events", stats.events);
            let after =
                crate::check::kinetic_energy(&sim.balls().collect::<Vec<_>>(), b.mass, b.radius);
            // No pockets: nothing leaves. Elastic and frictionless: the energy stays.
            assert!(sim.balls().all(|s| s.motion.on_table()));
            if friction {
                assert!(after < 0.5 * before, "{after} of {before} J left");
            } else {
                assert!(
                    (after - before).abs() < 1e-9 * before,
                    "{before} -> {after} J"
                );
            }
        }
    }
}
