//! Racks as at a real table: frozen, but with the small random gaps and offsets a real rack
//! has, from a seed that a recording stores so the rack can be rebuilt exactly.
//!
//! Magnitudes: the balls sit on a lattice of spacing `2R + RACK_GAP` (0.05 mm of slack), and
//! each ball is then moved by up to [`RACK_JITTER`] (0.025 mm, uniform in a disc). Two
//! neighbours are therefore between 0 and 0.1 mm apart, never overlapping (the lattice slack
//! is exactly twice the largest offset). Why: WPA equipment specifications allow ball
//! diameters of 2.25 in ± 0.005 in (± 0.127 mm), so even a perfectly racked set leaves gaps
//! of that order; and a rack racked "tight" by hand leaves gaps thinner than a sheet of paper
//! (0.1 mm). The paper's 1/10 in (2.5 mm) is 25 times more, and a break of it rarely pockets
//! a ball; a perfectly frozen rack is a measure-zero case whose break depends on rounding.
//!
//! Two ways of racking, as players do ([`RackStyle`]): a template (a thin sheet that holds
//! every ball frozen against its neighbours: no gaps at all) or a triangle (racked by hand:
//! the seeded gaps above).
//!
//! Orders: 9-ball (WPA 2.2): the 1 at the apex on the foot spot, the 9 in the centre, the
//! others at random. 8-ball (WPA 3.2): the 8 in the centre of the third row, a solid and a
//! stripe in the two back corners (which one left is random), the other twelve at random.
//! 10-ball (WPA 9.2): a triangle of four rows, the 1 at the apex on the foot spot, the 10 in
//! the middle (the centre of the third row), the others at random.

use billiards_physics::{BallSetup, BallSpec, Table, Vec2};
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// Slack added to the lattice spacing of a rack, metres (0.05 mm).
pub const RACK_GAP: f64 = 0.05e-3;

/// Largest random offset of a racked ball from its lattice point, metres (0.025 mm).
pub const RACK_JITTER: f64 = 0.5 * RACK_GAP;

/// How the balls are racked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RackStyle {
    /// A template rack: every ball frozen to its neighbours (gaps of zero).
    Template,
    /// A triangle racked by hand: gaps of 0 to 0.1 mm from the seed ([`RACK_GAP`]).
    #[default]
    Triangle,
}

impl RackStyle {
    /// Both styles.
    pub const ALL: [RackStyle; 2] = [RackStyle::Template, RackStyle::Triangle];

    /// The lattice slack of this style, metres.
    pub fn gap(self) -> f64 {
        match self {
            RackStyle::Template => 0.0,
            RackStyle::Triangle => RACK_GAP,
        }
    }

    /// Its name on the command line: `template`, `triangle`.
    pub fn name(self) -> &'static str {
        match self {
            RackStyle::Template => "template",
            RackStyle::Triangle => "triangle",
        }
    }
}

impl std::str::FromStr for RackStyle {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        RackStyle::ALL
            .into_iter()
            .find(|r| r.name() == s)
            .ok_or_else(|| format!("rack `{s}`: expected template or triangle"))
    }
}

/// Row sizes of the 9-ball diamond, apex first.
const DIAMOND: [usize; 5] = [1, 2, 3, 2, 1];
/// Row sizes of the 10-ball triangle, apex first.
const TEN_TRIANGLE: [usize; 4] = [1, 2, 3, 4];
/// Row sizes of the 15-ball triangle, apex first.
const TRIANGLE: [usize; 5] = [1, 2, 3, 4, 5];

/// Lattice points of a rack with these rows, apex on the foot spot, spacing `d`; row by row,
/// left (+y) to right.
fn lattice(table: &Table, rows: &[usize], d: f64) -> Vec<Vec2> {
    let apex = table.foot_spot();
    let mut points = Vec::new();
    for (k, &n) in rows.iter().enumerate() {
        let x = apex.x + k as f64 * d * 3f64.sqrt() / 2.0;
        for i in 0..n {
            let y = ((n as f64 - 1.0) / 2.0 - i as f64) * d;
            points.push(Vec2::new(x, apex.y + y));
        }
    }
    points
}

/// Puts `numbers[k]` on lattice point `k`, each moved by a random offset of up to `jitter`;
/// the cue ball (number 0) first, on the head spot.
fn place(
    table: &Table,
    points: &[Vec2],
    numbers: &[u8],
    jitter: f64,
    rng: &mut ChaCha8Rng,
) -> Vec<BallSetup> {
    let mut balls = vec![BallSetup::at(0, table.head_spot())];
    for (&p, &n) in points.iter().zip(numbers) {
        // Uniform in the disc: radius by the square root of a uniform draw.
        let r = jitter * rng.random::<f64>().sqrt();
        let offset = Vec2::from_angle(rng.random_range(0.0..std::f64::consts::TAU)) * r;
        balls.push(BallSetup::at(n, p + offset));
    }
    balls
}

/// A 9-ball rack (WPA 2.2) from `seed`: the cue ball on the head spot, then the nine balls.
pub fn nine_ball(table: &Table, ball: &BallSpec, seed: u64) -> Vec<BallSetup> {
    nine_ball_spaced(table, ball, seed, RACK_GAP)
}

/// [`nine_ball`] with another lattice slack `gap` (metres; offsets up to `gap / 2`), for
/// experiments on how the break depends on the gaps.
pub fn nine_ball_spaced(table: &Table, ball: &BallSpec, seed: u64, gap: f64) -> Vec<BallSetup> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let points = lattice(table, &DIAMOND, 2.0 * ball.radius + gap);
    let mut others: Vec<u8> = (2..=8).collect();
    others.shuffle(&mut rng);
    // Lattice order: apex, row 2 (two), row 3 (three, the centre is index 4), rows 4 and 5.
    let mut numbers = Vec::with_capacity(9);
    numbers.push(1);
    let mut rest = others.into_iter();
    for k in 1..9 {
        numbers.push(if k == 4 {
            9
        } else {
            rest.next().expect("seven")
        });
    }
    place(table, &points, &numbers, 0.5 * gap, &mut rng)
}

/// A 10-ball rack (WPA 9.2) from `seed`: the cue ball on the head spot, then the ten balls.
pub fn ten_ball(table: &Table, ball: &BallSpec, seed: u64) -> Vec<BallSetup> {
    ten_ball_spaced(table, ball, seed, RACK_GAP)
}

/// [`ten_ball`] with another lattice slack `gap` (metres; offsets up to `gap / 2`).
pub fn ten_ball_spaced(table: &Table, ball: &BallSpec, seed: u64, gap: f64) -> Vec<BallSetup> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let points = lattice(table, &TEN_TRIANGLE, 2.0 * ball.radius + gap);
    let mut others: Vec<u8> = (2..=9).collect();
    others.shuffle(&mut rng);
    let mut rest = others.into_iter();
    // Lattice order: apex, row 2 (two), row 3 (three, its centre is index 4: the middle of
    // the triangle, WPA 9.2), row 4 (four).
    let numbers: Vec<u8> = (0..10)
        .map(|k| match k {
            0 => 1,
            4 => 10,
            _ => rest.next().expect("eight"),
        })
        .collect();
    place(table, &points, &numbers, 0.5 * gap, &mut rng)
}

/// An 8-ball rack (WPA 3.2) from `seed`: the cue ball on the head spot, then the fifteen.
pub fn eight_ball(table: &Table, ball: &BallSpec, seed: u64) -> Vec<BallSetup> {
    eight_ball_spaced(table, ball, seed, RACK_GAP)
}

/// [`eight_ball`] with another lattice slack `gap` (metres; offsets up to `gap / 2`).
pub fn eight_ball_spaced(table: &Table, ball: &BallSpec, seed: u64, gap: f64) -> Vec<BallSetup> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let points = lattice(table, &TRIANGLE, 2.0 * ball.radius + gap);
    let mut solids: Vec<u8> = (1..=7).collect();
    let mut stripes: Vec<u8> = (9..=15).collect();
    solids.shuffle(&mut rng);
    stripes.shuffle(&mut rng);
    let (solid, stripe) = (solids.pop().expect("7"), stripes.pop().expect("7"));
    let mut corners = [solid, stripe];
    if rng.random::<bool>() {
        corners.swap(0, 1);
    }
    let mut rest: Vec<u8> = solids.into_iter().chain(stripes).collect();
    rest.shuffle(&mut rng);
    let mut rest = rest.into_iter();
    // Lattice order: index 4 is the centre of row 3; 10 and 14 are the back corners.
    let numbers: Vec<u8> = (0..15)
        .map(|k| match k {
            4 => 8,
            10 => corners[0],
            14 => corners[1],
            _ => rest.next().expect("twelve"),
        })
        .collect();
    place(table, &points, &numbers, 0.5 * gap, &mut rng)
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::{Params, Simulation};

    fn check(balls: &[BallSetup], r: f64) {
        // The solver's own placement check.
        Simulation::new(Table::wpa_8ft(), Params::default(), balls).expect("valid rack");
        // Neighbours (centres within 2R + 0.2 mm) are 0 to 0.1 mm apart.
        let mut neighbours = 0;
        for (i, a) in balls.iter().enumerate().skip(1) {
            for b in &balls[i + 1..] {
                let gap = (a.position - b.position).length() - 2.0 * r;
                if gap < 0.2e-3 {
                    neighbours += 1;
                    assert!(
                        (-1e-12..=2.0 * RACK_GAP + 1e-12).contains(&gap),
                        "gap {gap}"
                    );
                }
            }
        }
        assert!(neighbours > 0);
    }

    #[test]
    fn wpa_2_2_nine_ball_rack_has_the_1_on_the_spot_and_the_9_in_the_centre() {
        let (table, spec) = (Table::wpa_8ft(), BallSpec::default());
        for seed in 0..50 {
            let balls = nine_ball(&table, &spec, seed);
            assert_eq!(balls.len(), 10);
            assert_eq!(balls[0].number, 0);
            assert_eq!(balls[1].number, 1);
            assert!((balls[1].position - table.foot_spot()).length() <= RACK_JITTER + 1e-15);
            // The 9 is the ball nearest the diamond's centre (two rows behind the apex).
            let centre = table.foot_spot()
                + Vec2::new(
                    2.0 * (2.0 * spec.radius + RACK_GAP) * 3f64.sqrt() / 2.0,
                    0.0,
                );
            assert_eq!(balls[5].number, 9);
            assert!((balls[5].position - centre).length() <= RACK_JITTER + 1e-15);
            let mut numbers: Vec<u8> = balls.iter().map(|b| b.number).collect();
            numbers.sort_unstable();
            assert_eq!(numbers, (0..=9).collect::<Vec<u8>>());
            check(&balls, spec.radius);
        }
    }

    #[test]
    fn wpa_9_2_ten_ball_rack_has_the_1_on_the_spot_and_the_10_in_the_middle() {
        let (table, spec) = (Table::wpa_9ft(), BallSpec::default());
        let mut second_row_two = 0;
        for seed in 0..50 {
            let balls = ten_ball(&table, &spec, seed);
            assert_eq!(balls.len(), 11);
            assert_eq!(balls[0].number, 0);
            assert_eq!(balls[1].number, 1);
            assert!((balls[1].position - table.foot_spot()).length() <= RACK_JITTER + 1e-15);
            // The 10 in the centre of the third row, two rows behind the apex on the axis.
            let centre = table.foot_spot()
                + Vec2::new(
                    2.0 * (2.0 * spec.radius + RACK_GAP) * 3f64.sqrt() / 2.0,
                    0.0,
                );
            assert_eq!(balls[5].number, 10);
            assert!((balls[5].position - centre).length() <= RACK_JITTER + 1e-15);
            // Four rows: the back row is three rows behind the apex.
            let back = balls
                .iter()
                .skip(1)
                .map(|b| b.position.x)
                .fold(f64::MIN, f64::max);
            let rows =
                (back - table.foot_spot().x) / ((2.0 * spec.radius + RACK_GAP) * 3f64.sqrt() / 2.0);
            assert!((rows - 3.0).abs() < 1e-3, "{rows} rows behind the apex");
            let mut numbers: Vec<u8> = balls.iter().map(|b| b.number).collect();
            numbers.sort_unstable();
            assert_eq!(numbers, (0..=10).collect::<Vec<u8>>());
            second_row_two += usize::from(balls[2].number == 2);
            check(&balls, spec.radius);
        }
        // The others are placed at random: the 2 is not always in the same place.
        assert!((1..50).contains(&second_row_two), "{second_row_two}");
        assert_eq!(ten_ball(&table, &spec, 7), ten_ball(&table, &spec, 7));
        assert_ne!(ten_ball(&table, &spec, 7), ten_ball(&table, &spec, 8));
    }

    #[test]
    fn wpa_3_2_eight_ball_rack_has_the_8_in_the_centre_and_mixed_back_corners() {
        let (table, spec) = (Table::wpa_8ft(), BallSpec::default());
        let mut left_solid = 0;
        for seed in 0..50 {
            let balls = eight_ball(&table, &spec, seed);
            assert_eq!(balls.len(), 16);
            assert_eq!(balls[5].number, 8, "the 8 in the centre of row 3");
            let (a, b) = (balls[11].number, balls[15].number);
            let solid = |n: u8| (1..=7).contains(&n);
            let stripe = |n: u8| (9..=15).contains(&n);
            assert!(
                (solid(a) && stripe(b)) || (stripe(a) && solid(b)),
                "{a} {b}"
            );
            left_solid += usize::from(solid(a));
            let mut numbers: Vec<u8> = balls.iter().map(|b| b.number).collect();
            numbers.sort_unstable();
            assert_eq!(numbers, (0..=15).collect::<Vec<u8>>());
            check(&balls, spec.radius);
        }
        assert!(
            (10..=40).contains(&left_solid),
            "the solid's side is random"
        );
    }

    #[test]
    fn a_template_rack_is_frozen_and_a_triangle_has_small_gaps() {
        let (table, spec) = (Table::wpa_9ft(), BallSpec::default());
        let gaps = |balls: &[BallSetup]| -> Vec<f64> {
            let mut g = Vec::new();
            for (i, a) in balls.iter().enumerate().skip(1) {
                for b in &balls[i + 1..] {
                    let gap = (a.position - b.position).length() - 2.0 * spec.radius;
                    if gap < 0.2e-3 {
                        g.push(gap);
                    }
                }
            }
            g
        };
        let t = nine_ball_spaced(&table, &spec, 3, RackStyle::Template.gap());
        Simulation::new(table, Params::default(), &t).expect("valid rack");
        assert!(gaps(&t).iter().all(|g| g.abs() < 1e-15), "{:?}", gaps(&t));
        assert_eq!(gaps(&t).len(), 16, "the diamond's 16 touching pairs");
        let h = nine_ball_spaced(&table, &spec, 3, RackStyle::Triangle.gap());
        assert!(gaps(&h).iter().any(|&g| g > 1e-6));
        assert_eq!("template".parse::<RackStyle>(), Ok(RackStyle::Template));
        assert!(
            "loose"
                .parse::<RackStyle>()
                .unwrap_err()
                .contains("expected")
        );
        // On the 9-ft table the apex is on its foot spot.
        assert_eq!(t[1].position, table.foot_spot());
    }

    #[test]
    fn a_rack_is_reproduced_by_its_seed_and_differs_between_seeds() {
        let (table, spec) = (Table::wpa_8ft(), BallSpec::default());
        assert_eq!(nine_ball(&table, &spec, 7), nine_ball(&table, &spec, 7));
        assert_eq!(eight_ball(&table, &spec, 7), eight_ball(&table, &spec, 7));
        assert_ne!(nine_ball(&table, &spec, 7), nine_ball(&table, &spec, 8));
        assert_ne!(eight_ball(&table, &spec, 7), eight_ball(&table, &spec, 8));
    }
}
