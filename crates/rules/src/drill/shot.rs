//! One shot of an attempt as the solver recorded it ([`DrillShot`]).

use crate::shot::{CUE, ShotSummary};
use billiards_physics::{Event, EventKind, Simulation, Vec2};
use serde::{Deserialize, Serialize};

/// One shot of an attempt as the solver recorded it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DrillShot {
    /// The rules' summary of its events.
    pub summary: ShotSummary,
    /// Cushion contacts of the cue ball before its first contact with a ball (jaws apart).
    pub cue_cushions_before_contact: u32,
    /// Cushion contacts (jaws apart) of each ball before it was pocketed (or in the shot),
    /// by number; balls without any are left out.
    pub cushions: Vec<(u8, u32)>,
    /// The balls on the table at rest after the shot, by number.
    pub rest: Vec<(u8, Vec2)>,
}

impl DrillShot {
    /// The shot of `events` (from its strike to rest; see [`crate::summarise`]) with the
    /// balls resting at `rest` afterwards.
    pub fn from_events(events: &[Event], numbers: &[u8], rest: Vec<(u8, Vec2)>) -> Self {
        let mut s = DrillShot {
            rest,
            ..Default::default()
        };
        for kind in crate::shot::after_strike(events) {
            s.record(&kind, numbers);
        }
        s
    }

    /// Adds one event after the strike (the lean solver's way, one event at a time).
    pub fn record(&mut self, kind: &EventKind, numbers: &[u8]) {
        // Cushion noses only: a ball rattled in the jaws on its way in is no bank.
        if let EventKind::Cushion { ball, .. } = *kind {
            let n = numbers.get(ball).copied().unwrap_or(u8::MAX);
            if n == CUE && self.summary.first_contact.is_none() {
                self.cue_cushions_before_contact += 1;
            }
            match self.cushions.iter_mut().find(|c| c.0 == n) {
                Some(c) => c.1 += 1,
                None => self.cushions.push((n, 1)),
            }
        }
        self.summary.record(kind, numbers);
    }

    /// The shot just played on `sim` (with a history), from event `first` (the history's
    /// length before the strike) to now, the balls at rest.
    pub fn of(sim: &Simulation, first: usize) -> Self {
        let events = &sim.history().events()[first..];
        Self::from_events(events, sim.numbers(), resting(sim))
    }

    /// Cushions ball `n` touched.
    pub fn cushions_of(&self, n: u8) -> u32 {
        self.cushions.iter().find(|c| c.0 == n).map_or(0, |c| c.1)
    }
}

/// The balls of `sim` on the table, by number and centre.
pub fn resting(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}
