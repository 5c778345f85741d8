//! The table's sounds: the cue strike, ball-ball clicks, cushion thuds and jaw knocks with a
//! volume from the impact speed, and pocket drops, all from the solver's messages
//! ([`crate::sim::CueStruck`], [`crate::sim::BallContact`], [`crate::sim::CushionHit`],
//! [`crate::sim::BallPocketed`]). The sounds are synthesised at start ([`synth`]). Playing them
//! needs the cargo feature `sound` (Bevy's audio, which needs ALSA's headers); `M` mutes.

pub mod synth;

#[cfg(feature = "sound")]
mod player;

#[cfg(feature = "sound")]
pub use player::{SoundOn, plugin};
