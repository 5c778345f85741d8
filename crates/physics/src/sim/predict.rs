//! Prediction: each ball's earliest next event, cached until an event changes it or its
//! partner, and the earliest of them all. A ball's events with no other ball are found here
//! ([`Scene::predict_solo`], in `scene.rs`); its contacts with other balls by one of two
//! strategies, chosen by the size of the scene ([`Strategy`]).

use super::cell_lists::CellLists;
use super::pair_table::PairTable;
use super::pending::Pending;
use super::scene::Scene;
use crate::ball::BallId;
use crate::grid::{Grid, Side};
use crate::math::Vec2;
use crate::queue::Tournament;

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
        // From 32,768 balls, where a tree over the balls passes 2 MB (the L2 cache), the
        // queue in blocks of 16 balls, whose tree stays in cache (issue 53, `Tournament`;
        // measured in the physics README, "The queue in blocks"). At 10,000 balls the blocks
        // were no faster: fewer misses, more instructions.
        let (strategy, queue) = match grid {
            Some(grid) => (
                Strategy::CellLists(CellLists::new(grid, n)),
                Tournament::with_blocks(n, if n > 1 << 15 { 4 } else { 0 }),
            ),
            None => (Strategy::PairTable(PairTable::new(n)), Tournament::new(n)),
        };
        Self { queue, strategy }
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
    use super::super::pending::PendingKind;
    use super::*;
    use crate::params::{Model, Params, SpinModel};
    use crate::racks::{self, Rack};
    use crate::sim::{BallSetup, Simulation};
    use crate::soak;
    use crate::table::Table;

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
