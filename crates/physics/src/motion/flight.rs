//! A ball in the air: its closed-form flight and its landing.
//!
//! In the air the cloth has no hold on the ball, so (air drag neglected, below) its centre
//! moves at constant velocity in the plane and on the parabola `z(tau) = h0 + v_z tau -
//! g tau^2 / 2` above its height on the cloth, with constant spin (no torque acts; pooltool's
//! `_evolve_airborne_state`). It lands at the positive root of `z(tau) = 0`, in closed form
//! (below), and meets the slate ([`crate::resolve::slate::bounce`]): it bounces again while
//! the rebound would rise at least [`crate::resolve::slate::MIN_BOUNCE_HEIGHT`], then slides
//! on the cloth under the usual model.
//!
//! Air drag, neglected: `F = (1/2) rho C_d A v^2` with `rho = 1.2 kg/m^3`, `C_d = 0.5`,
//! `A = pi R^2 = 2.57e-3 m^2` is 7.7e-4 N per (m/s)^2, a deceleration of 4.5e-3 v^2 m/s^2 for
//! a 0.17 kg ball: at 5 m/s, 0.11 m/s^2 against gravity's 9.81, over a 0.2 s flight 2 cm/s
//! of speed and 2 mm of distance.

use crate::ball::{BallState, Motion, Segment};
use crate::math::Vec2;
use crate::params::{Params, SpinModel};
use crate::resolve::slate::{self, Bounce, Slate};

/// Time from `state` (height `h`, upward speed `v_z`) until the centre is back at its height
/// on the cloth, the positive root of `h + v_z tau - g tau^2 / 2 = 0`: `2 v_z / g` from the
/// cloth, else `(v_z + s) / g` with `s = sqrt(v_z^2 + 2 g h)`, written `2h / (s - v_z)` when
/// `v_z < 0` so that no two near-equal numbers are subtracted.
pub fn landing_time(gravity: f64, height: f64, vertical: f64) -> f64 {
    if height == 0.0 {
        return 2.0 * vertical.max(0.0) / gravity;
    }
    let s = (vertical * vertical + 2.0 * gravity * height).sqrt();
    if vertical >= 0.0 {
        (vertical + s) / gravity
    } else {
        2.0 * height / (s - vertical)
    }
}

/// The flight segment of a ball in `state` (its height and upward speed set) from `start`:
/// constant velocity and spin, falling at `g`, ending when it lands.
pub fn airborne(params: &Params, start: f64, state: BallState) -> Segment {
    let state = BallState {
        motion: Motion::Airborne,
        ..state
    };
    let tau = landing_time(params.gravity, state.height, state.vertical);
    let mut seg = Segment::new(
        start,
        state,
        Vec2::ZERO,
        crate::math::Vec3::ZERO,
        Some(start + tau),
    );
    seg.fall = params.gravity;
    seg
}

/// Where flight `seg` lands and how the ball leaves the slate there: the slate's reaction to
/// the landing speed `-sqrt(v_z^2 + 2 g h)` (energy conservation in flight, exact in closed
/// form). An upward speed means a new flight ([`airborne`] from the cloth); none, the cloth's
/// motion (the caller's [`super::segment_from`]).
pub fn landing(params: &Params, m: &SpinModel, seg: &Segment) -> (f64, Vec2, Bounce) {
    let end = seg.end.expect("a flight ends when it lands");
    let s = seg.state;
    let g = params.gravity;
    let down = -(s.vertical * s.vertical + 2.0 * g * s.height).sqrt();
    let table = Slate {
        restitution: slate::SLATE_RESTITUTION,
        mu: m.mu_slide,
        gravity: g,
        radius: params.ball.radius,
    };
    let b = slate::bounce(&table, s.velocity, down, s.angular_velocity);
    (end, seg.position_at(end), b)
}
