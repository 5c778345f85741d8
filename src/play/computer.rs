//! The computer at the table (issue 16): a seat of a match played by [`billiards_ai`], and the
//! hint a human can ask for. The decision runs on a background thread (the frame never
//! waits); then the computer shows its aim (the cue, the aiming aid and the ghost ball, as a
//! human's aim shows) for a moment and shoots through the same messages a human shot takes,
//! so the recording holds its placements and strikes like any others.

use std::{
    thread::JoinHandle,
    time::{Duration, Instant},
};

use bevy::{math::DVec2, prelude::*, window::RequestRedraw};
use billiards_ai::{Level, any_game::Move};
use billiards_physics::{Shot, Vec2};
use billiards_rules::{Declaration, GameRules};

pub use super::decided::{Decided, describe};
use crate::{
    mode::GameMode,
    play::game::{Rules, Turn, TurnCommand},
    settings::ShotSettings,
    sim::{HandRule, ShotRequested, SimStatus, SimSystems, Solver, place_ball_in_hand},
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
    view::camera::OrbitCamera,
};

/// How long the computer shows its aim (or its choice) before it acts; tests set zero.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ComputerPace(pub Duration);

impl Default for ComputerPace {
    fn default() -> Self {
        Self(Duration::from_millis(1500))
    }
}

/// The level the hint plays at.
pub const HINT_LEVEL: Level = Level::Hard;

/// Asks for a hint: the computer's choice for the human to play.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct HintRequested;

/// The computer's side of the live game.
#[derive(Resource, Debug, Default)]
pub struct Computer {
    /// The computer's own turn: a decision being made, or one being shown.
    turn: Option<Task>,
    /// A hint being searched.
    hint_task: Option<Task>,
    /// The last hint, for the HUD (with the turn it was for).
    pub hint: Option<(TurnKey, Hint)>,
    /// What the computer is doing, for the HUD.
    pub doing: Option<String>,
    /// The turn whose shot was just sent, and when: not decided again while the strike takes
    /// effect (a refused shot is decided again after a few seconds).
    fired: Option<(TurnKey, Instant)>,
}

/// The hint as the HUD shows it. The decision is kept, not its words: its cushions are named
/// as the view shows them when it is drawn ([`describe`], whose `cushion_name` does it).
#[derive(Debug, Clone, PartialEq)]
pub enum Hint {
    /// The search runs.
    Thinking,
    /// The computer's choice for the human.
    Decided(Decided),
    /// No hint: why.
    Failed(String),
}

impl Hint {
    /// The hint's line in the HUD in the words of `game` (the game in play), cushions named
    /// as `view` shows them.
    pub fn text(&self, game: Option<&dyn GameRules>, view: &OrbitCamera) -> String {
        match self {
            Hint::Thinking => "hint: thinking...".to_owned(),
            Hint::Decided(decision) => match game {
                Some(game) => format!("hint: {}", describe(decision, game, view)),
                None => "hint: none (the game has ended)".to_owned(),
            },
            Hint::Failed(error) => format!("hint: none ({error})"),
        }
    }
}

/// Which turn of which rack a decision is for: a decision for another turn is dropped.
pub type TurnKey = (u64, usize, usize);

#[derive(Debug)]
enum Task {
    /// The verdict of the last shot is on screen; the computer continues after a moment.
    Reading { key: TurnKey, since: Instant },
    Thinking {
        key: TurnKey,
        seed: u64,
        level: Level,
        handle: JoinHandle<Result<Decided, String>>,
    },
    Showing {
        key: TurnKey,
        seed: u64,
        level: Level,
        decision: Decided,
        since: Instant,
    },
}

impl Task {
    fn key(&self) -> TurnKey {
        match self {
            Task::Reading { key, .. } | Task::Thinking { key, .. } | Task::Showing { key, .. } => {
                *key
            }
        }
    }
}

/// The turn as the computer sees it, in either game, borrowed from the rules each frame (the
/// game is copied for a decision only when one starts: [`question`]).
struct TurnView<'a> {
    key: TurnKey,
    /// Who is to shoot (or to choose).
    name: String,
    /// The shooter's level, `None` for a human.
    level: Option<Level>,
    /// The rack or frame is over.
    over: bool,
    /// Choices are offered before the shot.
    choosing: bool,
    has_human: bool,
    /// Where the cue ball in hand may go.
    hand: Option<HandRule>,
    /// The game's rules, to carry a decision out as one of its moves.
    live: &'a dyn GameRules,
}

/// The turn in play as the computer sees it; `None` in free play.
fn turn_view(rules: &Rules) -> Option<TurnView<'_>> {
    let game = rules.live.as_ref()?;
    let turn = game.rules.turn();
    Some(TurnView {
        key: game.turn_key(),
        name: game.name(turn.striker).to_owned(),
        level: game.computer(turn.striker),
        over: game.rules.end().is_some(),
        choosing: !turn.choices.is_empty(),
        has_human: game.has_human(),
        hand: HandRule::of_place(turn.place),
        live: game.rules.as_ref(),
    })
}

/// Registers the computer's turn and the hint.
pub fn plugin(app: &mut App) {
    app.init_resource::<Computer>()
        .init_resource::<ComputerPace>()
        // Its words name cushions as the view shows them (the camera's plugin inits it too).
        .init_resource::<OrbitCamera>()
        .add_message::<HintRequested>()
        .add_systems(
            Update,
            (play_computer_turn, give_hint)
                .after(SimSystems::Flow)
                .before(SimSystems::Commands)
                .run_if(in_state(GameMode::Play)),
        );
}

/// The seed of a decision: the rack's seed and the turn, so a replayed match decides alike.
fn decision_seed(key: TurnKey) -> u64 {
    let (seed, shots, choices) = key;
    seed ^ (shots as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ ((choices as u64) << 56)
}

/// Starts the search for the turn in play on a background thread, on a copy of the game
/// (each game by its own search: [`billiards_ai::game::decide_game`]); `None` with no match.
fn think(rules: &Rules, sim: &Solver, level: Level, key: TurnKey) -> Option<Task> {
    let game = rules.live.as_ref()?.rules.boxed_clone();
    let sim = sim.simulation().clone();
    let seed = decision_seed(key);
    let handle = std::thread::spawn(move || {
        billiards_ai::game::decide_game(game.as_ref(), &sim, level, seed)
    });
    Some(Task::Thinking {
        key,
        seed,
        level,
        handle,
    })
}

/// The computer's turn: decide in the background, show the aim, then shoot (or choose, or
/// continue after a verdict).
#[allow(clippy::too_many_arguments)]
fn play_computer_turn(
    rules: Res<Rules>,
    turn: Option<Res<State<Turn>>>,
    status: Res<SimStatus>,
    solver: Option<Res<Solver>>,
    spec: Res<TableSpec>,
    pace: Res<ComputerPace>,
    mut computer: ResMut<Computer>,
    mut shot_settings: ResMut<ShotSettings>,
    mut cue_ball: Query<(&Ball, &mut BallMotion), Without<Pocketed>>,
    mut turn_commands: MessageWriter<TurnCommand>,
    mut shots: MessageWriter<ShotRequested>,
    mut redraw: MessageWriter<RequestRedraw>,
    view: Res<OrbitCamera>,
) {
    let (Some(seat), Some(turn), Some(solver)) = (turn_view(&rules), turn, solver) else {
        computer.turn = None;
        computer.doing = None;
        return;
    };
    let key = seat.key;
    let ours = seat.level.is_some()
        && status.at_rest
        && !seat.over
        && matches!(*turn.get(), Turn::Aiming | Turn::BallInHand | Turn::Verdict);
    if !ours || computer.turn.as_ref().is_some_and(|t| t.key() != key) {
        computer.turn = None;
        computer.doing = None;
    }
    let just_fired = computer
        .fired
        .is_some_and(|(k, at)| k == key && at.elapsed() < Duration::from_secs(3));
    let Some(level) = seat.level.filter(|_| ours && !just_fired) else {
        return;
    };
    // The window draws on demand only: keep frames coming while the computer plays.
    redraw.write(RequestRedraw);
    if *turn.get() == Turn::Verdict && !seat.choosing {
        read_verdict(&seat, &mut computer, pace.0, &mut turn_commands);
        return;
    }
    // The verdict was continued: what the computer read is done with.
    if matches!(computer.turn, Some(Task::Reading { .. })) {
        computer.turn = None;
    }
    let name = seat.name.clone();
    match computer.turn.take() {
        None => {
            computer.doing = Some(format!("{name} ({level}) is thinking"));
            computer.turn = think(&rules, &solver, level, key);
        }
        Some(Task::Thinking {
            key,
            seed,
            level,
            handle,
        }) if handle.is_finished() => match outcome(handle) {
            Ok(decision) => {
                announce(&decision, &seat, &mut turn_commands);
                if let Some((shot, place)) = decision.aim() {
                    let place = place.zip(seat.hand);
                    let table = (&*solver, &*spec);
                    show_aim(shot, place, table, &mut shot_settings, &mut cue_ball);
                }
                if let Some(game) = &rules.live {
                    let words = describe(&decision, game.rules.as_ref(), &view);
                    computer.doing = Some(format!("{name} ({level}): {words}"));
                }
                computer.turn = Some(Task::Showing {
                    key,
                    seed,
                    level,
                    decision,
                    since: Instant::now(),
                });
            }
            Err(error) => {
                // Nothing the rules allow: the game waits for a human (a new game).
                computer.doing = Some(format!("{name} ({level}) cannot play: {error}"));
                warn!("computer player: {error}");
            }
        },
        Some(Task::Showing {
            key,
            seed,
            level,
            decision,
            since,
        }) if since.elapsed() >= pace.0 => {
            let shot = carry_out(&decision, &seat, &solver, level, seed, &mut turn_commands);
            if let Some(shot) = shot {
                shots.write(shot);
                computer.fired = Some((key, Instant::now()));
            }
        }
        task => computer.turn = task,
    }
}

/// The verdict is up and no choice is offered: a human at the table reads it (a foul of
/// theirs, ball in hand) and says when, so it stays until they continue; between two
/// computers it goes on after `pace`. The match's own line already reads "NAME to play next:
/// continue" (issue 48, played: a second line said the same).
fn read_verdict(
    seat: &TurnView,
    computer: &mut Computer,
    pace: Duration,
    turn_commands: &mut MessageWriter<TurnCommand>,
) {
    if seat.has_human {
        computer.doing = None;
        return;
    }
    let since = match &computer.turn {
        Some(Task::Reading { since, .. }) => *since,
        _ => {
            let since = Instant::now();
            computer.turn = Some(Task::Reading {
                key: seat.key,
                since,
            });
            since
        }
    };
    if since.elapsed() >= pace {
        turn_commands.write(TurnCommand::Continue);
        computer.turn = None;
    }
}

/// Carries a shown decision out as one of the game's moves: an option taken (a command), or
/// the stroke under the level's execution noise (returned, to be struck). The noise stream
/// is a plan's ([`billiards_ai::Plan::executed`]), so a replayed match decides alike.
fn carry_out(
    decision: &Decided,
    seat: &TurnView,
    solver: &Solver,
    level: Level,
    seed: u64,
    turn_commands: &mut MessageWriter<TurnCommand>,
) -> Option<ShotRequested> {
    match decision.as_move(seat.live) {
        Some(Move::Choose(index)) => {
            turn_commands.write(TurnCommand::ChooseOption(index));
            None
        }
        Some(Move::Strike(stroke)) => {
            let params = solver.simulation().params();
            let mut rng = billiards_ai::noise::stream(seed, u64::MAX, 0);
            let shot = level.execution_noise().apply(stroke.shot, params, &mut rng);
            Some(ShotRequested::from(shot))
        }
        None => {
            warn!("the computer's decision is not for this game: {decision:?}");
            None
        }
    }
}

/// A finished decision thread's answer; a panic is said as such, not as a rules error.
fn outcome(handle: JoinHandle<Result<Decided, String>>) -> Result<Decided, String> {
    handle
        .join()
        .map_err(|_| "the decision thread panicked".to_owned())?
}

/// What goes with a decided shot before it is struck: its declaration (pool's call,
/// snooker's nomination).
fn announce(decision: &Decided, seat: &TurnView, commands: &mut MessageWriter<TurnCommand>) {
    if let Some(Move::Strike(stroke)) = decision.as_move(seat.live)
        && stroke.declared != Declaration::None
    {
        commands.write(TurnCommand::Declare(stroke.declared));
    }
}

/// Puts a decided shot on the table as a human's aim shows: the cue ball in hand where it
/// goes (`place`, under its rule), and the cue's angle, power and tip.
fn show_aim(
    shot: Shot,
    place: Option<(Vec2, HandRule)>,
    (solver, spec): (&Solver, &TableSpec),
    shot_settings: &mut ShotSettings,
    cue_ball: &mut Query<(&Ball, &mut BallMotion), Without<Pocketed>>,
) {
    if let Some((at, rule)) = place
        && let Some((_, mut motion)) = cue_ball
            .iter_mut()
            .find(|(b, _)| b.number == solver.cue_number())
        && let Err(error) = place_ball_in_hand(solver, spec, &mut motion, to_dvec(at), rule)
    {
        warn!("computer's cue ball placement refused: {error}");
    }
    shot_settings.angle = shot.angle.rem_euclid(std::f64::consts::TAU);
    shot_settings.power = shot.speed;
    shot_settings.tip = shot.tip;
    shot_settings.elevation = shot.elevation.to_degrees();
}

fn to_dvec(v: Vec2) -> DVec2 {
    DVec2::new(v.x, v.y)
}

/// A hint for the human to play: the computer's choice at [`HINT_LEVEL`], shown as an aim.
#[allow(clippy::too_many_arguments)]
fn give_hint(
    mut requests: MessageReader<HintRequested>,
    rules: Res<Rules>,
    status: Res<SimStatus>,
    solver: Option<Res<Solver>>,
    spec: Res<TableSpec>,
    mut computer: ResMut<Computer>,
    mut shot_settings: ResMut<ShotSettings>,
    mut cue_ball: Query<(&Ball, &mut BallMotion), Without<Pocketed>>,
    (mut redraw, mut calls): (MessageWriter<RequestRedraw>, MessageWriter<TurnCommand>),
) {
    let asked = requests.read().count() > 0;
    let (Some(seat), Some(solver)) = (turn_view(&rules), solver) else {
        computer.hint_task = None;
        return;
    };
    let key = seat.key;
    if asked && status.at_rest && computer.hint_task.is_none() {
        computer.hint = Some((key, Hint::Thinking));
        computer.hint_task = think(&rules, &solver, HINT_LEVEL, key);
    }
    let finished = matches!(
        &computer.hint_task,
        Some(Task::Thinking { handle, .. }) if handle.is_finished()
    );
    if computer.hint_task.is_some() {
        redraw.write(RequestRedraw);
    }
    if !finished {
        return;
    }
    let Some(Task::Thinking {
        key: asked_for,
        handle,
        ..
    }) = computer.hint_task.take()
    else {
        return;
    };
    if asked_for != key {
        computer.hint = None;
        return;
    }
    let hint = match outcome(handle) {
        Ok(decision) => {
            // The hint's call or nomination too: the player confirms it by shooting, or
            // changes it.
            announce(&decision, &seat, &mut calls);
            if let Some((shot, place)) = decision.aim() {
                let place = place.zip(seat.hand);
                let table = (&*solver, &*spec);
                show_aim(shot, place, table, &mut shot_settings, &mut cue_ball);
            }
            Hint::Decided(decision)
        }
        Err(error) => Hint::Failed(error),
    };
    computer.hint = Some((key, hint));
}
