//! What a simulation starts from: the balls as given, the checks they must pass (one set,
//! shared by [`Simulation::new`] and [`Simulation::place`]) and the errors they report.

use crate::ball::BallId;
use crate::event::Shot;
use crate::limits::{self, LimitError};
use crate::math::{Vec2, Vec3};
use crate::params::ParamError;
use crate::resolve;
use crate::table::TableError;
use serde::{Deserialize, Serialize};

#[cfg(doc)]
use super::Simulation;

/// How far two balls may overlap, or a ball cross a cushion line, in a valid starting layout
/// (metres): exactly touching layouts computed in floating point land within rounding of it.
pub const PLACEMENT_TOLERANCE: f64 = 1e-9;

/// A ball as given to [`Simulation::new`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BallSetup {
    /// Number painted on the ball (0 for the cue ball).
    pub number: u8,
    /// Centre, metres.
    pub position: Vec2,
    /// Velocity, m/s.
    #[serde(default)]
    pub velocity: Vec2,
    /// Angular velocity, rad/s (ignored by the paper's model, which has no spin).
    #[serde(default)]
    pub spin: Vec3,
}

impl BallSetup {
    /// A ball at rest.
    pub fn at(number: u8, position: Vec2) -> Self {
        Self {
            number,
            position,
            velocity: Vec2::ZERO,
            spin: Vec3::ZERO,
        }
    }

    /// A ball moving with `velocity` and no spin.
    pub fn moving(number: u8, position: Vec2, velocity: Vec2) -> Self {
        Self {
            velocity,
            ..Self::at(number, position)
        }
    }
}

/// Why a simulation could not be built or changed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SetupError {
    /// A parameter is out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The table is malformed.
    #[error(transparent)]
    Table(#[from] TableError),
    /// A ball's position, velocity or spin is NaN or infinite.
    #[error("ball {ball} has a non-finite {what}")]
    NonFinite {
        /// Ball index.
        ball: BallId,
        /// "position", "velocity" or "spin".
        what: &'static str,
    },
    /// A ball's centre is outside the area its centre may occupy.
    #[error("ball {ball} at ({x}, {y}) is outside the table")]
    OutsideTable {
        /// Ball index.
        ball: BallId,
        /// Its x.
        x: f64,
        /// Its y.
        y: f64,
    },
    /// Two balls overlap.
    #[error("balls {a} and {b} overlap by {overlap} m")]
    Overlap {
        /// First ball.
        a: BallId,
        /// Second ball.
        b: BallId,
        /// Depth of the overlap, metres.
        overlap: f64,
    },
    /// There is no ball with this index.
    #[error("there is no ball {0}")]
    NoSuchBall(BallId),
    /// The ball has been pocketed.
    #[error("ball {0} is pocketed")]
    Pocketed(BallId),
    /// The cue tip offset is beyond the miscue limit.
    #[error(transparent)]
    Miscue(#[from] resolve::cue::Miscue),
    /// A value outside the input contract (a shot, a ball's speed or spin, the clock).
    #[error(transparent)]
    Limit(#[from] LimitError),
}

/// Why the simulation stopped short of the requested time.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SimError {
    /// More events than `Params::max_events` in one call: the state is valid, at `time`.
    #[error("event cap of {cap} reached at t = {time} s without coming to rest")]
    EventCap {
        /// The cap.
        cap: usize,
        /// Simulation time reached.
        time: f64,
    },
    /// A step with negative or non-finite length.
    #[error("cannot advance by {0} s: time steps must be finite and non-negative")]
    BadStep(f64),
    /// A step that would end past [`crate::limits::MAX_TIME`].
    #[error(transparent)]
    Limit(#[from] LimitError),
}

/// Checks one ball (index `id`) as given to [`Simulation::new`] or [`Simulation::place`]: its
/// position, velocity and spin are finite, its speed and spin within the input contract
/// ([`crate::limits`]), and its centre within `bounds` (the half extents of the area a centre
/// may occupy, [`crate::Table::centre_bounds`]) up to [`PLACEMENT_TOLERANCE`].
pub(super) fn check_ball(
    id: BallId,
    ball: &BallSetup,
    radius: f64,
    bounds: Vec2,
) -> Result<(), SetupError> {
    let BallSetup {
        number,
        position,
        velocity,
        spin,
    } = *ball;
    for (what, ok) in [
        ("position", position.is_finite()),
        ("velocity", velocity.is_finite()),
        ("spin", spin.is_finite()),
    ] {
        if !ok {
            return Err(SetupError::NonFinite { ball: id, what });
        }
    }
    limits::check_motion(velocity, spin, radius).map_err(|e| e.for_ball(id, number))?;
    if position.x.abs() > bounds.x + PLACEMENT_TOLERANCE
        || position.y.abs() > bounds.y + PLACEMENT_TOLERANCE
    {
        return Err(SetupError::OutsideTable {
            ball: id,
            x: position.x,
            y: position.y,
        });
    }
    Ok(())
}

/// Checks that balls `a` at `pa` and `b` at `pb`, of radius `r`, overlap by no more than
/// [`PLACEMENT_TOLERANCE`].
pub(super) fn check_clear(
    (a, pa): (BallId, Vec2),
    (b, pb): (BallId, Vec2),
    r: f64,
) -> Result<(), SetupError> {
    let overlap = 2.0 * r - (pb - pa).length();
    if overlap > PLACEMENT_TOLERANCE {
        return Err(SetupError::Overlap {
            a: a.min(b),
            b: a.max(b),
            overlap,
        });
    }
    Ok(())
}

/// Checks every ball of a layout with [`check_ball`], then every pair with [`check_clear`].
pub(super) fn check_layout(balls: &[BallSetup], r: f64, bounds: Vec2) -> Result<(), SetupError> {
    for (id, b) in balls.iter().enumerate() {
        check_ball(id, b, r, bounds)?;
    }
    // Sort by x so only neighbours within 2R in x are compared (large layouts stay fast).
    let mut order: Vec<usize> = (0..balls.len()).collect();
    order.sort_by(|&i, &j| balls[i].position.x.total_cmp(&balls[j].position.x));
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if balls[j].position.x - balls[i].position.x >= 2.0 * r {
                break;
            }
            check_clear((i, balls[i].position), (j, balls[j].position), r)?;
        }
    }
    Ok(())
}

/// Checks a shot of ball `id` (numbered `number`) as given to [`Simulation::strike`] at
/// `time`: the shot and the clock within the input contract ([`crate::limits`]).
pub(super) fn check_shot(id: BallId, number: u8, shot: &Shot, time: f64) -> Result<(), SetupError> {
    limits::check_shot(shot).map_err(|e| e.for_ball(id, number))?;
    limits::check_clock(time)?;
    Ok(())
}
