//! The rules in the game: any game of the catalog behind the one interface ([`LiveGame`]
//! holding a [`billiards_rules::GameRules`]), free play included, and the turn's
//! phase as a Bevy sub-state of [`GameMode::Play`](crate::mode::GameMode::Play).
//!
//! One source of truth: the [`Rules`] resource (the match, the declaration, whether a
//! verdict or the call window is up). Every frame, in [`SimSystems::Flow`]:
//! 1. `judge_live`: on [`ShotFinished`](crate::sim::ShotFinished), the stroke's events (from
//!    its strike on) and the layouts before and after are judged
//!    ([`GameRules::judge`](billiards_rules::GameRules::judge)); the judgement is logged
//!    ([`StrokeLog`](billiards_rules::StrokeLog), saved beside the autosaved recording) and
//!    the balls it puts back wait for `put_pending`;
//! 2. `apply_commands`: the player's [`TurnCommand`]s and [`NewGameRequested`];
//! 3. `put_pending`: the balls a judgement or an option put back set on the table;
//! 4. `follow_rules`: derives the [`Turn`] from the resource, the cue ball in hand
//!    ([`SimStatus::ball_in_hand`](crate::sim::SimStatus::ball_in_hand)) from the game's
//!    turn, and tells the simulation's [`Referee`](crate::sim::Referee) whether a shot may be
//!    taken now.
//!
//! Free play is a game of the catalog like the others, the sandbox
//! ([`billiards_rules::GameRules::sandbox`]): its table may be set by hand (the
//! [`Referee`](crate::sim::Referee)'s `edits`), its strokes are judged on the table their
//! strike finds and need no reading, a scratch's cue ball is put back by its judgement, and
//! it follows a table set by hand ([`LiveGame::bind_sandbox`], `follow_sandbox_table`). A
//! drill session is a game here too, a one-player one
//! ([`billiards_rules::GameRules::solo`], started by `crate::practice`).
//!
//! [`table_plugin`] adds what needs a window: the legal area of the cue ball in hand, the
//! pockets while calling and the called pocket (gizmos), and the click on a pocket.

mod call;
mod commands;
mod flow;
mod live;
mod live_flow;
pub mod put;
mod state;
pub mod stroke;
mod table_input;
mod turn;

pub use state::*;
pub use table_input::pocket_near;

use commands::{apply_commands, start_game_at_launch};
use flow::follow_rules;
use table_input::{click_pocket, confirm_key, draw_rules, lock_aim};

use bevy::prelude::*;

use crate::{
    input::{AimLocked, InputSystems},
    sim::SimSystems,
};

/// Registers the rules, the turn's sub-state and its messages. Needs no window (headless
/// tests add it beside the simulation).
pub fn plugin(app: &mut App) {
    app.add_sub_state::<Turn>()
        .add_message::<NewGameRequested>()
        .add_message::<TurnCommand>()
        .init_resource::<Rules>()
        .init_resource::<DialogOpen>()
        .init_resource::<AimLocked>()
        .add_systems(Startup, start_game_at_launch)
        .add_systems(Update, lock_aim.before(InputSystems::Pointer))
        .add_systems(
            Update,
            (
                live_flow::judge_live,
                apply_commands,
                live_flow::put_pending,
                live_flow::follow_sandbox_table,
                follow_rules,
            )
                .chain()
                .in_set(SimSystems::Flow),
        );
}

/// What needs a window: the pointer on the pockets while calling, the legal area of the cue
/// ball in hand and the called pocket.
pub fn table_plugin(app: &mut App) {
    app.add_systems(
        Update,
        (
            click_pocket
                .in_set(InputSystems::Pointer)
                .run_if(in_state(Turn::Calling))
                .before(SimSystems::Flow),
            confirm_key
                .in_set(InputSystems::Keyboard)
                .run_if(in_state(Turn::Verdict))
                .before(SimSystems::Flow),
            draw_rules.after(SimSystems::Commands),
        ),
    );
}
