//! The carom table and balls (three-cushion): a match table without pockets and the larger,
//! heavier carom ball.
//!
//! Source: UMB (Union Mondiale de Billard), "World rules of carom billiard" (edition of 1
//! January 1989), Art. 11 (the match billiard: playing surface 2.84 x 1.42 m between the
//! cushion noses) and Art. 12 (balls: diameter 61 to 61.5 mm, weight 205 to 220 g); the
//! figures are also those of the project's `games.md` reference.
//!
//! Cloth and cushions: the carom table keeps the pool parameters ([`Params::default`]'s
//! friction, ball restitution and cushion model). A heated carom cloth is faster than a pool
//! cloth and a carom cushion livelier; no measurement of either is in the project's
//! references, so none is invented here.

use crate::params::{BallSpec, Params};
use crate::table::{PocketShape, Table};

/// Art. 11: the match billiard's playing surface between the cushion noses, 2.84 m long.
pub const CAROM_LENGTH: f64 = 2.84;
/// Art. 11: 1.42 m wide.
pub const CAROM_WIDTH: f64 = 1.42;
/// Art. 12: the ball's diameter, 61.5 mm (the top of the 61–61.5 mm range).
pub const CAROM_BALL_DIAMETER: f64 = 0.0615;
/// Art. 12: the ball's mass, 210 g (within the 205–220 g range).
pub const CAROM_BALL_MASS: f64 = 0.210;

impl Table {
    /// The carom match table: 2.84 x 1.42 m between the cushion noses, no pockets
    /// ([`PocketShape::Pocketless`], both mouths zero).
    pub fn carom_match() -> Self {
        Self {
            length: CAROM_LENGTH,
            width: CAROM_WIDTH,
            corner_mouth: 0.0,
            side_mouth: 0.0,
            pockets: PocketShape::Pocketless,
        }
    }
}

impl BallSpec {
    /// The carom ball: 61.5 mm, 210 g ([`CAROM_BALL_DIAMETER`], [`CAROM_BALL_MASS`]).
    pub fn carom() -> Self {
        Self {
            radius: 0.5 * CAROM_BALL_DIAMETER,
            mass: CAROM_BALL_MASS,
        }
    }
}

impl Params {
    /// The default physics (pool cloth and cushions, see the module's note) with the carom
    /// ball ([`BallSpec::carom`]).
    pub fn carom() -> Self {
        Self {
            ball: BallSpec::carom(),
            ..Self::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::{Cushion, Pocket};
    use crate::{TableError, Vec2};

    #[test]
    fn the_carom_table_is_valid_and_has_no_pocket_anywhere_on_its_cushions() {
        let t = Table::carom_match();
        t.validate(BallSpec::carom().radius).unwrap();
        assert!(t.jaws().is_empty());
        // Every point of every cushion line, corners and the middle of the long sides (where
        // a pool table has its mouths) included.
        let (hx, hy) = (0.5 * t.length, 0.5 * t.width);
        for k in 0..=100 {
            let f = f64::from(k) / 100.0 * 2.0 - 1.0;
            for (c, p) in [
                (Cushion::Head, Vec2::new(-hx, f * hy)),
                (Cushion::Foot, Vec2::new(hx, f * hy)),
                (Cushion::Left, Vec2::new(f * hx, hy)),
                (Cushion::Right, Vec2::new(f * hx, -hy)),
            ] {
                assert_eq!(t.pocket_at(c, p), None::<Pocket>, "{c:?} at {p:?}");
                assert!(t.on_cushion(c, p));
            }
        }
    }

    #[test]
    fn a_table_without_pockets_refuses_pocket_mouths() {
        let t = Table {
            side_mouth: 0.1,
            ..Table::carom_match()
        };
        let e = t.validate(0.03).unwrap_err();
        assert!(matches!(e, TableError::Inconsistent { .. }), "{e}");
        assert!(e.to_string().contains("side_mouth"), "{e}");
    }
}
