//! The box a ball's centre stays in over a search window: a cheap test that rules out the
//! fixed bodies it cannot reach before their time-of-impact search.

use crate::ball::Segment;
use crate::math::Vec2;

/// The box the centre of a ball stays in over a search window, from its exact path, widened by
/// [`PathBox::MARGIN`]: a fixed body it keeps clear of cannot be touched in that window, so
/// its time-of-impact search (which would find no root) is skipped. Only searches that
/// return `None` are skipped, so no event changes.
#[derive(Clone, Copy, Debug)]
pub(super) struct PathBox {
    min: Vec2,
    max: Vec2,
}

impl PathBox {
    /// Clearance kept beyond the box (m): far above the rounding of positions (~1e-16 m) and
    /// of the contact functions, which then stay positive by about `2 contact MARGIN`.
    const MARGIN: f64 = 1e-9;

    /// The box of the path of `seg` over `[t, t + horizon]`, `None` for an infinite or
    /// non-finite window. Each coordinate `p + v s + a s^2 / 2` takes its extremes at the
    /// ends of the window or at its vertex `s = -v / a`.
    #[inline]
    pub(super) fn of(seg: &Segment, t: f64, horizon: f64) -> Option<Self> {
        if !horizon.is_finite() {
            return None;
        }
        let h = horizon.max(0.0);
        let (p, v, a) = (seg.position_at(t), seg.velocity_at(t), seg.acceleration);
        let range = |p: f64, v: f64, a: f64| {
            let end = p + (v + 0.5 * a * h) * h;
            let (mut lo, mut hi) = (p.min(end), p.max(end));
            if a != 0.0 {
                let s = -v / a;
                if s > 0.0 && s < h {
                    let vertex = p + 0.5 * v * s;
                    lo = lo.min(vertex);
                    hi = hi.max(vertex);
                }
            }
            // Rounding of the end and vertex values, relative to the largest term.
            let slack = Self::MARGIN + 1e-12 * (p.abs() + (v * h).abs() + (a * h * h).abs());
            (lo - slack, hi + slack)
        };
        let (x0, x1) = range(p.x, v.x, a.x);
        let (y0, y1) = range(p.y, v.y, a.y);
        let b = Self {
            min: Vec2::new(x0, y0),
            max: Vec2::new(x1, y1),
        };
        (b.min.is_finite() && b.max.is_finite()).then_some(b)
    }

    /// The box of `points` widened by `widen` each way.
    pub(super) fn around(points: impl Iterator<Item = Vec2>, widen: f64) -> Self {
        let inf = Vec2::new(f64::INFINITY, f64::INFINITY);
        let (min, max) = points.fold((inf, -inf), |(lo, hi), c| {
            (
                Vec2::new(lo.x.min(c.x), lo.y.min(c.y)),
                Vec2::new(hi.x.max(c.x), hi.y.max(c.y)),
            )
        });
        let w = Vec2::new(widen, widen);
        Self {
            min: min - w,
            max: max + w,
        }
    }

    /// Whether the two boxes are more than `distance` apart along some axis.
    #[inline]
    pub(super) fn apart(&self, other: &Self, distance: f64) -> bool {
        other.min.x - self.max.x > distance
            || self.min.x - other.max.x > distance
            || other.min.y - self.max.y > distance
            || self.min.y - other.max.y > distance
    }

    /// Whether every point of the box is more than `distance` from `c` along some axis (so
    /// the centre never comes within `distance` of `c`).
    #[inline]
    pub(super) fn clear_of_point(&self, c: Vec2, distance: f64) -> bool {
        c.x < self.min.x - distance
            || c.x > self.max.x + distance
            || c.y < self.min.y - distance
            || c.y > self.max.y + distance
    }

    /// Whether the whole box lies where `offset + n·p > 0` (so the centre never reaches the
    /// line).
    #[inline]
    pub(super) fn clear_of_line(&self, n: Vec2, offset: f64) -> bool {
        // The corner of the box furthest towards the line.
        let x = if n.x > 0.0 { self.min.x } else { self.max.x };
        let y = if n.y > 0.0 { self.min.y } else { self.max.y };
        offset + n.x * x + n.y * y > 0.0
    }
}
