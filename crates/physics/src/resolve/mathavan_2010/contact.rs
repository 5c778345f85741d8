//! The contacts of the Mathavan 2010 impact: slips, friction within the cones, the rates
//! of the velocities per unit impulse, one Runge–Kutta step, and the grip of a zero slip.

/// One contact's friction: sliding against its slip (the direction kept for a slip of zero),
/// or stuck.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Grip {
    Slide([f64; 2]),
    Stick,
}

/// Where a sliding contact's friction takes its direction from in a rate evaluation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Dir {
    /// Its slip's own direction (its grip's while the slip is within `zero`).
    Own,
    /// Its grip's, whatever the slip (a step meant to end on the slip's zero).
    Held,
    /// The direction its slip grows in at the state (`slaved.rs`), the Newton iteration
    /// started from this growth rate.
    Slaved(f64),
}

/// The geometry and constants in the form the equations use.
#[derive(Clone, Copy, Debug)]
pub(super) struct Setup {
    pub(super) s: f64,
    pub(super) c: f64,
    pub(super) r: f64,
    /// `5 / (2R)`, the spins' rate per unit friction (eq. 14), computed once: `2.5 / r`.
    pub(super) k: f64,
    pub(super) mu_w: f64,
    pub(super) mu_s: f64,
    /// Slips below this (m/s) count as zero in the events.
    pub(super) tol: f64,
    /// Slips below this (m/s) have no direction of their own: a sliding contact's friction
    /// keeps its grip's (the integration's tolerance, at least `tol`).
    pub(super) zero: f64,
}

/// State: `vx, vy, wx, wy, wz, W` (W: the normal force's work per unit mass).
pub(super) type State = [f64; 6];

/// The length of `v` (no guard against overflow: slips are far from it, and this is
/// several times faster than `f64::hypot`).
pub(super) fn hypot(v: [f64; 2]) -> f64 {
    (v[0] * v[0] + v[1] * v[1]).sqrt()
}

pub(super) fn unit(v: [f64; 2], fallback: [f64; 2]) -> [f64; 2] {
    let l = hypot(v);
    if l > 0.0 {
        [v[0] / l, v[1] / l]
    } else {
        fallback
    }
}

impl Setup {
    /// Slips at the nose `(x_I, y'_I)` and at the cloth `(x_C, y_C)` (eqs. 12–13).
    pub(super) fn slips(&self, y: &State) -> ([f64; 2], [f64; 2]) {
        let (s, c, r) = (self.s, self.c, self.r);
        (
            [y[0] + r * (y[3] * s - y[4] * c), -y[1] * s + r * y[2]],
            [y[0] - r * y[3], y[1] + r * y[2]],
        )
    }

    /// Friction `(a, b, p, q)` per unit impulse for the grips, and the table's normal `N`.
    pub(super) fn friction(&self, y: &State, gi: Grip, gc: Grip) -> ([f64; 4], f64) {
        self.friction_fixed(y, gi, gc, [Dir::Own; 2])
    }

    /// [`Self::friction`], the sliding directions taken as `dirs` says.
    pub(super) fn friction_fixed(
        &self,
        y: &State,
        gi: Grip,
        gc: Grip,
        dirs: [Dir; 2],
    ) -> ([f64; 4], f64) {
        let (f, n, _) = self.friction_slaved(y, gi, gc, dirs);
        (f, n)
    }

    /// [`Self::friction_fixed`] and the slaved contact's growth rate `lambda` (zero if none).
    pub(super) fn friction_slaved(
        &self,
        y: &State,
        gi: Grip,
        gc: Grip,
        dirs: [Dir; 2],
    ) -> ([f64; 4], f64, f64) {
        let (s, c) = (self.s, self.c);
        let (si, sc) = self.slips(y);
        // Both contacts' inverse lengths side by side (the two square roots and divisions
        // are most of an evaluation's time); a length within `zero` is not used.
        let l2 = [si[0] * si[0] + si[1] * si[1], sc[0] * sc[0] + sc[1] * sc[1]];
        let inv = [1.0 / l2[0].sqrt(), 1.0 / l2[1].sqrt()];
        let z2 = self.zero * self.zero;
        let along = |g: Grip, sl: [f64; 2], k: usize| match g {
            Grip::Slide(d) if matches!(dirs[k], Dir::Held) || l2[k] <= z2 => d,
            Grip::Slide(_) => [sl[0] * inv[k], sl[1] * inv[k]],
            Grip::Stick => [0.0, 0.0],
        };
        let (mut ui, mut uc) = (along(gi, si, 0), along(gc, sc, 1));
        // A slaved contact (never both) takes the direction its slip grows in, given the
        // other's friction.
        let mut lambda = 0.0;
        if let Dir::Slaved(l0) = dirs[0]
            && let Some((u, l, _)) = self.slaved(true, uc, matches!(gc, Grip::Stick), l0)
        {
            (ui, lambda) = (u, l);
        } else if let Dir::Slaved(l0) = dirs[1]
            && let Some((u, l, _)) = self.slaved(false, ui, matches!(gi, Grip::Stick), l0)
        {
            (uc, lambda) = (u, l);
        }
        let normal = |b: f64| (s - c * b).max(0.0);
        // The slip rates are d(slip)/dP = g + K f with g = (0, s c | 0, -c) and
        // K = [[7/2, 1 - 5s/2], [1 - 5s/2, 7/2]] on (a, p), [[s^2 + 5/2, 5/2 - s], [5/2 - s, 7/2]]
        // on (b, q): a stuck contact takes the friction that keeps its slip rate zero.
        let (kx, ky) = (1.0 - 2.5 * s, 2.5 - s);
        let f = match (gi, gc) {
            (Grip::Slide(_), Grip::Slide(_)) => {
                let (a, b) = (-self.mu_w * ui[0], -self.mu_w * ui[1]);
                let n = normal(b);
                [a, b, -self.mu_s * n * uc[0], -self.mu_s * n * uc[1]]
            }
            (Grip::Stick, Grip::Slide(_)) => {
                // q = -mu_s uc_y (s - c b) is linear in b: solve the Y' row for b.
                let m = self.mu_s * uc[1];
                let b = (-s * c + ky * m * s) / (s * s + 2.5 + ky * m * c);
                let n = normal(b);
                let (p, q) = (-self.mu_s * n * uc[0], -self.mu_s * n * uc[1]);
                [-kx * p / 3.5, b, p, q]
            }
            (Grip::Slide(_), Grip::Stick) => {
                let (a, b) = (-self.mu_w * ui[0], -self.mu_w * ui[1]);
                [a, b, -kx * a / 3.5, (c - ky * b) / 3.5]
            }
            (Grip::Stick, Grip::Stick) => {
                let (ka, kb, kd) = (s * s + 2.5, ky, 3.5);
                let det = ka * kd - kb * kb;
                let (g1, g2) = (-s * c, c);
                [
                    0.0,
                    (g1 * kd - kb * g2) / det,
                    0.0,
                    (ka * g2 - kb * g1) / det,
                ]
            }
        };
        (f, normal(f[1]), lambda)
    }

    /// Whether stuck contacts' friction lies within their cones.
    pub(super) fn holds(&self, f: &[f64; 4], n: f64, gi: Grip, gc: Grip) -> bool {
        let slack = 1.0 + 1e-12;
        (!matches!(gi, Grip::Stick) || hypot([f[0], f[1]]) <= self.mu_w * slack)
            && (!matches!(gc, Grip::Stick) || hypot([f[2], f[3]]) <= self.mu_s * n * slack)
    }

    /// The rates of the slips `z = (x_I, y'_I, x_C, y_C)` with both contacts sliding along their own slips
    /// (`di`, `dc`: their grips' directions, for a slip within `zero`), and the friction
    /// `(a, b, p, q)` ([`Self::rate_of_friction`] gives the state's rate): the arithmetic of
    /// [`Self::friction_fixed`] without its cases, for the steps that need none (most). The
    /// slip rates are `g + K f` (see `friction_fixed`), so a Runge–Kutta stage needs only
    /// this: from the slips to their rates, one square root and one division side by side,
    /// then multiplies and adds.
    #[inline(always)]
    pub(super) fn slip_rates_sliding(
        &self,
        z: &[f64; 4],
        di: [f64; 2],
        dc: [f64; 2],
    ) -> ([f64; 4], [f64; 4]) {
        let (s, c) = (self.s, self.c);
        let l2 = [z[0] * z[0] + z[1] * z[1], z[2] * z[2] + z[3] * z[3]];
        // 1/|S| = |S| (1/|S|^2): the square root and the division in parallel, not in turn
        // (within two roundings of 1/sqrt); a |S|^2 too small for 1/|S|^2 takes the latter.
        let mut inv = [l2[0].sqrt() * (1.0 / l2[0]), l2[1].sqrt() * (1.0 / l2[1])];
        if !(inv[0].is_finite() && inv[1].is_finite()) {
            inv = [1.0 / l2[0].sqrt(), 1.0 / l2[1].sqrt()];
        }
        let z2 = self.zero * self.zero;
        // Friction -mu u; N = s - c b = s + c mu_w u_y.
        let (ma, mc) = (-self.mu_w, -self.mu_s);
        let (a, b, n) = if l2[0] <= z2 {
            let (a, b) = (ma * di[0], ma * di[1]);
            (a, b, s - c * b)
        } else {
            let (a, b) = ((ma * z[0]) * inv[0], (ma * z[1]) * inv[0]);
            (a, b, s - (c * ma * z[1]) * inv[0])
        };
        let n = n.max(0.0);
        let (p, q) = if l2[1] <= z2 {
            (n * (mc * dc[0]), n * (mc * dc[1]))
        } else {
            (n * ((mc * z[2]) * inv[1]), n * ((mc * z[3]) * inv[1]))
        };
        let (kx, ka, kb) = (1.0 - 2.5 * s, s * s + 2.5, 2.5 - s);
        (
            [
                3.5 * a + kx * p,
                s * c + ka * b + kb * q,
                kx * a + 3.5 * p,
                kb * b - c + 3.5 * q,
            ],
            [a, b, p, q],
        )
    }

    /// The state's rate at `y` for friction `f = (a, b, p, q)` (eqs. 14, 17).
    #[inline(always)]
    pub(super) fn rate_of_friction(&self, f: &[f64; 4], y: &State) -> State {
        let (s, c) = (self.s, self.c);
        let [a, b, p, q] = *f;
        let k = self.k;
        [
            a + p,
            -c - b * s + q,
            k * (b + q),
            k * (a * s - p),
            -k * a * c,
            c * y[1],
        ]
    }

    pub(super) fn rate(&self, y: &State, gi: Grip, gc: Grip) -> State {
        self.rate_fixed(y, gi, gc, [Dir::Own; 2])
    }

    pub(super) fn rate_fixed(&self, y: &State, gi: Grip, gc: Grip, dirs: [Dir; 2]) -> State {
        let (f, _) = self.friction_fixed(y, gi, gc, dirs);
        self.rate_of_friction(&f, y)
    }

    /// [`Self::rate_fixed`] and the slaved contact's growth rate `lambda` (zero if none).
    pub(super) fn rate_slaved(
        &self,
        y: &State,
        gi: Grip,
        gc: Grip,
        dirs: [Dir; 2],
    ) -> (State, f64) {
        let (f, _, lambda) = self.friction_slaved(y, gi, gc, dirs);
        (self.rate_of_friction(&f, y), lambda)
    }

    /// Slip rates of the nose and the cloth.
    pub(super) fn slip_rates(&self, y: &State, gi: Grip, gc: Grip) -> ([f64; 2], [f64; 2]) {
        self.slip_rates_of(&self.rate(y, gi, gc))
    }

    /// Slip rates of the nose and the cloth from the state's rate `d`.
    pub(super) fn slip_rates_of(&self, d: &State) -> ([f64; 2], [f64; 2]) {
        let (s, c, r) = (self.s, self.c, self.r);
        (
            [d[0] + r * (d[3] * s - d[4] * c), -d[1] * s + r * d[2]],
            [d[0] - r * d[3], d[1] + r * d[2]],
        )
    }

    /// The table's normal `N = sin theta - b cos theta` of the friction behind rate `d`
    /// (from `dvy/dP = -cos - b sin + q` and `dwx/dP = 5/(2R) (b + q)`).
    pub(super) fn normal_of(&self, d: &State) -> f64 {
        let (s, c) = (self.s, self.c);
        let b = (d[2] * self.r / 2.5 - d[1] - c) / (1.0 + s);
        (s - c * b).max(0.0)
    }

    /// The grip of the nose (`nose`) or cloth contact whose slip is zero: stuck if the cone
    /// holds the friction that keeps it so, otherwise sliding the way its slip then grows
    /// (the direction `u` with slip rate along `u` while friction opposes `u`, by fixed point).
    pub(super) fn grip_at_zero(&self, y: &State, nose: bool, other: Grip) -> Grip {
        let (gi, gc) = if nose {
            (Grip::Stick, other)
        } else {
            (other, Grip::Stick)
        };
        let (f, n) = self.friction(y, gi, gc);
        if self.holds(&f, n, gi, gc) {
            return Grip::Stick;
        }
        let pick = |u: [f64; 2]| {
            let (ri, rc) = if nose {
                self.slip_rates(y, Grip::Slide(u), other)
            } else {
                self.slip_rates(y, other, Grip::Slide(u))
            };
            if nose { ri } else { rc }
        };
        let need = if nose { [f[0], f[1]] } else { [f[2], f[3]] };
        let cone = if nose { self.mu_w } else { self.mu_s * n };
        let boundary = unit(need, [1.0, 0.0]);
        let boundary = [-boundary[0], -boundary[1]];
        // Just past a let-go the friction stays continuous: it opposes what sticking needs.
        if hypot(need) <= cone * (1.0 + 1e-6) {
            return Grip::Slide(boundary);
        }
        let mut u = boundary;
        for _ in 0..30 {
            let next = unit(pick(u), u);
            let moved = (next[0] - u[0]).abs() + (next[1] - u[1]).abs();
            u = next;
            if moved <= 1e-13 {
                break; // converged (a fixed point reached, the usual case in a few steps)
            }
        }
        let r = pick(u);
        if r[0] * u[0] + r[1] * u[1] > 0.0 {
            Grip::Slide(u)
        } else {
            Grip::Slide(boundary)
        }
    }
}

/// What ends a step early.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Event {
    /// The normal velocity reaches zero: compression ends.
    Compressed,
    /// The work reaches its final value: the impact ends.
    Restituted,
    /// The nose's (`true`) or the cloth's slip reaches zero along its start direction.
    SlipZero(bool),
    /// A stuck nose (`true`) or cloth contact needs more friction than its cone holds.
    LetsGo(bool),
}

impl Setup {
    /// Sets a contact's slip, found zero to within the last step's error, to exactly zero
    /// through the spins (a change of the order of that error), so that its sliding direction
    /// after a let-go is not the residue's.
    pub(super) fn snap(&self, y: &mut State, nose: bool) {
        let (si, sc) = self.slips(y);
        if nose {
            y[2] -= si[1] / self.r;
            y[4] += si[0] / (self.r * self.c.max(1e-3));
        } else {
            y[3] += sc[0] / self.r;
            y[2] -= sc[1] / self.r;
        }
    }

    /// Grips made consistent at state `y`: a stuck contact whose cone no longer holds its
    /// friction slides, the other contact then re-checked (both may have zero slip at once).
    pub(super) fn settle(&self, y: &State, mut gi: Grip, mut gc: Grip) -> (Grip, Grip) {
        for _ in 0..4 {
            let (f, n) = self.friction(y, gi, gc);
            if self.holds(&f, n, gi, gc) {
                break;
            }
            let nose_holds =
                !matches!(gi, Grip::Stick) || self.holds(&f, n, gi, Grip::Slide([0.0, 0.0]));
            if !nose_holds {
                gi = self.grip_at_zero(y, true, gc);
            } else {
                gc = self.grip_at_zero(y, false, gi);
            }
        }
        (gi, gc)
    }
}
