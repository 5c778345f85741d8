//! Closed forms of the paper's model for the scenes that have one, written independently of
//! the library's event loop, so the exact solver's own error can be measured.

use crate::scene::Scene;
use crate::trace::Sample;
use billiards_physics::{Vec2, resolve};

/// A ball moving in a straight line with the paper's piecewise constant deceleration: sliding
/// at `a_s` down to the threshold speed, then rolling at `a_r` to a stop.
#[derive(Clone, Copy, Debug)]
pub struct Path {
    start: f64,
    origin: Vec2,
    dir: Vec2,
    speed: f64,
    a_slide: f64,
    a_roll: f64,
    threshold: f64,
}

impl Path {
    /// A path from `origin` at time `start` with velocity `velocity`, under `scene`'s model.
    pub fn new(scene: &Scene, start: f64, origin: Vec2, velocity: Vec2) -> Self {
        let m = scene.paper_model();
        let g = scene.params.gravity;
        let speed = velocity.length();
        Self {
            start,
            origin,
            dir: velocity.normalized().unwrap_or(Vec2::new(1.0, 0.0)),
            speed,
            a_slide: m.mu_slide * g,
            a_roll: m.mu_roll * g,
            threshold: m.slide_roll_speed,
        }
    }

    /// The sliding phase: its duration and the speed at its end.
    fn slide(&self) -> (f64, f64) {
        if self.speed > self.threshold {
            ((self.speed - self.threshold) / self.a_slide, self.threshold)
        } else {
            (0.0, self.speed)
        }
    }

    /// Distance travelled and speed `tau` seconds after the start.
    fn along(&self, tau: f64) -> (f64, f64) {
        let (t1, v1) = self.slide();
        if tau <= t1 {
            return (
                self.speed * tau - 0.5 * self.a_slide * tau * tau,
                self.speed - self.a_slide * tau,
            );
        }
        let d1 = self.speed * t1 - 0.5 * self.a_slide * t1 * t1;
        let tr = (tau - t1).min(v1 / self.a_roll);
        (
            d1 + v1 * tr - 0.5 * self.a_roll * tr * tr,
            v1 - self.a_roll * tr,
        )
    }

    /// Time after the start at which the ball has travelled `s` metres, if it gets that far.
    fn time_to(&self, s: f64) -> Option<f64> {
        // Smaller root of s = v t - a t^2 / 2, in the cancellation-free form 2 s / (v + sqrt).
        let root = |v: f64, a: f64, s: f64| {
            let disc = v * v - 2.0 * a * s;
            (disc >= 0.0).then(|| 2.0 * s / (v + disc.sqrt()))
        };
        let (t1, v1) = self.slide();
        let d1 = self.speed * t1 - 0.5 * self.a_slide * t1 * t1;
        if s <= d1 {
            root(self.speed, self.a_slide, s)
        } else {
            root(v1, self.a_roll, s - d1).map(|t| t1 + t)
        }
    }

    /// Time at which the ball stops.
    pub fn stop_time(&self) -> f64 {
        let (t1, v1) = self.slide();
        self.start + t1 + v1 / self.a_roll
    }

    /// Position and velocity at absolute time `t` (at or after the start).
    pub fn at(&self, t: f64) -> Sample {
        let (s, v) = self.along(t - self.start);
        Sample {
            position: self.origin + self.dir * s,
            velocity: self.dir * v.max(0.0),
            pocketed: None,
        }
    }
}

/// The closed-form solution of a scene, where one exists.
#[derive(Clone, Debug)]
pub enum Solution {
    /// One ball, no contact.
    Single(Path),
    /// The cut shot: the cue ball's path until the contact, then both balls' paths.
    Cut {
        /// Cue ball until the contact.
        before: Path,
        /// Object ball's resting position.
        object: Vec2,
        /// Time of the contact.
        contact: f64,
        /// Cue ball after the contact.
        cue_after: Path,
        /// Object ball after the contact.
        object_after: Path,
    },
}

impl Solution {
    /// The closed form for `scene` if it is the one-ball stop or a cut on a resting ball
    /// (neither reaching a cushion).
    pub fn of(scene: &Scene) -> Option<Solution> {
        let cue = scene.balls.first()?;
        let before = Path::new(scene, 0.0, cue.position, cue.velocity);
        match scene.balls.len() {
            1 => Some(Solution::Single(before)),
            2 => {
                let object = scene.balls[1].position;
                let m = scene.paper_model();
                // Contact where the line of the cue ball passes 2R from the object ball.
                let rel = object - cue.position;
                let along = rel.dot(before.dir);
                let off = rel.perp_dot(before.dir);
                let d = 2.0 * scene.radius();
                let s = along - (d * d - off * off).sqrt();
                let tau = before.time_to(s)?;
                let at = before.at(tau);
                let n = (object - at.position).normalized()?;
                let (va, vb) =
                    resolve::equal_mass_restitution(at.velocity, Vec2::ZERO, n, m.e_ball)?;
                Some(Solution::Cut {
                    before,
                    object,
                    contact: tau,
                    cue_after: Path::new(scene, tau, at.position, va),
                    object_after: Path::new(scene, tau, object, vb),
                })
            }
            _ => None,
        }
    }

    /// Every ball's state at time `t`.
    pub fn at(&self, t: f64) -> Vec<Sample> {
        match self {
            Solution::Single(p) => vec![p.at(t)],
            Solution::Cut {
                before,
                object,
                contact,
                cue_after,
                object_after,
            } => {
                if t < *contact {
                    vec![
                        before.at(t),
                        Sample {
                            position: *object,
                            ..Sample::default()
                        },
                    ]
                } else {
                    vec![cue_after.at(t), object_after.at(t)]
                }
            }
        }
    }

    /// Time at which every ball has stopped.
    pub fn rest_time(&self) -> f64 {
        match self {
            Solution::Single(p) => p.stop_time(),
            Solution::Cut {
                cue_after,
                object_after,
                ..
            } => cue_after.stop_time().max(object_after.stop_time()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene;

    #[test]
    fn a_sliding_ball_stops_after_the_two_phase_distance() {
        let s = scene::stop();
        let b = s.balls[0];
        let path = Path::new(&s, 0.0, b.position, b.velocity);
        let m = s.paper_model();
        let (g, v0, vs) = (s.params.gravity, b.velocity.length(), m.slide_roll_speed);
        let d = (v0 * v0 - vs * vs) / (2.0 * m.mu_slide * g) + vs * vs / (2.0 * m.mu_roll * g);
        let end = path.at(path.stop_time() + 1.0);
        assert!(((end.position - b.position).length() - d).abs() < 1e-12);
        assert_eq!(end.velocity, Vec2::ZERO);
    }

    #[test]
    fn the_cut_sends_the_balls_off_at_right_angles() {
        let Some(Solution::Cut {
            cue_after,
            object_after,
            contact,
            ..
        }) = Solution::of(&scene::cut())
        else {
            panic!("the cut scene has a closed form");
        };
        let (a, b) = (cue_after.at(contact), object_after.at(contact));
        assert!(a.velocity.dot(b.velocity).abs() < 1e-12);
        let cut = (scene::CUT_OFFSET / (2.0 * scene::cut().radius())).asin();
        assert!((b.velocity.angle() - cut).abs() < 1e-12);
    }
}
