//! A drill behind the one game interface ([`GameRules`], issue 50): a one-player game whose
//! "game" is one try at the drill's position and whose "match" is the session of
//! [`Drill::tries`] tries. Each shot is judged by the position's game rules (for the ball on
//! and the calls) and each try by the drill's goals ([`Drill::judge`]); a try ends when the
//! drill says the attempt does not go on ([`Drill::continues`]).

use crate::drill::{Attempt, Drill, DrillScore, DrillShot};
use crate::interface::{
    CueBallPlace, Declaration, Declarations, GameEnd, GameRules, Judgement, RulesError, Setup,
    StrokeRecord, Turn,
};
use crate::shot::CUE;
use crate::state::GameState;
use crate::turn::{Call, Seat};
use billiards_physics::{BallSetup, BallSpec, Table, Vec2};

/// A drill session in play.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct DrillGame {
    /// The drill.
    pub drill: Drill,
    /// The player (seat A) and the drill itself (seat B, which "wins" a missed try).
    pub players: [String; 2],
    /// The balls.
    pub ball: BallSpec,
    /// The position's rules for the try in play (the ball on, calls).
    pub state: GameState,
    /// The shots of the try in play.
    pub shots: Vec<DrillShot>,
    /// The tries judged so far.
    pub score: DrillScore,
    /// The last try's judgement.
    pub last: Option<Attempt>,
}

impl DrillGame {
    /// A session of `drill` for `player` with balls `ball`; refused when the drill is not
    /// one ([`Drill::check`]).
    pub fn new(drill: Drill, player: String, ball: BallSpec) -> Result<Self, RulesError> {
        drill.check().map_err(RulesError::from_display)?;
        let state = drill.game_state();
        Ok(Self {
            drill,
            players: [player, "the drill".to_owned()],
            ball,
            state,
            shots: Vec::new(),
            score: DrillScore::default(),
            last: None,
        })
    }

    /// The try in play has been judged (its end is [`GameRules::end`]); the next one
    /// starts with [`GameRules::next_game`].
    pub fn try_over(&self) -> bool {
        self.last.is_some() && self.shots.is_empty()
    }

    /// Every try of the session taken.
    pub fn session_over(&self) -> bool {
        self.score.tries >= self.drill.tries
    }

    /// "try 3 of 10": the try in play, or the last one while it waits for the next.
    pub fn try_text(&self) -> String {
        let tries = self.drill.tries;
        let k = (self.score.tries + u32::from(!self.try_over())).min(tries);
        format!("try {k} of {tries}")
    }

    fn end_of_try(&self) -> Option<GameEnd> {
        let attempt = self.last.as_ref().filter(|_| self.try_over())?;
        Some(GameEnd {
            winner: if attempt.success { Seat::A } else { Seat::B },
            reason: format!(
                "try {} {} (score {:.0}): {}",
                self.score.tries,
                if attempt.success { "made" } else { "missed" },
                attempt.score,
                attempt.reasons.join("; ")
            ),
            match_over: self.session_over(),
        })
    }
}

impl GameRules for DrillGame {
    fn name(&self) -> &'static str {
        "drill"
    }

    fn players(&self) -> &[String; 2] {
        &self.players
    }

    fn table(&self) -> Table {
        self.drill.position.table
    }

    fn ball(&self) -> BallSpec {
        self.drill.position.params.map_or(self.ball, |p| p.ball)
    }

    fn layout(&self) -> Result<Vec<BallSetup>, RulesError> {
        Ok(self
            .drill
            .position
            .balls
            .iter()
            .map(|b| BallSetup::at(b.number, b.position))
            .collect())
    }

    fn turn(&self) -> Turn {
        let next = &self.state.next;
        Turn {
            striker: Seat::A,
            cue_ball: CUE,
            place: CueBallPlace::AsItLies,
            legal_first: next.legal_first.clone(),
            ball_on: crate::pool::ball_on_text(&self.state, next),
            declare: Declarations {
                pocket: crate::pool::need_of(next.call),
                callable: crate::pool::callable(&self.state, next),
                ..Declarations::default()
            },
            opening: false,
            choices: Vec::new(),
        }
    }

    fn ball_name(&self, ball: u8) -> String {
        if ball == CUE {
            "the cue ball".to_owned()
        } else {
            format!("the {ball}")
        }
    }

    fn choose(&mut self, index: usize, _layout: &[(u8, Vec2)]) -> Result<Setup, RulesError> {
        Err(RulesError(format!("a drill offers no option {index}")))
    }

    fn check_hand(&self, _at: Vec2, _others: &[(u8, Vec2)]) -> Result<(), RulesError> {
        Err(RulesError(
            "a drill is played from its position: no ball in hand".to_owned(),
        ))
    }

    fn judge(&mut self, stroke: &StrokeRecord<'_>) -> Result<Judgement, RulesError> {
        if self.session_over() {
            return Err(RulesError("the session is over".to_owned()));
        }
        if self.try_over() {
            return Err(RulesError(
                "the try is over: start the next one (next_game)".to_owned(),
            ));
        }
        let call = match stroke.declared {
            Declaration::None => Call::None,
            Declaration::Pocket { ball, pocket } => Call::Ball { ball, pocket },
            other => return Err(RulesError(format!("a drill takes no {other:?}"))),
        };
        stroke.check_strike()?;
        let shot = DrillShot::from_events(stroke.events, stroke.numbers, stroke.after.to_vec());
        // The position's rules keep the ball on for the next shot of a run-out; a foul
        // there ends the visit, which the drill's judge reads from the shots.
        let verdict = self.state.play(&shot.summary, call).ok();
        self.shots.push(shot);
        let fouls: Vec<String> = verdict
            .iter()
            .flat_map(|v| v.fouls.iter().map(ToString::to_string))
            .collect();
        if self.drill.continues(&self.shots) {
            return Ok(Judgement {
                striker: Seat::A,
                fair: fouls.is_empty(),
                text: "the try goes on".to_owned(),
                fouls,
                put: Vec::new(),
                continues: true,
                end: None,
            });
        }
        let attempt = self.drill.judge(&self.shots);
        self.score.add(&attempt);
        self.shots.clear();
        self.last = Some(attempt);
        let end = self.end_of_try();
        Ok(Judgement {
            striker: Seat::A,
            fair: fouls.is_empty(),
            text: end.as_ref().map_or(String::new(), |e| e.reason.clone()),
            fouls,
            put: Vec::new(),
            continues: false,
            end,
        })
    }

    fn score_line(&self) -> String {
        format!(
            "drill {}: {} of {} tries made, {} to go, best score {:.0}",
            self.drill.name,
            self.score.successes,
            self.score.tries,
            self.drill.tries.saturating_sub(self.score.tries),
            self.score.best
        )
    }

    fn points(&self) -> [u32; 2] {
        [
            self.score.successes,
            self.score.tries - self.score.successes,
        ]
    }

    fn status(&self) -> Vec<String> {
        self.drill
            .goals
            .iter()
            .map(|g| format!("goal: {}", g.text()))
            .collect()
    }

    fn end(&self) -> Option<GameEnd> {
        self.end_of_try()
    }

    fn solo(&self) -> bool {
        true
    }

    /// The try in play given up after its first shot: counted as a miss (a session's tally
    /// cannot be bettered by walking away from a try that went wrong). Before its first shot
    /// there is nothing to give up: the position is set again instead.
    fn concede(&mut self) -> Result<GameEnd, RulesError> {
        if !self.concedes() {
            return Err(RulesError(
                "no try in play to give up: it has no shot yet".to_owned(),
            ));
        }
        let shots = self.shots.len();
        let attempt = Attempt {
            success: false,
            score: 0.0,
            reasons: vec![format!(
                "given up after {shots} shot{}",
                if shots == 1 { "" } else { "s" }
            )],
            shots,
        };
        self.score.add(&attempt);
        self.shots.clear();
        self.last = Some(attempt);
        self.end_of_try()
            .ok_or_else(|| RulesError("the try did not end".to_owned()))
    }

    fn concedes(&self) -> bool {
        !self.shots.is_empty() && !self.session_over()
    }

    fn match_winner(&self) -> Option<Seat> {
        // A session has no opponent: it ends with the player's tally.
        self.session_over().then_some(Seat::A)
    }

    fn next_game(&mut self) -> Result<Vec<BallSetup>, RulesError> {
        if !self.try_over() || self.session_over() {
            return Err(RulesError(
                "the next try starts once this one is over and tries are left".to_owned(),
            ));
        }
        self.state = self.drill.game_state();
        self.last = None;
        self.layout()
    }

    fn boxed_clone(&self) -> Box<dyn GameRules> {
        Box::new(self.clone())
    }

    fn save(&self) -> Result<serde_json::Value, RulesError> {
        crate::interface::saved("drill", self)
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
