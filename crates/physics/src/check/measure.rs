//! The quantities the invariants bound: kinetic energy, how far a ball is off the table
//! ([`outside_by`], which [`crate::bounds`] owns), the deepest overlap of two balls.

pub use crate::bounds::outside_by;

use crate::ball::{BallId, BallState};

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

/// Energy of the balls in the air beyond their kinetic energy in the plane, joules: the
/// vertical motion's `m v_z^2 / 2` and the height's `m g h` (0 for every ball on the cloth).
pub fn flight_energy(states: &[BallState], mass: f64, gravity: f64) -> f64 {
    states
        .iter()
        .filter(|s| s.motion.on_table())
        .map(|s| mass * (0.5 * s.vertical * s.vertical + gravity * s.height))
        .sum()
}

/// The deepest overlap among the balls in play (pair and depth), if any pair is closer than
/// `2 radius` in space (a ball in the air may pass over another). Sweeps along x, so large
/// layouts stay fast.
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
            let dz = states[j].height - states[i].height;
            let d = pj - pi;
            let depth = contact - (d.length_squared() + dz * dz).sqrt();
            if depth > 0.0 && worst.is_none_or(|w| depth > w.2) {
                worst = Some((i.min(j), i.max(j), depth));
            }
        }
    }
    worst
}
