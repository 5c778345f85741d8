//! Candidate shots from the geometry of the table: the ghost ball of every legal ball and
//! pocket (straight and cut shots), one-rail banks of the object ball, one-rail kicks of the
//! cue ball, two-ball combinations whose first ball is legal; then each aim in several speeds
//! and tip offsets.
//!
//! The ghost ball: to send an object ball at `b` along unit `u`, the cue ball must touch it
//! at `b - 2R u`. A bank or a kick aims at the mirror image of its target in the line a
//! ball's centre follows along the cushion (`R` inside the nose), which is exact for a
//! mirror-like rebound and a first guess for the real cushion (the noisy samples judge it).

use billiards_physics::{Cushion, Pocket, Shot, Simulation, Table, TipOffset, Vec2};
use billiards_rules::{CUE, Call};

/// What a shot tries to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ShotKind {
    /// The break.
    Break,
    /// A straight or cut shot: `ball` into `pocket`.
    Pot {
        /// The object ball.
        ball: u8,
        /// The pocket.
        pocket: Pocket,
    },
    /// `ball` off `cushion` into `pocket`.
    Bank {
        /// The object ball.
        ball: u8,
        /// The pocket.
        pocket: Pocket,
        /// The cushion it banks off.
        cushion: Cushion,
    },
    /// The cue ball off `cushion`, then `ball` into `pocket`.
    Kick {
        /// The object ball.
        ball: u8,
        /// The pocket.
        pocket: Pocket,
        /// The cushion the cue ball kicks off.
        cushion: Cushion,
    },
    /// `first` into `ball`, `ball` into `pocket`.
    Combo {
        /// The ball the cue ball hits (a legal one).
        first: u8,
        /// The ball meant to drop.
        ball: u8,
        /// The pocket.
        pocket: Pocket,
    },
    /// A legal hit on `ball` that leaves the opponent as little as possible.
    Safety {
        /// The ball hit first.
        ball: u8,
    },
    /// A 9-ball or 10-ball push out (WPA 2.4, 9.4).
    PushOut,
}

/// The balls on the table, by number, and the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// The table.
    pub table: Table,
    /// Ball radius, metres.
    pub radius: f64,
    /// Where the cue ball is (or would be placed).
    pub cue: Vec2,
    /// The object balls on the table: number and centre.
    pub balls: Vec<(u8, Vec2)>,
}

impl Layout {
    /// The resting balls of `sim`, the cue ball at `cue` (`None`: where it is; `None` is
    /// returned when it is then off the table).
    pub fn of(sim: &Simulation, cue: Option<Vec2>) -> Option<Layout> {
        let mut at = cue;
        let mut balls = Vec::new();
        for (state, &n) in sim.balls().zip(sim.numbers()) {
            if !state.motion.on_table() {
                continue;
            }
            if n == CUE {
                at = at.or(Some(state.position));
            } else {
                balls.push((n, state.position));
            }
        }
        Some(Layout {
            table: *sim.table(),
            radius: sim.params().ball.radius,
            cue: at?,
            balls,
        })
    }

    /// Where ball `n` is.
    pub fn ball(&self, n: u8) -> Option<Vec2> {
        self.balls.iter().find(|b| b.0 == n).map(|b| b.1)
    }

    /// The straight path from `a` to `b` of a ball's centre touches no ball but those in
    /// `skip` (the cue ball counts, as [`CUE`]).
    pub fn clear(&self, a: Vec2, b: Vec2, skip: &[u8]) -> bool {
        let d = 2.0 * self.radius;
        let seg = b - a;
        let len2 = seg.dot(seg).max(1e-18);
        let blocked = |c: Vec2| {
            let t = ((c - a).dot(seg) / len2).clamp(0.0, 1.0);
            (a + seg * t - c).length() < d
        };
        let cue = std::iter::once((CUE, self.cue));
        !cue.chain(self.balls.iter().copied())
            .any(|(n, c)| !skip.contains(&n) && blocked(c))
    }
}

/// A geometric aim: the cue ball's direction and what the error in it costs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aim {
    /// What the shot tries.
    pub kind: ShotKind,
    /// The cue ball's direction, radians.
    pub angle: f64,
    /// The ball the cue ball must hit first.
    pub first: u8,
    /// The direction that ball must leave in (for the throw correction).
    pub object_dir: Vec2,
    /// Metres of miss at the pocket per radian of aim error.
    pub spread: f64,
    /// Half the width of the pocket's opening as seen along the ball's path, less the
    /// jaws' bite, metres: a miss smaller than this still drops.
    pub tolerance: f64,
    /// The cue speed that sends the ball to its pocket with a little to spare, m/s.
    pub speed: f64,
}

/// Where a ball's centre aims into `pocket`, and the pocket's outward direction.
pub fn pocket_target(table: &Table, radius: f64, pocket: Pocket) -> (Vec2, Vec2) {
    let (hx, hy, leg) = (0.5 * table.length, 0.5 * table.width, table.corner_leg());
    let corner = |sx: f64, sy: f64| {
        let mid = Vec2::new(sx * (hx - 0.5 * leg), sy * (hy - 0.5 * leg));
        let out = Vec2::new(sx, sy) / std::f64::consts::SQRT_2;
        (mid + out * (0.5 * radius), out)
    };
    match pocket {
        Pocket::HeadLeft => corner(-1.0, 1.0),
        Pocket::HeadRight => corner(-1.0, -1.0),
        Pocket::FootLeft => corner(1.0, 1.0),
        Pocket::FootRight => corner(1.0, -1.0),
        Pocket::SideLeft => (Vec2::new(0.0, hy + 0.5 * radius), Vec2::new(0.0, 1.0)),
        Pocket::SideRight => (Vec2::new(0.0, -hy - 0.5 * radius), Vec2::new(0.0, -1.0)),
    }
}

/// Half-width of the opening of `pocket` seen along unit `dir`, less 0.6 R of jaw, or
/// `None` when the ball comes in too steeply to drop (more than 70 degrees off a corner's
/// axis, 55 off a side pocket's).
fn tolerance(table: &Table, radius: f64, pocket: Pocket, out: Vec2, dir: Vec2) -> Option<f64> {
    let (half, min_cos) = if pocket.is_corner() {
        (0.5 * table.corner_mouth, 70f64.to_radians().cos())
    } else {
        (0.5 * table.side_mouth, 55f64.to_radians().cos())
    };
    let c = dir.dot(out);
    (c >= min_cos)
        .then_some(half * c - 0.6 * radius)
        .filter(|&t| t > 0.0)
}

/// The cue speed that brings an object ball `d2` metres (plus 0.3 m to spare) after a cut
/// of cosine `cut_cos`, the cue ball having rolled `d1`: rolling deceleration 0.1 m/s^2,
/// 2/7 of a sliding ball's speed lost before it rolls, the collision passing
/// `cos(cut) (1 + e) / 2` of the speed.
fn speed_for(d1: f64, d2: f64, cut_cos: f64) -> f64 {
    const A_ROLL: f64 = 0.1;
    let v_obj = 1.4 * (2.0 * A_ROLL * (d2 + 0.3)).sqrt();
    let v_contact = v_obj / (0.975 * cut_cos.max(0.2));
    (1.4 * (v_contact * v_contact + 2.0 * A_ROLL * d1).sqrt()).clamp(0.6, 6.0)
}

/// The line a ball's centre follows along `cushion`: a point on it and its inward normal.
fn rail_line(table: &Table, radius: f64, cushion: Cushion) -> (Vec2, Vec2) {
    let b = table.centre_bounds(radius);
    let n = cushion.inward_normal();
    (Vec2::new(-n.x * b.x, -n.y * b.y), n)
}

/// `p` mirrored in `cushion`'s centre line.
fn mirror(table: &Table, radius: f64, cushion: Cushion, p: Vec2) -> Vec2 {
    let (on, n) = rail_line(table, radius, cushion);
    p - n * (2.0 * (p - on).dot(n))
}

/// Where the straight path from `a` to `b`'s mirror image meets `cushion`'s centre line, if
/// that point is on the cushion itself (not in a pocket's mouth).
fn bounce(table: &Table, radius: f64, cushion: Cushion, a: Vec2, image: Vec2) -> Option<Vec2> {
    let (on, n) = rail_line(table, radius, cushion);
    let (da, db) = ((a - on).dot(n), (image - on).dot(n));
    if da <= 0.0 || db >= 0.0 {
        return None;
    }
    let p = a + (image - a) * (da / (da - db));
    table.on_cushion(cushion, p).then_some(p)
}

/// The aim that sends `ball` (at `b`) along unit `u` from a cue ball arriving from `from`
/// (the cue ball or its bounce point); `None` beyond an 80-degree cut.
fn ghost(b: Vec2, u: Vec2, from: Vec2, radius: f64) -> Option<(Vec2, Vec2, f64)> {
    let g = b - u * (2.0 * radius);
    let dir = (g - from).normalized()?;
    let cut_cos = dir.dot(u);
    (cut_cos >= 80f64.to_radians().cos()).then_some((g, dir, cut_cos))
}

/// Straight and cut shots of each ball of `legal` into each pocket.
pub fn direct_aims(layout: &Layout, legal: &[u8]) -> Vec<Aim> {
    let mut out = Vec::new();
    each_direct_aim(layout, legal, true, |aim, lines| {
        if lines.open(layout) {
            out.push(aim);
        }
    });
    out
}

/// The two lines a direct aim needs clear: the cue ball to the ghost ball, and the ball to
/// its pocket.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Lines {
    cue: Vec2,
    ghost: Vec2,
    ball: Vec2,
    target: Vec2,
    number: u8,
}

impl Lines {
    /// Whether no other ball blocks either line (the costly part of an aim).
    pub(crate) fn open(&self, layout: &Layout) -> bool {
        self.cue_open(layout) && self.pocket_open(layout)
    }

    /// Whether no other ball blocks the cue ball's path to the ghost ball.
    pub(crate) fn cue_open(&self, layout: &Layout) -> bool {
        layout.clear(self.cue, self.ghost, &[CUE, self.number])
    }

    /// Whether no other ball blocks the object ball's path to its pocket.
    pub(crate) fn pocket_open(&self, layout: &Layout) -> bool {
        layout.clear(self.ball, self.target, &[self.number])
    }

    /// Where the cue ball's centre must be at contact (the ghost ball).
    pub(crate) fn ghost(&self) -> Vec2 {
        self.ghost
    }
}

/// Every geometric straight or cut shot of each ball of `legal` into each pocket, in the
/// order of [`direct_aims`], handed to `f` with the lines it needs clear, unchecked (so a
/// caller that does not need an aim need not check them). Without `angles` each aim's
/// `angle` is NaN (for callers that read only its spread, tolerance and speed).
pub(crate) fn each_direct_aim(
    layout: &Layout,
    legal: &[u8],
    angles: bool,
    mut f: impl FnMut(Aim, Lines),
) {
    let (t, r) = (&layout.table, layout.radius);
    for &n in legal {
        let Some(b) = layout.ball(n) else { continue };
        for pocket in Pocket::ALL {
            let (target, outward) = pocket_target(t, r, pocket);
            let Some(u) = (target - b).normalized() else {
                continue;
            };
            let Some(tol) = tolerance(t, r, pocket, outward, u) else {
                continue;
            };
            let Some((g, dir, cut_cos)) = ghost(b, u, layout.cue, r) else {
                continue;
            };
            let (d1, d2) = ((g - layout.cue).length(), (target - b).length());
            let aim = Aim {
                kind: ShotKind::Pot { ball: n, pocket },
                angle: if angles { dir.angle() } else { f64::NAN },
                first: n,
                object_dir: u,
                // Aim error e moves the contact by d1 e, turning the ball by d1 e / (2R cos).
                spread: d2 * (1.0 + d1 / (2.0 * r * cut_cos)),
                tolerance: tol,
                speed: speed_for(d1, d2, cut_cos),
            };
            let lines = Lines {
                cue: layout.cue,
                ghost: g,
                ball: b,
                target,
                number: n,
            };
            f(aim, lines);
        }
    }
}

/// The best of `values` (each with its lines) whose lines are open in `layout`, 0 when
/// none is positive and open: the values best first, the first open one.
pub(crate) fn best_open(layout: &Layout, values: &mut [(f64, Lines)]) -> f64 {
    values.sort_by(|a, b| b.0.total_cmp(&a.0));
    values
        .iter()
        .find(|v| v.0 > 0.0 && v.1.open(layout))
        .map_or(0.0, |v| v.0)
}

/// One-rail banks of the object ball and kicks of the cue ball, for each ball of `legal`.
pub fn rail_aims(layout: &Layout, legal: &[u8]) -> Vec<Aim> {
    let (t, r) = (&layout.table, layout.radius);
    let mut out = Vec::new();
    for &n in legal {
        let Some(b) = layout.ball(n) else { continue };
        for pocket in Pocket::ALL {
            let (target, outward) = pocket_target(t, r, pocket);
            for cushion in Cushion::ALL {
                // Bank: the object ball to the mirror image of the pocket.
                let image = mirror(t, r, cushion, target);
                if let Some(p) = bounce(t, r, cushion, b, image)
                    && let (Some(u), Some(u2)) = ((p - b).normalized(), (target - p).normalized())
                    && let Some(tol) = tolerance(t, r, pocket, outward, u2)
                    && let Some((g, dir, cut_cos)) = ghost(b, u, layout.cue, r)
                    && layout.clear(layout.cue, g, &[CUE, n])
                    && layout.clear(b, p, &[n])
                    && layout.clear(p, target, &[n])
                {
                    let (d1, d2) = ((g - layout.cue).length(), (image - b).length());
                    out.push(Aim {
                        kind: ShotKind::Bank {
                            ball: n,
                            pocket,
                            cushion,
                        },
                        angle: dir.angle(),
                        first: n,
                        object_dir: u,
                        // A cushion is less true than a mirror: half again the spread.
                        spread: 1.5 * d2 * (1.0 + d1 / (2.0 * r * cut_cos)),
                        tolerance: tol,
                        speed: speed_for(d1, d2 * 1.4, cut_cos),
                    });
                }
                // Kick: the cue ball to the mirror image of the ghost ball of a direct pot.
                let Some(u) = (target - b).normalized() else {
                    continue;
                };
                let g = b - u * (2.0 * r);
                let image = mirror(t, r, cushion, g);
                if let Some(p) = bounce(t, r, cushion, layout.cue, image)
                    && let Some(tol) = tolerance(t, r, pocket, outward, u)
                    && let Some((_, _, cut_cos)) = ghost(b, u, p, r)
                    && let Some(dir) = (p - layout.cue).normalized()
                    && layout.clear(layout.cue, p, &[CUE])
                    && layout.clear(p, g, &[CUE, n])
                    && layout.clear(b, target, &[n])
                {
                    let d1 = (p - layout.cue).length() + (g - p).length();
                    let d2 = (target - b).length();
                    out.push(Aim {
                        kind: ShotKind::Kick {
                            ball: n,
                            pocket,
                            cushion,
                        },
                        angle: dir.angle(),
                        first: n,
                        object_dir: u,
                        spread: 1.5 * d2 * (1.0 + d1 / (2.0 * r * cut_cos)),
                        tolerance: tol,
                        speed: speed_for(d1 * 1.3, d2, cut_cos),
                    });
                }
            }
        }
    }
    out
}

/// Two-ball combinations: a ball of `legal` into a ball of `second` (not itself), that one
/// into a pocket.
pub fn combo_aims(layout: &Layout, legal: &[u8], second: &[u8]) -> Vec<Aim> {
    let (t, r) = (&layout.table, layout.radius);
    let mut out = Vec::new();
    for &n1 in legal {
        let Some(b1) = layout.ball(n1) else { continue };
        for &n2 in second.iter().filter(|&&n| n != n1) {
            let Some(b2) = layout.ball(n2) else { continue };
            for pocket in Pocket::ALL {
                let (target, outward) = pocket_target(t, r, pocket);
                let Some(u2) = (target - b2).normalized() else {
                    continue;
                };
                let Some(tol) = tolerance(t, r, pocket, outward, u2) else {
                    continue;
                };
                // The first ball must reach the second's ghost within a 60-degree cut.
                let Some((g2, u1, cut2)) = ghost(b2, u2, b1, r) else {
                    continue;
                };
                let Some((g1, dir, cut1)) = ghost(b1, u1, layout.cue, r) else {
                    continue;
                };
                if cut2 < 0.5
                    || !layout.clear(layout.cue, g1, &[CUE, n1])
                    || !layout.clear(b1, g2, &[n1, n2])
                    || !layout.clear(b2, target, &[n2])
                {
                    continue;
                }
                let (d1, d12, d2) = (
                    (g1 - layout.cue).length(),
                    (g2 - b1).length(),
                    (target - b2).length(),
                );
                // Each collision multiplies the error (the ghost-ball relation, twice).
                let turn1 = 1.0 + d1 / (2.0 * r * cut1);
                let turn2 = 1.0 + d12 * turn1 / (2.0 * r * cut2);
                out.push(Aim {
                    kind: ShotKind::Combo {
                        first: n1,
                        ball: n2,
                        pocket,
                    },
                    angle: dir.angle(),
                    first: n1,
                    object_dir: u1,
                    spread: d2 * turn2,
                    tolerance: tol,
                    speed: speed_for(d1 + d12, d2 + 0.3, cut1 * cut2),
                });
            }
        }
    }
    out
}

/// A shot to evaluate: the strike, the call that goes with it and where the cue ball goes
/// first when it is in hand.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// What the shot tries.
    pub kind: ShotKind,
    /// The strike, before execution noise.
    pub shot: Shot,
    /// The call (8-ball and 10-ball: the ball and pocket; 9-ball: none, or a push out).
    pub call: Call,
    /// Ball in hand: where the cue ball is put before the shot.
    pub place: Option<Vec2>,
    /// The ball the cue ball must hit first and the direction it should leave in, for the
    /// throw correction (`None`: no correction).
    pub object: Option<(u8, Vec2)>,
}

/// The call of a shot of `kind` in a game of called shots (`called`: 8-ball, 10-ball; the
/// ball meant to drop and its pocket, WPA 1.6, 9.5), else none.
pub fn call_for(kind: ShotKind, called: bool) -> Call {
    match kind {
        ShotKind::Pot { ball, pocket }
        | ShotKind::Bank { ball, pocket, .. }
        | ShotKind::Kick { ball, pocket, .. }
        | ShotKind::Combo { ball, pocket, .. }
            if called =>
        {
            Call::Ball { ball, pocket }
        }
        ShotKind::PushOut => Call::PushOut,
        _ => Call::None,
    }
}

/// Each aim in each speed of `speeds` (multiples of its own) and, for straight and cut
/// shots, each tip of `tips`; rail shots and combinations are struck in the centre; `called`
/// as in [`call_for`].
pub fn expand(
    aims: &[Aim],
    speeds: &[f64],
    tips: &[TipOffset],
    called: bool,
    place: Option<Vec2>,
) -> Vec<Candidate> {
    let mut out = Vec::new();
    for aim in aims {
        let direct = matches!(aim.kind, ShotKind::Pot { .. });
        let centre = [TipOffset::default()];
        let tips = if direct { tips } else { &centre[..] };
        for &k in speeds {
            for &tip in tips {
                out.push(Candidate {
                    kind: aim.kind,
                    shot: Shot {
                        angle: aim.angle,
                        speed: (aim.speed * k).min(8.0),
                        tip,
                        elevation: 0.0,
                    },
                    call: call_for(aim.kind, called),
                    place,
                    object: matches!(aim.kind, ShotKind::Pot { .. } | ShotKind::Combo { .. })
                        .then_some((aim.first, aim.object_dir)),
                });
            }
        }
    }
    out
}

/// Safety candidates on each ball of `legal`: `per_ball` hits from full to thin on either
/// side, soft and medium, where the ball can be seen; otherwise a kick off each cushion to
/// a full hit. With nothing found, a firm shot straight at the first legal ball (a foul may
/// follow, but the rules get a shot).
pub fn safeties(
    layout: &Layout,
    legal: &[u8],
    per_ball: usize,
    place: Option<Vec2>,
) -> Vec<Candidate> {
    let (t, r) = (&layout.table, layout.radius);
    let mut out = Vec::new();
    let push = |out: &mut Vec<Candidate>, kind, angle: f64, speed: f64| {
        out.push(Candidate {
            kind,
            shot: Shot::new(angle, speed),
            call: Call::None,
            place,
            object: None,
        })
    };
    for &n in legal {
        let Some(b) = layout.ball(n) else { continue };
        let Some(to) = (b - layout.cue).normalized() else {
            continue;
        };
        let d = (b - layout.cue).length();
        let kind = ShotKind::Safety { ball: n };
        if !layout.clear(layout.cue, b - to * (2.0 * r), &[CUE, n]) {
            for cushion in Cushion::ALL {
                let image = mirror(t, r, cushion, b);
                if let Some(p) = bounce(t, r, cushion, layout.cue, image)
                    && layout.clear(layout.cue, p, &[CUE])
                    && layout.clear(p, b, &[CUE, n])
                {
                    let travel = d + (p - b).length();
                    push(&mut out, kind, (p - layout.cue).angle(), 1.2 + 0.6 * travel);
                }
            }
            continue;
        }
        for k in 0..per_ball {
            // Fractions of the widest contact offset, -0.9..0.9 of 2R.
            let f = if per_ball == 1 {
                0.0
            } else {
                -0.9 + 1.8 * k as f64 / (per_ball - 1) as f64
            };
            let off = (2.0 * r * f / d).clamp(-1.0, 1.0).asin();
            for speed in [0.9, 1.8] {
                push(&mut out, kind, to.angle() + off, speed + 0.4 * d);
            }
        }
    }
    if out.is_empty()
        && let Some((n, b)) = legal.iter().find_map(|&n| layout.ball(n).map(|b| (n, b)))
    {
        let kind = ShotKind::Safety { ball: n };
        push(&mut out, kind, (b - layout.cue).angle(), 3.0);
    }
    out
}
