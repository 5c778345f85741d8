//! Where a ball's centre may be on a table: the one measure the setup checks
//! (`sim/setup.rs`) and the invariant monitor ([`crate::check`]) both apply.

use crate::math::Vec2;
use crate::table::{Cushion, PocketShape, Table};

/// How far (metres) a ball centred at `p` is where no ball in play may be; zero or negative
/// when it is fine. Inside the cushion lines ([`Table::centre_bounds`]) everywhere; on a table
/// with jaws also beyond them inside a pocket mouth, on the table side of the pocket's opening
/// and clear of its jaws.
pub fn outside_by(table: &Table, radius: f64, p: Vec2) -> f64 {
    let b = table.centre_bounds(radius);
    let by = (p.x.abs() - b.x).max(p.y.abs() - b.y);
    let PocketShape::Jaws { radius: rho } = table.pockets else {
        return by;
    };
    if by <= 0.0 {
        return by;
    }
    // Beyond a cushion line: only inside a mouth, where that cushion has no nose.
    let beyond = [
        (Cushion::Head, -p.x - b.x),
        (Cushion::Foot, p.x - b.x),
        (Cushion::Left, p.y - b.y),
        (Cushion::Right, -p.y - b.y),
    ];
    let mut worst = f64::NEG_INFINITY;
    for (c, d) in beyond {
        if d > 0.0 {
            match table.pocket_at(c, p) {
                Some(pocket) => {
                    let o = table.openings().into_iter().find(|o| o.pocket == pocket);
                    if let Some(o) = o {
                        worst = worst.max(-(o.offset + o.normal.dot(p)));
                    }
                }
                None => worst = worst.max(d),
            }
        }
    }
    for j in table.jaws() {
        worst = worst.max(radius + rho - (p - j.centre).length());
    }
    worst
}
