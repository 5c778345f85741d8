//! Cushion rebounds: the cushion laws against Mathavan's measurements, the curves of
//! `cushion.svg`.

use super::data;
use billiards_physics::resolve::{Mathavan2010, han_2005, mathavan_2010, reflect};
use billiards_physics::*;

/// A cushion law for the curves: how a ball of radius `r` leaves a cushion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CushionCurve {
    /// Reflection, e = 0.85 (the solver's constant).
    Reflect,
    /// Han 2005 with the solver's default e = 0.85, mu = 0.2.
    Han2005,
    /// Mathavan 2010 with the paper's e = 0.98, mu_w = 0.14, mu_s = 0.212.
    Mathavan2010,
}

impl CushionCurve {
    /// All three, in the plots' order.
    pub const ALL: [Self; 3] = [Self::Reflect, Self::Han2005, Self::Mathavan2010];

    /// The legend's name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Reflect => "reflection (e 0.85)",
            Self::Han2005 => "Han 2005 (e 0.85, mu 0.2)",
            Self::Mathavan2010 => "Mathavan 2010 (e 0.98, mu 0.14)",
        }
    }

    /// Rebound `(speed m/s, angle deg from the cushion line)` of the paper's snooker ball
    /// (radius, nose at 7R/5) meeting the cushion at `speed` and `alpha` degrees from the
    /// cushion line (90: square), with topspin `top` times natural roll and side spin `side`
    /// times `v/R` (positive: about +z).
    pub fn rebound(self, speed: f64, alpha: f64, top: f64, side: f64) -> (f64, f64) {
        let (r, _, h, mu_s) = data::MATHAVAN_BALL;
        let a = alpha.to_radians();
        let v = Vec2::new(speed * a.cos(), speed * a.sin());
        let w = (Vec2::new(-a.sin(), a.cos()) * (top * speed / r)).extend()
            + Vec3::new(0.0, 0.0, side * speed / r);
        let n = Vec2::new(0.0, -1.0);
        let out = match self {
            Self::Reflect => reflect(v, n, 0.85),
            Self::Han2005 => han_2005(v, w, n, 0.85, 0.2, r, h * r).map(|(v, _)| v),
            Self::Mathavan2010 => {
                let m = Mathavan2010 {
                    e: 0.98,
                    mu_cushion: 0.14,
                    mu_table: mu_s,
                    height: h * r,
                };
                mathavan_2010(v, w, n, &m, r).map(|(v, _)| v)
            }
        };
        let out = out.unwrap_or(Vec2::ZERO);
        (out.length(), (-out.y).atan2(out.x).to_degrees())
    }
}

/// Restitution of `model` (reflection or Han, Han's friction kept at 0.2) whose rebound of a
/// rolling ball square into the cushion matches the mean measured ratio of Fig. 7(a) below
/// 2.5 m/s (bisection; the models have no rate, so one speed stands for all); with the
/// model's ratio at that restitution and the measured mean (e = 1 if none reaches it).
pub fn fit_e(model: CushionCurve) -> (f64, f64, f64) {
    let below: Vec<f64> = data::MATHAVAN_FIG7A
        .iter()
        .filter(|p| p.0 < data::MATHAVAN_RIGID_LIMIT)
        .map(|p| p.1 / p.0)
        .collect();
    let want = below.iter().sum::<f64>() / below.len() as f64;
    let (r, _, h, _) = data::MATHAVAN_BALL;
    let ratio = |e: f64| {
        let v = Vec2::new(0.0, 1.0);
        let w = Vec3::new(-1.0 / r, 0.0, 0.0);
        let n = Vec2::new(0.0, -1.0);
        let out = match model {
            CushionCurve::Han2005 => han_2005(v, w, n, e, 0.2, r, h * r).map(|p| p.0),
            _ => reflect(v, n, e),
        };
        out.map_or(0.0, |o| o.length())
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if ratio(mid) < want {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let e = 0.5 * (lo + hi);
    (e, ratio(e), want)
}

/// How a cushion model meets Mathavan's Fig. 7(a): relative errors of the rebound speed over
/// the points below and above the rigid-cushion limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    /// Root-mean-square relative error, points below 2.5 m/s.
    pub rms_below: f64,
    /// Largest relative error, points below 2.5 m/s.
    pub max_below: f64,
    /// Root-mean-square relative error, points above.
    pub rms_above: f64,
    /// Mean measured rebound/incident ratio minus the model's, below the limit.
    pub bias_below: f64,
}

/// [`Fit`] of `model` to [`data::MATHAVAN_FIG7A`] (rolling, square).
pub fn fig7a_fit(model: CushionCurve) -> Fit {
    let (mut below, mut above) = (Vec::new(), Vec::new());
    for &(vin, vout) in &data::MATHAVAN_FIG7A {
        let (model_out, _) = model.rebound(vin, 90.0, 1.0, 0.0);
        let rel = (model_out - vout) / vout;
        if vin < data::MATHAVAN_RIGID_LIMIT {
            below.push((rel, vout / vin - model_out / vin));
        } else {
            above.push(rel);
        }
    }
    let rms = |x: &[f64]| (x.iter().map(|e| e * e).sum::<f64>() / x.len() as f64).sqrt();
    let rel_below: Vec<f64> = below.iter().map(|p| p.0).collect();
    Fit {
        rms_below: rms(&rel_below),
        max_below: rel_below.iter().fold(0.0, |m, e| m.max(e.abs())),
        rms_above: rms(&above),
        bias_below: below.iter().map(|p| p.1).sum::<f64>() / below.len() as f64,
    }
}
