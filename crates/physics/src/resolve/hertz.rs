//! Compliant contact of balls in a cluster: Hertz forces with a restitution-matched damping,
//! integrated over one impact of finite duration.
//!
//! A pair of balls pressed `d` into each other pushes with (Landau & Lifshitz, *Theory of
//! Elasticity*, section 9; Tsuji, Tanaka & Ishida, Powder Technology 71, 1992, for the damping)
//!
//! ```text
//! F = k d^1.5 + c d^0.25 dd/dt  (never pulling: F >= 0),
//! k = (4/3) E* sqrt(R/2),  1/E* = 2 (1 - nu^2) / E,  c = alpha sqrt(m* k),  m* = m/2.
//! ```
//!
//! With this damping the restitution of a pair does not depend on the impact speed (the
//! equation has no length scale once divided by `k d^1.5`), so `alpha` is found once for the
//! model's ball–ball restitution `e` ([`damping_for_restitution`]) and a pair in a cluster
//! rebounds with `e` at any speed, as an isolated pair does under the exact law.
//!
//! The impact is instantaneous for the event loop (the balls keep their positions, as under
//! every impulse law): [`impact`] integrates the balls' displacements `u` during the contact
//! along the pairs' fixed normals, from their gaps, so gaps that close within the contact make
//! the cluster respond as one body, and the velocities it returns leave every pair open and
//! not approaching along those normals.
//!
//! Each contact's friction on the slip of its contact points is a force in the same
//! equations ([`Tangential`], a regularised Coulomb law), so spins and throw come out of the
//! one integration, every contact's forces from one state ([`impact_with_friction`]).

use crate::math::{Vec2, Vec3};
use crate::params::{BallSpec, HertzContact};

mod dopri;
mod tangential;
use dopri::{DP_A, DP_E, combine};
pub use tangential::{SLIP_SCALE, Tangential};

/// An elastic Hertz impact at approach speed `v` lasts `HERTZ_TIME * d_max / v`, `d_max` its
/// largest compression (Landau & Lifshitz, section 9).
pub const HERTZ_TIME: f64 = 2.943_2;

/// The force law of two balls and what it implies for one impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hertz {
    /// Stiffness `k` of `F = k d^1.5`, N/m^1.5.
    pub stiffness: f64,
    /// Mass of one ball, kg.
    pub mass: f64,
    /// Dimensionless damping `alpha` (0: elastic).
    pub alpha: f64,
    /// Damping coefficient `c = alpha sqrt(m* k)`, N s/m^1.25.
    pub damping: f64,
}

impl Hertz {
    /// The contact of two balls of `ball` made of `material`, damped to restitution `e`.
    pub fn new(material: &HertzContact, ball: &BallSpec, e: f64) -> Self {
        let h = Self::elastic(material, ball);
        let alpha = damping_for_restitution(e);
        Self {
            alpha,
            damping: alpha * (0.5 * h.mass * h.stiffness).sqrt(),
            ..h
        }
    }

    /// The undamped contact (its [`Hertz::reach`] and [`Hertz::duration`] need no damping).
    pub fn elastic(material: &HertzContact, ball: &BallSpec) -> Self {
        let e_star = material.young / (2.0 * (1.0 - material.poisson * material.poisson));
        Self {
            stiffness: 4.0 / 3.0 * e_star * (0.5 * ball.radius).sqrt(),
            mass: ball.mass,
            alpha: 0.0,
            damping: 0.0,
        }
    }

    /// Largest compression of an elastic impact at approach speed `v`:
    /// `(5 m* v^2 / (4 k))^(2/5)`.
    pub fn max_compression(&self, v: f64) -> f64 {
        (1.25 * 0.5 * self.mass * v * v / self.stiffness).powf(0.4)
    }

    /// Duration of an elastic impact at approach speed `v`, seconds.
    pub fn duration(&self, v: f64) -> f64 {
        HERTZ_TIME * self.max_compression(v) / v.max(f64::MIN_POSITIVE)
    }

    /// The distance a pair approaching at `v` closes during one contact (`v` times
    /// [`Hertz::duration`]): balls closer than this to an impact take part in it.
    pub fn reach(&self, v: f64) -> f64 {
        HERTZ_TIME * self.max_compression(v)
    }

    /// Force between two balls compressed `d` (m) at compression rate `rate` (m/s).
    #[inline]
    fn force(&self, d: f64, rate: f64) -> f64 {
        if d <= 0.0 {
            return 0.0;
        }
        let q = d.sqrt(); // d^0.5
        (self.stiffness * d * q + self.damping * q.sqrt() * rate).max(0.0)
    }
}

/// The damping `alpha` that gives restitution `e` in `[0, 1]`, solved on the
/// dimensionless impact `x'' = -(x^1.5 + alpha x^0.25 x')`, `x(0) = 0`, `x'(0) = 1`, whose
/// exit speed is `e` (Tsuji et al. 1992 give the same relation as a fit). Memoised per thread.
pub fn damping_for_restitution(e: f64) -> f64 {
    use std::cell::RefCell;
    thread_local! {
        static MEMO: RefCell<Vec<(u64, f64)>> = const { RefCell::new(Vec::new()) };
    }
    let e = e.clamp(0.0, 1.0);
    if e >= 1.0 {
        return 0.0;
    }
    if let Some(a) = MEMO.with(|m| m.borrow().iter().find(|p| p.0 == e.to_bits()).map(|p| p.1)) {
        return a;
    }
    // e(alpha) falls from 1 at alpha = 0 to below 0.01 before alpha = 20: the Illinois
    // variant of regula falsi on that bracket (a dozen evaluations instead of bisection's 48).
    let f = |a: f64| dimensionless_restitution(a) - e;
    let (mut lo, mut hi) = (0.0, 20.0);
    let (mut flo, mut fhi) = (f(lo), f(hi));
    let mut side = 0;
    let mut alpha = 0.5 * (lo + hi);
    for _ in 0..60 {
        alpha = (lo * fhi - hi * flo) / (fhi - flo);
        let fa = f(alpha);
        if fa.abs() < 1e-13 || hi - lo < 1e-13 {
            break;
        }
        if fa > 0.0 {
            (lo, flo) = (alpha, fa);
            if side == 1 {
                fhi *= 0.5;
            }
            side = 1;
        } else {
            (hi, fhi) = (alpha, fa);
            if side == -1 {
                flo *= 0.5;
            }
            side = -1;
        }
    }
    MEMO.with(|m| {
        let mut m = m.borrow_mut();
        if m.len() >= 32 {
            m.remove(0);
        }
        m.push((e.to_bits(), alpha));
    });
    alpha
}

/// Exit speed of the dimensionless damped Hertz impact at entry speed 1 (classical RK4,
/// step 1e-3 of a contact lasting about 3.2; the exit is interpolated to the step).
pub fn dimensionless_restitution(alpha: f64) -> f64 {
    let acc = |x: f64, v: f64| {
        if x <= 0.0 {
            0.0
        } else {
            -(x * x.sqrt() + alpha * x.sqrt().sqrt() * v).max(0.0)
        }
    };
    let h = 1e-3;
    let (mut x, mut v) = (0.0f64, 1.0f64);
    for _ in 0..1_000_000 {
        let (k1x, k1v) = (v, acc(x, v));
        let (k2x, k2v) = (v + 0.5 * h * k1v, acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v));
        let (k3x, k3v) = (v + 0.5 * h * k2v, acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v));
        let (k4x, k4v) = (v + h * k3v, acc(x + h * k3x, v + h * k3v));
        x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        // Out of contact and separating, or pushing no more while separating: free flight.
        if v < 0.0 && (x <= 0.0 || acc(x, v) == 0.0) {
            return -v;
        }
    }
    0.0
}

/// A pair of balls in a cluster impact: local indices `a`, `b`, the unit normal from `a` to
/// `b` and their gap (m, negative if they overlap) when the impact starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Edge {
    /// First ball (index into the impact's velocities).
    pub a: usize,
    /// Second ball.
    pub b: usize,
    /// Unit normal from `a` to `b`.
    pub n: Vec2,
    /// Distance between the surfaces, m.
    pub gap: f64,
}

/// What one impact did to each pair and how the integration went.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Impact {
    /// Per edge, the normal impulse it carried (N s; 0 if it never closed).
    pub impulse: Vec<f64>,
    /// Per edge, when its contact began, seconds into the impact (infinite if never).
    pub onset: Vec<f64>,
    /// Accepted integration steps.
    pub steps: usize,
    /// Duration of the impact, seconds.
    pub duration: f64,
    /// Relative kinetic energy the integrator's error added and the rescaling removed (0 when
    /// the integrated energy did not rise).
    pub energy_trimmed: f64,
}

/// Relative error allowed per step (Dormand–Prince 5(4) estimate) on displacements, in units
/// of the largest compression, and on velocities, in units of the fastest approach. Against
/// an RK4 solution at 1/20000 of a contact (tests/cradle.rs) the balls of a 5-ball cradle
/// leave within 3e-5 of the approach speed, and an elastic one keeps its energy to 4e-6;
/// a frozen 15-ball break takes about 60 steps.
pub const TOLERANCE: f64 = 3e-7;

/// `sqrt(2/5)`: a spin error `dw` weighs as a velocity error `sqrt(2/5) R dw`, the speed
/// of the same kinetic energy (`I = 2/5 m R^2`).
const SPIN_ERROR: f64 = 0.632_455_532_033_675_9;

/// Largest number of accepted steps before an impact is cut short (it is then left as it
/// stands: momentum kept, energy not raised; the event loop meets any pair still approaching).
pub const MAX_STEPS: usize = 200_000;

/// Integrates one impact of a cluster of smooth balls: `velocities` (m/s, in the table
/// plane) change by the Hertz forces of `edges` alone ([`impact_with_friction`] without
/// friction and with no spin).
pub fn impact(hertz: &Hertz, velocities: &mut [Vec2], edges: &[Edge]) -> Impact {
    let mut spins = vec![Vec3::ZERO; velocities.len()];
    impact_with_friction(hertz, None, velocities, &mut spins, edges)
}

/// Integrates one impact of a cluster: `velocities` (m/s, in the table plane) and `spins`
/// (rad/s) change by the Hertz forces of `edges` and, with `friction`, by the contacts'
/// friction ([`Tangential`], its regularisation speed [`SLIP_SCALE`] times the fastest
/// approach), until every edge is open and no edge approaches. Every force of a stage comes
/// from that stage's one state, so the order of the balls and edges does not matter (to
/// rounding). Cloth friction is left out during the impact (a quarter of a millisecond; see
/// [`Tangential`]). The integrator is Dormand–Prince 5(4) with step control to
/// [`TOLERANCE`]; open stretches are crossed in one exact jump. Momentum is kept to rounding
/// (the drift of thousands of steps is shared back out); if the integrator's error raised the
/// kinetic energy (rotational included), the velocities relative to the centre of mass and
/// the spins are scaled down to the energy before, so it never rises.
pub fn impact_with_friction(
    hertz: &Hertz,
    friction: Option<(crate::resolve::friction::PairFriction, f64)>,
    velocities: &mut [Vec2],
    spins: &mut [Vec3],
    edges: &[Edge],
) -> Impact {
    assert_eq!(velocities.len(), spins.len(), "one spin a ball");
    let vmax = edges
        .iter()
        .map(|e| (velocities[e.a] - velocities[e.b]).dot(e.n))
        .fold(0.0f64, f64::max);
    let tangential = friction
        .filter(|(f, _)| f.constant > 0.0 || f.law != crate::params::BallFriction::Constant)
        .map(|(f, radius)| Tangential::new(f, radius, vmax));
    let chain = Chain {
        hertz,
        edges,
        n: velocities.len(),
        tangential,
    };
    let (n, m) = (chain.n, edges.len());
    let mut out = Impact {
        impulse: vec![0.0; m],
        onset: vec![f64::INFINITY; m],
        ..Impact::default()
    };
    if vmax.is_nan() || vmax <= 0.0 {
        return out;
    }
    let scales = (hertz.max_compression(vmax), vmax);
    let tref = hertz.duration(vmax);
    // State: displacements u (2n), velocities v (2n), spins w (3n), normal impulses J (m).
    let dim = 7 * n + m;
    let mut y = vec![0.0; dim];
    for (i, v) in velocities.iter().enumerate() {
        y[2 * n + 2 * i] = v.x;
        y[2 * n + 2 * i + 1] = v.y;
    }
    for (i, w) in spins.iter().enumerate() {
        y[4 * n + 3 * i] = w.x;
        y[4 * n + 3 * i + 1] = w.y;
        y[4 * n + 3 * i + 2] = w.z;
    }
    let mut k = vec![vec![0.0; dim]; 7];
    let mut tmp = vec![0.0; dim];
    let (mut t, mut h) = (0.0, tref / 50.0);
    chain.deriv(&y, &mut k[0]);
    while out.steps < MAX_STEPS {
        if !chain.pushing(&k[0]) {
            match chain.free_flight(&mut y, &mut k[0], 4.0 * tref) {
                Some(dt) => t += dt,
                None => break,
            }
            h = h.min(tref / 50.0);
        }
        let err = chain.step(&y, &mut k, &mut tmp, h, scales);
        if err <= 1.0 {
            t += h;
            out.steps += 1;
            y.copy_from_slice(&tmp);
            k.swap(0, 6);
            for (i, e) in edges.iter().enumerate() {
                if out.onset[i].is_infinite() && chain.compression(&y, e) > 0.0 {
                    out.onset[i] = t;
                }
            }
            // Done once nothing pushes and no pair approaches.
            let vs = &y[2 * n..4 * n];
            if !chain.pushing(&k[0]) && edges.iter().all(|e| chain.rate(vs, e) <= 0.0) {
                break;
            }
        }
        let grow = if err == 0.0 {
            5.0
        } else {
            (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
        };
        h = (h * grow).min(tref / 8.0);
    }
    out.impulse.copy_from_slice(&y[7 * n..]);
    out.duration = t;
    out.energy_trimmed = chain.finish(&y, &out.impulse, velocities, spins);
    out
}

/// The equations of one impact.
struct Chain<'a> {
    hertz: &'a Hertz,
    edges: &'a [Edge],
    /// Number of balls.
    n: usize,
    /// The contacts' friction (`None`: smooth balls, spins untouched).
    tangential: Option<Tangential>,
}

impl Chain<'_> {
    /// Compression of edge `e` in state `y` (m; negative while open).
    #[inline]
    fn compression(&self, y: &[f64], e: &Edge) -> f64 {
        (y[2 * e.a] - y[2 * e.b]) * e.n.x + (y[2 * e.a + 1] - y[2 * e.b + 1]) * e.n.y - e.gap
    }

    /// Rate of compression of edge `e` for velocities `v` (m/s; positive approaching).
    #[inline]
    fn rate(&self, v: &[f64], e: &Edge) -> f64 {
        (v[2 * e.a] - v[2 * e.b]) * e.n.x + (v[2 * e.a + 1] - v[2 * e.b + 1]) * e.n.y
    }

    /// Whether any edge pushes, from a derivative `dy` (its impulse rates are the forces).
    fn pushing(&self, dy: &[f64]) -> bool {
        dy[7 * self.n..].iter().any(|&f| f > 0.0)
    }

    /// The time derivative `dy` of state `y`.
    fn deriv(&self, y: &[f64], dy: &mut [f64]) {
        let n = self.n;
        let inv_m = 1.0 / self.hertz.mass;
        let (u, rest) = y.split_at(2 * n);
        let (v, rest) = rest.split_at(2 * n);
        let w = &rest[..3 * n];
        let (du, rest) = dy.split_at_mut(2 * n);
        let (dv, rest) = rest.split_at_mut(2 * n);
        let (dw, dj) = rest.split_at_mut(3 * n);
        du.copy_from_slice(v);
        dv.fill(0.0);
        dw.fill(0.0);
        // Per ball (x, y): one bounds check a ball, not one a component.
        let (u, v) = (u.as_chunks::<2>().0, v.as_chunks::<2>().0);
        let (w, dw) = (w.as_chunks::<3>().0, dw.as_chunks_mut::<3>().0);
        let dv = dv.as_chunks_mut::<2>().0;
        // Torque factor R / I = 5 / (2 m R) (I = 2/5 m R^2).
        let spin_of = self.tangential.map_or(0.0, |t| 2.5 * inv_m / t.radius);
        for (e, force) in self.edges.iter().zip(dj.iter_mut()) {
            let (ua, ub) = (u[e.a], u[e.b]);
            let d = (ua[0] - ub[0]) * e.n.x + (ua[1] - ub[1]) * e.n.y - e.gap;
            if d <= 0.0 {
                *force = 0.0;
                continue;
            }
            let (va, vb) = (v[e.a], v[e.b]);
            let rate = (va[0] - vb[0]) * e.n.x + (va[1] - vb[1]) * e.n.y;
            let f = self.hertz.force(d, rate);
            *force = f;
            if f > 0.0 {
                let (fx, fy) = (f * e.n.x * inv_m, f * e.n.y * inv_m);
                dv[e.a][0] -= fx;
                dv[e.a][1] -= fy;
                dv[e.b][0] += fx;
                dv[e.b][1] += fy;
                if let Some(law) = &self.tangential {
                    // Friction from this same state (tangential.rs): F_t along
                    // t = (-n_y, n_x), F_z vertical, on a; -F on b; the torque R n x F on both.
                    let (wa, wb) = (w[e.a], w[e.b]);
                    let ws = [wa[0] + wb[0], wa[1] + wb[1], wa[2] + wb[2]];
                    let dvab = [va[0] - vb[0], va[1] - vb[1]];
                    let (ft, fz) = law.force(f, law.slip([e.n.x, e.n.y], dvab, ws));
                    let (tx, ty) = (-e.n.y, e.n.x);
                    let (lx, ly) = (ft * tx * inv_m, ft * ty * inv_m);
                    dv[e.a][0] += lx;
                    dv[e.a][1] += ly;
                    dv[e.b][0] -= lx;
                    dv[e.b][1] -= ly;
                    // dw = 5 / (2 m R) (F_t z - F_z t), the same for both balls.
                    let dwv = [-fz * tx * spin_of, -fz * ty * spin_of, ft * spin_of];
                    for i in 0..3 {
                        dw[e.a][i] += dwv[i];
                        dw[e.b][i] += dwv[i];
                    }
                }
            }
        }
    }

    /// With no pair pushing, moves every ball at its constant velocity to the next closing
    /// (and a millionth of a contact time into it) and refreshes `dy`; the time jumped, or
    /// `None` once no pair approaches, or none closes within `horizon` seconds.
    fn free_flight(&self, y: &mut [f64], dy: &mut [f64], horizon: f64) -> Option<f64> {
        let n = self.n;
        let next = self
            .edges
            .iter()
            .filter_map(|e| {
                let r = self.rate(&y[2 * n..4 * n], e);
                (r > 0.0).then(|| (-self.compression(y, e)).max(0.0) / r)
            })
            .fold(f64::INFINITY, f64::min);
        if next.is_nan() || next >= horizon {
            return None;
        }
        let dt = next + 1e-6 * horizon;
        for i in 0..2 * n {
            y[i] += y[2 * n + i] * dt;
        }
        self.deriv(y, dy);
        self.pushing(dy).then_some(dt)
    }

    /// One Dormand–Prince step of size `h` from `y` (with `k[0]` its derivative) into `tmp`
    /// (and `k[6]` its derivative); the error relative to [`TOLERANCE`] of the displacement
    /// and velocity `scales`.
    fn step(
        &self,
        y: &[f64],
        k: &mut [Vec<f64>],
        tmp: &mut [f64],
        h: f64,
        scales: (f64, f64),
    ) -> f64 {
        for s in 1..7 {
            let (done, rest) = k.split_at_mut(s);
            let a = &DP_A[s - 1];
            let c = |j: usize| h * a[j];
            // Each stage in one pass, the terms added in the order the tableau gives them,
            // skipping zero ones, so every element is the same sum as term by term.
            macro_rules! stage {
                ($($j:expr),*) => { combine(tmp, y, [$(c($j)),*], [$(&done[$j][..]),*]) };
            }
            // Row 6 has a zero in column 1 (the fifth-order weights).
            match s {
                1 => stage!(0),
                2 => stage!(0, 1),
                3 => stage!(0, 1, 2),
                4 => stage!(0, 1, 2, 3),
                5 => stage!(0, 1, 2, 3, 4),
                _ => stage!(0, 2, 3, 4, 5),
            }
            self.deriv(tmp, &mut rest[0]);
        }
        // The error estimate, element by element in the weights' order (zero ones skipped).
        let m = 4 * self.n;
        let w = [DP_E[0], DP_E[2], DP_E[3], DP_E[4], DP_E[5], DP_E[6]];
        let ks = [&k[0], &k[2], &k[3], &k[4], &k[5], &k[6]];
        let error = |i: usize| {
            let mut e = 0.0;
            for (w, kj) in w.iter().zip(ks) {
                e += w * kj[i];
            }
            e.abs()
        };
        let worst = |r: std::ops::Range<usize>| r.map(error).fold(0.0f64, f64::max);
        let (eu, mut ev) = (worst(0..2 * self.n), worst(2 * self.n..m));
        if let Some(t) = &self.tangential {
            // A spin's error as the speed of the same kinetic energy, sqrt(2/5) R w.
            ev = ev.max(SPIN_ERROR * t.radius * worst(m..7 * self.n));
        }
        (h / TOLERANCE) * (eu / scales.0).max(ev / scales.1)
    }

    /// Writes the impact's end velocities and spins into `velocities` and `spins` (those
    /// before), after sharing out the momentum drift and trimming any gain of kinetic energy
    /// (`sum m v^2 / 2 + I w^2 / 2`, `I = 2/5 m R^2`) among the balls that were pushed;
    /// returns the relative energy trimmed.
    fn finish(
        &self,
        y: &[f64],
        impulse: &[f64],
        velocities: &mut [Vec2],
        spins: &mut [Vec3],
    ) -> f64 {
        let n = self.n;
        let mut v1: Vec<Vec2> = (0..n)
            .map(|i| Vec2::new(y[2 * n + 2 * i], y[2 * n + 2 * i + 1]))
            .collect();
        let mut w1: Vec<Vec3> = (0..n)
            .map(|i| Vec3::new(y[4 * n + 3 * i], y[4 * n + 3 * i + 1], y[4 * n + 3 * i + 2]))
            .collect();
        let mut moved = vec![false; n];
        for (e, &j) in self.edges.iter().zip(impulse) {
            if j > 0.0 {
                moved[e.a] = true;
                moved[e.b] = true;
            }
        }
        let count = moved.iter().filter(|&&m| m).count().max(1) as f64;
        let total = |v: &[Vec2]| {
            (0..n)
                .filter(|&i| moved[i])
                .fold(Vec2::ZERO, |s, i| s + v[i])
        };
        let drift = (total(&v1) - total(velocities)) * (1.0 / count);
        for i in (0..n).filter(|&i| moved[i]) {
            v1[i] -= drift;
        }
        // Twice the kinetic energy over m: v^2 + (2/5) R^2 w^2.
        let rot = self.tangential.map_or(0.0, |t| 0.4 * t.radius * t.radius);
        let ke = |v: &[Vec2], w: &[Vec3]| {
            (0..n)
                .filter(|&i| moved[i])
                .map(|i| v[i].length_squared() + rot * w[i].dot(w[i]))
                .sum::<f64>()
        };
        let (ke0, ke1) = (ke(velocities, spins), ke(&v1, &w1));
        let mut trimmed = 0.0;
        if ke1 > ke0 {
            // Scaling the velocities about their mean and the spins by s keeps the momentum:
            // the energy is count vc^2 + s^2 (ke1 - count vc^2).
            let vc = total(&v1) * (1.0 / count);
            let kc = count * vc.length_squared();
            let s = ((ke0 - kc).max(0.0) / (ke1 - kc)).sqrt() * (1.0 - 4.0 * f64::EPSILON);
            for i in (0..n).filter(|&i| moved[i]) {
                v1[i] = vc + (v1[i] - vc) * s;
                if rot > 0.0 {
                    w1[i] = w1[i] * s;
                }
            }
            trimmed = (ke1 - ke0) / ke0;
        }
        velocities.copy_from_slice(&v1);
        if self.tangential.is_some() {
            spins.copy_from_slice(&w1);
        }
        trimmed
    }
}

#[cfg(test)]
mod tests;
