//! The three balls of three-cushion and how the solver's ball ids name them.

use super::error::ThreeCushionError;
use crate::turn::Seat;
use billiards_physics::BallId;
use serde::{Deserialize, Serialize};

/// One of the three carom balls.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Ball {
    /// The white: player A's cue ball (UMB 3.3: the player who starts plays with the white).
    White,
    /// The yellow: player B's cue ball.
    Yellow,
    /// The red: an object ball for both.
    Red,
}

/// Ball `n` in words: "white", "yellow", "red" (its [`Ball::index`]), "ball N" beyond.
pub fn word(n: u8) -> String {
    Ball::ALL
        .get(usize::from(n))
        .map_or_else(|| format!("ball {n}"), |b| b.name().to_owned())
}

/// Balls named ("the white", "the red"): those driven off the table.
pub fn list_names(numbers: &[u8]) -> Vec<String> {
    numbers
        .iter()
        .map(|&n| format!("the {}", word(n)))
        .collect()
}

impl Ball {
    /// The three, in the order of [`Ball::index`].
    pub const ALL: [Ball; 3] = [Ball::White, Ball::Yellow, Ball::Red];

    /// 0, 1, 2 for white, yellow, red.
    pub fn index(self) -> usize {
        match self {
            Ball::White => 0,
            Ball::Yellow => 1,
            Ball::Red => 2,
        }
    }

    /// Its name in a sentence: "white", "yellow", "red".
    pub fn name(self) -> &'static str {
        match self {
            Ball::White => "white",
            Ball::Yellow => "yellow",
            Ball::Red => "red",
        }
    }

    /// The cue ball of `seat`: white for A, yellow for B.
    pub fn cue_of(seat: Seat) -> Ball {
        match seat {
            Seat::A => Ball::White,
            Seat::B => Ball::Yellow,
        }
    }

    /// The two object balls of the player whose cue ball this is.
    pub fn objects(self) -> [Ball; 2] {
        match self {
            Ball::White => [Ball::Yellow, Ball::Red],
            Ball::Yellow => [Ball::White, Ball::Red],
            Ball::Red => [Ball::White, Ball::Yellow],
        }
    }
}

/// Which of the solver's ball ids is which ball (three distinct ids).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct BallIds {
    /// The white's id.
    pub white: BallId,
    /// The yellow's id.
    pub yellow: BallId,
    /// The red's id.
    pub red: BallId,
}

impl Default for BallIds {
    /// White 0, yellow 1, red 2: the order of [`crate::three_cushion::ThreeCushionGame::setups`].
    fn default() -> Self {
        Self {
            white: 0,
            yellow: 1,
            red: 2,
        }
    }
}

impl BallIds {
    /// The id of `ball`.
    pub fn id(&self, ball: Ball) -> BallId {
        match ball {
            Ball::White => self.white,
            Ball::Yellow => self.yellow,
            Ball::Red => self.red,
        }
    }

    /// The ball of id `id`, or an error naming the id.
    pub fn ball(&self, id: BallId) -> Result<Ball, ThreeCushionError> {
        Ball::ALL
            .into_iter()
            .find(|&b| self.id(b) == id)
            .ok_or(ThreeCushionError::UnknownBall(id))
    }

    /// An error unless the three ids differ.
    pub fn check(&self) -> Result<(), ThreeCushionError> {
        if self.white == self.yellow || self.white == self.red || self.yellow == self.red {
            return Err(ThreeCushionError::Rules(format!(
                "the three balls need three different ids, got {self:?}"
            )));
        }
        Ok(())
    }
}
