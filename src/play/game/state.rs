//! The rules' state in the game: the match in play, the turn, the player's commands.

use bevy::prelude::*;
use billiards_ai::Level;
use billiards_rules::{
    Call, CallRule, Choice, CueBall, Game, GameLog, GameState, Group, Match, NextShot, Outcome,
    RackStyle, Seat, Verdict,
};

pub use super::live::LiveGame;
pub use super::turn::Turn;
use crate::settings::TableSetup;

/// A game the player can start: one of pool's, or snooker.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GameChoice {
    /// 8-ball, 9-ball, 10-ball or free play ([`Game`]).
    Pool(Game),
    /// A game of the catalog played behind the one interface alone, by its id
    /// ([`billiards_rules::catalog::find`]): snooker, three-cushion.
    Catalog(&'static str),
}

impl GameChoice {
    /// Every choice, in the dialog's order.
    pub const ALL: [GameChoice; 6] = [
        GameChoice::Pool(Game::NineBall),
        GameChoice::Pool(Game::TenBall),
        GameChoice::Pool(Game::EightBall),
        GameChoice::Catalog("snooker"),
        GameChoice::Catalog("three-cushion"),
        GameChoice::Pool(Game::FreePlay),
    ];

    /// The player's name for it.
    pub fn label(self) -> &'static str {
        match self {
            GameChoice::Pool(Game::NineBall) => "9-ball",
            GameChoice::Pool(Game::TenBall) => "10-ball",
            GameChoice::Pool(Game::EightBall) => "8-ball",
            GameChoice::Pool(Game::FreePlay) => "free play",
            GameChoice::Catalog(id) => {
                billiards_rules::catalog::find(id).map_or("unknown game", |entry| entry.label)
            }
        }
    }

    /// What the match's length counts ("race to", "best of", "points to") and its usual
    /// length.
    pub fn length(self) -> (&'static str, u32) {
        match self {
            GameChoice::Catalog(id) => billiards_rules::catalog::find(id)
                .map_or(("race to", 3), |e| (e.length_unit, e.default_length)),
            _ => ("race to", 3),
        }
    }

    /// What the length is in: "racks", "frames", "points".
    pub fn length_noun(self) -> &'static str {
        match self {
            GameChoice::Catalog(id) => {
                billiards_rules::catalog::find(id).map_or("racks", |e| e.length_noun)
            }
            _ => "racks",
        }
    }
}

impl From<Game> for GameChoice {
    fn from(game: Game) -> Self {
        GameChoice::Pool(game)
    }
}

/// Starts a new game (the dialog's Start).
#[derive(Message, Debug, Clone, PartialEq, Eq)]
pub struct NewGameRequested {
    /// The game; free play is the sandbox (no match).
    pub game: GameChoice,
    /// The players' names.
    pub players: [String; 2],
    /// The match's length in the game's own unit ([`GameChoice::length`]): racks to win,
    /// frames best of (snooker), points to reach (three-cushion).
    pub race_to: u32,
    /// The seed of the first rack's gaps (each later rack takes the next seed).
    pub seed: u64,
    /// Each seat's computer level; `None`: a human.
    pub computer: [Option<Level>; 2],
    /// The table and the rack style.
    pub setup: TableSetup,
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
    /// Snooker: the striker concedes the frame (2.1(a)); any game that has a concession.
    Concede,
    /// Take option `index` of the turn ([`billiards_rules::Turn::choices`]): a game behind
    /// the interface.
    ChooseOption(usize),
    /// Declare this for the next stroke: a game behind the interface.
    Declare(billiards_rules::Declaration),
    /// The rack is over: rack the next one of the match.
    NextRack,
}

/// The rules side of the live game: all `None` in free play, at most one set.
#[derive(Resource, Debug, Default)]
pub struct Rules {
    /// The pool match in play, if any.
    pub game: Option<GameInPlay>,
    /// A match of any other game, behind the one interface, if any.
    pub live: Option<LiveGame>,
}

impl Rules {
    /// Whether a match (of any game) is in play.
    pub fn in_match(&self) -> bool {
        self.game.is_some() || self.live.is_some()
    }

    /// No match: free play.
    pub fn clear(&mut self) {
        self.game = None;
        self.live = None;
    }

    /// The match's next player: whether the computer plays that seat (its level, `None` for
    /// a human) and whether choices are offered first; `None` in free play.
    pub fn to_play(&self) -> Option<(Option<Level>, bool)> {
        if let Some(game) = &self.live {
            let turn = game.rules.turn();
            return Some((game.computer(turn.striker), !turn.choices.is_empty()));
        }
        let game = self.game.as_ref()?;
        let next = game.next();
        Some((game.computer(next.shooter), !next.choices.is_empty()))
    }
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
    /// The call the aim proposed when the dialog opened, for the player to confirm.
    pub proposed: Option<Call>,
    /// The last verdict, and whether it is still shown (waiting for Continue).
    pub last: Option<Verdict>,
    /// The last verdict waits for the player.
    pub verdict_shown: bool,
    /// The last foul's reason, kept until a later foul.
    pub last_foul: Option<String>,
    /// What the last shot did: the balls pocketed and where, a called ball's fate
    /// ([`billiards_rules::what_happened`]).
    pub last_what: Option<String>,
    /// Choices taken since the last shot (logged with the next one).
    pub(super) choices: Vec<Choice>,
    /// Each seat's computer level; `None`: a human.
    pub seats: [Option<Level>; 2],
    /// How this match's racks are set.
    pub rack_style: RackStyle,
}

impl GameInPlay {
    /// The verdict and what the shot did: "legal: the 7 in the right side pocket", "foul:
    /// the cue ball was pocketed; the 3 in the foot-left corner, the cue ball in ...".
    pub fn verdict_text(&self, verdict: &Verdict) -> String {
        match &self.last_what {
            Some(what) if !what.is_empty() => format!("{}: {what}", verdict.reason()),
            _ => verdict.reason(),
        }
    }

    /// Whether a human plays in this match (a verdict then waits for them to continue).
    pub fn has_human(&self) -> bool {
        self.seats.iter().any(Option::is_none)
    }

    /// Who shoots next and what they may do with the cue ball: "Ann shoots next, with ball
    /// in hand anywhere on the table".
    pub fn next_text(&self) -> String {
        let next = self.next();
        let who = match self.computer(next.shooter) {
            Some(_) => format!("{} (computer)", self.name(next.shooter)),
            None => self.name(next.shooter).to_owned(),
        };
        let hand = match next.cue_ball {
            CueBall::InHandAnywhere => ", with ball in hand anywhere on the table",
            CueBall::InHandBehindHeadString => ", with ball in hand behind the head string",
            CueBall::AsItLies | CueBall::Respot => " from where the cue ball lies",
        };
        format!("{who} shoots next{hand}")
    }

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
    /// to do, the ball on, groups and balls left, fouls in a row, the last foul. `dropped`:
    /// the balls the shot in play has pocketed so far, counted off the balls left at once
    /// (the rack's own list changes only with the verdict).
    pub fn hud_lines(&self, turn: Turn, dropped: &[u8]) -> Vec<String> {
        let play = &self.play;
        let rack = self.rack();
        let next = self.next();
        let game = match play.game {
            Game::NineBall => "9-ball",
            Game::TenBall => "10-ball",
            Game::EightBall => "8-ball",
            Game::FreePlay => "free play",
        };
        // The computer's seat marked from the start (issue 48), not only on its turn.
        let seat = |s: Seat| match self.computer(s) {
            Some(_) => format!("{} (computer)", play.name(s)),
            None => play.name(s).to_owned(),
        };
        let mut lines = vec![format!(
            "{game}, race to {}: {} {} - {} {}",
            play.race_to,
            seat(Seat::A),
            play.score[0],
            play.score[1],
            seat(Seat::B),
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
            lines.push(format!(
                "ball on: {}",
                billiards_rules::pool::ball_on_text(rack, next)
            ));
        }
        if play.game == Game::EightBall {
            lines.push(match rack.group(Seat::A) {
                None => "open table".to_owned(),
                Some(_) => [Seat::A, Seat::B]
                    .map(|seat| {
                        let group = rack.group(seat).unwrap_or(Group::Solids);
                        let left = rack
                            .on_table
                            .iter()
                            .filter(|&&b| group.contains(b) && !dropped.contains(&b))
                            .count();
                        format!("{}: {} ({left} left)", self.name(seat), group.name())
                    })
                    .join(", "),
            });
        } else {
            let left = rack.on_table.iter().filter(|b| !dropped.contains(b));
            lines.push(format!("balls left: {}", left.count()));
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
                self.verdict_text(verdict)
            ));
        }
        if let Some(foul) = &self.last_foul {
            lines.push(format!("last foul: {foul}"));
        }
        lines
    }
}

fn choices_text(choices: &[Choice]) -> String {
    choices
        .iter()
        .map(|&c| c.label())
        .collect::<Vec<_>>()
        .join(" or ")
}

/// The game to start at launch (`--game`), two players, race to 3.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StartGame {
    /// The game.
    pub game: GameChoice,
    /// The second seat's computer level (`--computer`); `None`: two humans.
    pub computer: Option<Level>,
    /// The first rack's seed (`--seed`); `None`: from the clock.
    pub seed: Option<u64>,
}

/// Whether the new-game dialog is open.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct DialogOpen(pub bool);

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
