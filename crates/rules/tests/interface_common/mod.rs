//! What the tests of the one game interface share: the table by number, a ball's id, a
//! place for the cue ball in hand that the rules accept.

use billiards_physics::{Simulation, Vec2};
use billiards_rules::GameRules;

/// Every ball on the table by number.
pub fn layout_of(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}

/// The solver's id of ball `number`.
pub fn id_of(sim: &Simulation, number: u8) -> usize {
    sim.numbers().iter().position(|&n| n == number).unwrap()
}

/// A place for the cue ball in hand that the rules accept, scanning the table (not every
/// test file that shares this module places a ball in hand).
#[allow(dead_code)]
pub fn hand_place(game: &dyn GameRules, sim: &Simulation, cue: u8) -> Vec2 {
    let others: Vec<(u8, Vec2)> = layout_of(sim)
        .into_iter()
        .filter(|&(n, _)| n != cue)
        .collect();
    let table = game.table();
    let (nx, ny) = (40, 20);
    for i in 0..nx {
        for j in 0..ny {
            let at = Vec2::new(
                (i as f64 / nx as f64 - 0.5) * table.length,
                (j as f64 / ny as f64 - 0.5) * table.width,
            );
            if game.check_hand(at, &others).is_ok() {
                return at;
            }
        }
    }
    panic!("no place for the cue ball in hand on the whole table");
}
