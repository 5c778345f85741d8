//! The event loop: the paper's `Progress(T)` (section 4.2) as a loop over exact events.

use crate::ball::{BallId, BallState, Motion, Segment};
use crate::detect::{self, Kinematics};
use crate::event::{Event, EventKind, Shot};
use crate::grid::{Grid, Side};
use crate::history::History;
use crate::limits::{self, LimitError};
use crate::math::{Vec2, Vec3};
use crate::motion;
use crate::params::{CushionModel, Model, ParamError, Params, Prediction};
use crate::queue::Tournament;
use crate::resolve;
use crate::table::{Cushion, Jaw, Opening, PocketShape, Table, TableError};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::hint::select_unpredictable;

/// How far two balls may overlap, or a ball cross a cushion line, in a valid starting layout
/// (metres): exactly touching layouts computed in floating point land within rounding of it.
pub const PLACEMENT_TOLERANCE: f64 = 1e-9;

/// A ball as given to [`Simulation::new`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BallSetup {
    /// Number painted on the ball (0 for the cue ball).
    pub number: u8,
    /// Centre, metres.
    pub position: Vec2,
    /// Velocity, m/s.
    #[serde(default)]
    pub velocity: Vec2,
    /// Angular velocity, rad/s (ignored by the paper's model, which has no spin).
    #[serde(default)]
    pub spin: Vec3,
}

impl BallSetup {
    /// A ball at rest.
    pub fn at(number: u8, position: Vec2) -> Self {
        Self {
            number,
            position,
            velocity: Vec2::ZERO,
            spin: Vec3::ZERO,
        }
    }

    /// A ball moving with `velocity` and no spin.
    pub fn moving(number: u8, position: Vec2, velocity: Vec2) -> Self {
        Self {
            velocity,
            ..Self::at(number, position)
        }
    }
}

/// Why a simulation could not be built or changed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SetupError {
    /// A parameter is out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The table is malformed.
    #[error(transparent)]
    Table(#[from] TableError),
    /// A ball's position or velocity is NaN or infinite.
    #[error("ball {ball} has a non-finite {what}")]
    NonFinite {
        /// Ball index.
        ball: BallId,
        /// "position" or "velocity".
        what: &'static str,
    },
    /// A ball's centre is outside the area its centre may occupy.
    #[error("ball {ball} at ({x}, {y}) is outside the table")]
    OutsideTable {
        /// Ball index.
        ball: BallId,
        /// Its x.
        x: f64,
        /// Its y.
        y: f64,
    },
    /// Two balls overlap.
    #[error("balls {a} and {b} overlap by {overlap} m")]
    Overlap {
        /// First ball.
        a: BallId,
        /// Second ball.
        b: BallId,
        /// Depth of the overlap, metres.
        overlap: f64,
    },
    /// There is no ball with this index.
    #[error("there is no ball {0}")]
    NoSuchBall(BallId),
    /// The ball has been pocketed.
    #[error("ball {0} is pocketed")]
    Pocketed(BallId),
    /// The cue tip offset is beyond the miscue limit.
    #[error(transparent)]
    Miscue(#[from] resolve::cue::Miscue),
    /// A value outside the input contract (a shot, a ball's speed or spin, the clock).
    #[error(transparent)]
    Limit(#[from] LimitError),
}

/// Why the simulation stopped short of the requested time.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SimError {
    /// More events than `Params::max_events` in one call: the state is valid, at `time`.
    #[error("event cap of {cap} reached at t = {time} s without coming to rest")]
    EventCap {
        /// The cap.
        cap: usize,
        /// Simulation time reached.
        time: f64,
    },
    /// A step with negative or non-finite length.
    #[error("cannot advance by {0} s: time steps must be finite and non-negative")]
    BadStep(f64),
    /// A step that would end past [`crate::limits::MAX_TIME`].
    #[error(transparent)]
    Limit(#[from] LimitError),
}

/// What one [`Simulation::advance`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Advance {
    /// Index range of the events it processed, into [`History::events`].
    pub events: std::ops::Range<usize>,
}

/// A predicted event, cached per ball until one of its balls changes.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Pending {
    time: f64,
    kind: PendingKind,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum PendingKind {
    /// Internal: the ball leaves its grid cell (no physical effect, not recorded).
    Crossing(BallId, Side),
    Transition(BallId),
    Cushion(BallId, Cushion),
    /// Contact with jaw `k` of `Simulation::jaws`.
    Jaw(BallId, usize),
    /// The ball's centre crosses pocket opening `k` of `Simulation::openings`.
    Opening(BallId, usize),
    Pair(BallId, BallId),
}

impl Pending {
    /// Tie order between events at equal times: grid crossings (bookkeeping, so that a
    /// contact at the same instant is seen), state transitions, then cushions, then ball
    /// pairs (after pooltool), each by ball index, then by cushion order.
    fn key(&self) -> (u8, BallId, usize) {
        match self.kind {
            PendingKind::Crossing(b, s) => (0, b, s as usize),
            PendingKind::Transition(b) => (1, b, 0),
            PendingKind::Opening(b, k) => (2, b, k),
            PendingKind::Cushion(b, c) => (3, b, c as usize),
            PendingKind::Jaw(b, k) => (4, b, k),
            PendingKind::Pair(a, b) => (5, a, b),
        }
    }

    /// The order of events as one integer: the time (its bits mapped so that integer order
    /// is `f64::total_cmp` order), then the tie order of [`Pending::key`].
    fn rank(&self) -> u128 {
        let time = time_order(self.time);
        let (kind, a, b) = self.key();
        debug_assert!(
            a < 1 << 30 && b < 1 << 30,
            "ball and part indices fit in 30 bits"
        );
        let tie = (kind as u64) << 60 | (a as u64) << 30 | b as u64;
        (time as u128) << 64 | tie as u128
    }

    #[inline]
    fn precedes(&self, other: &Pending) -> bool {
        // Times nearly always differ: compare them first, in the same order as `rank`.
        let (a, b) = (time_order(self.time), time_order(other.time));
        if a != b {
            return a < b;
        }
        self.rank() < other.rank()
    }

    /// The other ball of a pair event, seen from `id`.
    fn partner(&self, id: BallId) -> Option<BallId> {
        match self.kind {
            PendingKind::Pair(a, b) if a == id => Some(b),
            PendingKind::Pair(a, b) if b == id => Some(a),
            _ => None,
        }
    }

    fn involves(&self, id: BallId) -> bool {
        match self.kind {
            PendingKind::Crossing(b, _)
            | PendingKind::Transition(b)
            | PendingKind::Cushion(b, _)
            | PendingKind::Jaw(b, _)
            | PendingKind::Opening(b, _) => b == id,
            PendingKind::Pair(a, b) => a == id || b == id,
        }
    }
}

/// Every ball's segment (start, position, velocity, acceleration) and the time of its own
/// next event (infinity for none), one array per component so that the cull of a row of
/// pairs is a loop the compiler vectorizes. Updated only for the balls an event changes.
#[derive(Clone, Debug, Default)]
struct Kin {
    start: Vec<f64>,
    px: Vec<f64>,
    py: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
    ax: Vec<f64>,
    ay: Vec<f64>,
    until: Vec<f64>,
    /// Moving (bit 0), on the table (bit 1).
    live: Vec<u8>,
    /// How many balls have a non-zero (or NaN) acceleration: with none (a frictionless
    /// scene), the cull drops the acceleration terms.
    accelerating: usize,
}

impl Kin {
    fn new(n: usize) -> Self {
        let z = vec![0.0; n];
        Self {
            start: z.clone(),
            px: z.clone(),
            py: z.clone(),
            vx: z.clone(),
            vy: z.clone(),
            ax: z.clone(),
            ay: z,
            until: vec![f64::INFINITY; n],
            live: vec![0; n],
            accelerating: 0,
        }
    }

    /// Records ball `id`'s segment and the time of its own next event.
    fn set(&mut self, id: BallId, seg: &Segment, own: Option<Pending>) {
        let s = &seg.state;
        let was = self.ax[id] != 0.0 || self.ay[id] != 0.0;
        let now = seg.acceleration.x != 0.0 || seg.acceleration.y != 0.0;
        self.accelerating = self.accelerating + usize::from(now) - usize::from(was);
        self.start[id] = seg.start;
        (self.px[id], self.py[id]) = (s.position.x, s.position.y);
        (self.vx[id], self.vy[id]) = (s.velocity.x, s.velocity.y);
        (self.ax[id], self.ay[id]) = (seg.acceleration.x, seg.acceleration.y);
        self.until[id] = own.map_or(f64::INFINITY, |p| p.time);
        self.live[id] = u8::from(s.motion.is_moving()) | u8::from(s.motion.on_table()) << 1;
    }

    /// For every ball `j`, whether balls `i` and `j` may touch between `t` and the earlier
    /// of their own next events: the test of [`detect::misses`] (with the real accelerations,
    /// which only widens it in the linear prediction mode) without branches, so that it
    /// vectorizes; conservative in every degenerate case (a NaN or infinite bound keeps the
    /// pair). Ball `i` must be moving: a resting ball is at rest from its segment's start.
    /// The verdicts go to `gap`, positive for pairs that cannot touch (a separate argument, so
    /// the compiler knows it overlaps none of the columns read).
    fn cull_row(&self, gap: &mut [f64], i: BallId, t: f64, contact: f64) {
        if self.accelerating == 0 {
            return self.cull_row_straight(gap, i, t, contact);
        }
        let ti = t - self.start[i];
        let (vxi, vyi) = (self.vx[i] + self.ax[i] * ti, self.vy[i] + self.ay[i] * ti);
        let (pxi, pyi) = (
            self.px[i] + (self.vx[i] + self.ax[i] * (0.5 * ti)) * ti,
            self.py[i] + (self.vy[i] + self.ay[i] * (0.5 * ti)) * ti,
        );
        let (axi, ayi, ui) = (self.ax[i], self.ay[i], self.until[i]);
        let rows = self.start.iter().zip(self.px.iter().zip(&self.py));
        let rows = rows.zip(self.vx.iter().zip(&self.vy));
        let rows = rows.zip(self.ax.iter().zip(&self.ay).zip(&self.until));
        for (gap, (((start, (px, py)), (vx, vy)), ((ax, ay), until))) in gap.iter_mut().zip(rows) {
            let tj = t - start;
            let (vxj, vyj) = (vx + ax * tj, vy + ay * tj);
            let (pxj, pyj) = (
                px + (vx + ax * (0.5 * tj)) * tj,
                py + (vy + ay * (0.5 * tj)) * tj,
            );
            let (dpx, dpy, dvx, dvy) = (pxj - pxi, pyj - pyi, vxj - vxi, vyj - vyi);
            let (dax, day) = (ax - axi, ay - ayi);
            // Plain selects rather than `f64::min`/`max` (no NaN fix-ups in the vector code):
            // a NaN closest time (no relative motion) becomes `h`, still a valid time.
            let h = if *until < ui { *until } else { ui } - t;
            let pv = dpx * dvx + dpy * dvy;
            let vv = dvx * dvx + dvy * dvy;
            let tau = -pv / vv;
            let tau = if tau < h { tau } else { h };
            let tau = if tau > 0.0 { tau } else { 0.0 };
            let (cx, cy) = (dpx + dvx * tau, dpy + dvy * tau);
            let bend = 0.5 * (dax * dax + day * day).sqrt() * h * h;
            let reach = (contact + bend) * (1.0 + 1e-9) + 1e-9;
            // (With h < 0, tau is 0 and a touching pair is kept.)
            *gap = cx * cx + cy * cy - (reach * reach + 1e-12 * (dpx * dpx + dpy * dpy));
        }
    }

    /// [`Kin::cull_row`] when no ball accelerates: the same test without the acceleration
    /// terms (each is a zero, and `bend` is `0 h h`: zero, or NaN for an unbounded horizon,
    /// which keeps the pair as the general cull does).
    fn cull_row_straight(&self, gap: &mut [f64], i: BallId, t: f64, contact: f64) {
        let ti = t - self.start[i];
        let (vxi, vyi) = (self.vx[i], self.vy[i]);
        let (pxi, pyi) = (self.px[i] + vxi * ti, self.py[i] + vyi * ti);
        let ui = self.until[i];
        // `reach` of the general cull with `bend` zero, squared, once for the row.
        let reach = contact * (1.0 + 1e-9) + 1e-9;
        let reach2 = reach * reach;
        let rows = self.start.iter().zip(self.px.iter().zip(&self.py));
        let rows = rows.zip(self.vx.iter().zip(&self.vy)).zip(&self.until);
        for (gap, (((start, (px, py)), (vx, vy)), until)) in gap.iter_mut().zip(rows) {
            let tj = t - start;
            let (dpx, dpy) = (px + vx * tj - pxi, py + vy * tj - pyi);
            let (dvx, dvy) = (vx - vxi, vy - vyi);
            let h = if *until < ui { *until } else { ui } - t;
            let pv = dpx * dvx + dpy * dvy;
            let vv = dvx * dvx + dvy * dvy;
            let tau = -pv / vv;
            let tau = if tau < h { tau } else { h };
            let tau = if tau > 0.0 { tau } else { 0.0 };
            let (cx, cy) = (dpx + dvx * tau, dpy + dvy * tau);
            // NaN for an unbounded horizon (keeps the pair, as `0 h h` does in the general
            // cull); zero otherwise, leaving `reach2` as it is.
            let unbounded = 0.0 * h;
            *gap = cx * cx + cy * cy - ((reach2 + unbounded) + 1e-12 * (dpx * dpx + dpy * dpy));
        }
    }
}

/// The bits of a time mapped so that integer order is `f64::total_cmp` order.
#[inline]
fn time_order(t: f64) -> u64 {
    let bits = t.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

/// Rank of an optional prediction in the tournament (see [`Pending::rank`]).
fn rank(p: Option<Pending>) -> u128 {
    p.map_or(Tournament::<Pending>::EMPTY, |p| p.rank())
}

#[inline]
fn earlier(a: Option<Pending>, b: Option<Pending>) -> Option<Pending> {
    match (a, b) {
        (Some(x), Some(y)) => Some(if y.precedes(&x) { y } else { x }),
        (x, None) => x,
        (None, y) => y,
    }
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
    /// Single-cell scenes: every ball's segment for the pair culls (see [`Kin`]).
    kin: Kin,
    /// Single-cell scenes: the verdicts of the last [`Kin::cull_row`].
    gap: Vec<f64>,
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
    rng: Option<ChaCha8Rng>,
    bounds: Vec2,
    /// The fixed-body contacts (cushion or jaw, ball, which) resolved at the current instant
    /// `instant_time`: a resting contact that repeats within one instant is plastic.
    instant: Vec<(u8, BallId, usize)>,
    instant_time: f64,
}

impl Simulation {
    /// Builds a simulation at time 0, checking the table, the parameters and the layout.
    pub fn new(table: Table, params: Params, balls: &[BallSetup]) -> Result<Self, SetupError> {
        params.validate()?;
        let r = params.ball.radius;
        table.validate(r)?;
        let bounds = table.centre_bounds(r);
        for (id, b) in balls.iter().enumerate() {
            if !b.position.is_finite() {
                return Err(SetupError::NonFinite {
                    ball: id,
                    what: "position",
                });
            }
            if !b.velocity.is_finite() {
                return Err(SetupError::NonFinite {
                    ball: id,
                    what: "velocity",
                });
            }
            if b.position.x.abs() > bounds.x + PLACEMENT_TOLERANCE
                || b.position.y.abs() > bounds.y + PLACEMENT_TOLERANCE
            {
                return Err(SetupError::OutsideTable {
                    ball: id,
                    x: b.position.x,
                    y: b.position.y,
                });
            }
        }
        limits::check_setups(balls, r)?;
        check_overlaps(balls, r)?;
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
            kin: Kin::default(),
            gap: Vec::new(),
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
            rng: params
                .randomization
                .map(|r| ChaCha8Rng::seed_from_u64(r.seed)),
            bounds,
            instant: Vec::new(),
            instant_time: f64::NAN,
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
        limits::check_clock(t)?;
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
        let state = self.ball_checked(id)?;
        limits::check_shot(&shot).map_err(|e| e.for_ball(id, self.numbers[id]))?;
        limits::check_clock(self.time)?;
        let dir = Vec2::from_angle(shot.angle);
        let (r, mass) = (self.params.ball.radius, self.params.ball.mass);
        let (v, w) = match self.params.model {
            Model::Paper(_) => (dir * shot.speed, Vec3::ZERO),
            Model::Spin(m) => resolve::cue::strike(&m, mass, r, dir, shot.speed, shot.tip)?,
        };
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
        for (what, ok) in [
            ("position", position.is_finite()),
            ("velocity", velocity.is_finite()),
            ("spin", spin.is_finite()),
        ] {
            if !ok {
                return Err(SetupError::NonFinite { ball: id, what });
            }
        }
        let radius = self.params.ball.radius;
        limits::check_motion(velocity, spin, radius)
            .map_err(|e| e.for_ball(id, self.numbers[id]))?;
        limits::check_clock(self.time)?;
        if position.x.abs() > self.bounds.x + PLACEMENT_TOLERANCE
            || position.y.abs() > self.bounds.y + PLACEMENT_TOLERANCE
        {
            return Err(SetupError::OutsideTable {
                ball: id,
                x: position.x,
                y: position.y,
            });
        }
        let r = self.params.ball.radius;
        for (j, seg) in self.segments.iter().enumerate() {
            if j != id && seg.state.motion.on_table() {
                let overlap = 2.0 * r - (seg.position_at(self.time) - position).length();
                if overlap > PLACEMENT_TOLERANCE {
                    return Err(SetupError::Overlap {
                        a: id.min(j),
                        b: id.max(j),
                        overlap,
                    });
                }
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
            self.rng = params
                .randomization
                .map(|r| ChaCha8Rng::seed_from_u64(r.seed));
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
                let n = c.inward_normal();
                let limit = self.cushion_limit(c);
                let tau = match detect::line_contact(p, v, a, n, limit, horizon) {
                    None => continue,
                    // A contact in a mouth of a table with jaws: the full search goes on.
                    Some(tau)
                        if self.table.pockets != PocketShape::Mouth
                            && !self.table.on_cushion(c, seg.position_at(t + tau)) =>
                    {
                        match self.cushion_contact(seg, t, c, horizon, kin) {
                            Some(tau) => tau,
                            None => continue,
                        }
                    }
                    Some(tau) => tau,
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
    /// `keep` is the cull's verdict ([`Kin::cull_row`]): a culled pair has no contact.
    fn solve_pair(&self, i: BallId, j: BallId, t: f64, keep: bool) -> f64 {
        let k = &self.kin;
        // Both on the table, and one of them moving.
        let (li, lj) = (k.live[i], k.live[j]);
        if !keep || li & lj & 2 == 0 || (li | lj) & 1 == 0 {
            return f64::INFINITY;
        }
        let h = k.until[i].min(k.until[j]) - t;
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

    /// The verdict of the last [`Kin::cull_row`] on ball `j` (a NaN gap keeps the pair).
    fn may_touch(&self, j: BallId) -> bool {
        self.gap[j].is_nan() || self.gap[j] <= 0.0
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
            self.kin.set(id, &self.segments[id], self.own[id]);
        }
        let contact = 2.0 * self.params.ball.radius;
        let mut affected = std::mem::take(&mut self.affected);
        affected.clear();
        // Each touched ball's earliest pair, found while its row is worked through: entries
        // left out are infinite (culled, and no contact before), and scanning partners in
        // ascending order with a strict comparison picks the same pair as `best_of_row`.
        let mut rows = [(f64::INFINITY, 0); N];
        for (k, &id) in touched.iter().enumerate() {
            if self.kin.live[id] == 3 {
                self.kin.cull_row(&mut self.gap, id, t, contact);
            } else {
                self.gap.fill(f64::NEG_INFINITY);
            }
            let (mut least, mut at) = (f64::INFINITY, 0);
            let mut base = 0;
            while base < n {
                // Most pairs are culled and had no contact before either: nothing changes for
                // them. Mark the others, 64 at a time in a tight loop (the row's later entries
                // are not written while this block is worked through).
                let end = n.min(base + 64);
                let gaps = &self.gap[base..end];
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
                        let time = self.solve_pair(id, j, t, self.may_touch(j));
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

    /// Response of ball `id` in state `s` to a fixed body (cushion or jaw) with unit normal `n`
    /// pointing towards the ball, `depth` metres into it: a resting contact (see [`resting`])
    /// or the model's cushion response. A slow spinning ball settles against a cushion or a
    /// jaw (soak seeds 10288 and 260383: rebounds that cloth friction on the spin sent
    /// straight back, or a ball wedged between a jaw and a ball).
    fn fixed_contact(
        &mut self,
        id: BallId,
        s: &BallState,
        n: Vec2,
        depth: f64,
        repeat: bool,
    ) -> (Vec2, Vec3) {
        let pressing = -self.segments[id].acceleration.dot(n);
        let approach = -s.velocity.dot(n);
        if matches!(self.params.model, Model::Spin(_)) && approach.abs() < resolve::SETTLE_SPEED {
            // Slow contact in the spin model: cloth friction on the spin would bring a
            // rebound straight back (see `resolve::SETTLE_SPEED`).
            return resolve::settle(s.velocity, s.angular_velocity, n);
        }
        if resting(depth, approach, pressing) {
            let v = if repeat {
                // A second resting contact with the same body in one instant: a ball wedged
                // between a jaw and a ball held by the other jaw bounced elastically between
                // them forever at that instant (soak seed 349173). Plastic: the approach
                // goes, no hop, and the wedge's contacts converge.
                s.velocity + n * approach.max(0.0)
            } else {
                resolve::resting_reflect(s.velocity, n, pressing, detect::RESTING_HOP)
            };
            (v, keep_rolling(s, v, self.params.ball.radius))
        } else {
            self.cushion_response(s, n)
        }
    }

    /// Has this contact already been resolved at the current instant? Records it if not.
    fn repeats(&mut self, contact: (u8, BallId, usize)) -> bool {
        if self.instant_time != self.time {
            self.instant.clear();
            self.instant_time = self.time;
        }
        let seen = self.instant.contains(&contact);
        if !seen {
            self.instant.push(contact);
        }
        seen
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

    /// When the ball of `seg` next touches `cushion`. With the paper's mouths, any contact
    /// with the cushion line counts (a contact inside a mouth pockets the ball). With jaws,
    /// only contacts on the cushion itself count: a root in a mouth means the ball crossed the
    /// line's extension into the mouth, and the search goes on from where it comes back out.
    fn cushion_contact(
        &self,
        seg: &Segment,
        t: f64,
        cushion: Cushion,
        horizon: f64,
        kin: Kinematics,
    ) -> Option<f64> {
        let limit = self.cushion_limit(cushion);
        let n = cushion.inward_normal();
        let mut from = 0.0;
        // A path is a parabola: it crosses a line at most twice, so two retries suffice.
        for _ in 0..3 {
            let tau = detect::ball_line(seg, t + from, n, limit, horizon - from, kin)? + from;
            if self.table.pockets == PocketShape::Mouth
                || self.table.on_cushion(cushion, seg.position_at(t + tau))
            {
                return Some(tau);
            }
            // In a mouth: skip to where the centre is back on the table side of the line.
            let p = seg.position_at(t + tau);
            let v = seg.velocity_at(t + tau);
            let a = match kin {
                Kinematics::Exact => seg.acceleration,
                Kinematics::Linear => Vec2::ZERO,
            };
            let back = crate::poly::Poly::new([
                -(limit + n.dot(p)) + detect::SEPARATION,
                -n.dot(v),
                -0.5 * n.dot(a),
                0.0,
                0.0,
            ]);
            let out = crate::poly::first_entry(
                &back,
                0.0,
                (horizon - tau).min(crate::poly::root_bound(&back)),
            )?;
            from = tau + out.max(f64::EPSILON * (t + tau).abs());
        }
        None
    }

    fn predict_all(&mut self) {
        if !self.grid.is_split() {
            let (n, t) = (self.segments.len(), self.time);
            self.pairs = vec![f64::INFINITY; n * n];
            for id in 0..n {
                self.own[id] = self.predict_own(id, t);
            }
            self.kin = Kin::new(n);
            self.gap = vec![0.0; n];
            for id in 0..n {
                self.kin.set(id, &self.segments[id], self.own[id]);
            }
            let contact = 2.0 * self.params.ball.radius;
            for i in 0..n {
                if self.kin.live[i] == 3 {
                    self.kin.cull_row(&mut self.gap, i, t, contact);
                } else {
                    self.gap.fill(f64::NEG_INFINITY);
                }
                for j in i + 1..n {
                    let time = self.solve_pair(i, j, t, self.may_touch(j));
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

    /// A Gaussian rotation of a collision normal (paper 5), if randomization is on.
    fn perturbation(&mut self) -> Option<f64> {
        let spread = self.params.randomization?.spread;
        let rng = self.rng.as_mut()?;
        // Box–Muller from two uniforms in (0, 1].
        let u1: f64 = 1.0 - rng.random::<f64>();
        let u2: f64 = rng.random::<f64>();
        Some(spread * (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos())
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
                let n = d.normalized().unwrap_or(Vec2::new(0.0, 1.0));
                let depth = self.params.ball.radius + self.jaw_radius() - d.length();
                let repeat = self.repeats((1, id, k));
                let (v, w) = self.fixed_contact(id, &s, n, depth, repeat);
                self.segments[id] = motion::segment_from(&self.params, t, s.position, v, w);
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
                    let n = cushion.inward_normal();
                    let limit = self.cushion_limit(cushion);
                    let depth = -(limit + n.dot(s.position));
                    let repeat = self.repeats((0, id, cushion as usize));
                    let (v, w) = self.fixed_contact(id, &s, n, depth, repeat);
                    self.segments[id] = motion::segment_from(&self.params, t, s.position, v, w);
                    self.record(EventKind::Cushion { ball: id, cushion });
                }
                self.repredict([id]);
            }
            PendingKind::Pair(a, b) => {
                let (sa, sb) = (self.segments[a].state_at(t), self.segments[b].state_at(t));
                let d = sb.position - sa.position;
                let n = d.normalized().unwrap_or(Vec2::new(1.0, 0.0));
                let depth = 2.0 * self.params.ball.radius - d.length();
                let dv = sb.velocity - sa.velocity;
                let da = self.segments[b].acceleration - self.segments[a].acceleration;
                // Relative normal acceleration pushing the pair together, less the centripetal
                // term of their sliding past each other (which pulls them apart).
                let pressing =
                    -da.dot(n) - dv.perp_dot(n).powi(2) / d.length().max(f64::MIN_POSITIVE);
                let (na, nb) = if resting(depth, -dv.dot(n), pressing) {
                    let (va, vb) = resolve::resting_contact(
                        sa.velocity,
                        sb.velocity,
                        n,
                        pressing,
                        detect::RESTING_HOP,
                    );
                    let r = self.params.ball.radius;
                    // Pressed head-on with no tangential speed to turn into the hop (a sliding
                    // ball driven into another by its own spin, as after a follow shot): its
                    // spin pays for the hop, as its cloth friction would by pushing.
                    let (mut va, mut vb, mut wa, mut wb) =
                        (va, vb, sa.angular_velocity, sb.angular_velocity);
                    let want = (2.0 * pressing.max(0.0) * detect::RESTING_HOP).sqrt();
                    let got = (vb - va).dot(n);
                    if got < want {
                        let half = n * (0.5 * (want - got));
                        let (va2, vb2) = (va - half, vb + half);
                        let m = self.params.ball.mass;
                        let cost = 0.5
                            * m
                            * (va2.length_squared() + vb2.length_squared()
                                - va.length_squared()
                                - vb.length_squared());
                        let inertia = 0.4 * m * r * r;
                        let spin_energy = |w: Vec3| 0.5 * inertia * (w.x * w.x + w.y * w.y);
                        let payer = [(&sa, &mut wa), (&sb, &mut wb)]
                            .into_iter()
                            .filter(|(s, w)| {
                                s.motion == Motion::Sliding && spin_energy(**w) > 2.0 * cost
                            })
                            .max_by(|x, y| spin_energy(*x.1).total_cmp(&spin_energy(*y.1)));
                        if cost <= 0.0 {
                            (va, vb) = (va2, vb2);
                        } else if let Some((_, w)) = payer {
                            let k = (1.0 - cost * (1.0 + 1e-9) / spin_energy(*w)).sqrt();
                            *w = Vec3::new(w.x * k, w.y * k, w.z);
                            (va, vb) = (va2, vb2);
                        } else {
                            // Nothing to pay a hop with (soak seed 16706: a ball with next to
                            // no roll spin driven by its slip into a ball held by a rail): the
                            // contact holds, and its slip into the other ball goes, as cloth
                            // friction would remove it within microseconds.
                            if sa.motion == Motion::Sliding {
                                wa = resolve::unpress(va, wa, n, r).unwrap_or(wa);
                            }
                            if sb.motion == Motion::Sliding {
                                wb = resolve::unpress(vb, wb, -n, r).unwrap_or(wb);
                            }
                        }
                    }
                    let sa = BallState {
                        angular_velocity: wa,
                        ..sa
                    };
                    let sb = BallState {
                        angular_velocity: wb,
                        ..sb
                    };
                    // Both rolling: the pair's energy is 7/10 m (|va|^2 + |vb|^2), which the
                    // resting contact never raises. Otherwise only a ball that slows may keep
                    // rolling (its spin energy then falls too).
                    let both = sa.motion == Motion::Rolling && sb.motion == Motion::Rolling;
                    let roll = |s: &BallState, v: Vec2| {
                        if both || v.length_squared() <= s.velocity.length_squared() {
                            keep_rolling(s, v, r)
                        } else {
                            s.angular_velocity
                        }
                    };
                    (
                        BallState {
                            velocity: va,
                            angular_velocity: roll(&sa, va),
                            ..sa
                        },
                        BallState {
                            velocity: vb,
                            angular_velocity: roll(&sb, vb),
                            ..sb
                        },
                    )
                } else {
                    self.pair_response(&sa, &sb, n)
                };
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

    /// Velocity and spin after a cushion contact with inward normal `n`, under the model in
    /// force; with randomization the normal is perturbed, unless that would send the ball out.
    fn cushion_response(&mut self, s: &BallState, n: Vec2) -> (Vec2, Vec3) {
        let (v, w, r) = (s.velocity, s.angular_velocity, self.params.ball.radius);
        let model = self.params.model;
        let respond = |n: Vec2| match model {
            Model::Paper(m) => resolve::reflect(v, n, m.e_cushion).map(|v| (v, w)),
            Model::Spin(m) => match m.cushion {
                CushionModel::Reflect { e } => resolve::reflect(v, n, e).map(|v| (v, w)),
                CushionModel::Han2005 { e, mu } => {
                    resolve::han_2005(v, w, n, e, mu, r, 2.0 * r * m.cushion_height)
                }
            },
        };
        let perturbed = self.perturbation().map(|a| n.rotated(a));
        perturbed
            .and_then(respond)
            .filter(|(v, _)| v.dot(n) >= 0.0)
            .or_else(|| respond(n))
            .unwrap_or((v, w))
    }

    /// States after a ball–ball contact along unit normal `n` (from `a` to `b`), under the
    /// model in force; with randomization the normal is perturbed, unless that would leave the
    /// balls approaching along the true normal.
    fn pair_response(&mut self, a: &BallState, b: &BallState, n: Vec2) -> (BallState, BallState) {
        let (r, model) = (self.params.ball.radius, self.params.model);
        let respond = |n: Vec2| match model {
            Model::Paper(m) => resolve::equal_mass_restitution(a.velocity, b.velocity, n, m.e_ball)
                .map(|(va, vb)| {
                    (
                        BallState { velocity: va, ..*a },
                        BallState { velocity: vb, ..*b },
                    )
                }),
            Model::Spin(m) => resolve::frictional_spheres(a, b, n, m.e_ball, m.mu_ball, r),
        };
        let separating = |(x, y): &(BallState, BallState)| (x.velocity - y.velocity).dot(n) <= 0.0;
        let perturbed = self.perturbation().map(|ang| n.rotated(ang));
        perturbed
            .and_then(respond)
            .filter(separating)
            .or_else(|| respond(n))
            .unwrap_or((*a, *b))
    }
}

/// Is a contact a resting one (resolved by [`resolve::resting_contact`]): sunk past half the
/// resting depth, or pressed together and approaching too slowly to hop apart by the resting
/// depth on its own? Such contacts bounce elastically with a minimum hop, so that neither a
/// pressed pair (a Zeno cascade of ever smaller bounces) nor an inelastic collapse can make
/// unboundedly many events per second.
fn resting(depth: f64, approach: f64, pressing: f64) -> bool {
    depth > 0.5 * detect::RESTING_DEPTH
        || (pressing > 0.0 && approach * approach < 8.0 * pressing * detect::RESTING_DEPTH)
}

/// Spin of a ball in state `s` whose velocity a resting contact changed to `v`: a rolling ball
/// keeps rolling (its spin follows the small change of velocity), so a micro-impulse does not
/// leave a tiny slip whose sliding friction, large against it, would press the pair together
/// again within femtoseconds (the spin model); any other ball keeps its spin.
fn keep_rolling(s: &BallState, v: Vec2, radius: f64) -> Vec3 {
    if s.motion != Motion::Rolling {
        return s.angular_velocity;
    }
    let dv = v - s.velocity;
    s.angular_velocity + Vec3::new(-dv.y / radius, dv.x / radius, 0.0)
}

fn check_overlaps(balls: &[BallSetup], r: f64) -> Result<(), SetupError> {
    // Sort by x so only neighbours within 2R in x are compared (large layouts stay fast).
    let mut order: Vec<usize> = (0..balls.len()).collect();
    order.sort_by(|&i, &j| balls[i].position.x.total_cmp(&balls[j].position.x));
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if balls[j].position.x - balls[i].position.x >= 2.0 * r {
                break;
            }
            let overlap = 2.0 * r - (balls[j].position - balls[i].position).length();
            if overlap > PLACEMENT_TOLERANCE {
                return Err(SetupError::Overlap {
                    a: i.min(j),
                    b: i.max(j),
                    overlap,
                });
            }
        }
    }
    Ok(())
}
