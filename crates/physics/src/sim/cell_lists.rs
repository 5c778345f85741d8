//! The prediction strategy of scenes split into cells (250 balls or more): each ball is tested
//! only against the balls in the cells around it ([`Grid`]), leaving its cell is an event,
//! and an event re-predicts the balls it touched in full and every ball whose cached event
//! was a contact with one of them (found through a dependents index, not a scan). A ball's
//! events with no other ball are kept until its segment changes, so a crossing or a
//! partner's event re-solves only its pairs and its next crossing.

use super::pending::{Pending, PendingKind, earlier, rank};
use super::scene::Scene;
use crate::ball::BallId;
use crate::detect::{self, Kinematics};
use crate::grid::{Cell, Grid, Side};
use crate::math::Vec2;
use crate::queue::Tournament;
use crate::table::Cushion;

/// What a ball's pair searches read of a neighbour, in one cache line (64 bytes, the first
/// of the ball's [`Record`]): its segment's start, state and acceleration, and the time of
/// its next event with no other ball (a contact after it is searched again then). Random
/// access by ball, so one line a neighbour, not one a field.
#[derive(Clone, Copy, Debug, Default)]
struct Path {
    start: f64,
    p: Vec2,
    v: Vec2,
    a: Vec2,
    until: f64,
}

impl Path {
    /// Position and velocity at `t`, computed as [`crate::ball::Segment::position_at`] and
    /// `velocity_at` do (bit for bit, so the cull below sees what the exact search sees).
    #[inline]
    fn at(&self, t: f64) -> (Vec2, Vec2) {
        let tau = t - self.start;
        (
            self.p + (self.v + self.a * (0.5 * tau)) * tau,
            self.v + self.a * tau,
        )
    }
}

/// Everything the cell lists keep of one ball, in one record of two cache lines (issue 53:
/// spread over five arrays and the segments, a crossing read some eight lines of its own
/// ball and two of each neighbour). First line: the [`Path`] a neighbour's test reads;
/// second: the cached events and what only the ball's own events read, its cell among them.
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(64))]
struct Record {
    path: Path,
    /// The ball's earliest contact with another ball found so far, valid until either
    /// segment changes. Searched without the cap of the ball's next crossing, so a crossing
    /// keeps it and searches only the cells it brings into the neighbourhood.
    pair: Option<Pending>,
    /// When the segment ends by itself (`f64::INFINITY` if never), the next crossing's
    /// horizon, as `Segment::end`.
    end: f64,
    /// Stamp of the prediction round that last predicted the ball.
    stamp: u64,
    /// The ball's earliest event with no other ball, kept until its segment changes (a grid
    /// crossing or a partner's event re-predicts only its pairs and crossing).
    solo: Solo,
    /// The ball's grid cell as `[x, y]`, [`NOWHERE`] if none.
    cell: [u32; 2],
}

/// `Record::cell` of a ball in no cell.
const NOWHERE: [u32; 2] = [u32::MAX; 2];

impl Record {
    /// The ball's grid cell.
    #[inline]
    fn cell(&self) -> Option<Cell> {
        let [x, y] = self.cell;
        (x != u32::MAX).then_some(Cell {
            x: x as usize,
            y: y as usize,
        })
    }

    /// Stores the ball's grid cell (cells are indexed by `u32`: `Grid::new` makes about one
    /// a ball).
    #[inline]
    fn set_cell(&mut self, cell: Option<Cell>) {
        self.cell = cell.map_or(NOWHERE, |c| [c.x as u32, c.y as u32]);
    }
}

// Two cache lines a ball, the first the neighbours' (the layout above depends on it).
const _: () = assert!(std::mem::size_of::<Record>() == 128 && std::mem::size_of::<Path>() == 64);

/// A ball's earliest event with no other ball in 8 bytes: its time is the record's
/// `Path::until` (to the bit: `until` is that time), its ball the record's; and the ball's
/// motion bits.
#[derive(Clone, Copy, Debug, Default)]
struct Solo {
    /// 0: none; 1 to 4: [`PendingKind::Transition`], `Opening`, `Cushion`, `Jaw`.
    tag: u8,
    /// [`MOVING`] and [`ON_TABLE`] bits of the segment's motion.
    flags: u8,
    /// The opening, cushion (its place in [`Cushion::ALL`]) or jaw.
    index: u32,
}

impl Solo {
    /// `solo`, an event of ball `id` alone ([`Scene::predict_solo`]), with `flags`.
    fn pack(solo: Option<Pending>, id: BallId, flags: u8) -> Self {
        let (tag, index) = match solo.map(|p| p.kind) {
            None => (0, 0),
            Some(PendingKind::Transition(_)) => (1, 0),
            Some(PendingKind::Opening(_, k)) => (2, k),
            Some(PendingKind::Cushion(_, c)) => (3, c as usize),
            Some(PendingKind::Jaw(_, k)) => (4, k),
            Some(PendingKind::Crossing(..) | PendingKind::Pair(..)) => {
                unreachable!("a ball's own events are transitions, openings, cushions, jaws")
            }
        };
        debug_assert!(solo.is_none_or(|p| p.involves(id) && p.partner(id).is_none()));
        debug_assert!(
            index < 1 << 30,
            "part indices fit in 30 bits (`Pending::rank`)"
        );
        Self {
            tag,
            flags,
            index: index as u32,
        }
    }

    /// The event packed, of ball `id` at time `until`.
    #[inline]
    fn unpack(self, id: BallId, until: f64) -> Option<Pending> {
        let k = self.index as usize;
        let kind = match self.tag {
            1 => PendingKind::Transition(id),
            2 => PendingKind::Opening(id, k),
            3 => PendingKind::Cushion(id, Cushion::ALL[k & 3]),
            4 => PendingKind::Jaw(id, k),
            _ => return None,
        };
        Some(Pending { time: until, kind })
    }
}

/// `Solo::flags` bit: the ball moves.
const MOVING: u8 = 1;
/// `Solo::flags` bit: the ball is on the table.
const ON_TABLE: u8 = 2;

/// The cell lists and the index of which predictions depend on which ball.
#[derive(Debug)]
pub(super) struct CellLists {
    grid: Grid,
    /// Each ball's paths and cached events.
    balls: Vec<Record>,
    /// For each ball, the balls whose cached event is a contact with it (may hold stale
    /// entries; checked before use).
    dependents: Vec<Vec<BallId>>,
    /// The current prediction round.
    round: u64,
}

clone_reusing!(CellLists {
    grid,
    balls,
    dependents,
    round
});

impl CellLists {
    /// Cell lists over `grid` for `n` balls (filled by [`CellLists::predict_all`]).
    pub fn new(grid: Grid, n: usize) -> Self {
        Self {
            grid,
            balls: vec![
                Record {
                    cell: NOWHERE,
                    ..Record::default()
                };
                n
            ],
            dependents: vec![Vec::new(); n],
            round: 0,
        }
    }

    /// Puts every ball in its cell and predicts it from time `t`.
    pub fn predict_all(&mut self, scene: &Scene, queue: &mut Tournament<Pending>, t: f64) {
        self.round += 1;
        for deps in &mut self.dependents {
            deps.clear();
        }
        let segments = scene.segments;
        for (id, seg) in segments.iter().enumerate() {
            let on_table = seg.state.motion.on_table();
            let from = self.balls[id].cell();
            let cell = self
                .grid
                .set(id, from, on_table.then(|| seg.position_at(t)));
            self.balls[id].set_cell(cell);
            self.set_path(scene, id, t);
        }
        for id in 0..segments.len() {
            self.predict(scene, queue, id, t);
        }
    }

    /// Re-predicts the balls an event changed, and every ball whose cached event was a
    /// contact with one of them; all other predictions stay valid.
    #[inline]
    pub fn repredict<const N: usize>(
        &mut self,
        scene: &Scene,
        queue: &mut Tournament<Pending>,
        touched: &[BallId; N],
        t: f64,
    ) {
        self.round += 1;
        for &id in touched {
            let seg = &scene.segments[id];
            let on_table = seg.state.motion.on_table();
            let from = self.balls[id].cell();
            let cell = self
                .grid
                .set(id, from, on_table.then_some(seg.state.position));
            self.balls[id].set_cell(cell);
            self.set_path(scene, id, t);
        }
        for &id in touched {
            self.predict(scene, queue, id, t);
        }
        for &id in touched {
            for m in std::mem::take(&mut self.dependents[id]) {
                let stale = self.balls[m].pair.is_some_and(|p| p.involves(id));
                if !stale {
                    continue;
                }
                if self.balls[m].stamp == self.round {
                    // Re-predicted earlier in this round (say, as a dependent of another
                    // touched ball) and now waiting on `id`: keep the link, or the next change
                    // of `id` leaves `m`'s pair event stale and it fires at a gap.
                    self.dependents[id].push(m);
                } else {
                    self.predict(scene, queue, m, t);
                }
            }
        }
    }

    /// Ball `id` leaves its cell through `side` at time `t`: it is tested against the balls
    /// of the cells that come into its neighbourhood only (its contacts with the others were
    /// searched beyond this crossing, and are kept).
    pub fn cross(
        &mut self,
        scene: &Scene,
        queue: &mut Tournament<Pending>,
        id: BallId,
        side: Side,
        t: f64,
    ) {
        self.round += 1;
        if let Some(from) = self.balls[id].cell() {
            let cell = self.grid.cross(id, from, side);
            if cell != from {
                self.balls[id].set_cell(Some(cell));
                let best = self.balls[id].pair;
                let found = self.search(scene, id, t, best, self.grid.entered(Some(cell), side));
                self.balls[id].pair = found;
            }
        }
        self.set_cache(queue, scene, id, t);
    }

    /// Ball `id`'s segment changed: its events with no other ball and its path.
    fn set_path(&mut self, scene: &Scene, id: BallId, t: f64) {
        let seg = &scene.segments[id];
        let solo = scene.predict_solo(id, t);
        let m = seg.state.motion;
        let ball = &mut self.balls[id];
        ball.path = Path {
            start: seg.start,
            p: seg.state.position,
            v: seg.state.velocity,
            a: match scene.kinematics() {
                Kinematics::Exact => seg.acceleration,
                Kinematics::Linear => Vec2::ZERO,
            },
            until: solo.map_or(f64::INFINITY, |p| p.time),
        };
        let flags =
            if m.is_moving() { MOVING } else { 0 } | if m.on_table() { ON_TABLE } else { 0 };
        ball.solo = Solo::pack(solo, id, flags);
        ball.end = seg.end.unwrap_or(f64::INFINITY);
    }

    /// Stores ball `id`'s earliest event (its own, its next crossing, its best pair) and
    /// indexes its best pair under the partner.
    fn set_cache(&mut self, queue: &mut Tournament<Pending>, scene: &Scene, id: BallId, t: f64) {
        self.balls[id].stamp = self.round;
        let ball = &self.balls[id];
        let (pair, solo) = (ball.pair, ball.solo.unpack(id, ball.path.until));
        let p = earlier(earlier(solo, self.crossing(scene, id, t)), pair);
        queue.set(id, p, rank(p));
        if let Some(partner) = pair.and_then(|p| p.partner(id)) {
            let deps = &mut self.dependents[partner];
            deps.push(id);
            if deps.len() > 64 {
                // Drop stale entries so the list stays short in long runs.
                let balls = &self.balls;
                deps.retain(|&m| balls[m].pair.is_some_and(|q| q.involves(partner)));
                deps.sort_unstable();
                deps.dedup();
            }
        }
    }

    /// Predicts ball `id` from `t` in full: its pairs with every ball around it.
    fn predict(&mut self, scene: &Scene, queue: &mut Tournament<Pending>, id: BallId, t: f64) {
        let cell = self.balls[id].cell();
        let found = self.search(scene, id, t, None, self.grid.neighbours(cell));
        self.balls[id].pair = found;
        self.set_cache(queue, scene, id, t);
    }

    /// The earliest contact of ball `id` from `t` on with a ball of `others` (ball `id`
    /// itself and balls out of play skipped), or `best` if none is earlier. A pair is
    /// searched only up to the earlier of its balls' next events with no other ball and the
    /// best contact found so far, and only if [`detect::misses`] keeps it.
    fn search(
        &self,
        scene: &Scene,
        id: BallId,
        t: f64,
        mut best: Option<Pending>,
        others: impl Iterator<Item = BallId>,
    ) -> Option<Pending> {
        let fi = self.balls[id].solo.flags;
        let me = self.balls[id].path;
        if fi & ON_TABLE == 0 {
            return None;
        }
        let seg = &scene.segments[id];
        let kin = scene.kinematics();
        let r = scene.params.ball.radius;
        let contact = 2.0 * r;
        let (pi, vi) = me.at(t);
        for j in others {
            // Only balls on the table are in the grid (`Grid::set` and `set_path` see the same
            // segment), so `j` is; and its flags (another cache line) are read only when ball
            // `id` stands still, to skip a pair of which neither ball moves.
            if j == id || (fi & MOVING == 0 && self.balls[j].solo.flags & MOVING == 0) {
                continue;
            }
            debug_assert!(
                self.balls[j].solo.flags & ON_TABLE != 0,
                "ball {j} in the grid"
            );
            let other = self.balls[j].path;
            let until = if other.until < me.until {
                other.until
            } else {
                me.until
            };
            // Capped by the best contact so far, a few ulps wide so that a pair touching at
            // the same instant is still found (and wins if it ranks first); not capped by a
            // best at `t` itself, where a zero horizon would miss contacts of this instant.
            let h = until - t;
            let h = match best {
                Some(b) if b.time > t => h.min((b.time - t) * (1.0 + 1e-12)),
                _ => h,
            };
            let (pj, vj) = other.at(t);
            if detect::misses(pj - pi, vj - vi, other.a - me.a, contact, h) {
                continue;
            }
            let segj = &scene.segments[j];
            if let Some(tau) = detect::ball_ball_kept(seg, segj, t, r, h, kin) {
                let (a, b) = (id.min(j), id.max(j));
                best = earlier(
                    best,
                    Some(Pending {
                        time: t + tau,
                        kind: PendingKind::Pair(a, b),
                    }),
                );
            }
        }
        best
    }

    /// When moving ball `id` first leaves its cell after `t`, if it does.
    fn crossing(&self, scene: &Scene, id: BallId, t: f64) -> Option<Pending> {
        let ball = &self.balls[id];
        if ball.solo.flags & MOVING == 0 {
            return None;
        }
        // `end - t` is infinite for a segment that never ends, as `Segment::end`'s `None`.
        let horizon = ball.end - t;
        // The state once for every side, as `detect::ball_line` computes it for each; the
        // real path even in the linear comparison mode (where the record's acceleration is
        // zero, so the segment is read). `Path::at` is `Segment::position_at` and
        // `velocity_at` to the bit.
        let (p, v, a) = match scene.kinematics() {
            Kinematics::Exact => {
                let (p, v) = ball.path.at(t);
                (p, v, ball.path.a)
            }
            Kinematics::Linear => {
                let seg = &scene.segments[id];
                (seg.position_at(t), seg.velocity_at(t), seg.acceleration)
            }
        };
        let mut best = None;
        for (side, at) in self.grid.exits(ball.cell()) {
            let (n, offset) = match side {
                Side::XPlus => (Vec2::new(-1.0, 0.0), at),
                Side::XMinus => (Vec2::new(1.0, 0.0), -at),
                Side::YPlus => (Vec2::new(0.0, -1.0), at),
                Side::YMinus => (Vec2::new(0.0, 1.0), -at),
            };
            if let Some(tau) = detect::line_contact(p, v, a, n, offset, horizon) {
                best = earlier(
                    best,
                    Some(Pending {
                        time: t + tau,
                        kind: PendingKind::Crossing(id, side),
                    }),
                );
            }
        }
        best
    }
}
