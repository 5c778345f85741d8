//! The cue strike (spin model): a cue, level or elevated, hitting the ball at a tip offset.

pub use crate::event::TipOffset;
use crate::math::{Vec2, Vec3};
use crate::params::SpinModel;

/// The tip offset is beyond the miscue limit.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error("miscue: tip offset {offset:.3} R is beyond the limit of {limit:.3} R")]
pub struct Miscue {
    /// Distance of the tip from the centre, in radii.
    pub offset: f64,
    /// The limit.
    pub limit: f64,
}

/// The cue at the strike: its direction in the table plane and its elevation above level.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cue {
    /// Unit direction of the cue's projection on the table.
    pub dir: Vec2,
    /// Angle of the cue above level, radians (0 is level; the butt is raised).
    pub elevation: f64,
}

/// Velocity and spin given by a cue along `cue`, striking at `tip`, where `speed` is the
/// ball speed along the cue that a centre hit would give.
///
/// The impulse `J` acts along the cue at the tip's contact point `r` (Alciatore, TP A-30;
/// Leckie & Greenspan; pooltool's `instantaneous_point`, which takes the offset in the cue's
/// frame as here). With an elastic tip and effective ball mass
/// `m / (1 + 5 (a^2 + b^2) / (2 R^2))` at that point, the ball's speed along the cue is
/// `2 V / (1 + m/M + 5 (a^2 + b^2)/(2 R^2))`, scaled so a centre hit gives `speed`. The
/// offsets `a` (side) and `b` (height) are the cue line's distances from the centre, in radii,
/// seen along the cue, so `|r x d| = (a^2 + b^2)^(1/2) R` whatever the elevation `theta` and
/// the miscue limit bounds the same offset. With `d = cos(theta) dir - sin(theta) z` the cue's
/// unit direction, the spin `w = r x J / I` is
/// `(5 v / 2R) (a cos(theta) z + a sin(theta) dir + b (z x dir))`: side english on an
/// elevated cue tilts the spin axis towards the shot, and the cloth's friction on that part
/// curves the path (swerve) while the ball slides. The impulse's vertical part,
/// `J sin(theta)`, drives the ball into the slate, which takes it through the contact point
/// below the centre (no torque): the ball keeps `v cos(theta)` in the plane and stays on the
/// table (no jump; the cloth's friction during that instant is neglected, as pooltool does).
/// A level cue (`theta = 0`) gives exactly the level strike's numbers.
pub fn strike(
    model: &SpinModel,
    ball_mass: f64,
    radius: f64,
    cue: Cue,
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
    let dir = cue.dir;
    let (sin, cos) = cue.elevation.sin_cos();
    let mass_ratio = ball_mass / model.cue_mass;
    let v = speed * (1.0 + mass_ratio) / (1.0 + mass_ratio + 2.5 * offset * offset);
    let k = 2.5 * v / radius;
    let mut w = Vec3::new(0.0, 0.0, k * tip.side * cos) + dir.perp().extend() * (k * tip.height);
    if sin != 0.0 {
        // Skipped when level, so a level strike stays bit for bit (no signed zeros added).
        w += dir.extend() * (k * tip.side * sin);
    }
    let heading = match model.end_mass {
        // Right english (side > 0) squirts the ball left of the cue line (TP A-31, a level
        // cue; applied to the horizontal heading as pooltool does).
        Some(m) => dir.rotated(squirt_angle(tip.side, ball_mass / m)),
        None => dir,
    };
    Ok((heading * (v * cos), w))
}

/// Squirt angle (radians, signed like `side`) of a ball struck at a side offset `side` (in
/// radii) by a shaft of effective end mass `ball_mass / mass_ratio` (Alciatore TP A-31,
/// after Shepard 2001: the ball pushes the tip sideways during contact):
/// `tan(squirt) = (5/2) b sqrt(1 - b^2) / (1 + m/m_e + (5/2)(1 - b^2))`, `b = side`.
pub fn squirt_angle(side: f64, mass_ratio: f64) -> f64 {
    let b = side.clamp(-1.0, 1.0);
    let c2 = 1.0 - b * b;
    (2.5 * b * c2.sqrt() / (1.0 + mass_ratio + 2.5 * c2)).atan()
}

#[cfg(test)]
mod tests {
    use super::*;

    const LEVEL: Cue = Cue {
        dir: Vec2::new(1.0, 0.0),
        elevation: 0.0,
    };

    #[test]
    fn squirt_follows_tp_a31_and_points_away_from_the_english() {
        let m = SpinModel {
            end_mass: Some(0.17 / 22.0),
            ..SpinModel::default()
        };
        let tip = TipOffset {
            side: 0.5,
            height: 0.0,
        };
        let (v, w) = strike(&m, 0.17, 0.028575, LEVEL, 2.0, tip).unwrap();
        // tan = 2.5 * 0.5 * sqrt(0.75) / (1 + 22 + 2.5 * 0.75) = 1.0825 / 24.875.
        let want = (1.25 * 0.75f64.sqrt() / 24.875).atan();
        assert!((v.angle() - want).abs() < 1e-15, "{} vs {want}", v.angle());
        assert!(
            v.y > 0.0 && w.z > 0.0,
            "right english spins +z and squirts left"
        );
        // The same speed and spin as without squirt: only the heading turns.
        let plain = SpinModel::default();
        let (v0, w0) = strike(&plain, 0.17, 0.028575, LEVEL, 2.0, tip).unwrap();
        assert!((v.length() - v0.length()).abs() < 1e-15 && w == w0);
        assert_eq!(v0.y, 0.0);
        // Centre ball: no squirt; a lighter end mass squirts less.
        assert_eq!(squirt_angle(0.0, 22.0), 0.0);
        assert!(squirt_angle(0.5, 40.0) < squirt_angle(0.5, 22.0));
        assert_eq!(squirt_angle(-0.5, 22.0), -squirt_angle(0.5, 22.0));
    }
}
