//! Pool's games (8-ball, 9-ball, free play: [`Game`]) behind the one game interface
//! ([`GameRules`], issue 50): a [`PoolMatch`] is a race to N racks ([`Match`]) on a table
//! with its balls, and turns the WPA rules' own words ([`NextShot`], [`Verdict`](crate::Verdict)) into the
//! interface's ([`Turn`], [`Judgement`]).

use crate::foul::Group;
use crate::hand::check_place;
use crate::interface::{
    CueBallPlace, Declaration, Declarations, GameEnd, GameRules, HandRegion, Judgement, Need,
    RulesError, Setup, StrokeRecord, Turn,
};
use crate::race::Match;
use crate::racks::RackStyle;
use crate::respot::{foot_spot_position, head_string_spot};
use crate::shot::CUE;
use crate::state::{Game, GameState};
use crate::turn::{Call, CallRule, Choice, CueBall, NextShot, Outcome, Seat, what_happened};
use billiards_physics::{BallSetup, BallSpec, Table, Vec2};

/// A match of one of pool's games, with its equipment and the seed of the rack in play.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PoolMatch {
    /// The match: players, race, score and the rack in play.
    pub play: Match,
    /// The table.
    pub table: Table,
    /// The balls.
    pub ball: BallSpec,
    /// The seed of the rack in play (each later rack takes the next).
    pub seed: u64,
    /// How the racks are set.
    pub style: RackStyle,
}

impl PoolMatch {
    /// A race to `race_to` racks of `game` between `players`, A breaking the first rack of
    /// seed `seed`.
    pub fn new(
        game: Game,
        players: [String; 2],
        race_to: u32,
        table: Table,
        ball: BallSpec,
        seed: u64,
        style: RackStyle,
    ) -> Self {
        Self {
            play: Match::new(game, players, race_to, Seat::A),
            table,
            ball,
            seed,
            style,
        }
    }

    /// The rack in play.
    pub fn rack(&self) -> &GameState {
        &self.play.rack
    }

    fn next(&self) -> &NextShot {
        self.play.next()
    }

    /// Where the balls `spot` go on the long string (WPA 1.4), one after the other, with
    /// the balls of `layout` (the cue ball included) left where they are.
    fn spot_places(
        &self,
        spot: &[u8],
        layout: &[(u8, Vec2)],
    ) -> Result<Vec<(u8, Vec2)>, RulesError> {
        let mut others: Vec<Vec2> = layout
            .iter()
            .filter(|(n, _)| !spot.contains(n))
            .map(|&(_, p)| p)
            .collect();
        let mut put = Vec::new();
        for &ball in spot {
            let at =
                foot_spot_position(&self.table, self.ball.radius, &others).ok_or_else(|| {
                    RulesError(format!("no free place on the long string for the {ball}"))
                })?;
            others.push(at);
            put.push((ball, at));
        }
        Ok(put)
    }

    fn rack_layout(&self) -> Vec<BallSetup> {
        self.play
            .game
            .rack_styled(&self.table, &self.ball, self.seed, self.style)
    }
}

/// The interface's declaration as pool's call; a nomination is not pool's.
fn call_of(declared: Declaration) -> Result<Call, RulesError> {
    Ok(match declared {
        Declaration::None => Call::None,
        Declaration::Pocket { ball, pocket } => Call::Ball { ball, pocket },
        Declaration::Safety => Call::Safety,
        Declaration::PushOut => Call::PushOut,
        Declaration::Nominate { .. } => {
            return Err(RulesError("pool has no nomination".to_owned()));
        }
    })
}

/// What is on in words: "the 3", "any ball but the 8" (an open 8-ball table, WPA 3.5),
/// "the solids", "any of [1, 2]".
pub fn ball_on_text(rack: &GameState, next: &NextShot) -> String {
    match (rack.game, next.legal_first.as_slice()) {
        (Game::FreePlay, _) => "any ball".to_owned(),
        (_, []) => "none".to_owned(),
        (_, [one]) => format!("the {one}"),
        // WPA 3.3: the break need not hit any particular ball.
        (Game::EightBall, _) if next.break_shot => "any ball (the break)".to_owned(),
        (Game::EightBall, _) if rack.group(next.shooter).is_none() => {
            // The next line says "open table" (WPA 3.5); not twice.
            "any ball but the 8".to_owned()
        }
        (Game::EightBall, _) => format!(
            "the {}",
            rack.group(next.shooter).map_or("group", Group::name)
        ),
        (_, many) => format!("any of {many:?}"),
    }
}

/// The game's name for a player.
pub fn game_name(game: Game) -> &'static str {
    match game {
        Game::NineBall => "9-ball",
        Game::EightBall => "8-ball",
        Game::TenBall => "10-ball",
        Game::FreePlay => "free play",
    }
}

/// The balls that may be called with a pocket on the next shot ([`Declarations::callable`]).
pub fn callable(rack: &GameState, next: &NextShot) -> Vec<u8> {
    match next.call {
        CallRule::NotUsed => Vec::new(),
        CallRule::EightPocket => vec![8],
        CallRule::Optional => next.legal_first.clone(),
        // WPA 9.5: any ball may be called, the first ball hit must still be the lowest.
        CallRule::BallAndPocket => rack.on_table.clone(),
    }
}

/// Whether the next shot needs a call, in the interface's words.
pub fn need_of(call: CallRule) -> Need {
    match call {
        CallRule::NotUsed => Need::NotUsed,
        CallRule::Optional => Need::Optional,
        // 8-ball's 8 (WPA 3.8) and every 10-ball shot after the break (WPA 9.5).
        CallRule::EightPocket | CallRule::BallAndPocket => Need::Required,
    }
}

impl GameRules for PoolMatch {
    fn name(&self) -> &'static str {
        game_name(self.play.game)
    }

    fn players(&self) -> &[String; 2] {
        &self.play.players
    }

    fn table(&self) -> Table {
        self.table
    }

    fn ball(&self) -> BallSpec {
        self.ball
    }

    fn layout(&self) -> Result<Vec<BallSetup>, RulesError> {
        Ok(self.rack_layout())
    }

    fn turn(&self) -> Turn {
        let next = self.next();
        let place = match next.cue_ball {
            CueBall::AsItLies => CueBallPlace::AsItLies,
            CueBall::InHandAnywhere => CueBallPlace::InHand {
                region: HandRegion::Anywhere,
            },
            CueBall::InHandBehindHeadString => CueBallPlace::InHand {
                region: HandRegion::BehindHeadString,
            },
            CueBall::Respot => CueBallPlace::Placed,
        };
        let pocket = need_of(next.call);
        Turn {
            striker: next.shooter,
            cue_ball: CUE,
            place,
            legal_first: next.legal_first.clone(),
            ball_on: ball_on_text(self.rack(), next),
            declare: Declarations {
                pocket,
                callable: callable(self.rack(), next),
                safety: next.call != CallRule::NotUsed,
                push_out: next.push_out_allowed,
                nominate: Vec::new(),
            },
            opening: next.break_shot,
            choices: next.choices.iter().map(|c| c.label().to_owned()).collect(),
        }
    }

    fn ball_name(&self, ball: u8) -> String {
        if ball == CUE {
            "the cue ball".to_owned()
        } else {
            format!("the {ball}")
        }
    }

    fn choose(&mut self, index: usize, layout: &[(u8, Vec2)]) -> Result<Setup, RulesError> {
        let choice: Choice = *self.next().choices.get(index).ok_or_else(|| {
            RulesError(format!(
                "option {index} is not offered ({} offered)",
                self.next().choices.len()
            ))
        })?;
        let next = self.play.choose(choice).map_err(RulesError::from_display)?;
        if next.rerack {
            // WPA 3.3: a fresh rack, from the next seed (a new rack is a new draw of gaps).
            self.seed = self.seed.wrapping_add(1);
            return Ok(Setup::Rack {
                balls: self.rack_layout(),
            });
        }
        if next.spot.is_empty() {
            return Ok(Setup::Keep);
        }
        // WPA 3.3: the 8 pocketed on the break is spotted when the shooter so chooses.
        Ok(Setup::Put {
            balls: self.spot_places(&next.spot, layout)?,
        })
    }

    fn check_hand(&self, at: Vec2, others: &[(u8, Vec2)]) -> Result<(), RulesError> {
        check_place(
            &self.table,
            self.ball.radius,
            at,
            others,
            self.next().cue_ball,
        )
        .map_err(RulesError::from_display)
    }

    fn judge(&mut self, stroke: &StrokeRecord<'_>) -> Result<Judgement, RulesError> {
        let call = call_of(stroke.declared)?;
        let summary = stroke.summary()?;
        if self.sandbox() {
            // Free play's table is the player's: the balls on it are those the strike
            // finds, whatever was placed, taken off or racked since the last stroke.
            self.play.rack.take_stock(stroke.before);
        }
        let verdict = self
            .play
            .play(&summary, call)
            .map_err(RulesError::from_display)?;
        let what = what_happened(&summary, call, &verdict.fouls);
        let mut text = if self.sandbox() {
            // Free play judges no fouls: what the stroke did, in words, no "legal".
            what
        } else if what.is_empty() {
            verdict.reason()
        } else {
            format!("{}: {what}", verdict.reason())
        };
        if let Some(group) = verdict.assigned {
            // WPA 3.5: the table is no longer open; said with the stroke that closed it.
            text.push_str(&format!("; the shooter takes the {}", group.name()));
        }
        let mut put = Vec::new();
        if let Some(next) = &verdict.next {
            put = self.spot_places(&next.spot, stroke.after)?;
            if next.cue_ball == CueBall::Respot {
                let mut others: Vec<Vec2> = stroke
                    .after
                    .iter()
                    .filter(|&&(n, _)| n != CUE)
                    .map(|&(_, p)| p)
                    .collect();
                others.extend(put.iter().map(|&(_, p)| p));
                let at = head_string_spot(&self.table, self.ball.radius, &others)
                    .ok_or_else(|| RulesError("no free place on the head string".to_owned()))?;
                put.push((CUE, at));
                let how = if summary.cue_off_table() {
                    "the cue ball flew off the table"
                } else {
                    "scratch"
                };
                text = if text.is_empty() {
                    format!("{how}: the cue ball is back on the head string")
                } else {
                    format!("{text}; {how}: the cue ball is back on the head string")
                };
            }
        }
        let end = match verdict.outcome {
            Outcome::GameOver { winner, reason } => Some(GameEnd {
                winner,
                reason: reason.to_string(),
                match_over: self.play.winner().is_some(),
            }),
            _ => None,
        };
        Ok(Judgement {
            striker: verdict.shooter,
            fair: verdict.legal(),
            fouls: verdict.fouls.iter().map(ToString::to_string).collect(),
            text,
            put,
            continues: verdict.outcome == Outcome::Continues,
            end,
        })
    }

    fn score_line(&self) -> String {
        let play = &self.play;
        if self.sandbox() {
            // No match is kept in free play: no race, no score (the turn's line names the
            // shooter).
            return self.name().to_owned();
        }
        format!(
            "{}, race to {}: {} {} - {} {}",
            self.name(),
            play.race_to,
            play.name(Seat::A),
            play.score[0],
            play.score[1],
            play.name(Seat::B),
        )
    }

    fn points(&self) -> [u32; 2] {
        self.play.score
    }

    fn status(&self) -> Vec<String> {
        self.status_while(&[])
    }

    fn status_while(&self, off: &[u8]) -> Vec<String> {
        let rack = self.rack();
        let next = self.next();
        let balls_left = || {
            let left = rack.on_table.iter().filter(|b| !off.contains(b));
            format!("balls left: {}", left.count())
        };
        if self.sandbox() {
            // Free play: any ball is on (the turn says so), no groups, no fouls.
            return vec![balls_left()];
        }
        let mut lines = Vec::new();
        if rack.over.is_none() && !next.break_shot {
            lines.push(format!("ball on: {}", ball_on_text(rack, next)));
        }
        if rack.game == Game::EightBall {
            lines.push(match rack.group(Seat::A) {
                None => "open table".to_owned(),
                Some(_) => [Seat::A, Seat::B]
                    .map(|seat| {
                        let group = rack.group(seat).unwrap_or(Group::Solids);
                        let left = rack
                            .on_table
                            .iter()
                            .filter(|&&b| group.contains(b) && !off.contains(&b));
                        format!(
                            "{}: {} ({} left)",
                            self.play.name(seat),
                            group.name(),
                            left.count()
                        )
                    })
                    .join(", "),
            });
        } else {
            lines.push(balls_left());
        }
        lines.push(format!(
            "fouls in a row: {} {}, {} {}",
            self.play.name(Seat::A),
            rack.fouls[0],
            self.play.name(Seat::B),
            rack.fouls[1]
        ));
        lines
    }

    fn end(&self) -> Option<GameEnd> {
        self.rack().over.map(|(winner, reason)| GameEnd {
            winner,
            reason: reason.to_string(),
            match_over: self.play.winner().is_some(),
        })
    }

    fn match_winner(&self) -> Option<Seat> {
        self.play.winner()
    }

    fn next_game(&mut self) -> Result<Vec<BallSetup>, RulesError> {
        self.play.next_rack().map_err(RulesError::from_display)?;
        self.seed = self.seed.wrapping_add(1);
        Ok(self.rack_layout())
    }

    fn set_by_hand(&mut self, layout: &[(u8, Vec2)]) -> Result<(), RulesError> {
        if !self.sandbox() {
            return Err(crate::interface::not_by_hand(self.name()));
        }
        self.play.rack.take_stock(layout);
        Ok(())
    }

    fn sandbox(&self) -> bool {
        self.play.game == Game::FreePlay
    }

    fn boxed_clone(&self) -> Box<dyn GameRules> {
        Box::new(self.clone())
    }

    fn save(&self) -> Result<serde_json::Value, RulesError> {
        crate::interface::saved("pool", self)
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
