//! Player-editable settings: the next shot and the physical parameters.
//!
//! The panels write these resources; the simulation reads them. Every numeric field has a
//! physical range and [`ShotSettings::clamp_to_physical`] / [`PhysicsSettings::clamp_to_physical`]
//! pull out-of-range values back into it and report what they changed, so the panel can say so.

use std::{f64::consts::TAU, fmt};

use bevy::prelude::*;
use billiards_physics::{Prediction, SpinModel, TipOffset};
use serde::{Deserialize, Serialize};

/// Registers the settings resources.
pub fn plugin(app: &mut App) {
    app.init_resource::<ShotSettings>()
        .init_resource::<PhysicsSettings>()
        .init_resource::<ViewSettings>()
        .init_resource::<GraphicsSettings>()
        .init_resource::<ClampReport>();
}

/// The physical range of one parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamRange {
    /// Name shown to the player.
    pub label: &'static str,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value.
    pub max: f64,
    /// Unit suffix shown after the value ("" for dimensionless numbers).
    pub unit: &'static str,
}

impl ParamRange {
    /// Clamps `value` into the range, recording a note when it had to change it.
    /// A NaN (which no widget should produce) becomes the lower bound.
    pub fn clamp(&self, value: &mut f64, notes: &mut Vec<ClampNote>) {
        let applied = if value.is_nan() {
            self.min
        } else {
            value.clamp(self.min, self.max)
        };
        if applied != *value {
            notes.push(ClampNote {
                range: *self,
                requested: *value,
                applied,
            });
            *value = applied;
        }
    }

    /// The range as an inclusive `f64` range, for sliders.
    pub fn as_range(&self) -> std::ops::RangeInclusive<f64> {
        self.min..=self.max
    }
}

/// A value the player asked for that was outside its physical range, and what was used.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClampNote {
    /// The parameter and its range.
    pub range: ParamRange,
    /// What was asked for.
    pub requested: f64,
    /// What is used instead.
    pub applied: f64,
}

impl fmt::Display for ClampNote {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = &self.range;
        write!(
            f,
            "{} {}{} is outside {}..{}{}: clamped to {}{}",
            r.label, self.requested, r.unit, r.min, r.max, r.unit, self.applied, r.unit
        )
    }
}

/// The clamp notes of the most recent edit, shown by the panel until the next clamp.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct ClampReport {
    /// Notes of the last edit that needed clamping.
    pub notes: Vec<ClampNote>,
}

/// The shot the player is lining up.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct ShotSettings {
    /// Aim direction in the table plane, radians counter-clockwise from +x (toward the foot
    /// rail), kept in [0, 2 pi).
    pub angle: f64,
    /// Power, as the speed the cue gives the cue ball, in m/s.
    pub power: f64,
    /// Where the tip strikes, in ball radii from the centre (spin model; the paper's model
    /// ignores it): `side` right of centre, `height` above it.
    pub tip: TipOffset,
}

impl Default for ShotSettings {
    fn default() -> Self {
        // Straight up the table at a firm break speed, as in the paper's default layout.
        Self {
            angle: 0.0,
            power: 6.0,
            tip: TipOffset::default(),
        }
    }
}

impl ShotSettings {
    /// Cue-ball speed range: from a gentle touch to a hard break (11-13 m/s).
    pub const POWER: ParamRange = ParamRange {
        label: "power",
        min: 0.05,
        max: 13.0,
        unit: " m/s",
    };

    /// Wraps the angle into [0, 2 pi) and clamps the power, returning what was clamped.
    /// Wrapping the angle is not a clamp: every direction is valid.
    pub fn clamp_to_physical(&mut self) -> Vec<ClampNote> {
        let mut notes = Vec::new();
        if self.angle.is_finite() {
            self.angle = self.angle.rem_euclid(TAU);
            // rem_euclid can round up to exactly TAU for tiny negative inputs.
            if self.angle >= TAU {
                self.angle = 0.0;
            }
        } else {
            self.angle = 0.0;
        }
        Self::POWER.clamp(&mut self.power, &mut notes);
        Self::TIP_SIDE.clamp(&mut self.tip.side, &mut notes);
        Self::TIP_HEIGHT.clamp(&mut self.tip.height, &mut notes);
        // Beyond the miscue limit the tip would slip off: pull it back along its direction.
        let limit = Self::tip_limit();
        let offset = self.tip.side.hypot(self.tip.height);
        if offset > limit {
            let scale = limit / offset;
            notes.push(ClampNote {
                range: ParamRange {
                    label: "tip offset",
                    min: 0.0,
                    max: limit,
                    unit: " R",
                },
                requested: offset,
                applied: limit,
            });
            self.tip.side *= scale;
            self.tip.height *= scale;
        }
        notes
    }

    /// Tip offsets left/right of centre, in ball radii.
    pub const TIP_SIDE: ParamRange = ParamRange {
        label: "side (english)",
        min: -0.5,
        max: 0.5,
        unit: " R",
    };

    /// Tip offsets below (draw) and above (follow) centre, in ball radii.
    pub const TIP_HEIGHT: ParamRange = ParamRange {
        label: "height (follow/draw)",
        min: -0.5,
        max: 0.5,
        unit: " R",
    };

    /// The largest tip offset the solver accepts before calling a miscue, in radii.
    pub fn tip_limit() -> f64 {
        SpinModel::default().miscue_limit
    }

    /// The shot these settings describe.
    pub fn shot(&self) -> billiards_physics::Shot {
        billiards_physics::Shot {
            angle: self.angle,
            speed: self.power,
            tip: self.tip,
        }
    }

    /// The aim direction as a unit vector in the table plane.
    pub fn direction(&self) -> bevy::math::DVec2 {
        bevy::math::DVec2::from_angle(self.angle)
    }
}

/// The cushion model of the spin model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CushionChoice {
    /// Han (2005): impulse at the nose height with friction; english changes the rebound.
    #[default]
    Han2005,
    /// Plain reflection with restitution (no spin effect).
    Reflect,
}

impl CushionChoice {
    /// Every choice, in the panel's order.
    pub const ALL: [Self; 2] = [Self::Han2005, Self::Reflect];

    /// The name shown to the player.
    pub fn label(self) -> &'static str {
        match self {
            Self::Han2005 => "Han 2005 (spin-aware)",
            Self::Reflect => "reflection",
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
        Self {
            mu_slide: 0.2,
            mu_roll: 0.01,
            slide_roll_speed: 0.5,
            e_ball: 0.95,
            e_cushion: 0.85,
            mu_spin: spin.mu_spin,
            mu_ball: spin.mu_ball,
            cushion: CushionChoice::Han2005,
            mu_cushion: 0.2,
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

/// What is drawn on top of the scene.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct ViewSettings {
    /// Draw the paper's vectors: the red cue vector and blue ball velocities.
    pub show_vectors: bool,
    /// Draw the aiming aid: the path to the first contact, the ghost ball, the paths after.
    pub show_aim: bool,
    /// How far the aid follows each ball after the first contact: until it rests, drops or
    /// has made this many more contacts (balls, cushions, jaws).
    pub aid_contacts: u32,
}

impl ViewSettings {
    /// The range offered for [`ViewSettings::aid_contacts`].
    pub const AID_CONTACTS: std::ops::RangeInclusive<u32> = 1..=10;
}

impl Default for ViewSettings {
    fn default() -> Self {
        // The paper's default layout figure shows the cue vector.
        Self {
            show_vectors: true,
            show_aim: true,
            aid_contacts: 2,
        }
    }
}

/// Graphics quality, so a slow machine stays playable.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct GraphicsSettings {
    /// The lamps cast shadows.
    pub shadows: bool,
    /// Side of each lamp's shadow map, in texels.
    pub shadow_resolution: u32,
    /// Multisample anti-aliasing: samples per pixel (1 is off).
    pub msaa_samples: u32,
    /// The 3D view's resolution, in percent of the window's: below 100 the table is drawn
    /// into a smaller image and stretched over the window (the UI stays sharp).
    pub render_scale: u32,
}

impl GraphicsSettings {
    /// The shadow-map sizes offered.
    pub const SHADOW_RESOLUTIONS: [u32; 3] = [512, 1024, 2048];
    /// The MSAA sample counts offered (1: off).
    pub const MSAA_SAMPLES: [u32; 3] = [1, 2, 4];
    /// The render scales offered, in percent.
    pub const RENDER_SCALES: [u32; 3] = [50, 75, 100];

    /// The lowest settings: no shadows, no anti-aliasing, half resolution.
    pub const LOW: Self = Self {
        shadows: false,
        shadow_resolution: 512,
        msaa_samples: 1,
        render_scale: 50,
    };

    /// The render scale as a fraction of the window's resolution.
    pub fn render_fraction(&self) -> f32 {
        self.render_scale as f32 / 100.0
    }

    /// A copy with every value one the game offers (a hand-edited file may hold others).
    pub fn sanitized(self) -> Self {
        let nearest = |value: u32, choices: &[u32]| {
            *choices
                .iter()
                .min_by_key(|&&c| c.abs_diff(value))
                .expect("choices are not empty")
        };
        Self {
            shadows: self.shadows,
            shadow_resolution: nearest(self.shadow_resolution, &Self::SHADOW_RESOLUTIONS),
            msaa_samples: nearest(self.msaa_samples, &Self::MSAA_SAMPLES),
            render_scale: nearest(self.render_scale, &Self::RENDER_SCALES),
        }
    }
}

impl Default for GraphicsSettings {
    fn default() -> Self {
        Self {
            shadows: true,
            // Bevy's default for spot lights.
            shadow_resolution: 1024,
            msaa_samples: 4,
            render_scale: 100,
        }
    }
}

/// Writes an edited shot back (only if it changed, to keep change detection meaningful),
/// clamped, with any clamp reported to the panel.
pub fn apply_shot_edit(mut next: ShotSettings, shot: &mut ShotSettings, report: &mut ClampReport) {
    if next == *shot {
        return;
    }
    let notes = next.clamp_to_physical();
    if !notes.is_empty() {
        report.notes = notes;
    }
    *shot = next;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_inside_their_ranges() {
        assert!(PhysicsSettings::default().clamp_to_physical().is_empty());
        assert!(ShotSettings::default().clamp_to_physical().is_empty());
    }

    #[test]
    fn out_of_range_values_are_clamped_and_reported() {
        let mut settings = PhysicsSettings {
            mu_slide: 0.9,
            e_cushion: -1.0,
            ..default()
        };
        let notes = settings.clamp_to_physical();
        assert_eq!(settings.mu_slide, 0.4);
        assert_eq!(settings.e_cushion, 0.6);
        assert_eq!(notes.len(), 2);
        assert_eq!(notes[0].requested, 0.9);
        assert!(notes[0].to_string().contains("sliding friction"));
    }

    #[test]
    fn nan_is_replaced() {
        let mut shot = ShotSettings {
            angle: f64::NAN,
            power: f64::NAN,
            tip: TipOffset {
                side: f64::NAN,
                height: 0.0,
            },
        };
        let notes = shot.clamp_to_physical();
        assert_eq!(shot.angle, 0.0);
        assert_eq!(shot.power, ShotSettings::POWER.min);
        assert_eq!(shot.tip.side, ShotSettings::TIP_SIDE.min);
        assert_eq!(notes.len(), 2);
    }

    #[test]
    fn a_tip_beyond_the_miscue_limit_is_pulled_back_along_its_direction() {
        let mut shot = ShotSettings {
            tip: TipOffset {
                side: 0.4,
                height: -0.4,
            },
            ..default()
        };
        let notes = shot.clamp_to_physical();
        assert_eq!(notes.len(), 1);
        let limit = ShotSettings::tip_limit();
        assert!((shot.tip.side.hypot(shot.tip.height) - limit).abs() < 1e-12);
        assert!((shot.tip.side + shot.tip.height).abs() < 1e-12);
        assert!(notes[0].to_string().contains("tip offset"));
    }

    #[test]
    fn angle_wraps_without_a_note() {
        let mut shot = ShotSettings {
            angle: -std::f64::consts::FRAC_PI_2,
            power: 1.0,
            tip: TipOffset::default(),
        };
        assert!(shot.clamp_to_physical().is_empty());
        assert!((shot.angle - 1.5 * std::f64::consts::PI).abs() < 1e-12);
    }
}
