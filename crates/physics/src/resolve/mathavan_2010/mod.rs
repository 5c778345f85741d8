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
//! Integrator: the embedded Runge–Kutta pair 3(2) of Bogacki & Shampine in `P` (`bs3.rs`),
//! each step's local error held to [`Accuracy::tol`] of the incoming speed (the error control
//! of Hairer, Nørsett & Wanner, section II.4, with Gustafsson's PI step size control). Between
//! events the rates change only as the sliding directions turn, so where they do not turn a
//! step spans the whole phase. Events (compression ends, restitution ends, a stuck contact
//! lets go) are found on the pair's dense output. Near a zero slip the direction turns at
//! 7/2 mu / |slip| per unit impulse: steps stay within the explicit method's stability there
//! (`limits.rs`), a slip heading for zero is met by one step along its direction once what
//! that neglects is within the tolerance, and a slip within the tolerance of zero keeps its
//! grip's direction. A slip that leaves zero slowly (its direction stiff: relaxing far faster
//! than it grows) is slaved to the direction it grows in, solved from the contacts' affine
//! rates (`slaved.rs`), while the friction impulse that misdirects stays within half the
//! tolerance. Compression's end changes no rate, so a step that contains it goes on past it.
//! At the default 7e-5 a step (safety factor 0.8) the result differs from a reference at 1e-9
//! a step and steps of 1e-3 of the impulse by at most 1.4e-4 of the incoming speed over 3,000
//! random impacts (99 % within 7.3e-5), and from one with 100 times smaller steps by at most
//! 5.5e-5 over 38 test shots (a test pins 2e-4) and 7.2e-5 over the 18 cushion impacts of a
//! 9-ball break (`examples/mathavan_probe.rs`); it agrees with the paper's own explicit Euler
//! scheme at 200,000 steps within 2e-4.
//! pooltool's `mathavan_2010` (explicit Euler, fixed `delta_p`, the same equations) is the
//! comparison implementation.

mod bs3;
mod contact;
mod events;
mod limits;
mod slaved;
#[cfg(test)]
mod tests;

use crate::math::{Vec2, Vec3};
use contact::{Dir, Event, Grip, Setup, State, hypot, unit};

/// Most steps one impact may take before the result is given up for Han's impulse.
const MAX_STEPS: usize = 100_000;

/// The step size control's safety factor: the step proposed from an error estimate aims at
/// this fraction of the step that estimate allows (Hairer, Norsett & Wanner, section II.4).
/// At 0.8 and 7e-5 a step the results are closer to the fine reference than at 0.9 and 5e-5,
/// in as many rate evaluations (docs/realism.md, Cost).
const SAFETY: f64 = 0.8;

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

/// How closely an impact is integrated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accuracy {
    /// Largest local error of a step, relative to the incoming speed `|v| + R |w|` (on the
    /// velocities and the spins' surface speeds `R w`).
    pub tol: f64,
    /// Longest step, as a fraction of the expected impulse `(1 + e) v_y / cos theta`.
    pub max_step: f64,
}

impl Accuracy {
    /// The game's: 7e-5 a step, steps as long as the error allows (within 1.4e-4 of the
    /// incoming speed of a fine reference over 3,000 random impacts, 99 % within 7.3e-5: see
    /// the module). A seventh of a millimetre a second at 1 m/s, against the 2.6 % the model
    /// stands from the measured rebound (docs/realism.md); finer tolerances cost rate
    /// evaluations, which issue 37 bounds (a break at most 1.5 times a Han break).
    pub const DEFAULT: Self = Self {
        tol: 7e-5,
        max_step: 1.0,
    };
}

/// What an integration cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Steps kept.
    pub steps: usize,
    /// Steps tried and thrown away (too large an error, or a slip turned past zero).
    pub rejected: usize,
    /// Evaluations of the rates.
    pub evaluations: usize,
    /// The longest step kept, as a fraction of the expected impulse.
    pub longest: f64,
    /// Steps kept with a contact slaved to the direction its slip grows in.
    pub slaved: usize,
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
    /// The expected impulse (the span of a frictionless impact).
    span: f64,
    /// Absolute tolerance on velocities (m/s) and the longest step.
    atol: f64,
    max_h: f64,
    /// The incoming speed `|v| + R |w|`.
    scale: f64,
    /// The step the error control proposes next (infinite before the first).
    h: f64,
    /// The rate at `y` for the current grips, if known (the last step's last stage).
    d: Option<State>,
    stats: Stats,
    /// Where each contact's friction takes its direction from (slaved or its slip's).
    dirs: [Dir; 2],
    /// A bound on the friction impulse (per unit mass) misdirected so far by slaving.
    lag: f64,
    /// The slaved direction at the last plan, and the longest slaved step from there.
    slaved_at: Option<([f64; 2], f64)>,
    /// How fast the slaved contact's growth rate `lambda` changed per unit impulse over the
    /// last step (its Newton iterations start from the extrapolation).
    slope: f64,
    /// The last step kept.
    last_h: f64,
    /// The error of the last step kept, to the power 1/8 (the step size control's memory).
    err_old: f64,
    /// The longest step kept (`Stats::longest` times the span).
    longest: f64,
}

/// The step planned from the current state.
struct Plan {
    h: f64,
    /// The zero slip the step is meant to end on (its contact held to its direction).
    predicted: Option<Event>,
    /// The contacts' sliding directions at the step's start.
    u0: [[f64; 2]; 2],
    /// The events located inside a step (a slip's zero is met by the plan instead): the
    /// phase's end, and a stuck nose's and cloth contact's let-go.
    phase: Event,
    lets_go: [Option<Event>; 2],
    /// The rate at the step's start (the first stage).
    d: State,
    /// The slips `(x_I, y'_I, x_C, y_C)` at the step's start and their rates there.
    z0: [f64; 4],
    dz1: [f64; 4],
    /// The step planned before a zero slip shortened it, should that step fail.
    h_free: f64,
}

impl Impact {
    fn new(y: State, m: &Mathavan2010, radius: f64, scale: f64, acc: Accuracy) -> Self {
        let s = (m.height / radius - 1.0).clamp(-1.0, 1.0);
        let c = (1.0 - s * s).sqrt();
        let setup = Setup {
            s,
            c,
            r: radius,
            k: 2.5 / radius,
            mu_w: m.mu_cushion,
            mu_s: m.mu_table,
            tol: 1e-12 * scale,
            zero: (acc.tol * scale).max(1e-12 * scale),
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
        let max_h = span * acc.max_step.clamp(1e-9, 1.0);
        Self {
            setup,
            y,
            gi,
            gc,
            target: None,
            tol_w: 0.0,
            e: m.e,
            span,
            atol: acc.tol.max(1e-15) * scale,
            max_h,
            scale: scale.max(f64::MIN_POSITIVE),
            h: f64::INFINITY,
            d: None,
            stats: Stats::default(),
            dirs: [Dir::Own; 2],
            lag: 0.0,
            slaved_at: None,
            slope: 0.0,
            last_h: 0.0,
            err_old: 0.1f64.sqrt(),
            longest: 0.0,
        }
    }

    /// Ends compression at the current state.
    fn compressed(&mut self) {
        self.target = Some((1.0 - self.e * self.e) * self.y[5]);
        self.tol_w = 1e-14 * self.y[5];
    }

    /// Runs to the end of restitution; `None` past the step cap.
    fn run(mut self) -> Option<(State, Stats)> {
        for _ in 0..MAX_STEPS {
            // Phase ends reached on the way to another event.
            if self.target.is_none() && self.y[1] <= self.setup.tol {
                self.compressed();
            }
            if self.target.is_some_and(|wf| self.y[5] - wf <= self.tol_w) {
                let stats = Stats {
                    longest: self.longest / self.span,
                    ..self.stats
                };
                return Some((self.y, stats));
            }
            let plan = self.plan();
            let (hit, next) = self.take(&plan);
            self.y = next;
            self.apply(hit);
        }
        None
    }

    /// The grips made consistent and the next step planned: the error control's proposal,
    /// shortened before a slip's zero and by the stiffness near one, or ending on the zero.
    fn plan(&mut self) -> Plan {
        let setup = self.setup;
        let y = self.y;
        if matches!(self.gi, Grip::Stick) || matches!(self.gc, Grip::Stick) {
            let settled = setup.settle(&y, self.gi, self.gc);
            if settled != (self.gi, self.gc) {
                (self.gi, self.gc) = settled;
                self.d = None;
            }
        }
        let (mut si, mut sc) = setup.slips(&self.y);
        let mut sizes = [hypot(si), hypot(sc)];
        let near = |l: f64| l > setup.tol && l <= setup.zero;
        if near(sizes[0]) || near(sizes[1]) {
            self.snap_zero_slips();
            (si, sc) = setup.slips(&self.y);
            sizes = [hypot(si), hypot(sc)];
        }
        let y = self.y;
        // Sliding directions at the step's start (a slip's own direction, or the one kept
        // within `zero`).
        let along = |sl: [f64; 2], size: f64, g: Grip| match g {
            Grip::Slide(d) if size <= setup.zero => d,
            Grip::Slide(_) => {
                let inv = 1.0 / size;
                [sl[0] * inv, sl[1] * inv]
            }
            Grip::Stick => [0.0, 0.0],
        };
        let u0 = [along(si, sizes[0], self.gi), along(sc, sizes[1], self.gc)];
        if let Grip::Slide(_) = self.gi {
            self.gi = Grip::Slide(u0[0]);
        }
        if let Grip::Slide(_) = self.gc {
            self.gc = Grip::Slide(u0[1]);
        }
        self.slave(sizes, u0);
        let (gi, gc) = (self.gi, self.gc);
        let phase = if self.target.is_none() {
            Event::Compressed
        } else {
            Event::Restituted
        };
        let lets_go =
            |nose: bool, grip: Grip| matches!(grip, Grip::Stick).then_some(Event::LetsGo(nose));
        let lets_go = [lets_go(true, gi), lets_go(false, gc)];
        // The rate here, with the grips' directions (a contact held to its kept direction
        // has that direction here): the first stage of every step tried from here.
        let d = match self.d {
            Some(d) => d,
            None => {
                self.stats.evaluations += 1;
                setup.rate_fixed(&y, gi, gc, self.dirs)
            }
        };
        let (ri, rc) = setup.slip_rates_of(&d);
        let (mut h, finals) = self.limits(sizes, [ri, rc], &d, u0);
        let h_free = h;
        let mut predicted = None;
        for (k, reach) in finals.into_iter().enumerate() {
            if let Some(reach) = reach
                && predicted.is_none_or(|_| reach < h)
            {
                h = reach;
                predicted = Some(Event::SlipZero(k == 0));
            }
        }
        Plan {
            h,
            h_free,
            predicted,
            u0,
            phase,
            lets_go,
            d,
            z0: [si[0], si[1], sc[0], sc[1]],
            dz1: [ri[0], ri[1], rc[0], rc[1]],
        }
    }

    /// Whether a sliding slip (above zero) turned by more than 0.5 rad from its start
    /// direction: it passed close by zero inside the step.
    fn turned(&self, t: &State, predicted: Option<Event>, plan: &Plan) -> bool {
        let (a, b) = self.setup.slips(t);
        let z2 = self.setup.zero * self.setup.zero;
        let turned = |sl: [f64; 2], g: Grip, k: usize| {
            let u = plan.u0[k];
            // cos(angle) < 0.8776 (0.5 rad) against the start, squared: no square root.
            let (dot, l2) = (sl[0] * u[0] + sl[1] * u[1], sl[0] * sl[0] + sl[1] * sl[1]);
            matches!(g, Grip::Slide(_))
                && matches!(self.dirs[k], Dir::Own)
                && !matches!(predicted, Some(Event::SlipZero(nose)) if nose == (k == 0))
                && l2 > z2
                && (dot < 0.0 || dot * dot < 0.8776 * 0.8776 * l2)
        };
        turned(a, self.gi, 0) || turned(b, self.gc, 1)
    }

    /// The local error estimate relative to the tolerance (1: at the tolerance).
    fn error(&self, err: &State) -> f64 {
        let r = self.setup.r;
        let v = err[0].abs().max(err[1].abs());
        let w = r * err[2].abs().max(err[3].abs()).max(err[4].abs());
        // The work is about speed x speed: its error over the speed.
        let work = err[5].abs() / self.scale;
        // max(v, w) / atol unless the work's error is the larger: the one division need
        // not wait on the other (the same quotient to the bit).
        let top = v.max(w);
        if work <= top {
            top / self.atol
        } else {
            top.max(work) / self.atol
        }
    }

    /// Takes the planned step, shortened while its error is above the tolerance or a slip
    /// turns past its zero, then cut back to the earliest event inside it (located on the
    /// step's dense output); returns that event.
    fn take(&mut self, plan: &Plan) -> (Option<Event>, State) {
        let (mut h, mut predicted) = (plan.h, plan.predicted);
        let setup = self.setup;
        let (gi, gc) = (self.gi, self.gc);
        let floor = 1e-12 * self.span;
        let mut rejected = false;
        // Assigned in place (a step is some 500 bytes: moving it out of the loop copies it).
        let mut dirs;
        let mut st;
        loop {
            dirs = self.dirs;
            if let Some(Event::SlipZero(nose)) = predicted {
                dirs[usize::from(!nose)] = Dir::Held;
            }
            st = match (gi, gc, dirs) {
                (Grip::Slide(di), Grip::Slide(dc), [Dir::Own, Dir::Own]) => bs3::step_split(
                    &self.y,
                    &plan.d,
                    h,
                    plan.z0,
                    plan.dz1,
                    #[inline(always)]
                    |z| setup.slip_rates_sliding(z, di, dc),
                    #[inline(always)]
                    |f, t| setup.rate_of_friction(f, t),
                ),
                _ => match dirs {
                    [Dir::Slaved(l), _] | [_, Dir::Slaved(l)] => {
                        self.slaved_step(plan, h, l, (gi, gc), dirs)
                    }
                    _ => bs3::step(&self.y, &plan.d, h, |t| setup.rate_fixed(t, gi, gc, dirs)),
                },
            };
            self.stats.evaluations += bs3::EVALS;
            let err = self.error(&st.err);
            let turned = self.turned(&st.y, predicted, plan);
            if (err <= 1.0 && !turned) || h <= floor {
                self.stats.steps += 1;
                // (The longest step's fraction at the end: division by the positive span is
                // monotone, so the largest quotient is the largest step's, to the bit.)
                self.longest = self.longest.max(h);
                self.last_h = h;
                if !matches!(self.dirs, [Dir::Own, Dir::Own]) {
                    self.stats.slaved += 1;
                }
                if predicted.is_none() {
                    // Step size control with memory (Gustafsson's PI control, Hairer & Wanner,
                    // Solving ODEs II, section IV.2): the next step from this one's error and
                    // the last's, err^(-0.7/3) err_old^(0.4/3) for the pair's 2nd-order
                    // estimate, here err^(-1/4) err_old^(1/8) (square roots: `powf` took 12 %
                    // of an impact), within a factor 0.2 to 5, no larger after a rejection.
                    let e = err.max(1e-12);
                    let e4 = e.sqrt().sqrt();
                    let fac = (SAFETY * self.err_old / e4).clamp(0.2, 5.0);
                    // max(e, 1e-4)^(1/8) from e^(1/4): a correctly rounded square root is
                    // monotone, so it commutes with `max` to the bit.
                    self.err_old = e4.max(1e-4f64.sqrt().sqrt()).sqrt();
                    self.h = if rejected { h * fac.min(1.0) } else { h * fac };
                }
                break;
            }
            self.stats.rejected += 1;
            rejected = true;
            if predicted.is_some() {
                h = plan.h_free;
            } else {
                h *= if turned {
                    0.5
                } else {
                    (SAFETY / err.cbrt()).clamp(0.1, 0.5)
                };
            }
            predicted = None;
        }
        // A step meant to end on a zero slip finds it like the other events: its rate along
        // the held direction need not stay constant (the other contact turns).
        let aimed = predicted.filter(|e| matches!(e, Event::SlipZero(_)));
        let (hit, theta, found) = self.first_event(plan, &st, aimed);
        // Compression's end changes no rate (it only fixes the work restitution ends at, eq.
        // 16): the step goes on past it, its work there from the dense output, unless another
        // event or restitution's end falls within the step too.
        if matches!(hit, Some(Event::Compressed))
            && theta < 1.0
            && found == 1
            && predicted.is_none()
        {
            let wc = st.at_one(5, theta);
            let target = (1.0 - self.e * self.e) * wc;
            if st.y[5] - target > 1e-14 * wc {
                (self.target, self.tol_w) = (Some(target), 1e-14 * wc);
                self.d = Some(st.k4); // (no direction held: `predicted` is none)
                return (None, st.y);
            }
        }
        // At an event inside the step, the state from the dense output (3rd order, within
        // the step's tolerance: a step to it would cost three more evaluations).
        let next = if hit.is_some() && theta < 1.0 {
            st.at(theta)
        } else {
            st.y
        };
        // The last stage is the next step's first unless an event changes the rates.
        // (A step aimed at a zero slip held its direction: `dirs` differs from `self.dirs`.)
        self.d = (hit.is_none() && predicted.is_none()).then_some(st.k4);
        (hit, next)
    }
}

impl Impact {
    /// A step with a slaved contact (`dirs`, its growth rate `lambda` at the step's start):
    /// each stage's Newton iteration for the slaved direction starts from `lambda`
    /// extrapolated linearly through the last two known (the last step's slope, then the
    /// stages': stages at 1/2, 3/4 and 1 of the step, in turn), some two iterations fewer a
    /// stage than from `lambda` itself, which grows quickly as a slip leaves zero.
    fn slaved_step(
        &self,
        plan: &Plan,
        h: f64,
        lambda: f64,
        (gi, gc): (Grip, Grip),
        dirs: [Dir; 2],
    ) -> bs3::Step {
        let setup = self.setup;
        let k = usize::from(!matches!(dirs[0], Dir::Slaved(_)));
        // (fraction of the step, lambda there, d lambda / d fraction), and the stages so far.
        let known = std::cell::Cell::new((0.0, lambda, self.slope * h));
        let stage = std::cell::Cell::new(0usize);
        bs3::step(&self.y, &plan.d, h, |t| {
            let at = bs3::STAGES[stage.get().min(bs3::STAGES.len() - 1)];
            stage.set(stage.get() + 1);
            let (t0, l0, slope) = known.get();
            let guess = l0 + slope * (at - t0);
            let mut d = dirs;
            d[k] = Dir::Slaved(if guess > 0.0 { guess } else { l0 });
            let (rate, l) = setup.rate_slaved(t, gi, gc, d);
            if l > 0.0 {
                known.set((at, l, (l - l0) / (at - t0)));
            }
            rate
        })
    }
}

/// Velocity and spin after a cushion impact by [`Mathavan2010`], with unit inward normal `n`,
/// integrated to `acc`, and what that cost. Returns `None` if the ball is not moving into the
/// cushion or the integration did not finish within its step cap.
pub fn mathavan_2010_with(
    v: Vec2,
    w: Vec3,
    n: Vec2,
    m: &Mathavan2010,
    radius: f64,
    acc: Accuracy,
) -> Option<(Vec2, Vec3, Stats)> {
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
    let (y, stats) = Impact::new(y, m, radius, scale, acc).run()?;
    let (v2, w2) = (
        ex * y[0] + ey * y[1].min(0.0),
        (ex * y[2] + ey * y[3]).extend() + Vec3::new(0.0, 0.0, y[4]),
    );
    // The model dissipates (friction, e <= 1), so a rise in kinetic energy is integration
    // error (within the tolerance): scaled back onto the incoming energy, which keeps the
    // rebound's direction and its ratio of spin to speed.
    let energy = |v: Vec2, w: Vec3| v.length_squared() + 0.4 * radius * radius * w.dot(w);
    let (before, after) = (energy(v, w), energy(v2, w2));
    let k = if after > before {
        (before / after).sqrt()
    } else {
        1.0
    };
    Some((v2 * k, w2 * k, stats))
}

/// [`mathavan_2010_with`] at [`Accuracy::DEFAULT`]; if the integration does not finish within
/// its step cap (never seen), Han's impulse with the same constants answers instead.
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
    mathavan_2010_with(v, w, n, m, radius, Accuracy::DEFAULT)
        .map(|(v, w, _)| (v, w))
        .or_else(|| super::ball_cushion::han_2005(v, w, n, m.e, m.mu_cushion, radius, m.height))
}
