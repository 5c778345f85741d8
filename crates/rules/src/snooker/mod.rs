//! Snooker under the WPBSA "Official Rules of the Games of Snooker and English Billiards",
//! revised November 2019 (Section 2 definitions, Section 3 the game): a public API of its own
//! beside [`crate::Game`] (which the game matches on exhaustively).
//!
//! Flow: [`Frame::new`]; for each stroke read [`Frame::next`]; if it offers choices, the
//! striker picks one with [`Frame::choose`] (after a replace, set the balls it returns);
//! place the cue ball in the D if in hand; strike; run to rest; summarise; [`Frame::play`]
//! with the layouts before and after returns the [`Verdict`]; spot its colours.
//!
//! - `balls`: numbers, values, names;
//! - `geometry`: re-spotting (3.6), snookered (2.16), a clear path (3.14);
//! - `frame`, `judge`: the frame and its strokes; `verdict`: what a stroke returns;
//! - `matches`: a match of N frames;
//! - `rules`: the frame behind the one game interface ([`crate::interface::GameRules`]);
//! - `log`: the rules log of a recorded frame ([`FrameLog`]), re-judged against its recording.

pub mod balls;
pub mod frame;
pub mod geometry;
mod judge;
pub mod log;
pub mod matches;
pub mod rules;
pub mod verdict;

pub use frame::{Chosen, Frame, Snapshot, SnookerError};
pub use judge::Stroke;
pub use log::{FRAME_LOG_VERSION, FrameLog, FrameLogError, LoggedStroke};
pub use matches::SnookerMatch;
pub use verdict::{BallOn, Choice, Foul, FrameEnd, NextShot, Verdict};
