//! The player's commands and new games (`apply_commands`, step 2 of the frame's flow): a new
//! match of pool or snooker, free play, and each [`TurnCommand`] applied to the match in play.

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use billiards_rules::{Call, CallRule, Choice, Game, GameLog, Match, Seat};

use super::call::{preselected_ball, proposed_call};
use super::flow::{new_rack, prepare_table, rack_request};
use super::live_flow::{live_command, start_live};
use super::state::*;
use crate::{
    play::aim::AimPrediction,
    settings::{PhysicsSettings, TableSetup},
    sim::{LayoutRequested, RackRequested, SimStatus, Solver, clock_seed, params_for, table_for},
    table::balls::BallMotion,
    table::geometry::TableSpec,
};

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

/// The live simulation a choice changes (balls spotted, the cue ball put back) and the
/// status line that takes a refused command's reason.
#[derive(SystemParam)]
pub(super) struct Live<'w, 's> {
    commands: Commands<'w, 's>,
    solver: Option<Res<'w, Solver>>,
    balls: Query<'w, 's, &'static mut BallMotion>,
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
    // A rack from the panel is free play.
    if requests.racks.read().count() > 0 {
        state.rules.clear();
    }
    for request in requests.new_games.read() {
        start_game(request, &mut state, &mut table, &mut live.status);
    }
    for &command in requests.turns.read() {
        turn_command(command, &mut state, &mut table, &mut live, aim.as_deref());
    }
}

/// A new game from the dialog: the dialog closes, the match in play ends, and snooker, a
/// pool match or free play starts.
fn start_game(
    request: &NewGameRequested,
    state: &mut MatchState,
    table: &mut TableAccess,
    status: &mut SimStatus,
) {
    state.dialog.0 = false;
    state.rules.clear();
    match request.game {
        GameChoice::Catalog(id) => {
            match start_live(
                request,
                id,
                &mut table.spec,
                &table.settings,
                &mut table.layouts,
            ) {
                Ok(game) => state.rules.live = Some(game),
                Err(error) => status.note = Some(error),
            }
        }
        GameChoice::Pool(game) => start_pool(request, game, &mut state.rules, table),
    }
}

/// A pool game: the table set up first (the rack is set on it, and the table's meshes
/// follow), then free play's starting rack, or a match's first rack and its log.
fn start_pool(request: &NewGameRequested, game: Game, rules: &mut Rules, table: &mut TableAccess) {
    table.setup.set_if_neq(request.setup);
    table.spec.set_if_neq(TableSpec::of(request.setup.table));
    if game == Game::FreePlay {
        let physics = table_for(&table.spec, &table.settings);
        let rack = crate::sim::STARTING_RACK;
        table.layouts.write(LayoutRequested {
            balls: rack.layout(&physics, &params_for(&table.spec, &table.settings).ball),
            rack,
            name: crate::sim::rack_slug(rack),
        });
        return;
    }
    let play = Match::new(game, request.players.clone(), request.race_to, Seat::A);
    let log = GameLog::new(game, request.seed, request.players.clone(), Seat::A);
    let rack = (request.seed, request.setup.rack_style);
    table
        .layouts
        .write(rack_request(game, rack, &table.spec, &table.settings));
    rules.game = Some(GameInPlay {
        play,
        log,
        seed: request.seed,
        call: Call::None,
        call_ball: None,
        calling: false,
        proposed: None,
        last: None,
        verdict_shown: false,
        last_foul: None,
        last_what: None,
        choices: Vec::new(),
        seats: request.computer,
        rack_style: request.setup.rack_style,
    });
}

/// One command: the dialog opened or closed, then the command applied to the snooker or
/// pool match in play (free play has none).
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
        live_command(game, command, &mut live.status, &mut table.layouts, &layout);
        return;
    }
    if let Some(game) = state.rules.game.as_mut() {
        pool_command(game, command, table, live, aim);
    }
}

/// A player's command in a pool match: a verdict dismissed, a choice (WPA 1.6, 2.4), the call
/// (proposed from the aim, then confirmed), the next rack.
fn pool_command(
    game: &mut GameInPlay,
    command: TurnCommand,
    table: &mut TableAccess,
    live: &mut Live,
    aim: Option<&AimPrediction>,
) {
    match command {
        TurnCommand::OpenDialog
        | TurnCommand::CloseDialog
        | TurnCommand::ChooseOption(_)
        | TurnCommand::Declare(_)
        | TurnCommand::Concede => {}
        TurnCommand::Continue => game.verdict_shown = false,
        TurnCommand::Choose(choice) => choose(game, choice, table, live),
        TurnCommand::StartCalling if game.next().call == CallRule::NotUsed => {
            live.status.note = Some("no call on this shot".to_owned());
        }
        TurnCommand::Call(Call::PushOut) if !game.next().push_out_allowed => {
            live.status.note = Some("a push out only right after the break (WPA 2.4)".to_owned());
        }
        TurnCommand::StartCalling => {
            game.calling = true;
            // The call follows the aim: the ball the aiming aid sends into a pocket, and
            // that pocket, proposed for the player to confirm or change.
            game.proposed = aim.and_then(|aim| proposed_call(game.next(), aim));
            game.call_ball = preselected_ball(game.next(), game.proposed, aim).or(game.call_ball);
        }
        TurnCommand::CallBall(ball) => game.call_ball = Some(ball),
        TurnCommand::Call(call) => {
            game.call = call;
            game.calling = false;
        }
        TurnCommand::NextRack => {
            if game.play.next_rack().is_ok() {
                game.last = None;
                game.last_foul = None;
                game.verdict_shown = false;
                table
                    .layouts
                    .write(new_rack(game, &table.spec, &table.settings));
            }
        }
    }
}

/// The player's choice after a verdict, taken by the rules; the table then made ready for
/// the shot it leads to (a refused choice's reason goes to the status line).
fn choose(game: &mut GameInPlay, choice: Choice, table: &mut TableAccess, live: &mut Live) {
    match game.play.choose(choice) {
        Ok(next) => {
            game.choices.push(choice);
            game.verdict_shown = false;
            if let Some(solver) = &live.solver {
                prepare_table(
                    &mut live.commands,
                    game,
                    &next,
                    solver,
                    &mut live.balls,
                    &mut live.status,
                    &mut table.layouts,
                    (&table.spec, &table.settings),
                );
            }
        }
        Err(error) => live.status.note = Some(error.to_string()),
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
