//! Practice and sharing (issue 39): balls placed by hand, a position as a text code (copy,
//! paste, `--position CODE`, a replay's shot), and drills with scores.
//!
//! - [`placing`]: the Place tool (free play): pick a ball and drag it (or click where it
//!   goes), snapped to the spots, never onto another ball or over a pocket; add and remove
//!   balls; every edit undoable.
//! - `edits`: the Place tool's edits carried out (move, add, remove, clear, undo).
//! - [`position`]: [`PositionRequested`] sets a position on the table; the current table
//!   as a position; the clipboard.
//! - [`drill_list`]: the drills listed (the standard set, the player's folder) and saved;
//! - [`drill`]: a drill session, a one-player game behind the one interface in play like any
//!   game: the drill's position for each try, the best kept in the settings file
//!   ([`DrillBests`]).
//!
//! The mode is one [`Practice`] state: free play, the Place tool, or a drill.

pub mod drill;
pub mod drill_list;
mod edits;
pub mod placing;
pub mod position;
pub mod state;

use bevy::prelude::*;

pub use drill::{
    DrillBests, DrillCommand, DrillList, DrillRequested, DrillSession, SaveDrillRequested,
    StartDrill,
};
pub use placing::{EditRequested, Placing};
pub use position::{
    Clipboard, PendingPosition, PositionCode, PositionCommand, PositionRequested,
    ShotAsPositionRequested, StartPosition,
};
pub use state::{KeptNote, Practice};

use crate::{
    input::{InputSystems, PointerTool},
    mode::GameMode,
    sim::SimSystems,
};

/// The Place tool takes the pointer from the cue while it is up.
fn take_pointer(mut tool: ResMut<PointerTool>) {
    tool.0 = true;
}

fn give_pointer_back(mut tool: ResMut<PointerTool>) {
    tool.0 = false;
}

/// Registers the practice tools: their state, messages and systems.
pub fn plugin(app: &mut App) {
    app.init_state::<Practice>()
        // Read to end a drill; the stress plugin writes it (added again here, a no-op in the
        // game, so the practice tools also run without the stress table).
        .add_message::<crate::stress::StressRequested>()
        .add_message::<PositionRequested>()
        .add_message::<PositionCommand>()
        .add_message::<ShotAsPositionRequested>()
        .init_resource::<PendingPosition>()
        .add_message::<EditRequested>()
        .add_message::<DrillRequested>()
        .add_message::<DrillCommand>()
        .add_message::<SaveDrillRequested>()
        .init_resource::<Placing>()
        .init_resource::<DrillBests>()
        .init_resource::<DrillList>()
        .init_resource::<Clipboard>()
        .init_resource::<PositionCode>()
        .init_resource::<KeptNote>()
        .add_systems(Update, state::restore_note.after(SimSystems::Commands))
        .add_systems(
            Startup,
            (position::start_position, drill::start_drill_at_launch),
        )
        .add_systems(
            Update,
            (
                placing::pick_and_drag
                    .in_set(InputSystems::Pointer)
                    .run_if(in_state(Practice::Placing))
                    .run_if(resource_exists::<ButtonInput<MouseButton>>),
                (
                    placing::placing_keys.run_if(in_state(Practice::Placing)),
                    place_tool_key,
                    drill::drill_keys.run_if(in_state(Practice::Drill)),
                )
                    .in_set(InputSystems::Keyboard)
                    // A headless app (the tests) has no keyboard.
                    .run_if(resource_exists::<ButtonInput<KeyCode>>),
            )
                .before(SimSystems::Flow)
                .run_if(in_state(GameMode::Play)),
        )
        .add_systems(
            Update,
            (
                drill::end_drill_on_new_table,
                drill::after_stroke,
                drill::drill_commands,
                drill::start_drill,
                position::open_pending,
                position::position_commands,
                position::load_position,
                edits::apply_edits,
                placing::leave_placing_in_a_match,
                drill::save_as_drill,
            )
                .chain()
                .after(SimSystems::Flow)
                .before(crate::recording::SaveBeforeRack)
                .run_if(in_state(GameMode::Play)),
        )
        .add_systems(
            Update,
            placing::draw_placing
                .after(SimSystems::Commands)
                .run_if(in_state(Practice::Placing))
                // Headless (the tests): nothing draws.
                .run_if(resource_exists::<bevy::gizmos::config::GizmoConfigStore>),
        )
        .add_systems(
            Update,
            drill::draw_goals
                .after(SimSystems::Commands)
                .run_if(in_state(Practice::Drill).and_then(in_state(GameMode::Play)))
                .run_if(resource_exists::<bevy::gizmos::config::GizmoConfigStore>),
        )
        .add_systems(
            Update,
            position::shot_as_position.run_if(in_state(GameMode::Replay)),
        )
        .init_resource::<PointerTool>()
        .add_systems(OnEnter(Practice::Placing), take_pointer)
        .add_systems(
            OnExit(Practice::Placing),
            (placing::clear_selection, give_pointer_back),
        );
}

/// P takes the Place tool up or puts it down: free play only (not in a match, nor in a drill,
/// whose position is the drill's).
fn place_tool_key(
    keys: Res<ButtonInput<KeyCode>>,
    referee: Res<crate::sim::Referee>,
    state: Res<State<Practice>>,
    mut next: ResMut<NextState<Practice>>,
    mut status: ResMut<crate::sim::SimStatus>,
) {
    if !keys.just_pressed(KeyCode::KeyP) {
        return;
    }
    match (*state.get(), referee.edits) {
        (Practice::Placing, _) => next.set(Practice::Off),
        (Practice::Off, true) => next.set(Practice::Placing),
        (Practice::Off, false) => {
            status.note = Some("balls are placed in free play, not in a match".to_owned());
        }
        (Practice::Drill, _) => {
            status.note = Some("leave the drill to place balls".to_owned());
        }
    }
}
