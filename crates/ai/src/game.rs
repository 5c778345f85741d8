//! The computer at a game behind the one interface ([`GameRules`], issue 50), with each
//! game's strongest search: pool's ([`crate::decide`]) and snooker's
//! ([`crate::decide_snooker`]) where the game is one of theirs, the shared search
//! ([`decide_any`]) for every other game. The decision is also given as a [`Move`] of the
//! interface (an option by index, a stroke with its declaration), which is all a caller
//! needs to carry it out.

use crate::any_game::{Move, Stroke, decide_any};
use crate::level::Level;
use crate::snooker::{SnookerDecision, decide_snooker};
use crate::{Decision, Player, decide};
use billiards_physics::Simulation;
use billiards_rules::pool::PoolMatch;
use billiards_rules::snooker::rules::SnookerGame;
use billiards_rules::{Call, Declaration, GameRules};

/// A decision of the search that played the game.
#[derive(Debug, Clone, PartialEq)]
pub enum Decided {
    /// Pool's ([`crate::decide`]).
    Pool(Decision),
    /// Snooker's ([`crate::decide_snooker`]).
    Snooker(SnookerDecision),
    /// The shared search's ([`decide_any`]).
    Any(Move),
}

/// What the computer does next in `game`, by the game's own search.
pub fn decide_game(
    game: &dyn GameRules,
    sim: &Simulation,
    level: Level,
    seed: u64,
) -> Result<Decided, String> {
    if let Some(snooker) = game.as_any().downcast_ref::<SnookerGame>() {
        return decide_snooker(&snooker.frame, sim, level, seed)
            .map(Decided::Snooker)
            .map_err(|e| e.to_string());
    }
    if let Some(pool) = game.as_any().downcast_ref::<PoolMatch>() {
        return decide(pool.rack(), sim, level, seed)
            .map(Decided::Pool)
            .map_err(|e| e.to_string());
    }
    decide_any(game, sim, level, seed).map(Decided::Any)
}

impl Player {
    /// What this player does next in `game`: a computer level by the game's own search
    /// ([`decide_game`]); a baseline (greedy, one-ply) at pool's games only, refused with
    /// why at any other.
    pub fn decide_game(
        self,
        game: &dyn GameRules,
        sim: &Simulation,
        seed: u64,
    ) -> Result<Decided, String> {
        match self {
            Player::Computer(level) => decide_game(game, sim, level, seed),
            Player::Greedy | Player::OnePly => {
                let pool = game.as_any().downcast_ref::<PoolMatch>().ok_or_else(|| {
                    format!("{self} plays pool's games only: {}", levels_only(game))
                })?;
                self.decide(pool.rack(), sim, seed)
                    .map(Decided::Pool)
                    .map_err(|e| e.to_string())
            }
        }
    }

    /// Whether this player plays `game`: every player at pool's games, only the computer's
    /// levels at the others (`Err` says so, in words).
    pub fn plays(self, game: &dyn GameRules) -> Result<(), String> {
        match self {
            Player::Computer(_) => Ok(()),
            _ if game.as_any().is::<PoolMatch>() => Ok(()),
            _ => Err(format!("{self}: {}", levels_only(game))),
        }
    }
}

/// "snooker has computer levels only".
fn levels_only(game: &dyn GameRules) -> String {
    format!(
        "{} has computer levels only (easy, medium, hard, expert, perfect)",
        game.name()
    )
}

impl Decided {
    /// Noisy simulations the search ran, where it counts them (pool's and snooker's).
    pub fn simulations(&self) -> Option<usize> {
        match self {
            Decided::Pool(Decision::Shoot(plan)) => Some(plan.simulations),
            Decided::Snooker(SnookerDecision::Shoot(plan)) => Some(plan.simulations),
            _ => None,
        }
    }

    /// The shot decided on and the cue ball's place in hand; `None` for an option.
    pub fn aim(&self) -> Option<(billiards_physics::Shot, Option<billiards_physics::Vec2>)> {
        match self {
            Decided::Pool(Decision::Shoot(plan)) => Some((plan.shot, plan.place)),
            Decided::Snooker(SnookerDecision::Shoot(plan)) => Some((plan.shot, plan.place)),
            Decided::Any(Move::Strike(stroke)) => Some((stroke.shot, stroke.place)),
            Decided::Pool(Decision::Choose { .. })
            | Decided::Snooker(SnookerDecision::Choose { .. })
            | Decided::Any(Move::Choose(_)) => None,
        }
    }

    /// The decision as a move of the interface in `game` (the game it was decided for): an
    /// option by its index among [`billiards_rules::Turn::choices`], or a stroke with its
    /// declaration. `None` for an option the game no longer offers.
    pub fn as_move(&self, game: &dyn GameRules) -> Option<Move> {
        let index_of = |label: &str| game.turn().choices.iter().position(|c| c == label);
        match self {
            Decided::Any(m) => Some(m.clone()),
            Decided::Pool(Decision::Choose { choice, .. }) => {
                index_of(choice.label()).map(Move::Choose)
            }
            Decided::Snooker(SnookerDecision::Choose { choice, .. }) => {
                let snooker = game.as_any().downcast_ref::<SnookerGame>()?;
                index_of(&snooker.choice_label(*choice)).map(Move::Choose)
            }
            Decided::Pool(Decision::Shoot(plan)) => Some(Move::Strike(Stroke {
                place: plan.place,
                shot: plan.shot,
                declared: declaration_of(plan.call),
                kind: Some(plan.kind),
                value: plan.value,
            })),
            Decided::Snooker(SnookerDecision::Shoot(plan)) => Some(Move::Strike(Stroke {
                place: plan.place,
                shot: plan.shot,
                declared: plan
                    .nominated
                    .map_or(Declaration::None, |ball| Declaration::Nominate { ball }),
                kind: Some(plan.kind),
                value: plan.value,
            })),
        }
    }
}

/// Pool's call as the interface's declaration.
pub fn declaration_of(call: Call) -> Declaration {
    match call {
        Call::None => Declaration::None,
        Call::Ball { ball, pocket } => Declaration::Pocket { ball, pocket },
        Call::Safety => Declaration::Safety,
        Call::PushOut => Declaration::PushOut,
    }
}
