//! The next shot as the player set it up: direction, power, tip.

use std::f64::consts::TAU;

use bevy::prelude::*;
use billiards_physics::{SpinModel, TipOffset};

use super::range::{ClampNote, ClampReport, ParamRange};

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
    /// How far the cue's butt is raised, degrees (spin model): with side spin the cue ball
    /// swerves, curving back towards the english as the cloth acts on it.
    pub elevation: f64,
}

impl Default for ShotSettings {
    fn default() -> Self {
        // Straight up the table at a firm break speed, as in the paper's default layout.
        Self {
            angle: 0.0,
            power: 6.0,
            tip: TipOffset::default(),
            elevation: 0.0,
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
        Self::ELEVATION.clamp(&mut self.elevation, &mut notes);
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

    /// Cue elevation: level to the solver's limit (85 degrees, `limits::MAX_ELEVATION`): a
    /// jump shot at 30-60 degrees, a masse above (issue 52).
    pub const ELEVATION: ParamRange = ParamRange {
        label: "cue elevation",
        min: 0.0,
        max: 85.0,
        unit: " deg",
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
            // 85 degrees in radians may round a hair above the solver's limit.
            elevation: self
                .elevation
                .to_radians()
                .clamp(0.0, billiards_physics::limits::MAX_ELEVATION),
        }
    }

    /// The aim direction as a unit vector in the table plane.
    pub fn direction(&self) -> bevy::math::DVec2 {
        bevy::math::DVec2::from_angle(self.angle)
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

/// An aim angle (radians) in degrees as the panel shows it, to two decimals in 0..=359.99: an
/// angle a hair below a full turn reads 0.00, not 360.00.
pub fn shown_degrees(angle: f64) -> f64 {
    let degrees = (angle.to_degrees().rem_euclid(360.0) * 100.0).round() / 100.0;
    if degrees >= 360.0 { 0.0 } else { degrees }
}
