//! What the headless app tests share.

use std::time::Duration;

use bevy::{app::Plugins, prelude::*, time::TimeUpdateStrategy};
use billiards::{mode, recording, settings, sim};

/// A headless game: `MinimalPlugins`, the modes, the settings, the simulation and the
/// autosave, then `extra`, in 16 ms frames; no frame run yet.
pub fn headless<M>(extra: impl Plugins<M>) -> App {
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins,
        mode::plugin,
        settings::plugin,
        sim::plugin,
        recording::plugin,
    ))
    .add_plugins(extra);
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(
        16,
    )));
    app
}
