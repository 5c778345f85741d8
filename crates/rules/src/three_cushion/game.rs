//! A game of three-cushion to a target score: whose stroke, with which ball, the score and
//! the innings, and the end (with the equalising inning).

use super::balls::{Ball, BallIds};
use super::error::ThreeCushionError;
use super::judge::{Foul, fouls, read_stroke, reason};
use super::layout::{Side, Spots, frozen_to};
use crate::turn::Seat;
use billiards_physics::{BallSetup, Event, EventKind, Table, Vec2};
use serde::{Deserialize, Serialize};

/// How far (metres) the events may strike a ball from where the game has it: 1 mm (the
/// solver's resting contacts nudge balls by far less; a different layout by far more).
const STRUCK_WHERE_KEPT: f64 = 1e-3;

/// The match's settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Rules {
    /// The distance: points that win (UMB matches are played to 40 or 50; 40 here).
    pub target: u32,
    /// The equalising inning (UMB Art. 29, end of the match): when the player who started
    /// reaches the distance, the other plays one more inning, and a draw if they reach it
    /// too, so both have had as many innings. UMB group matches are played
    /// with it; since December 2019 knock-out matches are not (UMB news, "New UMB 3-Cushion
    /// Events Rules Changes", 17 Dec 2019).
    pub equal_innings: bool,
    /// The solver's ids of the three balls.
    pub ids: BallIds,
    /// The starting spot player A's white takes on the opening.
    pub opening_side: Side,
}

impl Default for Rules {
    fn default() -> Self {
        Self {
            target: 40,
            equal_innings: true,
            ids: BallIds::default(),
            opening_side: Side::Right,
        }
    }
}

/// How a game ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Outcome {
    /// This player won.
    Won(Seat),
    /// Both reached the distance in the same number of innings (the equalising inning).
    Draw,
}

/// The next stroke.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Next {
    /// Who strikes.
    pub striker: Seat,
    /// Their cue ball (white for A, yellow for B).
    pub cue_ball: Ball,
    /// The opening stroke: the red must be hit first, directly (UMB 3.3).
    pub opening: bool,
    /// The balls the cue ball is frozen to: the striker may play away from them or have the
    /// balls set up again ([`ThreeCushionGame::respot_frozen`], Art. 27).
    pub frozen_to: Vec<Ball>,
    /// This inning is the equalising one: a miss ends the game.
    pub equalising: bool,
}

/// What a stroke did, and what follows.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Verdict {
    /// Who played it.
    pub striker: Seat,
    /// A point was scored.
    pub point: bool,
    /// Why, in words a player reads.
    pub reason: String,
    /// The cue ball's cushions before the second object ball (all of them if it did not
    /// reach a second object ball).
    pub cushions: u32,
    /// The fouls (each ends the inning without a point).
    pub fouls: Vec<Foul>,
    /// The next stroke (`None` once the game is over).
    pub next: Option<Next>,
    /// Points of A and B.
    pub scores: [u32; 2],
    /// Innings of A and B (a player's turn at the table counts once, from its first stroke).
    pub innings: [u32; 2],
    /// How the game ended, if it did.
    pub end: Option<Outcome>,
    /// Balls that jumped off the table set up again on their spots (Art. 28), and where.
    #[serde(default)]
    pub spotted: Vec<(Ball, Vec2)>,
}

/// A game of three-cushion: the layout (kept from the events' states), the striker, the
/// scores, the innings and the end.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ThreeCushionGame {
    rules: Rules,
    spots: Spots,
    radius: f64,
    positions: [Vec2; 3],
    striker: Seat,
    opening: bool,
    equalising: bool,
    scores: [u32; 2],
    innings: [u32; 2],
    end: Option<Outcome>,
}

impl ThreeCushionGame {
    /// A game on `table` with balls of `radius`, the balls in the opening position (UMB 3.3),
    /// player A (white) to play the opening stroke.
    pub fn new(rules: Rules, table: &Table, radius: f64) -> Result<Self, ThreeCushionError> {
        rules.ids.check()?;
        if rules.target == 0 {
            return Err(ThreeCushionError::Rules(
                "the distance must be at least 1 point".into(),
            ));
        }
        let spots = Spots::of(table, radius)?;
        Ok(Self {
            positions: spots.opening(Ball::White, rules.opening_side),
            rules,
            spots,
            radius,
            striker: Seat::A,
            opening: true,
            equalising: false,
            scores: [0; 2],
            innings: [1, 0],
            end: None,
        })
    }

    /// A game in progress (a shared position, a study): the balls at `positions` (by
    /// [`Ball::index`]), `striker` to play with their own cue ball, no points yet, past the
    /// opening stroke. Refused when two balls overlap or a ball is off the cloth.
    pub fn in_progress(
        rules: Rules,
        table: &Table,
        radius: f64,
        positions: [Vec2; 3],
        striker: Seat,
    ) -> Result<Self, ThreeCushionError> {
        let mut game = Self::new(rules, table, radius)?;
        let bounds = table.centre_bounds(radius);
        for (k, p) in positions.iter().enumerate() {
            if !(p.is_finite() && p.x.abs() <= bounds.x && p.y.abs() <= bounds.y) {
                return Err(ThreeCushionError::Rules(format!(
                    "the {} at ({:.3}, {:.3}) is not on the cloth",
                    Ball::ALL[k].name(),
                    p.x,
                    p.y
                )));
            }
            for q in &positions[k + 1..] {
                if (*p - *q).length() < 2.0 * radius {
                    return Err(ThreeCushionError::Rules(format!(
                        "the {} overlaps another ball",
                        Ball::ALL[k].name()
                    )));
                }
            }
        }
        game.positions = positions;
        game.striker = striker;
        game.opening = false;
        game.innings = [0; 2];
        game.innings[striker.index()] = 1;
        Ok(game)
    }

    /// The rules in force.
    pub fn rules(&self) -> &Rules {
        &self.rules
    }

    /// The table's spots.
    pub fn spots(&self) -> &Spots {
        &self.spots
    }

    /// Where `ball` is.
    pub fn position(&self, ball: Ball) -> Vec2 {
        self.positions[ball.index()]
    }

    /// The three balls at rest where the game has them, in the order of their ids (with the
    /// default ids 0, 1, 2: a simulation's balls); numbered 0 (white), 1 (yellow), 2 (red).
    pub fn setups(&self) -> Vec<BallSetup> {
        let mut balls: Vec<(usize, BallSetup)> = Ball::ALL
            .into_iter()
            .map(|b| {
                let setup = BallSetup::at(b.index() as u8, self.positions[b.index()]);
                (self.rules.ids.id(b), setup)
            })
            .collect();
        balls.sort_by_key(|&(id, _)| id);
        balls.into_iter().map(|(_, s)| s).collect()
    }

    /// Points of A and B.
    pub fn scores(&self) -> [u32; 2] {
        self.scores
    }

    /// Innings of A and B.
    pub fn innings(&self) -> [u32; 2] {
        self.innings
    }

    /// How the game ended (`None` while it goes on).
    pub fn end(&self) -> Option<Outcome> {
        self.end
    }

    /// The next stroke (`None` once the game is over).
    pub fn next(&self) -> Option<Next> {
        self.end.is_none().then(|| {
            let cue_ball = Ball::cue_of(self.striker);
            Next {
                striker: self.striker,
                cue_ball,
                opening: self.opening,
                frozen_to: frozen_to(&self.positions, cue_ball, self.radius),
                equalising: self.equalising,
            }
        })
    }

    /// Art. 27: the striker's cue ball is frozen to a ball and they choose to have the balls
    /// set up again; returns the new positions (by [`Ball::index`]) for the simulation.
    pub fn respot_frozen(&mut self) -> Result<[Vec2; 3], ThreeCushionError> {
        if self.end.is_some() {
            return Err(ThreeCushionError::GameOver);
        }
        let cue = Ball::cue_of(self.striker);
        self.positions = self.spots.respot_frozen(self.positions, cue, self.radius)?;
        Ok(self.positions)
    }

    /// Judges one stroke from the solver's events (from the strike, or from balls placed
    /// before it, to rest) and moves the game on: a point continues the inning, a miss or a
    /// foul passes it (UMB Art. 24, Art. 41); the distance ends the game, after the
    /// equalising inning if the rules have it.
    pub fn play(&mut self, events: &[Event]) -> Result<Verdict, ThreeCushionError> {
        if self.end.is_some() {
            return Err(ThreeCushionError::GameOver);
        }
        let (before, strike) = self.before_strike(events)?;
        let cue = Ball::cue_of(self.striker);
        // Art. 27 reads the layout as the cue strikes (after any ball placed by hand).
        let frozen = frozen_to(&before, cue, self.radius);
        let facts = read_stroke(&self.rules.ids, before, &events[strike..])?;
        let fouls = fouls(&facts, cue, self.opening, &frozen);
        let point = fouls.is_empty() && facts.carom();
        let striker = self.striker;
        self.positions = facts.positions;
        // Art. 28: the balls off the table back on their spots, the incoming striker's cue
        // ball taking the bottom spot (a foul always passes the inning).
        let incoming = Ball::cue_of(striker.other());
        self.positions =
            self.spots
                .respot_off_table(self.positions, &facts.off_table, incoming, self.radius);
        let spotted = facts
            .off_table
            .iter()
            .map(|&b| (b, self.positions[b.index()]))
            .collect();
        self.opening = false;
        if point {
            self.score(striker);
        } else if self.equalising {
            // The equalising inning ends short of the distance: the starter wins.
            self.end = Some(Outcome::Won(striker.other()));
        } else {
            self.striker = striker.other();
            self.innings[self.striker.index()] += 1;
        }
        Ok(Verdict {
            striker,
            point,
            reason: reason(&facts, &fouls),
            cushions: facts.counted_cushions(),
            fouls,
            next: self.next(),
            scores: self.scores,
            innings: self.innings,
            end: self.end,
            spotted,
        })
    }

    /// A point for `seat`; at the distance, the end or the equalising inning.
    fn score(&mut self, seat: Seat) {
        let i = seat.index();
        self.scores[i] += 1;
        if self.scores[i] < self.rules.target {
            return;
        }
        if self.equalising {
            self.end = Some(Outcome::Draw);
        } else if self.rules.equal_innings && self.innings[seat.other().index()] < self.innings[i] {
            self.equalising = true;
            self.striker = seat.other();
            self.innings[self.striker.index()] += 1;
        } else {
            self.end = Some(Outcome::Won(seat));
        }
    }

    /// The layout as the cue strikes (the game's, moved by the balls placed before the strike)
    /// and the strike's index; an error if there is no strike or if it strikes a ball away
    /// from where that layout has it (the simulation and the game disagree).
    fn before_strike(&self, events: &[Event]) -> Result<([Vec2; 3], usize), ThreeCushionError> {
        let mut positions = self.positions;
        for (k, e) in events.iter().enumerate() {
            if let EventKind::Strike { ball, .. } = e.kind {
                let b = self.rules.ids.ball(ball)?;
                let (p, g) = (e.after[0].position, positions[b.index()]);
                if (p - g).length() > STRUCK_WHERE_KEPT {
                    return Err(ThreeCushionError::NotWhereTheGameHasIt {
                        ball: b.name(),
                        x: p.x,
                        y: p.y,
                        gx: g.x,
                        gy: g.y,
                    });
                }
                return Ok((positions, k));
            }
            for (id, s) in e.states_after() {
                positions[self.rules.ids.ball(id)?.index()] = s.position;
            }
        }
        Err(ThreeCushionError::NoStrike)
    }
}
