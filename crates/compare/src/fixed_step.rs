//! Fixed-step integration of the paper's model, the way most games step their physics.
//!
//! Semi-implicit (symplectic) Euler: each step first decelerates every velocity by the
//! friction of the ball's current speed regime, then moves every ball with its new velocity.
//! Collisions are then found either the common way ([`Collisions::Discrete`]: look for
//! overlaps at the end of the step, resolve them with the paper's collision laws and push the
//! balls apart) or with continuous detection ([`Collisions::Swept`]: sweep the straight paths
//! of the step and stop at every time of impact inside it). Collision laws are exactly the
//! library's (`resolve::reflect`, `resolve::equal_mass_restitution`), so differences from the
//! exact solver come only from the time stepping.

use crate::scene::Scene;
use crate::trace::{
    CONTACT_TOLERANCE, Contact, ContactKey, OVERLAP_TOLERANCE, OverlapWatch, Sample, Trace,
};
use billiards_physics::{Cushion, Pocket, Table, Vec2, resolve};

/// How a fixed-step integrator finds collisions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Collisions {
    /// Move every ball a full step, then look for overlaps and push the balls apart.
    Discrete,
    /// Sweep the straight paths of the step and stop at each time of impact inside it
    /// (continuous collision detection); friction still acts once per step.
    Swept,
}

/// A solver that advances by a fixed time step (this module's integrators and Rapier).
pub trait Stepper {
    /// The time step, seconds.
    fn dt(&self) -> f64;
    /// Advances one step.
    fn step(&mut self);
    /// Writes every ball's current state into `out` (cleared first).
    fn balls(&self, out: &mut Vec<Sample>);
    /// For each ball, whether a contact changed its velocity during the last step.
    fn hit(&self) -> &[bool];
    /// The contacts resolved since the last call.
    fn take_contacts(&mut self) -> Vec<Contact>;
    /// Ball–ball collisions resolved more than [`CONTACT_TOLERANCE`] from touching, and the
    /// largest distance from touching at a resolved collision (NaN if the solver does not
    /// expose it).
    fn contact_gaps(&self) -> (usize, f64);
}

/// Most collisions one swept step resolves before it gives up and moves on; only a cluster
/// of balls pressed together can reach it.
const SWEPT_EVENT_CAP: usize = 10_000;

/// One ball of a fixed-step integrator.
#[derive(Clone, Copy, Debug)]
struct Body {
    position: Vec2,
    velocity: Vec2,
    pocketed: Option<Pocket>,
}

/// Semi-implicit Euler integration of the paper's model at a fixed time step.
#[derive(Clone, Debug)]
pub struct FixedStep {
    dt: f64,
    collisions: Collisions,
    table: Table,
    bounds: Vec2,
    radius: f64,
    decel_slide: f64,
    decel_roll: f64,
    slide_roll_speed: f64,
    e_ball: f64,
    e_cushion: f64,
    bodies: Vec<Body>,
    steps: u64,
    hit: Vec<bool>,
    contacts: Vec<Contact>,
    gap_contacts: usize,
    max_contact_gap: f64,
}

impl FixedStep {
    /// An integrator for `scene` stepping by `dt` seconds.
    pub fn new(scene: &Scene, dt: f64, collisions: Collisions) -> Self {
        let m = scene.paper_model();
        let g = scene.params.gravity;
        Self {
            dt,
            collisions,
            table: scene.table,
            bounds: scene.bounds(),
            radius: scene.radius(),
            decel_slide: m.mu_slide * g,
            decel_roll: m.mu_roll * g,
            slide_roll_speed: m.slide_roll_speed,
            e_ball: m.e_ball,
            e_cushion: m.e_cushion,
            bodies: scene
                .balls
                .iter()
                .map(|b| Body {
                    position: b.position,
                    velocity: b.velocity,
                    pocketed: None,
                })
                .collect(),
            steps: 0,
            hit: vec![false; scene.balls.len()],
            contacts: Vec::new(),
            gap_contacts: 0,
            max_contact_gap: 0.0,
        }
    }

    /// Time at the start of the current step.
    fn now(&self) -> f64 {
        self.steps as f64 * self.dt
    }

    /// Friction for one step: the regime is chosen from the speed at the start of the step,
    /// and the speed is clamped at the end of the regime (the slide/roll threshold, or zero)
    /// instead of overshooting it, as a careful per-frame game update does. Without the clamp
    /// a sliding ball undershoots the threshold by up to `mu_s g dt`, and the long rolling
    /// phase (`mu_r` is 20 times smaller) turns that into decimetres.
    fn apply_friction(&mut self) {
        for b in self.bodies.iter_mut().filter(|b| b.pocketed.is_none()) {
            let speed = b.velocity.length();
            if speed == 0.0 {
                continue;
            }
            let (decel, floor) = if speed > self.slide_roll_speed {
                (self.decel_slide, self.slide_roll_speed)
            } else {
                (self.decel_roll, 0.0)
            };
            let new_speed = (speed - decel * self.dt).max(floor);
            b.velocity = if new_speed > 0.0 {
                b.velocity * (new_speed / speed)
            } else {
                Vec2::ZERO
            };
        }
    }

    /// The limit of the centre's coordinate along a cushion's axis, and that coordinate.
    fn cushion_gap(&self, b: &Body, c: Cushion) -> f64 {
        // Distance (positive inside) from the centre to the line it may not cross.
        match c {
            Cushion::Head => b.position.x + self.bounds.x,
            Cushion::Foot => self.bounds.x - b.position.x,
            Cushion::Left => self.bounds.y - b.position.y,
            Cushion::Right => b.position.y + self.bounds.y,
        }
    }

    /// A ball touching cushion `c` at its current position: drops into the pocket if the
    /// contact is inside a mouth, otherwise reflects (if moving into the cushion).
    fn cushion_contact(&mut self, i: usize, c: Cushion, time: f64) {
        let n = c.inward_normal();
        let b = &mut self.bodies[i];
        if let Some(p) = self.table.pocket_at(c, b.position) {
            b.pocketed = Some(p);
            b.velocity = Vec2::ZERO;
            self.hit[i] = true;
            self.contacts.push(Contact {
                time,
                key: ContactKey::Pocket(i),
            });
        } else if let Some(v) = resolve::reflect(b.velocity, n, self.e_cushion) {
            b.velocity = v;
            self.hit[i] = true;
            self.contacts.push(Contact {
                time,
                key: ContactKey::Cushion(i),
            });
        }
    }

    /// Resolves a contact between balls `i` and `j` touching or overlapping now; returns
    /// whether they were approaching (a real collision).
    fn pair_contact(&mut self, i: usize, j: usize, time: f64) -> bool {
        let (a, b) = (self.bodies[i], self.bodies[j]);
        let n = (b.position - a.position)
            .normalized()
            .unwrap_or(Vec2::new(1.0, 0.0));
        match resolve::equal_mass_restitution(a.velocity, b.velocity, n, self.e_ball) {
            Some((va, vb)) => {
                // Discrete detection resolves at whatever overlap the step ended with.
                let gap = ((b.position - a.position).length() - 2.0 * self.radius).abs();
                self.max_contact_gap = self.max_contact_gap.max(gap);
                if gap > CONTACT_TOLERANCE {
                    self.gap_contacts += 1;
                }
                self.bodies[i].velocity = va;
                self.bodies[j].velocity = vb;
                self.hit[i] = true;
                self.hit[j] = true;
                self.contacts.push(Contact {
                    time,
                    key: ContactKey::pair(i, j),
                });
                true
            }
            None => false,
        }
    }

    fn step_discrete(&mut self) {
        let end = self.now() + self.dt;
        for b in self.bodies.iter_mut().filter(|b| b.pocketed.is_none()) {
            b.position += b.velocity * self.dt;
        }
        let d2 = 2.0 * self.radius;
        let n = self.bodies.len();
        for i in 0..n {
            if self.bodies[i].pocketed.is_some() {
                continue;
            }
            for j in i + 1..n {
                let (a, b) = (&self.bodies[i], &self.bodies[j]);
                let d = b.position - a.position;
                // The common case first: apart (pocketed balls never take part).
                if d.length_squared() >= d2 * d2 || b.pocketed.is_some() {
                    continue;
                }
                self.pair_contact(i, j, end);
                // Push apart symmetrically along the centre line to exactly touching.
                let dist = d.length();
                let n = d.normalized().unwrap_or(Vec2::new(1.0, 0.0));
                let push = n * (0.5 * (d2 - dist));
                self.bodies[i].position -= push;
                self.bodies[j].position += push;
            }
        }
        // Cushions last, so no ball is left outside them by a push.
        for i in 0..self.bodies.len() {
            let b = self.bodies[i];
            if b.pocketed.is_some() {
                continue;
            }
            // Push back inside onto the nearest point of the allowed rectangle (both axes at
            // once, so a ball past a corner is judged where it meets the cushions, not at the
            // depth it reached), then decide pocket or rebound there for each cushion crossed.
            let inside = Vec2::new(
                b.position.x.clamp(-self.bounds.x, self.bounds.x),
                b.position.y.clamp(-self.bounds.y, self.bounds.y),
            );
            if inside == b.position {
                continue;
            }
            self.bodies[i].position = inside;
            for c in Cushion::ALL {
                if self.cushion_gap(&b, c) < 0.0 && self.bodies[i].pocketed.is_none() {
                    self.cushion_contact(i, c, end);
                }
            }
        }
    }

    /// The earliest contact within `horizon` seconds if every ball keeps its velocity.
    fn earliest_contact(&self, horizon: f64) -> Option<(f64, Hit)> {
        let mut best: Option<(f64, Hit)> = None;
        let mut consider = |tau: f64, hit: Hit| {
            if tau <= horizon && best.is_none_or(|(t, _)| tau < t) {
                best = Some((tau, hit));
            }
        };
        let four_r2 = 4.0 * self.radius * self.radius;
        for (i, a) in self.bodies.iter().enumerate() {
            if a.pocketed.is_some() {
                continue;
            }
            for c in Cushion::ALL {
                let closing = -a.velocity.dot(c.inward_normal());
                if closing > 0.0 {
                    consider(
                        (self.cushion_gap(a, c) / closing).max(0.0),
                        Hit::Cushion(i, c),
                    );
                }
            }
            for (j, b) in self.bodies.iter().enumerate().skip(i + 1) {
                if b.pocketed.is_some() {
                    continue;
                }
                let d = b.position - a.position;
                let w = b.velocity - a.velocity;
                let dw = d.dot(w);
                if dw >= 0.0 {
                    continue; // separating or parallel
                }
                let c = d.length_squared() - four_r2;
                if c <= 0.0 {
                    consider(0.0, Hit::Pair(i, j));
                    continue;
                }
                let ww = w.length_squared();
                let disc = dw * dw - ww * c;
                if disc < 0.0 {
                    continue;
                }
                // The smaller root of |d + w t|^2 = 4R^2 in the cancellation-free form.
                consider(c / (-dw + disc.sqrt()), Hit::Pair(i, j));
            }
        }
        best
    }

    fn step_swept(&mut self) {
        let start = self.now();
        let mut left = self.dt;
        for _ in 0..SWEPT_EVENT_CAP {
            let Some((tau, hit)) = self.earliest_contact(left) else {
                break;
            };
            for b in self.bodies.iter_mut().filter(|b| b.pocketed.is_none()) {
                b.position += b.velocity * tau;
            }
            left -= tau;
            let time = start + (self.dt - left);
            match hit {
                Hit::Pair(i, j) => {
                    self.pair_contact(i, j, time);
                }
                Hit::Cushion(i, c) => {
                    // Land exactly on the line: rounding must not leave the ball outside.
                    let gap = self.cushion_gap(&self.bodies[i], c);
                    self.bodies[i].position -= c.inward_normal() * gap.min(0.0);
                    self.cushion_contact(i, c, time);
                }
            }
        }
        for b in self.bodies.iter_mut().filter(|b| b.pocketed.is_none()) {
            b.position += b.velocity * left;
        }
    }
}

/// A contact found by the swept test.
#[derive(Clone, Copy, Debug)]
enum Hit {
    Pair(usize, usize),
    Cushion(usize, Cushion),
}

impl Stepper for FixedStep {
    fn dt(&self) -> f64 {
        self.dt
    }

    fn step(&mut self) {
        self.hit.fill(false);
        self.apply_friction();
        match self.collisions {
            Collisions::Discrete => self.step_discrete(),
            Collisions::Swept => self.step_swept(),
        }
        self.steps += 1;
    }

    fn balls(&self, out: &mut Vec<Sample>) {
        out.clear();
        out.extend(self.bodies.iter().map(|b| Sample {
            position: b.position,
            velocity: b.velocity,
            pocketed: b.pocketed,
        }));
    }

    fn hit(&self) -> &[bool] {
        &self.hit
    }

    fn take_contacts(&mut self) -> Vec<Contact> {
        std::mem::take(&mut self.contacts)
    }

    fn contact_gaps(&self) -> (usize, f64) {
        (self.gap_contacts, self.max_contact_gap)
    }
}

/// Runs a fixed-step solver over `scene` until `end`, sampling every ball at the scene's
/// sample times. With `diagnose`, every step's output state is also checked for overlaps,
/// escapes and tunnelling (this costs an O(n^2) pass per step, so timed runs leave it off).
///
/// # Panics
///
/// If the solver's time step does not divide the scene's sample interval.
pub fn run<S: Stepper>(solver: &mut S, scene: &Scene, end: f64, diagnose: bool) -> Trace {
    let dt = solver.dt();
    let per_sample = (scene.sample_interval / dt).round();
    assert!(
        (per_sample * dt - scene.sample_interval).abs() < 1e-9 * scene.sample_interval,
        "time step {dt} s does not divide the sample interval"
    );
    let per_sample = per_sample as usize;
    let samples_wanted = crate::exact::sample_count(scene, end);
    let n = scene.balls.len();
    let mut trace = Trace::default();
    let mut current = Vec::with_capacity(n);
    solver.balls(&mut current);
    trace.samples.push(current.clone());
    let mut watch = OverlapWatch::new(n);
    let mut previous = current.clone();
    let mut tunnelled = 0;
    for _ in 0..samples_wanted {
        for _ in 0..per_sample {
            solver.step();
            if diagnose {
                solver.balls(&mut current);
                watch.observe(&current, scene.radius(), scene.bounds());
                tunnelled += count_tunnelled(&previous, &current, solver.hit(), scene.radius());
                std::mem::swap(&mut previous, &mut current);
            }
        }
        solver.balls(&mut current);
        trace.samples.push(current.clone());
        if diagnose {
            previous.clone_from(&current);
        }
    }
    trace.contacts = solver.take_contacts();
    if diagnose {
        trace.diagnostics = watch.diagnostics;
        trace.diagnostics.tunnelled = tunnelled;
        (
            trace.diagnostics.gap_contacts,
            trace.diagnostics.max_contact_gap,
        ) = solver.contact_gaps();
    }
    trace
}

/// Pairs that passed through each other during one step: apart (not overlapping) at both
/// ends of the step, but the straight relative path between the two states comes closer than
/// a diameter, and no contact touched either ball in the step. This is a collision the step
/// never saw.
pub fn count_tunnelled(before: &[Sample], after: &[Sample], hit: &[bool], radius: f64) -> usize {
    let limit = 2.0 * radius - OVERLAP_TOLERANCE;
    let mut count = 0;
    for i in 0..before.len() {
        if hit[i] || before[i].pocketed.is_some() || after[i].pocketed.is_some() {
            continue;
        }
        for j in i + 1..before.len() {
            if hit[j] || before[j].pocketed.is_some() || after[j].pocketed.is_some() {
                continue;
            }
            let d0 = before[j].position - before[i].position;
            let d1 = after[j].position - after[i].position;
            if d0.length() < limit || d1.length() < limit {
                continue;
            }
            // Closest approach of d0 + (d1 - d0) s for s in [0, 1].
            let w = d1 - d0;
            let ww = w.length_squared();
            if ww == 0.0 {
                continue;
            }
            let s = (-d0.dot(w) / ww).clamp(0.0, 1.0);
            if (d0 + w * s).length() < limit {
                count += 1;
            }
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene;

    fn at(x: f64, y: f64) -> Sample {
        Sample {
            position: Vec2::new(x, y),
            ..Sample::default()
        }
    }

    #[test]
    fn two_balls_swapping_sides_in_one_step_count_as_tunnelled() {
        let r = 0.028575;
        let before = [at(0.0, 0.0), at(0.1, 0.0)];
        let after = [at(0.1, 0.0), at(0.0, 0.0)];
        assert_eq!(count_tunnelled(&before, &after, &[false, false], r), 1);
        // The same motion with a contact resolved in the step is not a pass-through.
        assert_eq!(count_tunnelled(&before, &after, &[true, false], r), 0);
        // Passing each other at more than a diameter is not either.
        let after_wide = [at(0.1, 0.0), at(0.0, 0.06)];
        let before_wide = [at(0.0, 0.0), at(0.1, 0.06)];
        assert_eq!(
            count_tunnelled(&before_wide, &after_wide, &[false, false], r),
            0
        );
    }

    #[test]
    fn discrete_steps_let_a_break_speed_ball_pass_through_a_ball_the_swept_steps_hit() {
        // Head-on at 11 m/s, 1/30 s steps: 37 cm per step against a 5.7 cm diameter.
        let mut s = scene::billiard(1.0);
        s.balls = vec![
            billiards_physics::BallSetup::moving(0, Vec2::new(-0.3, 0.0), Vec2::new(11.0, 0.0)),
            billiards_physics::BallSetup::at(1, Vec2::new(-0.1, 0.0)),
        ];
        let discrete = run(
            &mut FixedStep::new(&s, 1.0 / 30.0, Collisions::Discrete),
            &s,
            0.1,
            true,
        );
        assert_eq!(discrete.diagnostics.tunnelled, 1);
        assert!(
            discrete
                .contacts
                .iter()
                .all(|c| c.key != ContactKey::pair(0, 1))
        );
        let swept = run(
            &mut FixedStep::new(&s, 1.0 / 30.0, Collisions::Swept),
            &s,
            0.1,
            true,
        );
        assert_eq!(swept.diagnostics.tunnelled, 0);
        assert_eq!(swept.contacts[0].key, ContactKey::pair(0, 1));
        // Swept and elastic: the object ball leaves with the full speed, the cue ball stops.
        let last = swept.samples.last().unwrap();
        assert_eq!(last[0].velocity, Vec2::ZERO);
        assert_eq!(last[1].velocity, Vec2::new(11.0, 0.0));
    }
}
