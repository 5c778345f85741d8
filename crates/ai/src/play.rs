//! A whole rack between two players, headless: what `billiards-cli tournament` runs on every
//! core, and what the tests and examples use to watch the players at work.
//!
//! The table is the game's (WPA 8-ft, jaws of 15 mm, the spin model) or another [`Venue`];
//! each rack comes from the game's seed ([`billiards_rules::Game::rack_styled`]); every shot is the player's decision
//! struck with its execution noise, run to rest without a history, summarised and judged.

use crate::noise::Noise;
use crate::noise::stream;
use crate::{Decision, Plan, Player};
use billiards_physics::{Model, Params, Simulation, SpinModel, Table, TableChoice, Vec2, Vec3};
use billiards_rules::{
    CUE, Game, GameState, Outcome, RackStyle, Seat, ShotSummary, object_ball_spot,
};
use rand::Rng;
use serde::{Deserialize, Serialize};
use std::time::Instant;

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

/// A fresh rack of `game` from `seed` at `venue`, without a history.
fn rack(venue: Venue, game: Game, seed: u64) -> Result<Simulation, String> {
    let (table, params) = table_and_params_on(venue.table);
    let balls = game.rack_styled(&table, &params.ball, seed, venue.rack);
    let mut sim = Simulation::new(table, params, &balls).map_err(|e| e.to_string())?;
    sim.set_record_history(false);
    Ok(sim)
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

/// [`play_rack`] at `venue`.
pub fn play_rack_at(
    venue: Venue,
    game: Game,
    players: [Player; 2],
    index: u64,
    seed: u64,
    breaker: usize,
) -> Result<RackRecord, String> {
    let seat = |i: usize| if i == 0 { Seat::A } else { Seat::B };
    let mut racks = 0u64;
    let mut sim = rack(venue, game, stream(seed, 0, racks).random())?;
    let mut state = GameState::new(game, seat(breaker));
    let mut tally: [Tally; 2] = Default::default();
    let (mut shots, mut last, mut opponent_shot) = (0, None, false);
    let mut breaker_now = seat(breaker);
    while state.over.is_none() && shots < MAX_SHOTS {
        let next = state.next.clone();
        if next.rerack {
            racks += 1;
            sim = rack(venue, game, stream(seed, 0, racks).random())?;
            state.next.rerack = false;
            breaker_now = next.shooter;
            opponent_shot = false;
        }
        spot_balls(&mut sim, &next.spot)?;
        state.next.spot.clear();
        let who = next.shooter.index();
        let player = players[who];
        let started = Instant::now();
        let decision = player
            .decide(&state, &sim, stream(seed, 1, shots as u64).random())
            .map_err(|e| format!("shot {shots}: {player}: {e}"))?;
        let secs = started.elapsed().as_secs_f64();
        let t = &mut tally[who];
        t.decisions += 1;
        t.decision_secs += secs;
        t.max_decision_secs = t.max_decision_secs.max(secs);
        let plan = match decision {
            Decision::Choose { choice, .. } => {
                state.choose(choice).map_err(|e| e.to_string())?;
                continue;
            }
            Decision::Shoot(plan) => plan,
        };
        t.simulations += plan.simulations;
        if last != Some(who) {
            t.innings += 1;
            last = Some(who);
        }
        if next.shooter != breaker_now {
            opponent_shot = true;
        }
        let summary = execute(
            &mut sim,
            &plan,
            player.execution_noise(),
            stream(seed, 2, shots as u64).random(),
        )?;
        let verdict = state.play(&summary, plan.call).map_err(|e| e.to_string())?;
        shots += 1;
        t.shots += 1;
        t.pocketed += summary.pocketed_object_balls().count();
        t.fouls += usize::from(!verdict.legal());
        if verdict.outcome != Outcome::Continues {
            last = None;
        }
    }
    let winner = state.over.map(|(w, _)| w.index());
    Ok(RackRecord {
        index,
        seed,
        breaker,
        winner,
        break_and_run: winner.is_some() && winner == Some(breaker_now.index()) && !opponent_shot,
        shots,
        reason: match state.over {
            Some((_, why)) => why.to_string(),
            None => format!("no winner after {MAX_SHOTS} shots"),
        },
        players: tally,
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
