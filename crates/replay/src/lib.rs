//! Headless tools for billiards recordings: the command line (`simulate`, `verify`, `export`;
//! the batch commands `tournament`, `breaks`, `soak` and `study`, sharded by [`shard`];
//! `position`, position codes to and from JSON; `drill`, a drill played by the computer;
//! `stress`, the many-ball table),
//! a software top-view renderer and GIF/PNG export. No GPU, no Bevy: they run anywhere.

pub mod any_match;
pub mod args;
pub mod breaks;
pub mod cli;
pub mod computer_game;
pub mod drill;
pub mod export;
pub mod flight;
pub mod interface_game;
pub mod position;
pub mod render;
pub mod setup;
pub mod shard;
pub mod simulate;
pub mod soak;
pub mod stats;
pub mod stress;
pub mod study;
pub mod tournament;
