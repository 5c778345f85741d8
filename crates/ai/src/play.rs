//! A whole rack between two players, headless: what `billiards-cli tournament` runs on every
//! core, and what the tests and examples use to watch the players at work.
//!
//! The table is the game's (WPA 8-ft, jaws of 15 mm, the spin model) or another [`Venue`];
//! each rack comes from the game's seed ([`billiards_rules::Game::rack_styled`]); the rack
//! is played through the one game interface by the match loop every game shares
//! ([`crate::any_match`]), and its figures read from it.

use crate::any_match::{Seating, play_match};
use crate::noise::Noise;
use crate::noise::stream;
use crate::{Plan, Player};
use billiards_physics::{Model, Params, Simulation, SpinModel, Table, TableChoice, Vec2, Vec3};
use billiards_rules::pool::PoolMatch;
use billiards_rules::{CUE, Game, RackStyle, Seat, ShotSummary, object_ball_spot};
use rand::Rng;
use serde::{Deserialize, Serialize};

/// Most shots a rack may take before it is given up as a draw.
pub const MAX_SHOTS: usize = 400;

/// One player's figures in one rack.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Tally {
    /// Visits to the table (a turn: from taking the table to leaving it).
    pub innings: usize,
    /// Object balls pocketed on the player's shots.
    pub pocketed: usize,
    /// Shots played.
    pub shots: usize,
    /// Fouls.
    pub fouls: usize,
    /// Decisions taken (shots and choices).
    pub decisions: usize,
    /// Seconds spent deciding, in all.
    pub decision_secs: f64,
    /// The longest decision, seconds.
    pub max_decision_secs: f64,
    /// Noisy simulations the decisions ran.
    pub simulations: usize,
}

/// The record of one rack.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RackRecord {
    /// The game's index in its tournament.
    pub index: u64,
    /// The seed of its rack and of every random draw in it.
    pub seed: u64,
    /// Who broke, 0 or 1 (by the order of the players).
    pub breaker: usize,
    /// The winner, 0 or 1; `None`: a draw after [`MAX_SHOTS`] shots.
    pub winner: Option<usize>,
    /// The breaker won without the other player taking a shot.
    pub break_and_run: bool,
    /// Shots played.
    pub shots: usize,
    /// Why the game ended.
    pub reason: String,
    /// Each player's figures.
    pub players: [Tally; 2],
}

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

/// Plays one rack of `game` between `players` (`players[0]` is seat A), `breaker` breaking,
/// every random draw from `seed`, on the game's default table. Re-racks (8-ball break
/// options) start a new rack in the same record.
pub fn play_rack(
    game: Game,
    players: [Player; 2],
    index: u64,
    seed: u64,
    breaker: usize,
) -> Result<RackRecord, String> {
    play_rack_at(Venue::default(), game, players, index, seed, breaker)
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

/// [`play_rack`] at `venue`: one rack of a [`PoolMatch`] race to 1, played by the one
/// match loop of every game ([`play_match`]); player `breaker` sits in seat A (the rules'
/// breaker), and the seats' figures are given back by player. The rack comes from
/// `stream(seed, 0, 0)`, a re-rack (8-ball's break options, WPA 3.3) from the next seed.
pub fn play_rack_at(
    venue: Venue,
    game: Game,
    players: [Player; 2],
    index: u64,
    seed: u64,
    breaker: usize,
) -> Result<RackRecord, String> {
    let (table, params) = table_and_params_on(venue.table);
    // Player `k` sits in seat `seat_of(k)`.
    let seat_of = |k: usize| if k == breaker { 0 } else { 1 };
    let mut seats = [players[0]; 2];
    for k in 0..2 {
        seats[seat_of(k)] = players[k];
    }
    let names = seats.map(|p| p.to_string());
    let mut rack = PoolMatch::new(
        game,
        names,
        1,
        table,
        params.ball,
        stream(seed, 0, 0).random(),
        venue.rack,
    );
    let run = play_match(
        &mut rack,
        &Seating::new(seats, params, seed, MAX_SHOTS),
        &mut |_| {},
    )?;
    let played = run.played.last().ok_or("no rack was played")?;
    let player_of = |seat: Seat| {
        if seat.index() == 0 {
            breaker
        } else {
            1 - breaker
        }
    };
    let tally = |k: usize| {
        let t = &run.tally[seat_of(k)];
        Tally {
            innings: t.visits,
            pocketed: t.pocketed,
            shots: t.strokes,
            fouls: t.fouls,
            decisions: t.decisions,
            decision_secs: t.decision_secs,
            max_decision_secs: t.max_decision_secs,
            simulations: t.simulations,
        }
    };
    Ok(RackRecord {
        index,
        seed,
        breaker,
        winner: run.winner.map(player_of),
        break_and_run: played.run_out,
        shots: run.strokes,
        reason: match run.winner {
            Some(_) => played.reason.clone(),
            None => format!("no winner after {MAX_SHOTS} shots"),
        },
        players: [tally(0), tally(1)],
    })
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
