//! What three-cushion refuses, in words a player or a programmer can act on.

use billiards_physics::BallId;

/// Why a stroke, a request or a set-up was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ThreeCushionError {
    /// The rules or the table cannot make a game.
    #[error("three-cushion: {0}")]
    Rules(String),
    /// An event names a ball that is none of the three.
    #[error("ball id {0} is none of the three carom balls")]
    UnknownBall(BallId),
    /// The events hold no cue strike.
    #[error("the events hold no cue strike: nothing to judge")]
    NoStrike,
    /// The events hold more than one cue strike (one stroke is judged at a time).
    #[error("the events hold {0} cue strikes: judge one stroke at a time")]
    SeveralStrikes(usize),
    /// A ball was placed by hand while the balls were moving.
    #[error("ball id {0} was placed during the stroke")]
    PlacedDuringStroke(BallId),
    /// A ball was pocketed: three-cushion is played on a table without pockets.
    #[error("ball id {0} was pocketed: three-cushion is played on a table without pockets")]
    Pocketed(BallId),
    /// The stroke was struck from another layout than the game's.
    #[error(
        "the {ball} ball was struck at ({x:.4}, {y:.4}) m but the game has it at ({gx:.4}, {gy:.4}) m"
    )]
    NotWhereTheGameHasIt {
        /// The ball's name.
        ball: &'static str,
        /// Where the events strike it.
        x: f64,
        /// Where the events strike it.
        y: f64,
        /// Where the game has it.
        gx: f64,
        /// Where the game has it.
        gy: f64,
    },
    /// The game is over: no stroke is played any more.
    #[error("the game is over")]
    GameOver,
    /// The balls were asked to be re-spotted while the cue ball touches no ball.
    #[error("the {0} cue ball touches no ball: nothing to re-spot (UMB Art. 27)")]
    NotFrozen(&'static str),
}
