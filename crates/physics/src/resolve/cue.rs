//! The cue strike (spin model): a level cue hitting the ball at a tip offset.

use crate::math::{Vec2, Vec3};
use crate::params::SpinModel;
use serde::{Deserialize, Serialize};

/// Where the cue tip strikes, as fractions of the ball's radius from its centre, seen from
/// behind the cue.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct TipOffset {
    /// Right of centre is positive (right english).
    pub side: f64,
    /// Above centre is positive (follow), below negative (draw).
    pub height: f64,
}

/// The tip offset is beyond the miscue limit.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error("miscue: tip offset {offset:.3} R is beyond the limit of {limit:.3} R")]
pub struct Miscue {
    /// Distance of the tip from the centre, in radii.
    pub offset: f64,
    /// The limit.
    pub limit: f64,
}

/// Velocity and spin given by a level cue along unit direction `dir`, striking at `tip`, where
/// `speed` is the ball speed a centre hit would give.
///
/// The impulse acts along the cue at the contact point `r` (Alciatore, TP A-30; Leckie &
/// Greenspan): with an elastic tip and effective ball mass `m / (1 + 5 (a^2 + b^2) / (2 R^2))`
/// at that point, the ball speed is `2 V / (1 + m/M + 5 (a^2 + b^2)/(2 R^2))`, scaled here so
/// a centre hit gives `speed`; the spin is `w = r x J / I = (5 v / 2R) (a z + b (z x dir))`
/// for offsets `a`, `b` in radii (so `b = 2/5` rolls at once).
pub fn strike(
    model: &SpinModel,
    ball_mass: f64,
    radius: f64,
    dir: Vec2,
    speed: f64,
    tip: TipOffset,
) -> Result<(Vec2, Vec3), Miscue> {
    let offset = (tip.side * tip.side + tip.height * tip.height).sqrt();
    if offset.is_nan() || offset > model.miscue_limit {
        return Err(Miscue {
            offset,
            limit: model.miscue_limit,
        });
    }
    let mass_ratio = ball_mass / model.cue_mass;
    let v = speed * (1.0 + mass_ratio) / (1.0 + mass_ratio + 2.5 * offset * offset);
    let k = 2.5 * v / radius;
    let w = Vec3::new(0.0, 0.0, k * tip.side) + dir.perp().extend() * (k * tip.height);
    Ok((dir * v, w))
}
