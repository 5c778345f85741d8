//! The event history: every event, and each ball's piecewise closed-form trajectory, so any
//! instant can be sampled exactly without re-simulating.
//!
//! A ball's segment after an event is not stored: it is rebuilt on demand from the event's
//! recorded after-state and the parameters then in force ([`motion::segment_with_motion`], the
//! very segment the solver built), so the history costs an event and a small index per
//! ball it changed (about 200 bytes an event, not the 390 that storing every segment took).
//! Only segments no event holds are stored whole: the initial ones and those re-derived when
//! the parameters change.

use crate::ball::{BallId, BallState, Segment};
use crate::event::Event;
use crate::motion;
use crate::params::Params;

/// Where one segment of a ball's track comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Source {
    /// The after-state of event `.0`, in slot `.1` of its balls.
    Event(usize, u8),
    /// Stored segment `.0` of [`History::stored`].
    Stored(usize),
}

/// Everything that happened in a simulation, in time order.
#[derive(Debug, PartialEq)]
pub struct History {
    events: Vec<Event>,
    /// Per ball, the sources of its segments in start order (the first one is its initial
    /// state).
    tracks: Vec<Vec<Source>>,
    /// Segments that no event's after-state gives.
    stored: Vec<Segment>,
    /// The parameters in force from each event index on, in index order (the first from 0).
    params: Vec<(usize, Params)>,
    /// Event index ranges that are one cluster impact each, in order (not saved in
    /// recordings: a history rebuilt from one has none).
    impacts: Vec<std::ops::Range<usize>>,
}

clone_reusing!(History {
    events,
    tracks,
    stored,
    params,
    impacts
});

impl History {
    /// A history that starts with these segments, under `params`, and no events.
    pub fn new(initial: &[Segment], params: Params) -> Self {
        Self {
            events: Vec::new(),
            tracks: (0..initial.len())
                .map(|i| vec![Source::Stored(i)])
                .collect(),
            stored: initial.to_vec(),
            params: vec![(0, params)],
            impacts: Vec::new(),
        }
    }

    /// Marks the events `range` (the last ones pushed) as one cluster impact: pair events at
    /// one instant, each holding its balls' states after the whole impact.
    pub fn mark_impact(&mut self, range: std::ops::Range<usize>) {
        debug_assert!(range.end == self.events.len());
        self.impacts.push(range);
    }

    /// The cluster impact event `index` belongs to, if any.
    pub fn impact_of(&self, index: usize) -> Option<std::ops::Range<usize>> {
        let k = self.impacts.partition_point(|r| r.end <= index);
        self.impacts.get(k).filter(|r| r.contains(&index)).cloned()
    }

    /// Appends an event; the balls it names continue on the segments that their states in
    /// `event.after` start under the parameters in force.
    pub fn push(&mut self, event: Event) {
        let index = self.events.len();
        for (slot, id) in event.kind.balls().enumerate() {
            self.tracks[id].push(Source::Event(index, slot as u8));
        }
        self.events.push(event);
    }

    /// Appends a change of parameters to `params`, after which every ball continues on its
    /// segment in `segments`.
    pub fn push_all(&mut self, event: Event, segments: &[Segment], params: Params) {
        let index = self.events.len();
        for (id, seg) in segments.iter().enumerate() {
            if self.last_segment(id) != *seg {
                self.tracks[id].push(Source::Stored(self.stored.len()));
                self.stored.push(*seg);
            }
        }
        self.params.push((index, params));
        self.events.push(event);
    }

    /// All events so far, in the order they were processed (non-decreasing time).
    pub fn events(&self) -> &[Event] {
        &self.events
    }

    /// Ball `id`'s trajectory: segments in start order.
    pub fn track(&self, id: BallId) -> Vec<Segment> {
        self.tracks[id]
            .iter()
            .map(|&s| self.segment_of(s))
            .collect()
    }

    /// Number of segments in ball `id`'s trajectory.
    pub fn track_len(&self, id: BallId) -> usize {
        self.tracks[id].len()
    }

    /// Segment `k` of ball `id`'s trajectory (0 is its initial segment).
    pub fn segment(&self, id: BallId, k: usize) -> Segment {
        self.segment_of(self.tracks[id][k])
    }

    /// Number of balls.
    pub fn ball_count(&self) -> usize {
        self.tracks.len()
    }

    /// The state of ball `id` at time `t`, from the last segment starting at or before `t`.
    /// Times before the first segment give the initial state.
    pub fn state_at(&self, id: BallId, t: f64) -> BallState {
        let track = &self.tracks[id];
        let i = track.partition_point(|&s| self.start_of(s) <= t).max(1) - 1;
        let seg = self.segment_of(track[i]);
        seg.state_at(t.max(seg.start))
    }

    /// Every ball's state at time `t`.
    pub fn states_at(&self, t: f64) -> Vec<BallState> {
        (0..self.tracks.len())
            .map(|id| self.state_at(id, t))
            .collect()
    }

    fn last_segment(&self, id: BallId) -> Segment {
        let last = *self.tracks[id]
            .last()
            .expect("every track starts with a segment");
        self.segment_of(last)
    }

    fn start_of(&self, source: Source) -> f64 {
        match source {
            Source::Event(e, _) => self.events[e].time,
            Source::Stored(s) => self.stored[s].start,
        }
    }

    fn segment_of(&self, source: Source) -> Segment {
        match source {
            Source::Stored(s) => self.stored[s],
            Source::Event(e, slot) => {
                let event = &self.events[e];
                // The last change of parameters at or before this event.
                let k = self.params.partition_point(|&(from, _)| from <= e);
                let params = &self.params[k.max(1) - 1].1;
                motion::segment_with_motion(params, event.time, &event.after[usize::from(slot)])
            }
        }
    }
}
