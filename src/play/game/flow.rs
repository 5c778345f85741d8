//! The match flow: judging a finished shot, the player's commands, the turn's phase.

use bevy::prelude::*;
use billiards_physics::Rack;
use billiards_rules::{
    Call, CallRule, CueBall, Game, GameLog, LoggedShot, Match, NextShot, RackStyle, Seat, summarise,
};

use super::snooker::{self, SnookerInPlay};
use super::state::*;
use crate::{
    play::aim::AimPrediction,
    recording::{RecordingsFolder, save_rules_log},
    settings::{PhysicsSettings, TableSetup},
    sim::{
        HandRule, LayoutRequested, RackRequested, Referee, ShotFinished, SimStatus, Solver,
        clock_seed, params_for, respot_ball, table_for,
    },
    table::balls::BallMotion,
    table::geometry::TableSpec,
};

/// The phase the game is in, from the rules, the flags and the table.
fn phase(rules: &Rules, status: &SimStatus, dialog: bool) -> Turn {
    if dialog {
        return Turn::NewGame;
    }
    if !status.at_rest {
        return Turn::ShotInPlay;
    }
    if let Some(snooker) = &rules.snooker {
        return snooker.phase();
    }
    let Some(game) = &rules.game else {
        return Turn::Aiming;
    };
    let next = game.next();
    if game.rack().over.is_some() {
        Turn::GameOver
    } else if game.verdict_shown || !next.choices.is_empty() {
        Turn::Verdict
    } else if game.calling {
        Turn::Calling
    } else if in_hand(next).is_some() {
        Turn::BallInHand
    } else {
        Turn::Aiming
    }
}

fn in_hand(next: &NextShot) -> Option<CueBall> {
    matches!(
        next.cue_ball,
        CueBall::InHandAnywhere | CueBall::InHandBehindHeadString
    )
    .then_some(next.cue_ball)
}

/// A new rack of the match (a re-rack or the next one): its own seed, a fresh log, and its
/// layout to ask of the simulation.
fn new_rack(
    game: &mut GameInPlay,
    spec: &TableSpec,
    settings: &PhysicsSettings,
) -> LayoutRequested {
    game.seed = game.seed.wrapping_add(1);
    game.log = GameLog::new(
        game.play.game,
        game.seed,
        game.play.players.clone(),
        game.rack().breaker,
    );
    rack_request(game.play.game, (game.seed, game.rack_style), spec, settings)
}

/// The rack of `game` from `seed`, asked of the simulation.
fn rack_request(
    game: Game,
    (seed, style): (u64, RackStyle),
    spec: &TableSpec,
    settings: &PhysicsSettings,
) -> LayoutRequested {
    let table = table_for(spec, settings);
    let params = params_for(spec, settings);
    LayoutRequested {
        balls: game.rack_styled(&table, &params.ball, seed, style),
        rack: match game {
            Game::NineBall => Rack::NineBall,
            // The sandbox has no 10-ball rack; the 15-ball triangle is its nearest.
            Game::TenBall | Game::EightBall | Game::FreePlay => Rack::FifteenBall,
        },
        name: match game {
            Game::NineBall => "9-ball",
            Game::TenBall => "10-ball",
            Game::EightBall => "8-ball",
            Game::FreePlay => "15-ball",
        },
    }
}

/// On a finished shot of a rules game: summarise, judge, log, prepare the table.
#[allow(clippy::too_many_arguments)]
pub(super) fn judge_shot(
    mut commands: Commands,
    mut finished: MessageReader<ShotFinished>,
    mut rules: ResMut<Rules>,
    solver: Option<Res<Solver>>,
    mut balls: Query<&mut BallMotion>,
    mut status: ResMut<SimStatus>,
    folder: Res<RecordingsFolder>,
    mut layouts: MessageWriter<LayoutRequested>,
    (spec, settings): (Res<TableSpec>, Res<PhysicsSettings>),
) {
    if finished.read().count() == 0 {
        return;
    }
    let (Some(game), Some(solver)) = (rules.game.as_mut(), solver) else {
        return;
    };
    let sim = solver.simulation();
    let events = sim.history().events();
    let Some(strike) = events
        .iter()
        .rposition(|e| matches!(e.kind, billiards_physics::EventKind::Strike { .. }))
    else {
        return;
    };
    let summary = summarise(&events[strike..], sim.numbers());
    let call = std::mem::take(&mut game.call);
    game.call_ball = None;
    let verdict = match game.play.play(&summary, call) {
        Ok(verdict) => verdict,
        Err(error) => {
            status.note = Some(format!("the rules refused the shot: {error}"));
            return;
        }
    };
    if !verdict.legal() {
        let reason = verdict.reason();
        let reason = reason.strip_prefix("foul: ").unwrap_or(&reason);
        game.last_foul = Some(format!("{} ({})", reason, game.play.name(verdict.shooter)));
    }
    game.log.shots.push(LoggedShot {
        choices: std::mem::take(&mut game.choices),
        call,
        verdict: verdict.clone(),
    });
    game.last_what = Some(billiards_rules::what_happened(
        &summary,
        call,
        &verdict.fouls,
    ));
    game.last = Some(verdict);
    game.verdict_shown = true;
    save_rules_log(
        &folder,
        &solver,
        GameLog::path_beside,
        &game.log,
        &mut status,
    );
    if game.rack().over.is_none() {
        let next = game.next().clone();
        prepare_table(
            &mut commands,
            game,
            &next,
            &solver,
            &mut balls,
            &mut status,
            &mut layouts,
            (&spec, &settings),
        );
    }
}

/// Puts the table as the next shot needs it: a new rack, balls spotted (WPA 1.4), the cue
/// ball back on the table (on the head string, a legal spot for every kind of ball in hand).
#[allow(clippy::too_many_arguments)]
fn prepare_table(
    commands: &mut Commands,
    game: &mut GameInPlay,
    next: &NextShot,
    solver: &Solver,
    balls: &mut Query<&mut BallMotion>,
    status: &mut SimStatus,
    layouts: &mut MessageWriter<LayoutRequested>,
    (spec, settings): (&TableSpec, &PhysicsSettings),
) {
    if next.rerack {
        layouts.write(new_rack(game, spec, settings));
        return;
    }
    let sim = solver.simulation();
    for &number in &next.spot {
        if let Some(id) = sim.numbers().iter().position(|&n| n == number) {
            respot_ball(commands, solver, id, balls, status);
        }
    }
    if let Some(cue) = solver.cue_ball()
        && !sim.ball(cue).motion.on_table()
    {
        respot_ball(commands, solver, cue, balls, status);
    }
}

/// The player's commands and new games.
#[allow(clippy::too_many_arguments)]
pub(super) fn apply_commands(
    mut commands: Commands,
    mut turn_commands: MessageReader<TurnCommand>,
    mut new_games: MessageReader<NewGameRequested>,
    mut racks: MessageReader<RackRequested>,
    mut rules: ResMut<Rules>,
    mut dialog: ResMut<DialogOpen>,
    solver: Option<Res<Solver>>,
    mut balls: Query<&mut BallMotion>,
    mut status: ResMut<SimStatus>,
    mut layouts: MessageWriter<LayoutRequested>,
    (mut spec, settings, mut setup, aim): (
        ResMut<TableSpec>,
        Res<PhysicsSettings>,
        ResMut<TableSetup>,
        Option<Res<AimPrediction>>,
    ),
) {
    // A rack from the panel is free play.
    if racks.read().count() > 0 {
        rules.game = None;
        rules.snooker = None;
    }
    for request in new_games.read() {
        dialog.0 = false;
        rules.game = None;
        rules.snooker = None;
        let game = match request.game {
            GameChoice::Snooker => {
                start_snooker(
                    request,
                    &mut rules,
                    &mut spec,
                    &settings,
                    &mut layouts,
                    &mut status,
                );
                continue;
            }
            GameChoice::Pool(game) => game,
        };
        // The table first: the rack below is set on it, and the table's meshes follow.
        setup.set_if_neq(request.setup);
        spec.set_if_neq(TableSpec::of(request.setup.table));
        if game == Game::FreePlay {
            let table = table_for(&spec, &settings);
            let rack = crate::sim::STARTING_RACK;
            layouts.write(LayoutRequested {
                balls: rack.layout(&table, &params_for(&spec, &settings).ball),
                rack,
                name: crate::sim::rack_slug(rack),
            });
            continue;
        }
        let play = Match::new(game, request.players.clone(), request.race_to, Seat::A);
        let log = GameLog::new(game, request.seed, request.players.clone(), Seat::A);
        let rack = (request.seed, request.setup.rack_style);
        layouts.write(rack_request(game, rack, &spec, &settings));
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
    for &command in turn_commands.read() {
        match command {
            TurnCommand::OpenDialog => dialog.0 = true,
            TurnCommand::CloseDialog => dialog.0 = false,
            _ => {}
        }
        if let Some(game) = rules.snooker.as_mut() {
            snooker_command(game, command, &mut status, &mut layouts, &spec, &settings);
            continue;
        }
        let Some(game) = rules.game.as_mut() else {
            continue;
        };
        match command {
            TurnCommand::OpenDialog
            | TurnCommand::CloseDialog
            | TurnCommand::SnookerChoose(_)
            | TurnCommand::Nominate(_)
            | TurnCommand::Concede => {}
            TurnCommand::Continue => game.verdict_shown = false,
            TurnCommand::Choose(choice) => match game.play.choose(choice) {
                Ok(next) => {
                    game.choices.push(choice);
                    game.verdict_shown = false;
                    if let Some(solver) = &solver {
                        prepare_table(
                            &mut commands,
                            game,
                            &next,
                            solver,
                            &mut balls,
                            &mut status,
                            &mut layouts,
                            (&spec, &settings),
                        );
                    }
                }
                Err(error) => status.note = Some(error.to_string()),
            },
            TurnCommand::StartCalling if game.next().call == CallRule::NotUsed => {
                status.note = Some("no call on this shot".to_owned());
            }
            TurnCommand::Call(Call::PushOut) if !game.next().push_out_allowed => {
                status.note = Some("a push out only right after the break (WPA 2.4)".to_owned());
            }
            TurnCommand::StartCalling => {
                game.calling = true;
                // The call follows the aim: the ball the aiming aid sends into a pocket, and
                // that pocket, proposed for the player to confirm or change.
                game.proposed = aim.as_ref().and_then(|aim| proposed_call(game.next(), aim));
                game.call_ball =
                    preselected_ball(game.next(), game.proposed, aim.as_deref()).or(game.call_ball);
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
                    layouts.write(new_rack(game, &spec, &settings));
                }
            }
        }
    }
}

pub(super) fn start_game_at_launch(
    start: Option<Res<StartGame>>,
    mut new_games: MessageWriter<NewGameRequested>,
    setup: Res<TableSetup>,
) {
    if let Some(start) = start {
        new_games.write(NewGameRequested {
            game: start.game,
            players: ["Player 1".to_owned(), "Player 2".to_owned()],
            race_to: 3,
            seed: start.seed.unwrap_or_else(clock_seed),
            computer: [None, start.computer],
            setup: *setup,
        });
    }
}

/// Derives the turn, the cue ball in hand and the referee's word from the rules.
pub(super) fn follow_rules(
    rules: Res<Rules>,
    dialog: Res<DialogOpen>,
    mut status: ResMut<SimStatus>,
    mut referee: ResMut<Referee>,
    turn: Option<Res<State<Turn>>>,
    mut next_turn: ResMut<NextState<Turn>>,
) {
    let wanted = phase(&rules, &status, dialog.0);
    if turn.is_some_and(|turn| *turn.get() != wanted) {
        next_turn.set(wanted);
    }
    let refuse_shot = match wanted {
        Turn::NewGame => Some("finish the new-game dialog first"),
        Turn::Verdict => Some("the verdict first: continue or choose"),
        Turn::GameOver => Some("the rack is over"),
        Turn::Calling => Some("click a pocket to call it first"),
        Turn::Aiming | Turn::BallInHand => rules.game.as_ref().and_then(|game| {
            (game.next().call == CallRule::EightPocket
                && !matches!(game.call, Call::Ball { ball: 8, .. }))
            .then_some("call a pocket for the 8 first")
        }),
        Turn::ShotInPlay => None,
    }
    .map(str::to_owned);
    let wanted_referee = Referee {
        active: rules.in_match(),
        refuse_shot,
        rack_over: wanted == Turn::GameOver,
    };
    referee.set_if_neq(wanted_referee);
    if let Some(game) = &rules.snooker
        && status.at_rest
    {
        let next = game.next();
        let hand = (next.in_hand && game.frame.end.is_none()).then_some(HandRule::InD);
        if status.ball_in_hand != hand {
            status.ball_in_hand = hand;
        }
    }
    if let Some(game) = &rules.game
        && status.at_rest
    {
        let hand = in_hand(game.next())
            .filter(|_| game.rack().over.is_none())
            .and_then(HandRule::of);
        if status.ball_in_hand != hand {
            status.ball_in_hand = hand;
        }
    }
}

/// The ball the call dialog opens on (issue 48: it chose the 1 while the aim was on the 6):
/// the proposed call's ball, else the 8 when it must be called, else the ball the aim hits
/// first if it may be called, else the lowest legal ball.
fn preselected_ball(
    next: &NextShot,
    proposed: Option<Call>,
    aim: Option<&AimPrediction>,
) -> Option<u8> {
    if let Some(Call::Ball { ball, .. }) = proposed {
        return Some(ball);
    }
    if next.call == CallRule::EightPocket {
        return Some(8);
    }
    let aimed = aim.and_then(|aim| match aim.contact {
        Some((crate::play::aim::FirstContact::Ball { number }, _)) => Some(number),
        _ => None,
    });
    aimed
        .filter(|n| next.legal_first.contains(n))
        .or_else(|| next.legal_first.first().copied())
}

/// The call the aim proposes: the first callable ball (the 8 when it is on, in 10-ball any
/// ball, else a legal first ball) whose drawn path ends in a pocket.
fn proposed_call(next: &NextShot, aim: &AimPrediction) -> Option<Call> {
    let callable = |n: u8| match next.call {
        CallRule::EightPocket => n == 8,
        CallRule::Optional => next.legal_first.contains(&n),
        // 10-ball: any ball the aim sends into a pocket (a combination on the 10 too).
        CallRule::BallAndPocket => true,
        CallRule::NotUsed => false,
    };
    aim.after
        .iter()
        .filter(|path| path.number != 0 && callable(path.number))
        .find_map(|path| {
            path.pocket.map(|pocket| Call::Ball {
                ball: path.number,
                pocket,
            })
        })
}

/// A new snooker match: the 12-ft table, the 22 balls, frame 1.
fn start_snooker(
    request: &NewGameRequested,
    rules: &mut Rules,
    spec: &mut ResMut<TableSpec>,
    settings: &PhysicsSettings,
    layouts: &mut MessageWriter<LayoutRequested>,
    status: &mut SimStatus,
) {
    spec.set_if_neq(TableSpec::snooker());
    let (table, ball) = snooker::equipment(spec, settings);
    // 2.1: a match is the best of an odd number of frames; `race_to` frames win it.
    let best_of = 2 * request.race_to.max(1) - 1;
    let started = SnookerInPlay::new(
        request.players.clone(),
        best_of,
        request.computer,
        request.seed,
        &table,
        &ball,
    );
    match (started, snooker::rack_request(spec, settings)) {
        (Ok(game), Ok(rack)) => {
            rules.snooker = Some(game);
            layouts.write(rack);
        }
        (Err(error), _) => status.note = Some(format!("cannot start snooker: {}", error.0)),
        (_, Err(error)) => status.note = Some(format!("cannot start snooker: {error}")),
    }
}

/// A player's command in a snooker match.
fn snooker_command(
    game: &mut SnookerInPlay,
    command: TurnCommand,
    status: &mut SimStatus,
    layouts: &mut MessageWriter<LayoutRequested>,
    spec: &TableSpec,
    settings: &PhysicsSettings,
) {
    match command {
        TurnCommand::Continue => game.verdict_shown = false,
        TurnCommand::SnookerChoose(choice) => match game.frame.choose(choice) {
            Ok(chosen) => {
                game.choices.push(choice);
                game.verdict_shown = false;
                game.pending_layout = chosen.layout;
            }
            Err(error) => status.note = Some(error.to_string()),
        },
        TurnCommand::Nominate(ball) => game.nominated = Some(ball),
        TurnCommand::Concede => {
            let striker = game.next().striker;
            match game.frame.concede(striker) {
                Ok(_) => {
                    game.verdict_shown = false;
                    game.count_the_frame();
                }
                Err(error) => status.note = Some(error.to_string()),
            }
        }
        TurnCommand::NextRack => {
            if game.frame.winner().is_none() || game.frames.winner().is_some() {
                return;
            }
            if let Err(error) = game.next_frame(spec, settings, layouts) {
                status.note = Some(error);
            }
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use crate::play::{
        aim::{AimPrediction, BallPath},
        game::flow::{preselected_ball, proposed_call},
    };
    use bevy::math::DVec2;
    use billiards_physics::Pocket;
    use billiards_rules::{Call, CallRule, CueBall, NextShot, Seat};

    fn next(call: CallRule, legal_first: Vec<u8>) -> NextShot {
        NextShot {
            shooter: Seat::A,
            cue_ball: CueBall::AsItLies,
            legal_first,
            call,
            break_shot: false,
            push_out_allowed: false,
            choices: Vec::new(),
            spot: Vec::new(),
            rerack: false,
            fouls_in_a_row: 0,
        }
    }

    fn path(number: u8, pocket: Option<Pocket>) -> BallPath {
        BallPath {
            number,
            points: Vec::new(),
            pocket,
        }
    }

    /// Issue 28: the call follows the aim: the first ball of the player's that the aiming aid
    /// sends into a pocket, with that pocket; not the cue ball, not a ball the player may not
    /// call, nothing when no ball drops; the 8 only when it is on.
    #[test]
    fn the_proposed_call_is_the_ball_the_aim_pockets() {
        let aim = AimPrediction {
            after: vec![
                path(0, Some(Pocket::FootLeft)),
                path(2, None),
                path(9, Some(Pocket::SideRight)),
                path(3, Some(Pocket::FootRight)),
            ],
            ..Default::default()
        };
        let solids = next(CallRule::Optional, vec![1, 2, 3, 4, 5, 6, 7]);
        assert_eq!(
            proposed_call(&solids, &aim),
            Some(Call::Ball {
                ball: 3,
                pocket: Pocket::FootRight
            })
        );
        let stripes = next(CallRule::Optional, vec![9, 10]);
        assert_eq!(
            proposed_call(&stripes, &aim),
            Some(Call::Ball {
                ball: 9,
                pocket: Pocket::SideRight
            })
        );
        assert_eq!(
            proposed_call(&next(CallRule::EightPocket, vec![8]), &aim),
            None
        );
        assert_eq!(proposed_call(&next(CallRule::NotUsed, vec![3]), &aim), None);
    }

    /// Issue 48: with no pocket in the aim's paths, the dialog opens on the ball the aim
    /// hits first (the 6), not the lowest (the 1); a ball that may not be called is passed
    /// over for the lowest; the 8 when it must be called.
    #[test]
    fn the_call_dialog_opens_on_the_ball_aimed_at() {
        use crate::play::aim::FirstContact;
        let solids = next(CallRule::Optional, vec![1, 2, 3, 4, 5, 6, 7]);
        let on = |number| AimPrediction {
            contact: Some((FirstContact::Ball { number }, DVec2::ZERO)),
            ..Default::default()
        };
        assert_eq!(preselected_ball(&solids, None, Some(&on(6))), Some(6));
        assert_eq!(preselected_ball(&solids, None, Some(&on(12))), Some(1));
        assert_eq!(preselected_ball(&solids, None, None), Some(1));
        let proposed = Some(Call::Ball {
            ball: 3,
            pocket: Pocket::FootRight,
        });
        assert_eq!(preselected_ball(&solids, proposed, Some(&on(6))), Some(3));
        let eight = next(CallRule::EightPocket, vec![8]);
        assert_eq!(preselected_ball(&eight, None, Some(&on(6))), Some(8));
    }
}
