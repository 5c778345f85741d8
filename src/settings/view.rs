//! What the player sees: the view and the graphics quality.

use bevy::prelude::*;
use serde::{Deserialize, Serialize};

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
