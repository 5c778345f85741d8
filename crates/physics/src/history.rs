//! The event history: every event, and each ball's piecewise closed-form trajectory, so any
//! instant can be sampled exactly without re-simulating.

use crate::ball::{BallId, BallState, Segment};
use crate::event::Event;
use serde::{Deserialize, Serialize};

/// Everything that happened in a simulation, in time order.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct History {
    events: Vec<Event>,
    /// Per ball, its segments in start order (the first one is its initial state).
    tracks: Vec<Vec<Segment>>,
}

impl History {
    /// A history that starts with these segments and no events.
    pub fn new(initial: &[Segment]) -> Self {
        Self {
            events: Vec::new(),
            tracks: initial.iter().map(|s| vec![*s]).collect(),
        }
    }

    /// Appends an event; the balls it names continue with their segments in `segments`.
    pub fn push(&mut self, event: Event, segments: &[Segment]) {
        for id in event.kind.balls() {
            self.tracks[id].push(segments[id]);
        }
        self.events.push(event);
    }

    /// Appends an event after which every ball continues with its segment in `segments`.
    pub fn push_all(&mut self, event: Event, segments: &[Segment]) {
        for (track, seg) in self.tracks.iter_mut().zip(segments) {
            if track.last() != Some(seg) {
                track.push(*seg);
            }
        }
        self.events.push(event);
    }

    /// All events so far, in the order they were processed (non-decreasing time).
    pub fn events(&self) -> &[Event] {
        &self.events
    }

    /// Ball `id`'s trajectory: segments in start order.
    pub fn track(&self, id: BallId) -> &[Segment] {
        &self.tracks[id]
    }

    /// Number of balls.
    pub fn ball_count(&self) -> usize {
        self.tracks.len()
    }

    /// The state of ball `id` at time `t`, from the last segment starting at or before `t`.
    /// Times before the first segment give the initial state.
    pub fn state_at(&self, id: BallId, t: f64) -> BallState {
        let track = &self.tracks[id];
        let i = track.partition_point(|s| s.start <= t).max(1) - 1;
        let seg = &track[i];
        seg.state_at(t.max(seg.start))
    }

    /// Every ball's state at time `t`.
    pub fn states_at(&self, t: f64) -> Vec<BallState> {
        (0..self.tracks.len())
            .map(|id| self.state_at(id, t))
            .collect()
    }
}
