//! The prediction strategy of scenes split into cells (64 balls or more): each ball is tested
//! only against the balls in the cells around it ([`Grid`]), leaving its cell is an event,
//! and an event re-predicts the balls it touched in full and every ball whose cached event
//! was a contact with one of them (found through a dependents index, not a scan).

use super::pending::{Pending, PendingKind, earlier, rank};
use super::predict::Scene;
use crate::ball::BallId;
use crate::detect::{self, Kinematics};
use crate::grid::{Grid, Side};
use crate::math::Vec2;
use crate::queue::Tournament;

/// The cell lists and the index of which predictions depend on which ball.
#[derive(Debug)]
pub(super) struct CellLists {
    grid: Grid,
    /// For each ball, the balls whose cached event is a contact with it (may hold stale
    /// entries; checked before use).
    dependents: Vec<Vec<BallId>>,
    /// Stamp of the prediction round that last predicted each ball.
    stamps: Vec<u64>,
    /// The current prediction round.
    round: u64,
}

clone_reusing!(CellLists {
    grid,
    dependents,
    stamps,
    round
});

impl CellLists {
    /// Cell lists over `grid` for `n` balls (filled by [`CellLists::predict_all`]).
    pub fn new(grid: Grid, n: usize) -> Self {
        Self {
            grid,
            dependents: vec![Vec::new(); n],
            stamps: vec![0; n],
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
            self.grid.set(id, on_table.then(|| seg.position_at(t)));
        }
        for id in 0..segments.len() {
            let p = self.predict(scene, id, t);
            self.set_cache(queue, id, p);
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
            self.grid.set(id, on_table.then_some(seg.state.position));
            let p = self.predict(scene, id, t);
            self.set_cache(queue, id, p);
        }
        for &id in touched {
            for m in std::mem::take(&mut self.dependents[id]) {
                let stale = queue.get(m).is_some_and(|p| p.involves(id));
                if !stale {
                    continue;
                }
                if self.stamps[m] == self.round {
                    // Re-predicted earlier in this round (say, as a dependent of another
                    // touched ball) and now waiting on `id`: keep the link, or the next change
                    // of `id` leaves `m`'s pair event stale and it fires at a gap.
                    self.dependents[id].push(m);
                } else {
                    let p = self.predict(scene, m, t);
                    self.set_cache(queue, m, p);
                }
            }
        }
    }

    /// Ball `id` leaves its cell through `side` at time `t`: it is tested against its new
    /// neighbours.
    pub fn cross(
        &mut self,
        scene: &Scene,
        queue: &mut Tournament<Pending>,
        id: BallId,
        side: Side,
        t: f64,
    ) {
        self.grid.cross(id, side);
        self.round += 1;
        let p = self.predict(scene, id, t);
        self.set_cache(queue, id, p);
    }

    /// Stores ball `id`'s prediction and indexes it under its partner, if any.
    fn set_cache(&mut self, queue: &mut Tournament<Pending>, id: BallId, p: Option<Pending>) {
        self.stamps[id] = self.round;
        queue.set(id, p, rank(p));
        if let Some(partner) = p.and_then(|p| p.partner(id)) {
            let deps = &mut self.dependents[partner];
            deps.push(id);
            if deps.len() > 64 {
                // Drop stale entries so the list stays short in long runs.
                deps.retain(|&m| queue.get(m).is_some_and(|q| q.involves(partner)));
                deps.sort_unstable();
                deps.dedup();
            }
        }
    }

    /// The earliest event of ball `id` from time `t` on: its own events, a grid crossing, or
    /// a contact with any other ball in play in the cells around it.
    fn predict(&self, scene: &Scene, id: BallId, t: f64) -> Option<Pending> {
        let seg = &scene.segments[id];
        if !seg.state.motion.on_table() {
            return None;
        }
        let kin = scene.kinematics();
        let horizon = seg.end.map_or(f64::INFINITY, |e| e - t);
        let mut best = earlier(scene.predict_solo(id, t), self.crossing(scene, id, t));
        let r = scene.params.ball.radius;
        for j in self.grid.neighbours(id) {
            let other = &scene.segments[j];
            if j == id || !other.state.motion.on_table() {
                continue;
            }
            let h = other.end.map_or(horizon, |e| horizon.min(e - t));
            // Only a pair that could be earlier than the best so far is worth solving.
            let h = best.map_or(h, |b| h.min(b.time - t));
            if let Some(tau) = detect::ball_ball(seg, other, t, r, h, kin) {
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
        let seg = &scene.segments[id];
        if !seg.state.motion.is_moving() {
            return None;
        }
        let horizon = seg.end.map_or(f64::INFINITY, |e| e - t);
        let mut best = None;
        for (side, at) in self.grid.exits(id) {
            let (n, offset) = match side {
                Side::XPlus => (Vec2::new(-1.0, 0.0), at),
                Side::XMinus => (Vec2::new(1.0, 0.0), -at),
                Side::YPlus => (Vec2::new(0.0, -1.0), at),
                Side::YMinus => (Vec2::new(0.0, 1.0), -at),
            };
            // Crossings follow the real path even in the linear comparison mode.
            if let Some(tau) = detect::ball_line(seg, t, n, offset, horizon, Kinematics::Exact) {
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
