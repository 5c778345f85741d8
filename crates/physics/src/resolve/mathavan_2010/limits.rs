//! What bounds a step of the Mathavan 2010 integration besides its error: slips near zero,
//! whose sliding direction turns at a rate 1 / |slip|.

use super::Impact;
use super::bs3::STABLE;
use super::contact::{Dir, Grip, State, hypot};

impl Impact {
    /// A sliding slip within the tolerance of zero is zero: moved into the spins (a change
    /// within the tolerance) and its grip decided again, stuck or sliding the way it then
    /// grows; its own direction would turn too fast to follow. Not without friction, where a
    /// slip does nothing and the spins must stay as they are.
    pub(super) fn snap_zero_slips(&mut self) {
        let setup = self.setup;
        for nose in [true, false] {
            let (si, sc) = setup.slips(&self.y);
            let (sl, grip, other) = if nose {
                (si, self.gi, self.gc)
            } else {
                (sc, self.gc, self.gi)
            };
            let size = hypot(sl);
            let mu = if nose { setup.mu_w } else { setup.mu_s };
            let free = matches!(self.dirs[usize::from(!nose)], Dir::Own);
            if matches!(grip, Grip::Slide(_))
                && free
                && mu > 0.0
                && size > setup.tol
                && size <= setup.zero
            {
                setup.snap(&mut self.y, nose);
                let grip = setup.grip_at_zero(&self.y, nose, other);
                if nose {
                    self.gi = grip;
                } else {
                    self.gc = grip;
                }
                self.d = None;
            }
        }
    }

    /// The longest step the sliding contacts allow, from the slips' sizes `sl`, their rates `r`, the
    /// state's rate `d` (the table's normal from it, where the cloth's slip needs it) and the
    /// sliding directions `u0`; and for each slip heading for zero close enough to be met in
    /// one step, the impulse to its zero.
    pub(super) fn limits(
        &self,
        sl: [f64; 2],
        r: [[f64; 2]; 2],
        d: &State,
        u0: [[f64; 2]; 2],
    ) -> (f64, [Option<f64>; 2]) {
        let setup = &self.setup;
        let grips = [self.gi, self.gc];
        let mut h = self.h.min(self.max_h);
        if let Some((_, cap)) = self.slaved_at {
            h = h.min(cap);
        }
        let mut finals: [Option<f64>; 2] = [None; 2];
        for k in 0..2 {
            let size = sl[k];
            if self.h.is_infinite() && matches!(grips[k], Grip::Slide(_)) && size <= setup.zero {
                // The first step from a slip leaving zero (a rolling ball's cloth contact): its
                // friction turns as the slip grows, which the error, not the rule below, sees;
                // at 0.3 of the impulse the break's impacts no longer reject their first
                // step (at the whole impulse 13 of 18 did, their error 1 to 4 times the
                // tolerance at about half of it).
                h = h.min(0.3 * self.span);
            }
            if !matches!(grips[k], Grip::Slide(_))
                || size <= setup.zero
                || !matches!(self.dirs[k], Dir::Own)
            {
                continue;
            }
            // (The table's normal only here: two divisions a plan otherwise.)
            let mu = if k == 0 {
                setup.mu_w
            } else {
                setup.mu_s * setup.normal_of(d)
            };
            let (u, r) = (u0[k], r[k]);
            let along = r[0] * u[0] + r[1] * u[1];
            // (Its square root only where needed: not for a growing slip after the first step.)
            let across = || hypot([r[0] - along * u[0], r[1] - along * u[1]]);
            if self.h.is_infinite() {
                // The first step: one that turns no slip by more than 0.1 rad.
                h = h.min(0.1 * size / across().max(f64::MIN_POSITIVE));
            }
            // Across the slip friction relaxes its direction at 7/2 mu / |slip| per unit
            // impulse; an explicit step is stable while that, integrated over the step,
            // stays below the method's bound (`STABLE`).
            let stiff = 3.5 * mu.max(f64::MIN_POSITIVE);
            if along >= 0.0 {
                // A slip growing at `along` relaxes ever more slowly: the integral is
                // (stiff / along) ln(1 + along h / |slip|), so h may reach |slip| / along
                // (exp(x) - 1), x = STABLE along / stiff; its cubic bounds that from below.
                // (The bound is at least `STABLE size / stiff` (x >= 0, rounding monotone):
                // a step within that need not wait on the divisions of the cubic.)
                let floor = STABLE * size / stiff;
                if h > floor || h.is_nan() {
                    let x = STABLE * along / stiff;
                    h = h.min(floor * (1.0 + x * (0.5 + x / 6.0)));
                }
                continue;
            }
            // A slip heading for zero is met in one step along its start direction once what
            // that step neglects is within the tolerance: the part of its rate across it
            // leaves a residue (which the snap at the zero moves into the spins), and the
            // friction's direction, however it would turn, changes the velocities by at most
            // 2 mu x the step. Until then it is approached in steps of at most half the
            // remaining reach.
            let reach = size / -along;
            if (across() * reach * (1.0 + mu / -along)).min(2.0 * mu * reach) <= self.atol {
                finals[k] = Some(reach);
            } else {
                h = h.min(0.5 * reach).min(STABLE * size / stiff);
            }
        }
        (h, finals)
    }

    /// Slaves a sliding contact to the direction its slip grows in (`slaved.rs`) while its
    /// direction's relaxation, not the error, bounds the step and the friction impulse the
    /// slaving misdirects stays within half the tolerance; frees it otherwise. `sl`: the
    /// slips' sizes, `u0` their sliding directions.
    ///
    /// The bound: slaved, the friction's direction lags the true one by at most
    /// `|S| |dphi*/dP| / kappa`, so a step misdirects at most `mu |S| |dphi*| / kappa` of
    /// impulse (`dphi*`: how far `u*` turned over it); freed, the slip's direction (which
    /// followed `u*` on average) relaxes to the true one within `|S| / kappa`, misdirecting at
    /// most `mu |S / |S| - u*| |S| / kappa`. Both are charged to `lag`, which may not exceed
    /// half the tolerance over the impact.
    pub(super) fn slave(&mut self, sl: [f64; 2], u0: [[f64; 2]; 2]) {
        let setup = self.setup;
        let grips = [self.gi, self.gc];
        let budget = 0.5 * self.atol;
        for k in 0..2 {
            let other = 1 - k;
            let (size, mu) = (sl[k], [setup.mu_w, setup.mu_s][k]);
            if !matches!(grips[k], Grip::Slide(_))
                || !matches!(self.dirs[other], Dir::Own)
                || mu <= 0.0
            {
                self.free(k);
                continue;
            }
            // From the last plan's growth rate, extrapolated over the last step.
            let start = match self.dirs[k] {
                Dir::Slaved(l) if l + self.slope * self.last_h > 0.0 => {
                    l + self.slope * self.last_h
                }
                Dir::Slaved(l) => l,
                // Not worth a look unless its relaxation (about 7/2 mu / |S|) would bound the
                // step well below the error's.
                _ if STABLE * size.max(setup.zero) > 0.5 * 3.5 * mu * self.h.min(self.max_h) => {
                    continue;
                }
                _ => 0.0,
            };
            let Some((u, lambda, kappa)) = setup.slaved(
                k == 0,
                u0[other],
                matches!(grips[other], Grip::Stick),
                start,
            ) else {
                self.free(k);
                continue;
            };
            // Its friction's part of the table's normal for the cloth (N ~ 1 suffices for a
            // bound: N = s - c b <= s + c mu_w).
            let mu = if k == 0 {
                mu
            } else {
                mu * (setup.s + setup.c * setup.mu_w)
            };
            // (A slip within `zero` has its grip's direction, and may be that far off it.)
            let off = hypot([u0[k][0] - u[0], u0[k][1] - u[1]]);
            let exit = mu * off * size.max(setup.zero) / kappa;
            // The explicit step its relaxation allows (as in `limits`), against the step the
            // error would allow.
            let x = STABLE * lambda / kappa;
            let stable = STABLE * size.max(setup.zero) / kappa * (1.0 + x * (0.5 + x / 6.0));
            // (A slip growing fast relaxes ever more slowly: explicit steps then grow fast.)
            let stiff = x < 1.0 && stable < self.h.min(self.max_h);
            // The longest slaved step: at most 4 times the last, and short enough that the
            // lag over it and the freeing after it stay within the budget, with u* turning
            // as it did over the last step: both are about mu (dphi*/dP) |S|_end^2 / (lambda
            // kappa) (the slip's direction averages u* over the |S| / lambda it grew in).
            let cap = |rate: f64, last: f64, lag: f64| {
                let rem = (budget - lag).max(0.0);
                let end = (rem * kappa * lambda / (1.5 * mu * rate.max(1e-300))).sqrt();
                ((end - size) / lambda).max(0.0).min(4.0 * last)
            };
            let keep = match (self.dirs[k], self.slaved_at) {
                (Dir::Slaved(_), Some((before, _))) if self.last_h > 0.0 => {
                    let turned = hypot([u[0] - before[0], u[1] - before[1]]);
                    self.lag += mu * size * turned / kappa;
                    let h = cap(turned / self.last_h, self.last_h, self.lag);
                    (stiff && h > stable && self.lag + exit <= budget).then_some(h)
                }
                (Dir::Slaved(_), _) => None,
                // Entered off the slow manifold, the transient to it is neglected: it
                // misdirects at most `exit`, charged at once (and the first step is short).
                _ => (stiff && self.lag + 2.0 * exit <= budget).then(|| {
                    self.lag += exit;
                    self.d = None;
                    4.0 * stable
                }),
            };
            self.slope = match self.dirs[k] {
                Dir::Slaved(l) if self.last_h > 0.0 => (lambda - l) / self.last_h,
                _ => 0.0,
            };
            match keep {
                Some(h) => {
                    self.dirs[k] = Dir::Slaved(lambda);
                    self.slaved_at = Some((u, h));
                }
                None => {
                    if !matches!(self.dirs[k], Dir::Own) {
                        self.lag += exit;
                    }
                    self.free(k);
                }
            }
        }
    }

    /// Frees contact `k` from slaving.
    fn free(&mut self, k: usize) {
        if !matches!(self.dirs[k], Dir::Own) {
            self.dirs[k] = Dir::Own;
            self.slaved_at = None;
            self.d = None;
        }
    }
}
