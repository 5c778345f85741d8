//! The event loop: the paper's `Progress(T)` (section 4.2) as a loop over exact events.

use crate::ball::{BallId, BallState, Motion, Segment};
use crate::detect::cull::{PathColumns, kept};
use crate::detect::{self, Kinematics};
use crate::event::{Event, EventKind, Shot};
use crate::grid::{Grid, Side};
use crate::history::History;
use crate::math::{Vec2, Vec3};
use crate::motion;
use crate::params::{ParamError, Params, Prediction};
use crate::queue::Tournament;
use crate::resolve::{self, FixedBody, FixedContact, InstantContacts, Laws, NormalPerturbation};
use crate::table::{Cushion, Jaw, Opening, PocketShape, Table};
use pending::{Pending, PendingKind, earlier, rank};
use std::hint::select_unpredictable;

mod pending;
mod setup;

pub use setup::{BallSetup, PLACEMENT_TOLERANCE, SetupError, SimError};

/// What one [`Simulation::advance`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Advance {
    /// Index range of the events it processed, into [`History::events`].
    pub events: std::ops::Range<usize>,
}

/// An exact, event-driven billiards simulation.
///
/// Each ball follows a closed-form segment from its last event; positions are always evaluated
/// from there, never accumulated per step, so the trajectory does not depend on how time is
/// sliced. Predictions are cached per ball and redone only for the balls an event touched.
#[derive(Clone, Debug)]
pub struct Simulation {
    table: Table,
    params: Params,
    numbers: Vec<u8>,
    segments: Vec<Segment>,
    /// Each ball's earliest predicted event, and the earliest of them all.
    cache: Tournament<Pending>,
    /// Single-cell scenes: each ball's earliest event of its own (not with another ball).
    own: Vec<Option<Pending>>,
    /// Single-cell scenes: contact time of each pair (`n * n`, both halves, infinity for
    /// none), valid until either ball's segment changes; an event then re-solves only the
    /// pairs of the balls it touched, and every other ball takes its best from its row.
    pairs: Vec<f64>,
    /// Single-cell scenes: every ball's segment for the pair culls.
    paths: PathColumns,
    /// Single-cell scenes: the verdicts of the last [`PathColumns::cull_row`].
    clearance: Vec<f64>,
    /// Scratch: balls whose pair with a touched ball changed in this event.
    affected: Vec<BallId>,
    /// For each ball, the balls whose cached event is a contact with it (may hold stale
    /// entries; checked before use). Scenes split into cells only.
    dependents: Vec<Vec<BallId>>,
    /// Stamp of the prediction round that last predicted each ball, and the current round.
    stamps: Vec<u64>,
    round: u64,
    grid: Grid,
    /// Pocket jaws and openings (empty unless the table has jaws).
    jaws: Vec<Jaw>,
    openings: Vec<Opening>,
    time: f64,
    history: History,
    /// The rotation of collision normals (paper 5), if randomization is on.
    perturbation: NormalPerturbation,
    bounds: Vec2,
    /// The contacts with cushions and jaws resolved at the current instant.
    instant_contacts: InstantContacts,
}

impl Simulation {
    /// Builds a simulation at time 0, checking the table, the parameters and the layout.
    pub fn new(table: Table, params: Params, balls: &[BallSetup]) -> Result<Self, SetupError> {
        params.validate()?;
        let r = params.ball.radius;
        table.validate(r)?;
        let bounds = table.centre_bounds(r);
        setup::check_layout(balls, r, bounds)?;
        let segments: Vec<Segment> = balls
            .iter()
            .map(|b| motion::segment_from(&params, 0.0, b.position, b.velocity, b.spin))
            .collect();
        let mut sim = Self {
            table,
            params,
            numbers: balls.iter().map(|b| b.number).collect(),
            history: History::new(&segments, params),
            cache: Tournament::new(segments.len()),
            own: vec![None; segments.len()],
            pairs: Vec::new(),
            paths: PathColumns::default(),
            clearance: Vec::new(),
            affected: Vec::new(),
            dependents: vec![Vec::new(); segments.len()],
            stamps: vec![0; segments.len()],
            round: 0,
            grid: Grid::new(bounds, r, segments.len()),
            jaws: table.jaws(),
            openings: match table.pockets {
                PocketShape::Mouth => Vec::new(),
                PocketShape::Jaws { .. } => table.openings().to_vec(),
            },
            segments,
            time: 0.0,
            perturbation: NormalPerturbation::new(params.randomization),
            bounds,
            instant_contacts: InstantContacts::default(),
        };
        sim.predict_all();
        Ok(sim)
    }

    /// Current simulation time, seconds.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The table.
    pub fn table(&self) -> &Table {
        &self.table
    }

    /// The parameters in force.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// Number of balls (pocketed ones included).
    pub fn ball_count(&self) -> usize {
        self.segments.len()
    }

    /// The number painted on each ball.
    pub fn numbers(&self) -> &[u8] {
        &self.numbers
    }

    /// Ball `id`'s state now.
    pub fn ball(&self, id: BallId) -> BallState {
        self.segments[id].state_at(self.time)
    }

    /// Every ball's state now.
    pub fn balls(&self) -> impl ExactSizeIterator<Item = BallState> + '_ {
        self.segments.iter().map(|s| s.state_at(self.time))
    }

    /// Ball `id`'s current closed-form segment.
    pub fn segment(&self, id: BallId) -> &Segment {
        &self.segments[id]
    }

    /// The event history.
    pub fn history(&self) -> &History {
        &self.history
    }

    /// No ball is moving.
    pub fn is_at_rest(&self) -> bool {
        self.segments.iter().all(|s| s.state.motion.is_at_rest())
    }

    /// Time of the next event, if any.
    pub fn next_event_time(&self) -> Option<f64> {
        self.next_pending().map(|p| p.time)
    }

    /// The paper's `Progress(T)`: processes every event up to `time + dt` in time order, then
    /// leaves the state at `time + dt`.
    pub fn advance(&mut self, dt: f64) -> Result<Advance, SimError> {
        if !(dt.is_finite() && dt >= 0.0) {
            return Err(SimError::BadStep(dt));
        }
        self.advance_to(self.time + dt)
    }

    /// Processes every event up to absolute time `t`, then sets the clock to `t`.
    pub fn advance_to(&mut self, t: f64) -> Result<Advance, SimError> {
        if !(t.is_finite() && t >= self.time) {
            return Err(SimError::BadStep(t - self.time));
        }
        let advance = self.process_until(t)?;
        self.time = t;
        Ok(advance)
    }

    /// Advances exactly to the next event and processes it (and only it); `None` at rest.
    pub fn step_event(&mut self) -> Option<Event> {
        let before = self.history.events().len();
        // Grid crossings are internal: keep going until a physical event is recorded.
        while self.history.events().len() == before {
            let p = self.next_pending()?;
            self.process(p);
        }
        self.history.events().last().copied()
    }

    /// Runs until every ball rests; the clock ends at the last event.
    pub fn run_to_rest(&mut self) -> Result<Advance, SimError> {
        self.process_until(f64::INFINITY)
    }

    /// The event loop: processes pending events in order while they are due by `t`, at most
    /// `params.max_events` of them.
    fn process_until(&mut self, t: f64) -> Result<Advance, SimError> {
        let first = self.history.events().len();
        let mut count = 0;
        while let Some(p) = self.next_pending().filter(|p| p.time <= t) {
            if count == self.params.max_events {
                return Err(SimError::EventCap {
                    cap: count,
                    time: self.time,
                });
            }
            self.process(p);
            count += 1;
        }
        Ok(Advance {
            events: first..self.history.events().len(),
        })
    }

    /// Strikes ball `id` now: the paper's cue (an angle and a magnitude); the spin model also
    /// takes the tip offset (the paper's model has no spin and ignores it).
    pub fn strike(&mut self, id: BallId, shot: Shot) -> Result<(), SetupError> {
        let finite = shot.angle.is_finite()
            && shot.speed.is_finite()
            && shot.tip.side.is_finite()
            && shot.tip.height.is_finite();
        if !(finite && shot.speed >= 0.0) {
            return Err(SetupError::BadShot {
                angle: shot.angle,
                speed: shot.speed,
            });
        }
        let state = self.ball_checked(id)?;
        let dir = Vec2::from_angle(shot.angle);
        let cue = Laws::of(&self.params.model).cue;
        let (v, w) = cue.strike(&self.params.ball, dir, shot.speed, shot.tip)?;
        self.segments[id] = motion::segment_from(&self.params, self.time, state.position, v, w);
        self.record(EventKind::Strike { ball: id, shot });
        self.repredict([id]);
        Ok(())
    }

    /// Sets ball `id`'s position and velocity now (editing, respotting). The new position must
    /// be on the table and clear of the other balls.
    pub fn place(
        &mut self,
        id: BallId,
        position: Vec2,
        velocity: Vec2,
        spin: Vec3,
    ) -> Result<(), SetupError> {
        if id >= self.segments.len() {
            return Err(SetupError::NoSuchBall(id));
        }
        setup::check_ball(id, position, velocity, spin, self.bounds)?;
        let r = self.params.ball.radius;
        for (j, seg) in self.segments.iter().enumerate() {
            if j != id && seg.state.motion.on_table() {
                setup::check_clear((id, position), (j, seg.position_at(self.time)), r)?;
            }
        }
        self.segments[id] = motion::segment_from(&self.params, self.time, position, velocity, spin);
        self.record(EventKind::Placed { ball: id });
        self.repredict([id]);
        Ok(())
    }

    /// Replaces the parameters now; moving balls continue from their current state under the
    /// new ones. The ball size cannot change mid-game.
    pub fn set_params(&mut self, params: Params) -> Result<(), SetupError> {
        params.validate()?;
        if params.ball != self.params.ball {
            return Err(SetupError::Param(ParamError {
                name: "ball",
                value: params.ball.radius,
                expected: "unchanged while balls are on the table",
            }));
        }
        if params.randomization != self.params.randomization {
            self.perturbation = NormalPerturbation::new(params.randomization);
        }
        self.params = params;
        for seg in &mut self.segments {
            *seg = motion::under_new_params(&params, self.time, seg);
        }
        let event = Event {
            time: self.time,
            kind: EventKind::ParamsChanged,
            after: Default::default(),
        };
        self.history.push_all(event, &self.segments, params);
        self.predict_all();
        Ok(())
    }

    fn ball_checked(&self, id: BallId) -> Result<BallState, SetupError> {
        let seg = self.segments.get(id).ok_or(SetupError::NoSuchBall(id))?;
        if !seg.state.motion.on_table() {
            return Err(SetupError::Pocketed(id));
        }
        Ok(self.ball(id))
    }

    fn kinematics(&self) -> Kinematics {
        match self.params.prediction {
            Prediction::Exact => Kinematics::Exact,
            Prediction::PaperLinear => Kinematics::Linear,
        }
    }

    fn next_pending(&self) -> Option<Pending> {
        self.cache.best().map(|(_, p)| p)
    }

    /// Stores ball `id`'s prediction and indexes it under its partner, if any.
    fn set_cache(&mut self, id: BallId, p: Option<Pending>) {
        self.stamps[id] = self.round;
        self.cache.set(id, p, rank(p));
        if let Some(partner) = p.and_then(|p| p.partner(id)) {
            let deps = &mut self.dependents[partner];
            deps.push(id);
            if deps.len() > 64 {
                // Drop stale entries so the list stays short in long runs.
                let cache = &self.cache;
                deps.retain(|&m| cache.get(m).is_some_and(|q| q.involves(partner)));
                deps.sort_unstable();
                deps.dedup();
            }
        }
    }

    /// The earliest event of ball `id` from time `t` on: its own transition, a cushion, or a
    /// contact with any other ball in play in the cells around it.
    fn predict(&self, id: BallId, t: f64) -> Option<Pending> {
        let seg = &self.segments[id];
        if !seg.state.motion.on_table() {
            return None;
        }
        let kin = self.kinematics();
        let horizon = seg.end.map_or(f64::INFINITY, |e| e - t);
        let mut best = self.predict_own(id, t);
        let r = self.params.ball.radius;
        for j in self.grid.neighbours(id) {
            let other = &self.segments[j];
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

    /// The earliest event of ball `id` from time `t` on that involves no other ball: its own
    /// transition, a cushion, a jaw, a pocket opening or a grid crossing.
    fn predict_own(&self, id: BallId, t: f64) -> Option<Pending> {
        let seg = &self.segments[id];
        if !seg.state.motion.on_table() {
            return None;
        }
        let kin = self.kinematics();
        let horizon = seg.end.map_or(f64::INFINITY, |e| e - t);
        let mut best = seg.end.map(|end| Pending {
            time: end,
            kind: PendingKind::Transition(id),
        });
        if seg.state.motion.is_moving() {
            // The ball's state once for all four cushions (`cushion_contact` starts at `t + 0.0`
            // too); `line_contact` skips a cushion the ball leaves for good before any root.
            let v = seg.velocity_at(t + 0.0);
            let a = match kin {
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
            for &c in cushions.iter().flatten() {
                let limit = self.cushion_limit(c);
                let table = &self.table;
                let Some(tau) =
                    detect::cushion_contact(seg, t, (p, v, a), c, limit, table, horizon)
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
            let jaw_contact = self.params.ball.radius + self.jaw_radius();
            for (k, jaw) in self.jaws.iter().enumerate() {
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
            for (k, o) in self.openings.iter().enumerate() {
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
        }
        if seg.state.motion.is_moving() && self.grid.is_split() {
            for (side, at) in self.grid.exits(id) {
                let (n, offset) = match side {
                    Side::XPlus => (Vec2::new(-1.0, 0.0), at),
                    Side::XMinus => (Vec2::new(1.0, 0.0), -at),
                    Side::YPlus => (Vec2::new(0.0, -1.0), at),
                    Side::YMinus => (Vec2::new(0.0, 1.0), -at),
                };
                // Crossings follow the real path even in the linear comparison mode.
                if let Some(tau) = detect::ball_line(seg, t, n, offset, horizon, Kinematics::Exact)
                {
                    best = earlier(
                        best,
                        Some(Pending {
                            time: t + tau,
                            kind: PendingKind::Crossing(id, side),
                        }),
                    );
                }
            }
        }
        best
    }

    /// Contact time of balls `i` and `j` from time `t` on (infinity for none), searched only
    /// up to the earlier of their own next events: each of those changes a segment (there are
    /// no crossings in a single cell) and wins ties, so a later contact could never happen.
    /// `keep` is the cull's verdict ([`PathColumns::cull_row`]): a culled pair has no contact.
    fn solve_pair(&self, i: BallId, j: BallId, t: f64, keep: bool) -> f64 {
        let paths = &self.paths;
        if !keep || !paths.may_meet(i, j) {
            return f64::INFINITY;
        }
        let h = paths.until(i).min(paths.until(j)) - t;
        let (si, sj) = (&self.segments[i], &self.segments[j]);
        let r = self.params.ball.radius;
        detect::ball_ball_kept(si, sj, t, r, h, self.kinematics())
            .map_or(f64::INFINITY, |tau| t + tau)
    }

    /// Ball `id`'s earliest event from the pair table and its own events. Scanning partners in
    /// ascending order with a strict comparison keeps the tie order of [`Pending::key`].
    fn best_of_row(&self, id: BallId) -> Option<Pending> {
        let n = self.segments.len();
        let row = &self.pairs[id * n..(id + 1) * n];
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
        earlier(self.own[id], pair)
    }

    /// Stores a pair's contact time in both halves of the table.
    fn set_pair(&mut self, i: BallId, j: BallId, time: f64) {
        let n = self.segments.len();
        self.pairs[i * n + j] = time;
        self.pairs[j * n + i] = time;
    }

    /// Single-cell scenes: re-solves the own events of the touched balls and every pair
    /// containing one of them, then updates the best of the touched balls and of every ball
    /// whose pair with one of them changed.
    fn repredict_pairs<const N: usize>(&mut self, touched: &[BallId; N]) {
        let t = self.time;
        let n = self.segments.len();
        for &id in touched {
            self.own[id] = self.predict_own(id, t);
            self.paths.set(
                id,
                &self.segments[id],
                self.own[id].map_or(f64::INFINITY, |p| p.time),
            );
        }
        let contact = 2.0 * self.params.ball.radius;
        let mut affected = std::mem::take(&mut self.affected);
        affected.clear();
        // Each touched ball's earliest pair, found while its row is worked through: entries
        // left out are infinite (culled, and no contact before), and scanning partners in
        // ascending order with a strict comparison picks the same pair as `best_of_row`.
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
                let gaps = &self.clearance[base..end];
                let row = &self.pairs[id * n + base..id * n + end];
                let mut mask = 0u64;
                for (b, (&g, &p)) in gaps.iter().zip(row).enumerate() {
                    let skip = (g > 0.0) & (p == f64::INFINITY);
                    mask |= u64::from(!skip) << b;
                }
                // Not the ball with itself (its gap is negative).
                if (base..end).contains(&id) {
                    mask &= !(1 << (id - base));
                }
                while mask != 0 {
                    let j = base + mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    // A pair of two touched balls is solved once.
                    let time = if touched[..k].contains(&j) {
                        self.pairs[id * n + j]
                    } else {
                        let time = self.solve_pair(id, j, t, kept(self.clearance[j]));
                        if time != self.pairs[id * n + j] {
                            self.set_pair(id, j, time);
                            affected.push(j);
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
        for (&id, &(least, at)) in touched.iter().zip(&rows) {
            let pair = (least < f64::INFINITY).then(|| Pending {
                time: least,
                kind: PendingKind::Pair(id.min(at), id.max(at)),
            });
            let p = earlier(self.own[id], pair);
            debug_assert_eq!(p, self.best_of_row(id));
            self.cache.set(id, p, rank(p));
        }
        // A ball may appear twice (paired with both touched balls): updating it is idempotent.
        for &j in &affected {
            if touched.contains(&j) {
                continue;
            }
            let cur = self.cache.get(j);
            let stale = matches!(cur, Some(Pending { kind: PendingKind::Pair(a, b), .. })
                    if touched.contains(&a) || touched.contains(&b));
            if stale {
                let p = self.best_of_row(j);
                self.cache.set(j, p, rank(p));
                continue;
            }
            // Only the touched balls' pairs changed, and the best was none of them.
            let mut best = self.cache.rank(j);
            let mut found = None;
            for &id in touched {
                let time = self.pairs[j * n + id];
                if time < f64::INFINITY {
                    let kind = PendingKind::Pair(id.min(j), id.max(j));
                    let p = Pending { time, kind };
                    if p.rank() < best {
                        (best, found) = (p.rank(), Some(p));
                    }
                }
            }
            if found.is_some() {
                self.cache.set(j, found, best);
            }
        }
        self.affected = affected;
    }

    /// How far the centre may go from the table's centre line towards `cushion`.
    fn cushion_limit(&self, cushion: Cushion) -> f64 {
        match cushion {
            Cushion::Head | Cushion::Foot => self.bounds.x,
            Cushion::Left | Cushion::Right => self.bounds.y,
        }
    }

    fn jaw_radius(&self) -> f64 {
        match self.table.pockets {
            PocketShape::Jaws { radius } => radius,
            PocketShape::Mouth => 0.0,
        }
    }

    fn predict_all(&mut self) {
        if !self.grid.is_split() {
            let (n, t) = (self.segments.len(), self.time);
            self.pairs = vec![f64::INFINITY; n * n];
            for id in 0..n {
                self.own[id] = self.predict_own(id, t);
            }
            self.paths = PathColumns::new(n);
            self.clearance = vec![0.0; n];
            for id in 0..n {
                self.paths.set(
                    id,
                    &self.segments[id],
                    self.own[id].map_or(f64::INFINITY, |p| p.time),
                );
            }
            let contact = 2.0 * self.params.ball.radius;
            for i in 0..n {
                if self.paths.moving_on_table(i) {
                    self.paths.cull_row(&mut self.clearance, i, t, contact);
                } else {
                    self.clearance.fill(f64::NEG_INFINITY);
                }
                for j in i + 1..n {
                    let time = self.solve_pair(i, j, t, kept(self.clearance[j]));
                    self.set_pair(i, j, time);
                }
            }
            for id in 0..n {
                let p = self.best_of_row(id);
                self.cache.set(id, p, rank(p));
            }
            return;
        }
        self.round += 1;
        for deps in &mut self.dependents {
            deps.clear();
        }
        for id in 0..self.segments.len() {
            let on_table = self.segments[id].state.motion.on_table();
            self.grid.set(
                id,
                on_table.then(|| self.segments[id].position_at(self.time)),
            );
        }
        for id in 0..self.segments.len() {
            let p = self.predict(id, self.time);
            self.set_cache(id, p);
        }
    }

    /// Re-predicts the balls an event changed, and every ball whose cached event was a contact
    /// with one of them; all other predictions stay valid.
    /// `N` (one or two balls) is a constant, so that every loop over the touched balls is
    /// unrolled rather than a branch on how many there are.
    fn repredict<const N: usize>(&mut self, touched: [BallId; N]) {
        if !self.grid.is_split() {
            return self.repredict_pairs(&touched);
        }
        let t = self.time;
        self.round += 1;
        for id in touched {
            let on_table = self.segments[id].state.motion.on_table();
            self.grid
                .set(id, on_table.then(|| self.segments[id].state.position));
            let p = self.predict(id, t);
            self.set_cache(id, p);
        }
        for id in touched {
            for m in std::mem::take(&mut self.dependents[id]) {
                let stale = self.cache.get(m).is_some_and(|p| p.involves(id));
                if !stale {
                    continue;
                }
                if self.stamps[m] == self.round {
                    // Re-predicted earlier in this round (say, as a dependent of another
                    // touched ball) and now waiting on `id`: keep the link, or the next change
                    // of `id` leaves `m`'s pair event stale and it fires at a gap.
                    self.dependents[id].push(m);
                } else {
                    let p = self.predict(m, t);
                    self.set_cache(m, p);
                }
            }
        }
    }

    fn record(&mut self, kind: EventKind) {
        let mut after = [BallState::default(); 2];
        for (slot, id) in after.iter_mut().zip(kind.balls()) {
            *slot = self.segments[id].state;
        }
        let event = Event {
            time: self.time,
            kind,
            after,
        };
        self.history.push(event);
    }

    fn process(&mut self, p: Pending) {
        debug_assert!(p.time >= self.time, "time never goes back");
        self.time = p.time;
        let t = p.time;
        match p.kind {
            PendingKind::Crossing(id, side) => {
                self.grid.cross(id, side);
                self.round += 1;
                let p = self.predict(id, t);
                self.set_cache(id, p);
            }
            PendingKind::Transition(id) => {
                let from = self.segments[id].state.motion;
                self.segments[id] = motion::after_transition(&self.params, &self.segments[id]);
                let to = self.segments[id].state.motion;
                self.record(EventKind::Transition { ball: id, from, to });
                self.repredict([id]);
            }
            PendingKind::Opening(id, k) => {
                let s = self.segments[id].state_at(t);
                let pocket = self.openings[k].pocket;
                self.segments[id] = Segment::at_rest(t, s.position, Motion::Pocketed(pocket));
                self.record(EventKind::Pocketed { ball: id, pocket });
                self.repredict([id]);
            }
            PendingKind::Jaw(id, k) => {
                let s = self.segments[id].state_at(t);
                let jaw = self.jaws[k];
                let d = s.position - jaw.centre;
                let normal = d.normalized().unwrap_or(Vec2::new(0.0, 1.0));
                let depth = self.params.ball.radius + self.jaw_radius() - d.length();
                let repeat = self.instant_contacts.repeats(t, id, FixedBody::Jaw(k));
                let contact = FixedContact {
                    normal,
                    depth,
                    repeat,
                };
                self.resolve_fixed_body(id, &s, contact);
                self.record(EventKind::Jaw {
                    ball: id,
                    pocket: jaw.pocket,
                });
                self.repredict([id]);
            }
            PendingKind::Cushion(id, cushion) => {
                let s = self.segments[id].state_at(t);
                let mouth = match self.table.pockets {
                    PocketShape::Mouth => self.table.pocket_at(cushion, s.position),
                    PocketShape::Jaws { .. } => None,
                };
                if let Some(pocket) = mouth {
                    self.segments[id] = Segment::at_rest(t, s.position, Motion::Pocketed(pocket));
                    self.record(EventKind::Pocketed { ball: id, pocket });
                } else {
                    let normal = cushion.inward_normal();
                    let limit = self.cushion_limit(cushion);
                    let depth = -(limit + normal.dot(s.position));
                    let body = FixedBody::Cushion(cushion);
                    let repeat = self.instant_contacts.repeats(t, id, body);
                    let contact = FixedContact {
                        normal,
                        depth,
                        repeat,
                    };
                    self.resolve_fixed_body(id, &s, contact);
                    self.record(EventKind::Cushion { ball: id, cushion });
                }
                self.repredict([id]);
            }
            PendingKind::Pair(a, b) => {
                let (sa, sb) = (self.segments[a].state_at(t), self.segments[b].state_at(t));
                let laws = Laws::of(&self.params.model);
                let (na, nb) = resolve::ball_pair(
                    &laws,
                    (sa, self.segments[a].acceleration),
                    (sb, self.segments[b].acceleration),
                    &self.params.ball,
                    &mut self.perturbation,
                );
                self.segments[a] = motion::segment_from(
                    &self.params,
                    t,
                    sa.position,
                    na.velocity,
                    na.angular_velocity,
                );
                self.segments[b] = motion::segment_from(
                    &self.params,
                    t,
                    sb.position,
                    nb.velocity,
                    nb.angular_velocity,
                );
                self.record(EventKind::BallBall { a, b });
                self.repredict([a, b]);
            }
        }
    }
}

impl Simulation {
    /// Ball `id`, in state `s` now, after `contact` with a cushion or jaw.
    fn resolve_fixed_body(&mut self, id: BallId, s: &BallState, contact: FixedContact) {
        let laws = Laws::of(&self.params.model);
        let (r, acceleration) = (self.params.ball.radius, self.segments[id].acceleration);
        let (v, w) =
            resolve::fixed_body(&laws, s, acceleration, contact, r, &mut self.perturbation);
        self.segments[id] = motion::segment_from(&self.params, self.time, s.position, v, w);
    }
}
