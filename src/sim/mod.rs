//! The simulation: `billiards-physics` inside the ECS.
//!
//! One frame, in [`Update`]:
//! 1. [`SimSystems::Step`]: one exclusive system advances the solver by the frame's virtual
//!    time (so pause and time scale apply), or by exactly one event when the paused player
//!    asks for a step. It writes back only the balls whose state changed and turns the
//!    solver's events into messages ([`BallContact`], [`CushionHit`], [`BallPocketed`],
//!    [`ShotFinished`]). When every ball rests it does nothing at all.
//! 2. [`SimSystems::Flow`]: the game's reaction to a finished shot (respotting after a scratch).
//! 3. [`SimSystems::Commands`]: requests for the next frame: rack, settings changes, edited
//!    balls (found by change detection, so only those are re-predicted), the shot.
//!
//! Running the requests after the step means a shot starts with the next frame's delta, not
//! with whatever idle time the reactive window accumulated before the key press.

use bevy::{prelude::*, window::RequestRedraw};

use crate::{mode::GameMode, table::geometry::TableSpec};

mod commands;
mod messages;
mod respot;
mod solver;
mod step;
mod undo;

pub use commands::{carom_layout, snooker_layout};
pub use messages::*;
pub use respot::{HandError, move_ball_in_hand, place_ball_in_hand};
pub use solver::{JAW_RADIUS, Solver, ball_motion, layout_now, params_for, table_for, to_dvec2};

use commands::{
    apply_physics_settings, follow_table_setup, place_edited_balls, rack_balls, strike_cue_ball,
};
pub use step::MAX_FRAME_STEP;
use step::{advance_solver, allow_slow_frames, apply_clock_settings, request_default_rack};
use undo::undo_last_shot;

/// Registers the solver, its messages and the game-flow systems. Needs no rendering, so it
/// runs headless under `MinimalPlugins` too (together with [`crate::settings::plugin`]).
pub fn plugin(app: &mut App) {
    app.add_message::<RackRequested>()
        .add_message::<LayoutRequested>()
        .add_message::<SceneRequested>()
        .add_message::<ShotRequested>()
        .add_message::<StepRequested>()
        .add_message::<CueStruck>()
        .add_message::<UndoRequested>()
        .add_message::<ShotUndone>()
        .add_message::<BallContact>()
        .add_message::<CushionHit>()
        .add_message::<BallPocketed>()
        .add_message::<ShotFinished>()
        .add_message::<RequestRedraw>()
        .init_resource::<TableSpec>()
        .init_resource::<SimStatus>()
        .init_resource::<Referee>()
        .configure_sets(
            Update,
            (SimSystems::Step, SimSystems::Flow, SimSystems::Commands).chain(),
        )
        // The live solver neither advances nor takes commands while a recording is shown.
        .configure_sets(Update, SimSystems::Step.run_if(in_state(GameMode::Play)))
        .configure_sets(Update, SimSystems::Flow.run_if(in_state(GameMode::Play)))
        .configure_sets(
            Update,
            SimSystems::Commands.run_if(in_state(GameMode::Play)),
        )
        // A rack's new balls get their meshes in the frame the old ones are despawned, so no
        // frame shows an empty table.
        .configure_sets(
            Update,
            crate::table::balls::BallSystems::Visuals.after(SimSystems::Commands),
        )
        .add_systems(Startup, (request_default_rack, allow_slow_frames))
        .add_systems(
            Update,
            (
                advance_solver.in_set(SimSystems::Step),
                (
                    apply_clock_settings,
                    follow_table_setup,
                    rack_balls,
                    apply_physics_settings,
                    place_edited_balls,
                    undo_last_shot,
                    strike_cue_ball,
                )
                    .chain()
                    .in_set(SimSystems::Commands),
            ),
        );
}

/// The phases of the simulation within a frame, in order.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SimSystems {
    /// The exclusive solver step and its writeback.
    Step,
    /// Game flow reacting to what the step reported.
    Flow,
    /// Requests that take effect from the next step on.
    Commands,
}
