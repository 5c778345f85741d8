//! The state of one rack ([`GameState`]): the game, the balls on the table, the groups, the
//! fouls in a row and the choices pending, with the moves every game's rules make on it. The
//! judging itself dispatches by game in [`crate::game`]; the state lives here so that the
//! games' rules, which that dispatcher calls, need not import it back (issue 50).

use crate::foul::{Group, WinReason};
use crate::shot::ShotSummary;
use crate::turn::{Choice, NextShot, Seat};
use billiards_physics::{BallSetup, BallSpec, Table};
use serde::{Deserialize, Serialize};

/// The game played.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Game {
    /// 8-ball, WPA section 3.
    EightBall,
    /// 9-ball, WPA section 2.
    NineBall,
    /// 10-ball, WPA section 9 (added to the rules on 1 January 2009): 9-ball's rotation
    /// with every shot called.
    TenBall,
    /// The sandbox: no fouls, no turns, a scratch respots the cue ball.
    FreePlay,
}

impl Game {
    /// The object balls of a full rack.
    pub fn object_balls(self) -> Vec<u8> {
        match self {
            Game::NineBall => (1..=9).collect(),
            Game::TenBall => (1..=10).collect(),
            Game::EightBall | Game::FreePlay => (1..=15).collect(),
        }
    }

    /// The rack of this game from `seed` ([`crate::racks`]); free play racks the 15 balls
    /// as 8-ball does. The cue ball comes first, on the head spot.
    pub fn rack(self, table: &Table, ball: &BallSpec, seed: u64) -> Vec<BallSetup> {
        self.rack_styled(table, ball, seed, crate::racks::RackStyle::Triangle)
    }

    /// [`Game::rack`] racked in `style`: a template (frozen) or a triangle (seeded gaps).
    pub fn rack_styled(
        self,
        table: &Table,
        ball: &BallSpec,
        seed: u64,
        style: crate::racks::RackStyle,
    ) -> Vec<BallSetup> {
        let gap = style.gap();
        match self {
            Game::NineBall => crate::racks::nine_ball_spaced(table, ball, seed, gap),
            Game::TenBall => crate::racks::ten_ball_spaced(table, ball, seed, gap),
            Game::EightBall | Game::FreePlay => {
                crate::racks::eight_ball_spaced(table, ball, seed, gap)
            }
        }
    }
}

/// Why a shot or a choice was refused (nothing changes).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RuleError {
    /// The game is over.
    #[error("the game is over")]
    GameOver,
    /// A choice must be made before the next shot.
    #[error("a choice must be made first: one of {0:?}")]
    ChoicePending(Vec<Choice>),
    /// The choice is not among those offered.
    #[error("{choice:?} is not offered (offered: {offered:?})")]
    ChoiceNotOffered {
        /// The choice made.
        choice: Choice,
        /// The choices offered.
        offered: Vec<Choice>,
    },
    /// The call names a ball that is not on the table.
    #[error("the {0} is not on the table")]
    BallNotOnTable(u8),
    /// The call is not one this shot allows.
    #[error("cannot call the {ball}: {why}")]
    IllegalCall {
        /// The ball called.
        ball: u8,
        /// Why not.
        why: &'static str,
    },
    /// A push out outside its window.
    #[error("a push out is allowed only on the shot right after a legal break (WPA 2.4)")]
    PushOutNotAllowed,
    /// A call this game does not use.
    #[error("{0:?} has no {1}")]
    CallNotUsed(Game, &'static str),
    /// The summary pockets a ball that is not on the table.
    #[error("the shot pocketed the {0}, which was not on the table")]
    UnknownBall(u8),
}

/// Choices pending, with what they depend on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub(crate) enum Pending {
    /// 8-ball illegal break: the incoming player decides (WPA 3.3).
    IllegalBreak {
        /// The player who broke.
        breaker: Seat,
        /// The cue ball was pocketed on that break.
        scratched: bool,
    },
    /// 8-ball: the 8 went in on the break (WPA 3.3).
    EightOnBreak {
        /// The player who broke.
        breaker: Seat,
        /// The break was a foul (the incoming player chooses).
        foul: bool,
    },
    /// 9-ball and 10-ball: after a push out (WPA 2.4, 9.4).
    PushOut {
        /// The player who pushed.
        pusher: Seat,
    },
    /// 10-ball: a ball went down on a shot that did not pocket the called ball in the called
    /// pocket; the incoming player shoots or hands the table back (WPA 9.7).
    HandBack {
        /// The player whose shot it was.
        shooter: Seat,
    },
}

/// The state of one rack.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct GameState {
    /// The game.
    pub game: Game,
    /// The player who broke this rack (or breaks it next).
    pub breaker: Seat,
    /// 8-ball: the group of player A (`None`: the table is open; B has the other).
    pub group_a: Option<Group>,
    /// Fouls in a row of each player, by [`Seat::index`] (counted in every game; 9-ball and
    /// 10-ball lose on the third, WPA 2.8, 9.11 — 8-ball has no such rule, WPA 6.14).
    pub fouls: [u8; 2],
    /// Object balls on the table (after spotting), ascending.
    pub on_table: Vec<u8>,
    /// What the next shot must respect.
    pub next: NextShot,
    /// The winner and why, once the game is over.
    pub over: Option<(Seat, WinReason)>,
    pub(crate) pending: Option<Pending>,
}

impl GameState {
    /// The group of `seat` (8-ball; `None` while the table is open).
    pub fn group(&self, seat: Seat) -> Option<Group> {
        match seat {
            Seat::A => self.group_a,
            Seat::B => self.group_a.map(Group::other),
        }
    }

    /// Puts a spotted ball back among the balls on the table.
    pub(crate) fn put_back(&mut self, ball: u8) {
        if let Err(at) = self.on_table.binary_search(&ball) {
            self.on_table.insert(at, ball);
        }
    }

    /// Free play: the object balls on the table are those of `layout` (number and centre,
    /// the cue ball among them or not), as placed by hand; the next shot may hit any.
    pub(crate) fn take_stock(&mut self, layout: &[(u8, billiards_physics::Vec2)]) {
        let mut balls: Vec<u8> = layout
            .iter()
            .map(|&(n, _)| n)
            .filter(|&n| n != crate::shot::CUE)
            .collect();
        balls.sort_unstable();
        balls.dedup();
        self.next.legal_first.clone_from(&balls);
        self.on_table = balls;
    }

    /// Takes the pocketed object balls and those driven off the table (WPA 6.5) out of
    /// play; a game's rules put back the ones it spots.
    pub(crate) fn take_off(&mut self, shot: &ShotSummary) {
        self.on_table.retain(|b| {
            !shot.pocketed.iter().any(|&(p, _)| p == *b) && !shot.off_table.contains(b)
        });
    }
}
