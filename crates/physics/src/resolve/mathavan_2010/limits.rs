//! What bounds a step of the Mathavan 2010 integration besides its error: slips near zero,
//! whose sliding direction turns at a rate 1 / |slip|.

use super::Impact;
use super::contact::{Grip, hypot};

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
            if matches!(grip, Grip::Slide(_)) && mu > 0.0 && size > setup.tol && size <= setup.zero
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

    /// The longest step the sliding contacts allow, from the slips `sl`, their rates `r`, the
    /// table's normal `nn` and the sliding directions `u0`; and for each slip heading for
    /// zero close enough to be met in one step, the impulse to its zero.
    pub(super) fn limits(
        &self,
        sl: [[f64; 2]; 2],
        r: [[f64; 2]; 2],
        nn: f64,
        u0: [[f64; 2]; 2],
    ) -> (f64, [Option<f64>; 2]) {
        let setup = &self.setup;
        let grips = [self.gi, self.gc];
        let mus = [setup.mu_w, setup.mu_s * nn];
        let mut h = self.h.min(self.max_h);
        let mut finals: [Option<f64>; 2] = [None; 2];
        for k in 0..2 {
            let size = hypot(sl[k]);
            if !matches!(grips[k], Grip::Slide(_)) || size <= setup.zero {
                continue;
            }
            let (u, r, mu) = (u0[k], r[k], mus[k]);
            let along = r[0] * u[0] + r[1] * u[1];
            let across = hypot([r[0] - along * u[0], r[1] - along * u[1]]);
            if self.h.is_infinite() {
                // The first step: one that turns no slip by more than 0.1 rad.
                h = h.min(0.1 * size / across.max(f64::MIN_POSITIVE));
            }
            // Across the slip friction relaxes its direction at 7/2 mu / |slip| per unit
            // impulse; an explicit step is stable while that, integrated over the step,
            // stays below about 3 (here 2.5).
            let stiff = 3.5 * mu.max(f64::MIN_POSITIVE);
            if along >= 0.0 {
                // A slip growing at `along` relaxes ever more slowly: the integral is
                // (stiff / along) ln(1 + along h / |slip|), so h may reach |slip| / along
                // (exp(x) - 1), x = 2.5 along / stiff; its cubic bounds that from below.
                let x = 2.5 * along / stiff;
                h = h.min(2.5 * size / stiff * (1.0 + x * (0.5 + x / 6.0)));
                continue;
            }
            // A slip heading for zero is met in one step along its start direction once what
            // that step neglects is within the tolerance: the part of its rate across it
            // leaves a residue (which the snap at the zero moves into the spins), and the
            // friction's direction, however it would turn, changes the velocities by at most
            // 2 mu x the step. Until then it is approached in steps of at most half the
            // remaining reach.
            let reach = size / -along;
            if (across * reach * (1.0 + mu / -along)).min(2.0 * mu * reach) <= self.atol {
                finals[k] = Some(reach);
            } else {
                h = h.min(0.5 * reach).min(2.5 * size / stiff);
            }
        }
        (h, finals)
    }
}
