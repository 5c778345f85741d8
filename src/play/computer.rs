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
use billiards_ai::{AiError, Decision, Level, Plan, ShotKind};
use billiards_physics::{Cushion, Vec2};
use billiards_rules::{Call, GameState, pocket_name};

use crate::{
    mode::GameMode,
    play::game::{Rules, Turn, TurnCommand},
    settings::ShotSettings,
    sim::{HandRule, ShotRequested, SimStatus, SimSystems, Solver, place_ball_in_hand},
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
    view::camera::{CameraMode, OrbitCamera},
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
/// as the view shows them when it is drawn ([`cushion_name`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Hint {
    /// The search runs.
    Thinking,
    /// The computer's choice for the human.
    Decided(Decision),
    /// No hint: why.
    Failed(String),
}

impl Hint {
    /// The hint's line in the HUD, cushions named as `view` shows them.
    pub fn text(&self, view: &OrbitCamera) -> String {
        match self {
            Hint::Thinking => "hint: thinking...".to_owned(),
            Hint::Decided(decision) => format!("hint: {}", describe(decision, view)),
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
        handle: JoinHandle<Result<Decision, AiError>>,
    },
    Showing {
        key: TurnKey,
        seed: u64,
        level: Level,
        decision: Decision,
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

fn think(state: GameState, sim: &Solver, level: Level, key: TurnKey) -> Task {
    let sim = sim.simulation().clone();
    let seed = decision_seed(key);
    let handle = std::thread::spawn(move || billiards_ai::decide(&state, &sim, level, seed));
    Task::Thinking {
        key,
        seed,
        level,
        handle,
    }
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
    let (Some(game), Some(turn), Some(solver)) = (&rules.game, turn, solver) else {
        computer.turn = None;
        computer.doing = None;
        return;
    };
    let next = game.next();
    let key = game.turn_key();
    let seat = next.shooter;
    let level = game.computer(seat);
    let ours = level.is_some()
        && status.at_rest
        && game.rack().over.is_none()
        && matches!(*turn.get(), Turn::Aiming | Turn::BallInHand | Turn::Verdict);
    if !ours || computer.turn.as_ref().is_some_and(|t| t.key() != key) {
        computer.turn = None;
        computer.doing = None;
    }
    let just_fired = computer
        .fired
        .is_some_and(|(k, at)| k == key && at.elapsed() < Duration::from_secs(3));
    let Some(level) = level.filter(|_| ours && !just_fired) else {
        return;
    };
    // The window draws on demand only: keep frames coming while the computer plays.
    redraw.write(RequestRedraw);
    if *turn.get() == Turn::Verdict && next.choices.is_empty() {
        // A human at the table reads the verdict (a foul of theirs, ball in hand) and says
        // when: it stays until they continue. Between two computers it goes on after a moment.
        if game.has_human() {
            computer.doing = Some(format!("{} waits for you to continue", game.name(seat)));
            return;
        }
        let since = match &computer.turn {
            Some(Task::Reading { since, .. }) => *since,
            _ => {
                let since = Instant::now();
                computer.turn = Some(Task::Reading { key, since });
                since
            }
        };
        if since.elapsed() >= pace.0 {
            turn_commands.write(TurnCommand::Continue);
            computer.turn = None;
        }
        return;
    }
    // The verdict was continued: what the computer read is done with.
    if matches!(computer.turn, Some(Task::Reading { .. })) {
        computer.turn = None;
    }
    let name = game.name(seat).to_owned();
    match computer.turn.take() {
        None => {
            computer.doing = Some(format!("{name} ({level}) is thinking"));
            computer.turn = Some(think(game.rack().clone(), &solver, level, key));
        }
        Some(Task::Thinking {
            key,
            seed,
            level,
            handle,
        }) if handle.is_finished() => {
            match outcome(handle) {
                Ok(decision) => {
                    if let Decision::Shoot(plan) = &decision {
                        show_plan(
                            plan,
                            &solver,
                            &spec,
                            HandRule::of(next.cue_ball),
                            &mut shot_settings,
                            &mut cue_ball,
                        );
                        if plan.call != game.call {
                            turn_commands.write(TurnCommand::Call(plan.call));
                        }
                    }
                    computer.doing =
                        Some(format!("{name} ({level}): {}", describe(&decision, &view)));
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
            }
        }
        Some(Task::Showing {
            key,
            seed,
            level,
            decision,
            since,
        }) if since.elapsed() >= pace.0 => match decision {
            Decision::Choose { choice, .. } => {
                turn_commands.write(TurnCommand::Choose(choice));
            }
            Decision::Shoot(plan) => {
                let shot =
                    plan.executed(level.execution_noise(), solver.simulation().params(), seed);
                shots.write(ShotRequested::from(shot));
                computer.fired = Some((key, Instant::now()));
            }
        },
        task => computer.turn = task,
    }
}

/// A finished decision thread's answer; a panic is said as such, not as a rules error.
fn outcome(handle: JoinHandle<Result<Decision, AiError>>) -> Result<Decision, String> {
    handle
        .join()
        .map_err(|_| "the decision thread panicked".to_owned())?
        .map_err(|e| e.to_string())
}

/// Puts the plan on the table as a human's aim shows: the cue ball in hand where it goes, and
/// the cue's angle, power and tip (the aiming aid and the cue follow them).
fn show_plan(
    plan: &Plan,
    solver: &Solver,
    spec: &TableSpec,
    rule: Option<HandRule>,
    shot_settings: &mut ShotSettings,
    cue_ball: &mut Query<(&Ball, &mut BallMotion), Without<Pocketed>>,
) {
    if let Some(at) = plan.place
        && let Some(rule) = rule
        && let Some((_, mut motion)) = cue_ball.iter_mut().find(|(b, _)| b.number == 0)
        && let Err(error) = place_ball_in_hand(solver, spec, &mut motion, to_dvec(at), rule)
    {
        warn!("computer's cue ball placement refused: {error}");
    }
    shot_settings.angle = plan.shot.angle.rem_euclid(std::f64::consts::TAU);
    shot_settings.power = plan.shot.speed;
    shot_settings.tip = plan.shot.tip;
    shot_settings.elevation = plan.shot.elevation.to_degrees();
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
    let (Some(game), Some(solver)) = (&rules.game, solver) else {
        computer.hint_task = None;
        return;
    };
    let key = game.turn_key();
    if asked && status.at_rest && computer.hint_task.is_none() {
        computer.hint = Some((key, Hint::Thinking));
        computer.hint_task = Some(think(game.rack().clone(), &solver, HINT_LEVEL, key));
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
            if let Decision::Shoot(plan) = &decision {
                show_plan(
                    plan,
                    &solver,
                    &spec,
                    HandRule::of(game.next().cue_ball),
                    &mut shot_settings,
                    &mut cue_ball,
                );
                // The hint's call too (a ball and pocket, a safety): the player confirms it by
                // shooting, or changes it.
                if plan.call != Call::None {
                    calls.write(TurnCommand::Call(plan.call));
                }
            }
            Hint::Decided(decision)
        }
        Err(error) => Hint::Failed(error.to_string()),
    };
    computer.hint = Some((key, hint));
}

/// The decision in words, with its success probability; cushions named as `view` shows them.
pub fn describe(decision: &Decision, view: &OrbitCamera) -> String {
    match decision {
        Decision::Choose { choice, estimate } => {
            format!("{} ({:.0} %)", choice.label(), 100.0 * estimate)
        }
        Decision::Shoot(plan) => {
            let what = kind_text(plan.kind, view);
            let call = match plan.call {
                Call::Ball { .. } | Call::None => String::new(),
                other => other.text().map_or(String::new(), |c| format!(", {c}")),
            };
            format!(
                "{what}{call}, {:.0} % to succeed, {:.0} % foul",
                100.0 * plan.success,
                100.0 * plan.foul
            )
        }
    }
}

/// A cushion's name as `view` shows it. The short ones keep the players' "head" and "foot";
/// a long one is named by where it lies on the screen: "left" or "right", and "far" or
/// "near" (in the top view "top" or "bottom"). The rules' "left" (seen from the head end)
/// read as the top rail in the top view (issue 28, item 10).
pub fn cushion_name(cushion: Cushion, view: &OrbitCamera) -> &'static str {
    match cushion {
        Cushion::Head => return "head",
        Cushion::Foot => return "foot",
        Cushion::Left | Cushion::Right => {}
    }
    let outward = -cushion.inward_normal();
    // The camera's forward and right on the table, in the solver's axes (yaw 0 looks along
    // the solver's +y, with its +x to the right).
    let yaw = f64::from(view.yaw);
    let forward = Vec2::new(-yaw.sin(), yaw.cos());
    let right = Vec2::new(yaw.cos(), yaw.sin());
    let (ahead, aside) = (outward.dot(forward), outward.dot(right));
    let top = view.mode == CameraMode::Top;
    match (aside.abs() >= ahead.abs(), aside > 0.0, ahead > 0.0, top) {
        (true, true, _, _) => "right",
        (true, false, _, _) => "left",
        (false, _, true, true) => "top",
        (false, _, true, false) => "far",
        (false, _, false, true) => "bottom",
        (false, _, false, false) => "near",
    }
}

fn kind_text(kind: ShotKind, view: &OrbitCamera) -> String {
    let cushion = |c: Cushion| cushion_name(c, view);
    match kind {
        ShotKind::Break => "the break".to_owned(),
        ShotKind::Pot { ball, pocket } => format!("the {ball} in the {}", pocket_name(pocket)),
        ShotKind::Bank {
            ball,
            pocket,
            cushion: c,
        } => format!(
            "the {ball} off the {} cushion in the {}",
            cushion(c),
            pocket_name(pocket)
        ),
        ShotKind::Kick {
            ball,
            pocket,
            cushion: c,
        } => format!(
            "a kick off the {} cushion, the {ball} in the {}",
            cushion(c),
            pocket_name(pocket)
        ),
        ShotKind::Combo {
            first,
            ball,
            pocket,
        } => format!(
            "the {first} into the {ball}, in the {}",
            pocket_name(pocket)
        ),
        ShotKind::Safety { ball } => format!("a safety on the {ball}"),
        ShotKind::PushOut => "a push out".to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The long cushions are named as the screen shows them: from the default view behind the
    /// head rail the rules' left cushion is on the left; in the top view (head rail on the
    /// left) it is the top one; seen from the foot end, sides swap.
    #[test]
    fn long_cushions_are_named_as_the_view_shows_them() {
        let behind_head = OrbitCamera::default();
        assert_eq!(cushion_name(Cushion::Left, &behind_head), "left");
        assert_eq!(cushion_name(Cushion::Right, &behind_head), "right");
        assert_eq!(cushion_name(Cushion::Head, &behind_head), "head");
        let top = OrbitCamera::top_view();
        assert_eq!(cushion_name(Cushion::Left, &top), "top");
        assert_eq!(cushion_name(Cushion::Right, &top), "bottom");
        assert_eq!(cushion_name(Cushion::Foot, &top), "foot");
        let behind_foot = OrbitCamera {
            yaw: behind_head.yaw + std::f32::consts::PI,
            ..behind_head
        };
        assert_eq!(cushion_name(Cushion::Left, &behind_foot), "right");
        // Looking across the table from the right long cushion, the left one is far.
        let across = OrbitCamera {
            yaw: 0.0,
            ..behind_head
        };
        assert_eq!(cushion_name(Cushion::Left, &across), "far");
        assert_eq!(cushion_name(Cushion::Right, &across), "near");
    }
}
