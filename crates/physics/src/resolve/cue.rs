//! The cue strike (spin model): a cue, level or elevated, hitting the ball at a tip offset.

pub use crate::event::TipOffset;
use crate::math::{Vec2, Vec3};
use crate::params::SpinModel;
use crate::resolve::slate::{self, Bounce, Slate};

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

/// Velocity, upward speed and spin given by a cue along `cue`, striking at `tip`, where
/// `speed` is the ball speed along the cue that a centre hit would give, on a table with
/// `gravity`.
///
/// The impulse `J` acts along the cue at the tip's contact point `r` (Alciatore, TP A-30;
/// Leckie & Greenspan; pooltool's `instantaneous_point`, which takes the offset in the cue's
/// frame as here). With an elastic tip and effective ball mass
/// `m / (1 + 5 (a^2 + b^2) / (2 R^2))` at that point, the ball's speed along the cue is
/// `2 V / (1 + m/M + 5 (a^2 + b^2)/(2 R^2))`, scaled so a centre hit gives `speed`. The
/// offsets `a` (side) and `b` (height) are the cue line's distances from the centre, in radii,
/// seen along the cue, so `|r x d| = (a^2 + b^2)^(1/2) R` whatever the elevation `theta` and
/// the miscue limit bounds the same offset. With `d = cos(theta) dir - sin(theta) z` the cue's
/// unit direction, the ball takes `v d` (the whole impulse, its downward part
/// `-v sin(theta) z` included) and the spin `w = r x J / I` is
/// `(5 v / 2R) (a cos(theta) z + a sin(theta) dir + b (z x dir))`: side english on an
/// elevated cue tilts the spin axis towards the shot, and the cloth's friction on that part
/// curves the path (swerve) while the ball slides.
///
/// The ball, driven down at `v sin(theta)`, meets the slate at once: the slate's reaction
/// ([`slate::bounce`]: restitution [`slate::SLATE_RESTITUTION`], the cloth's sliding friction
/// `mu_slide` or the no-slip limit, whichever is smaller) sets its take-off speed
/// `e v sin(theta)` and changes its velocity and spin by the friction impulse, as pooltool's
/// strike followed by its `frictional_inelastic` ball-table resolution. A ball that would rise
/// under [`slate::MIN_BOUNCE_HEIGHT`] stays on the cloth with the planar strike's numbers (the
/// slate takes the vertical part, no friction), bit for bit as before flight was modelled. A level cue (`theta = 0`) drives nothing
/// into the slate and gives exactly the level strike's numbers, bit for bit.
pub fn strike(
    model: &SpinModel,
    ball_mass: f64,
    radius: f64,
    gravity: f64,
    cue: Cue,
    speed: f64,
    tip: TipOffset,
) -> Result<Bounce, Miscue> {
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
    let heading = match model.end_mass {
        // Right english (side > 0) squirts the ball left of the cue line (TP A-31, a level
        // cue; applied to the horizontal heading as pooltool does).
        Some(m) => dir.rotated(squirt_angle(tip.side, ball_mass / m)),
        None => dir,
    };
    let velocity = heading * (v * cos);
    if sin == 0.0 {
        // Level: nothing driven into the slate, and no signed zeros added to the spin.
        return Ok(Bounce {
            velocity,
            vertical: 0.0,
            spin: w,
        });
    }
    w += dir.extend() * (k * tip.side * sin);
    let up = slate::SLATE_RESTITUTION * v * sin;
    if up * up / (2.0 * gravity) < slate::MIN_BOUNCE_HEIGHT {
        // The ball stays on the cloth: the slate takes the impulse's vertical part through
        // the contact point below the centre, as the strike always did (the cloth's friction
        // in that instant neglected, as pooltool's strike does), so every shot that stays
        // down keeps its events bit for bit (issue 51): a swerve, or a level shot with the
        // computer's elevation noise.
        return Ok(Bounce {
            velocity,
            vertical: 0.0,
            spin: w,
        });
    }
    let slate = Slate {
        restitution: slate::SLATE_RESTITUTION,
        mu: model.mu_slide,
        gravity,
        radius,
    };
    Ok(slate::bounce(&slate, velocity, -v * sin, w))
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
        let b = strike(&m, 0.17, 0.028575, 9.81, LEVEL, 2.0, tip).unwrap();
        let (v, w) = (b.velocity, b.spin);
        // tan = 2.5 * 0.5 * sqrt(0.75) / (1 + 22 + 2.5 * 0.75) = 1.0825 / 24.875.
        let want = (1.25 * 0.75f64.sqrt() / 24.875).atan();
        assert!((v.angle() - want).abs() < 1e-15, "{} vs {want}", v.angle());
        assert!(
            v.y > 0.0 && w.z > 0.0,
            "right english spins +z and squirts left"
        );
        // The same speed and spin as without squirt: only the heading turns.
        let plain = SpinModel::default();
        let b0 = strike(&plain, 0.17, 0.028575, 9.81, LEVEL, 2.0, tip).unwrap();
        let (v0, w0) = (b0.velocity, b0.spin);
        assert!((v.length() - v0.length()).abs() < 1e-15 && w == w0);
        assert_eq!(v0.y, 0.0);
        // Centre ball: no squirt; a lighter end mass squirts less.
        assert_eq!(squirt_angle(0.0, 22.0), 0.0);
        assert!(squirt_angle(0.5, 40.0) < squirt_angle(0.5, 22.0));
        assert_eq!(squirt_angle(-0.5, 22.0), -squirt_angle(0.5, 22.0));
    }

    #[test]
    fn an_elevated_centre_hit_leaves_the_slate_rolling_at_e_v_sin_theta() {
        // 3 m/s at 45 degrees, centre: the ball takes v d, the slate returns e v sin(theta)
        // upward and friction P mu = 0.2 (1.5) v sin(theta) exceeds the no-slip limit
        // (2/7) v cos(theta) (tan 45 >= (2/7) / (mu (1 + e)), the reference's 43.6 degrees), so
        // it leaves rolling at (5/7) v cos(theta) and rises (e v sin(theta))^2 / 2g = 57 mm.
        let m = SpinModel::default();
        let (r, g, theta) = (0.028575, 9.81, std::f64::consts::FRAC_PI_4);
        let cue = Cue {
            dir: Vec2::new(0.0, 1.0),
            elevation: theta,
        };
        let b = strike(&m, 0.17, r, g, cue, 3.0, TipOffset::default()).unwrap();
        let (vz, vxy) = (0.5 * 3.0 * theta.sin(), 5.0 / 7.0 * 3.0 * theta.cos());
        assert!((b.vertical - vz).abs() < 1e-12, "{}", b.vertical);
        assert!(b.velocity.x.abs() < 1e-15 && (b.velocity.y - vxy).abs() < 1e-12);
        assert!(
            (b.spin.x * -r - b.velocity.y).abs() < 1e-12,
            "rolling: v = -R w_x"
        );
        let rise = b.vertical * b.vertical / (2.0 * g);
        assert!((rise - 0.0573).abs() < 1e-4, "rise {rise}");
        // Under the grip angle, Coulomb's mu (1 + e) v sin(theta) is what the slate takes.
        let low = Cue {
            elevation: 0.5,
            ..cue
        };
        let b = strike(&m, 0.17, r, g, low, 3.0, TipOffset::default()).unwrap();
        let want = 3.0 * 0.5f64.cos() - 0.2 * 1.5 * 3.0 * 0.5f64.sin();
        assert!(
            (b.velocity.y - want).abs() < 1e-12,
            "{} vs {want}",
            b.velocity.y
        );
        // A gentle raised cue is absorbed: 1 m/s at 10 degrees would rise 0.2 mm.
        let soft = Cue {
            elevation: 10f64.to_radians(),
            ..cue
        };
        let b = strike(&m, 0.17, r, g, soft, 1.0, TipOffset::default()).unwrap();
        assert_eq!(b.vertical, 0.0);
    }
}
