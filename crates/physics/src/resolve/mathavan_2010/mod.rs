//! Mathavan, Jackson & Parkin (2010), "A theoretical analysis of billiard ball dynamics under
//! cushion impacts", Proc. IMechE C 224, pp. 1863–1873: the ball's velocities during the
//! impact, integrated over the normal impulse at the cushion nose, with Coulomb friction at
//! the nose (I) and at the cloth (C) and the impact ended by an energetic restitution.
//!
//! Frame (the paper's Fig. 2): X along the cushion, Y into it, Z up; the nose touches the ball
//! at angle `theta` above its centre (`sin theta = h/R - 1`). Per unit mass, with the friction
//! at I `f = (a, b)` along `(X, Y')` and at C `(p, q)` along `(X, Y)`, each per unit normal
//! impulse `P` at I, the table's normal impulse is `N = sin theta - b cos theta` (no vertical
//! motion) and (eqs. 14, 17, written for any friction within the cones):
//!
//! ```text
//! dvx/dP = a + p               dwx/dP = 5/(2R) (b + q)
//! dvy/dP = -cos - b sin + q    dwy/dP = 5/(2R) (a sin - p)
//!                              dwz/dP = -5/(2R) a cos
//! ```
//!
//! Sliding friction is `-mu_w (cos phi, sin phi)` at I and `-mu_s N (cos phi', sin phi')` at
//! C against the slips of eqs. 12–13, which is the paper's eq. 17 exactly. Where a slip
//! reaches zero the contact sticks if the friction needed to hold it lies in its cone (the
//! paper's eq. 15 drops the friction instead, which its fixed step then chatters around).
//! Compression ends at `vy = 0` with work `Wc = int cos vy dP`; restitution ends when the work
//! has fallen to `(1 - e^2) Wc` (eq. 16).
//!
//! Integrator: classical 4th-order Runge–Kutta in `P`. A step is at most 8/[`STEPS`] of the
//! expected impulse and turns no sliding direction by more than 2/[`STEPS`] rad (with fixed
//! directions the rates are constant, so only turning costs accuracy), unless that would make
//! it shorter than 1/100 of a nominal step; it is cut short by a
//! Newton estimate so that it ends on every event (a slip reaching zero, the end of
//! compression, the end of restitution), stick ends are found by regula falsi, and near a
//! zero slip, where friction turns the slip's direction at 7/2 mu / |slip|, steps stay below
//! half of that. Against 100 times finer steps (`steps` x 100) the result differs by at most
//! 1.8e-6 of the incoming speed over 38 test shots (a test pins 1e-5); it agrees with the
//! paper's own explicit Euler scheme at 200,000 steps within 2e-4.
//! pooltool's `mathavan_2010` (explicit Euler, fixed `delta_p`, the same equations) is the
//! comparison implementation.

mod contact;
#[cfg(test)]
mod tests;

use crate::math::{Vec2, Vec3};
use contact::{Event, Grip, Setup, State, hypot, unit};

/// Nominal Runge–Kutta steps per impact (more are taken at events and near zero slip).
pub const STEPS: usize = 64;

/// Most steps one impact may take before the result is given up for Han's impulse.
const MAX_STEPS: usize = 200_000;

/// The constants of the model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mathavan2010 {
    /// Energetic restitution at the nose (the paper's fit: 0.98).
    pub e: f64,
    /// Sliding friction ball–cushion, `mu_w` (the paper's fit: 0.14).
    pub mu_cushion: f64,
    /// Sliding friction ball–cloth during the impact, `mu_s` (the paper: 0.212).
    pub mu_table: f64,
    /// Height of the nose above the cloth, metres (the paper: 7R/5).
    pub height: f64,
}
/// One impact being integrated: the state in the cushion's frame (X along it, Y into it),
/// the grips of the two contacts and the phase.
struct Impact {
    setup: Setup,
    y: State,
    gi: Grip,
    gc: Grip,
    /// Restitution's final work, once compression has ended.
    target: Option<f64>,
    /// Tolerance of the work, set relative to the compression's.
    tol_w: f64,
    e: f64,
    h_nominal: f64,
    /// Largest turn of a sliding direction in one step, radians (2 / steps).
    turn: f64,
    span: f64,
}

/// The step planned from the current state.
struct Plan {
    h: f64,
    /// The event the step is meant to end on.
    predicted: Option<Event>,
    /// The contacts' sliding directions at the step's start.
    u0: [[f64; 2]; 2],
    /// The events watched in this step.
    events: [Event; 3],
    /// The rate at the step's start (Runge–Kutta's first stage, computed once a step).
    d: State,
}

impl Impact {
    fn new(y: State, m: &Mathavan2010, radius: f64, scale: f64, steps: usize) -> Self {
        let s = (m.height / radius - 1.0).clamp(-1.0, 1.0);
        let c = (1.0 - s * s).sqrt();
        let setup = Setup {
            s,
            c,
            r: radius,
            mu_w: m.mu_cushion,
            mu_s: m.mu_table,
            tol: 1e-12 * scale,
        };
        let span = (1.0 + m.e) * y[1] / c.max(1e-3);
        // Grips at the start: a contact without slip sticks or picks its direction.
        let (si, sc) = setup.slips(&y);
        let mut gi = Grip::Slide(unit(si, [1.0, 0.0]));
        let mut gc = Grip::Slide(unit(sc, [1.0, 0.0]));
        for nose in [true, false, true] {
            let (si, sc) = setup.slips(&y);
            if nose && hypot(si) <= setup.tol {
                gi = setup.grip_at_zero(&y, true, gc);
            } else if !nose && hypot(sc) <= setup.tol {
                gc = setup.grip_at_zero(&y, false, gi);
            }
        }
        Self {
            setup,
            y,
            gi,
            gc,
            target: None,
            tol_w: 0.0,
            e: m.e,
            h_nominal: span / steps.max(1) as f64,
            turn: 2.0 / steps.max(1) as f64,
            span,
        }
    }

    /// Ends compression at the current state.
    fn compressed(&mut self) {
        self.target = Some((1.0 - self.e * self.e) * self.y[5]);
        self.tol_w = 1e-14 * self.y[5];
    }

    /// Runs to the end of restitution; `None` past the step cap.
    fn run(mut self) -> Option<State> {
        for _ in 0..MAX_STEPS {
            // Phase ends reached on the way to another event.
            if self.target.is_none() && self.y[1] <= self.setup.tol {
                self.compressed();
            }
            if self.target.is_some_and(|wf| self.y[5] - wf <= self.tol_w) {
                return Some(self.y);
            }
            let plan = self.plan();
            let (hit, next) = self.take(&plan);
            self.y = next;
            self.apply(hit);
        }
        None
    }

    /// Event function `e` at state `t`: positive until the event.
    fn g(&self, e: Event, t: &State, u0: &[[f64; 2]; 2]) -> f64 {
        let setup = &self.setup;
        match e {
            Event::Compressed => t[1],
            Event::Restituted => t[5] - self.target.unwrap_or(0.0),
            Event::SlipZero(nose) => {
                let (a, b) = setup.slips(t);
                let (sl, u) = if nose { (a, u0[0]) } else { (b, u0[1]) };
                sl[0] * u[0] + sl[1] * u[1]
            }
            Event::LetsGo(nose) => {
                let (f, nn) = setup.friction(t, self.gi, self.gc);
                if nose {
                    setup.mu_w - hypot([f[0], f[1]])
                } else {
                    setup.mu_s * nn - hypot([f[2], f[3]])
                }
            }
        }
    }

    fn tol_of(&self, e: Event) -> f64 {
        match e {
            Event::Restituted => self.tol_w,
            Event::LetsGo(_) => 1e-13,
            _ => self.setup.tol,
        }
    }

    /// The grips made consistent and the next step planned: nominal, shortened by Newton's
    /// estimate of each approaching event and by the stiffness near a zero slip.
    fn plan(&mut self) -> Plan {
        let setup = self.setup;
        let y = self.y;
        if self.gi == Grip::Stick || self.gc == Grip::Stick {
            (self.gi, self.gc) = setup.settle(&y, self.gi, self.gc);
        }
        let (si, sc) = setup.slips(&y);
        // Sliding directions at the step's start (a slip's own direction, or the one kept).
        let u0 = [setup.direction(si, self.gi), setup.direction(sc, self.gc)];
        if let Grip::Slide(_) = self.gi {
            self.gi = Grip::Slide(u0[0]);
        }
        if let Grip::Slide(_) = self.gc {
            self.gc = Grip::Slide(u0[1]);
        }
        let (gi, gc, h_nominal) = (self.gi, self.gc, self.h_nominal);
        let contact = |nose: bool, grip: Grip| match grip {
            Grip::Slide(_) => Event::SlipZero(nose),
            Grip::Stick => Event::LetsGo(nose),
        };
        let phase = if self.target.is_none() {
            Event::Compressed
        } else {
            Event::Restituted
        };
        let events = [phase, contact(true, gi), contact(false, gc)];
        // The rate here, with the grips' directions: also the first stage of every step tried
        // from here (a contact held to its kept direction has that direction here).
        let (d, nn) = setup.rate_and_normal(&y, gi, gc, [false; 2]);
        let (ri, rc) = setup.slip_rates_of(&d);
        // Near zero slip the sliding direction turns fast: across the slip, friction relaxes
        // it at about 7/2 mu / |slip| per unit impulse, so a step stays below half of that
        // (explicit Runge–Kutta is stable below 2.8), and a slip growing from zero starts
        // with a step of 1e-6 of the nominal one. Steps never fall below 1e-6 of a nominal
        // one, where a slip's turning costs nothing measurable.
        let mut stiff = [f64::INFINITY; 2];
        for (k, (sl, grip, mu)) in [(si, gi, setup.mu_w), (sc, gc, setup.mu_s * nn)]
            .into_iter()
            .enumerate()
        {
            if let Grip::Slide(_) = grip {
                stiff[k] = if hypot(sl) > setup.tol {
                    (0.5 * hypot(sl) / (3.5 * mu).max(f64::MIN_POSITIVE)).max(1e-6 * h_nominal)
                } else {
                    1e-6 * h_nominal
                };
            }
        }
        // Newton's estimate of the step to each approaching event. A slip is approached in
        // steps of 0.9 of it while it may still turn (a slip that cannot stick curves past
        // zero), and met in one last step along its start direction (exempt from its own
        // stiffness limit) once that is 1e-3 of a nominal step away.
        let (mut h_events, mut predicted, mut finals) = (f64::INFINITY, None, [None; 2]);
        for &e in &events {
            let (value, rate) = match e {
                Event::Compressed => (y[1], d[1]),
                Event::Restituted => (self.g(e, &y, &u0), d[5]),
                Event::SlipZero(nose) => {
                    let (r, u) = if nose { (ri, u0[0]) } else { (rc, u0[1]) };
                    (self.g(e, &y, &u0), r[0] * u[0] + r[1] * u[1])
                }
                Event::LetsGo(_) => continue,
            };
            if value <= self.tol_of(e) || rate >= 0.0 {
                continue;
            }
            let reach = value / -rate;
            match e {
                Event::SlipZero(nose) if reach <= 1e-3 * h_nominal => {
                    finals[usize::from(!nose)] = Some((nose, reach));
                }
                Event::SlipZero(_) => h_events = h_events.min(0.9 * reach),
                _ if reach < h_events => {
                    h_events = reach;
                    predicted = Some(e);
                }
                _ => {}
            }
        }
        // Between events the rates change only as the sliding directions turn (with fixed
        // directions they are constant and a step of any length is exact), so a step may be
        // 8 nominal ones long as long as no slip turns by more than 2 / steps rad in it.
        // Never below 1/100 of a nominal step: near zero slip the stiffness limit governs.
        let mut h_max = 8.0 * h_nominal;
        for (sl, r, grip) in [(si, ri, gi), (sc, rc, gc)] {
            let size = hypot(sl);
            if matches!(grip, Grip::Slide(_)) && size > setup.tol {
                let u = [sl[0] / size, sl[1] / size];
                let along = r[0] * u[0] + r[1] * u[1];
                let across = hypot([r[0] - along * u[0], r[1] - along * u[1]]);
                if across > 0.0 {
                    h_max = h_max.min((self.turn * size / across).max(1e-2 * h_nominal));
                }
            }
        }
        let mut h = h_max.min(h_events);
        if h < h_events || stiff[0].min(stiff[1]) < h {
            predicted = None;
        }
        h = h.min(stiff[0]).min(stiff[1]);
        for (nose, reach) in finals.into_iter().flatten() {
            let cap = h_max.min(h_events).min(stiff[usize::from(nose)]);
            let best = matches!(predicted, Some(Event::SlipZero(_))).then_some(h);
            if reach < cap && best.is_none_or(|b| reach < b) {
                h = reach;
                predicted = Some(Event::SlipZero(nose));
            }
        }
        Plan {
            h,
            predicted,
            u0,
            events,
            d,
        }
    }

    /// One Runge–Kutta step of `h` from the plan's start, the slip it is meant to end on held
    /// to its direction.
    fn step(&self, plan: &Plan, h: f64, predicted: Option<Event>) -> State {
        let mut fixed = [false; 2];
        match predicted {
            Some(Event::SlipZero(true)) => fixed[0] = true,
            Some(Event::SlipZero(false)) => fixed[1] = true,
            _ => {}
        }
        self.setup
            .rk4(&self.y, &plan.d, h, (self.gi, self.gc), fixed)
    }

    /// Whether a sliding slip turned by more than 0.5 rad from its start direction.
    fn turned(&self, t: &State, predicted: Option<Event>, u0: &[[f64; 2]; 2]) -> bool {
        let (a, b) = self.setup.slips(t);
        [(a, self.gi, u0[0], true), (b, self.gc, u0[1], false)]
            .iter()
            .any(|&(sl, g, u, nose)| {
                matches!(g, Grip::Slide(_))
                    && predicted != Some(Event::SlipZero(nose))
                    && hypot(sl) > self.setup.tol
                    && (sl[0] * u[0] + sl[1] * u[1]) < 0.8776 * hypot(sl)
            })
    }

    /// Takes the planned step, halved while a slip turns fast (passing close by zero without
    /// reaching it), then cut back to the earliest event inside it; returns that event.
    fn take(&self, plan: &Plan) -> (Option<Event>, State) {
        let (mut h, mut predicted) = (plan.h, plan.predicted);
        let mut next = self.step(plan, h, predicted);
        let mut halvings = 0;
        while self.turned(&next, predicted, &plan.u0) && halvings < 60 {
            h *= 0.5;
            predicted = None;
            next = self.step(plan, h, predicted);
            halvings += 1;
        }
        let (mut hit, mut h_hit) = (None, h);
        for &e in &plan.events {
            if let Event::SlipZero(_) = e {
                continue; // met by the planned approach
            }
            if let Some(at) = self.locate(e, plan, h, predicted, &next)
                && (hit.is_none() || at < h_hit)
            {
                (hit, h_hit) = (Some(e), at);
            }
        }
        if hit.is_some() && h_hit < h {
            next = self.step(plan, h_hit, predicted);
        } else if let Some(Event::SlipZero(_)) = predicted {
            hit = predicted;
        }
        (hit, next)
    }

    /// Where in a step of `h` ending at `next` event `e` happens, if it does: its function
    /// changed sign, located by the Illinois variant of regula falsi on the step length.
    fn locate(
        &self,
        e: Event,
        plan: &Plan,
        h: f64,
        predicted: Option<Event>,
        next: &State,
    ) -> Option<f64> {
        let u0 = &plan.u0;
        let (g0, g1, tol) = (self.g(e, &self.y, u0), self.g(e, next, u0), self.tol_of(e));
        if g0 <= tol || g1 > tol {
            return None; // not approaching from above, or not reached in this step
        }
        if g1 >= -tol {
            return Some(h);
        }
        let (mut lo, mut glo, mut hi, mut ghi) = (0.0, g0, h, g1);
        let (mut side, mut at) = (0, h);
        for _ in 0..100 {
            at = (lo * ghi - hi * glo) / (ghi - glo);
            if !(at > lo && at < hi) {
                at = 0.5 * (lo + hi);
            }
            let ga = self.g(e, &self.step(plan, at, predicted), u0);
            if ga.abs() <= tol || hi - lo <= 1e-15 * self.span {
                break;
            }
            if ga > 0.0 {
                (lo, glo) = (at, ga);
                if side == 1 {
                    ghi *= 0.5;
                }
                side = 1;
            } else {
                (hi, ghi) = (at, ga);
                if side == -1 {
                    glo *= 0.5;
                }
                side = -1;
            }
        }
        Some(at)
    }

    /// What an event does: the phase changes, or a contact's grip.
    fn apply(&mut self, hit: Option<Event>) {
        let setup = self.setup;
        match hit {
            None | Some(Event::Restituted) => {} // the end is checked at the loop's top
            Some(Event::Compressed) => self.compressed(),
            Some(Event::SlipZero(nose)) => {
                let (y, gi, gc) = (self.y, self.gi, self.gc);
                if nose {
                    self.gi = setup.grip_at_zero(&y, true, gc);
                } else {
                    self.gc = setup.grip_at_zero(&y, false, gi);
                }
                if (nose && self.gi == Grip::Stick) || (!nose && self.gc == Grip::Stick) {
                    setup.snap(&mut self.y, nose);
                }
            }
            Some(Event::LetsGo(nose)) => {
                // Past its cone: friction keeps its direction, opposing what sticking needed.
                let (f, _) = setup.friction(&self.y, self.gi, self.gc);
                let need = if nose { [f[0], f[1]] } else { [f[2], f[3]] };
                let u = unit(need, [1.0, 0.0]);
                let grip = Grip::Slide([-u[0], -u[1]]);
                if nose {
                    self.gi = grip;
                } else {
                    self.gc = grip;
                }
            }
        }
    }
}

/// Velocity and spin after a cushion impact by [`Mathavan2010`], with unit inward normal `n`,
/// integrated with `steps` nominal Runge–Kutta steps (use [`STEPS`]). Returns `None` if the
/// ball is not moving into the cushion or the integration did not finish within its step cap.
pub fn mathavan_2010_steps(
    v: Vec2,
    w: Vec3,
    n: Vec2,
    m: &Mathavan2010,
    radius: f64,
    steps: usize,
) -> Option<(Vec2, Vec3)> {
    let ey = -n;
    let ex = -ey.perp();
    let y: State = [
        v.dot(ex),
        v.dot(ey),
        w.xy().dot(ex),
        w.xy().dot(ey),
        w.z,
        0.0,
    ];
    if y[1] <= 0.0 {
        return None;
    }
    let scale = v.length() + radius * w.length();
    let y = Impact::new(y, m, radius, scale, steps).run()?;
    Some((
        ex * y[0] + ey * y[1].min(0.0),
        (ex * y[2] + ey * y[3]).extend() + Vec3::new(0.0, 0.0, y[4]),
    ))
}

/// [`mathavan_2010_steps`] with [`STEPS`]; if the integration does not finish within its step
/// cap (never seen), Han's impulse with the same constants answers instead.
pub fn mathavan_2010(
    v: Vec2,
    w: Vec3,
    n: Vec2,
    m: &Mathavan2010,
    radius: f64,
) -> Option<(Vec2, Vec3)> {
    if v.dot(n) >= 0.0 {
        return None;
    }
    mathavan_2010_steps(v, w, n, m, radius, STEPS)
        .or_else(|| super::han_2005(v, w, n, m.e, m.mu_cushion, radius, m.height))
}
