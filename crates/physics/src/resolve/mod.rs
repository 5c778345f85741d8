//! Resolution: what a contact does to the velocities. One model per collision kind, named
//! after its source; the model in force is read in one place ([`Laws::of`]), and the loop
//! resolves every contact through [`fixed_body`] or [`ball_pair`].

pub mod ball_air;
mod ball_ball;
mod ball_cushion;
pub mod cue;
mod friction;
pub mod hertz;
pub mod mathavan_2010;
mod resting;
pub mod slate;
mod throw;

pub use ball_ball::{equal_mass_restitution, frictional_spheres, resting_contact, unpress};
pub use ball_cushion::{SETTLE_SPEED, han_2005, reflect, resting_reflect, settle};
pub use friction::PairFriction;
pub use mathavan_2010::{Mathavan2010, mathavan_2010};
pub use resting::{
    FixedBody, InstantContacts, is_resting, keep_rolling, resting_on_fixed_body, resting_pair,
};
pub use throw::{contact_slip_speed, speed_dependent_spheres};

use crate::ball::BallState;
use crate::math::{Vec2, Vec3};
use crate::params::{BallSpec, CushionModel, Model, Randomization, SpinModel};
use cue::{Miscue, TipOffset};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The response laws of a model, one per contact kind (pooltool's one strategy slot per
/// event kind).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Laws {
    /// The cue strike.
    pub cue: CueLaw,
    /// A ball meeting a cushion or a jaw.
    pub cushion: CushionLaw,
    /// Two balls meeting.
    pub ball: BallLaw,
    /// Does a ball meeting a fixed body slower than [`SETTLE_SPEED`] settle against it
    /// ([`settle`])? Only with spin, whose cloth friction would bring a rebound straight back.
    pub settles: bool,
}

impl Laws {
    /// The laws of `model`: the only place that dispatches on the model.
    pub fn of(model: &Model) -> Self {
        match *model {
            Model::Paper(m) => Self {
                cue: CueLaw::Centre,
                cushion: CushionLaw::Reflect { e: m.e_cushion },
                ball: BallLaw::EqualMassRestitution { e: m.e_ball },
                settles: false,
            },
            Model::Spin(m) => Self {
                cue: CueLaw::Tip(m),
                cushion: match m.cushion {
                    CushionModel::Reflect { e } => CushionLaw::Reflect { e },
                    CushionModel::Han2005 { e, mu } => CushionLaw::Han2005 {
                        e,
                        mu,
                        height: m.cushion_height,
                    },
                    CushionModel::Mathavan2010 { e, mu } => {
                        CushionLaw::Mathavan2010(Mathavan2010 {
                            e,
                            mu_cushion: mu,
                            mu_table: m.mu_slide,
                            // Set from the ball's radius in `respond`.
                            height: m.cushion_height,
                        })
                    }
                },
                ball: BallLaw::FrictionalSpheres {
                    e: m.e_ball,
                    mu: PairFriction::of(&m),
                },
                settles: true,
            },
        }
    }
}

/// How the cue sets a ball moving.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CueLaw {
    /// The paper's cue: a velocity along the shot, no spin; the tip offset and the cue's
    /// elevation are ignored.
    Centre,
    /// A cue striking at the tip offset, level or elevated ([`cue::strike`]).
    Tip(SpinModel),
}

impl CueLaw {
    /// Velocity, upward speed and spin of a ball of `ball` struck by `cue` at `speed` on a
    /// table with `gravity` (the paper's cue never lifts a ball).
    pub fn strike(
        self,
        ball: &BallSpec,
        gravity: f64,
        cue: cue::Cue,
        speed: f64,
        tip: TipOffset,
    ) -> Result<slate::Bounce, Miscue> {
        match self {
            CueLaw::Centre => Ok(slate::Bounce {
                velocity: cue.dir * speed,
                vertical: 0.0,
                spin: Vec3::ZERO,
            }),
            CueLaw::Tip(m) => cue::strike(&m, ball.mass, ball.radius, gravity, cue, speed, tip),
        }
    }
}

/// How a ball rebounds from a cushion or a jaw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CushionLaw {
    /// [`reflect`] with restitution `e`; spin untouched.
    Reflect {
        /// Restitution of the normal velocity.
        e: f64,
    },
    /// [`han_2005`].
    Han2005 {
        /// Restitution along the contact normal.
        e: f64,
        /// Ball–cushion friction.
        mu: f64,
        /// Height of the cushion nose as a fraction of the ball's diameter.
        height: f64,
    },
    /// [`mathavan_2010()`]; its `height` is the nose height as a fraction of the diameter.
    Mathavan2010(Mathavan2010),
}

impl CushionLaw {
    /// Velocity and spin after meeting a fixed body of unit inward normal `n`; `None` if the
    /// ball is not moving into it.
    #[inline]
    pub fn respond(self, v: Vec2, w: Vec3, n: Vec2, radius: f64) -> Option<(Vec2, Vec3)> {
        match self {
            CushionLaw::Reflect { e } => reflect(v, n, e).map(|v| (v, w)),
            CushionLaw::Han2005 { e, mu, height } => {
                han_2005(v, w, n, e, mu, radius, 2.0 * radius * height)
            }
            CushionLaw::Mathavan2010(m) => {
                let m = Mathavan2010 {
                    height: 2.0 * radius * m.height,
                    ..m
                };
                mathavan_2010(v, w, n, &m, radius)
            }
        }
    }
}

/// How two balls collide.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BallLaw {
    /// [`equal_mass_restitution`]: smooth balls, spins untouched (the paper).
    EqualMassRestitution {
        /// Restitution.
        e: f64,
    },
    /// [`frictional_spheres`]: throw from friction between the balls.
    FrictionalSpheres {
        /// Restitution.
        e: f64,
        /// Ball–ball friction.
        mu: PairFriction,
    },
}

impl BallLaw {
    /// States after balls `a` and `b` meet along unit normal `n` (from `a` to `b`); `None` if
    /// they are not approaching along it.
    #[inline]
    pub fn respond(
        self,
        a: &BallState,
        b: &BallState,
        n: Vec2,
        radius: f64,
    ) -> Option<(BallState, BallState)> {
        match self {
            BallLaw::EqualMassRestitution { e } => {
                equal_mass_restitution(a.velocity, b.velocity, n, e).map(|(va, vb)| {
                    (
                        BallState { velocity: va, ..*a },
                        BallState { velocity: vb, ..*b },
                    )
                })
            }
            BallLaw::FrictionalSpheres { e, mu } => frictional_spheres(a, b, n, e, mu, radius),
        }
    }
}

/// A Gaussian rotation of collision normals (paper 5, after Barzel et al.), from a seeded
/// portable generator so that a run is reproducible.
#[derive(Clone, Debug)]
pub struct NormalPerturbation {
    /// The spread (radians) and the generator; `None` without randomization.
    source: Option<(f64, ChaCha8Rng)>,
}

impl NormalPerturbation {
    /// The perturbation of `randomization`, its generator at the start of its seed.
    pub fn new(randomization: Option<Randomization>) -> Self {
        Self {
            source: randomization.map(|r| (r.spread, ChaCha8Rng::seed_from_u64(r.seed))),
        }
    }

    /// The next rotation angle (radians), if randomization is on.
    pub fn sample(&mut self) -> Option<f64> {
        let (spread, rng) = self.source.as_mut()?;
        // Box–Muller from two uniforms in (0, 1].
        let u1: f64 = 1.0 - rng.random::<f64>();
        let u2: f64 = rng.random::<f64>();
        Some(*spread * (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos())
    }
}

/// A ball touching a fixed body (cushion or jaw).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedContact {
    /// Unit normal of the body, towards the ball.
    pub normal: Vec2,
    /// How far the ball is into the body (m; negative while apart).
    pub depth: f64,
    /// The same contact was already resolved at this instant ([`InstantContacts`]).
    pub repeat: bool,
}

/// Velocity and spin of a ball in state `s`, with acceleration `acceleration`, after
/// `contact`: a slow spinning ball settles (soak seeds 10288 and 260383: rebounds that cloth
/// friction on the spin sent straight back, or a ball wedged between a jaw and a ball), a
/// resting contact hops ([`is_resting`]), any other contact follows the cushion law, its
/// normal perturbed unless that would send the ball into the body.
pub fn fixed_body(
    laws: &Laws,
    s: &BallState,
    acceleration: Vec2,
    contact: FixedContact,
    radius: f64,
    perturbation: &mut NormalPerturbation,
) -> (Vec2, Vec3) {
    let n = contact.normal;
    let pressing = -acceleration.dot(n);
    let approach = -s.velocity.dot(n);
    if laws.settles && approach.abs() < SETTLE_SPEED {
        return settle(s.velocity, s.angular_velocity, n);
    }
    if is_resting(contact.depth, approach, pressing) {
        return resting_on_fixed_body(s, n, approach, pressing, contact.repeat, radius);
    }
    let (v, w) = (s.velocity, s.angular_velocity);
    let respond = |n: Vec2| laws.cushion.respond(v, w, n, radius);
    let perturbed = perturbation.sample().map(|a| n.rotated(a));
    perturbed
        .and_then(respond)
        .filter(|(v, _)| v.dot(n) >= 0.0)
        .or_else(|| respond(n))
        .unwrap_or((v, w))
}

/// States after balls `a` and `b` (each a state and its acceleration) touch: a resting
/// contact hops ([`is_resting`], pressed by their relative acceleration less the centripetal
/// term of their sliding past each other), any other contact follows the ball law, its
/// normal perturbed unless that would leave them approaching along the true normal.
pub fn ball_pair(
    laws: &Laws,
    (sa, acc_a): (BallState, Vec2),
    (sb, acc_b): (BallState, Vec2),
    ball: &BallSpec,
    perturbation: &mut NormalPerturbation,
) -> (BallState, BallState) {
    let d = sb.position - sa.position;
    let n = d.normalized().unwrap_or(Vec2::new(1.0, 0.0));
    let depth = 2.0 * ball.radius - d.length();
    let dv = sb.velocity - sa.velocity;
    let da = acc_b - acc_a;
    // Relative normal acceleration pushing the pair together, less the centripetal term of
    // their sliding past each other (which pulls them apart).
    let pressing = -da.dot(n) - dv.perp_dot(n).powi(2) / d.length().max(f64::MIN_POSITIVE);
    if is_resting(depth, -dv.dot(n), pressing) {
        return resting_pair(sa, sb, n, pressing, ball);
    }
    let respond = |n: Vec2| laws.ball.respond(&sa, &sb, n, ball.radius);
    let separating = |(x, y): &(BallState, BallState)| (x.velocity - y.velocity).dot(n) <= 0.0;
    let perturbed = perturbation.sample().map(|ang| n.rotated(ang));
    perturbed
        .and_then(respond)
        .filter(separating)
        .or_else(|| respond(n))
        .unwrap_or((sa, sb))
}
