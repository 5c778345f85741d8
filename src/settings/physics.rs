//! The physical parameters the player can edit, and the model choices.

use bevy::prelude::*;
use billiards_physics::{Prediction, SpinModel};
use serde::{Deserialize, Serialize};

use super::range::{ClampNote, ParamRange};

/// The cushion model of the spin model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CushionChoice {
    /// Han (2005): impulse at the nose height with friction; english changes the rebound.
    Han2005,
    /// Plain reflection with restitution (no spin effect).
    Reflect,
    /// Mathavan, Jackson and Parkin (2010): the impact integrated with slip at the nose and
    /// the cloth; fits their high-speed camera data best below 2.5 m/s (docs/realism.md), so
    /// the game's default.
    #[default]
    Mathavan2010,
}

impl CushionChoice {
    /// Every choice, in the panel's order.
    pub const ALL: [Self; 3] = [Self::Han2005, Self::Reflect, Self::Mathavan2010];

    /// The name shown to the player.
    pub fn label(self) -> &'static str {
        match self {
            Self::Han2005 => "Han 2005 (spin-aware)",
            Self::Reflect => "reflection",
            Self::Mathavan2010 => "Mathavan 2010 (integrated)",
        }
    }

    /// The restitution and nose friction its authors fitted, loaded into the panel's shared
    /// sliders when the model is chosen: Mathavan et al. 2010 (e 0.98, mu 0.14, the game's
    /// defaults), Han 2005 as the game had them before (0.85, 0.2). `None`: keep the sliders.
    pub fn fitted(self) -> Option<(f64, f64)> {
        match self {
            Self::Han2005 => Some((0.85, 0.2)),
            Self::Mathavan2010 => Some((0.98, 0.14)),
            Self::Reflect => None,
        }
    }
}

/// How ball–ball friction (throw) is found at each contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BallFrictionChoice {
    /// The ball-ball friction slider's constant.
    #[default]
    Constant,
    /// Falls with the sliding speed at the contact: Alciatore's fit to Marlow's measurements
    /// (TP A-14), `mu = 0.00995 + 0.108 exp(-1.088 v)`.
    SpeedDependent,
}

impl BallFrictionChoice {
    /// Every choice, in the panel's order.
    pub const ALL: [Self; 2] = [Self::Constant, Self::SpeedDependent];

    /// The name shown to the player.
    pub fn label(self) -> &'static str {
        match self {
            Self::Constant => "constant",
            Self::SpeedDependent => "speed-dependent (Alciatore)",
        }
    }
}

/// The cue's shaft: how far side english squirts the cue ball off the cue line (Alciatore
/// TP A-31: the lighter the shaft's end, the less squirt).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShaftChoice {
    /// No squirt: the ball leaves along the cue (the game's behaviour before squirt).
    #[default]
    NoSquirt,
    /// A standard maple shaft, effective end mass 8 g.
    Standard,
    /// A low-deflection shaft, effective end mass 4 g.
    LowDeflection,
}

impl ShaftChoice {
    /// Every choice, in the panel's order.
    pub const ALL: [Self; 3] = [Self::NoSquirt, Self::Standard, Self::LowDeflection];

    /// The name shown to the player.
    pub fn label(self) -> &'static str {
        match self {
            Self::NoSquirt => "no squirt",
            Self::Standard => "standard shaft (8 g end)",
            Self::LowDeflection => "low-deflection shaft (4 g end)",
        }
    }

    /// The shaft's effective end mass, kg (illustrative values, docs/realism.md).
    pub fn end_mass(self) -> Option<f64> {
        match self {
            Self::NoSquirt => None,
            Self::Standard => Some(0.008),
            Self::LowDeflection => Some(0.004),
        }
    }
}

/// Which physics model the solver runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PhysicsModel {
    /// The paper's model: no spin, sliding friction above the slide/roll threshold speed and
    /// rolling friction below it.
    Paper,
    /// Spin (Leckie and Greenspan): sliding turns into rolling by friction at the contact
    /// point, throw between balls, a spin-aware cushion. The slide/roll threshold is unused.
    #[default]
    Spin,
}

impl PhysicsModel {
    /// Every model, in the order the panel lists them.
    pub const ALL: [Self; 2] = [Self::Paper, Self::Spin];

    /// The name shown to the player.
    pub fn label(self) -> &'static str {
        match self {
            Self::Paper => "paper (no spin)",
            Self::Spin => "spin (Leckie & Greenspan)",
        }
    }
}

/// The name of a contact-time prediction, as shown to the player.
pub fn prediction_label(prediction: Prediction) -> &'static str {
    match prediction {
        Prediction::Exact => "exact (roots of the real motion)",
        Prediction::PaperLinear => "paper's linear prediction",
    }
}

/// Every prediction, in the order the panel lists them.
pub const PREDICTIONS: [Prediction; 2] = [Prediction::Exact, Prediction::PaperLinear];

/// Random perturbation of collision normals (the paper's section 5).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Randomization {
    /// Whether collisions are perturbed at all.
    pub enabled: bool,
    /// Standard deviation of the perturbation of each collision normal, in degrees.
    pub spread_degrees: f64,
    /// Seed of the random sequence, so that a perturbed run can be replayed.
    pub seed: u64,
}

impl Default for Randomization {
    fn default() -> Self {
        Self {
            enabled: false,
            spread_degrees: 0.5,
            seed: 1,
        }
    }
}

/// The physical parameters of the simulation and its clock. Kept between runs (the settings
/// file); a field missing from the file takes its default.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PhysicsSettings {
    /// Sliding friction between ball and cloth.
    pub mu_slide: f64,
    /// Rolling resistance between ball and cloth.
    pub mu_roll: f64,
    /// Speed below which a ball counts as rolling rather than sliding (the paper's switch
    /// between its two friction regimes), in m/s.
    pub slide_roll_speed: f64,
    /// Ball-ball coefficient of restitution.
    pub e_ball: f64,
    /// Ball-cushion coefficient of restitution.
    pub e_cushion: f64,
    /// Friction turning a ball's spin about the vertical (spin model).
    pub mu_spin: f64,
    /// Friction between two balls in contact: throw and spin transfer (spin model).
    pub mu_ball: f64,
    /// Whether ball-ball friction is the constant above or falls with the sliding speed.
    pub ball_friction: BallFrictionChoice,
    /// The shaft, for squirt (spin model).
    pub shaft: ShaftChoice,
    /// How cushions respond (spin model; the paper's model always reflects).
    pub cushion: CushionChoice,
    /// Friction between ball and cushion nose (Han 2005 cushion).
    pub mu_cushion: f64,
    /// Height of the cushion nose above the cloth, as a fraction of the ball's diameter.
    pub cushion_height: f64,
    /// Mass of the cue, kg (how much of the stroke's speed the ball gets off centre).
    pub cue_mass: f64,
    /// Round the pocket jaws so balls can rattle (takes effect at the next rack: the table is
    /// fixed during a game); otherwise the mouths end square.
    pub jaws: bool,
    /// Perturbation of collision normals.
    pub randomization: Randomization,
    /// Physics model.
    pub model: PhysicsModel,
    /// How contact times are predicted.
    pub prediction: Prediction,
    /// Simulated seconds per real second.
    pub time_scale: f64,
    /// Whether the simulation clock is stopped (not kept between runs).
    #[serde(skip)]
    pub paused: bool,
}

impl Default for PhysicsSettings {
    fn default() -> Self {
        // Typical values from docs/physics reference (pooltool, FastFiz, Alciatore).
        let spin = SpinModel::default();
        let cushion = CushionChoice::default();
        // The default cushion's fitted constants (Mathavan et al.: e 0.98, mu 0.14); a default
        // without a fit (reflection) would start from Han's.
        let (e_cushion, mu_cushion) = cushion.fitted().unwrap_or((0.85, 0.2));
        Self {
            mu_slide: 0.2,
            mu_roll: 0.01,
            slide_roll_speed: 0.5,
            e_ball: 0.95,
            e_cushion,
            mu_spin: spin.mu_spin,
            mu_ball: spin.mu_ball,
            ball_friction: BallFrictionChoice::Constant,
            shaft: ShaftChoice::NoSquirt,
            cushion,
            mu_cushion,
            cushion_height: spin.cushion_height,
            cue_mass: spin.cue_mass,
            jaws: true,
            randomization: Randomization::default(),
            model: PhysicsModel::default(),
            prediction: Prediction::Exact,
            time_scale: 1.0,
            paused: false,
        }
    }
}

impl PhysicsSettings {
    /// Sliding friction of real cloths.
    pub const MU_SLIDE: ParamRange = ParamRange {
        label: "sliding friction",
        min: 0.15,
        max: 0.4,
        unit: "",
    };
    /// Rolling resistance of real cloths.
    pub const MU_ROLL: ParamRange = ParamRange {
        label: "rolling friction",
        min: 0.005,
        max: 0.015,
        unit: "",
    };
    /// The slide/roll switch speed; above a few m/s every ball would count as rolling.
    pub const SLIDE_ROLL_SPEED: ParamRange = ParamRange {
        label: "slide/roll threshold",
        min: 0.0,
        max: 2.0,
        unit: " m/s",
    };
    /// Ball-ball restitution: phenolic balls are 0.92-0.98; 1 is the paper's elastic ideal.
    pub const E_BALL: ParamRange = ParamRange {
        label: "ball restitution",
        min: 0.9,
        max: 1.0,
        unit: "",
    };
    /// Ball-cushion restitution: real rubber cushions are 0.6-0.9; 1 is the paper's mirror.
    pub const E_CUSHION: ParamRange = ParamRange {
        label: "cushion restitution",
        min: 0.6,
        max: 1.0,
        unit: "",
    };
    /// Spin friction: the reference's 0.044 (FastFiz) with room either side.
    pub const MU_SPIN: ParamRange = ParamRange {
        label: "spin friction",
        min: 0.01,
        max: 0.1,
        unit: "",
    };
    /// Ball-ball friction, the reference's range.
    pub const MU_BALL: ParamRange = ParamRange {
        label: "ball-ball friction",
        min: 0.03,
        max: 0.08,
        unit: "",
    };
    /// Ball-cushion friction (Han 2005 uses about 0.2).
    pub const MU_CUSHION: ParamRange = ParamRange {
        label: "cushion friction",
        min: 0.0,
        max: 0.4,
        unit: "",
    };
    /// Cushion nose height: WPA's 63.5 % of the diameter, with room either side (a nose at
    /// the centre height, 50 %, would give no spin-dependent rebound).
    pub const CUSHION_HEIGHT: ParamRange = ParamRange {
        label: "cushion nose height",
        min: 0.55,
        max: 0.75,
        unit: " D",
    };
    /// Cue mass: house cues run from about 16 to 23 oz.
    pub const CUE_MASS: ParamRange = ParamRange {
        label: "cue mass",
        min: 0.45,
        max: 0.65,
        unit: " kg",
    };
    /// Spread of the normal perturbation: beyond a few degrees play stops looking plausible.
    pub const SPREAD: ParamRange = ParamRange {
        label: "spread",
        min: 0.0,
        max: 5.0,
        unit: " deg",
    };
    /// Slow motion to fast forward.
    pub const TIME_SCALE: ParamRange = ParamRange {
        label: "time scale",
        min: 0.05,
        max: 4.0,
        unit: "x",
    };

    /// Clamps every parameter into its physical range, returning what was clamped.
    pub fn clamp_to_physical(&mut self) -> Vec<ClampNote> {
        let mut notes = Vec::new();
        Self::MU_SLIDE.clamp(&mut self.mu_slide, &mut notes);
        Self::MU_ROLL.clamp(&mut self.mu_roll, &mut notes);
        Self::SLIDE_ROLL_SPEED.clamp(&mut self.slide_roll_speed, &mut notes);
        Self::E_BALL.clamp(&mut self.e_ball, &mut notes);
        Self::E_CUSHION.clamp(&mut self.e_cushion, &mut notes);
        Self::MU_SPIN.clamp(&mut self.mu_spin, &mut notes);
        Self::MU_BALL.clamp(&mut self.mu_ball, &mut notes);
        Self::MU_CUSHION.clamp(&mut self.mu_cushion, &mut notes);
        Self::CUSHION_HEIGHT.clamp(&mut self.cushion_height, &mut notes);
        Self::CUE_MASS.clamp(&mut self.cue_mass, &mut notes);
        Self::SPREAD.clamp(&mut self.randomization.spread_degrees, &mut notes);
        Self::TIME_SCALE.clamp(&mut self.time_scale, &mut notes);
        notes
    }
}
