//! What a prediction reads: the balls' segments, the parameters and the fixed bodies
//! ([`Scene`]), and a ball's next event with no other ball in it ([`Scene::predict_solo`]).
//! The strategies that find contacts between balls (`pair_table.rs`, `cell_lists.rs`) and
//! the cache over them (`predict.rs`) all read it.

use super::path_box::PathBox;
use super::pending::{Pending, PendingKind, earlier};
use crate::ball::{BallId, Segment};
use crate::detect::{self, Kinematics};
use crate::math::Vec2;
use crate::params::{Params, Prediction};
use crate::table::{Cushion, Jaw, Opening, PocketShape, Table};
use std::hint::select_unpredictable;

/// The fixed bodies a ball can meet: the cushions (as the bounds of its centre), the pocket
/// jaws and openings (empty unless the table has jaws: none with the paper's mouths or
/// without pockets).
#[derive(Debug)]
pub(super) struct Bodies {
    /// The table.
    pub table: Table,
    /// Half extents of the area a ball's centre may occupy.
    pub bounds: Vec2,
    /// The table's jaws.
    pub jaws: Vec<Jaw>,
    /// The table's pocket openings.
    pub openings: Vec<Opening>,
    /// Around each opening, the box a centre must enter to cross it: its pocket's two jaw
    /// centres, widened by a ball and a jaw radius and 1 cm. Beyond it the opening line runs
    /// behind the cushions, which a ball meets first; and a centre outside it is more than a
    /// ball and a jaw radius from both jaws.
    pub opening_regions: Vec<PathBox>,
    /// For each jaw, the index of its pocket's opening (and region).
    pub jaw_regions: Vec<usize>,
}

clone_reusing!(Bodies {
    table,
    bounds,
    jaws,
    openings,
    opening_regions,
    jaw_regions
});

impl Bodies {
    /// The bodies of `table` for balls of radius `radius`.
    pub fn new(table: Table, radius: f64) -> Self {
        let mut bodies = Self {
            table,
            bounds: table.centre_bounds(radius),
            jaws: table.jaws(),
            openings: match table.pockets {
                PocketShape::Mouth | PocketShape::Pocketless => Vec::new(),
                PocketShape::Jaws { .. } => table.openings().to_vec(),
            },
            opening_regions: Vec::new(),
            jaw_regions: Vec::new(),
        };
        let widen = radius + bodies.jaw_radius() + 0.01;
        let jaws = &bodies.jaws;
        bodies.opening_regions = bodies
            .openings
            .iter()
            .map(|o| {
                let ends = jaws.iter().filter(|j| j.pocket == o.pocket);
                PathBox::around(ends.map(|j| j.centre), widen)
            })
            .collect();
        bodies.jaw_regions = jaws
            .iter()
            .map(|j| {
                let k = bodies.openings.iter().position(|o| o.pocket == j.pocket);
                k.expect("every pocket with jaws has an opening")
            })
            .collect();
        bodies
    }

    /// How far the centre may go from the table's centre line towards `cushion`.
    #[inline]
    pub fn cushion_limit(&self, cushion: Cushion) -> f64 {
        match cushion {
            Cushion::Head | Cushion::Foot => self.bounds.x,
            Cushion::Left | Cushion::Right => self.bounds.y,
        }
    }

    /// Radius of the jaws (zero for the paper's mouths).
    #[inline]
    pub fn jaw_radius(&self) -> f64 {
        match self.table.pockets {
            PocketShape::Jaws { radius } => radius,
            PocketShape::Mouth | PocketShape::Pocketless => 0.0,
        }
    }
}

/// What a prediction reads: the balls' segments, the parameters and the fixed bodies.
pub(super) struct Scene<'a> {
    /// Every ball's current segment.
    pub segments: &'a [Segment],
    /// The parameters in force.
    pub params: &'a Params,
    /// The fixed bodies.
    pub bodies: &'a Bodies,
}

impl Scene<'_> {
    /// How times of impact are predicted.
    #[inline]
    pub fn kinematics(&self) -> Kinematics {
        match self.params.prediction {
            Prediction::Exact => Kinematics::Exact,
            Prediction::PaperLinear => Kinematics::Linear,
        }
    }

    /// The earliest event of ball `id` from time `t` on that involves no other ball: its own
    /// transition, a cushion, a jaw or a pocket opening (each searched only up to the
    /// earliest found so far where that saves work).
    pub fn predict_solo(&self, id: BallId, t: f64) -> Option<Pending> {
        let seg = &self.segments[id];
        if !seg.state.motion.on_table() {
            return None;
        }
        let horizon = seg.end.map_or(f64::INFINITY, |e| e - t);
        let best = seg.end.map(|end| Pending {
            time: end,
            kind: PendingKind::Transition(id),
        });
        if !seg.state.motion.is_moving() {
            return best;
        }
        let bounds = PathBox::of(seg, t, horizon);
        // The pockets whose region the path box comes into (bit k: opening k), tested once
        // for the pocket's two jaws and its opening; every pocket without a box.
        let near = bounds.map_or(u64::MAX, |b| {
            let regions = self.bodies.opening_regions.iter().enumerate();
            regions.fold(0, |m, (k, r)| m | (u64::from(!b.apart(r, 0.0)) << k))
        });
        // The linear prediction searches cushions and jaws along another path than the box's.
        let exact = bounds.filter(|_| self.kinematics() == Kinematics::Exact);
        let best = earlier(best, self.cushion(id, t, horizon, exact));
        let jaws_near = if exact.is_some() { near } else { u64::MAX };
        let best = self.jaw(id, t, horizon, best, exact, jaws_near);
        earlier(best, self.opening(id, t, horizon, bounds, near))
    }

    /// The first cushion contact of moving ball `id` after `t`, within `horizon` seconds.
    #[inline]
    fn cushion(
        &self,
        id: BallId,
        t: f64,
        horizon: f64,
        bounds: Option<PathBox>,
    ) -> Option<Pending> {
        let seg = &self.segments[id];
        // The ball's state once for all four cushions (`cushion_contact` starts at `t + 0.0`
        // too); `line_contact` skips a cushion the ball leaves for good before any root.
        let v = seg.velocity_at(t + 0.0);
        let a = match self.kinematics() {
            Kinematics::Exact => seg.acceleration,
            Kinematics::Linear => Vec2::ZERO,
        };
        let p = seg.position_at(t + 0.0);
        // A ball decelerating along its velocity stops before it could turn back
        // (`Segment::straight`): only the cushion of each pair ahead of it (`n·v < 0`) is
        // searched, picked by the signs of the velocity without a branch on them (which
        // would be as good as random).
        let ahead = [
            (v.x != 0.0).then_some(select_unpredictable(
                v.x < 0.0,
                Cushion::Head,
                Cushion::Foot,
            )),
            (v.y != 0.0).then_some(select_unpredictable(
                v.y > 0.0,
                Cushion::Left,
                Cushion::Right,
            )),
        ];
        let all = Cushion::ALL.map(Some);
        let straight = seg.straight && v.x.is_finite() && v.y.is_finite();
        let cushions: &[Option<Cushion>] = if straight { &ahead } else { &all };
        let (table, mut best) = (&self.bodies.table, None);
        for &c in cushions.iter().flatten() {
            let limit = self.bodies.cushion_limit(c);
            if bounds.is_some_and(|b| b.clear_of_line(c.inward_normal(), limit)) {
                continue;
            }
            let Some(tau) = detect::cushion_contact(seg, t, (p, v, a), c, limit, table, horizon)
            else {
                continue;
            };
            best = earlier(
                best,
                Some(Pending {
                    time: t + tau,
                    kind: PendingKind::Cushion(id, c),
                }),
            );
        }
        best
    }

    /// The first jaw contact of moving ball `id` after `t` if earlier than `best`, searched
    /// only up to `best`; the earlier of the two. Only the jaws of the pockets in `near`
    /// (bit k: opening k) are looked at.
    #[inline]
    fn jaw(
        &self,
        id: BallId,
        t: f64,
        horizon: f64,
        mut best: Option<Pending>,
        bounds: Option<PathBox>,
        near: u64,
    ) -> Option<Pending> {
        let seg = &self.segments[id];
        let kin = self.kinematics();
        let jaw_contact = self.params.ball.radius + self.bodies.jaw_radius();
        let regions = &self.bodies.jaw_regions;
        for (k, (jaw, &region)) in self.bodies.jaws.iter().zip(regions).enumerate() {
            if near & (1 << region) == 0
                || bounds.is_some_and(|b| b.clear_of_point(jaw.centre, jaw_contact))
            {
                continue;
            }
            let h = best.map_or(horizon, |b| horizon.min(b.time - t));
            if let Some(tau) = detect::ball_jaw(seg, t, jaw.centre, jaw_contact, h, kin) {
                let kind = PendingKind::Jaw(id, k);
                best = earlier(
                    best,
                    Some(Pending {
                        time: t + tau,
                        kind,
                    }),
                );
            }
        }
        best
    }

    /// When moving ball `id`'s centre first crosses a pocket opening after `t`, among the
    /// openings in `near` (bit k: opening k).
    #[inline]
    fn opening(
        &self,
        id: BallId,
        t: f64,
        horizon: f64,
        bounds: Option<PathBox>,
        near: u64,
    ) -> Option<Pending> {
        let seg = &self.segments[id];
        let mut best = None;
        for (k, o) in self.bodies.openings.iter().enumerate() {
            if near & (1 << k) == 0 || bounds.is_some_and(|b| b.clear_of_line(o.normal, o.offset)) {
                continue;
            }
            // The real path decides when a ball drops, even in the linear comparison mode.
            let exact = Kinematics::Exact;
            if let Some(tau) = detect::ball_line(seg, t, o.normal, o.offset, horizon, exact) {
                let kind = PendingKind::Opening(id, k);
                best = earlier(
                    best,
                    Some(Pending {
                        time: t + tau,
                        kind,
                    }),
                );
            }
        }
        best
    }
}
