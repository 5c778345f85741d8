//! The snooker table's marks and the starting layout of its 22 balls.
//!
//! Source: WPBSA, "Official Rules of the Games of Snooker and English Billiards", revised
//! November 2019, Section 1 (Equipment): 1.1 the standard table (playing area, baulk-line,
//! the "D", the spots), 1.2 the balls; Section 3 rule 2 (position of balls).
//!
//! Coordinates as everywhere in the crate: the bottom (baulk) cushion is the head at `-x`, the
//! top cushion the foot at `+x`; left is `+y` looking from baulk to the top.

use crate::ball::BallSetup;
use crate::math::Vec2;
use crate::params::BallSpec;
use crate::table::Table;
use serde::{Deserialize, Serialize};

pub use crate::params::{SNOOKER_BALL_DIAMETER, SNOOKER_BALL_MASS};
pub use crate::table::{SNOOKER_LENGTH, SNOOKER_WIDTH};

/// 1.1(d): the baulk-line, 737 mm from the face of the bottom cushion.
pub const BAULK_LINE: f64 = 0.737;
/// 1.1(e): the radius of the "D", 292 mm.
pub const D_RADIUS: f64 = 0.292;
/// 1.1(f)(i): the black spot, 324 mm from the face of the top cushion.
pub const BLACK_SPOT_FROM_TOP: f64 = 0.324;
/// The gap left between the pink and the apex red ("as close as possible without touching",
/// 3.2(a)), and between neighbouring reds of the triangle: 0.1 mm.
pub const REDS_CLEARANCE: f64 = 1e-4;

/// The cue ball's number (as in every rack of the project).
pub const WHITE: u8 = 0;
/// The reds are numbers 1 to 15.
pub const REDS: std::ops::RangeInclusive<u8> = 1..=15;
/// The yellow's number (value 2).
pub const YELLOW: u8 = 16;
/// The green's number (value 3).
pub const GREEN: u8 = 17;
/// The brown's number (value 4).
pub const BROWN: u8 = 18;
/// The blue's number (value 5).
pub const BLUE: u8 = 19;
/// The pink's number (value 6).
pub const PINK: u8 = 20;
/// The black's number (value 7).
pub const BLACK: u8 = 21;
/// The six colours in the order they are played at the end of a frame (3.3(c)).
pub const COLOURS: [u8; 6] = [YELLOW, GREEN, BROWN, BLUE, PINK, BLACK];

/// The marks of a snooker table (1.1(d)–(f)), measured from its cushion faces.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SnookerMarks {
    /// `x` of the baulk-line.
    pub baulk_x: f64,
    /// Radius of the D.
    pub d_radius: f64,
    /// The yellow spot: the right-hand corner of the D seen from baulk (`-y`).
    pub yellow: Vec2,
    /// The green spot: the left-hand corner of the D (`+y`).
    pub green: Vec2,
    /// The brown spot: the middle of the baulk-line, the centre of the D.
    pub brown: Vec2,
    /// The blue (centre) spot, midway between the faces of the top and bottom cushions.
    pub blue: Vec2,
    /// The pink (pyramid) spot, midway between the centre spot and the top cushion.
    pub pink: Vec2,
    /// The black spot ("the Spot"), 324 mm from the top cushion.
    pub black: Vec2,
}

impl SnookerMarks {
    /// The marks of `table`, at the WPBSA distances from its cushions. An error if the table
    /// is too short for them to keep their order (the black beyond the pink, the baulk-line
    /// below the blue) or too narrow for the D.
    pub fn of(table: &Table) -> Result<Self, String> {
        let (hx, hy) = (0.5 * table.length, 0.5 * table.width);
        let baulk_x = -hx + BAULK_LINE;
        let pink = Vec2::new(0.5 * hx, 0.0);
        let black = Vec2::new(hx - BLACK_SPOT_FROM_TOP, 0.0);
        if !(baulk_x < 0.0 && black.x > pink.x && D_RADIUS < hy) {
            return Err(format!(
                "a {:.3} x {:.3} m table is too small for the snooker marks",
                table.length, table.width
            ));
        }
        Ok(Self {
            baulk_x,
            d_radius: D_RADIUS,
            yellow: Vec2::new(baulk_x, -D_RADIUS),
            green: Vec2::new(baulk_x, D_RADIUS),
            brown: Vec2::new(baulk_x, 0.0),
            blue: Vec2::ZERO,
            pink,
            black,
        })
    }

    /// The pyramid spot (1.1(f)(iii)): the pink spot.
    pub fn pyramid(&self) -> Vec2 {
        self.pink
    }

    /// The spot of colour `n` (`None` for the cue ball and the reds).
    pub fn spot(&self, n: u8) -> Option<Vec2> {
        Some(match n {
            YELLOW => self.yellow,
            GREEN => self.green,
            BROWN => self.brown,
            BLUE => self.blue,
            PINK => self.pink,
            BLACK => self.black,
            _ => return None,
        })
    }

    /// Is `p` in the D (on its lines included)? The cue ball in hand is placed there (3.4).
    pub fn in_d(&self, p: Vec2) -> bool {
        const EPS: f64 = 1e-9;
        p.x <= self.baulk_x + EPS && (p - self.brown).length() <= self.d_radius + EPS
    }
}

/// The 22 balls as a frame starts (3.2): the colours on their spots, the 15 reds in a
/// triangle behind the pink, its apex as close to the pink as possible without touching
/// ([`REDS_CLEARANCE`]) and its back row parallel to the top cushion, and the cue ball at
/// `cue` (an error unless it is in the D and clear of the brown, green and yellow).
pub fn layout(table: &Table, ball: &BallSpec, cue: Vec2) -> Result<Vec<BallSetup>, String> {
    let marks = SnookerMarks::of(table)?;
    if !cue.is_finite() || !marks.in_d(cue) {
        return Err(format!(
            "the cue ball at ({:.3}, {:.3}) is not in the D",
            cue.x, cue.y
        ));
    }
    let r = ball.radius;
    let pitch = 2.0 * r + REDS_CLEARANCE;
    let mut balls = vec![BallSetup::at(WHITE, cue)];
    let apex = marks.pink.x + pitch;
    let mut n = 1;
    for row in 0..5u8 {
        let x = apex + f64::from(row) * pitch * 0.5 * 3f64.sqrt();
        for k in 0..=row {
            let y = (f64::from(k) - 0.5 * f64::from(row)) * pitch;
            balls.push(BallSetup::at(n, Vec2::new(x, y)));
            n += 1;
        }
    }
    let back = apex + 4.0 * pitch * 0.5 * 3f64.sqrt();
    if back + r >= marks.black.x - r {
        return Err("the reds do not fit between the pink and the black".into());
    }
    for c in COLOURS {
        let spot = marks.spot(c).ok_or("colour without a spot")?;
        if (spot - cue).length() < 2.0 * r {
            return Err(format!(
                "the cue ball touches the ball on the spot of colour {c}"
            ));
        }
        balls.push(BallSetup::at(c, spot));
    }
    Ok(balls)
}

/// A default place for the cue ball in the D: between the brown and the yellow spots, on
/// the baulk side, 10 cm behind the baulk-line.
pub fn default_cue_position(marks: &SnookerMarks) -> Vec2 {
    Vec2::new(marks.baulk_x - 0.1, -0.5 * marks.d_radius)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::PocketShape;

    fn p_sign(v: f64) -> f64 {
        if v < 0.0 { -1.0 } else { 1.0 }
    }

    fn start() -> (Table, BallSpec, Vec<BallSetup>) {
        let t = Table::snooker_12ft();
        let b = BallSpec::snooker();
        let m = SnookerMarks::of(&t).unwrap();
        let balls = layout(&t, &b, default_cue_position(&m)).unwrap();
        (t, b, balls)
    }

    #[test]
    fn wpbsa_1_1_table_dimensions_and_marks() {
        let t = Table::snooker_12ft();
        assert_eq!((t.length, t.width), (3.569, 1.778));
        assert!(matches!(t.pockets, PocketShape::Jaws { .. }));
        assert!(
            t.corner_mouth < Table::wpa_9ft().corner_mouth,
            "snooker mouths are narrower"
        );
        let m = SnookerMarks::of(&t).unwrap();
        // Distances from the cushion faces, to the millimetre.
        let mm = |v: f64| (v * 1000.0).round();
        assert_eq!(mm(m.baulk_x + t.length / 2.0), 737.0);
        assert_eq!(mm(t.length / 2.0 - m.black.x), 324.0);
        assert_eq!(mm((m.yellow - m.brown).length()), 292.0);
        assert_eq!(mm((m.green - m.brown).length()), 292.0);
        assert!(
            m.yellow.y < 0.0 && m.green.y > 0.0,
            "yellow on the right seen from baulk"
        );
        assert_eq!(m.blue, Vec2::ZERO);
        assert_eq!(mm(t.length / 2.0 - m.pink.x), mm(m.pink.x));
        assert_eq!(m.pyramid(), m.pink);
        assert!(m.in_d(m.brown) && m.in_d(m.yellow) && !m.in_d(m.blue));
        assert!(
            !m.in_d(m.brown + Vec2::new(0.01, 0.0)),
            "the D is behind the baulk-line"
        );
        let tiny = Table {
            length: 1.0,
            ..Table::wpa_7ft()
        };
        assert!(SnookerMarks::of(&tiny).is_err());
    }

    #[test]
    fn wpbsa_1_2_ball_is_52_5_mm() {
        let b = BallSpec::snooker();
        assert_eq!(2.0 * b.radius, 0.0525);
        assert_eq!(b.mass, 0.142);
        assert!(Table::snooker_12ft().validate(b.radius).is_ok());
    }

    #[test]
    fn wpbsa_3_2_twenty_two_balls_on_the_bed_none_overlapping() {
        let (t, b, balls) = start();
        assert_eq!(balls.len(), 22);
        let mut numbers: Vec<u8> = balls.iter().map(|s| s.number).collect();
        numbers.sort_unstable();
        assert_eq!(numbers, (0..=21).collect::<Vec<u8>>());
        let bound = t.centre_bounds(b.radius);
        for s in &balls {
            assert!(
                s.position.x.abs() < bound.x && s.position.y.abs() < bound.y,
                "{s:?}"
            );
        }
        for (i, p) in balls.iter().enumerate() {
            for q in &balls[i + 1..] {
                let d = (p.position - q.position).length();
                assert!(
                    d > 2.0 * b.radius,
                    "{} and {} overlap: {d}",
                    p.number,
                    q.number
                );
            }
        }
        // The solver accepts the layout.
        assert!(crate::Simulation::new(t, crate::Params::snooker(), &balls).is_ok());
    }

    #[test]
    fn wpbsa_3_2_reds_behind_the_pink_apex_as_close_as_possible() {
        let (t, b, balls) = start();
        let m = SnookerMarks::of(&t).unwrap();
        let reds: Vec<Vec2> = balls
            .iter()
            .filter(|s| REDS.contains(&s.number))
            .map(|s| s.position)
            .collect();
        assert_eq!(reds.len(), 15);
        for p in &reds {
            assert!(p.x > m.pink.x && p.x < m.black.x, "{p:?}");
        }
        let nearest = reds
            .iter()
            .map(|p| (*p - m.pink).length())
            .fold(f64::INFINITY, f64::min);
        let gap = nearest - 2.0 * b.radius;
        assert!(gap > 0.0 && gap <= REDS_CLEARANCE + 1e-12, "apex gap {gap}");
        // The apex on the centre line, the back row of five parallel to the top cushion.
        let back = reds.iter().map(|p| p.x).fold(f64::MIN, f64::max);
        assert_eq!(
            reds.iter().filter(|p| (p.x - back).abs() < 1e-12).count(),
            5
        );
        assert!(
            reds.iter()
                .any(|p| p.y == 0.0 && (p.x - m.pink.x - 2.0 * b.radius) < 1e-3)
        );
    }

    #[test]
    fn wpbsa_3_4_the_cue_ball_must_start_in_the_d() {
        let t = Table::snooker_12ft();
        let b = BallSpec::snooker();
        let m = SnookerMarks::of(&t).unwrap();
        assert!(layout(&t, &b, m.blue).unwrap_err().contains("not in the D"));
        assert!(layout(&t, &b, Vec2::new(f64::NAN, 0.0)).is_err());
        assert!(layout(&t, &b, m.brown).unwrap_err().contains("touches"));
        assert!(layout(&t, &b, m.brown - Vec2::new(0.2, 0.0)).is_ok());
    }

    #[test]
    fn every_snooker_pocket_takes_a_straight_ball_between_its_jaws() {
        use crate::{Motion, Pocket, Shot, Simulation};
        let t = Table::snooker_12ft();
        let params = crate::Params::snooker();
        let (hx, hy, leg) = (t.length / 2.0, t.width / 2.0, t.corner_leg());
        let run = |cue: Vec2, obj: Vec2, dir: Vec2| {
            let balls = [BallSetup::at(0, cue), BallSetup::at(1, obj)];
            let mut sim = Simulation::new(t, params, &balls).unwrap();
            sim.strike(0, Shot::new(dir.angle(), 1.5)).unwrap();
            sim.run_to_rest().unwrap();
            sim.ball(1).motion
        };
        // Straight into every pocket, along the middle of its mouth.
        for p in Pocket::ALL {
            let (mouth, dir) = if p.is_corner() {
                let s = Vec2::new(
                    p_sign(t.pocket_position(p).x),
                    p_sign(t.pocket_position(p).y),
                );
                let m = Vec2::new(s.x * (hx - 0.5 * leg), s.y * (hy - 0.5 * leg));
                (m, s.normalized().unwrap())
            } else {
                let s = p_sign(t.pocket_position(p).y);
                (Vec2::new(0.0, s * hy), Vec2::new(0.0, s))
            };
            let obj = mouth - dir * 0.3;
            assert_eq!(run(obj - dir * 0.4, obj, dir), Motion::Pocketed(p), "{p:?}");
        }
    }
}
