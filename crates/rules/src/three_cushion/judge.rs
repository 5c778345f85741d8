//! One stroke judged from the solver's events: the cue ball's contacts and cushions in order
//! (Art. 83, the point), and the fouls the events show (3.3 / Art. 23 the opening, Art. 27 a
//! frozen ball, Art. 28 a ball off the table, Art. 41 the wrong ball).

use super::balls::{Ball, BallIds};
use super::error::ThreeCushionError;
use billiards_physics::{Event, EventKind, Motion, Vec2};
use serde::{Deserialize, Serialize};
use std::fmt;

/// A foul the events show. Each ends the inning without a point (UMB Art. 41; three-cushion
/// has no penalty points).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Foul {
    /// Art. 41: the striker played another ball than their own cue ball.
    WrongBall {
        /// The ball the cue struck.
        played: Ball,
        /// The striker's cue ball.
        own: Ball,
    },
    /// UMB 3.3 (Art. 23): the opening stroke must be played by direct attack on the red: the
    /// red the first ball touched, before any cushion.
    OpeningNotOnTheRed {
        /// The first ball the cue ball touched, if any.
        first: Option<Ball>,
        /// Cushions the cue ball touched before it.
        cushions_before: u32,
    },
    /// Art. 27: with the cue ball frozen to a ball, the striker plays away from it (another
    /// ball or a cushion first); playing straight into it is a foul.
    IntoTheFrozenBall {
        /// The ball the cue ball was frozen to.
        ball: Ball,
    },
    /// Art. 28 ("Balls bounding out of the billiard", 1989 edition): a ball jumped off the
    /// table. The article's text could not be confirmed from the text at hand; the stroke is
    /// taken as a foul ending the inning without a point (Art. 41), and the ball is set up
    /// again on its spot as the balls are under Art. 27 ([`super::Spots::respot_off_table`]).
    OffTable {
        /// The ball that left the table.
        ball: Ball,
    },
}

impl fmt::Display for Foul {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Foul::WrongBall { played, own } => write!(
                f,
                "played the {} ball instead of the own cue ball, the {} (UMB Art. 41)",
                played.name(),
                own.name()
            ),
            Foul::OpeningNotOnTheRed {
                first: Some(Ball::Red),
                cushions_before,
            } => write!(
                f,
                "the opening stroke must hit the red directly, not after {cushions_before} \
                 cushion(s) (UMB 3.3)"
            ),
            Foul::OpeningNotOnTheRed { first, .. } => write!(
                f,
                "the opening stroke must hit the red first, but {} (UMB 3.3)",
                match first {
                    Some(b) => format!("the {} was hit first", b.name()),
                    None => "no ball was hit".into(),
                }
            ),
            Foul::IntoTheFrozenBall { ball } => write!(
                f,
                "the cue ball was played straight into the {} it was frozen to (UMB Art. 27)",
                ball.name()
            ),
            Foul::OffTable { ball } => {
                write!(f, "the {} jumped off the table (UMB Art. 28)", ball.name())
            }
        }
    }
}

/// The facts of one stroke about the ball the cue struck.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StrokeFacts {
    /// The ball the cue struck.
    pub struck: Ball,
    /// The first object ball it touched, and the cushions it had touched before.
    pub first: Option<(Ball, u32)>,
    /// The second object ball it touched (the other one), and the cushions before it.
    pub second: Option<(Ball, u32)>,
    /// Cushions it touched in the whole stroke.
    pub cushions: u32,
    /// Where each ball rests after the stroke (by [`Ball::index`]), from the events' states
    /// (a ball off the table: where it left the game).
    pub positions: [Vec2; 3],
    /// The balls that jumped off the table, in order (Art. 28); empty in facts saved before
    /// flight.
    #[serde(default)]
    pub off_table: Vec<Ball>,
}

impl StrokeFacts {
    /// Art. 83: both object balls touched, with at least three cushions before the second
    /// (cushions before the first count; one cushion may count several times).
    pub fn carom(&self) -> bool {
        self.second.is_some_and(|(_, c)| c >= 3)
    }

    /// The cushions that decide the point: those before the second ball, or all of them when
    /// there was no second ball.
    pub fn counted_cushions(&self) -> u32 {
        self.second.map_or(self.cushions, |(_, c)| c)
    }
}

/// Reads one stroke from `events`: events before the strike (balls placed by hand) only move
/// balls, then exactly one strike, then the balls' motion to rest. `positions` is the layout
/// before them (by [`Ball::index`]). Errors: no strike or several, a ball placed during the
/// stroke, a pocketed ball, an id that is none of the three.
pub fn read_stroke(
    ids: &BallIds,
    positions: [Vec2; 3],
    events: &[Event],
) -> Result<StrokeFacts, ThreeCushionError> {
    let strikes = events
        .iter()
        .filter(|e| matches!(e.kind, EventKind::Strike { .. }))
        .count();
    match strikes {
        0 => return Err(ThreeCushionError::NoStrike),
        1 => {}
        n => return Err(ThreeCushionError::SeveralStrikes(n)),
    }
    let mut positions = positions;
    let mut facts: Option<StrokeFacts> = None;
    for e in events {
        for (id, s) in e.states_after() {
            positions[ids.ball(id)?.index()] = s.position;
        }
        match (e.kind, facts.as_mut()) {
            (EventKind::Strike { ball, .. }, _) => {
                facts = Some(StrokeFacts {
                    struck: ids.ball(ball)?,
                    first: None,
                    second: None,
                    cushions: 0,
                    positions,
                    off_table: Vec::new(),
                });
            }
            (EventKind::Pocketed { ball, .. }, _) => return Err(ThreeCushionError::Pocketed(ball)),
            (
                EventKind::Transition {
                    ball,
                    to: Motion::OffTable,
                    ..
                },
                Some(f),
            ) => {
                let b = ids.ball(ball)?;
                if !f.off_table.contains(&b) {
                    f.off_table.push(b);
                }
            }
            (EventKind::Placed { ball }, Some(_)) => {
                return Err(ThreeCushionError::PlacedDuringStroke(ball));
            }
            // A jaw cannot occur without pockets; were it to, it is the end of a cushion.
            (EventKind::Cushion { ball, .. } | EventKind::Jaw { ball, .. }, Some(f))
                if ids.ball(ball)? == f.struck =>
            {
                f.cushions += 1;
            }
            (EventKind::BallBall { a, b }, Some(f)) => {
                let (a, b) = (ids.ball(a)?, ids.ball(b)?);
                let other = match (a == f.struck, b == f.struck) {
                    (true, _) => b,
                    (_, true) => a,
                    _ => continue,
                };
                match f.first {
                    None => f.first = Some((other, f.cushions)),
                    Some((first, _)) if f.second.is_none() && other != first => {
                        f.second = Some((other, f.cushions));
                    }
                    _ => {}
                }
            }
            _ => {}
        }
    }
    let mut facts = facts.ok_or(ThreeCushionError::NoStrike)?;
    facts.positions = positions;
    Ok(facts)
}

/// The fouls of a stroke whose facts are `facts`, played by the owner of `cue`, on the
/// opening or not, with the cue ball frozen to the balls `frozen` when it was struck.
pub fn fouls(facts: &StrokeFacts, cue: Ball, opening: bool, frozen: &[Ball]) -> Vec<Foul> {
    let mut out = Vec::new();
    // Art. 28: a ball off the table, whatever else the stroke did.
    out.extend(facts.off_table.iter().map(|&ball| Foul::OffTable { ball }));
    if facts.struck != cue {
        out.push(Foul::WrongBall {
            played: facts.struck,
            own: cue,
        });
        return out;
    }
    if opening && !matches!(facts.first, Some((Ball::Red, 0))) {
        out.push(Foul::OpeningNotOnTheRed {
            first: facts.first.map(|(b, _)| b),
            cushions_before: facts.first.map_or(facts.cushions, |(_, c)| c),
        });
    }
    if let Some((ball, 0)) = facts.first
        && frozen.contains(&ball)
    {
        out.push(Foul::IntoTheFrozenBall { ball });
    }
    out
}

/// Why the stroke scored or not, in words a player reads.
pub fn reason(facts: &StrokeFacts, fouls: &[Foul]) -> String {
    let cue = facts.struck.name();
    if let Some(f) = fouls.first() {
        return format!("Foul: {f}. No point; the inning ends.");
    }
    let plural = |n: u32| if n == 1 { "cushion" } else { "cushions" };
    match (facts.first, facts.second) {
        (None, _) => format!(
            "No point: the {cue} touched neither object ball ({} {}).",
            facts.cushions,
            plural(facts.cushions)
        ),
        (Some((b, _)), None) => format!(
            "No point: the {cue} touched only the {} ({} {} in all).",
            b.name(),
            facts.cushions,
            plural(facts.cushions)
        ),
        (Some(_), Some((b, c))) if c < 3 => format!(
            "No point: only {c} {} before the second object ball (the {}); three are needed \
             (UMB Art. 83).",
            plural(c),
            b.name()
        ),
        (Some((a, _)), Some((b, c))) => format!(
            "Point: the {cue} touched the {} and the {} with {c} {} before the second.",
            a.name(),
            b.name(),
            plural(c)
        ),
    }
}
