//! The rules in the game: a match of 8-ball or 9-ball (`billiards-rules`), or free play, and
//! the turn's phase as a Bevy sub-state of [`GameMode::Play`].
//!
//! One source of truth: the [`Rules`] resource (the match, the call, whether a verdict or the
//! call dialog is up). Every frame, in [`SimSystems::Flow`]:
//! 1. `judge_shot`: on [`ShotFinished`], the shot's events (from its strike on) are
//!    summarised ([`billiards_rules::summarise`]) and judged ([`Match::play`]); the verdict is
//!    logged ([`GameLog`], saved beside the autosaved recording) and the table prepared for
//!    the next shot (balls spotted, the cue ball back on the table, a new rack);
//! 2. `apply_commands`: the player's [`TurnCommand`]s and [`NewGameRequested`];
//! 3. `follow_rules`: derives the [`Turn`] from the resource, the cue ball in hand
//!    ([`SimStatus::ball_in_hand`]) from the next shot, and tells the simulation's
//!    [`Referee`] whether a shot may be taken now.
//!
//! Free play has no match: the turn is [`Turn::Aiming`] or [`Turn::ShotInPlay`], and a
//! scratch is respotted by the simulation as before.
//!
//! [`table_plugin`] adds what needs a window: the legal area of the cue ball in hand, the
//! pockets while calling and the called pocket (gizmos), and the click on a pocket.

use std::time::{SystemTime, UNIX_EPOCH};

use bevy::{math::DVec2, prelude::*};
use billiards_ai::Level;
use billiards_physics::{Pocket, Rack};
use billiards_rules::{
    Call, CallRule, Choice, CueBall, Game, GameLog, GameState, Group, LoggedShot, Match, NextShot,
    Outcome, Seat, Verdict, summarise,
};

use crate::{
    balls::BallMotion,
    cue::PointerInput,
    geometry::{TableSpec, to_world},
    input::{AimLocked, InputSystems},
    mode::GameMode,
    recording::{RecordingsFolder, game_file},
    settings::PhysicsSettings,
    sim::{
        LayoutRequested, RackRequested, Referee, ShotFinished, SimStatus, SimSystems, Solver,
        params_from, respot_ball, table_for,
    },
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
            (judge_shot, apply_commands, follow_rules)
                .chain()
                .in_set(SimSystems::Flow)
                .after(crate::sim::respot_after_scratch),
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

/// The phase of the turn, while the live game is shown.
#[derive(SubStates, Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[source(GameMode = GameMode::Play)]
pub enum Turn {
    /// The new-game dialog is open: game, players, race.
    NewGame,
    /// Aim and shoot (a call may be made first in 8-ball; the break is a shot too).
    #[default]
    Aiming,
    /// The cue ball is in hand: drag it where the rules allow, then aim and shoot.
    BallInHand,
    /// Calling a pocket: click it on the table.
    Calling,
    /// The balls are moving.
    ShotInPlay,
    /// The last shot's verdict is shown; continue, or take one of the options offered.
    Verdict,
    /// The rack is over: next rack, or a new game once the match is won.
    GameOver,
}

/// Starts a new game (the dialog's Start).
#[derive(Message, Debug, Clone, PartialEq, Eq)]
pub struct NewGameRequested {
    /// The game; [`Game::FreePlay`] is the sandbox (no match).
    pub game: Game,
    /// The players' names.
    pub players: [String; 2],
    /// Racks needed to win the match.
    pub race_to: u32,
    /// The seed of the first rack's gaps (each later rack takes the next seed).
    pub seed: u64,
    /// Each seat's computer level; `None`: a human.
    pub computer: [Option<Level>; 2],
}

/// What the player does between shots.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub enum TurnCommand {
    /// Open the new-game dialog.
    OpenDialog,
    /// Close it without a new game.
    CloseDialog,
    /// The verdict has been read: on to the next shot.
    Continue,
    /// Take one of the options offered ([`NextShot::choices`]).
    Choose(Choice),
    /// Start calling a pocket (click it on the table).
    StartCalling,
    /// The ball to call (8-ball, an optional call).
    CallBall(u8),
    /// Make this call for the next shot (a pocket, a safety, a push out, or none).
    Call(Call),
    /// The rack is over: rack the next one of the match.
    NextRack,
}

/// The rules side of the live game: `None` in free play.
#[derive(Resource, Debug, Default)]
pub struct Rules {
    /// The match in play, if any.
    pub game: Option<GameInPlay>,
}

/// A match in play and what the players did since the last shot.
#[derive(Debug, Clone)]
pub struct GameInPlay {
    /// The match: players, race, score and the rack in play.
    pub play: Match,
    /// The rack's log (calls, choices, verdicts), saved beside its recording.
    pub log: GameLog,
    /// The seed of the rack in play.
    pub seed: u64,
    /// The call for the next shot.
    pub call: Call,
    /// The ball the player is calling (8-ball optional calls); the 8 when it is on.
    pub call_ball: Option<u8>,
    /// The call dialog is open.
    pub calling: bool,
    /// The last verdict, and whether it is still shown (waiting for Continue).
    pub last: Option<Verdict>,
    /// The last verdict waits for the player.
    pub verdict_shown: bool,
    /// The last foul's reason, kept until a later foul.
    pub last_foul: Option<String>,
    /// Choices taken since the last shot (logged with the next one).
    choices: Vec<Choice>,
    /// Each seat's computer level; `None`: a human.
    pub seats: [Option<Level>; 2],
}

impl GameInPlay {
    /// What the next shot must respect.
    pub fn next(&self) -> &NextShot {
        self.play.next()
    }

    /// The rack in play.
    pub fn rack(&self) -> &GameState {
        &self.play.rack
    }

    /// The name of `seat`.
    pub fn name(&self, seat: Seat) -> &str {
        self.play.name(seat)
    }

    /// The computer's level at `seat`, `None` for a human.
    pub fn computer(&self, seat: Seat) -> Option<Level> {
        self.seats[seat.index()]
    }

    /// Which turn this is: the rack's seed, the shots and the choices so far.
    pub fn turn_key(&self) -> (u64, usize, usize) {
        (self.seed, self.log.shots.len(), self.choices.len())
    }

    /// The lines of the HUD for this game in phase `turn`: the match, whose turn and what
    /// to do, the ball on, groups and balls left, fouls in a row, the last foul.
    pub fn hud_lines(&self, turn: Turn) -> Vec<String> {
        let play = &self.play;
        let rack = self.rack();
        let next = self.next();
        let game = match play.game {
            Game::NineBall => "9-ball",
            Game::EightBall => "8-ball",
            Game::FreePlay => "free play",
        };
        let mut lines = vec![format!(
            "{game}, race to {}: {} {} - {} {}",
            play.race_to,
            play.name(Seat::A),
            play.score[0],
            play.score[1],
            play.name(Seat::B),
        )];
        let shooter = self.name(next.shooter);
        let doing = match turn {
            Turn::NewGame => "new game: choose the game and the players".to_owned(),
            // The next shot is the one in play until its verdict.
            Turn::ShotInPlay => format!("{shooter} shot: balls moving"),
            Turn::GameOver => match (rack.over, play.winner()) {
                (Some((winner, reason)), Some(_)) => format!(
                    "{} wins the rack and the match: {reason}",
                    self.name(winner)
                ),
                (Some((winner, reason)), None) => {
                    format!("{} wins the rack: {reason}", self.name(winner))
                }
                (None, _) => "the rack is over".to_owned(),
            },
            Turn::Verdict if !next.choices.is_empty() => {
                format!("{shooter} to choose: {}", choices_text(&next.choices))
            }
            Turn::Verdict => format!("{shooter} to shoot next: continue"),
            Turn::Calling => match next.call {
                CallRule::EightPocket => format!("{shooter} calls the 8: click a pocket"),
                _ => format!("{shooter} calls a ball and a pocket: click the pocket"),
            },
            // The computer's turn: no instructions meant for a human at the mouse (its plan
            // follows on the next line of the HUD).
            Turn::BallInHand | Turn::Aiming if let Some(level) = self.computer(next.shooter) => {
                format!(
                    "{shooter} (computer, {level}) to {}",
                    if next.break_shot { "break" } else { "shoot" }
                )
            }
            Turn::BallInHand => format!(
                "{shooter} to {}: ball in hand {}, drag the cue ball, aim and shoot",
                if next.break_shot { "break" } else { "shoot" },
                match next.cue_ball {
                    CueBall::InHandBehindHeadString => "behind the head string",
                    _ => "anywhere",
                }
            ),
            Turn::Aiming => format!(
                "{shooter} to {}: aim and shoot",
                if next.break_shot { "break" } else { "shoot" }
            ),
        };
        lines.push(doing);
        if rack.over.is_none() && !next.break_shot {
            lines.push(format!("ball on: {}", ball_on_text(rack, next)));
        }
        if play.game == Game::EightBall {
            lines.push(match rack.group(Seat::A) {
                None => "open table".to_owned(),
                Some(_) => [Seat::A, Seat::B]
                    .map(|seat| {
                        let group = rack.group(seat).unwrap_or(Group::Solids);
                        let left = rack.on_table.iter().filter(|&&b| group.contains(b)).count();
                        format!("{}: {} ({left} left)", self.name(seat), group.name())
                    })
                    .join(", "),
            });
        } else {
            lines.push(format!("balls left: {}", rack.on_table.len()));
        }
        match self.call {
            Call::None => {}
            Call::PushOut => lines.push("call: push out".to_owned()),
            Call::Safety => lines.push("call: safety".to_owned()),
            Call::Ball { ball, pocket } => lines.push(format!(
                "call: the {ball} in the {}",
                billiards_rules::pocket_name(pocket)
            )),
        }
        lines.push(format!(
            "fouls in a row: {} {}, {} {}",
            play.name(Seat::A),
            rack.fouls[0],
            play.name(Seat::B),
            rack.fouls[1]
        ));
        if let Some(verdict) = &self.last {
            lines.push(format!(
                "last shot ({}): {}",
                self.name(verdict.shooter),
                verdict.reason()
            ));
        }
        if let Some(foul) = &self.last_foul {
            lines.push(format!("last foul: {foul}"));
        }
        lines
    }
}

fn ball_on_text(rack: &GameState, next: &NextShot) -> String {
    match (rack.game, next.legal_first.as_slice()) {
        (_, []) => "none".to_owned(),
        (_, [one]) => format!("the {one}"),
        (Game::EightBall, _) if rack.group(next.shooter).is_none() => {
            "any ball but the 8 (open table)".to_owned()
        }
        (Game::EightBall, _) => format!(
            "the {}",
            rack.group(next.shooter).map_or("group", Group::name)
        ),
        (_, many) => format!("any of {many:?}"),
    }
}

fn choices_text(choices: &[Choice]) -> String {
    choices
        .iter()
        .map(|&c| c.label())
        .collect::<Vec<_>>()
        .join(" or ")
}

/// The phase the game is in, from the rules, the flags and the table.
fn phase(rules: &Rules, status: &SimStatus, dialog: bool) -> Turn {
    if dialog {
        return Turn::NewGame;
    }
    if !status.at_rest {
        return Turn::ShotInPlay;
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

/// The rack of `game` from `seed`, asked of the simulation.
fn rack_request(
    game: Game,
    seed: u64,
    spec: &TableSpec,
    settings: &PhysicsSettings,
) -> LayoutRequested {
    let table = table_for(spec, settings);
    let params = params_from(settings);
    LayoutRequested {
        balls: game.rack(&table, &params.ball, seed),
        rack: match game {
            Game::NineBall => Rack::NineBall,
            Game::EightBall | Game::FreePlay => Rack::FifteenBall,
        },
    }
}

/// A seed from the clock, for a rack's gaps.
pub fn clock_seed() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64)
}

/// On a finished shot of a rules game: summarise, judge, log, prepare the table.
#[allow(clippy::too_many_arguments)]
fn judge_shot(
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
    game.last = Some(verdict);
    game.verdict_shown = true;
    save_log(game, &solver, &folder, &mut status);
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

/// Writes the rack's log beside its recording (`NAME.game.json`).
fn save_log(game: &GameInPlay, solver: &Solver, folder: &RecordingsFolder, status: &mut SimStatus) {
    let Some(folder) = &folder.0 else { return };
    let path = GameLog::path_beside(&game_file(folder, solver.started(), solver.rack()));
    let result = std::fs::create_dir_all(folder)
        .map_err(|e| e.to_string())
        .and_then(|()| serde_json::to_string_pretty(&game.log).map_err(|e| e.to_string()))
        .and_then(|json| {
            let temporary = path.with_extension("tmp");
            std::fs::write(&temporary, json)
                .and_then(|()| std::fs::rename(&temporary, &path))
                .map_err(|e| e.to_string())
        });
    if let Err(error) = result {
        warn!("game log not saved: {error}");
        status.note = Some(format!("game log not saved: {error}"));
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
        game.seed = game.seed.wrapping_add(1);
        game.log = GameLog::new(
            game.play.game,
            game.seed,
            game.play.players.clone(),
            game.rack().breaker,
        );
        layouts.write(rack_request(game.play.game, game.seed, spec, settings));
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
fn apply_commands(
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
    (spec, settings): (Res<TableSpec>, Res<PhysicsSettings>),
) {
    // A rack from the panel is free play.
    if racks.read().count() > 0 {
        rules.game = None;
    }
    for request in new_games.read() {
        dialog.0 = false;
        if request.game == Game::FreePlay {
            rules.game = None;
            let table = table_for(&spec, &settings);
            let rack = crate::sim::STARTING_RACK;
            layouts.write(LayoutRequested {
                balls: rack.layout(&table, &params_from(&settings).ball),
                rack,
            });
            continue;
        }
        let play = Match::new(
            request.game,
            request.players.clone(),
            request.race_to,
            Seat::A,
        );
        let log = GameLog::new(request.game, request.seed, request.players.clone(), Seat::A);
        layouts.write(rack_request(request.game, request.seed, &spec, &settings));
        rules.game = Some(GameInPlay {
            play,
            log,
            seed: request.seed,
            call: Call::None,
            call_ball: None,
            calling: false,
            last: None,
            verdict_shown: false,
            last_foul: None,
            choices: Vec::new(),
            seats: request.computer,
        });
    }
    for &command in turn_commands.read() {
        match command {
            TurnCommand::OpenDialog => dialog.0 = true,
            TurnCommand::CloseDialog => dialog.0 = false,
            _ => {}
        }
        let Some(game) = rules.game.as_mut() else {
            continue;
        };
        match command {
            TurnCommand::OpenDialog | TurnCommand::CloseDialog => {}
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
                if game.call_ball.is_none() {
                    game.call_ball = match game.next().call {
                        CallRule::EightPocket => Some(8),
                        _ => game.next().legal_first.first().copied(),
                    };
                }
            }
            TurnCommand::CallBall(ball) => game.call_ball = Some(ball),
            TurnCommand::Call(call) => {
                game.call = call;
                game.calling = false;
            }
            TurnCommand::NextRack => {
                if game.play.next_rack().is_ok() {
                    game.seed = game.seed.wrapping_add(1);
                    game.log = GameLog::new(
                        game.play.game,
                        game.seed,
                        game.play.players.clone(),
                        game.rack().breaker,
                    );
                    game.last = None;
                    game.last_foul = None;
                    game.verdict_shown = false;
                    layouts.write(rack_request(game.play.game, game.seed, &spec, &settings));
                }
            }
        }
    }
}

/// The game to start at launch (`--game`), two players, race to 3.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StartGame(pub Game);

fn start_game_at_launch(
    start: Option<Res<StartGame>>,
    mut new_games: MessageWriter<NewGameRequested>,
) {
    if let Some(start) = start {
        new_games.write(NewGameRequested {
            game: start.0,
            players: ["Player 1".to_owned(), "Player 2".to_owned()],
            race_to: 3,
            seed: clock_seed(),
            computer: [None, None],
        });
    }
}

/// Whether the new-game dialog is open.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct DialogOpen(pub bool);

/// Derives the turn, the cue ball in hand and the referee's word from the rules.
fn follow_rules(
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
    let active = rules.game.is_some();
    if referee.active != active || referee.refuse_shot != refuse_shot {
        *referee = Referee {
            active,
            refuse_shot,
        };
    }
    if let Some(game) = &rules.game
        && status.at_rest
    {
        let hand = in_hand(game.next()).filter(|_| game.rack().over.is_none());
        if status.ball_in_hand != hand {
            status.ball_in_hand = hand;
        }
    }
}

/// While calling: a click near a pocket calls it (with the ball chosen, the 8 when it is on).
fn click_pocket(
    input: PointerInput,
    spec: Res<TableSpec>,
    rules: Res<Rules>,
    mut turn_commands: MessageWriter<TurnCommand>,
) {
    let Some(game) = &rules.game else { return };
    if !input.clicked() {
        return;
    }
    let Some(point) = input.table_point(0.0) else {
        return;
    };
    if let Some(pocket) = pocket_near(&spec, point) {
        let ball = match game.next().call {
            CallRule::EightPocket => 8,
            _ => game
                .call_ball
                .or(game.next().legal_first.first().copied())
                .unwrap_or(8),
        };
        turn_commands.write(TurnCommand::Call(Call::Ball { ball, pocket }));
    }
}

/// The pocket whose hole is within a ball's reach of `point`, if any.
pub fn pocket_near(spec: &TableSpec, point: DVec2) -> Option<Pocket> {
    Pocket::ALL
        .into_iter()
        .map(|p| (p, spec.pocket(p).centre.distance(point)))
        .filter(|&(p, d)| d < spec.pocket(p).radius + 3.0 * spec.ball_radius)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(p, _)| p)
}

/// While a pocket is being called, a click on the table calls it and does not also aim; on
/// the computer's turn the pointer does not aim either.
fn lock_aim(turn: Option<Res<State<Turn>>>, rules: Res<Rules>, mut lock: ResMut<AimLocked>) {
    let calling = turn.is_some_and(|t| *t.get() == Turn::Calling);
    let computer = rules
        .game
        .as_ref()
        .is_some_and(|g| g.computer(g.next().shooter).is_some());
    lock.set_if_neq(AimLocked(calling || computer));
}

/// Enter continues after a verdict with no options.
fn confirm_key(
    keys: Res<ButtonInput<KeyCode>>,
    rules: Res<Rules>,
    mut turn_commands: MessageWriter<TurnCommand>,
) {
    if keys.just_pressed(KeyCode::Enter)
        && rules
            .game
            .as_ref()
            .is_some_and(|g| g.next().choices.is_empty())
    {
        turn_commands.write(TurnCommand::Continue);
    }
}

/// The legal area of the cue ball in hand, the pockets while calling, the called pocket.
fn draw_rules(
    rules: Res<Rules>,
    status: Res<SimStatus>,
    spec: Res<TableSpec>,
    turn: Option<Res<State<Turn>>>,
    mut gizmos: Gizmos,
) {
    let Some(game) = &rules.game else { return };
    let Some(turn) = turn.map(|t| *t.get()) else {
        return;
    };
    let lift = 0.003;
    let at = |p: DVec2| to_world(p.extend(lift));
    let flat = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    if turn == Turn::BallInHand
        && let Some(rule) = status.ball_in_hand
    {
        let h = spec.half_extents() - DVec2::splat(spec.ball_radius);
        let right = match rule {
            CueBall::InHandBehindHeadString => spec.head_spot().x,
            _ => h.x,
        };
        let corners = [
            DVec2::new(-h.x, -h.y),
            DVec2::new(right, -h.y),
            DVec2::new(right, h.y),
            DVec2::new(-h.x, h.y),
            DVec2::new(-h.x, -h.y),
        ];
        gizmos.linestrip(corners.map(at), Color::srgb(0.3, 0.9, 1.0));
    }
    if turn == Turn::Calling {
        for pocket in Pocket::ALL {
            let hole = spec.pocket(pocket);
            gizmos
                .circle(
                    Isometry3d::new(at(hole.centre), flat),
                    hole.radius as f32,
                    Color::srgba(1.0, 1.0, 1.0, 0.6),
                )
                .resolution(32);
        }
    }
    if let Call::Ball { pocket, .. } = game.call {
        let hole = spec.pocket(pocket);
        for k in [1.0, 1.15] {
            gizmos
                .circle(
                    Isometry3d::new(at(hole.centre), flat),
                    (hole.radius * k) as f32,
                    Color::srgb(1.0, 0.85, 0.1),
                )
                .resolution(48);
        }
    }
}

/// The outcome in a few words (the timeline, tests).
pub fn outcome_text(play: &Match, outcome: Outcome) -> String {
    match outcome {
        Outcome::Continues => "continues".to_owned(),
        Outcome::Passes => "the turn passes".to_owned(),
        Outcome::GameOver { winner, reason } => {
            format!("{} wins: {reason}", play.name(winner))
        }
    }
}
