//! Invariant checking, event by event: the stability contract of the solver, as code.
//!
//! A [`Monitor`] drives a [`Simulation`] one event at a time and checks, at each event:
//!
//! - no NaN or infinity in any ball's state;
//! - time never goes back;
//! - no two balls in play overlap by more than [`Tolerances::overlap`], just before the event,
//!   just after it, and at [`Tolerances::interior_samples`] instants between it and the
//!   previous event (so a pair that passed through each other between events is caught too);
//! - no ball in play is outside the cushion lines (`Table::centre_bounds`) by more than
//!   [`Tolerances::outside`];
//! - no event moves a ball (only [`EventKind::Placed`] may);
//! - the kinetic energy (translational plus rotational) never increases, neither between
//!   events nor at one, except at a [`EventKind::Strike`], [`EventKind::Placed`] or
//!   [`EventKind::ParamsChanged`];
//! - momentum is conserved by every ball–ball contact on the cloth to rounding;
//! - a run to rest ends within the event cap, with every ball at rest.
//!
//! Stability invariants hold for [`crate::Prediction::Exact`] only: the paper's linear
//! prediction is a deliberately inexact comparison mode.

use crate::ball::{BallId, BallState, Motion, Segment};
use crate::event::{Event, EventKind, Shot};
use crate::math::Vec2;
use crate::sim::{SetupError, Simulation};

mod measure;
#[cfg(test)]
mod tests;

pub use measure::{deepest_overlap, flight_energy, kinetic_energy, outside_by};

/// How much rounding each invariant allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Largest allowed overlap of two balls in play, metres.
    pub overlap: f64,
    /// Largest allowed distance of a ball's centre beyond its cushion line, metres.
    pub outside: f64,
    /// Largest allowed relative kinetic-energy gain (of the energy before) at or between
    /// events, on top of what rounding of the velocities can add (see the monitor).
    pub energy: f64,
    /// Largest allowed change of the pair's momentum at a ball–ball contact, relative to
    /// `|v_a| + |v_b|` before or after it, whichever is larger.
    pub momentum: f64,
    /// Largest allowed jump of a ball's position at an event, metres.
    pub jump: f64,
    /// Instants checked for overlaps strictly between consecutive events (evenly spaced).
    pub interior_samples: usize,
    /// Two events closer than this (seconds) belong to the same burst; the longest burst is
    /// reported in [`Stats::longest_burst`] (a Zeno cascade shows up as a huge burst).
    pub burst_window: f64,
}

impl Default for Tolerances {
    fn default() -> Self {
        Self {
            overlap: 1e-9,
            outside: 1e-9,
            energy: 1e-12,
            momentum: 1e-12,
            jump: 1e-12,
            interior_samples: 1,
            burst_window: 1e-9,
        }
    }
}

/// A broken invariant: what, where and when.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Violation {
    /// A ball's state holds NaN or infinity.
    #[error("ball {ball} has a non-finite state at t = {time}: {state:?}")]
    NonFinite {
        /// Time.
        time: f64,
        /// Ball.
        ball: BallId,
        /// Its state.
        state: BallState,
    },
    /// An event is earlier than the one before it.
    #[error("time went back from {before} to {after}")]
    TimeBack {
        /// Time of the previous event.
        before: f64,
        /// Time of this one.
        after: f64,
    },
    /// Two balls overlap.
    #[error("balls {a} and {b} overlap by {depth:e} m at t = {time} ({when})")]
    Overlap {
        /// Time.
        time: f64,
        /// Lower ball index.
        a: BallId,
        /// Higher ball index.
        b: BallId,
        /// Depth, metres.
        depth: f64,
        /// "before", "after" or "between" the event.
        when: &'static str,
    },
    /// A ball is beyond a cushion line.
    #[error("ball {ball} is {by:e} m beyond the cushions at t = {time}: {position:?}")]
    Outside {
        /// Time.
        time: f64,
        /// Ball.
        ball: BallId,
        /// Its centre.
        position: Vec2,
        /// How far beyond, metres.
        by: f64,
    },
    /// An event moved a ball.
    #[error("ball {ball} jumped by {by:e} m at t = {time} ({kind:?})")]
    Jump {
        /// Time.
        time: f64,
        /// What happened.
        kind: EventKind,
        /// Ball.
        ball: BallId,
        /// Distance, metres.
        by: f64,
    },
    /// The kinetic energy rose.
    #[error("kinetic energy rose from {before} J to {after} J at t = {time} ({what})")]
    EnergyGain {
        /// Time.
        time: f64,
        /// Energy before, joules.
        before: f64,
        /// Energy after, joules.
        after: f64,
        /// "at `<event>`" or "between events".
        what: String,
    },
    /// A ball–ball contact changed the pair's momentum.
    #[error("momentum of balls {a},{b} changed by {change:e} (relative) at t = {time}")]
    Momentum {
        /// Time.
        time: f64,
        /// Lower ball.
        a: BallId,
        /// Higher ball.
        b: BallId,
        /// Relative change.
        change: f64,
    },
    /// The run hit the event cap.
    #[error("{events} events without coming to rest (cap {cap}), at t = {time}")]
    EventCap {
        /// Events processed in the run.
        events: usize,
        /// The cap.
        cap: usize,
        /// Simulation time reached.
        time: f64,
    },
    /// No event is pending but a ball still moves.
    #[error("no event is pending but ball {ball} still moves at t = {time}")]
    MovingForever {
        /// Time.
        time: f64,
        /// Ball.
        ball: BallId,
    },
}

/// What a checked run measured.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Events processed.
    pub events: usize,
    /// Deepest overlap seen, metres (0 if none).
    pub worst_overlap: f64,
    /// Largest relative kinetic-energy gain seen where energy may not rise (0 if none).
    pub worst_energy_gain: f64,
    /// Largest relative momentum change at a ball–ball contact.
    pub worst_momentum: f64,
    /// Most events in one burst (consecutive events within `burst_window` of each other).
    pub longest_burst: usize,
    /// Simulation time at the end.
    pub time: f64,
}

impl Stats {
    /// Combines the figures of two runs (sums counts, keeps the worst of each measure).
    pub fn merge(&mut self, o: &Stats) {
        self.events += o.events;
        self.worst_overlap = self.worst_overlap.max(o.worst_overlap);
        self.worst_energy_gain = self.worst_energy_gain.max(o.worst_energy_gain);
        self.worst_momentum = self.worst_momentum.max(o.worst_momentum);
        self.longest_burst = self.longest_burst.max(o.longest_burst);
        self.time = self.time.max(o.time);
    }
}

/// Drives a simulation and checks every invariant of the module docs at every event it
/// records. The checks replay the simulation's [`crate::History`] (each event and the segment
/// each ball it names continues on), so they see exactly what a recording or the game sees,
/// whether the simulation is driven event by event or by [`Simulation::advance_to`].
#[derive(Clone, Debug)]
pub struct Monitor {
    tol: Tolerances,
    stats: Stats,
    last_time: f64,
    burst: usize,
    /// Kinetic energy just after the last event (or at the start).
    energy: f64,
    /// Events of the history checked so far.
    seen: usize,
    /// Per ball: index of its segment in force in its history track, and that segment.
    at: Vec<usize>,
    work: Vec<Segment>,
}

impl Monitor {
    /// Starts monitoring `sim` from its current state, which is checked at once.
    pub fn new(sim: &Simulation, tol: Tolerances) -> Result<Self, Violation> {
        let h = sim.history();
        let at: Vec<usize> = (0..sim.ball_count()).map(|i| h.track_len(i) - 1).collect();
        let work: Vec<Segment> = (0..sim.ball_count()).map(|i| *sim.segment(i)).collect();
        let states: Vec<BallState> = sim.balls().collect();
        let mut m = Self {
            tol,
            stats: Stats {
                time: sim.time(),
                ..Stats::default()
            },
            last_time: sim.time(),
            burst: 0,
            energy: 0.0,
            seen: h.events().len(),
            at,
            work,
        };
        m.check_states(sim, &states, sim.time(), "after")?;
        m.energy = m.energy_of(sim, &states);
        Ok(m)
    }

    /// The figures so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    fn energy_of(&self, sim: &Simulation, states: &[BallState]) -> f64 {
        let b = sim.params().ball;
        kinetic_energy(states, b.mass, b.radius)
            + flight_energy(states, b.mass, sim.params().gravity)
    }

    fn states_at(&self, t: f64) -> Vec<BallState> {
        self.work
            .iter()
            .map(|s| s.state_at(t.max(s.start)))
            .collect()
    }

    /// NaN, escape and overlap checks on one snapshot.
    fn check_states(
        &mut self,
        sim: &Simulation,
        states: &[BallState],
        time: f64,
        when: &'static str,
    ) -> Result<(), Violation> {
        let r = sim.params().ball.radius;
        for (ball, s) in states.iter().enumerate() {
            let finite =
                s.position.is_finite() && s.velocity.is_finite() && s.angular_velocity.is_finite();
            if !finite {
                return Err(Violation::NonFinite {
                    time,
                    ball,
                    state: *s,
                });
            }
            if s.motion.on_table() {
                let by = outside_by(sim.table(), r, s.position);
                if by > self.tol.outside {
                    return Err(Violation::Outside {
                        time,
                        ball,
                        position: s.position,
                        by,
                    });
                }
            }
        }
        if let Some((a, b, depth)) = deepest_overlap(states, r) {
            self.stats.worst_overlap = self.stats.worst_overlap.max(depth);
            if depth > self.tol.overlap {
                return Err(Violation::Overlap {
                    time,
                    a,
                    b,
                    depth,
                    when,
                });
            }
        }
        Ok(())
    }

    /// A ball–ball contact on the cloth keeps the momentum (in the plane) of `balls`, the
    /// balls of its group, to rounding.
    fn momentum_check(
        &mut self,
        kind: EventKind,
        balls: &[BallId],
        before: &[BallState],
        after: &[BallState],
        t: f64,
    ) -> Result<(), Violation> {
        // A contact in the air also exchanges vertical momentum, and the slate takes what
        // it drives into it: the plane's momentum is kept only by contacts on the cloth.
        let in_air = |i: usize| before[i].motion == Motion::Airborne;
        if let EventKind::BallBall { a, b } = kind
            && !in_air(a)
            && !in_air(b)
        {
            let sum = |s: &[BallState]| balls.iter().fold(Vec2::ZERO, |p, &i| p + s[i].velocity);
            let speeds =
                |s: &[BallState]| balls.iter().map(|&i| s[i].velocity.length()).sum::<f64>();
            let (p0, p1) = (sum(before), sum(after));
            // Rounding scales with the largest speeds in the sums: after the contact, if a
            // resting hop made them far larger than before (seed 349173: a 1e-4 m/s hop of
            // balls creeping at 1e-8 m/s).
            let scale = speeds(before).max(speeds(after));
            let change = (p1 - p0).length() / scale.max(f64::MIN_POSITIVE);
            self.stats.worst_momentum = self.stats.worst_momentum.max(change);
            if change > self.tol.momentum {
                return Err(Violation::Momentum {
                    time: t,
                    a,
                    b,
                    change,
                });
            }
        }
        Ok(())
    }

    /// Energy that rounding alone can add when velocities are evaluated at `t`: a velocity
    /// `v0 + a tau` is good to about `4 eps (|v0| + |a| (tau + 2 |t|))`, which is large against
    /// a small final speed (a ball set to exactly its slide/roll threshold after decelerating
    /// from a much higher speed, for instance).
    fn rounding_energy(&self, sim: &Simulation, t: f64) -> f64 {
        let m = sim.params().ball.mass;
        let r = sim.params().ball.radius;
        self.work
            .iter()
            .filter(|s| s.state.motion.is_moving())
            .map(|s| {
                // The elapsed time itself is only known to an ulp or so of the absolute time.
                let tau = (t - s.start).max(0.0);
                let slop = 4.0 * f64::EPSILON * (tau + 2.0 * t.abs());
                let v = s.speed + s.accel * tau;
                let dv = 4.0 * f64::EPSILON * s.speed + s.accel * slop;
                let w = s.state.angular_velocity.length() + s.angular_acceleration.length() * tau;
                let dw = 4.0 * f64::EPSILON * w + s.angular_acceleration.length() * slop;
                m * v * dv + 0.4 * m * r * r * w * dw
            })
            .sum()
    }

    fn energy_check(
        &mut self,
        before: f64,
        after: f64,
        rounding: f64,
        time: f64,
        what: impl FnOnce() -> String,
    ) -> Result<(), Violation> {
        let gain = (after - before) / before.max(f64::MIN_POSITIVE);
        if after > before {
            self.stats.worst_energy_gain = self.stats.worst_energy_gain.max(gain);
            if after - before > self.tol.energy * before + rounding {
                return Err(Violation::EnergyGain {
                    time,
                    before,
                    after,
                    what: what(),
                });
            }
        }
        Ok(())
    }

    /// Checks every event `sim` has recorded since the last check.
    pub fn catch_up(&mut self, sim: &Simulation) -> Result<(), Violation> {
        let h = sim.history();
        let n = self.work.len();
        while self.seen < h.events().len() {
            let event = h.events()[self.seen];
            let t = event.time;
            if t.is_nan() || t < self.last_time {
                return Err(Violation::TimeBack {
                    before: self.last_time,
                    after: t,
                });
            }
            // Between the previous event and this one: overlaps, and energy never rising.
            let t0 = self.last_time;
            let samples = self.tol.interior_samples;
            for k in 1..=samples {
                let ts = t0 + (t - t0) * k as f64 / (samples + 1) as f64;
                if ts > t0 && ts < t {
                    let states = self.states_at(ts);
                    self.check_states(sim, &states, ts, "between")?;
                }
            }
            let before = self.states_at(t);
            self.check_states(sim, &before, t, "before")?;
            let e_before = self.energy_of(sim, &before);
            let rounding = self.rounding_energy(sim, t);
            self.energy_check(self.energy, e_before, rounding, t, || {
                "between events".into()
            })?;

            // A cluster impact is several pair events at one instant, each with its balls'
            // states after the whole impact: checked as one event.
            let span = h.impact_of(self.seen).map_or(1, |r| r.end - self.seen);
            let group = &h.events()[self.seen..self.seen + span];
            // The segments the event's balls continue on.
            if event.kind == EventKind::ParamsChanged {
                // Every ball whose segment changed continues on a new one from this instant.
                for i in 0..n {
                    if self.at[i] + 1 < h.track_len(i) {
                        let next = h.segment(i, self.at[i] + 1);
                        if next.start == t {
                            self.at[i] += 1;
                            self.work[i] = next;
                        }
                    }
                }
            } else {
                for e in group {
                    for i in e.kind.balls() {
                        self.at[i] += 1;
                        self.work[i] = h.segment(i, self.at[i]);
                    }
                }
            }
            let mut balls: Vec<BallId> = group.iter().flat_map(|e| e.kind.balls()).collect();
            balls.sort_unstable();
            balls.dedup();
            let after = self.states_at(t);
            self.check_states(sim, &after, t, "after")?;
            for &ball in &balls {
                let by = (after[ball].position - before[ball].position).length();
                if by > self.tol.jump && !matches!(event.kind, EventKind::Placed { .. }) {
                    return Err(Violation::Jump {
                        time: t,
                        kind: event.kind,
                        ball,
                        by,
                    });
                }
            }
            let e_after = self.energy_of(sim, &after);
            let input = matches!(
                event.kind,
                EventKind::Strike { .. } | EventKind::Placed { .. } | EventKind::ParamsChanged
            );
            if !input {
                self.energy_check(e_before, e_after, rounding, t, || {
                    format!("at {:?}", event.kind)
                })?;
            }
            self.momentum_check(event.kind, &balls, &before, &after, t)?;
            if input {
                // A strike is not part of the shot's chain of events.
            } else if self.burst > 0 && t - self.last_time <= self.tol.burst_window {
                self.burst += 1;
            } else {
                self.burst = 1;
            }
            self.stats.longest_burst = self.stats.longest_burst.max(self.burst);
            if !input {
                self.stats.events += span;
            }
            self.stats.time = t;
            self.last_time = t;
            self.energy = e_after;
            self.seen += span;
        }
        Ok(())
    }

    /// Processes the next event of `sim` ([`Simulation::step_event`]) and checks it; `Ok(None)`
    /// when nothing is pending.
    pub fn step(&mut self, sim: &mut Simulation) -> Result<Option<Event>, Violation> {
        let Some(event) = sim.step_event() else {
            if let Some(ball) = (0..sim.ball_count()).find(|&i| sim.ball(i).motion.is_moving()) {
                return Err(Violation::MovingForever {
                    time: sim.time(),
                    ball,
                });
            }
            return Ok(None);
        };
        self.catch_up(sim)?;
        Ok(Some(event))
    }

    /// Strikes `ball` through the monitor (a strike is the one event allowed to add energy).
    pub fn strike(
        &mut self,
        sim: &mut Simulation,
        ball: BallId,
        shot: Shot,
    ) -> Result<(), SetupError> {
        sim.strike(ball, shot)?;
        self.catch_up(sim)
            .expect("a strike breaks no invariant by itself");
        Ok(())
    }

    /// Runs `sim` to rest, checking every event; at most `params().max_events` events in this
    /// call, as [`Simulation::run_to_rest`].
    pub fn run_to_rest(&mut self, sim: &mut Simulation) -> Result<Stats, Violation> {
        let cap = sim.params().max_events;
        let mut count = 0;
        loop {
            if count == cap && sim.next_event_time().is_some() {
                return Err(Violation::EventCap {
                    events: count,
                    cap,
                    time: sim.time(),
                });
            }
            if self.step(sim)?.is_none() {
                return Ok(self.stats);
            }
            count += 1;
        }
    }

    /// Runs `sim` up to absolute time `t` with [`Simulation::advance_to`] (for scenes that never
    /// rest, such as frictionless ones), then checks every event it processed and the state at
    /// `t`.
    pub fn run_until(&mut self, sim: &mut Simulation, t: f64) -> Result<Stats, Violation> {
        let advanced = sim.advance_to(t);
        self.catch_up(sim)?;
        if let Err(crate::SimError::EventCap { cap, time }) = advanced {
            return Err(Violation::EventCap {
                events: cap,
                cap,
                time,
            });
        }
        let states = self.states_at(t);
        self.check_states(sim, &states, t, "between")?;
        let e = self.energy_of(sim, &states);
        let rounding = self.rounding_energy(sim, t);
        self.energy_check(self.energy, e, rounding, t, || "between events".into())?;
        self.energy = e;
        self.last_time = t;
        self.stats.time = t;
        Ok(self.stats)
    }
}

/// Checks a whole run to rest of `sim` with default tolerances: the one-line form for tests.
pub fn run_to_rest_checked(sim: &mut Simulation) -> Result<Stats, Violation> {
    Monitor::new(sim, Tolerances::default())?.run_to_rest(sim)
}
