//! The flow of a game behind the interface ([`LiveGame`]): a match started from the catalog,
//! a finished stroke judged ([`GameRules::judge`]) and logged, the balls the judgement or an
//! option puts back, and the player's commands. Nothing here asks which game it is.

use bevy::prelude::*;
use billiards_physics::{Rack, Simulation, Vec2};
use billiards_rules::catalog::{self, MatchSettings};
use billiards_rules::{CueBallPlace, Declaration, GameRules, Need, Setup, StrokeEntry};

use super::call::{preselected_ball, proposed_call};
use super::live::LiveGame;
use super::put::{layout_at, set_balls};
use super::state::{NewGameRequested, Rules, TurnCommand};
use super::stroke::{judge_last_stroke, log_stroke};
use crate::{
    play::aim::AimPrediction,
    recording::RecordingsFolder,
    settings::{PhysicsSettings, TableSetup},
    sim::{LayoutRequested, ShotFinished, SimStatus, Solver, params_for, table_for},
    table::balls::{BallMotion, Pocketed},
    table::geometry::TableSpec,
};

/// Starts a match of catalog game `id` on its table: the player's pool table and rack style
/// for pool's games, the game's own table otherwise, set first (the layout is set on it);
/// then the game started on the solver's table and balls, and its layout asked of the
/// simulation. A refusal (an unknown id, a bad length) goes to the status line.
pub(super) fn start_live(
    request: &NewGameRequested,
    id: &str,
    (spec, setup): (&mut ResMut<TableSpec>, &mut ResMut<TableSetup>),
    settings: &PhysicsSettings,
    layouts: &mut MessageWriter<LayoutRequested>,
) -> Result<LiveGame, String> {
    let entry = catalog::find(id).map_err(|e| e.0)?;
    if entry.pool_table {
        setup.set_if_neq(request.setup);
        spec.set_if_neq(TableSpec::of(request.setup.table));
    } else {
        let (own_table, _) = (entry.equipment)();
        spec.set_if_neq(TableSpec::fitting(&own_table));
    }
    let equipment = (table_for(spec, settings), params_for(spec, settings).ball);
    let match_settings = MatchSettings {
        players: request.players.clone(),
        length: request.race_to,
        seed: request.seed,
        style: request.setup.rack_style,
        equipment: Some(equipment),
    };
    let cannot = |e: billiards_rules::RulesError| format!("cannot start {}: {e}", entry.label);
    let rules = entry.start(&match_settings).map_err(cannot)?;
    let balls = rules.layout().map_err(cannot)?;
    layouts.write(layout_request(rules.as_ref(), balls));
    LiveGame::new(rules, Some(entry), request.computer, request.seed).map_err(cannot)
}

/// The layout `balls` of `game` as asked of the simulation; the recording is named after
/// the game.
fn layout_request(
    game: &dyn GameRules,
    balls: Vec<billiards_physics::BallSetup>,
) -> LayoutRequested {
    LayoutRequested {
        // The standard rack nearest by its count (9-ball's, 10-ball's, a carom layout's:
        // the 9-ball diamond; 8-ball's, snooker's: the triangle); the panel's rack buttons
        // start free play on it.
        rack: if balls.len() <= 11 {
            Rack::NineBall
        } else {
            Rack::FifteenBall
        },
        balls,
        name: game.name(),
    }
}

/// A player's command in a match behind the interface. Balls an option puts back wait in
/// [`LiveGame::pending`] for [`put_pending`]; a new layout restarts the recording and its log.
/// `aim`: the aiming aid's prediction, whose pocketed ball a call proposes.
pub(super) fn live_command(
    game: &mut LiveGame,
    command: TurnCommand,
    (status, layouts): (&mut SimStatus, &mut MessageWriter<LayoutRequested>),
    layout: &[(u8, Vec2)],
    aim: Option<&AimPrediction>,
) {
    let refused = |status: &mut SimStatus, e: billiards_rules::RulesError| {
        status.note = Some(e.0);
    };
    match command {
        TurnCommand::Continue => game.verdict_shown = false,
        TurnCommand::ChooseOption(index) => match game.rules.choose(index, layout) {
            Ok(setup) => {
                game.choices.push(index);
                game.verdict_shown = false;
                match setup {
                    Setup::Keep => {}
                    Setup::Put { balls } => game.pending = balls,
                    // Every ball back where it was (snooker's replace, 3.14): moved in place,
                    // in the same recording, when no ball now on the table is left out.
                    Setup::Layout { balls }
                        if layout
                            .iter()
                            .all(|(n, _)| balls.iter().any(|(m, _)| m == n)) =>
                    {
                        game.pending = balls;
                    }
                    Setup::Layout { balls } => {
                        let balls = balls
                            .into_iter()
                            .map(|(n, p)| billiards_physics::BallSetup::at(n, p))
                            .collect();
                        new_layout(game, balls, layouts, status);
                    }
                    Setup::Rack { balls } => new_layout(game, balls, layouts, status),
                }
            }
            Err(e) => refused(status, e),
        },
        TurnCommand::StartCalling => {
            let turn = game.rules.turn();
            if turn.declare.pocket == Need::NotUsed || turn.declare.callable.is_empty() {
                status.note = Some("no call on this stroke".to_owned());
                return;
            }
            game.calling = true;
            // The call follows the aim: the ball the aiming aid sends into a pocket, and
            // that pocket, proposed for the player to confirm or change.
            game.proposed = aim.and_then(|aim| proposed_call(&turn, aim));
            game.call_ball = preselected_ball(&turn, game.proposed, aim).or(game.call_ball);
        }
        TurnCommand::CallBall(ball) => game.call_ball = Some(ball),
        TurnCommand::Declare(declaration) => {
            let declare = game.rules.turn().declare;
            let refused = match declaration {
                Declaration::PushOut if !declare.push_out => {
                    Some("a push out only right after the break (WPA 2.4)")
                }
                Declaration::Safety if !declare.safety => Some("no safety to call here"),
                Declaration::Pocket { ball, .. } if !declare.callable.contains(&ball) => {
                    Some("that ball may not be called now")
                }
                _ => None,
            };
            if let Some(why) = refused {
                status.note = Some(why.to_owned());
                return;
            }
            game.declared = declaration;
            game.calling = false;
            game.call_ball = None;
        }
        TurnCommand::Concede => match game.rules.concede() {
            Ok(_) => game.verdict_shown = false,
            Err(e) => refused(status, e),
        },
        TurnCommand::NextRack => {
            if game.rules.end().is_none_or(|end| end.match_over) {
                return;
            }
            match game.begin_next() {
                Ok(balls) => new_layout(game, balls, layouts, status),
                Err(e) => refused(status, e),
            }
        }
        _ => {}
    }
}

/// A new layout of the table: a new recording, so a new log from the game as it stands.
fn new_layout(
    game: &mut LiveGame,
    balls: Vec<billiards_physics::BallSetup>,
    layouts: &mut MessageWriter<LayoutRequested>,
    status: &mut SimStatus,
) {
    if let Err(e) = game.restart_log() {
        status.note = Some(format!("the game log restarts empty: {e}"));
    }
    layouts.write(layout_request(game.rules.as_ref(), balls));
}

/// On a finished stroke of a match behind the interface: judge it on the solver's events
/// from the strike and the layouts before and after, log it, and put back what the
/// judgement says (with the next striker's cue ball into a legal place when in hand).
pub(super) fn judge_live(
    mut finished: MessageReader<ShotFinished>,
    mut rules: ResMut<Rules>,
    solver: Option<Res<Solver>>,
    mut status: ResMut<SimStatus>,
    folder: Res<RecordingsFolder>,
) {
    if finished.read().count() == 0 {
        return;
    }
    let (Some(game), Some(solver)) = (rules.live.as_mut(), solver) else {
        return;
    };
    let sim = solver.simulation();
    if let Err(error) = game.bind_sandbox(solver.started(), *sim.table(), sim.params().ball) {
        status.note = Some(format!("free play could not follow the table: {error}"));
        return;
    }
    let declared = std::mem::take(&mut game.declared);
    game.calling = false;
    game.call_ball = None;
    let Some(judged) = judge_last_stroke(game.rules.as_mut(), solver.simulation(), declared) else {
        return;
    };
    let judgement = match judged {
        Ok(judgement) => judgement,
        Err(error) => {
            status.note = Some(format!("the rules refused the stroke: {error}"));
            return;
        }
    };
    if !judgement.fair {
        let what = if judgement.fouls.is_empty() {
            judgement.text.clone()
        } else {
            judgement.fouls.join("; ")
        };
        game.last_foul = Some(format!("{what} ({})", game.name(judgement.striker)));
    }
    let entry = StrokeEntry {
        choices: std::mem::take(&mut game.choices),
        declared,
        judgement: judgement.clone(),
    };
    log_stroke(&mut game.log, entry, (&folder, &solver), &mut status);
    let mut moves = judgement.put.clone();
    if game.rules.solo() {
        // A drill's try: its window and the HUD say how it went; nothing to read first.
    } else if game.rules.sandbox() {
        // Free play's strokes need no reading: the HUD says what each did, and the note
        // what the rules put back (a scratch's cue ball on the head string).
        if !moves.is_empty() {
            // The HUD's last stroke says what happened; this says what the player may do.
            status.note = Some(
                "the cue ball is on the head string: drag it, or the Shot section's slider \
                 moves it along the string"
                    .to_owned(),
            );
        }
    } else {
        game.verdict_shown = true;
    }
    game.last = Some(judgement);
    moves.extend(hand_place(game.rules.as_ref(), solver.simulation(), &moves));
    // Set on the table by `put_pending`, later in this frame's flow.
    game.pending = moves;
}

/// Free play's table set by hand (a rack, a position, a drill left, a ball placed): at rest,
/// when the table differs from the one its game last saw, the game follows it (bound to the
/// recording in play, [`LiveGame::bind_sandbox`]) and takes stock of its balls
/// ([`GameRules::set_by_hand`]), so that its lines between strokes are the table's (played:
/// "balls left: 15" with the one ball a drill had left).
pub(super) fn follow_sandbox_table(
    mut rules: ResMut<Rules>,
    solver: Option<Res<Solver>>,
    mut status: ResMut<SimStatus>,
) {
    let (Some(solver), true) = (solver, status.at_rest) else {
        return;
    };
    let Some(game) = rules.live.as_mut().filter(|g| g.rules.sandbox()) else {
        return;
    };
    let sim = solver.simulation();
    let layout = layout_at(sim, None);
    if layout == game.seen {
        return;
    }
    let taken = game
        .bind_sandbox(solver.started(), *sim.table(), sim.params().ball)
        .and_then(|()| game.rules.set_by_hand(&layout));
    if let Err(error) = taken {
        status.note = Some(format!("free play could not follow the table: {error}"));
    }
    game.seen = layout;
}

/// Balls the last judgement or an option put back ([`Judgement::put`](billiards_rules::Judgement),
/// [`Setup::Put`]), set on the table after the frame's judging and commands.
pub(super) fn put_pending(
    mut commands: Commands,
    mut rules: ResMut<Rules>,
    solver: Option<ResMut<Solver>>,
    mut balls: Query<(&mut BallMotion, Has<Pocketed>)>,
    mut status: ResMut<SimStatus>,
) {
    let (Some(game), Some(mut solver)) = (rules.live.as_mut(), solver) else {
        return;
    };
    if game.pending.is_empty() {
        return;
    }
    let moves = std::mem::take(&mut game.pending);
    let name = |n: u8| game.rules.ball_name(n);
    set_balls(
        &mut commands,
        &mut solver,
        &moves,
        &mut balls,
        &mut status,
        &name,
    );
}

/// With the cue ball in hand and off the table (pocketed), a place the rules accept for it
/// (after the balls `put` are set): [`billiards_rules::hand_place`], the first clear one of a
/// sweep of the table from the middle of its head half. `None` when it is on the table or
/// nothing is in hand.
fn hand_place(game: &dyn GameRules, sim: &Simulation, put: &[(u8, Vec2)]) -> Option<(u8, Vec2)> {
    let turn = game.turn();
    if !matches!(turn.place, CueBallPlace::InHand { .. }) {
        return None;
    }
    let cue = turn.cue_ball;
    let on_table = layout_at(sim, None);
    if on_table.iter().any(|&(n, _)| n == cue) {
        return None;
    }
    let others: Vec<(u8, Vec2)> = on_table
        .into_iter()
        .filter(|(n, _)| !put.iter().any(|(m, _)| m == n))
        .chain(put.iter().copied())
        .filter(|&(n, _)| n != cue)
        .collect();
    billiards_rules::hand_place(game, &others, None).map(|at| (cue, at))
}
