//! The prediction strategy of scenes in one cell (fewer than 250 balls): a table of every
//! pair's contact time, valid until either ball's segment changes. An event re-solves only
//! the pairs of the balls it touched (most culled in one vectorized pass over the other
//! balls), and every other ball takes its best from its row of the table.

use super::pending::{Pending, PendingKind, earlier, rank};
use super::scene::Scene;
use crate::ball::BallId;
use crate::detect::{
    self,
    cull::{PathColumns, kept},
};
use crate::queue::Tournament;

/// The pair table and what keeps it cheap to update.
#[derive(Debug)]
pub(super) struct PairTable {
    /// Each ball's earliest event with no other ball (transition, cushion, jaw, opening).
    solo: Vec<Option<Pending>>,
    /// Contact time of each pair (`n * n`, both halves, infinity for none), valid until
    /// either ball's segment changes.
    contact_times: Vec<f64>,
    /// Every ball's segment, for the batched cull of a row of pairs.
    paths: PathColumns,
    /// The verdicts of the last [`PathColumns::cull_row`] (positive: cannot touch).
    clearance: Vec<f64>,
    /// Scratch: balls whose pair with a touched ball changed in this event.
    changed_partners: Vec<BallId>,
}

clone_reusing!(PairTable {
    solo,
    contact_times,
    paths,
    clearance,
    changed_partners
});

impl PairTable {
    /// An empty table for `n` balls (filled by [`PairTable::predict_all`]).
    pub fn new(n: usize) -> Self {
        Self {
            solo: vec![None; n],
            contact_times: Vec::new(),
            paths: PathColumns::default(),
            clearance: Vec::new(),
            changed_partners: Vec::new(),
        }
    }

    /// Solves every pair and every ball's own events from time `t`.
    pub fn predict_all(&mut self, scene: &Scene, queue: &mut Tournament<Pending>, t: f64) {
        let n = scene.segments.len();
        self.contact_times = vec![f64::INFINITY; n * n];
        for id in 0..n {
            self.solo[id] = scene.predict_solo(id, t);
        }
        self.paths = PathColumns::new(n);
        self.clearance = vec![0.0; n];
        for id in 0..n {
            let until = self.solo[id].map_or(f64::INFINITY, |p| p.time);
            self.paths.set(id, &scene.segments[id], until);
        }
        let contact = 2.0 * scene.params.ball.radius;
        for i in 0..n {
            if self.paths.moving_on_table(i) {
                self.paths.cull_row(&mut self.clearance, i, t, contact);
            } else {
                self.clearance.fill(f64::NEG_INFINITY);
            }
            for j in i + 1..n {
                let time = self.solve_pair(scene, i, j, t, kept(self.clearance[j]));
                self.set_pair(n, i, j, time);
            }
        }
        for id in 0..n {
            let p = self.best_of_row(n, id);
            queue.set(id, p, rank(p));
        }
    }

    /// Re-solves the own events of the touched balls and every pair containing one of them,
    /// then updates the best of the touched balls and of every ball whose pair with one of
    /// them changed.
    #[inline]
    pub fn repredict<const N: usize>(
        &mut self,
        scene: &Scene,
        queue: &mut Tournament<Pending>,
        touched: &[BallId; N],
        t: f64,
    ) {
        for &id in touched {
            self.solo[id] = scene.predict_solo(id, t);
            let until = self.solo[id].map_or(f64::INFINITY, |p| p.time);
            self.paths.set(id, &scene.segments[id], until);
        }
        let mut changed = std::mem::take(&mut self.changed_partners);
        changed.clear();
        let rows = self.solve_rows(scene, touched, t, &mut changed);
        let n = scene.segments.len();
        for (&id, &(least, at)) in touched.iter().zip(&rows) {
            let pair = (least < f64::INFINITY).then(|| Pending {
                time: least,
                kind: PendingKind::Pair(id.min(at), id.max(at)),
            });
            let p = earlier(self.solo[id], pair);
            debug_assert_eq!(p, self.best_of_row(n, id));
            queue.set(id, p, rank(p));
        }
        self.update_partners(queue, n, touched, &changed);
        self.changed_partners = changed;
    }

    /// Re-solves every pair of each touched ball, pushing to `changed` each partner whose
    /// contact time changed. Returns each touched ball's earliest pair (time and partner),
    /// found while its row is worked through: entries left out are infinite (culled, and no
    /// contact before), and scanning partners in ascending order with a strict comparison
    /// picks the same pair as [`PairTable::best_of_row`].
    #[inline]
    fn solve_rows<const N: usize>(
        &mut self,
        scene: &Scene,
        touched: &[BallId; N],
        t: f64,
        changed: &mut Vec<BallId>,
    ) -> [(f64, BallId); N] {
        let n = scene.segments.len();
        let contact = 2.0 * scene.params.ball.radius;
        let mut rows = [(f64::INFINITY, 0); N];
        for (k, &id) in touched.iter().enumerate() {
            if self.paths.moving_on_table(id) {
                self.paths.cull_row(&mut self.clearance, id, t, contact);
            } else {
                self.clearance.fill(f64::NEG_INFINITY);
            }
            let (mut least, mut at) = (f64::INFINITY, 0);
            let mut base = 0;
            while base < n {
                // Most pairs are culled and had no contact before either: nothing changes for
                // them. Mark the others, 64 at a time in a tight loop (the row's later entries
                // are not written while this block is worked through).
                let end = n.min(base + 64);
                let clearance = &self.clearance[base..end];
                let row = &self.contact_times[id * n + base..id * n + end];
                let mut mask = 0u64;
                for (b, (&c, &p)) in clearance.iter().zip(row).enumerate() {
                    let skip = (c > 0.0) & (p == f64::INFINITY);
                    mask |= u64::from(!skip) << b;
                }
                // Not the ball with itself (its clearance is negative).
                if (base..end).contains(&id) {
                    mask &= !(1 << (id - base));
                }
                while mask != 0 {
                    let j = base + mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    // A pair of two touched balls is solved once.
                    let time = if touched[..k].contains(&j) {
                        self.contact_times[id * n + j]
                    } else {
                        let time = self.solve_pair(scene, id, j, t, kept(self.clearance[j]));
                        if time != self.contact_times[id * n + j] {
                            self.set_pair(n, id, j, time);
                            changed.push(j);
                        }
                        time
                    };
                    if time < least {
                        (least, at) = (time, j);
                    }
                }
                base = end;
            }
            rows[k] = (least, at);
        }
        rows
    }

    /// Updates the best of every ball in `changed` (a partner of a touched ball whose contact
    /// time with it changed). A ball may appear twice (paired with both touched balls):
    /// updating it is idempotent.
    #[inline]
    fn update_partners<const N: usize>(
        &self,
        queue: &mut Tournament<Pending>,
        n: usize,
        touched: &[BallId; N],
        changed: &[BallId],
    ) {
        for &j in changed {
            if touched.contains(&j) {
                continue;
            }
            let cur = queue.get(j);
            let stale = matches!(cur, Some(Pending { kind: PendingKind::Pair(a, b), .. })
                    if touched.contains(&a) || touched.contains(&b));
            if stale {
                let p = self.best_of_row(n, j);
                queue.set(j, p, rank(p));
                continue;
            }
            // Only the touched balls' pairs changed, and the best was none of them.
            let mut best = queue.rank(j);
            let mut found = None;
            for &id in touched {
                let time = self.contact_times[j * n + id];
                if time < f64::INFINITY {
                    let kind = PendingKind::Pair(id.min(j), id.max(j));
                    let p = Pending { time, kind };
                    if p.rank() < best {
                        (best, found) = (p.rank(), Some(p));
                    }
                }
            }
            if found.is_some() {
                queue.set(j, found, best);
            }
        }
    }

    /// Contact time of balls `i` and `j` from time `t` on (infinity for none), searched only
    /// up to the earlier of their own next events: each of those changes a segment (there are
    /// no crossings in a single cell) and wins ties, so a later contact could never happen.
    /// `keep` is the cull's verdict ([`PathColumns::cull_row`]): a culled pair has no contact.
    #[inline]
    fn solve_pair(&self, scene: &Scene, i: BallId, j: BallId, t: f64, keep: bool) -> f64 {
        let paths = &self.paths;
        if !keep || !paths.may_meet(i, j) {
            return f64::INFINITY;
        }
        let h = paths.until(i).min(paths.until(j)) - t;
        let (si, sj) = (&scene.segments[i], &scene.segments[j]);
        let r = scene.params.ball.radius;
        detect::ball_ball_kept(si, sj, t, r, h, scene.kinematics())
            .map_or(f64::INFINITY, |tau| t + tau)
    }

    /// Ball `id`'s earliest event from the pair table (of `n` balls) and its own events.
    /// Scanning partners in ascending order with a strict comparison keeps the tie order of
    /// [`Pending::key`].
    fn best_of_row(&self, n: usize, id: BallId) -> Option<Pending> {
        let row = &self.contact_times[id * n..(id + 1) * n];
        // The first of the smallest times below infinity, as a scan with a strict comparison
        // finds it (NaNs never win), in two passes that vectorize: the smallest time in four
        // independent lanes (the order of a minimum does not matter), then its first index.
        let mut lanes = [f64::INFINITY; 4];
        let mut chunks = row.chunks_exact(4);
        for c in &mut chunks {
            for (m, &x) in lanes.iter_mut().zip(c) {
                *m = if x < *m { x } else { *m };
            }
        }
        let mut least = f64::INFINITY;
        for &x in lanes.iter().chain(chunks.remainder()) {
            least = if x < least { x } else { least };
        }
        let pair = if least < f64::INFINITY {
            row.iter().position(|&x| x == least).map(|k| Pending {
                time: row[k],
                kind: PendingKind::Pair(id.min(k), id.max(k)),
            })
        } else {
            None
        };
        earlier(self.solo[id], pair)
    }

    /// Stores a pair's contact time in both halves of the table (of `n` balls).
    #[inline]
    fn set_pair(&mut self, n: usize, i: BallId, j: BallId, time: f64) {
        self.contact_times[i * n + j] = time;
        self.contact_times[j * n + i] = time;
    }
}
