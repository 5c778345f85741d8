//! The turn's phase: a Bevy sub-state of [`GameMode::Play`].

use bevy::prelude::*;

use crate::mode::GameMode;

/// The phase of the turn, while the live game is shown.
#[derive(SubStates, Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[source(GameMode = GameMode::Play)]
pub enum Turn {
    /// The new-game dialog is open: game, players, race.
    NewGame,
    /// Aim and shoot (a call may be made first in 8-ball; the break is a shot too).
    #[default]
    Aiming,
    /// The cue ball is in hand: drag it where the rules allow, then aim and shoot.
    BallInHand,
    /// Calling a pocket: click it on the table.
    Calling,
    /// The balls are moving.
    ShotInPlay,
    /// The last shot's verdict is shown; continue, or take one of the options offered.
    Verdict,
    /// The rack is over: next rack, or a new game once the match is won.
    GameOver,
}
