//! Execution noise: FastFiz's `GaussianNoise(magnitude)`, independent Gaussian errors on the
//! shot's parameters with, at magnitude 1, the standard deviations of the computer-pool
//! tournaments (`../shared/reference/games.md`): tip offset side and height 0.5 mm each, aim
//! angle 0.125 degrees, cue speed 0.075 m/s and cue elevation (FastFiz `theta`) 0.1 degrees.
//! The elevation cannot go below level, so a level shot's error is clamped at 0: half the
//! executed shots are level, the other half raised by `|N(0, 0.1 degrees)|`.
//!
//! Random numbers come from a ChaCha8 stream seeded by [`stream`] from the decision's seed and
//! the indices of what is drawn (candidate, sample), never from which thread draws them: the
//! same seed gives the same draws on one thread and on all cores.

use billiards_physics::{Params, Shot, TipOffset};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Standard deviation of the side tip offset at magnitude 1, metres (FastFiz `a`).
pub const SIGMA_SIDE: f64 = 0.5e-3;
/// Standard deviation of the height tip offset at magnitude 1, metres (FastFiz `b`).
pub const SIGMA_HEIGHT: f64 = 0.5e-3;
/// Standard deviation of the aim angle at magnitude 1, degrees (FastFiz `phi`).
pub const SIGMA_PHI_DEG: f64 = 0.125;
/// Standard deviation of the cue speed at magnitude 1, m/s (FastFiz `v`).
pub const SIGMA_SPEED: f64 = 0.075;
/// Standard deviation of the cue elevation at magnitude 1, degrees (FastFiz `theta`).
pub const SIGMA_THETA_DEG: f64 = 0.1;

/// Slowest shot the noise may leave (m/s): a shot is never turned into no shot.
const MIN_SPEED: f64 = 0.05;
/// Fastest shot, m/s (a hard break is about 12).
const MAX_SPEED: f64 = 14.0;

/// Gaussian execution noise of one magnitude (0: none; 1: the reference level).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Noise {
    /// Multiplier of every reference standard deviation.
    pub magnitude: f64,
}

impl Noise {
    /// No noise at all.
    pub const NONE: Noise = Noise { magnitude: 0.0 };

    /// The reference level (magnitude 1).
    pub const REFERENCE: Noise = Noise { magnitude: 1.0 };

    /// Standard deviation of the aim angle, radians.
    pub fn sigma_angle(self) -> f64 {
        self.magnitude * SIGMA_PHI_DEG.to_radians()
    }

    /// `shot` as executed: each parameter moved by its Gaussian error. The tip stays inside
    /// the miscue limit of `params` (a wild tip is pulled back radially to just inside it),
    /// the speed inside the range a cue can give, the elevation from level to
    /// [`billiards_physics::limits::MAX_ELEVATION`]. The elevation is drawn last, so the other
    /// parameters take the same draws as before it existed.
    pub fn apply(self, shot: Shot, params: &Params, rng: &mut ChaCha8Rng) -> Shot {
        if self.magnitude == 0.0 {
            return shot;
        }
        let m = self.magnitude;
        let r = params.ball.radius;
        let angle = shot.angle + m * SIGMA_PHI_DEG.to_radians() * gaussian(rng);
        let speed = (shot.speed + m * SIGMA_SPEED * gaussian(rng)).clamp(MIN_SPEED, MAX_SPEED);
        let mut tip = TipOffset {
            side: shot.tip.side + m * SIGMA_SIDE / r * gaussian(rng),
            height: shot.tip.height + m * SIGMA_HEIGHT / r * gaussian(rng),
        };
        let limit = 0.98 * miscue_limit(params);
        let offset = tip.side.hypot(tip.height);
        if offset > limit {
            tip.side *= limit / offset;
            tip.height *= limit / offset;
        }
        let elevation = (shot.elevation + m * SIGMA_THETA_DEG.to_radians() * gaussian(rng))
            .clamp(0.0, billiards_physics::limits::MAX_ELEVATION);
        Shot {
            angle,
            speed,
            tip,
            elevation,
        }
    }
}

/// The spin model's miscue limit in radii (the paper's model has no tip: any limit will do).
pub(crate) fn miscue_limit(params: &Params) -> f64 {
    match params.model {
        billiards_physics::Model::Spin(m) => m.miscue_limit,
        billiards_physics::Model::Paper(_) => 0.5,
    }
}

/// A standard normal draw (Box–Muller; one of the pair is used, which keeps the draws of a
/// sample independent of how many a caller takes).
fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    // 1 - u is in (0, 1], so the logarithm is finite.
    let u: f64 = 1.0 - rng.random::<f64>();
    let v: f64 = rng.random::<f64>();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// SplitMix64's finaliser: a well-mixed 64-bit value from any input.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The random stream of draw `b` of item `a` under `seed` (a candidate and its sample, or a
/// game and its shot): a function of the three numbers only.
pub fn stream(seed: u64, a: u64, b: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(mix(mix(mix(seed) ^ a) ^ b.rotate_left(32)))
}

/// The error function (Abramowitz and Stegun 7.1.26, absolute error below 1.5e-7).
pub(crate) fn erf(x: f64) -> f64 {
    let t = 1.0 / (1.0 + 0.327_591_1 * x.abs());
    let poly = t
        * (0.254_829_592
            + t * (-0.284_496_736
                + t * (1.421_413_741 + t * (-1.453_152_027 + t * 1.061_405_429))));
    let y = 1.0 - poly * (-x * x).exp();
    if x < 0.0 { -y } else { y }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_noise_has_fastfizs_deviations() {
        let params = Params::default();
        let shot = Shot::new(0.3, 2.0);
        let n = 20_000;
        let (mut sa, mut sv, mut ss) = (0.0, 0.0, 0.0);
        for k in 0..n {
            let s = Noise::REFERENCE.apply(shot, &params, &mut stream(1, 2, k));
            sa += (s.angle - 0.3).powi(2);
            sv += (s.speed - 2.0).powi(2);
            ss += (s.tip.side * params.ball.radius).powi(2);
        }
        let sd = |s: f64| (s / n as f64).sqrt();
        assert!((sd(sa).to_degrees() / SIGMA_PHI_DEG - 1.0).abs() < 0.03);
        assert!((sd(sv) / SIGMA_SPEED - 1.0).abs() < 0.03);
        assert!((sd(ss) / SIGMA_SIDE - 1.0).abs() < 0.03);
        assert_eq!(Noise::NONE.apply(shot, &params, &mut stream(1, 2, 3)), shot);
    }

    #[test]
    fn the_elevation_error_is_fastfizs_theta_clamped_at_level() {
        let params = Params::default();
        let n = 20_000;
        // A raised cue: the full Gaussian, 0.1 degrees.
        let raised = Shot {
            elevation: 10f64.to_radians(),
            ..Shot::new(0.3, 2.0)
        };
        let mut s2 = 0.0;
        for k in 0..n {
            let s = Noise::REFERENCE.apply(raised, &params, &mut stream(3, 4, k));
            s2 += (s.elevation - raised.elevation).powi(2);
        }
        let sd = (s2 / n as f64).sqrt().to_degrees();
        assert!((sd / SIGMA_THETA_DEG - 1.0).abs() < 0.03, "{sd}");
        // A level cue: never below level; half the shots stay level, the rest |N| (rms over
        // all of them sigma / sqrt 2).
        let level = Shot::new(0.3, 2.0);
        let (mut zero, mut s2) = (0, 0.0);
        for k in 0..n {
            let s = Noise::REFERENCE.apply(level, &params, &mut stream(3, 4, k));
            assert!(s.elevation >= 0.0);
            zero += usize::from(s.elevation == 0.0);
            s2 += s.elevation.powi(2);
        }
        assert!((zero as f64 / n as f64 - 0.5).abs() < 0.02, "{zero}");
        let rms = (s2 / n as f64).sqrt().to_degrees() * 2f64.sqrt();
        assert!((rms / SIGMA_THETA_DEG - 1.0).abs() < 0.03, "{rms}");
    }

    #[test]
    fn streams_depend_on_their_indices_only() {
        let a: u64 = stream(5, 6, 7).random();
        assert_eq!(a, stream(5, 6, 7).random::<u64>());
        assert_ne!(a, stream(5, 7, 6).random::<u64>());
        assert!((erf(1.0) - 0.842_700_79).abs() < 2e-7 && erf(-1.0) < 0.0);
    }
}
