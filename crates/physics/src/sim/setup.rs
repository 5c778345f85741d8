//! What a simulation starts from: the balls as given ([`BallSetup`], which the ball module
//! owns), the checks they must pass (one set, shared by
//! [`Simulation::new`](crate::Simulation::new) and
//! [`Simulation::place`](crate::Simulation::place)) and the errors they report.

use crate::ball::BallId;
use crate::event::Shot;
use crate::limits::{self, LimitError};
use crate::math::Vec2;
use crate::params::ParamError;
use crate::resolve;
use crate::table::{Table, TableError};

pub use crate::ball::BallSetup;

/// How far two balls may overlap, or a ball cross a cushion line, in a valid starting layout
/// (metres): exactly touching layouts computed in floating point land within rounding of it.
pub const PLACEMENT_TOLERANCE: f64 = 1e-9;

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
    #[error("{} has a non-finite {what}", ball_name(*.ball, *.number))]
    NonFinite {
        /// Ball index.
        ball: BallId,
        /// Its number.
        number: u8,
        /// "position", "velocity" or "spin".
        what: &'static str,
    },
    /// A ball's centre is outside the area its centre may occupy.
    #[error("{} at ({x}, {y}) is outside the table", ball_name(*.ball, *.number))]
    OutsideTable {
        /// Ball index.
        ball: BallId,
        /// Its number.
        number: u8,
        /// Its x.
        x: f64,
        /// Its y.
        y: f64,
    },
    /// Two balls overlap.
    #[error("{} and {} overlap by {overlap} m", ball_name(*.a, .numbers.0), ball_name(*.b, .numbers.1))]
    Overlap {
        /// First ball (index).
        a: BallId,
        /// Second ball (index).
        b: BallId,
        /// Their numbers, in the same order.
        numbers: (u8, u8),
        /// Depth of the overlap, metres.
        overlap: f64,
    },
    /// There is no ball with this index.
    #[error("there is no ball {0}")]
    NoSuchBall(BallId),
    /// The ball has been pocketed.
    #[error("{} is pocketed", ball_name(*.ball, *.number))]
    Pocketed {
        /// Ball index.
        ball: BallId,
        /// Its number.
        number: u8,
    },
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

/// How an error names a ball: by the number painted on it, with its index when they differ.
fn ball_name(index: BallId, number: u8) -> String {
    match number {
        0 if index == 0 => "the cue ball".to_string(),
        0 => format!("the cue ball (index {index})"),
        n if usize::from(n) == index => format!("ball {n}"),
        n => format!("ball {n} (index {index})"),
    }
}

/// Checks one ball (index `id`) as given to [`Simulation::new`](crate::Simulation::new) or
/// [`Simulation::place`](crate::Simulation::place): its
/// position, velocity and spin are finite, its speed and spin within the input contract
/// ([`crate::limits`]), and its centre where the solver itself may leave a ball
/// ([`crate::bounds::outside_by`]: inside the cushion lines, or in a pocket mouth between the
/// jaws) up to [`PLACEMENT_TOLERANCE`]. Every state the solver produces passes.
pub(super) fn check_ball(
    id: BallId,
    ball: &BallSetup,
    radius: f64,
    table: &Table,
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
            return Err(SetupError::NonFinite {
                ball: id,
                number,
                what,
            });
        }
    }
    limits::check_motion(velocity, spin, radius).map_err(|e| e.for_ball(id, number))?;
    if crate::bounds::outside_by(table, radius, position) > PLACEMENT_TOLERANCE {
        return Err(SetupError::OutsideTable {
            ball: id,
            number,
            x: position.x,
            y: position.y,
        });
    }
    Ok(())
}

/// Checks that balls `a` (numbered `na`) at `pa` and `b` (numbered `nb`) at `pb`, of radius
/// `r`, overlap by no more than [`PLACEMENT_TOLERANCE`].
pub(super) fn check_clear(
    (a, na, pa): (BallId, u8, Vec2),
    (b, nb, pb): (BallId, u8, Vec2),
    r: f64,
) -> Result<(), SetupError> {
    let overlap = 2.0 * r - (pb - pa).length();
    if overlap > PLACEMENT_TOLERANCE {
        let (a, b) = if a <= b {
            ((a, na), (b, nb))
        } else {
            ((b, nb), (a, na))
        };
        return Err(SetupError::Overlap {
            a: a.0,
            b: b.0,
            numbers: (a.1, b.1),
            overlap,
        });
    }
    Ok(())
}

/// Checks every ball of a layout with [`check_ball`], then every pair with [`check_clear`].
pub(super) fn check_layout(balls: &[BallSetup], r: f64, table: &Table) -> Result<(), SetupError> {
    for (id, b) in balls.iter().enumerate() {
        check_ball(id, b, r, table)?;
    }
    // Sort by x so only neighbours within 2R in x are compared (large layouts stay fast).
    let mut order: Vec<usize> = (0..balls.len()).collect();
    order.sort_by(|&i, &j| balls[i].position.x.total_cmp(&balls[j].position.x));
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if balls[j].position.x - balls[i].position.x >= 2.0 * r {
                break;
            }
            let (bi, bj) = (&balls[i], &balls[j]);
            check_clear((i, bi.number, bi.position), (j, bj.number, bj.position), r)?;
        }
    }
    Ok(())
}

/// Checks a shot of ball `id` (numbered `number`) as given to
/// [`Simulation::strike`](crate::Simulation::strike) at
/// `time`: the shot and the clock within the input contract ([`crate::limits`]).
pub(super) fn check_shot(id: BallId, number: u8, shot: &Shot, time: f64) -> Result<(), SetupError> {
    limits::check_shot(shot).map_err(|e| e.for_ball(id, number))?;
    limits::check_clock(time)?;
    Ok(())
}
