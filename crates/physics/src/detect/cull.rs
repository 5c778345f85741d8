//! The closest-approach cull of ball pairs: one pair at a time ([`misses`], before any
//! quartic is built) or a whole row of pairs at once ([`PathColumns::cull_row`], the same
//! test without branches, so that it vectorizes). Both use the margins below, so a pair
//! either of them rejects has no contact root.

use crate::ball::{BallId, Segment};
use crate::math::Vec2;

/// Relative margin of the closest-approach cull over the contact distance: a pair is kept
/// when it comes within `(contact + bend) (1 + MISS_RELATIVE_MARGIN) + MISS_ABSOLUTE_MARGIN`.
/// Far above the rounding of the contact quartic's coefficients, so a rejected pair has no
/// root either.
pub const MISS_RELATIVE_MARGIN: f64 = 1e-9;

/// Absolute margin (m) of the closest-approach cull over the contact distance (see
/// [`MISS_RELATIVE_MARGIN`]).
pub const MISS_ABSOLUTE_MARGIN: f64 = 1e-9;

/// Margin on the squared closest distance per squared initial distance: the rounding of
/// `|dp + dv tau|^2` grows with `|dp|^2`, so far pairs need a wider margin.
pub const MISS_ROUNDING: f64 = 1e-12;

/// The distance within which a pair is kept: the contact distance plus what the relative
/// acceleration can close (`bend`), with the margins above.
#[inline]
fn miss_reach(contact: f64, bend: f64) -> f64 {
    (contact + bend) * (1.0 + MISS_RELATIVE_MARGIN) + MISS_ABSOLUTE_MARGIN
}

/// Can `|dp + dv τ + da τ²/2|` surely not come down to `contact` for τ in `[0, h]`? The
/// closest approach of the linear part over the interval, less the most the acceleration
/// term can close (`|da| h² / 2`), with a margin far above the rounding of the quartic's
/// coefficients (so a pair it rejects has no root there either). Cheaper than the reach
/// bound and much tighter for fast pairs that pass each other.
#[inline]
pub fn misses(dp: Vec2, dv: Vec2, da: Vec2, contact: f64, h: f64) -> bool {
    if h.is_nan() || h < 0.0 {
        return false;
    }
    let (pv, vv) = (dp.dot(dv), dv.length_squared());
    let tau = if pv >= 0.0 {
        0.0
    } else if -pv >= vv * h {
        h
    } else {
        -pv / vv
    };
    let bend = if da == Vec2::ZERO {
        0.0
    } else {
        0.5 * da.length() * h * h
    };
    let closest = dp + dv * tau;
    let reach = miss_reach(contact, bend);
    // False whenever a bound is infinite or NaN (unbounded horizon): then nothing is culled.
    closest.length_squared() > reach * reach + MISS_ROUNDING * dp.length_squared()
}

/// [`PathColumns::flags`] bit: the ball moves.
const MOVING: u8 = 1;
/// [`PathColumns::flags`] bit: the ball is on the table.
const ON_TABLE: u8 = 2;

/// Every ball's segment (start, position, velocity, acceleration) and the time its segment
/// stops mattering to pair searches (the ball's next event with no other ball, infinity for
/// none), one array per component so that the cull of a row of pairs is a loop the compiler
/// vectorizes. Updated only for the balls an event changes.
#[derive(Debug, Default)]
pub(crate) struct PathColumns {
    start: Vec<f64>,
    px: Vec<f64>,
    py: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
    ax: Vec<f64>,
    ay: Vec<f64>,
    /// The time of each ball's next event with no other ball (infinity for none).
    until: Vec<f64>,
    /// [`MOVING`] and [`ON_TABLE`] bits.
    flags: Vec<u8>,
    /// How many balls have a non-zero (or NaN) acceleration: with none (a frictionless
    /// scene), the cull drops the acceleration terms.
    accelerating: usize,
}

clone_reusing!(PathColumns {
    start,
    px,
    py,
    vx,
    vy,
    ax,
    ay,
    until,
    flags,
    accelerating
});

impl PathColumns {
    /// Columns for `n` balls, all at rest off the table until [`PathColumns::set`].
    pub fn new(n: usize) -> Self {
        let z = vec![0.0; n];
        Self {
            start: z.clone(),
            px: z.clone(),
            py: z.clone(),
            vx: z.clone(),
            vy: z.clone(),
            ax: z.clone(),
            ay: z,
            until: vec![f64::INFINITY; n],
            flags: vec![0; n],
            accelerating: 0,
        }
    }

    /// Records ball `id`'s segment and the time of its next event with no other ball.
    #[inline]
    pub fn set(&mut self, id: BallId, seg: &Segment, until: f64) {
        let s = &seg.state;
        let was = self.ax[id] != 0.0 || self.ay[id] != 0.0;
        let now = seg.acceleration.x != 0.0 || seg.acceleration.y != 0.0;
        self.accelerating = self.accelerating + usize::from(now) - usize::from(was);
        self.start[id] = seg.start;
        (self.px[id], self.py[id]) = (s.position.x, s.position.y);
        (self.vx[id], self.vy[id]) = (s.velocity.x, s.velocity.y);
        (self.ax[id], self.ay[id]) = (seg.acceleration.x, seg.acceleration.y);
        self.until[id] = until;
        let moving = if s.motion.is_moving() { MOVING } else { 0 };
        let on_table = if s.motion.on_table() { ON_TABLE } else { 0 };
        self.flags[id] = moving | on_table;
    }

    /// The time of ball `id`'s next event with no other ball (infinity for none).
    #[inline]
    pub fn until(&self, id: BallId) -> f64 {
        self.until[id]
    }

    /// Is ball `id` on the table and moving (the only balls whose row is culled)?
    #[inline]
    pub fn moving_on_table(&self, id: BallId) -> bool {
        self.flags[id] == MOVING | ON_TABLE
    }

    /// Can balls `i` and `j` touch at all: both on the table, and one of them moving?
    #[inline]
    pub fn may_meet(&self, i: BallId, j: BallId) -> bool {
        let (fi, fj) = (self.flags[i], self.flags[j]);
        fi & fj & ON_TABLE != 0 && (fi | fj) & MOVING != 0
    }

    /// For every ball `j`, whether balls `i` and `j` may touch between `t` and the earlier
    /// of their next events with no other ball: the test of [`misses`] (with the real
    /// accelerations, which only widens it in the linear prediction mode) without branches,
    /// so that it vectorizes; conservative in every degenerate case (a NaN or infinite bound
    /// keeps the pair). Ball `i` must be moving: a resting ball is at rest from its segment's
    /// start. The verdicts go to `clearance`, positive for pairs that cannot touch (a
    /// separate argument, so the compiler knows it overlaps none of the columns read).
    pub fn cull_row(&self, clearance: &mut [f64], i: BallId, t: f64, contact: f64) {
        if self.accelerating == 0 {
            return self.cull_row_straight(clearance, i, t, contact);
        }
        let ti = t - self.start[i];
        let (vxi, vyi) = (self.vx[i] + self.ax[i] * ti, self.vy[i] + self.ay[i] * ti);
        let (pxi, pyi) = (
            self.px[i] + (self.vx[i] + self.ax[i] * (0.5 * ti)) * ti,
            self.py[i] + (self.vy[i] + self.ay[i] * (0.5 * ti)) * ti,
        );
        let (axi, ayi, ui) = (self.ax[i], self.ay[i], self.until[i]);
        let rows = self.start.iter().zip(self.px.iter().zip(&self.py));
        let rows = rows.zip(self.vx.iter().zip(&self.vy));
        let rows = rows.zip(self.ax.iter().zip(&self.ay).zip(&self.until));
        for (clear, (((start, (px, py)), (vx, vy)), ((ax, ay), until))) in
            clearance.iter_mut().zip(rows)
        {
            let tj = t - start;
            let (vxj, vyj) = (vx + ax * tj, vy + ay * tj);
            let (pxj, pyj) = (
                px + (vx + ax * (0.5 * tj)) * tj,
                py + (vy + ay * (0.5 * tj)) * tj,
            );
            let (dpx, dpy, dvx, dvy) = (pxj - pxi, pyj - pyi, vxj - vxi, vyj - vyi);
            let (dax, day) = (ax - axi, ay - ayi);
            // Plain selects rather than `f64::min`/`max` (no NaN fix-ups in the vector code):
            // a NaN closest time (no relative motion) becomes `h`, still a valid time.
            let h = if *until < ui { *until } else { ui } - t;
            let pv = dpx * dvx + dpy * dvy;
            let vv = dvx * dvx + dvy * dvy;
            let tau = -pv / vv;
            let tau = if tau < h { tau } else { h };
            let tau = if tau > 0.0 { tau } else { 0.0 };
            let (cx, cy) = (dpx + dvx * tau, dpy + dvy * tau);
            let bend = 0.5 * (dax * dax + day * day).sqrt() * h * h;
            let reach = miss_reach(contact, bend);
            // (With h < 0, tau is 0 and a touching pair is kept.)
            *clear = cx * cx + cy * cy - (reach * reach + MISS_ROUNDING * (dpx * dpx + dpy * dpy));
        }
    }

    /// [`PathColumns::cull_row`] when no ball accelerates: the same test without the
    /// acceleration terms (each is a zero, and `bend` is `0 h h`: zero, or NaN for an
    /// unbounded horizon, which keeps the pair as the general cull does).
    fn cull_row_straight(&self, clearance: &mut [f64], i: BallId, t: f64, contact: f64) {
        let ti = t - self.start[i];
        let (vxi, vyi) = (self.vx[i], self.vy[i]);
        let (pxi, pyi) = (self.px[i] + vxi * ti, self.py[i] + vyi * ti);
        let ui = self.until[i];
        // `reach` of the general cull with `bend` zero, squared, once for the row.
        let reach = miss_reach(contact, 0.0);
        let reach2 = reach * reach;
        let rows = self.start.iter().zip(self.px.iter().zip(&self.py));
        let rows = rows.zip(self.vx.iter().zip(&self.vy)).zip(&self.until);
        for (clear, (((start, (px, py)), (vx, vy)), until)) in clearance.iter_mut().zip(rows) {
            let tj = t - start;
            let (dpx, dpy) = (px + vx * tj - pxi, py + vy * tj - pyi);
            let (dvx, dvy) = (vx - vxi, vy - vyi);
            let h = if *until < ui { *until } else { ui } - t;
            let pv = dpx * dvx + dpy * dvy;
            let vv = dvx * dvx + dvy * dvy;
            let tau = -pv / vv;
            let tau = if tau < h { tau } else { h };
            let tau = if tau > 0.0 { tau } else { 0.0 };
            let (cx, cy) = (dpx + dvx * tau, dpy + dvy * tau);
            // NaN for an unbounded horizon (keeps the pair, as `0 h h` does in the general
            // cull); zero otherwise, leaving `reach2` as it is.
            let unbounded = 0.0 * h;
            *clear = cx * cx + cy * cy
                - ((reach2 + unbounded) + MISS_ROUNDING * (dpx * dpx + dpy * dpy));
        }
    }
}

/// The verdict of [`PathColumns::cull_row`] on one pair: may it touch? (A NaN clearance
/// keeps the pair.)
#[inline]
pub(crate) fn kept(clearance: f64) -> bool {
    clearance.is_nan() || clearance <= 0.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::{BallState, Motion};
    use crate::detect::{Kinematics, ball_ball_kept};
    use crate::math::Vec3;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    const RADIUS: f64 = 0.028575;

    /// A random moving or resting ball within a metre of the origin at `t`, its segment
    /// started before `t`: decelerating along its velocity (the paper's model), curving
    /// (a spinning ball), or with no acceleration at all (`straight_only`).
    fn random_segment(rng: &mut ChaCha8Rng, t: f64, straight_only: bool) -> Segment {
        let start = t - rng.random_range(0.0..0.5);
        let p = Vec2::new(rng.random_range(-1.0..1.0), rng.random_range(-0.5..0.5));
        if rng.random_bool(0.2) {
            return Segment::at_rest(start, p, Motion::Stationary);
        }
        let v = Vec2::from_angle(rng.random_range(0.0..std::f64::consts::TAU))
            * rng.random_range(0.0..4.0);
        let a = if straight_only {
            Vec2::ZERO
        } else if rng.random_bool(0.5) {
            -v.normalized().unwrap_or(Vec2::ZERO) * rng.random_range(0.0..2.0)
        } else {
            Vec2::new(rng.random_range(-2.0..2.0), rng.random_range(-2.0..2.0))
        };
        let state = BallState {
            position: p,
            velocity: v,
            motion: Motion::Sliding,
            ..BallState::default()
        };
        Segment::new(start, state, a, Vec3::ZERO, None)
    }

    /// Runs the row cull over random scenes and checks every verdict against [`misses`] on
    /// the same pair and against the contact quartic: a pair the row cull rejects is rejected
    /// by `misses` and has no contact within the horizon; and `misses` rejects no pair the
    /// row cull keeps (the two are the same test).
    fn row_cull_agrees_with_misses(straight_only: bool, seed: u64) -> (usize, usize) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let contact = 2.0 * RADIUS;
        let (n, t) = (24, 3.0);
        let (mut rejected, mut pairs) = (0, 0);
        for _ in 0..300 {
            let segments: Vec<Segment> = (0..n)
                .map(|_| random_segment(&mut rng, t, straight_only))
                .collect();
            let until: Vec<f64> = (0..n).map(|_| t + rng.random_range(0.0..0.6)).collect();
            let mut columns = PathColumns::new(n);
            for (id, seg) in segments.iter().enumerate() {
                columns.set(id, seg, until[id]);
            }
            let mut clearance = vec![0.0; n];
            for i in (0..n).filter(|&i| columns.moving_on_table(i)) {
                columns.cull_row(&mut clearance, i, t, contact);
                for j in (0..n).filter(|&j| j != i) {
                    let (a, b) = (&segments[i], &segments[j]);
                    let h = until[i].min(until[j]) - t;
                    let dp = b.position_at(t) - a.position_at(t);
                    let dv = b.velocity_at(t) - a.velocity_at(t);
                    let da = b.acceleration - a.acceleration;
                    let single = misses(dp, dv, da, contact, h);
                    let row = !kept(clearance[j]);
                    assert_eq!(row, single, "pair {i}, {j}: row cull against misses");
                    if row {
                        let root = ball_ball_kept(a, b, t, RADIUS, h, Kinematics::Exact);
                        assert_eq!(root, None, "pair {i}, {j} culled with a contact");
                        rejected += 1;
                    }
                    pairs += 1;
                }
            }
        }
        (rejected, pairs)
    }

    #[test]
    fn the_row_cull_rejects_exactly_the_pairs_misses_rejects() {
        let (rejected, pairs) = row_cull_agrees_with_misses(false, 1);
        // Both verdicts occur, so the comparison means something.
        assert!(
            rejected > pairs / 4 && rejected < pairs,
            "{rejected} of {pairs}"
        );
    }

    #[test]
    fn the_straight_row_cull_rejects_exactly_the_pairs_misses_rejects() {
        let (rejected, pairs) = row_cull_agrees_with_misses(true, 2);
        assert!(
            rejected > pairs / 4 && rejected < pairs,
            "{rejected} of {pairs}"
        );
    }

    /// Passing a resting ball at distances across the margins, 1e-11 m apart: both culls
    /// flip at the same distance (a margin changed in one of them moves its flip).
    #[test]
    fn both_culls_flip_at_the_same_distance_within_the_margins() {
        let contact = 2.0 * RADIUS;
        for accel in [0.0, 0.3] {
            let mut flips = 0;
            let mut last = None;
            for k in -400..400 {
                // The contact distance plus what the acceleration can close in the horizon.
                let d = contact + 0.5 * accel + f64::from(k) * 1e-11;
                let mover = BallState {
                    velocity: Vec2::new(1.0, 0.0),
                    motion: Motion::Sliding,
                    ..BallState::default()
                };
                let a = Vec2::new(0.0, accel);
                let segments = [
                    Segment::new(0.0, mover, a, Vec3::ZERO, None),
                    Segment::at_rest(0.0, Vec2::new(0.5, d), Motion::Stationary),
                ];
                let mut columns = PathColumns::new(2);
                columns.set(0, &segments[0], 1.0);
                columns.set(1, &segments[1], f64::INFINITY);
                let mut clearance = [0.0; 2];
                columns.cull_row(&mut clearance, 0, 0.0, contact);
                let (dp, dv) = (Vec2::new(0.5, d), Vec2::new(-1.0, 0.0));
                let single = misses(dp, dv, -a, contact, 1.0);
                assert_eq!(
                    !kept(clearance[1]),
                    single,
                    "distance {d}, acceleration {accel}"
                );
                flips += usize::from(last.is_some_and(|l| l != single));
                last = Some(single);
            }
            // The sweep crosses the margins exactly once.
            assert_eq!(flips, 1, "acceleration {accel}");
        }
    }

    #[test]
    fn an_unbounded_horizon_culls_nothing() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let segments: Vec<Segment> = (0..8)
            .map(|_| random_segment(&mut rng, 1.0, false))
            .collect();
        let mut columns = PathColumns::new(8);
        for (id, seg) in segments.iter().enumerate() {
            columns.set(id, seg, f64::INFINITY);
        }
        let mut clearance = vec![0.0; 8];
        for i in (0..8).filter(|&i| columns.moving_on_table(i)) {
            columns.cull_row(&mut clearance, i, 1.0, 2.0 * RADIUS);
            assert!(clearance.iter().all(|&c| kept(c)), "{clearance:?}");
        }
    }
}
