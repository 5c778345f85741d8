//! Pool's table for the computer's studies and a plan carried out by hand: where racks are
//! played ([`Venue`]: the WPA 8-ft table with 15 mm jaws and the spin model by default), a
//! [`Plan`] struck on a table ([`execute`]) and the balls the rules spot put back
//! ([`spot_balls`]). Whole racks between players are matches of the one loop
//! ([`crate::match_record`]), as every game's are.

use crate::Plan;
use crate::noise::Noise;
use billiards_physics::{Model, Params, Simulation, SpinModel, Table, TableChoice, Vec2, Vec3};
use billiards_rules::{CUE, RackStyle, ShotSummary, object_ball_spot};
use serde::{Deserialize, Serialize};

/// Most strokes a rack or a frame may take before it is stopped (then decided on points
/// where the game has them, a draw otherwise).
pub const MAX_SHOTS: usize = 400;

/// Where racks are played: the table and how its racks are racked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Venue {
    /// The table's size and pockets.
    pub table: TableChoice,
    /// Template (frozen) or triangle (small seeded gaps).
    pub rack: RackStyle,
}

/// The solver's table and parameters for the game: the game's defaults.
pub fn table_and_params() -> (Table, Params) {
    table_and_params_on(TableChoice::default())
}

/// [`table_and_params`] on another table (15 mm jaws, the spin model).
pub fn table_and_params_on(table: TableChoice) -> (Table, Params) {
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    (table.table().with_jaws(0.015), params)
}

/// Plays `plan` on `sim` as a player does: the cue ball placed where the plan says, the shot
/// struck with `noise` drawn from `seed`, run to rest and summarised for the rules.
pub fn execute(
    sim: &mut Simulation,
    plan: &Plan,
    noise: Noise,
    seed: u64,
) -> Result<ShotSummary, String> {
    let cue = sim
        .numbers()
        .iter()
        .position(|&n| n == CUE)
        .ok_or("no cue ball")?;
    if let Some(p) = plan.place {
        sim.place(cue, p, Vec2::ZERO, Vec3::ZERO)
            .map_err(|e| format!("place: {e}"))?;
    }
    let shot = plan.executed(noise, sim.params(), seed);
    sim.strike(cue, shot).map_err(|e| format!("strike: {e}"))?;
    let mut summary = ShotSummary::default();
    while let Some(e) = sim.step_event() {
        summary.record(&e.kind, sim.numbers());
    }
    Ok(summary)
}

/// Puts the balls `numbers` back on the table, one after another, where the rules spot them
/// (WPA 1.4, the foot string), as the game does before the shot that asks for it.
pub fn spot_balls(sim: &mut Simulation, numbers: &[u8]) -> Result<(), String> {
    for &n in numbers {
        let id = sim
            .numbers()
            .iter()
            .position(|&m| m == n)
            .ok_or("no ball to spot")?;
        let p = object_ball_spot(sim, id).ok_or("no place to spot a ball")?;
        sim.place(id, p, Vec2::ZERO, Vec3::ZERO)
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}
