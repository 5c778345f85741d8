//! What the table shows: the live game or a recording. The game's modes are one Bevy
//! [`States`] enum; each plugin gates its own systems with `run_if(in_state(..))` and enters or
//! leaves a mode in `OnEnter` / `OnExit` systems of its own.
//!
//! The rules issue adds the live game's phases (break, aiming, ball in hand, calling a pocket,
//! shot in play, verdict, game over) as sub-states of [`GameMode::Play`].

use bevy::{prelude::*, state::app::StatesPlugin};

/// Registers [`GameMode`] (and Bevy's state machinery when the app has no `DefaultPlugins`,
/// as in the headless tests). Add it once, before the plugins that gate on the mode.
pub fn plugin(app: &mut App) {
    if !app.is_plugin_added::<StatesPlugin>() {
        app.add_plugins(StatesPlugin);
    }
    app.init_state::<GameMode>();
}

/// Whether the table shows the live game or a recording.
#[derive(States, Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum GameMode {
    /// The live game: the solver runs, the cue takes input.
    #[default]
    Play,
    /// A recording is open: the live game waits, untouched, until the replay closes.
    Replay,
}
