//! Headless tools for billiards recordings: the command line (`simulate`, `verify`, `export`,
//! `tournament`),
//! a software top-view renderer and GIF/PNG export. No GPU, no Bevy: they run anywhere.

pub mod breaks;
pub mod cli;
pub mod export;
pub mod game;
pub mod render;
pub mod shard;
pub mod soak;
pub mod tournament;
