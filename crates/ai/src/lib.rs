//! The computer opponent, pure Rust (no Bevy): the game and `billiards-cli tournament` call
//! [`decide`] with the rules' state and the table at rest and get back what the rules ask
//! for next: a choice ([`Decision::Choose`]) or a shot with its call and, with the cue ball
//! in hand, its place ([`Decision::Shoot`]).
//!
//! How it decides (modules in order):
//! - [`candidates`]: ghost-ball shots of every legal ball into every pocket, one-rail banks,
//!   one-rail kicks, combinations with a legal first ball; each in several speeds and tips;
//! - [`position`]: an analytic success probability of an aim (ranks the aims, and values the
//!   position a shot leaves, one ply);
//! - [`evaluate`]: every candidate simulated N times under execution noise ([`noise`]) and
//!   judged by the rules, the best few refined with more samples; safeties (and push outs)
//!   when nothing scores;
//! - [`placement`]: ball in hand, by the same search from the best few places;
//! - [`twoply`]: the best few shots valued two plies deep, by a search of the next shot
//!   from their noisy outcomes;
//! - [`jump`]: with every legal ball hidden, jump pots and safeties over the blocker (hard
//!   and up), sampled like every other candidate;
//! - [`drill`]: the computer at a drill, by the rules' search or one scored by the drill;
//! - [`level`]: skill levels (noise and budget); [`greedy`]: a baseline without simulation;
//! - [`any_game`]: the computer at any game through the one game interface
//!   ([`billiards_rules::GameRules`]): one search, valued from the rules' judgements, run
//!   by the skeleton pool and snooker share ([`rounds::find`]);
//!   [`any_match`]: a whole match of any game between two players, the one loop every
//!   tournament and game between computers runs; [`match_record`]: such a match between
//!   players by index, opener alternating, its figures by player;
//! - [`snooker`]: the computer at snooker ([`decide_snooker`]), the same search judged by the
//!   WPBSA rules and valued in points, and a whole frame between two levels. Three-cushion
//!   (and every game added through the interface) is played by [`any_game`];
//! - [`game`]: the decision by the game's own search ([`game::decide_game`]); [`words`]: it
//!   in the game's words, through the interface.
//!
//! The same seed gives the same decision on any number of threads: every random draw comes
//! from a stream named by the seed, the candidate's index and the sample's ([`noise::stream`]).
//!
//! Running a [`Plan`] (as the game and the tournament do): spot any balls
//! [`billiards_rules::NextShot::spot`] names, then call [`decide`]; put the cue ball at
//! [`Plan::place`] if any (`Simulation::place`), strike the cue ball with
//! [`Plan::executed`] (the shot with the player's execution noise), run to rest, summarise
//! the events (`billiards_rules::summarise`) and pass them with `plan.call`
//! ([`Called::call`]) to `GameState::play`. A [`Decision::Choose`] goes to `GameState::choose`.

pub mod any_game;
pub mod any_match;
pub mod candidates;
pub mod drill;
pub mod evaluate;
pub mod game;
pub mod greedy;
pub mod jump;
pub mod level;
pub mod match_record;
pub mod noise;
pub mod placement;
pub mod plan;
pub mod play;
pub mod position;
pub mod quiet;
pub mod rounds;
mod search;
pub mod snooker;
pub mod twoply;
pub mod words;

pub use candidates::{Candidate, Layout, ShotKind};
pub use evaluate::{Mode, Stats};
pub use level::{Breaks, Budget, Jumps, Level, TwoPly, UnknownLevel};
pub use noise::Noise;
pub use plan::{Called, Decision, Plan};
pub use search::{decide, decide_planned, decide_with};
pub use snooker::{SnookerDecision, SnookerPlan, decide_snooker};

use billiards_physics::Simulation;
use billiards_rules::{GameState, NextShot};
use std::fmt;
use std::str::FromStr;

/// Why no decision can be made.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AiError {
    /// The game is over.
    #[error("the game is over")]
    GameOver,
    /// Balls are still moving.
    #[error("the balls are not at rest")]
    NotAtRest,
    /// The table has no cue ball (number 0).
    #[error("there is no cue ball")]
    NoCueBall,
    /// The cue ball is off the table and not in hand.
    #[error("the cue ball is off the table but not in hand")]
    CueBallOff,
    /// Ball in hand, and no legal place for the cue ball.
    #[error("there is no legal place for the cue ball")]
    NoPlace,
    /// No ball the rules allow is on the table.
    #[error("no legal ball is on the table")]
    NoBall,
}

/// The next shot, once the common preconditions hold: the game is on and the balls rest.
pub(crate) fn ready<'a>(state: &'a GameState, sim: &Simulation) -> Result<&'a NextShot, AiError> {
    rounds::at_rest(state.over.is_some(), sim)?;
    Ok(&state.next)
}

/// A player: the computer at a level, or a baseline: greedy, or the one-ply search.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Player {
    /// The search at a level.
    Computer(Level),
    /// [`greedy`]: the ghost-ball player without simulation.
    Greedy,
    /// Hard as it played before the second ply: the whole one-ply search
    /// ([`Level::one_ply`]) with hard's noise; the baseline the two-ply levels are measured
    /// against.
    OnePly,
}

impl Player {
    /// Its decision (the seed only matters to the search).
    pub fn decide(
        self,
        state: &GameState,
        sim: &Simulation,
        seed: u64,
    ) -> Result<Decision, AiError> {
        match self {
            Player::Computer(level) => decide(state, sim, level, seed),
            Player::Greedy => greedy::decide(state, sim),
            Player::OnePly => {
                let noise = Level::Hard.planning_noise();
                decide_planned(state, sim, noise, &Level::one_ply(), seed, Mode::Lean)
            }
        }
    }

    /// The noise on its shots: the baselines' hand is the reference one, as hard's, so they
    /// differ from hard in their choices only.
    pub fn execution_noise(self) -> Noise {
        match self {
            Player::Computer(level) => level.execution_noise(),
            Player::Greedy | Player::OnePly => Noise::REFERENCE,
        }
    }
}

impl fmt::Display for Player {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Player::Computer(level) => level.fmt(f),
            Player::Greedy => f.write_str("greedy"),
            Player::OnePly => f.write_str("one-ply"),
        }
    }
}

/// A name that is not a player.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown player {0:?}: expected easy, medium, hard, expert, perfect, greedy or one-ply")]
pub struct UnknownPlayer(pub String);

impl FromStr for Player {
    type Err = UnknownPlayer;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "greedy" => Ok(Player::Greedy),
            "one-ply" => Ok(Player::OnePly),
            _ => s
                .parse()
                .map(Player::Computer)
                .map_err(|_| UnknownPlayer(s.to_string())),
        }
    }
}
