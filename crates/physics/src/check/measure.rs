//! The quantities the invariants bound: kinetic energy, how far a ball is off the table, the
//! deepest overlap of two balls.

use crate::ball::{BallId, BallState};
use crate::math::Vec2;
use crate::table::{Cushion, PocketShape, Table};

/// Kinetic energy of the balls in play, translational plus rotational (solid spheres,
/// `I = 2/5 m R^2`), joules.
pub fn kinetic_energy(states: &[BallState], mass: f64, radius: f64) -> f64 {
    let inertia = 0.4 * mass * radius * radius;
    states
        .iter()
        .filter(|s| s.motion.on_table())
        .map(|s| {
            let w = s.angular_velocity;
            0.5 * mass * s.velocity.length_squared() + 0.5 * inertia * w.dot(w)
        })
        .sum()
}

/// How far (metres) a ball centred at `p` is where no ball in play may be; zero or negative
/// when it is fine. Inside the cushion lines (`Table::centre_bounds`) everywhere; on a table
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

/// The deepest overlap among the balls in play (pair and depth), if any pair is closer than
/// `2 radius`. Sweeps along x, so large layouts stay fast.
pub fn deepest_overlap(states: &[BallState], radius: f64) -> Option<(BallId, BallId, f64)> {
    let mut order: Vec<BallId> = (0..states.len())
        .filter(|&i| states[i].motion.on_table())
        .collect();
    order.sort_by(|&i, &j| states[i].position.x.total_cmp(&states[j].position.x));
    let contact = 2.0 * radius;
    let mut worst: Option<(BallId, BallId, f64)> = None;
    for (k, &i) in order.iter().enumerate() {
        let pi = states[i].position;
        for &j in &order[k + 1..] {
            let pj = states[j].position;
            if pj.x - pi.x >= contact {
                break;
            }
            let depth = contact - (pj - pi).length();
            if depth > 0.0 && worst.is_none_or(|w| depth > w.2) {
                worst = Some((i.min(j), i.max(j), depth));
            }
        }
    }
    worst
}
