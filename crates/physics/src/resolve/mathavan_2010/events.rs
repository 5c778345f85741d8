//! The events of the Mathavan 2010 integration (compression ends, restitution ends, a slip
//! reaches zero, a stuck contact lets go): their functions, their location on a step's dense
//! output, and what each does.

use super::contact::{Event, Grip, State, hypot, unit};
use super::{Impact, Plan, bs3};

impl Impact {
    /// Event function `e` at state `t`: positive until the event.
    pub(super) fn g(&self, e: Event, t: &State, u0: &[[f64; 2]; 2]) -> f64 {
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
                let (f, nn) = setup.friction_fixed(t, self.gi, self.gc, self.dirs);
                if nose {
                    setup.mu_w - hypot([f[0], f[1]])
                } else {
                    setup.mu_s * nn - hypot([f[2], f[3]])
                }
            }
        }
    }

    pub(super) fn tol_of(&self, e: Event) -> f64 {
        match e {
            Event::Restituted => self.tol_w,
            Event::LetsGo(_) => 1e-13,
            _ => self.setup.tol,
        }
    }

    /// Where in a step event `e` happens, as a fraction of the step, if it does: its
    /// function changed sign, located by the Illinois variant of regula falsi on the step's
    /// dense output.
    pub(super) fn locate(&self, e: Event, plan: &Plan, st: &bs3::Step) -> Option<f64> {
        let u0 = &plan.u0;
        // The phase ends (checked every step) without the call into `g`: the same numbers.
        let (g0, g1) = match e {
            Event::Compressed => (self.y[1], st.y[1]),
            Event::Restituted => {
                let wf = self.target.unwrap_or(0.0);
                (self.y[5] - wf, st.y[5] - wf)
            }
            _ => (self.g(e, &self.y, u0), self.g(e, &st.y, u0)),
        };
        let tol = self.tol_of(e);
        if g0 <= tol || g1 > tol {
            return None; // not approaching from above, or not reached in this step
        }
        if g1 >= -tol {
            return Some(1.0);
        }
        let (mut lo, mut glo, mut hi, mut ghi) = (0.0, g0, 1.0, g1);
        let (mut side, mut at) = (0, 1.0);
        for _ in 0..100 {
            at = (lo * ghi - hi * glo) / (ghi - glo);
            if !(at > lo && at < hi) {
                at = 0.5 * (lo + hi);
            }
            let ga = match e {
                Event::Compressed => st.at_one(1, at),
                Event::Restituted => st.at_one(5, at) - self.target.unwrap_or(0.0),
                _ => self.g(e, &st.at(at), u0),
            };
            if ga.abs() <= tol || hi - lo <= 1e-15 {
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

    /// The earliest event inside step `st` of `plan` (the aimed zero slip `aimed` among them),
    /// where in the step it happens, and how many events the step holds.
    pub(super) fn first_event(
        &self,
        plan: &Plan,
        st: &bs3::Step,
        aimed: Option<Event>,
    ) -> (Option<Event>, f64, usize) {
        let (mut hit, mut theta, mut found) = (None, 1.0, 0);
        // The phase's end, then the stuck contacts' let-goes and the aimed zero, in turn (an
        // event found no earlier than one before it does not replace it). Plain calls:
        // chained iterator adapters cost 0.6 % of the break, a loop over the four 0.3 %.
        let mut consider = |e: Event| {
            if let Some(at) = self.locate(e, plan, st) {
                found += 1;
                if hit.is_none() || at < theta {
                    (hit, theta) = (Some(e), at);
                }
            }
        };
        consider(plan.phase);
        if let Some(e) = plan.lets_go[0] {
            consider(e);
        }
        if let Some(e) = plan.lets_go[1] {
            consider(e);
        }
        if let Some(e) = aimed {
            consider(e);
        }
        (hit, theta, found)
    }

    /// What an event does: the phase changes, or a contact's grip.
    pub(super) fn apply(&mut self, hit: Option<Event>) {
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
                if (nose && matches!(self.gi, Grip::Stick))
                    || (!nose && matches!(self.gc, Grip::Stick))
                {
                    setup.snap(&mut self.y, nose);
                }
            }
            Some(Event::LetsGo(nose)) => {
                // Past its cone: friction keeps its direction, opposing what sticking needed.
                let (f, _) = setup.friction_fixed(&self.y, self.gi, self.gc, self.dirs);
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
