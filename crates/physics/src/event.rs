//! Events: what happened, when, and to which balls.

use crate::ball::{BallId, BallState, Motion};
use crate::table::{Cushion, Pocket};
use serde::{Deserialize, Serialize};

/// Where the cue tip strikes, as fractions of the ball's radius from its centre, seen from
/// behind the cue.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct TipOffset {
    /// Right of centre is positive (right english).
    pub side: f64,
    /// Above centre is positive (follow), below negative (draw).
    pub height: f64,
}

/// A cue strike: direction and speed given to the cue ball (the paper's cue, 2.3).
#[derive(Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Shot {
    /// Direction, radians from +x (towards the foot) towards +y.
    pub angle: f64,
    /// Speed given to the ball by a centre hit, m/s.
    pub speed: f64,
    /// Where the tip strikes (spin model only).
    #[serde(default)]
    pub tip: TipOffset,
    /// Elevation of the cue above the table, radians, from 0 (level) to
    /// [`crate::limits::MAX_ELEVATION`] (spin model only; absent from old files: level).
    #[serde(default, skip_serializing_if = "is_level")]
    pub elevation: f64,
}

/// A level cue is written as before elevation existed, so level shots' files are unchanged.
fn is_level(elevation: &f64) -> bool {
    *elevation == 0.0
}

/// Prints `elevation` only when the cue is raised, so a level shot prints as before it
/// existed (the fingerprint example hashes this text).
impl std::fmt::Debug for Shot {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut s = f.debug_struct("Shot");
        s.field("angle", &self.angle)
            .field("speed", &self.speed)
            .field("tip", &self.tip);
        if self.elevation != 0.0 {
            s.field("elevation", &self.elevation);
        }
        s.finish()
    }
}

impl Shot {
    /// A centre-ball shot.
    pub fn new(angle: f64, speed: f64) -> Self {
        Self {
            angle,
            speed,
            tip: Default::default(),
            elevation: 0.0,
        }
    }
}

/// What happened at an event.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EventKind {
    /// The cue struck a ball.
    Strike {
        /// The ball struck.
        ball: BallId,
        /// The shot.
        shot: Shot,
    },
    /// A ball was placed or its state set from outside (an editor, the game's respot).
    Placed {
        /// The ball.
        ball: BallId,
    },
    /// Parameters changed; every moving ball continues under the new ones.
    ParamsChanged,
    /// A ball changed motion state by itself (slide to roll, stop).
    Transition {
        /// The ball.
        ball: BallId,
        /// State before.
        from: Motion,
        /// State after.
        to: Motion,
    },
    /// A ball hit a cushion and rebounded.
    Cushion {
        /// The ball.
        ball: BallId,
        /// The cushion.
        cushion: Cushion,
    },
    /// A ball hit the rounded end of a cushion at a pocket mouth and rebounded.
    Jaw {
        /// The ball.
        ball: BallId,
        /// The pocket whose jaw it hit.
        pocket: Pocket,
    },
    /// A ball reached a cushion inside a pocket mouth and left play.
    Pocketed {
        /// The ball.
        ball: BallId,
        /// The pocket.
        pocket: Pocket,
    },
    /// Two balls collided.
    BallBall {
        /// Lower ball index.
        a: BallId,
        /// Higher ball index.
        b: BallId,
    },
}

impl EventKind {
    /// The balls this event changed, in order (at most two).
    pub fn balls(&self) -> impl Iterator<Item = BallId> {
        let (first, second) = match *self {
            EventKind::Strike { ball, .. }
            | EventKind::Placed { ball }
            | EventKind::Transition { ball, .. }
            | EventKind::Cushion { ball, .. }
            | EventKind::Jaw { ball, .. }
            | EventKind::Pocketed { ball, .. } => (Some(ball), None),
            EventKind::BallBall { a, b } => (Some(a), Some(b)),
            EventKind::ParamsChanged => (None, None),
        };
        first.into_iter().chain(second)
    }

    /// Is this a collision (ball–ball or cushion)?
    pub fn is_collision(&self) -> bool {
        matches!(
            self,
            EventKind::Cushion { .. } | EventKind::Jaw { .. } | EventKind::BallBall { .. }
        )
    }
}

/// One entry of the event history: the time, what happened and the states of the balls it
/// changed, just after it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Event {
    /// Simulation time, seconds.
    pub time: f64,
    /// What happened.
    pub kind: EventKind,
    /// State after the event of each ball in `kind.balls()`, in that order; unused slots hold
    /// the default state.
    pub after: [BallState; 2],
}

impl Event {
    /// The balls changed by this event with their states just after it.
    pub fn states_after(&self) -> impl Iterator<Item = (BallId, &BallState)> {
        self.kind.balls().zip(self.after.iter())
    }
}
