//! The simulation and its event loop: the paper's `Progress(T)` (section 4.2) as a loop over
//! exact events. Take the earliest predicted event (`predict.rs`), move the clock to it,
//! resolve it ([`crate::resolve`]) into new segments for the balls it touched, record it, and
//! re-predict only those balls and the balls whose prediction involved them.

use crate::ball::{BallId, BallState, Motion, Segment};
use crate::event::{Event, EventKind};
use crate::history::History;
use crate::limits;
use crate::math::{Vec2, Vec3};
use crate::motion;
use crate::params::{Model, ParamError, Params, SpinModel};
use crate::resolve::{self, FixedBody, FixedContact, InstantContacts, Laws, NormalPerturbation};
use crate::table::{Cushion, Pocket, PocketShape, Table};
use pending::{Pending, PendingKind};
use predict::{Predictions, StrategyChoice};
use scene::{Bodies, Scene};

mod cell_lists;
mod cluster;
mod deferred;
mod flight;
#[cfg(test)]
mod forge;
mod pair_table;
mod path_box;
mod pending;
mod predict;
mod reach;
mod scene;
mod setup;

pub use reach::{CLUSTER_MIN_SPEED, MAX_CLUSTER, cluster_reach};
pub use setup::{BallSetup, PLACEMENT_TOLERANCE, SetupError, SimError};

/// What one [`Simulation::advance`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Advance {
    /// Index range of the events it processed, counted from the simulation's start
    /// ([`Simulation::event_count`]): indices into [`History::events`] while the history has
    /// been recorded since the start.
    pub events: std::ops::Range<usize>,
}

/// An exact, event-driven billiards simulation.
///
/// Each ball follows a closed-form segment from its last event; positions are always evaluated
/// from there, never accumulated per step, so the trajectory does not depend on how time is
/// sliced. Predictions are cached per ball and redone only for the balls an event touched.
#[derive(Debug)]
pub struct Simulation {
    params: Params,
    numbers: Vec<u8>,
    segments: Vec<Segment>,
    /// The table's cushions, jaws and pocket openings.
    bodies: Bodies,
    /// Every ball's next event, and the strategy that keeps them up to date.
    predictions: Predictions,
    time: f64,
    history: History,
    /// Whether events go into [`Simulation::history`] (off: the lean mode of a search).
    record_history: bool,
    /// The last event processed.
    last_event: Option<Event>,
    /// Events processed since the simulation was built (grid crossings excluded), counted
    /// whether or not the history records them.
    event_count: usize,
    /// The rotation of collision normals (paper 5), if randomization is on.
    perturbation: NormalPerturbation,
    /// The contacts with cushions and jaws resolved at the current instant.
    instant_contacts: InstantContacts,
    /// Cluster impacts resolved so far.
    impacts: usize,
    /// The events of the last processed prediction (a cluster impact records several), and
    /// how many of them [`Simulation::step_event`] has handed out.
    burst: Vec<Event>,
    burst_next: usize,
    /// Whether the event being processed leaves its balls' re-prediction for later
    /// (`stale`): set while [`Simulation::step_event`] processes one with the history off.
    defer: bool,
    /// The balls of the last event handed out by [`Simulation::step_event`], not yet
    /// re-predicted: a caller that stops reading events there (the computer's lean search,
    /// once its verdict is known) never pays for their next events. Every other entry point
    /// re-predicts them first (`deferred.rs`).
    stale: Option<(BallId, Option<BallId>)>,
}

clone_reusing!(Simulation {
    params,
    numbers,
    segments,
    bodies,
    predictions,
    time,
    history,
    record_history,
    last_event,
    event_count,
    perturbation,
    instant_contacts,
    impacts,
    burst,
    burst_next,
    defer,
    stale,
});

impl Simulation {
    /// Builds a simulation at time 0, checking the table, the parameters and the layout.
    pub fn new(table: Table, params: Params, balls: &[BallSetup]) -> Result<Self, SetupError> {
        Self::with_strategy(table, params, balls, StrategyChoice::Auto)
    }

    /// [`Simulation::new`] with the strategy that finds ball contacts chosen by `choice`.
    pub(crate) fn with_strategy(
        table: Table,
        params: Params,
        balls: &[BallSetup],
        choice: StrategyChoice,
    ) -> Result<Self, SetupError> {
        params.validate()?;
        let r = params.ball.radius;
        table.validate(r)?;
        let bodies = Bodies::new(table, r);
        setup::check_layout(balls, r, &table)?;
        let segments: Vec<Segment> = balls
            .iter()
            .map(|b| motion::segment_from(&params, 0.0, b.position, b.velocity, b.spin))
            .collect();
        let n = segments.len();
        let mut sim = Self {
            params,
            numbers: balls.iter().map(|b| b.number).collect(),
            history: History::new(&segments, params),
            record_history: true,
            last_event: None,
            event_count: 0,
            predictions: Predictions::new(n, bodies.bounds, r, choice),
            bodies,
            segments,
            time: 0.0,
            perturbation: NormalPerturbation::new(params.randomization),
            instant_contacts: InstantContacts::default(),
            impacts: 0,
            burst: Vec::new(),
            burst_next: 0,
            defer: false,
            stale: None,
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
        &self.bodies.table
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

    /// The event history (empty of events while [`Simulation::set_record_history`] is off).
    pub fn history(&self) -> &History {
        &self.history
    }

    /// Turns the event history on or off. Off, the history is dropped (so cloning the
    /// simulation copies no history) and no event is stored: the lean mode of a search that
    /// reads each event from [`Simulation::step_event`] and needs no replay. On again, a new
    /// history starts from the current state. The events themselves are the same either way.
    pub fn set_record_history(&mut self, on: bool) {
        if on == self.record_history {
            return;
        }
        self.record_history = on;
        self.history = if on {
            History::new(&self.segments, self.params)
        } else {
            History::new(&[], self.params)
        };
    }

    /// Whether the event history is recorded ([`Simulation::set_record_history`]).
    pub fn records_history(&self) -> bool {
        self.record_history
    }

    /// Events processed since the simulation was built (recorded in the history or not).
    pub fn event_count(&self) -> usize {
        self.event_count
    }

    /// Cluster impacts resolved since the simulation was built (each recorded as one
    /// [`EventKind::BallBall`] per pair it pressed, see [`History::impact_of`]).
    pub fn cluster_impacts(&self) -> usize {
        self.impacts
    }

    /// No ball is moving.
    pub fn is_at_rest(&self) -> bool {
        self.segments.iter().all(|s| s.state.motion.is_at_rest())
    }

    /// Time of the next event, if any.
    pub fn next_event_time(&self) -> Option<f64> {
        match self.stale {
            None => self.predictions.next().map(|p| p.time),
            Some(_) => self.next_event_time_stale(),
        }
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
    /// A cluster impact records several events at one instant: they are handed out one a
    /// call, the first when the impact is processed.
    ///
    /// With the history off (a search's lean mode), the balls of the event handed out are
    /// re-predicted when the simulation goes on (the next call, or any other entry point), so
    /// a caller that stops reading there does not pay for it; the events are the same either
    /// way ([`Simulation::next_event_time`] then predicts them on a copy, so a loop that asks
    /// it between steps should keep the history on).
    pub fn step_event(&mut self) -> Option<Event> {
        if let Some(&e) = self.burst.get(self.burst_next) {
            self.burst_next += 1;
            return Some(e);
        }
        self.flush();
        let before = self.event_count;
        // Grid crossings are internal: keep going until a physical event is processed. In the
        // lean mode (no history) the event's balls are re-predicted on the next call.
        self.defer = !self.record_history;
        while self.event_count == before {
            let Some(p) = self.predictions.next() else {
                self.defer = false;
                return None;
            };
            self.process(p);
        }
        self.defer = false;
        self.burst_next = 1;
        self.burst.first().copied()
    }

    /// Runs until every ball rests; the clock ends at the last event.
    pub fn run_to_rest(&mut self) -> Result<Advance, SimError> {
        self.process_until(f64::INFINITY)
    }

    /// The event loop: processes the next event while it is due by `t`, at most
    /// `params.max_events` of them.
    fn process_until(&mut self, t: f64) -> Result<Advance, SimError> {
        self.flush();
        let first = self.event_count;
        let mut count = 0;
        while let Some(p) = self.predictions.next().filter(|p| p.time <= t) {
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
            events: first..self.event_count,
        })
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
        self.flush();
        let r = self.params.ball.radius;
        let ball = BallSetup {
            number: self.numbers[id],
            position,
            velocity,
            spin,
        };
        setup::check_ball(id, &ball, r, &self.bodies.table)?;
        limits::check_clock(self.time)?;
        for (j, seg) in self.segments.iter().enumerate() {
            if j != id && seg.state.motion.on_table() {
                let other = (j, self.numbers[j], seg.position_at(self.time));
                setup::check_clear((id, ball.number, position), other, r)?;
            }
        }
        self.segments[id] = motion::segment_from(&self.params, self.time, position, velocity, spin);
        self.record(EventKind::Placed { ball: id });
        self.inputs_done();
        self.repredict([id]);
        Ok(())
    }

    /// Replaces the parameters now; moving balls continue from their current state under the
    /// new ones. The ball size cannot change mid-game.
    pub fn set_params(&mut self, params: Params) -> Result<(), SetupError> {
        params.validate()?;
        self.flush();
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
        self.event_count += 1;
        self.last_event = Some(event);
        self.inputs_done();
        if self.record_history {
            self.history.push_all(event, &self.segments, params);
        }
        self.predict_all();
        Ok(())
    }

    fn ball_checked(&self, id: BallId) -> Result<BallState, SetupError> {
        let seg = self.segments.get(id).ok_or(SetupError::NoSuchBall(id))?;
        if !seg.state.motion.on_table() {
            return Err(SetupError::Pocketed {
                ball: id,
                number: self.numbers[id],
            });
        }
        Ok(self.ball(id))
    }

    /// Processes event `p`, the earliest pending: the clock moves to it, the balls it
    /// touches get new segments, and the event is recorded (all but grid crossings, which
    /// are bookkeeping) and its balls re-predicted.
    fn process(&mut self, p: Pending) {
        debug_assert!(p.time >= self.time, "time never goes back");
        self.burst.clear();
        self.burst_next = 0;
        self.time = p.time;
        match p.kind {
            PendingKind::Crossing(id, side) => {
                let scene = Scene {
                    segments: &self.segments,
                    params: &self.params,
                    bodies: &self.bodies,
                };
                self.predictions.cross(&scene, id, side, self.time);
            }
            PendingKind::Transition(id) => self.transition(id),
            PendingKind::Opening(id, k) => {
                let o = self.bodies.openings[k];
                self.across_opening(id, o.pocket, o.normal)
            }
            PendingKind::Cushion(id, cushion) => self.cushion(id, cushion),
            PendingKind::Jaw(id, k) => self.jaw(id, k),
            PendingKind::Pair(a, b) => self.ball_pair(a, b),
        }
        self.burst_next = self.burst.len();
    }

    /// Ball `id`'s motion changes by itself (slide to roll, roll to rest).
    fn transition(&mut self, id: BallId) {
        let from = self.segments[id].state.motion;
        self.segments[id] = motion::after_transition(&self.params, &self.segments[id]);
        let to = self.segments[id].state.motion;
        self.record(EventKind::Transition { ball: id, from, to });
        self.repredict_event(id, None);
    }

    /// Ball `id` drops into `pocket`.
    fn pocket(&mut self, id: BallId, pocket: Pocket) {
        let t = self.time;
        let s = self.segments[id].state_at(t);
        self.segments[id] = Segment::at_rest(t, s.position, Motion::Pocketed(pocket));
        self.record(EventKind::Pocketed { ball: id, pocket });
        self.repredict_event(id, None);
    }

    /// Ball `id` reaches `cushion`'s line: in a mouth of the paper's table it drops, anywhere
    /// else (and everywhere on a table without pockets) it rebounds.
    fn cushion(&mut self, id: BallId, cushion: Cushion) {
        let s = self.segments[id].state_at(self.time);
        let table = &self.bodies.table;
        let mouth = match table.pockets {
            PocketShape::Mouth => table.pocket_at(cushion, s.position),
            PocketShape::Jaws { .. } | PocketShape::Pocketless => None,
        };
        if let Some(pocket) = mouth {
            return self.across_opening(id, pocket, cushion.inward_normal());
        }
        if self.clears_cushion(id, cushion) {
            return self.off_table(id);
        }
        let normal = cushion.inward_normal();
        let depth = -(self.bodies.cushion_limit(cushion) + normal.dot(s.position));
        self.fixed_body(id, &s, FixedBody::Cushion(cushion), normal, depth);
        self.record(EventKind::Cushion { ball: id, cushion });
        self.repredict_event(id, None);
    }

    /// Ball `id` meets jaw `k`.
    fn jaw(&mut self, id: BallId, k: usize) {
        let s = self.segments[id].state_at(self.time);
        let jaw = self.bodies.jaws[k];
        let d = s.position - jaw.centre;
        let normal = d.normalized().unwrap_or(Vec2::new(0.0, 1.0));
        let depth = self.params.ball.radius + self.bodies.jaw_radius() - d.length();
        self.fixed_body(id, &s, FixedBody::Jaw(k), normal, depth);
        let pocket = jaw.pocket;
        self.record(EventKind::Jaw { ball: id, pocket });
        self.repredict_event(id, None);
    }

    /// Ball `id`, in state `s` now, touches `body` of unit normal `normal` (towards the
    /// ball), `depth` metres into it: its new segment.
    fn fixed_body(&mut self, id: BallId, s: &BallState, body: FixedBody, normal: Vec2, depth: f64) {
        let repeat = self.instant_contacts.repeats(self.time, id, body);
        let contact = FixedContact {
            normal,
            depth,
            repeat,
        };
        let laws = Laws::of(&self.params.model);
        let (r, acceleration) = (self.params.ball.radius, self.segments[id].acceleration);
        let (v, w) =
            resolve::fixed_body(&laws, s, acceleration, contact, r, &mut self.perturbation);
        self.segments[id] = motion::segment_after(&self.params, self.time, s, v, w);
    }

    /// Balls `a` and `b` touch: a cluster impact if they have neighbours within the reach of
    /// the contact, else the pair's own law.
    fn ball_pair(&mut self, a: BallId, b: BallId) {
        let t = self.time;
        if !self.level_at(a, t) || !self.level_at(b, t) {
            return self.air_pair(a, b);
        }
        let (sa, sb) = (self.segments[a].state_at(t), self.segments[b].state_at(t));
        if let Model::Spin(SpinModel {
            cluster: Some(_), ..
        }) = self.params.model
        {
            let d = sb.position - sa.position;
            let n = d.normalized().unwrap_or(Vec2::new(1.0, 0.0));
            let dv = sb.velocity - sa.velocity;
            let da = self.segments[b].acceleration - self.segments[a].acceleration;
            let pressing = -da.dot(n) - dv.perp_dot(n).powi(2) / d.length().max(f64::MIN_POSITIVE);
            let depth = 2.0 * self.params.ball.radius - d.length();
            let reach = reach::cluster_reach(
                &self.params.model,
                &self.params.ball,
                -dv.dot(n),
                depth,
                pressing,
            );
            if let Some(cluster) = reach.and_then(|reach| self.cluster_of(a, b, reach)) {
                return self.cluster_impact(&cluster);
            }
        }
        let laws = Laws::of(&self.params.model);
        let (na, nb) = resolve::ball_pair(
            &laws,
            (sa, self.segments[a].acceleration),
            (sb, self.segments[b].acceleration),
            &self.params.ball,
            &mut self.perturbation,
        );
        let params = &self.params;
        self.segments[a] = motion::segment_after(params, t, &sa, na.velocity, na.angular_velocity);
        self.segments[b] = motion::segment_after(params, t, &sb, nb.velocity, nb.angular_velocity);
        self.record(EventKind::BallBall { a, b });
        self.repredict_event(a, Some(b));
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
        self.event_count += 1;
        self.last_event = Some(event);
        self.burst.push(event);
        if self.record_history {
            self.history.push(event);
        }
    }

    /// Marks the events recorded so far as handed out (after an input: a strike, a
    /// placement, a change of parameters is not returned by [`Simulation::step_event`]).
    fn inputs_done(&mut self) {
        self.burst.clear();
        self.burst_next = 0;
    }

    /// Predicts every ball from now.
    fn predict_all(&mut self) {
        let scene = Scene {
            segments: &self.segments,
            params: &self.params,
            bodies: &self.bodies,
        };
        self.predictions.predict_all(&scene, self.time);
    }

    /// Re-predicts after an event changed the balls `touched` (one or two).
    #[inline]
    fn repredict<const N: usize>(&mut self, touched: [BallId; N]) {
        let scene = Scene {
            segments: &self.segments,
            params: &self.params,
            bodies: &self.bodies,
        };
        self.predictions.repredict(&scene, touched, self.time);
    }
}
