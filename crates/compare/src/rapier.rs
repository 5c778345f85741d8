//! Rapier (`rapier3d-f64`, no Bevy plugin) on the frictionless elastic scenes, where its rigid
//! body model and the paper's agree: smooth balls, restitution 1, no friction, no gravity in
//! the table plane.
//!
//! Configured as well as its documentation allows: continuous collision detection on for
//! every ball, CCD sub-steps, more solver iterations (Rapier's sub-steps) than the default,
//! restitution 1 combined with `Max` and friction 0 combined with `Min`, no sleeping, no
//! contact recycling (stale contacts trade accuracy for speed), rotations locked (they play no
//! part without friction) and motion locked to the table plane.

use crate::fixed_step::Stepper;
use crate::scene::Scene;
use crate::trace::{Contact, ContactKey, Sample};
use billiards_physics::Vec2;
use rapier3d_f64::prelude::*;

/// Solver iterations per step (Rapier's sub-steps; its default is 4).
pub const SOLVER_ITERATIONS: usize = 8;

/// Most CCD sub-steps per step (Rapier's default is 1).
pub const CCD_SUBSTEPS: usize = 4;

/// Half thickness of the cushion boxes, metres: thick enough that nothing jumps over them in
/// one step at these speeds even without CCD.
const WALL_HALF_THICKNESS: f64 = 0.5;

/// Velocity change (m/s) above which a ball counts as hit in a step. With no friction and no
/// gravity, only contacts change velocities.
const HIT_SPEED: f64 = 1e-6;

/// A Rapier world holding one scene.
pub struct RapierWorld {
    world: PhysicsWorld,
    balls: Vec<RigidBodyHandle>,
    radius: f64,
    bounds: Vec2,
    steps: u64,
    last_velocity: Vec<Vec2>,
    hit: Vec<bool>,
    contacts: Vec<Contact>,
}

impl RapierWorld {
    /// Builds the world for a frictionless `scene`, stepping by `dt`.
    ///
    /// # Panics
    ///
    /// If the scene has friction (Rapier's model would not match).
    pub fn new(scene: &Scene, dt: f64) -> Self {
        assert!(
            scene.frictionless,
            "Rapier runs only the frictionless scenes"
        );
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::new(0.0, 0.0, 0.0);
        let ip = &mut world.integration_parameters;
        ip.dt = dt;
        ip.num_solver_iterations = SOLVER_ITERATIONS;
        ip.max_ccd_substeps = CCD_SUBSTEPS;
        ip.contact_recycling = false;
        let r = scene.radius();
        let (length, width) = (scene.table.length, scene.table.width);
        // The cushions: four fixed boxes whose inner faces are the cushion noses.
        let rails = world.insert_body(RigidBodyBuilder::fixed());
        let h = WALL_HALF_THICKNESS;
        let walls = [
            (
                Vector::new(-(0.5 * length + h), 0.0, 0.0),
                h,
                0.5 * width + 2.0 * h,
            ),
            (
                Vector::new(0.5 * length + h, 0.0, 0.0),
                h,
                0.5 * width + 2.0 * h,
            ),
            (
                Vector::new(0.0, 0.5 * width + h, 0.0),
                0.5 * length + 2.0 * h,
                h,
            ),
            (
                Vector::new(0.0, -(0.5 * width + h), 0.0),
                0.5 * length + 2.0 * h,
                h,
            ),
        ];
        for (centre, hx, hy) in walls {
            world.insert_collider(
                ColliderBuilder::cuboid(hx, hy, 4.0 * r)
                    .translation(centre)
                    .restitution(1.0)
                    .restitution_combine_rule(CoefficientCombineRule::Max)
                    .friction(0.0)
                    .friction_combine_rule(CoefficientCombineRule::Min),
                Some(rails),
            );
        }
        let balls = scene
            .balls
            .iter()
            .map(|b| {
                let body = RigidBodyBuilder::dynamic()
                    .translation(Vector::new(b.position.x, b.position.y, 0.0))
                    .linvel(Vector::new(b.velocity.x, b.velocity.y, 0.0))
                    .ccd_enabled(true)
                    .can_sleep(false)
                    .lock_rotations()
                    .enabled_translations(true, true, false);
                let collider = ColliderBuilder::ball(r)
                    .mass(scene.mass())
                    .restitution(1.0)
                    .restitution_combine_rule(CoefficientCombineRule::Max)
                    .friction(0.0)
                    .friction_combine_rule(CoefficientCombineRule::Min);
                world.insert(body, collider).0
            })
            .collect();
        let n = scene.balls.len();
        Self {
            world,
            balls,
            radius: r,
            bounds: scene.bounds(),
            steps: 0,
            last_velocity: scene.balls.iter().map(|b| b.velocity).collect(),
            hit: vec![false; n],
            contacts: Vec::new(),
        }
    }

    fn state(&self, i: usize) -> (Vec2, Vec2) {
        let b = &self.world.bodies[self.balls[i]];
        let (p, v) = (b.translation(), b.linvel());
        (Vec2::new(p.x, p.y), Vec2::new(v.x, v.y))
    }

    /// Rapier reports impulses, not collision events of the kind the exact solver has, so
    /// contacts are inferred: a ball whose velocity changed in this step was hit; two hit
    /// balls within reach of each other collided; a hit ball within reach of a cushion hit it.
    fn infer_contacts(&mut self) {
        let n = self.balls.len();
        let dt = self.world.integration_parameters.dt;
        let slack = self.world.integration_parameters.prediction_distance();
        let time = self.steps as f64 * dt;
        let states: Vec<(Vec2, Vec2)> = (0..n).map(|i| self.state(i)).collect();
        for ((hit, last), (_, v)) in self
            .hit
            .iter_mut()
            .zip(&mut self.last_velocity)
            .zip(&states)
        {
            *hit = (*v - *last).length() > HIT_SPEED;
            *last = *v;
        }
        for i in (0..n).filter(|&i| self.hit[i]) {
            let (p, v) = states[i];
            let reach = v.length() * dt + slack;
            let near_cushion =
                self.bounds.x - p.x.abs() < reach || self.bounds.y - p.y.abs() < reach;
            if near_cushion {
                self.contacts.push(Contact {
                    time,
                    key: ContactKey::Cushion(i),
                });
            }
            for j in (i + 1..n).filter(|&j| self.hit[j]) {
                let (q, w) = states[j];
                let pair_reach = 2.0 * self.radius + (v.length() + w.length()) * dt + slack;
                if (q - p).length() < pair_reach {
                    self.contacts.push(Contact {
                        time,
                        key: ContactKey::pair(i, j),
                    });
                }
            }
        }
    }
}

impl Stepper for RapierWorld {
    fn dt(&self) -> f64 {
        self.world.integration_parameters.dt
    }

    fn step(&mut self) {
        self.world.step();
        self.steps += 1;
        self.infer_contacts();
    }

    fn balls(&self, out: &mut Vec<Sample>) {
        out.clear();
        out.extend((0..self.balls.len()).map(|i| {
            let (position, velocity) = self.state(i);
            Sample {
                position,
                velocity,
                pocketed: None,
            }
        }));
    }

    fn hit(&self) -> &[bool] {
        &self.hit
    }

    fn take_contacts(&mut self) -> Vec<Contact> {
        std::mem::take(&mut self.contacts)
    }

    fn contact_gaps(&self) -> (usize, f64) {
        // Soft contacts act over a distance by design (speculative contacts, slop).
        (0, f64::NAN)
    }
}
