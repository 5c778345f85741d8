//! Prediction: each ball's earliest next event, cached until an event changes it or its
//! partner, and the earliest of them all. A ball's events with no other ball are found here
//! ([`Scene::predict_solo`]); its contacts with other balls by one of two strategies, chosen
//! by the size of the scene ([`Strategy`]).

use super::cell_lists::CellLists;
use super::pair_table::PairTable;
use super::path_box::PathBox;
use super::pending::{Pending, PendingKind, earlier};
use crate::ball::{BallId, Segment};
use crate::detect::{self, Kinematics};
use crate::grid::{Grid, Side};
use crate::math::Vec2;
use crate::params::{Params, Prediction};
use crate::queue::Tournament;
use crate::table::{Cushion, Jaw, Opening, PocketShape, Table};
use std::hint::select_unpredictable;

/// The fixed bodies a ball can meet: the cushions (as the bounds of its centre), the pocket
/// jaws and openings (empty unless the table has jaws).
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
                PocketShape::Mouth => Vec::new(),
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
            PocketShape::Mouth => 0.0,
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

/// Which strategy finds contacts between balls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum StrategyChoice {
    /// By the size of the scene: the pair table below 250 balls, cell lists from there on.
    Auto,
    /// The pair table, whatever the size (tests).
    #[cfg_attr(not(test), allow(dead_code))]
    PairTable,
    /// Cell lists on a grid split into several cells, whatever the size (tests).
    #[cfg_attr(not(test), allow(dead_code))]
    CellLists,
}

/// How contacts between balls are found; each variant holds the data valid for it only.
#[derive(Debug)]
pub(super) enum Strategy {
    /// Scenes in one cell: every pair's contact time in a table.
    PairTable(PairTable),
    /// Scenes split into cells: each ball against the balls in the cells around it.
    CellLists(CellLists),
}

impl Clone for Strategy {
    fn clone(&self) -> Self {
        match self {
            Self::PairTable(s) => Self::PairTable(s.clone()),
            Self::CellLists(s) => Self::CellLists(s.clone()),
        }
    }

    /// Reuses the buffers of the same strategy (see `clone_reusing!`).
    fn clone_from(&mut self, source: &Self) {
        match (self, source) {
            (Self::PairTable(a), Self::PairTable(b)) => a.clone_from(b),
            (Self::CellLists(a), Self::CellLists(b)) => a.clone_from(b),
            (this, source) => *this = source.clone(),
        }
    }
}

/// Every ball's cached earliest event, the earliest of them all, and the strategy that keeps
/// them up to date.
#[derive(Debug)]
pub(super) struct Predictions {
    /// Each ball's earliest predicted event, and the earliest of them all.
    queue: Tournament<Pending>,
    strategy: Strategy,
}

clone_reusing!(Predictions { queue, strategy });

impl Predictions {
    /// Empty predictions for `n` balls on a table whose centres stay within `bounds`, with
    /// the strategy `choice` asks for (filled by [`Predictions::predict_all`]).
    pub fn new(n: usize, bounds: Vec2, radius: f64, choice: StrategyChoice) -> Self {
        let grid = match choice {
            StrategyChoice::Auto => Some(Grid::new(bounds, radius, n)).filter(Grid::is_split),
            StrategyChoice::PairTable => None,
            StrategyChoice::CellLists => Some(Grid::split(bounds, radius, n)),
        };
        let strategy = match grid {
            Some(grid) => Strategy::CellLists(CellLists::new(grid, n)),
            None => Strategy::PairTable(PairTable::new(n)),
        };
        Self {
            queue: Tournament::new(n),
            strategy,
        }
    }

    /// The earliest predicted event.
    #[inline]
    pub fn next(&self) -> Option<Pending> {
        self.queue.best().map(|(_, p)| p)
    }

    /// Predicts every ball from time `t`.
    pub fn predict_all(&mut self, scene: &Scene, t: f64) {
        match &mut self.strategy {
            Strategy::PairTable(s) => s.predict_all(scene, &mut self.queue, t),
            Strategy::CellLists(s) => s.predict_all(scene, &mut self.queue, t),
        }
    }

    /// Re-predicts after an event at `t` changed the balls `touched`. `N` (one or two balls)
    /// is a constant, so that every loop over the touched balls is unrolled rather than a
    /// branch on how many there are.
    #[inline]
    pub fn repredict<const N: usize>(&mut self, scene: &Scene, touched: [BallId; N], t: f64) {
        match &mut self.strategy {
            Strategy::PairTable(s) => s.repredict(scene, &mut self.queue, &touched, t),
            Strategy::CellLists(s) => s.repredict(scene, &mut self.queue, &touched, t),
        }
    }

    /// Ball `id` leaves its grid cell through `side` at `t` (only the cell lists predict
    /// such events).
    pub fn cross(&mut self, scene: &Scene, id: BallId, side: Side, t: f64) {
        match &mut self.strategy {
            Strategy::CellLists(s) => s.cross(scene, &mut self.queue, id, side, t),
            Strategy::PairTable(_) => unreachable!("a pair table predicts no grid crossings"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{Model, SpinModel};
    use crate::racks::{self, Rack};
    use crate::sim::{BallSetup, Simulation};
    use crate::soak;

    /// How often the two strategies agreed: exactly, within rounding of the time, or only
    /// on the time (two events within rounding of each other, whose order rounding decides).
    #[derive(Debug, Default)]
    struct Agreement {
        exact: usize,
        close: usize,
        ties: usize,
    }

    /// The next physical event of `sim`, processing grid crossings (bookkeeping) on the way.
    fn next_physical(sim: &mut Simulation) -> Option<Pending> {
        loop {
            let p = sim.predictions.next()?;
            if !matches!(p.kind, PendingKind::Crossing(..)) {
                return Some(p);
            }
            sim.process(p);
        }
    }

    /// `sim` with its predictions made from scratch by the strategy `choice`.
    fn predicted_afresh(sim: &Simulation, choice: StrategyChoice) -> Simulation {
        let mut fresh = sim.clone();
        let (n, r) = (sim.ball_count(), sim.params.ball.radius);
        fresh.predictions = Predictions::new(n, sim.bodies.bounds, r, choice);
        fresh.predict_all();
        fresh
    }

    /// Runs `sim` for up to `events` events. Before each, two copies predicted from scratch,
    /// one by each strategy, must pick the same next event: the same kind and balls, at the
    /// same time up to rounding (the two search pairs over different horizons), or at least
    /// an event within rounding of the same time (a near tie, ordered by rounding). (The
    /// simulation's own cached prediction is not compared: in a jam of pressed balls a
    /// contact time depends on when its search started, by up to the resting depth over the
    /// approach speed.)
    fn strategies_agree(mut sim: Simulation, events: usize) -> Agreement {
        let mut agreement = Agreement::default();
        for _ in 0..events {
            let Some(next) = next_physical(&mut sim) else {
                break;
            };
            let mut table = predicted_afresh(&sim, StrategyChoice::PairTable);
            let mut cells = predicted_afresh(&sim, StrategyChoice::CellLists);
            let mine = next_physical(&mut table).expect("the event the simulation has");
            let theirs = next_physical(&mut cells).expect("the event the simulation has");
            let tolerance = 1e-12 * mine.time.abs().max(1.0);
            assert!(
                (mine.time - theirs.time).abs() <= tolerance,
                "at t = {}: {mine:?} against {theirs:?}",
                sim.time
            );
            agreement.exact += usize::from(mine == theirs);
            agreement.close += usize::from(mine.kind == theirs.kind);
            agreement.ties += usize::from(mine.kind != theirs.kind);
            sim.process(next);
        }
        agreement
    }

    fn build(
        table: Table,
        params: Params,
        balls: &[BallSetup],
        choice: StrategyChoice,
    ) -> Simulation {
        Simulation::with_strategy(table, params, balls, choice).expect("a valid scene")
    }

    /// Small scenes (each run on either strategy in turn): breaks with and without spin and
    /// jaws, scattered moving balls, a frictionless gas and soak scenes.
    #[test]
    fn both_strategies_pick_the_same_next_event_on_small_scenes() {
        let spin = Params {
            model: Model::Spin(SpinModel::default()),
            ..Params::default()
        };
        let mut scenes = Vec::new();
        for (params, jaws) in [(Params::default(), false), (spin, true)] {
            let table = Table::wpa_8ft();
            let table = if jaws { table.with_jaws(0.01) } else { table };
            let balls = Rack::FifteenBall.layout(&table, &params.ball);
            scenes.push((table, params, balls, Some(crate::Shot::new(0.01, 9.0))));
            let balls = racks::scattered(&table, &params.ball, 16, 3.0, 7);
            scenes.push((table, params, balls, None));
        }
        let (table, params, balls) = racks::frictionless_gas(16);
        scenes.push((table, params, balls, None));
        // 60 soak scenes: enough that their events pass the count below whichever way
        // their breaks go (the cluster impact's friction changed them in 2026-12).
        for seed in 0..60 {
            let s = soak::scenario(seed);
            scenes.push((s.table, s.params, s.balls, s.shots.first().copied()));
        }
        let mut total = Agreement::default();
        for (k, (table, params, balls, shot)) in scenes.into_iter().enumerate() {
            let choice = [StrategyChoice::PairTable, StrategyChoice::CellLists][k % 2];
            let mut sim = build(table, params, &balls, choice);
            if let Some(shot) = shot
                && sim.strike(0, shot).is_err()
            {
                continue;
            }
            let a = strategies_agree(sim, 400);
            total.exact += a.exact;
            total.close += a.close;
            total.ties += a.ties;
        }
        // Thousands of events compared, every one the same event, nearly all to the bit.
        assert!(total.close > 3500 && total.ties == 0, "{total:?}");
        assert!(total.exact * 10 > total.close * 9, "{total:?}");
    }

    /// A scene large enough for the cell lists, where the pair table still fits.
    #[test]
    fn both_strategies_pick_the_same_next_event_on_a_large_scene() {
        let (table, params, balls) = racks::frictionless_gas(100);
        let sim = build(table, params, &balls, StrategyChoice::CellLists);
        let a = strategies_agree(sim, 1500);
        assert!(a.close == 1500 && a.ties == 0, "{a:?}");
        assert!(a.exact * 10 > a.close * 9, "{a:?}");
    }
}
