//! Per-ball state and its closed-form motion between events, and a ball as a simulation
//! starts from ([`BallSetup`]).

use crate::math::{Vec2, Vec3};
use crate::table::Pocket;
use serde::{Deserialize, Serialize};

/// Index of a ball in a [`crate::Simulation`] (0 is the cue ball in every standard setup).
pub type BallId = usize;

/// A ball as given to [`crate::Simulation::new`].
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

/// A ball's motion state. Set explicitly at every event, never re-derived from a float
/// comparison inside the event loop (see the reference's robustness lessons).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Motion {
    /// At rest.
    #[default]
    Stationary,
    /// Turning about the vertical in place (spin model), not moving.
    Spinning,
    /// Decelerating at the sliding rate.
    Sliding,
    /// Decelerating at the rolling rate.
    Rolling,
    /// In the air (spin model): a parabola under gravity with constant spin, no cloth
    /// friction; [`BallState::height`] and [`BallState::vertical`] hold its vertical state.
    Airborne,
    /// Out of play, in this pocket.
    Pocketed(Pocket),
    /// Out of play off the table: it flew over a cushion's nose (spin model).
    OffTable,
}

impl Motion {
    /// Moving on the table (not stationary, not pocketed).
    pub fn is_moving(self) -> bool {
        matches!(self, Motion::Sliding | Motion::Rolling | Motion::Airborne)
    }

    /// In play (not pocketed).
    pub fn on_table(self) -> bool {
        !matches!(self, Motion::Pocketed(_) | Motion::OffTable)
    }

    /// Nothing about the ball will change until something hits it.
    pub fn is_at_rest(self) -> bool {
        matches!(
            self,
            Motion::Stationary | Motion::Pocketed(_) | Motion::OffTable
        )
    }
}

/// A ball's kinematic state at one instant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BallState {
    /// Centre, in the table plane, metres.
    pub position: Vec2,
    /// Velocity, m/s.
    pub velocity: Vec2,
    /// Angular velocity, rad/s (zero in the paper's model).
    pub angular_velocity: Vec3,
    /// Motion state.
    pub motion: Motion,
    /// Height of the centre above its height on the cloth, metres: 0 unless
    /// [`Motion::Airborne`] (absent from files of balls on the cloth).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub height: f64,
    /// Upward speed, m/s: 0 unless [`Motion::Airborne`].
    #[serde(default, skip_serializing_if = "is_zero")]
    pub vertical: f64,
}

/// A ball on the cloth is written as before flight existed.
fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// The closed-form motion of one ball from one event to its next: constant acceleration, so
/// the position is quadratic in time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Segment {
    /// Absolute time the segment starts, seconds.
    pub start: f64,
    /// State at `start`.
    pub state: BallState,
    /// Constant linear acceleration over the segment, m/s^2.
    pub acceleration: Vec2,
    /// Constant angular acceleration over the segment, rad/s^2.
    pub angular_acceleration: Vec3,
    /// Absolute time at which the motion state changes by itself (slide to roll, stop), if it
    /// ever does.
    pub end: Option<f64>,
    /// Downward acceleration of the centre, m/s^2: gravity in the air, 0 on the cloth.
    #[serde(default)]
    pub fall: f64,
    /// Speed at `start` and magnitude of `acceleration`, cached for the culling bound
    /// [`Segment::reach`] on the hot path.
    pub speed: f64,
    /// Magnitude of `acceleration`.
    pub accel: f64,
    /// The acceleration is zero or exactly opposed to the velocity (a straight decelerating
    /// path, as in the paper's model).
    pub straight: bool,
}

impl Segment {
    /// A segment at rest (or pocketed) from `start` on.
    pub fn at_rest(start: f64, position: Vec2, motion: Motion) -> Self {
        let state = BallState {
            position,
            motion,
            ..BallState::default()
        };
        Self::new(start, state, Vec2::ZERO, Vec3::ZERO, None)
    }

    /// A segment from its state at `start`, its constant accelerations and its end.
    pub fn new(
        start: f64,
        state: BallState,
        acceleration: Vec2,
        angular_acceleration: Vec3,
        end: Option<f64>,
    ) -> Self {
        let v = state.velocity;
        let (speed, accel) = (v.length(), acceleration.length());
        // Decelerating along the velocity, and stopping no earlier than the segment ends: a
        // sliding ball with strong draw reverses within its segment and comes back past its
        // start, beyond the swept segment of `detect` and the bound of `reach` (soak seed
        // 23445). Overshooting the stop by 1e-9 of its time moves a ball ~1e-18 of its run.
        let stops_in_time = end.is_some_and(|e| {
            accel * (e - start) <= speed * (1.0 + 1e-9) + accel * 4.0 * f64::EPSILON * e.abs()
        });
        let straight = accel == 0.0
            || (v.perp_dot(acceleration).abs() <= 1e-12 * speed * accel
                && v.dot(acceleration) < 0.0
                && stops_in_time);
        Self {
            start,
            state,
            acceleration,
            angular_acceleration,
            end,
            speed,
            accel,
            straight,
            fall: 0.0,
        }
    }

    /// Height of the centre above its height on the cloth at absolute time `t`
    /// (`h0 + v_z tau - g tau^2 / 2`; 0 on the cloth).
    #[inline]
    pub fn height_at(&self, t: f64) -> f64 {
        let tau = t - self.start;
        self.state.height + (self.state.vertical - 0.5 * self.fall * tau) * tau
    }

    /// Upward speed at absolute time `t` (`v_z - g tau`).
    #[inline]
    pub fn vertical_at(&self, t: f64) -> f64 {
        self.state.vertical - self.fall * (t - self.start)
    }

    /// Position at absolute time `t` (within the segment).
    #[inline]
    pub fn position_at(&self, t: f64) -> Vec2 {
        let tau = t - self.start;
        let s = &self.state;
        s.position + (s.velocity + self.acceleration * (0.5 * tau)) * tau
    }

    /// Velocity at absolute time `t`.
    #[inline]
    pub fn velocity_at(&self, t: f64) -> Vec2 {
        self.state.velocity + self.acceleration * (t - self.start)
    }

    /// Angular velocity at absolute time `t`. The vertical component decays towards zero and
    /// stays there (spin friction about the vertical), so it needs no event of its own while
    /// the ball moves.
    pub fn angular_velocity_at(&self, t: f64) -> Vec3 {
        let tau = t - self.start;
        let w0 = self.state.angular_velocity;
        let w = w0 + self.angular_acceleration * tau;
        let z = if w.z * w0.z <= 0.0 { 0.0 } else { w.z };
        Vec3::new(w.x, w.y, z)
    }

    /// Full state at absolute time `t` (the motion state is the segment's).
    pub fn state_at(&self, t: f64) -> BallState {
        if self.state.motion == Motion::Spinning {
            let angular_velocity = self.angular_velocity_at(t);
            return BallState {
                angular_velocity,
                ..self.state
            };
        }
        if !self.state.motion.is_moving() {
            return self.state;
        }
        let (height, vertical) = if self.state.motion == Motion::Airborne {
            (self.height_at(t), self.vertical_at(t))
        } else {
            (0.0, 0.0)
        };
        BallState {
            position: self.position_at(t),
            velocity: self.velocity_at(t),
            angular_velocity: self.angular_velocity_at(t),
            motion: self.state.motion,
            height,
            vertical,
        }
    }

    /// An upper bound on how far the centre can move from its position at `t` before `t + h`.
    /// Used to cull pairs that cannot meet before any polynomial is solved.
    pub fn reach(&self, t: f64, h: f64) -> f64 {
        if !self.state.motion.is_moving() {
            return 0.0;
        }
        let tau = t - self.start;
        let h = match self.end {
            Some(end) => h.min(end - t),
            None => h,
        }
        .max(0.0);
        if self.straight {
            // Decelerating along the velocity: speed s - a tau, travelling at most s^2 / (2a).
            let s = (self.speed - self.accel * tau).max(0.0);
            let hs = if self.accel > 0.0 {
                h.min(s / self.accel)
            } else {
                h
            };
            return s * hs - 0.5 * self.accel * hs * hs;
        }
        let s = self.speed + self.accel * tau;
        s * h + 0.5 * self.accel * h * h
    }
}
