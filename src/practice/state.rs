//! The practice tools' mode, one Bevy state.

use bevy::prelude::*;

/// What the practice tools are doing: nothing (free play or a match), placing balls, or a
/// drill session.
#[derive(States, Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Practice {
    /// Free play or a match: clicks on the table aim.
    #[default]
    Off,
    /// The Place tool: clicks and drags on the table move balls.
    Placing,
    /// A drill is in session.
    Drill,
}

/// A note said as a new table is set up, said again once it is (the new rack resets the
/// status at `SimSystems::Commands`, after the practice tools ran).
#[derive(Resource, Debug, Clone, Default, PartialEq, Eq)]
pub struct KeptNote(pub Option<String>);

pub(super) fn restore_note(mut kept: ResMut<KeptNote>, mut status: ResMut<crate::sim::SimStatus>) {
    if let Some(note) = kept.0.take() {
        status.note = Some(note);
    }
}
