//! A match: two players, a race to N racks, the break alternating between racks.
//!
//! The WPA leaves the break order to the event (alternate break or winner breaks, Rules of
//! Play 2.1 / 3.1 "Determining the Break" and the Regulations); alternate break is used here,
//! the usual format of WPA events.

use crate::game::{Call, Choice, Game, GameState, NextShot, Outcome, RuleError, Seat, Verdict};
use crate::shot::ShotSummary;
use serde::{Deserialize, Serialize};

/// A match between two players.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Match {
    /// The game played.
    pub game: Game,
    /// The players' names, by [`Seat::index`].
    pub players: [String; 2],
    /// Racks needed to win the match.
    pub race_to: u32,
    /// Racks won, by [`Seat::index`].
    pub score: [u32; 2],
    /// The rack in play.
    pub rack: GameState,
}

impl Match {
    /// A match whose first rack `first_breaker` breaks.
    pub fn new(game: Game, players: [String; 2], race_to: u32, first_breaker: Seat) -> Self {
        Self {
            game,
            players,
            race_to: race_to.max(1),
            score: [0; 2],
            rack: GameState::new(game, first_breaker),
        }
    }

    /// The name of `seat`.
    pub fn name(&self, seat: Seat) -> &str {
        &self.players[seat.index()]
    }

    /// The match winner, once a player has `race_to` racks.
    pub fn winner(&self) -> Option<Seat> {
        [Seat::A, Seat::B]
            .into_iter()
            .find(|s| self.score[s.index()] >= self.race_to)
    }

    /// What the next shot of the rack must respect.
    pub fn next(&self) -> &NextShot {
        &self.rack.next
    }

    /// Judges a shot of the rack in play ([`GameState::play`]); a rack won scores a point.
    pub fn play(&mut self, shot: &ShotSummary, call: Call) -> Result<Verdict, RuleError> {
        let verdict = self.rack.play(shot, call)?;
        if let Outcome::GameOver { winner, .. } = verdict.outcome {
            self.score[winner.index()] += 1;
        }
        Ok(verdict)
    }

    /// Takes a choice offered in the rack in play ([`GameState::choose`]).
    pub fn choose(&mut self, choice: Choice) -> Result<NextShot, RuleError> {
        self.rack.choose(choice)
    }

    /// Starts the next rack once the one in play is over, the other player breaking
    /// (alternate break). Refused while the rack is in play or the match is won.
    pub fn next_rack(&mut self) -> Result<&NextShot, RuleError> {
        if self.rack.over.is_none() || self.winner().is_some() {
            return Err(RuleError::GameOver);
        }
        self.rack = GameState::new(self.game, self.rack.breaker.other());
        Ok(&self.rack.next)
    }
}
