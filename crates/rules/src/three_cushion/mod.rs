//! Three-cushion carom under the UMB rules: a public API of its own (like [`crate::snooker`]),
//! small enough for one adapter to the game's interface.
//!
//! Sources (the search tool's `pages` corpus): the UMB "World rules of carom billiard",
//! edition of 1 January 1989 (copy at 3cushionbilliards.com: Art. 13 the spots, Art. 23
//! starting position, Art. 24 cannon, Art. 27 balls in contact, Art. 29 end of the match,
//! Art. 41 fouls, Art. 83 three cushions), and the UMB rules' later numbering (copy at
//! billiardrule.com: 3.3 "Starting position, cue-ball"). Article numbers are cited in the code
//! and in `tests/three_cushion.rs`.
//!
//! Flow: [`ThreeCushionGame::new`] sets the opening position ([`ThreeCushionGame::setups`]);
//! for each stroke read [`ThreeCushionGame::next`] (striker, cue ball, the opening's red
//! first, frozen balls); if frozen, optionally [`ThreeCushionGame::respot_frozen`]; strike
//! and run the solver to rest; [`ThreeCushionGame::play`] with the stroke's events returns
//! the [`Verdict`].
//!
//! Left out: fouls the events cannot show (a push, a double hit, touching a ball, a ball off
//! the table: the solver keeps every ball on the cloth), time limits and time-outs, the
//! cushion draw for the break (A starts), the knock-out's penalty shots after a draw.
//!
//! - `balls`: [`Ball`], [`BallIds`]; `error`: [`ThreeCushionError`];
//! - `layout`: the spots, the opening, frozen balls and their re-spotting;
//! - `judge`: a stroke's facts from the events, its fouls, its reason in words;
//! - `game`: [`ThreeCushionGame`], [`Rules`], [`Next`], [`Verdict`], [`Outcome`];
//! - `rules`: [`rules::ThreeCushionMatch`], the game behind the one game interface
//!   ([`crate::interface::GameRules`]).

pub mod balls;
pub mod error;
pub mod game;
pub mod judge;
pub mod layout;
pub mod rules;

pub use balls::{Ball, BallIds};
pub use error::ThreeCushionError;
pub use game::{Next, Outcome, Rules, ThreeCushionGame, Verdict};
pub use judge::{Foul, StrokeFacts, fouls, read_stroke, reason};
pub use layout::{FROZEN_GAP, STARTING_SPOT_OFFSET, Side, Spots, frozen_to};
