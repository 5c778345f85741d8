//! The rules' state in the game: the match in play, the turn, the player's commands.

use bevy::prelude::*;
use billiards_ai::Level;
use billiards_rules::Game;

pub use super::live::LiveGame;
pub use super::turn::Turn;
use crate::settings::TableSetup;

/// A game the player can start: a game of the catalog, played behind the one interface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GameChoice {
    /// A game of the catalog by its id ([`billiards_rules::catalog::find`]): 9-ball, 10-ball,
    /// 8-ball, snooker, three-cushion, free play (the sandbox: the panel's racks, placing
    /// balls, undo and drills).
    Catalog(&'static str),
}

/// Free play's id in the catalog.
pub const FREE_PLAY: GameChoice = GameChoice::Catalog("free-play");

impl GameChoice {
    /// Every choice, in the dialog's order.
    pub const ALL: [GameChoice; 6] = [
        GameChoice::Catalog("nine-ball"),
        GameChoice::Catalog("ten-ball"),
        GameChoice::Catalog("eight-ball"),
        GameChoice::Catalog("snooker"),
        GameChoice::Catalog("three-cushion"),
        FREE_PLAY,
    ];

    /// The game's catalog entry (`None` for an id the catalog does not hold).
    pub fn entry(self) -> Option<&'static billiards_rules::catalog::GameEntry> {
        match self {
            GameChoice::Catalog(id) => billiards_rules::catalog::find(id).ok(),
        }
    }

    /// The player's name for it.
    pub fn label(self) -> &'static str {
        self.entry().map_or("unknown game", |e| e.label)
    }

    /// What the match's length counts ("race to", "best of", "points to") and its usual
    /// length.
    pub fn length(self) -> (&'static str, u32) {
        self.entry()
            .map_or(("race to", 3), |e| (e.length_unit, e.default_length))
    }

    /// What the length is in: "racks", "frames", "points".
    pub fn length_noun(self) -> &'static str {
        self.entry().map_or("racks", |e| e.unit.noun())
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
            Game::FreePlay => FREE_PLAY,
        }
    }
}

/// Starts a new game (the dialog's Start).
#[derive(Message, Debug, Clone, PartialEq, Eq)]
pub struct NewGameRequested {
    /// The game; free play ([`FREE_PLAY`]) is the sandbox.
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

/// The rules side of the live game: the game in play behind the one interface, free play's
/// sandbox and a drill session included; `None` only if even free play could not start.
#[derive(Resource, Debug)]
pub struct Rules {
    /// The game in play, behind the one interface, if any.
    pub live: Option<LiveGame>,
}

/// At launch: free play ([`Rules::free_play`]) until a game is started.
impl Default for Rules {
    fn default() -> Self {
        let mut rules = Self { live: None };
        rules.free_play();
        rules
    }
}

impl Rules {
    /// Whether a match whose table is its own is in play (any game but free play's
    /// sandbox): no ball is placed by hand, no shot taken back.
    pub fn in_match(&self) -> bool {
        self.live.as_ref().is_some_and(|g| !g.rules.sandbox())
    }

    /// Free play from now on: the sandbox in play is kept, a match ends and free play
    /// starts with its players (its table and log bound at its first stroke,
    /// [`LiveGame::sandbox`]).
    pub fn free_play(&mut self) {
        if self.live.as_ref().is_some_and(|g| g.rules.sandbox()) {
            return;
        }
        let (players, seats) = match &self.live {
            // A drill's second seat is the drill itself: its player and a second one.
            Some(g) if g.rules.solo() => (
                [g.rules.players()[0].clone(), "Player 2".to_owned()],
                [None, None],
            ),
            Some(g) => (g.rules.players().clone(), g.seats),
            None => (["Player 1".to_owned(), "Player 2".to_owned()], [None, None]),
        };
        self.live = LiveGame::sandbox(players, seats);
    }

    /// The game's next player: whether the computer plays that seat (its level, `None` for
    /// a human) and whether choices are offered first; `None` without a game.
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
