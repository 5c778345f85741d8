//! The player's commands and new games (`apply_commands`, step 2 of the frame's flow): a new
//! match of any game, free play, and each [`TurnCommand`] applied to the match in play.

use super::live_flow::{live_command, start_live};
use super::state::*;
use crate::{
    play::aim::AimPrediction,
    settings::{PhysicsSettings, TableSetup},
    sim::{LayoutRequested, RackRequested, SimStatus, Solver, clock_seed},
    table::geometry::TableSpec,
};
use bevy::ecs::system::SystemParam;
use bevy::prelude::*;

/// What asks the match to change this frame: the player's commands, new games, and racks
/// from the panel.
#[derive(SystemParam)]
pub(super) struct Requests<'w, 's> {
    turns: MessageReader<'w, 's, TurnCommand>,
    new_games: MessageReader<'w, 's, NewGameRequested>,
    racks: MessageReader<'w, 's, RackRequested>,
}

/// The match in play and whether the new-game dialog is up.
#[derive(SystemParam)]
pub(super) struct MatchState<'w> {
    rules: ResMut<'w, Rules>,
    dialog: ResMut<'w, DialogOpen>,
}

/// The table a game is set on: its kind and set-up, the physics settings, and the layouts
/// asked of the simulation.
#[derive(SystemParam)]
pub(super) struct TableAccess<'w> {
    spec: ResMut<'w, TableSpec>,
    setup: ResMut<'w, TableSetup>,
    settings: Res<'w, PhysicsSettings>,
    layouts: MessageWriter<'w, LayoutRequested>,
}

/// The live simulation (the layout a choice is taken on) and the status line that takes a
/// refused command's reason.
#[derive(SystemParam)]
pub(super) struct Live<'w> {
    solver: Option<Res<'w, Solver>>,
    status: ResMut<'w, SimStatus>,
}

/// The player's commands and new games.
pub(super) fn apply_commands(
    mut requests: Requests,
    mut state: MatchState,
    mut table: TableAccess,
    mut live: Live,
    aim: Option<Res<AimPrediction>>,
) {
    // A rack from the panel is free play (the sandbox follows the new table at its first
    // stroke).
    if requests.racks.read().count() > 0 {
        state.rules.free_play();
    }
    for request in requests.new_games.read() {
        start_game(request, &mut state, &mut table, &mut live.status);
    }
    for &command in requests.turns.read() {
        turn_command(command, &mut state, &mut table, &mut live, aim.as_deref());
    }
}

/// A new game from the dialog: the dialog closes, the game in play ends, and a game of the
/// catalog (free play's sandbox among them) starts.
fn start_game(
    request: &NewGameRequested,
    state: &mut MatchState,
    table: &mut TableAccess,
    status: &mut SimStatus,
) {
    state.dialog.0 = false;
    let GameChoice::Catalog(id) = request.game;
    match start_live(
        request,
        id,
        (&mut table.spec, &mut table.setup),
        &table.settings,
        &mut table.layouts,
    ) {
        Ok(game) => state.rules.live = Some(game),
        Err(error) => {
            // The table may be the new game's already: the match in play ends in free play.
            state.rules.free_play();
            status.note = Some(error);
        }
    }
}

/// One command: the dialog opened or closed, then the command applied to the game in play.
fn turn_command(
    command: TurnCommand,
    state: &mut MatchState,
    table: &mut TableAccess,
    live: &mut Live,
    aim: Option<&AimPrediction>,
) {
    match command {
        TurnCommand::OpenDialog => state.dialog.0 = true,
        TurnCommand::CloseDialog => state.dialog.0 = false,
        _ => {}
    }
    if let Some(game) = state.rules.live.as_mut() {
        let layout = live
            .solver
            .as_ref()
            .map_or_else(Vec::new, |s| super::put::layout_at(s.simulation(), None));
        live_command(
            game,
            command,
            (&mut live.status, &mut table.layouts),
            &layout,
            aim,
        );
    }
}

/// The game the command line asked for (`--game`), started at launch as from the dialog.
pub(super) fn start_game_at_launch(
    start: Option<Res<StartGame>>,
    mut new_games: MessageWriter<NewGameRequested>,
    setup: Res<TableSetup>,
) {
    if let Some(start) = start {
        new_games.write(NewGameRequested {
            game: start.game,
            players: ["Player 1".to_owned(), "Player 2".to_owned()],
            race_to: start.game.length().1,
            seed: start.seed.unwrap_or_else(clock_seed),
            computer: [None, start.computer],
            setup: *setup,
        });
    }
}
