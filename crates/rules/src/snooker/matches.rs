//! A match: the best of N frames (2.3), the break alternating between the players.

use super::frame::SnookerError;
use crate::game::Seat;
use serde::{Deserialize, Serialize};

/// A match of the best of `best_of` frames.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SnookerMatch {
    /// Frames to play at most (odd).
    pub best_of: u32,
    /// Frames won by A and B.
    pub frames: [u32; 2],
    /// Who breaks in the first frame.
    pub first_breaker: Seat,
}

impl SnookerMatch {
    /// A match of the best of `best_of` frames (odd, at least 1).
    pub fn new(best_of: u32, first_breaker: Seat) -> Result<Self, SnookerError> {
        if best_of.is_multiple_of(2) {
            return Err(SnookerError::BestOf(best_of));
        }
        Ok(Self {
            best_of,
            frames: [0, 0],
            first_breaker,
        })
    }

    /// Frames needed to win.
    pub fn to_win(&self) -> u32 {
        self.best_of / 2 + 1
    }

    /// The winner, once a player has won a majority of the frames.
    pub fn winner(&self) -> Option<Seat> {
        [Seat::A, Seat::B]
            .into_iter()
            .find(|s| self.frames[s.index()] >= self.to_win())
    }

    /// Who breaks in the next frame: the players take turns.
    pub fn next_breaker(&self) -> Seat {
        if (self.frames[0] + self.frames[1]).is_multiple_of(2) {
            self.first_breaker
        } else {
            self.first_breaker.other()
        }
    }

    /// Records a frame won by `winner`; returns the match's winner once decided.
    pub fn record(&mut self, winner: Seat) -> Result<Option<Seat>, SnookerError> {
        if self.winner().is_some() {
            return Err(SnookerError::Over);
        }
        self.frames[winner.index()] += 1;
        Ok(self.winner())
    }
}
