//! Playing the game: the match flow under the rules, the computer's seat and the hint, the
//! cue and its input, the aiming aid.

pub mod aim;
pub mod computer;
pub mod cue;
pub mod decided;
pub mod game;
pub mod key_repeat;
pub mod script;
