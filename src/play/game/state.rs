//! The rules' state in the game: the match in play, the turn, the player's commands.

use bevy::prelude::*;
use billiards_ai::Level;
use billiards_rules::Game;

pub use super::live::LiveGame;
pub use super::turn::Turn;
use crate::settings::TableSetup;

/// A game the player can start: a game of the catalog, or free play.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GameChoice {
    /// A game of the catalog by its id ([`billiards_rules::catalog::find`]), played behind
    /// the one interface: 9-ball, 10-ball, 8-ball, snooker, three-cushion.
    Catalog(&'static str),
    /// The sandbox: no match, the panel's racks and drills.
    FreePlay,
}

impl GameChoice {
    /// Every choice, in the dialog's order.
    pub const ALL: [GameChoice; 6] = [
        GameChoice::Catalog("nine-ball"),
        GameChoice::Catalog("ten-ball"),
        GameChoice::Catalog("eight-ball"),
        GameChoice::Catalog("snooker"),
        GameChoice::Catalog("three-cushion"),
        GameChoice::FreePlay,
    ];

    /// The game's catalog entry; `None` for free play.
    pub fn entry(self) -> Option<&'static billiards_rules::catalog::GameEntry> {
        match self {
            GameChoice::Catalog(id) => billiards_rules::catalog::find(id).ok(),
            GameChoice::FreePlay => None,
        }
    }

    /// The player's name for it.
    pub fn label(self) -> &'static str {
        match self {
            GameChoice::FreePlay => "free play",
            GameChoice::Catalog(_) => self.entry().map_or("unknown game", |e| e.label),
        }
    }

    /// What the match's length counts ("race to", "best of", "points to") and its usual
    /// length.
    pub fn length(self) -> (&'static str, u32) {
        self.entry()
            .map_or(("race to", 3), |e| (e.length_unit, e.default_length))
    }

    /// What the length is in: "racks", "frames", "points".
    pub fn length_noun(self) -> &'static str {
        self.entry().map_or("racks", |e| e.length_noun)
    }

    /// Whether it is played on the pool table of the player's choosing (size, pockets,
    /// rack style) rather than its own.
    pub fn pool_table(self) -> bool {
        self.entry().is_none_or(|e| e.pool_table)
    }
}

impl From<Game> for GameChoice {
    fn from(game: Game) -> Self {
        match game {
            Game::NineBall => GameChoice::Catalog("nine-ball"),
            Game::TenBall => GameChoice::Catalog("ten-ball"),
            Game::EightBall => GameChoice::Catalog("eight-ball"),
            Game::FreePlay => GameChoice::FreePlay,
        }
    }
}

/// Starts a new game (the dialog's Start).
#[derive(Message, Debug, Clone, PartialEq, Eq)]
pub struct NewGameRequested {
    /// The game; free play is the sandbox (no match).
    pub game: GameChoice,
    /// The players' names.
    pub players: [String; 2],
    /// The match's length in the game's own unit ([`GameChoice::length`]): racks to win,
    /// frames best of (snooker), points to reach (three-cushion).
    pub race_to: u32,
    /// The seed of the first rack's gaps (each later rack takes the next seed).
    pub seed: u64,
    /// Each seat's computer level; `None`: a human.
    pub computer: [Option<Level>; 2],
    /// The table and the rack style.
    pub setup: TableSetup,
}

/// What the player does between shots.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub enum TurnCommand {
    /// Open the new-game dialog.
    OpenDialog,
    /// Close it without a new game.
    CloseDialog,
    /// The verdict has been read: on to the next shot.
    Continue,
    /// Start calling a ball and a pocket (click the pocket on the table).
    StartCalling,
    /// The ball to call ([`billiards_rules::Declarations::callable`]).
    CallBall(u8),
    /// Snooker: the striker concedes the frame (2.1(a)); any game that has a concession.
    Concede,
    /// Take option `index` of the turn ([`billiards_rules::Turn::choices`]): a game behind
    /// the interface.
    ChooseOption(usize),
    /// Declare this for the next stroke (a called pocket, a safety, a push out, a
    /// nomination, or nothing); it ends a call in progress.
    Declare(billiards_rules::Declaration),
    /// The rack is over: rack the next one of the match.
    NextRack,
}

/// The rules side of the live game: `None` in free play.
#[derive(Resource, Debug, Default)]
pub struct Rules {
    /// The match in play, behind the one interface, if any.
    pub live: Option<LiveGame>,
}

impl Rules {
    /// Whether a match (of any game) is in play.
    pub fn in_match(&self) -> bool {
        self.live.is_some()
    }

    /// No match: free play.
    pub fn clear(&mut self) {
        self.live = None;
    }

    /// The match's next player: whether the computer plays that seat (its level, `None` for
    /// a human) and whether choices are offered first; `None` in free play.
    pub fn to_play(&self) -> Option<(Option<Level>, bool)> {
        let game = self.live.as_ref()?;
        let turn = game.rules.turn();
        Some((game.computer(turn.striker), !turn.choices.is_empty()))
    }
}

/// The game to start at launch (`--game`), two players, race to 3.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StartGame {
    /// The game.
    pub game: GameChoice,
    /// The second seat's computer level (`--computer`); `None`: two humans.
    pub computer: Option<Level>,
    /// The first rack's seed (`--seed`); `None`: from the clock.
    pub seed: Option<u64>,
}

/// Whether the new-game dialog is open.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct DialogOpen(pub bool);
