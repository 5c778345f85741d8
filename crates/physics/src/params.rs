//! Physical parameters: the ball, the model and its constants, prediction and randomization.

use serde::{Deserialize, Serialize};

/// Standard gravity, m/s^2.
pub const G: f64 = 9.80665;

/// WPBSA Official Rules (November 2019) 1.2: snooker ball diameter 52.5 mm.
pub const SNOOKER_BALL_DIAMETER: f64 = 0.0525;
/// Snooker ball mass, kg. 1.2 fixes no mass, only that balls of a set weigh the same within 0.5 g
/// (3 g a set); 142 g is the mass of a tournament set of 52.5 mm phenolic balls.
pub const SNOOKER_BALL_MASS: f64 = 0.142;

/// Ball size and mass (WPA: 2.25 in diameter; the paper writes "radius").
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BallSpec {
    /// Radius, metres (half of 2.25 in: the paper's slip 1 corrected).
    pub radius: f64,
    /// Mass, kg (the paper's 5.5 oz).
    pub mass: f64,
}

impl BallSpec {
    /// The snooker ball: 52.5 mm (WPBSA Official Rules, November 2019, 1.2), 142 g
    /// ([`SNOOKER_BALL_MASS`]: 1.2 fixes no mass).
    pub fn snooker() -> Self {
        Self {
            radius: 0.5 * SNOOKER_BALL_DIAMETER,
            mass: SNOOKER_BALL_MASS,
        }
    }
}

impl Default for BallSpec {
    fn default() -> Self {
        Self {
            radius: 0.5 * 2.25 * crate::table::INCH,
            mass: 5.5 * 0.028_349_523_125,
        }
    }
}

/// The paper's model: no spin; a ball slides (mu_s g deceleration) above a speed threshold and
/// rolls (mu_r g) below it; reflection at cushions and equal-mass normal exchange between balls,
/// each with a restitution factor (1 reproduces the paper).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PaperModel {
    /// Sliding friction coefficient ball–cloth (paper 3.4 "kinetic"), dimensionless.
    pub mu_slide: f64,
    /// Rolling resistance coefficient ball–cloth (paper 3.4 "static"), dimensionless.
    pub mu_roll: f64,
    /// Speed below which a ball rolls instead of sliding, m/s.
    pub slide_roll_speed: f64,
    /// Ball–ball restitution (1: the paper's exact exchange of normal components).
    pub e_ball: f64,
    /// Ball–cushion restitution (1: the paper's mirror reflection).
    pub e_cushion: f64,
}

impl Default for PaperModel {
    fn default() -> Self {
        // Friction from the reference's typical values; the paper gives no threshold, so the
        // slide/roll speed is a chosen 0.5 m/s (a medium shot slides for its first part).
        Self {
            mu_slide: 0.2,
            mu_roll: 0.01,
            slide_roll_speed: 0.5,
            e_ball: 1.0,
            e_cushion: 1.0,
        }
    }
}

/// How a ball rebounds from a cushion in the spin model.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum CushionModel {
    /// Mirror reflection of the velocity with restitution `e`; spin untouched.
    Reflect {
        /// Restitution of the normal velocity.
        e: f64,
    },
    /// Han (2005), "Dynamics in carom and three cushion billiards": an impulse at the cushion
    /// nose (above the ball's centre) with restitution and Coulomb friction, so running and
    /// reverse english change the rebound angle and the spin.
    Han2005 {
        /// Restitution along the contact normal.
        e: f64,
        /// Ball–cushion friction coefficient.
        mu: f64,
    },
    /// Mathavan, Jackson & Parkin (2010), Proc. IMechE C 224: the impact's equations of
    /// motion integrated over the impulse, with friction at the nose and at the cloth (the
    /// cloth's is `mu_slide`) and an energetic restitution. Their fit: `e = 0.98`,
    /// `mu = 0.14`, for normal speeds below about 2.5 m/s.
    Mathavan2010 {
        /// Energetic restitution at the nose.
        e: f64,
        /// Ball–cushion sliding friction.
        mu: f64,
    },
}

impl CushionModel {
    /// Mathavan et al.'s fitted constants (2010, abstract and section 5).
    pub const MATHAVAN_2010: Self = CushionModel::Mathavan2010 { e: 0.98, mu: 0.14 };
}

impl Default for CushionModel {
    fn default() -> Self {
        CushionModel::Han2005 { e: 0.85, mu: 0.2 }
    }
}

/// How the ball–ball friction coefficient is found at each collision.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum BallFriction {
    /// A constant coefficient, [`SpinModel::mu_ball`].
    #[default]
    Constant,
    /// `mu = a + b exp(-c v)`, with `v` the sliding speed of the contact points at the start
    /// of the collision (m/s): Alciatore's fit to Marlow's measurements (TP A-14 and TP A-28,
    /// "Throw plots for all types of shots", p. 1). Slow slip grips (0.118 at rest), fast slip
    /// slides (0.010 far above 3 m/s), so slow cuts throw more. `mu_ball` is then unused.
    SpeedDependent {
        /// Coefficient far above the sliding speed 1/c.
        a: f64,
        /// Extra coefficient at zero sliding speed.
        b: f64,
        /// Decay rate, s/m.
        c: f64,
    },
}

impl BallFriction {
    /// Alciatore's fitted constants (TP A-28 p. 1): a = 9.951e-3, b = 0.108, c = 1.088 s/m.
    pub const ALCIATORE: Self = BallFriction::SpeedDependent {
        a: 9.951e-3,
        b: 0.108,
        c: 1.088,
    };

    /// The coefficient for a contact sliding at `slip_speed` (m/s), with `constant` the
    /// model's `mu_ball`.
    #[inline]
    pub fn mu(&self, constant: f64, slip_speed: f64) -> f64 {
        match *self {
            BallFriction::Constant => constant,
            BallFriction::SpeedDependent { a, b, c } => a + b * (-c * slip_speed).exp(),
        }
    }
}

/// The realistic model with spin (Leckie & Greenspan's event-based model, as in pooltool and
/// FastFiz): sliding and rolling friction acting at the contact point, spin about the vertical
/// decaying on its own, frictional ball–ball collisions (throw) and a spin-aware cushion.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SpinModel {
    /// Sliding friction ball–cloth.
    pub mu_slide: f64,
    /// Rolling resistance ball–cloth.
    pub mu_roll: f64,
    /// Friction of spin about the vertical: it decays at `5 mu_spin g / (2R)`.
    pub mu_spin: f64,
    /// Ball–ball restitution.
    pub e_ball: f64,
    /// Ball–ball friction (cut- and spin-induced throw), when `ball_friction` is constant.
    pub mu_ball: f64,
    /// Constant or speed-dependent ball–ball friction (absent from old files: constant).
    pub ball_friction: BallFriction,
    /// The cushion model.
    pub cushion: CushionModel,
    /// Height of the cushion nose above the cloth as a fraction of the ball's diameter.
    pub cushion_height: f64,
    /// Mass of the cue stick, kg (sets how much of the cue's speed a tip offset costs).
    pub cue_mass: f64,
    /// Largest tip offset from the ball's centre, as a fraction of its radius, before a miscue.
    pub miscue_limit: f64,
    /// Effective end mass of the shaft, kg: side english then squirts the ball away from the
    /// english (Alciatore TP A-31; a low-deflection shaft has a smaller one). `None` (the
    /// default, and old files): no squirt, the ball leaves along the cue.
    pub end_mass: Option<f64>,
    /// Compliant contact of balls in clusters: a ball–ball impact reaching a ball with
    /// neighbours closer than the distance one contact closes is resolved over the whole
    /// cluster with Hertz forces ([`crate::resolve::hertz`]). `None` (and a file that omits
    /// it: recordings made before it existed) resolves every contact pair by pair.
    #[serde(default)]
    pub cluster: Option<HertzContact>,
}

/// The elastic constants of the balls, for Hertz contact (Landau & Lifshitz, *Theory of
/// Elasticity*, section 9): two spheres of radius `R` pressed `d` into each other push with
/// `F = (4/3) E* sqrt(R/2) d^1.5`, with `1/E* = 2 (1 - nu^2) / E`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct HertzContact {
    /// Young's modulus of the ball material, Pa.
    pub young: f64,
    /// Poisson's ratio of the ball material.
    pub poisson: f64,
}

impl Default for HertzContact {
    fn default() -> Self {
        // Phenolic resin billiard balls: E = 5.84 GPa, nu = 0.34 (S. Crown, "Modeling the
        // effects of velocity, spin, frictional coefficient, and impact angle on deflection
        // angle in near-elastic collisions of phenolic resin spheres", as quoted in
        // dbkcues.ru, "Collision of billiard balls"). They give a contact of about 0.24 ms at
        // 10 m/s, as measured for pool balls (a few hundred microseconds).
        Self {
            young: 5.84e9,
            poisson: 0.34,
        }
    }
}

impl Default for SpinModel {
    fn default() -> Self {
        // The reference's typical values (pooltool, FastFiz, Alciatore); cushion nose at
        // 63.5 % of the diameter (WPA).
        Self {
            mu_slide: 0.2,
            mu_roll: 0.01,
            mu_spin: 0.044,
            e_ball: 0.95,
            mu_ball: 0.05,
            ball_friction: BallFriction::Constant,
            cushion: CushionModel::default(),
            cushion_height: 0.635,
            cue_mass: 0.54,
            miscue_limit: 0.5,
            end_mass: None,
            cluster: Some(HertzContact::default()),
        }
    }
}

/// Which physics model resolves the motion and the collisions.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Model {
    /// Anderson's model (sections 3.1–3.4), slips corrected.
    Paper(PaperModel),
    /// Spin, tip offsets, throw and a spin-aware cushion.
    Spin(SpinModel),
}

impl Model {
    /// Sliding and rolling friction coefficients.
    pub fn friction(&self) -> (f64, f64) {
        match self {
            Model::Paper(m) => (m.mu_slide, m.mu_roll),
            Model::Spin(m) => (m.mu_slide, m.mu_roll),
        }
    }
}

impl Default for Model {
    fn default() -> Self {
        Model::Paper(PaperModel::default())
    }
}

/// How collision times are predicted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Prediction {
    /// Exact roots for the motion the balls really follow (quadratic with friction).
    #[default]
    Exact,
    /// The paper's own prediction (sections 3.1–3.2): straight lines at constant velocity,
    /// although the balls decelerate. Kept only to measure what exact prediction buys; balls
    /// may stop short of contacts or overlap in this mode.
    PaperLinear,
}

/// Random perturbation of collision normals (paper 5, after Barzel et al.).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Randomization {
    /// Standard deviation of the normal's rotation, radians (Gaussian).
    pub spread: f64,
    /// Seed of the portable generator (ChaCha8), so a run is reproducible.
    pub seed: u64,
}

/// Everything physical about a simulation except the table and the balls' states.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Params {
    /// Ball size and mass.
    pub ball: BallSpec,
    /// Gravity, m/s^2.
    pub gravity: f64,
    /// The physics model and its constants.
    pub model: Model,
    /// Exact or the paper's linear prediction.
    pub prediction: Prediction,
    /// Perturbation of collision normals; `None` is the exact deterministic result.
    pub randomization: Option<Randomization>,
    /// Most events one `advance` or `run_to_rest` call may process before it reports
    /// [`crate::SimError::EventCap`] instead of spinning.
    pub max_events: usize,
}

impl Params {
    /// The default physics with the snooker ball ([`BallSpec::snooker`]).
    pub fn snooker() -> Self {
        Self {
            ball: BallSpec::snooker(),
            ..Self::default()
        }
    }
}

impl Default for Params {
    fn default() -> Self {
        Self {
            ball: BallSpec::default(),
            gravity: G,
            model: Model::default(),
            prediction: Prediction::default(),
            randomization: None,
            max_events: 1_000_000,
        }
    }
}

/// A parameter outside its physical range.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("parameter {name} = {value} is invalid: {expected}")]
pub struct ParamError {
    /// Parameter name.
    pub name: &'static str,
    /// The value given.
    pub value: f64,
    /// What is allowed.
    pub expected: &'static str,
}

fn check(
    name: &'static str,
    value: f64,
    ok: bool,
    expected: &'static str,
) -> Result<(), ParamError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(ParamError {
            name,
            value,
            expected,
        })
    }
}

impl Params {
    /// Checks that every parameter is finite and in its physical range.
    pub fn validate(&self) -> Result<(), ParamError> {
        check(
            "ball.radius",
            self.ball.radius,
            self.ball.radius > 0.0,
            "positive, metres",
        )?;
        check(
            "ball.mass",
            self.ball.mass,
            self.ball.mass > 0.0,
            "positive, kg",
        )?;
        check(
            "gravity",
            self.gravity,
            self.gravity >= 0.0,
            "non-negative, m/s^2",
        )?;
        match self.model {
            Model::Paper(m) => {
                check("mu_slide", m.mu_slide, m.mu_slide >= 0.0, "non-negative")?;
                check("mu_roll", m.mu_roll, m.mu_roll >= 0.0, "non-negative")?;
                check(
                    "slide_roll_speed",
                    m.slide_roll_speed,
                    m.slide_roll_speed >= 0.0,
                    "non-negative, m/s",
                )?;
                check(
                    "e_ball",
                    m.e_ball,
                    (0.0..=1.0).contains(&m.e_ball),
                    "in [0, 1]",
                )?;
                check(
                    "e_cushion",
                    m.e_cushion,
                    (0.0..=1.0).contains(&m.e_cushion),
                    "in [0, 1]",
                )?;
            }
            Model::Spin(m) => m.validate()?,
        }
        if let Some(r) = self.randomization {
            check(
                "randomization.spread",
                r.spread,
                (0.0..=0.5).contains(&r.spread),
                "in [0, 0.5] rad",
            )?;
        }
        if self.max_events == 0 {
            return Err(ParamError {
                name: "max_events",
                value: 0.0,
                expected: "at least 1",
            });
        }
        Ok(())
    }
}

impl SpinModel {
    fn validate(&self) -> Result<(), ParamError> {
        let unit = |v: f64| (0.0..=1.0).contains(&v);
        check(
            "mu_slide",
            self.mu_slide,
            self.mu_slide >= 0.0,
            "non-negative",
        )?;
        check("mu_roll", self.mu_roll, self.mu_roll >= 0.0, "non-negative")?;
        check("mu_spin", self.mu_spin, self.mu_spin >= 0.0, "non-negative")?;
        check("e_ball", self.e_ball, unit(self.e_ball), "in [0, 1]")?;
        check("mu_ball", self.mu_ball, self.mu_ball >= 0.0, "non-negative")?;
        if let BallFriction::SpeedDependent { a, b, c } = self.ball_friction {
            check("ball_friction.a", a, a >= 0.0, "non-negative")?;
            check("ball_friction.b", b, b >= 0.0, "non-negative")?;
            check("ball_friction.c", c, c >= 0.0, "non-negative, s/m")?;
        }
        let h = self.cushion_height;
        check(
            "cushion_height",
            h,
            (0.5..1.0).contains(&h),
            "in [0.5, 1) of the diameter",
        )?;
        check(
            "cue_mass",
            self.cue_mass,
            self.cue_mass > 0.0,
            "positive, kg",
        )?;
        if let Some(m) = self.end_mass {
            check("end_mass", m, m > 0.0, "positive, kg")?;
        }
        let l = self.miscue_limit;
        check(
            "miscue_limit",
            l,
            (0.0..1.0).contains(&l),
            "in [0, 1) of the radius",
        )?;
        if let Some(h) = self.cluster {
            check("cluster.young", h.young, h.young > 0.0, "positive, Pa")?;
            check(
                "cluster.poisson",
                h.poisson,
                (0.0..0.5).contains(&h.poisson),
                "in [0, 0.5)",
            )?;
        }
        match self.cushion {
            CushionModel::Reflect { e } => check("cushion.e", e, unit(e), "in [0, 1]"),
            CushionModel::Han2005 { e, mu } | CushionModel::Mathavan2010 { e, mu } => {
                check("cushion.e", e, unit(e), "in [0, 1]")?;
                check("cushion.mu", mu, mu >= 0.0, "non-negative")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alciatore_ball_friction_falls_with_slip_speed_as_tp_a14_fits_it() {
        let f = BallFriction::ALCIATORE;
        assert!((f.mu(0.0, 0.0) - 0.117_951).abs() < 1e-6);
        assert!((f.mu(0.0, 0.9) - 0.0505).abs() < 5e-4, "{}", f.mu(0.0, 0.9));
        assert!((f.mu(0.0, 3.0) - 0.0141).abs() < 5e-4, "{}", f.mu(0.0, 3.0));
        assert!(
            (f.mu(0.0, 10.0) - 0.00995).abs() < 1e-4,
            "{}",
            f.mu(0.0, 10.0)
        );
    }

    #[test]
    fn a_spin_model_without_ball_friction_keeps_the_constant_mu_ball() {
        // Files written before the field existed read as the constant law.
        let m: SpinModel = serde_json::from_str(r#"{"mu_ball": 0.06}"#).unwrap();
        assert_eq!((m.mu_ball, m.ball_friction), (0.06, BallFriction::Constant));
        assert_eq!(SpinModel::default().ball_friction, BallFriction::Constant);
        let bad = SpinModel {
            ball_friction: BallFriction::SpeedDependent {
                a: -1.0,
                b: 0.108,
                c: 1.088,
            },
            ..SpinModel::default()
        };
        assert!(bad.validate().is_err());
    }
}
