//! The input contract: the values the solver honours, in one place.
//!
//! Every entry point (the library's [`crate::Simulation`], scene files, recordings, the
//! command line) rejects a value outside these ranges with a [`LimitError`] naming it, rather
//! than returning a silently wrong history. The numbers come from
//! `cargo run --release -p billiards-physics --example limits_probe`, which sweeps them until
//! the invariant monitor ([`crate::check`]) or a closed-form result breaks; each limit keeps a
//! wide margin inside what that experiment found.
//!
//! | input | accepted |
//! |---|---|
//! | shot speed, a ball's speed | 0, or [`MIN_SPEED`] to [`MAX_SPEED`] m/s |
//! | a ball's spin, as surface speed `\|w\| R` | 0, or [`MIN_SPEED`] to [`MAX_SURFACE_SPEED`] m/s |
//! | shot angle, tip offset | finite (any angle; the tip also within the miscue limit) |
//! | cue elevation | 0 to [`MAX_ELEVATION`] rad (85 degrees) |
//! | positions | finite and on the table ([`crate::sim::PLACEMENT_TOLERANCE`]) |
//! | the clock at an input, the end of an `advance` | at most [`MAX_TIME`] s |
//! | a ball set in the air | height 0 to [`MAX_HEIGHT`] m, upward speed within [`MAX_SPEED`] |
//! | parameters | [`crate::Params::validate`]; `max_events` at least 1 |

use crate::ball::BallId;
use crate::ball::BallSetup;
use crate::event::Shot;
use crate::math::{Vec2, Vec3};

/// Fastest shot or ball, m/s. A hard break is 11–13 m/s; the soak plays shots up to 100 m/s
/// and the probe's breaks keep every invariant up to 1e10 m/s (the first failure is near
/// 1e11 m/s), but the clock's rounding error grows with speed times time (see [`MAX_TIME`]),
/// so the speed stays at the soak's tested 100.
pub const MAX_SPEED: f64 = 100.0;

/// Slowest nonzero shot or ball speed (and spin surface speed), m/s. The spin model counts a
/// ball whose contact point slips by at most 1e-12 m/s as rolling, so the probe's centre-hit
/// shots of 1e-12 m/s and below skip their sliding phase (time to rest 37 % off); 1e-10 keeps
/// a factor 100 above that (the soak's slowest shot is 1e-9 m/s).
pub const MIN_SPEED: f64 = 1e-10;

/// Fastest spin, as the speed `|w| R` of the ball's surface, m/s: a cue strike gives at most
/// `2.5 v` times the tip offset (below one radius), so every shot within [`MAX_SPEED`] fits.
pub const MAX_SURFACE_SPEED: f64 = 2.5 * MAX_SPEED;

/// Latest simulation time an input may be given at or a step may end at, seconds. Positions
/// are computed from `t - t0`, whose rounding grows with the clock: the probe's 100 m/s break
/// breaks the 1e-9 m overlap invariant from a clock of 3e5 s (a 12 m/s break from 1e7 s).
/// 1e4 s (2.8 hours of motion) keeps a factor 30 at the fastest speed.
pub const MAX_TIME: f64 = 1e4;

/// Highest cue elevation, radians (85 degrees, pooltool's and the range): the strike
/// drives the ball into the slate, which may make it jump ([`crate::resolve::cue::strike`]);
/// a vertical cue would leave no direction in the table plane to shoot along.
pub const MAX_ELEVATION: f64 = 85.0 * (std::f64::consts::PI / 180.0);

/// An input outside the contract: what, its value, and what is accepted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}{what} {} {unit} is out of range: {expected}", ball_text(*.ball), number(*.value))]
pub struct LimitError {
    /// The ball it concerns, as `(index, number)`, if any.
    pub ball: Option<(BallId, u8)>,
    /// What the value is ("shot speed", "velocity", ...).
    pub what: &'static str,
    /// The value given (for vectors, their length).
    pub value: f64,
    /// Its unit.
    pub unit: &'static str,
    /// What is accepted, with the limits.
    pub expected: String,
}

/// Plain digits for everyday magnitudes, scientific notation beyond them (1e308, not 309 digits).
fn number(x: f64) -> String {
    if x == 0.0 || (1e-4..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

fn ball_text(ball: Option<(BallId, u8)>) -> String {
    match ball {
        Some((index, number)) if usize::from(number) == index => format!("ball {number}: "),
        Some((index, number)) => format!("ball {number} (index {index}): "),
        None => String::new(),
    }
}

impl LimitError {
    /// The same error, naming the ball with index `index` and number `number`.
    pub fn for_ball(self, index: BallId, number: u8) -> Self {
        Self {
            ball: Some((index, number)),
            ..self
        }
    }
}

fn error(what: &'static str, value: f64, unit: &'static str, expected: String) -> LimitError {
    LimitError {
        ball: None,
        what,
        value,
        unit,
        expected,
    }
}

/// `value` is 0 or within `[MIN_SPEED, max]` (NaN fails).
fn check_speed(what: &'static str, value: f64, max: f64) -> Result<(), LimitError> {
    if value == 0.0 || (MIN_SPEED..=max).contains(&value) {
        Ok(())
    } else {
        let expected = format!("0 or from {MIN_SPEED:e} to {max} m/s");
        Err(error(what, value, "m/s", expected))
    }
}

fn check_finite(what: &'static str, value: f64, unit: &'static str) -> Result<(), LimitError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(error(what, value, unit, "finite".into()))
    }
}

/// A shot's own values: a finite angle and tip, an elevation from 0 to [`MAX_ELEVATION`], a
/// speed of 0 or from [`MIN_SPEED`] to [`MAX_SPEED`]. (The tip's miscue limit depends on the
/// model and is checked at the strike.)
pub fn check_shot(shot: &Shot) -> Result<(), LimitError> {
    check_finite("shot angle", shot.angle, "rad")?;
    check_finite("tip side", shot.tip.side, "R")?;
    check_finite("tip height", shot.tip.height, "R")?;
    if !(0.0..=MAX_ELEVATION).contains(&shot.elevation) {
        let expected = format!("from 0 to {MAX_ELEVATION} rad (level to 85 degrees)");
        return Err(error("cue elevation", shot.elevation, "rad", expected));
    }
    if shot.speed < 0.0 {
        return Err(error(
            "shot speed",
            shot.speed,
            "m/s",
            "non-negative".into(),
        ));
    }
    check_speed("shot speed", shot.speed, MAX_SPEED)
}

/// A ball's velocity and spin (a ball of radius `radius`): finite, each zero or within
/// [`MIN_SPEED`] to [`MAX_SPEED`] (the spin as the surface speed `|w| R`, up to
/// [`MAX_SURFACE_SPEED`]).
pub fn check_motion(velocity: Vec2, spin: Vec3, radius: f64) -> Result<(), LimitError> {
    // hypot: the check itself must not overflow or underflow.
    let speed = velocity.x.hypot(velocity.y);
    check_speed("velocity", speed, MAX_SPEED)?;
    let surface = spin.x.hypot(spin.y).hypot(spin.z) * radius;
    check_speed("spin surface speed |w| R", surface, MAX_SURFACE_SPEED)
}

/// Every ball of a starting layout: [`check_motion`], naming the ball.
pub fn check_setups(balls: &[BallSetup], radius: f64) -> Result<(), LimitError> {
    for (index, b) in balls.iter().enumerate() {
        check_motion(b.velocity, b.spin, radius).map_err(|e| e.for_ball(index, b.number))?;
    }
    Ok(())
}

/// Highest a ball's centre may be set above its height on the cloth, metres: ten diameters,
/// far above any jump (a 12 m/s shot at 85 degrees rises 1.8 m in theory, but no cue drives
/// a ball that hard that steeply), and every flight from it lands within the clock's range.
pub const MAX_HEIGHT: f64 = 0.6;

/// A ball set in the air ([`crate::Simulation::launch`]): its height finite, from 0 to
/// [`MAX_HEIGHT`], its upward speed finite and at most [`MAX_SPEED`] either way, and one of
/// them making it fly (above the cloth, or rising from it).
pub fn check_flight(height: f64, vertical: f64) -> Result<(), LimitError> {
    if !(0.0..=MAX_HEIGHT).contains(&height) {
        let expected = format!("from 0 to {MAX_HEIGHT} m above the cloth");
        return Err(error("height", height, "m", expected));
    }
    if !(-MAX_SPEED..=MAX_SPEED).contains(&vertical) {
        let expected = format!("finite, from -{MAX_SPEED} to {MAX_SPEED} m/s");
        return Err(error("upward speed", vertical, "m/s", expected));
    }
    if height == 0.0 && vertical <= 0.0 {
        let expected = "above 0 at height 0 (a ball in the air rises from the cloth)".to_string();
        return Err(error("upward speed", vertical, "m/s", expected));
    }
    Ok(())
}

/// A clock reading an input is given at, or a step ends at: finite, from 0 to [`MAX_TIME`].
pub fn check_clock(time: f64) -> Result<(), LimitError> {
    if (0.0..=MAX_TIME).contains(&time) {
        Ok(())
    } else {
        let expected = format!("from 0 to {MAX_TIME} s (start a new simulation from the balls)");
        Err(error("simulation time", time, "s", expected))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn next_up(x: f64) -> f64 {
        f64::from_bits(x.to_bits() + 1)
    }

    fn next_down(x: f64) -> f64 {
        f64::from_bits(x.to_bits() - 1)
    }

    #[test]
    fn shot_speeds_at_the_limits_pass_and_one_ulp_beyond_fail() {
        for ok in [0.0, MIN_SPEED, 1.0, MAX_SPEED] {
            assert_eq!(check_shot(&Shot::new(0.0, ok)), Ok(()), "{ok}");
        }
        for bad in [
            next_down(MIN_SPEED),
            next_up(MAX_SPEED),
            1e-308,
            1e308,
            -1.0,
            f64::NAN,
            f64::INFINITY,
        ] {
            assert!(check_shot(&Shot::new(0.0, bad)).is_err(), "{bad}");
        }
    }

    #[test]
    fn elevations_from_level_to_85_degrees_pass_and_beyond_fail() {
        let at = |elevation| {
            check_shot(&Shot {
                elevation,
                ..Shot::new(0.0, 1.0)
            })
        };
        assert_eq!(MAX_ELEVATION, 85f64.to_radians());
        for ok in [0.0, 0.1, 30f64.to_radians(), 1.4, MAX_ELEVATION] {
            assert_eq!(at(ok), Ok(()), "{ok}");
        }
        for bad in [next_up(MAX_ELEVATION), -1e-9, 1.5, f64::NAN, f64::INFINITY] {
            let e = at(bad).unwrap_err();
            assert_eq!(e.what, "cue elevation", "{bad}");
        }
    }

    #[test]
    fn any_finite_angle_and_tip_pass_non_finite_fail() {
        assert_eq!(check_shot(&Shot::new(-1e300, 1.0)), Ok(()));
        assert_eq!(check_shot(&Shot::new(f64::MAX, 1.0)), Ok(()));
        assert!(check_shot(&Shot::new(f64::NAN, 1.0)).is_err());
        let mut shot = Shot::new(0.0, 1.0);
        shot.tip.height = f64::INFINITY;
        let e = check_shot(&shot).unwrap_err();
        assert_eq!(e.what, "tip height");
    }

    #[test]
    fn ball_speeds_and_spins_at_the_limits_pass_and_beyond_fail() {
        // A power of two, so that `(s / r) * r` is `s` exactly.
        let r = 0.031_25;
        let x = |v: f64| Vec2::new(v, 0.0);
        let w = |s: f64| Vec3::new(0.0, 0.0, s / r);
        for (v, s) in [
            (0.0, 0.0),
            (MIN_SPEED, MIN_SPEED),
            (MAX_SPEED, MAX_SURFACE_SPEED),
        ] {
            assert_eq!(check_motion(x(v), w(s), r), Ok(()), "{v} {s}");
        }
        assert!(check_motion(x(next_up(MAX_SPEED)), Vec3::ZERO, r).is_err());
        assert!(check_motion(x(next_down(MIN_SPEED)), Vec3::ZERO, r).is_err());
        assert!(check_motion(Vec2::ZERO, w(MAX_SURFACE_SPEED * 1.000_001), r).is_err());
        assert!(check_motion(Vec2::ZERO, w(MIN_SPEED * 0.999_999), r).is_err());
        // Components too large to square, or too small, are still measured right.
        assert!(check_motion(Vec2::new(1e300, 1e300), Vec3::ZERO, r).is_err());
        assert!(check_motion(Vec2::new(1e-300, 0.0), Vec3::ZERO, r).is_err());
        assert!(check_motion(Vec2::new(f64::NAN, 0.0), Vec3::ZERO, r).is_err());
        assert!(check_motion(Vec2::ZERO, Vec3::new(f64::NAN, 0.0, 0.0), r).is_err());
    }

    #[test]
    fn errors_name_the_ball_value_and_limit() {
        let balls = [
            BallSetup::at(0, Vec2::ZERO),
            BallSetup::moving(9, Vec2::ZERO, Vec2::new(0.0, 1e308)),
        ];
        let text = check_setups(&balls, 0.03).unwrap_err().to_string();
        assert_eq!(
            text,
            "ball 9 (index 1): velocity 1e308 m/s is out of range: 0 or from 1e-10 to 100 m/s"
        );
        let text = check_shot(&Shot::new(0.0, 1e308))
            .unwrap_err()
            .for_ball(0, 0);
        assert_eq!(
            text.to_string(),
            "ball 0: shot speed 1e308 m/s is out of range: 0 or from 1e-10 to 100 m/s"
        );
    }

    #[test]
    fn clock_limits() {
        assert_eq!(check_clock(0.0), Ok(()));
        assert_eq!(check_clock(MAX_TIME), Ok(()));
        assert!(check_clock(next_up(MAX_TIME)).is_err());
        assert!(check_clock(f64::NAN).is_err());
        assert!(check_clock(-1.0).is_err());
    }
}
