//! Closed-form motion between events for each model.
//!
//! Paper model (3.3–3.4): deceleration `mu g` against the velocity, `mu_s` above the slide/roll
//! speed and `mu_r` below it. Spin model (Leckie & Greenspan; the reference's equations of
//! motion): with contact-point velocity `u = v - R (w x z)`, a sliding ball decelerates at
//! `mu_s g` against `u` while `w_xy` gains `(5 mu_s g / 2R) (z x u_hat)`, so `u` keeps its
//! direction and shrinks at `(7/2) mu_s g` until the ball rolls after `2|u| / (7 mu_s g)`;
//! a rolling ball decelerates at `mu_r g` with `w_xy` locked to `v`; spin about the vertical
//! decays at `5 mu_sp g / (2R)` in every state. Every segment has constant accelerations, so
//! positions stay quadratic in time.

use crate::ball::{BallState, Motion, Segment};
use crate::math::{Vec2, Vec3};
use crate::params::{Model, Params, SpinModel};

pub mod flight;

/// Contact-point slip below which a ball counts as rolling (m/s): rounding noise in
/// `v - R (w x z)` at break speeds is about 1e-15 m/s.
const ROLLING_SLIP: f64 = 1e-12;

/// The segment a ball follows from `start`, given its state there, with its motion state
/// decided by the velocities (used after collisions and strikes, where the state really is
/// decided by the new velocities; transitions set it explicitly instead).
pub fn segment_from(
    params: &Params,
    start: f64,
    position: Vec2,
    velocity: Vec2,
    spin: Vec3,
) -> Segment {
    match params.model {
        Model::Paper(m) => {
            let speed = velocity.length();
            if speed == 0.0 {
                return Segment::at_rest(start, position, Motion::Stationary);
            }
            let motion = if speed > m.slide_roll_speed {
                Motion::Sliding
            } else {
                Motion::Rolling
            };
            paper_segment(params, start, position, velocity, motion)
        }
        Model::Spin(m) => {
            let state = BallState {
                position,
                velocity,
                angular_velocity: spin,
                motion: Motion::Sliding,
                ..BallState::default()
            };
            let slip = contact_velocity(&state, params.ball.radius);
            if velocity == Vec2::ZERO && spin.xy() == Vec2::ZERO {
                spinning_or_still(params, &m, start, position, spin.z)
            } else if slip.length() > ROLLING_SLIP {
                sliding(params, &m, start, state, slip)
            } else {
                rolling(params, &m, start, position, velocity, spin.z)
            }
        }
    }
}

/// The segment for a state whose motion state is already decided (an event's recorded
/// after-state): the same segment the solver built for it, without re-deriving the state.
pub fn segment_with_motion(params: &Params, start: f64, state: &BallState) -> Segment {
    let (p, v, w) = (state.position, state.velocity, state.angular_velocity);
    match (params.model, state.motion) {
        (_, Motion::Stationary | Motion::Pocketed(_) | Motion::OffTable) => {
            Segment::at_rest(start, p, state.motion)
        }
        (_, Motion::Airborne) => flight::airborne(params, start, *state),
        (Model::Paper(_), motion) => paper_segment(params, start, p, v, motion),
        (Model::Spin(m), Motion::Sliding) => sliding(
            params,
            &m,
            start,
            *state,
            contact_velocity(state, params.ball.radius),
        ),
        (Model::Spin(m), Motion::Rolling) => rolling(params, &m, start, p, v, w.z),
        (Model::Spin(m), Motion::Spinning) => spinning_or_still(params, &m, start, p, w.z),
    }
}

/// The segment a ball in state `before` (its state just before a collision, at `start`)
/// continues on with the new `velocity` and `spin`: in the air it keeps flying from its
/// height and upward speed (the collision is in the table plane), on the cloth it is
/// [`segment_from`].
pub fn segment_after(
    params: &Params,
    start: f64,
    before: &BallState,
    velocity: Vec2,
    spin: Vec3,
) -> Segment {
    if before.motion != Motion::Airborne {
        return segment_from(params, start, before.position, velocity, spin);
    }
    let state = BallState {
        velocity,
        angular_velocity: spin,
        ..*before
    };
    flight::airborne(params, start, state)
}

/// Velocity of the ball's contact point with the cloth, `v + w x (-R z)`.
pub fn contact_velocity(s: &BallState, radius: f64) -> Vec2 {
    let w = s.angular_velocity;
    Vec2::new(s.velocity.x - radius * w.y, s.velocity.y + radius * w.x)
}

fn paper_segment(
    params: &Params,
    start: f64,
    position: Vec2,
    velocity: Vec2,
    motion: Motion,
) -> Segment {
    let Model::Paper(m) = params.model else {
        unreachable!("paper segment for the paper model")
    };
    let speed = velocity.length();
    let (decel, end_speed) = match motion {
        Motion::Sliding => (m.mu_slide * params.gravity, m.slide_roll_speed),
        _ => (m.mu_roll * params.gravity, 0.0),
    };
    let dir = velocity / speed;
    let state = BallState {
        position,
        velocity,
        motion,
        ..BallState::default()
    };
    let end = (decel > 0.0).then(|| start + (speed - end_speed) / decel);
    Segment::new(start, state, dir * -decel, Vec3::ZERO, end)
}

/// Angular deceleration of spin about the vertical, `5 mu_sp g / (2R)`.
fn spin_decel(params: &Params, m: &SpinModel) -> f64 {
    2.5 * m.mu_spin * params.gravity / params.ball.radius
}

/// `alpha_z` that decays `wz` towards zero (the segment clamps it there).
fn spin_decay(params: &Params, m: &SpinModel, wz: f64) -> f64 {
    if wz == 0.0 {
        0.0
    } else {
        -wz.signum() * spin_decel(params, m)
    }
}

fn spinning_or_still(
    params: &Params,
    m: &SpinModel,
    start: f64,
    position: Vec2,
    wz: f64,
) -> Segment {
    let decel = spin_decel(params, m);
    if wz == 0.0 {
        return Segment::at_rest(start, position, Motion::Stationary);
    }
    let state = BallState {
        position,
        angular_velocity: Vec3::new(0.0, 0.0, wz),
        motion: Motion::Spinning,
        ..BallState::default()
    };
    let end = (decel > 0.0).then(|| start + wz.abs() / decel);
    Segment::new(
        start,
        state,
        Vec2::ZERO,
        Vec3::new(0.0, 0.0, spin_decay(params, m, wz)),
        end,
    )
}

fn sliding(params: &Params, m: &SpinModel, start: f64, state: BallState, slip: Vec2) -> Segment {
    let g = params.gravity;
    let r = params.ball.radius;
    let slip_speed = slip.length();
    let u = slip / slip_speed;
    let wz = state.angular_velocity.z;
    let alpha = (2.5 * m.mu_slide * g / r) * u.perp();
    let accel = Vec3::new(alpha.x, alpha.y, spin_decay(params, m, wz));
    let end = (m.mu_slide * g > 0.0).then(|| start + 2.0 * slip_speed / (7.0 * m.mu_slide * g));
    Segment::new(
        start,
        BallState {
            motion: Motion::Sliding,
            ..state
        },
        u * (-m.mu_slide * g),
        accel,
        end,
    )
}

/// Rolling: `w_xy` is set exactly to the rolling value for `v` (w x z = v / R).
fn rolling(
    params: &Params,
    m: &SpinModel,
    start: f64,
    position: Vec2,
    velocity: Vec2,
    wz: f64,
) -> Segment {
    let r = params.ball.radius;
    let speed = velocity.length();
    if speed == 0.0 {
        return spinning_or_still(params, m, start, position, wz);
    }
    let decel = m.mu_roll * params.gravity;
    let a = velocity * (-decel / speed);
    let state = BallState {
        position,
        velocity,
        angular_velocity: Vec3::new(-velocity.y / r, velocity.x / r, wz),
        motion: Motion::Rolling,
        ..BallState::default()
    };
    let alpha = Vec3::new(-a.y / r, a.x / r, spin_decay(params, m, wz));
    let end = (decel > 0.0).then(|| start + speed / decel);
    Segment::new(start, state, a, alpha, end)
}

/// The segment a ball on `seg` continues on from `t` when the parameters become `params`: a
/// moving or spinning ball goes on from its state at `t` under the new ones; a ball at rest
/// (or pocketed) keeps its segment.
pub fn under_new_params(params: &Params, t: f64, seg: &Segment) -> Segment {
    if !seg.state.motion.on_table() || seg.state.motion.is_at_rest() {
        return *seg;
    }
    let s = seg.state_at(t);
    segment_after(params, t, &s, s.velocity, s.angular_velocity)
}

/// The segment after `seg` reaches its end by itself. The new motion state is set explicitly,
/// never re-derived from the velocities, so a transition cannot fire again at the same
/// instant: sliding turns to rolling (paper: at exactly the threshold speed), rolling stops
/// (spin model: it may keep spinning about the vertical), spinning stops.
pub fn after_transition(params: &Params, seg: &Segment) -> Segment {
    let end = seg
        .end
        .expect("a transition happens only at a segment's end");
    let position = seg.position_at(end);
    match (params.model, seg.state.motion) {
        (Model::Paper(m), Motion::Sliding) if m.slide_roll_speed > 0.0 => {
            let dir = seg.state.velocity / seg.state.velocity.length();
            paper_segment(
                params,
                end,
                position,
                dir * m.slide_roll_speed,
                Motion::Rolling,
            )
        }
        (Model::Spin(m), Motion::Sliding) => {
            let wz = seg.angular_velocity_at(end).z;
            rolling(params, &m, end, position, seg.velocity_at(end), wz)
        }
        (Model::Spin(m), Motion::Rolling) => {
            spinning_or_still(params, &m, end, position, seg.angular_velocity_at(end).z)
        }
        (Model::Spin(m), Motion::Airborne) => {
            let (end, position, b) = flight::landing(params, &m, seg);
            if b.vertical > 0.0 {
                let state = BallState {
                    position,
                    velocity: b.velocity,
                    angular_velocity: b.spin,
                    motion: Motion::Airborne,
                    height: 0.0,
                    vertical: b.vertical,
                };
                return flight::airborne(params, end, state);
            }
            segment_from(params, end, position, b.velocity, b.spin)
        }
        _ => Segment::at_rest(end, position, Motion::Stationary),
    }
}
