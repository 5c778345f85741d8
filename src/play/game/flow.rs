//! The match flow: judging a finished shot, the table made ready for the next, the turn's
//! phase (the player's commands are in `commands.rs`).

use bevy::prelude::*;
use billiards_physics::Rack;
use billiards_rules::{
    Call, CallRule, CueBall, Game, GameLog, LoggedShot, NextShot, RackStyle, summarise,
};

use super::state::*;
use crate::{
    recording::{RecordingsFolder, save_rules_log},
    settings::PhysicsSettings,
    sim::{
        HandRule, LayoutRequested, Referee, ShotFinished, SimStatus, Solver, params_for,
        respot_ball, table_for,
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
    if let Some(game) = &rules.live {
        return game.phase();
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
pub(super) fn new_rack(
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
pub(super) fn rack_request(
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
pub(super) fn prepare_table(
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

/// Derives the turn, the cue ball in hand and the referee's word from the rules.
pub(super) fn follow_rules(
    rules: Res<Rules>,
    dialog: Res<DialogOpen>,
    solver: Option<ResMut<Solver>>,
    mut status: ResMut<SimStatus>,
    mut referee: ResMut<Referee>,
    turn: Option<Res<State<Turn>>>,
    mut next_turn: ResMut<NextState<Turn>>,
) {
    let wanted = phase(&rules, &status, dialog.0);
    // A game behind the interface: its turn, asked once a frame.
    let live = rules.live.as_ref().map(|g| (g, g.rules.turn()));
    if turn.is_some_and(|turn| *turn.get() != wanted) {
        next_turn.set(wanted);
    }
    let refuse_shot = match wanted {
        Turn::NewGame => Some("finish the new-game dialog first"),
        Turn::Verdict => Some("the verdict first: continue or choose"),
        Turn::GameOver => Some("the rack is over"),
        Turn::Calling => Some("click a pocket to call it first"),
        Turn::Aiming | Turn::BallInHand if let Some((game, turn)) = &live => (turn.declare.pocket
            == billiards_rules::Need::Required
            && !matches!(game.declared, billiards_rules::Declaration::Pocket { .. }))
        .then_some("declare a ball and a pocket first"),
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
    // The striker's own cue ball (three-cushion: the white or the yellow), 0 otherwise.
    let cue = live.as_ref().map_or(0, |(_, turn)| turn.cue_ball);
    if let Some(mut solver) = solver
        && solver.cue_number() != cue
    {
        solver.set_cue_number(cue);
    }
    if let Some((game, turn)) = &live
        && status.at_rest
    {
        let hand = HandRule::of_place(turn.place).filter(|_| game.rules.end().is_none());
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
