//! One rack of a game: its state, the shot's verdict and what the next shot must respect.
//!
//! The rulesets are one closed enum, [`Game`], rather than a trait: there are four games,
//! each `match` over them is checked for exhaustiveness, and the whole state (a plain value)
//! can be saved with a recording and compared when it is verified, which trait objects make
//! awkward. The per-game logic lives in [`crate::nine_ball`], [`crate::ten_ball`] and
//! [`crate::eight_ball`].
//!
//! Flow for a caller (the game, the command line): read [`GameState::next`]; if it offers
//! [`NextShot::choices`], the [`NextShot::shooter`] picks one with [`GameState::choose`];
//! prepare the table as it says (re-rack, spot balls, cue ball in hand); strike; run the
//! solver to rest; summarise the events ([`crate::summarise`]); [`GameState::play`] returns
//! the [`Verdict`] and moves the state on.
//!
//! Rules followed: the WPA World Standardized Rules, "Rules of Play", in the numbering of the
//! edition effective 1 January 2008 (section 2 nine ball, 3 eight ball, 6 fouls, 8
//! definitions), and its section 9 ten ball, in force from 1 January 2009; see the crate
//! README for the rules covered and left out.
//!
//! This file is the dispatcher: [`GameState::play`] and [`GameState::choose`] hand a shot to
//! the rules of its game. The words they share live below it, in [`crate::state`] and
//! [`crate::turn`], which the games import instead of this file (issue 50: a dispatcher is
//! never imported back by what it calls); they are re-exported here, where they always were.

pub use crate::state::{Game, GameState, RuleError};
pub use crate::turn::{
    Call, CallRule, Choice, CueBall, NextShot, Outcome, Seat, Verdict, what_happened,
};

use crate::shot::ShotSummary;
use crate::state::Pending;

impl GameState {
    /// A new rack of `game` broken by `breaker`.
    pub fn new(game: Game, breaker: Seat) -> Self {
        let on_table = game.object_balls();
        let cue_ball = match game {
            Game::FreePlay => CueBall::AsItLies,
            _ => CueBall::InHandBehindHeadString,
        };
        let legal_first = match game {
            // WPA 2.3 / 9.3 with 6.2: the 1 (the lowest) first.
            Game::NineBall | Game::TenBall => vec![1],
            _ => on_table.clone(),
        };
        let next = NextShot {
            break_shot: game != Game::FreePlay,
            ..NextShot::plain(breaker, cue_ball, legal_first, CallRule::NotUsed, 0)
        };
        Self {
            game,
            breaker,
            group_a: None,
            fouls: [0; 2],
            on_table,
            next,
            over: None,
            pending: None,
        }
    }

    /// A rack in progress (a drill, a shared position): `on_table` the object balls left,
    /// `shooter` at the table with the cue ball as it lies, no fouls, an open table in
    /// 8-ball, the lowest ball on in 9-ball (WPA 6.2).
    pub fn in_progress(game: Game, shooter: Seat, mut on_table: Vec<u8>) -> Self {
        on_table.sort_unstable();
        on_table.dedup();
        let mut state = Self::new(game, shooter);
        state.on_table = on_table;
        state.next = match game {
            Game::NineBall => crate::nine_ball::normal_next(&state, shooter, CueBall::AsItLies),
            Game::TenBall => crate::ten_ball::normal_next(&state, shooter, CueBall::AsItLies),
            Game::EightBall => crate::eight_ball::normal_next(&state, shooter, CueBall::AsItLies),
            Game::FreePlay => NextShot::plain(
                shooter,
                CueBall::AsItLies,
                state.on_table.clone(),
                CallRule::NotUsed,
                0,
            ),
        };
        state
    }

    /// Judges one shot played under [`GameState::next`] and moves the state on. Refused
    /// (state unchanged) while a choice is pending, once the game is over, or for a call the
    /// shot does not allow.
    pub fn play(&mut self, shot: &ShotSummary, call: Call) -> Result<Verdict, RuleError> {
        if self.over.is_some() {
            return Err(RuleError::GameOver);
        }
        if !self.next.choices.is_empty() {
            return Err(RuleError::ChoicePending(self.next.choices.clone()));
        }
        if let Some(b) = shot
            .pocketed_object_balls()
            .find(|b| !self.on_table.contains(b))
        {
            return Err(RuleError::UnknownBall(b));
        }
        let verdict = match self.game {
            Game::NineBall => crate::nine_ball::play(self, shot, call)?,
            Game::TenBall => crate::ten_ball::play(self, shot, call)?,
            Game::EightBall => crate::eight_ball::play(self, shot, call)?,
            Game::FreePlay => self.free_play(shot, call)?,
        };
        if let Outcome::GameOver { winner, reason } = verdict.outcome {
            self.over = Some((winner, reason));
        }
        if let Some(next) = &verdict.next {
            self.next = next.clone();
        }
        Ok(verdict)
    }

    /// Takes one of the [`NextShot::choices`] offered; returns the next shot it leads to.
    pub fn choose(&mut self, choice: Choice) -> Result<NextShot, RuleError> {
        if self.over.is_some() {
            return Err(RuleError::GameOver);
        }
        if !self.next.choices.contains(&choice) {
            return Err(RuleError::ChoiceNotOffered {
                choice,
                offered: self.next.choices.clone(),
            });
        }
        let chooser = self.next.shooter;
        let pending = self.pending.take();
        let next = match (pending, choice) {
            (_, Choice::RerackAndBreak) => self.rerack(chooser),
            (Some(Pending::IllegalBreak { breaker, .. }), Choice::RerackOpponentBreaks) => {
                self.rerack(breaker)
            }
            (Some(Pending::IllegalBreak { scratched, .. }), Choice::ShootFromHere) => {
                let cue_ball = if scratched {
                    CueBall::InHandBehindHeadString
                } else {
                    CueBall::AsItLies
                };
                crate::eight_ball::normal_next(self, chooser, cue_ball)
            }
            (Some(Pending::EightOnBreak { foul, .. }), Choice::SpotEightAndShoot) => {
                self.put_back(8);
                // WPA 3.3: after a foul, ball in hand behind the head string.
                let cue_ball = if foul {
                    CueBall::InHandBehindHeadString
                } else {
                    CueBall::AsItLies
                };
                let mut next = crate::eight_ball::normal_next(self, chooser, cue_ball);
                next.spot = vec![8];
                next
            }
            (Some(Pending::PushOut { .. } | Pending::HandBack { .. }), Choice::ShootFromHere) => {
                self.rotation_next(chooser)
            }
            (
                Some(Pending::PushOut { pusher: back } | Pending::HandBack { shooter: back }),
                Choice::PassBack,
            ) => self.rotation_next(back),
            (pending, _) => {
                // Unreachable: the choices offered always match the pending decision.
                self.pending = pending;
                return Err(RuleError::ChoiceNotOffered {
                    choice,
                    offered: self.next.choices.clone(),
                });
            }
        };
        self.next = next.clone();
        Ok(next)
    }

    /// The ordinary next shot of `shooter` in a rotation game (9-ball, 10-ball), the cue
    /// ball as it lies: after a push out (WPA 2.4, 9.4) or 10-ball's option (9.7).
    fn rotation_next(&self, shooter: Seat) -> NextShot {
        match self.game {
            Game::TenBall => crate::ten_ball::normal_next(self, shooter, CueBall::AsItLies),
            _ => crate::nine_ball::normal_next(self, shooter, CueBall::AsItLies),
        }
    }

    /// A fresh rack broken by `breaker`, with the fouls of the match kept.
    fn rerack(&mut self, breaker: Seat) -> NextShot {
        let fouls = self.fouls;
        *self = GameState::new(self.game, breaker);
        self.fouls = fouls;
        self.next.rerack = true;
        self.next.clone()
    }

    /// Free play: never a foul, the shooter stays, a scratch (or the cue ball off the table)
    /// respots the cue ball; object balls off the table stay off.
    fn free_play(&mut self, shot: &ShotSummary, call: Call) -> Result<Verdict, RuleError> {
        if call != Call::None {
            return Err(RuleError::CallNotUsed(Game::FreePlay, "calls"));
        }
        self.take_off(shot);
        let shooter = self.next.shooter;
        let cue_ball = if shot.scratch() || shot.cue_off_table() {
            CueBall::Respot
        } else {
            CueBall::AsItLies
        };
        let next = NextShot::plain(
            shooter,
            cue_ball,
            self.on_table.clone(),
            CallRule::NotUsed,
            0,
        );
        Ok(Verdict {
            shooter,
            break_shot: false,
            push_out: false,
            fouls: Vec::new(),
            outcome: Outcome::Continues,
            assigned: None,
            next: Some(next),
        })
    }
}
