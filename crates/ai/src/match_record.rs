//! A match between two players by index (player 0, player 1), whatever seat each takes:
//! the unit of `billiards-cli tournament` for every game, and of the examples and tests
//! that watch the players at work. The opener sits in seat A (the rules' opener: the
//! breaker, the player who breaks off, carom's first player); the match is played by the one
//! match loop ([`crate::any_match`]) and its figures, read from the interface, are given back
//! by player.

use crate::Player;
use crate::any_match::{MatchRun, SeatTally, Seating, play_match};
use billiards_physics::Params;
use billiards_rules::{GameRules, Seat};
use serde::{Deserialize, Serialize};

/// One match, by player (player 0 is the first of the two).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MatchRecord {
    /// The match's index in its tournament.
    pub index: u64,
    /// The seed of its every draw.
    pub seed: u64,
    /// The player who sat in seat A and opened.
    pub opener: usize,
    /// The winner; `None`: stopped at the stroke limit level on points.
    pub winner: Option<usize>,
    /// Strokes played.
    pub strokes: usize,
    /// Why it ended.
    pub reason: String,
    /// The game's points at the end (pool's racks, snooker's score, carom's points).
    pub points: [u32; 2],
    /// Games each player opened (breaks, break-offs, a re-rack's break).
    pub openings: [usize; 2],
    /// Games each player won from their opening without the other striking (break and run).
    pub run_outs: [usize; 2],
    /// Each player's figures.
    pub players: [SeatTally; 2],
}

/// Where the two players sit: player `opener` in seat A.
#[derive(Clone, Copy, Debug)]
pub struct Sides {
    /// The player in seat A.
    pub opener: usize,
}

impl Sides {
    /// The seat (its index) of player `k`.
    pub fn seat_of(self, k: usize) -> usize {
        usize::from(k != self.opener)
    }

    /// The player in `seat`.
    pub fn player_of(self, seat: Seat) -> usize {
        if seat == Seat::A {
            self.opener
        } else {
            1 - self.opener
        }
    }

    /// `by_player` by seat: seat A's first.
    pub fn by_seat<T: Clone>(self, by_player: &[T; 2]) -> [T; 2] {
        [Seat::A, Seat::B].map(|s| by_player[self.player_of(s)].clone())
    }
}

/// How a match between players is played: `players` by index, the solver's `params`, every
/// draw from `seed`, at most `max_strokes` strokes.
#[derive(Clone, Copy, Debug)]
pub struct Between {
    /// The players, by index.
    pub players: [Player; 2],
    /// The solver's parameters (the ball is the game's).
    pub params: Params,
    /// The seed of every draw.
    pub seed: u64,
    /// Strokes after which the match is stopped.
    pub max_strokes: usize,
}

/// Plays match `index` between `between.players`, player `opener` in seat A, of the game
/// `start` makes from the players' names in seat order; its record by player, and the game
/// as it ended.
pub fn play_between(
    index: u64,
    opener: usize,
    between: &Between,
    start: &dyn Fn([String; 2]) -> Result<Box<dyn GameRules>, String>,
) -> Result<(MatchRecord, Box<dyn GameRules>), String> {
    let sides = Sides { opener };
    let seats = sides.by_seat(&between.players);
    let mut game = start(seats.map(|p| p.to_string()))?;
    let seating = Seating::new(seats, between.params, between.seed, between.max_strokes);
    let run = play_match(game.as_mut(), &seating, &mut |_| {})?;
    Ok((MatchRecord::of(index, between.seed, sides, &run), game))
}

impl MatchRecord {
    /// Match `index`'s record by player, from its run by seat.
    pub fn of(index: u64, seed: u64, sides: Sides, run: &MatchRun) -> Self {
        let (mut openings, mut run_outs) = ([0; 2], [0; 2]);
        for game in &run.played {
            openings[sides.player_of(game.opener)] += 1;
            if game.run_out {
                run_outs[sides.player_of(game.opener)] += 1;
            }
        }
        // Stopped at the stroke limit, the match goes to the player ahead on the game's
        // points (snooker's frame score, carom's points; pool's racks), none when level.
        let [a, b] = run.points;
        let (winner, reason) = match run.winner {
            Some(w) => (
                Some(sides.player_of(w)),
                run.played
                    .last()
                    .map_or(String::new(), |p| p.reason.clone()),
            ),
            None if a != b => (
                Some(sides.player_of(if a > b { Seat::A } else { Seat::B })),
                format!("on points after {} strokes", run.strokes),
            ),
            None => (None, format!("no winner after {} strokes", run.strokes)),
        };
        MatchRecord {
            index,
            seed,
            opener: sides.opener,
            winner,
            strokes: run.strokes,
            reason,
            points: [0, 1].map(|k| run.points[sides.seat_of(k)]),
            openings,
            run_outs,
            players: [0, 1].map(|k| run.tally[sides.seat_of(k)].clone()),
        }
    }
}
