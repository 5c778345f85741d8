//! The strike and a ball's flight: the cue's 3D impulse with the slate's reaction
//! ([`crate::resolve::cue::strike`]), and the segments of a ball in the air.

use super::{SetupError, Simulation, setup};
use crate::ball::{BallId, BallState, Motion, Segment};
use crate::detect;
use crate::event::{EventKind, Shot};
use crate::math::{Vec2, Vec3};
use crate::motion;
use crate::params::Model;
use crate::resolve::slate::{SLATE_RESTITUTION, Slate};
use crate::resolve::{self, Laws};
use crate::table::{Cushion, Pocket};

impl Simulation {
    /// Strikes ball `id` now: the paper's cue (an angle and a magnitude); the spin model also
    /// takes the tip offset and the cue's elevation (the paper's model has no spin and
    /// ignores both).
    pub fn strike(&mut self, id: BallId, shot: Shot) -> Result<(), SetupError> {
        self.flush();
        let state = self.ball_checked(id)?;
        setup::check_shot(id, self.numbers[id], &shot, self.time)?;
        if state.motion == Motion::Airborne {
            // The cue's impulse is balanced by the slate's (`resolve/cue.rs`): none in the air.
            return Err(SetupError::Limit(crate::limits::LimitError {
                ball: Some((id, self.numbers[id])),
                what: "height",
                value: state.height,
                unit: "m",
                expected: "0: a ball in the air cannot be struck".into(),
            }));
        }
        let dir = Vec2::from_angle(shot.angle);
        let cue = Laws::of(&self.params.model).cue;
        let cue_at = resolve::cue::Cue {
            dir,
            elevation: shot.elevation,
        };
        let (ball, g) = (&self.params.ball, self.params.gravity);
        let b = cue.strike(ball, g, cue_at, shot.speed, shot.tip)?;
        let (p, v, w) = (state.position, b.velocity, b.spin);
        self.segments[id] = if b.vertical > 0.0 {
            // The slate's rebound lifts the ball: it flies from the cloth.
            let state = BallState {
                position: p,
                velocity: v,
                angular_velocity: w,
                motion: Motion::Airborne,
                height: 0.0,
                vertical: b.vertical,
            };
            motion::flight::airborne(&self.params, self.time, state)
        } else {
            motion::segment_from(&self.params, self.time, p, v, w)
        };
        self.record(EventKind::Strike { ball: id, shot });
        self.inputs_done();
        self.repredict([id]);
        Ok(())
    }
}

impl Simulation {
    /// Ball `id` is level with the cloth at `t`: on it, or in the air under
    /// [`detect::LEVEL`]. Its contacts with other level balls are in the plane (the pair law,
    /// a cluster impact); a ball higher up meets others in space ([`Self::air_pair`]).
    pub(super) fn level_at(&self, id: BallId, t: f64) -> bool {
        let seg = &self.segments[id];
        seg.state.motion != Motion::Airborne || seg.height_at(t) <= detect::LEVEL
    }

    /// Balls `a` and `b`, one of them at least in the air, touch in space
    /// ([`resolve::ball_air::air_pair`]): each flies on, or goes on along the cloth.
    pub(super) fn air_pair(&mut self, a: BallId, b: BallId) {
        let t = self.time;
        let (sa, sb) = (self.segments[a].state_at(t), self.segments[b].state_at(t));
        let (e, mu) = match self.params.model {
            Model::Spin(m) => (m.e_ball, m.mu_slide),
            Model::Paper(m) => (m.e_ball, m.mu_slide),
        };
        let table = Slate {
            restitution: SLATE_RESTITUTION,
            mu,
            gravity: self.params.gravity,
            radius: self.params.ball.radius,
        };
        let acc = |id: BallId| {
            let seg = &self.segments[id];
            Vec3::new(seg.acceleration.x, seg.acceleration.y, -seg.fall)
        };
        let (na, nb) = resolve::ball_air::air_pair(e, &table, (&sa, acc(a)), (&sb, acc(b)));
        for (id, s) in [(a, na), (b, nb)] {
            self.segments[id] = if s.motion == Motion::Airborne {
                motion::flight::airborne(&self.params, t, s)
            } else {
                motion::segment_from(&self.params, t, s.position, s.velocity, s.angular_velocity)
            };
        }
        self.record(EventKind::BallBall { a, b });
        self.repredict_event(a, Some(b));
    }
}

impl Simulation {
    /// Ball `id`, reaching `cushion`'s contact line, is in the air high enough to pass over
    /// the nose. The nose is `h_n = cushion_height (2R)` above the cloth and the ball's lowest
    /// point is its rise `z` above the cloth; the ball clears it if `z >= h_n` both now (its
    /// side level with the nose) and when its centre is over the nose, `R / v_n` later at its
    /// constant speed `v_n` towards the cushion (the parabola is concave, so `z` is least at
    /// one of the two). Lower, it meets the nose and rebounds as on the cloth.
    pub(super) fn clears_cushion(&self, id: BallId, cushion: Cushion) -> bool {
        let r = self.params.ball.radius;
        self.clears(id, cushion.inward_normal(), r)
    }

    /// Ball `id`, in the air, keeps its lowest point at or above the cushion nose's height
    /// (`cushion_height (2R)` above the cloth) from now until its centre has gone `reach`
    /// farther across a line of unit normal `inward` (pointing onto the table). The parabola
    /// is concave, so the least height over that stretch is at one of its two ends. False
    /// for a ball on the cloth, under the paper's model, or not crossing outwards.
    fn clears(&self, id: BallId, inward: Vec2, reach: f64) -> bool {
        let seg = &self.segments[id];
        let Model::Spin(m) = self.params.model else {
            return false;
        };
        if seg.state.motion != Motion::Airborne {
            return false;
        }
        let r = self.params.ball.radius;
        // The centre's height above its height on the cloth is the lowest point's rise.
        let nose = m.cushion_height * 2.0 * r;
        let towards = -inward.dot(seg.state.velocity);
        if towards <= 0.0 {
            return false;
        }
        let t = self.time;
        let over = t + reach / towards;
        seg.height_at(t) >= nose && seg.height_at(over) >= nose
    }

    /// Ball `id` crosses `pocket`'s opening (the line across a jaws table's mouth, or a
    /// mouth of the paper's table on the cushion line, unit normal `inward` onto the table):
    /// it drops in, a pocket event as on the cloth, unless it is in the air and flies over
    /// the whole hole. The hole is taken as wide as the pocket's mouth beyond the opening (the
    /// tables give no depth), and its far edge, the rail, as high as the cushion nose: the
    /// ball flies over and off the table when its lowest point stays at or above the nose's
    /// height until its centre is a mouth's width past the opening ([`Self::clears`]); lower,
    /// it comes down into the pocket or meets the far side below the rail's top and drops.
    pub(super) fn across_opening(&mut self, id: BallId, pocket: Pocket, inward: Vec2) {
        let table = &self.bodies.table;
        let mouth = if pocket.is_corner() {
            table.corner_mouth
        } else {
            table.side_mouth
        };
        if self.clears(id, inward, mouth) {
            self.off_table(id)
        } else {
            self.pocket(id, pocket)
        }
    }

    /// Ball `id` flies off the table over a cushion: out of play
    /// ([`Motion::OffTable`]), recorded as a transition from the air.
    pub(super) fn off_table(&mut self, id: BallId) {
        let t = self.time;
        let s = self.segments[id].state_at(t);
        self.segments[id] = Segment::at_rest(t, s.position, Motion::OffTable);
        let (from, to) = (Motion::Airborne, Motion::OffTable);
        self.record(EventKind::Transition { ball: id, from, to });
        self.repredict_event(id, None);
    }
}

impl Simulation {
    /// Sets ball `id`, on the table, in the air now: its centre `height` metres above its
    /// height on the cloth, rising at `vertical` m/s (falling if negative), its velocity in
    /// the plane and its spin kept (a scene file's ball in the air, an editor). Recorded as
    /// a placement ([`EventKind::Placed`], its state in the air). Only the spin model flies;
    /// the values are checked by [`crate::limits::check_flight`], and the ball must be clear
    /// of the others in space.
    pub fn launch(&mut self, id: BallId, height: f64, vertical: f64) -> Result<(), SetupError> {
        self.flush();
        let state = self.ball_checked(id)?;
        let number = self.numbers[id];
        if let Model::Paper(_) = self.params.model {
            return Err(SetupError::Limit(crate::limits::LimitError {
                ball: Some((id, number)),
                what: "height",
                value: height,
                unit: "m",
                expected: "0: the paper's model has no flight (use the spin model)".into(),
            }));
        }
        crate::limits::check_flight(height, vertical)
            .and_then(|()| crate::limits::check_clock(self.time))
            .map_err(|e| e.for_ball(id, number))?;
        let r2 = 2.0 * self.params.ball.radius;
        for (j, seg) in self.segments.iter().enumerate() {
            let d = seg.position_at(self.time) - state.position;
            let dz = seg.height_at(self.time) - height;
            let gap = (d.length_squared() + dz * dz).sqrt() - r2;
            if j != id && seg.state.motion.on_table() && gap < 0.0 {
                return Err(SetupError::Overlap {
                    a: id,
                    b: j,
                    numbers: (number, self.numbers[j]),
                    overlap: -gap,
                });
            }
        }
        let flying = BallState {
            height,
            vertical,
            motion: Motion::Airborne,
            ..state
        };
        self.segments[id] = motion::flight::airborne(&self.params, self.time, flying);
        self.record(EventKind::Placed { ball: id });
        self.inputs_done();
        self.repredict([id]);
        Ok(())
    }
}
