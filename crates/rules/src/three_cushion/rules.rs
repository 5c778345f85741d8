//! Three-cushion behind the one game interface ([`GameRules`], issue 50): a
//! [`ThreeCushionMatch`] is one game to a distance (the match), on the carom table, and turns
//! the UMB rules' own words into the interface's. Added through the interface alone: the
//! command line, the computer and the catalog know nothing else of it.

use super::balls::{Ball, BallIds};
use super::game::{Outcome, Rules, ThreeCushionGame};
use super::layout::Side;
use crate::interface::{
    CueBallPlace, Declaration, Declarations, GameEnd, GameRules, Judgement, RulesError, Setup,
    StrokeRecord, Turn,
};
use crate::turn::Seat;
use billiards_physics::{BallSetup, BallSpec, Table, Vec2};

/// A three-cushion match in play: one game to `target` points.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ThreeCushionMatch {
    /// The game.
    pub game: ThreeCushionGame,
    /// The players' names (A plays the white and opens).
    pub players: [String; 2],
    /// The table.
    pub table: Table,
    /// The balls.
    pub ball: BallSpec,
    /// Art. 27: the striker, frozen to a ball, chose to play on (the choice is not offered
    /// again before the stroke).
    frozen_choice_made: bool,
}

fn err(e: impl std::fmt::Display) -> RulesError {
    RulesError::from_display(e)
}

impl ThreeCushionMatch {
    /// A game to `target` points between `players` on `table` with balls `ball`. Played as
    /// UMB knock-out matches are since 2019, without the equalising inning (Art. 29's
    /// inning is `Rules::equal_innings`): a game then always has a winner.
    pub fn new(
        players: [String; 2],
        target: u32,
        table: Table,
        ball: BallSpec,
    ) -> Result<Self, RulesError> {
        let rules = Rules {
            target,
            equal_innings: false,
            ids: BallIds::default(),
            opening_side: Side::default(),
        };
        let game = ThreeCushionGame::new(rules, &table, ball.radius).map_err(err)?;
        Ok(Self {
            game,
            players,
            table,
            ball,
            frozen_choice_made: false,
        })
    }

    /// [`ThreeCushionMatch::new`] from a position in play ([`ThreeCushionGame::in_progress`]).
    pub fn in_progress(
        players: [String; 2],
        target: u32,
        (table, ball): (Table, BallSpec),
        positions: [Vec2; 3],
        striker: Seat,
    ) -> Result<Self, RulesError> {
        let mut m = Self::new(players, target, table, ball)?;
        let rules = *m.game.rules();
        m.game = ThreeCushionGame::in_progress(rules, &table, ball.radius, positions, striker)
            .map_err(err)?;
        Ok(m)
    }

    /// Whether the striker must first choose: their cue ball is frozen to a ball (Art. 27).
    fn frozen_choice(&self) -> bool {
        !self.frozen_choice_made && self.game.next().is_some_and(|n| !n.frozen_to.is_empty())
    }

    fn number(ball: Ball) -> u8 {
        ball.index() as u8
    }
}

impl GameRules for ThreeCushionMatch {
    fn name(&self) -> &'static str {
        "three-cushion"
    }

    fn players(&self) -> &[String; 2] {
        &self.players
    }

    fn table(&self) -> Table {
        self.table
    }

    fn ball(&self) -> BallSpec {
        self.ball
    }

    fn layout(&self) -> Result<Vec<BallSetup>, RulesError> {
        Ok(self.game.setups())
    }

    fn turn(&self) -> Turn {
        let Some(next) = self.game.next() else {
            // The game is over: the last striker's turn, nothing to play.
            return Turn {
                striker: Seat::A,
                cue_ball: 0,
                place: CueBallPlace::AsItLies,
                legal_first: Vec::new(),
                ball_on: "none: the game is over".to_owned(),
                declare: Declarations::default(),
                opening: false,
                choices: Vec::new(),
            };
        };
        let objects = next.cue_ball.objects();
        // UMB 3.3 / Art. 23: the opening stroke goes straight at the red.
        let (legal_first, ball_on) = if next.opening {
            (
                vec![Self::number(Ball::Red)],
                "the red first, with no cushion before it (the opening stroke)".to_owned(),
            )
        } else {
            (
                objects.iter().map(|&b| Self::number(b)).collect(),
                format!(
                    "the {} and the {}, three cushions before the second (Art. 83)",
                    objects[0].name(),
                    objects[1].name()
                ),
            )
        };
        let choices = if self.frozen_choice() {
            vec![
                "play on (not straight into the touching ball)".to_owned(),
                "have the balls re-spotted (Art. 27)".to_owned(),
            ]
        } else {
            Vec::new()
        };
        Turn {
            striker: next.striker,
            cue_ball: Self::number(next.cue_ball),
            place: CueBallPlace::AsItLies,
            legal_first,
            ball_on,
            declare: Declarations::default(),
            opening: next.opening,
            choices,
        }
    }

    fn ball_name(&self, ball: u8) -> String {
        match Ball::ALL.get(usize::from(ball)) {
            Some(b) => format!("the {}", b.name()),
            None => format!("ball {ball}"),
        }
    }

    fn choose(&mut self, index: usize, _layout: &[(u8, Vec2)]) -> Result<Setup, RulesError> {
        if !self.frozen_choice() {
            return Err(RulesError(format!("option {index} is not offered")));
        }
        match index {
            0 => {
                self.frozen_choice_made = true;
                Ok(Setup::Keep)
            }
            1 => {
                let at = self.game.respot_frozen().map_err(err)?;
                self.frozen_choice_made = true;
                Ok(Setup::Layout {
                    balls: Ball::ALL
                        .iter()
                        .map(|&b| (Self::number(b), at[b.index()]))
                        .collect(),
                })
            }
            _ => Err(RulesError(format!(
                "option {index} is not offered (2 offered)"
            ))),
        }
    }

    fn check_hand(&self, _at: Vec2, _others: &[(u8, Vec2)]) -> Result<(), RulesError> {
        Err(RulesError(
            "three-cushion has no ball in hand: the balls are played as they lie".to_owned(),
        ))
    }

    fn judge(&mut self, stroke: &StrokeRecord<'_>) -> Result<Judgement, RulesError> {
        if stroke.declared != Declaration::None {
            return Err(RulesError(
                "three-cushion has no call or nomination".to_owned(),
            ));
        }
        // The solver's ids must be the game's: white 0, yellow 1, red 2.
        if stroke.numbers.get(..3) != Some(&[0, 1, 2][..]) {
            return Err(RulesError(format!(
                "the table's balls are numbered {:?}, not white 0, yellow 1, red 2",
                stroke.numbers
            )));
        }
        if self.frozen_choice() {
            return Err(RulesError(
                "a choice is pending: play on or have the balls re-spotted".to_owned(),
            ));
        }
        let verdict = self.game.play(stroke.events).map_err(err)?;
        self.frozen_choice_made = false;
        let end = self.end();
        Ok(Judgement {
            striker: verdict.striker,
            fair: verdict.fouls.is_empty(),
            fouls: verdict.fouls.iter().map(ToString::to_string).collect(),
            text: verdict.reason.clone(),
            put: verdict
                .spotted
                .iter()
                .map(|&(b, at)| (Self::number(b), at))
                .collect(),
            continues: verdict.next.is_some_and(|n| n.striker == verdict.striker),
            end,
        })
    }

    fn score_line(&self) -> String {
        let (s, i) = (self.game.scores(), self.game.innings());
        format!(
            "three-cushion to {}: {} {} ({} innings) - {} {} ({} innings)",
            self.game.rules().target,
            self.players[0],
            s[0],
            i[0],
            self.players[1],
            s[1],
            i[1]
        )
    }

    fn points(&self) -> [u32; 2] {
        self.game.scores()
    }

    fn status(&self) -> Vec<String> {
        let (s, i) = (self.game.scores(), self.game.innings());
        // The general average, points per inning (UMB's ranking figure).
        let average = |k: usize| f64::from(s[k]) / f64::from(i[k].max(1));
        let mut lines = vec![format!(
            "average: {} {:.3}, {} {:.3}",
            self.players[0],
            average(0),
            self.players[1],
            average(1)
        )];
        if let Some(next) = self.game.next() {
            lines.push(format!(
                "{} plays the {}",
                self.players[next.striker.index()],
                next.cue_ball.name()
            ));
        }
        lines
    }

    fn end(&self) -> Option<GameEnd> {
        let (s, i) = (self.game.scores(), self.game.innings());
        match self.game.end()? {
            Outcome::Won(winner) => Some(GameEnd {
                winner,
                reason: format!(
                    "{} points in {} innings",
                    s[winner.index()],
                    i[winner.index()]
                ),
                match_over: true,
            }),
            // Unreachable without the equalising inning; said, not hidden.
            Outcome::Draw => None,
        }
    }

    fn match_winner(&self) -> Option<Seat> {
        self.end().map(|e| e.winner)
    }

    fn next_game(&mut self) -> Result<Vec<BallSetup>, RulesError> {
        Err(RulesError(
            "a three-cushion match is one game to its distance".to_owned(),
        ))
    }

    fn boxed_clone(&self) -> Box<dyn GameRules> {
        Box::new(self.clone())
    }

    fn save(&self) -> Result<serde_json::Value, RulesError> {
        crate::interface::saved("three_cushion", self)
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
