//! The shots of a recording: shot `k` (counted from 1, as a player counts) runs from its
//! strike to the next strike, or to the end of the recording. The game's timeline, its
//! exports and `billiards-cli export --shot K` all number shots this way.

use billiards_physics::recording::{Action, Recording};

/// The start times of a recording's shots and where the recording ends.
#[derive(Debug, Clone, PartialEq)]
pub struct Shots {
    /// Time of each strike input, in order.
    starts: Vec<f64>,
    /// The recording's end: its end time, or its last event if that is later.
    end: f64,
}

impl Shots {
    /// The shots of `recording`, from its strike inputs (the inputs, not the events, are what
    /// the player did; every accepted strike is also an event at the same time).
    pub fn of(recording: &Recording) -> Self {
        let starts = recording
            .inputs
            .iter()
            .filter(|input| matches!(input.action, Action::Strike { .. }))
            .map(|input| input.time)
            .collect();
        let last_event = recording.events.last().map_or(0.0, |event| event.time);
        Self {
            starts,
            end: recording.end_time.max(last_event),
        }
    }

    /// Shots from explicit strike times (sorted) and an end time.
    pub fn from_starts(starts: Vec<f64>, end: f64) -> Self {
        debug_assert!(starts.is_sorted(), "strike times must be in order");
        Self { starts, end }
    }

    /// How many shots there are.
    pub fn len(&self) -> usize {
        self.starts.len()
    }

    /// Whether the recording has no shot.
    pub fn is_empty(&self) -> bool {
        self.starts.is_empty()
    }

    /// Strike times, in order: shot `k` starts at `starts()[k - 1]`.
    pub fn starts(&self) -> &[f64] {
        &self.starts
    }

    /// Where the recording ends (its end time, or its last event if later).
    pub fn end(&self) -> f64 {
        self.end
    }

    /// The whole recording's time span.
    pub fn whole(&self) -> (f64, f64) {
        (0.0, self.end)
    }

    /// Time span of shot `k` (from 1): its strike to the next strike or the end. `None` for
    /// `k = 0` or past the last shot.
    pub fn span(&self, k: usize) -> Option<(f64, f64)> {
        let start = *self.starts.get(k.checked_sub(1)?)?;
        let end = self.starts.get(k).copied().unwrap_or(self.end);
        Some((start, end))
    }

    /// The shot under time `t`, from 1 (0 before the first strike). A strike's own instant
    /// belongs to the shot it starts.
    pub fn at(&self, t: f64) -> usize {
        self.starts.partition_point(|&start| start <= t)
    }

    /// The time of the first strike after `t`.
    pub fn next_start(&self, t: f64) -> Option<f64> {
        self.starts.iter().copied().find(|&start| start > t)
    }

    /// The time of the last strike before `t`.
    pub fn previous_start(&self, t: f64) -> Option<f64> {
        self.starts.iter().rev().copied().find(|&start| start < t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::{Params, Rack, Shot, Table, recording::Recorder};

    /// A real two-shot recording: a break, then a soft shot once everything rests.
    fn two_shots() -> Recording {
        let table = Table::wpa_8ft();
        let params = Params::default();
        let balls = Rack::NineBall.layout(&table, &params.ball);
        let mut rec = Recorder::new(table, params, balls).unwrap();
        rec.strike(0, Shot::new(0.0, 8.0)).unwrap();
        rec.run_to_rest().unwrap();
        rec.advance(0.5).unwrap();
        if rec.sim().ball(0).motion.on_table() {
            rec.strike(0, Shot::new(1.0, 1.0)).unwrap();
        } else {
            rec.place(0, table.head_spot(), Default::default(), Default::default())
                .unwrap();
            rec.strike(0, Shot::new(1.0, 1.0)).unwrap();
        }
        rec.run_to_rest().unwrap();
        rec.recording()
    }

    #[test]
    fn shots_count_from_one_and_span_strike_to_strike() {
        let recording = two_shots();
        let shots = Shots::of(&recording);
        assert_eq!(shots.len(), 2);
        let [first, second] = [shots.starts()[0], shots.starts()[1]];
        assert_eq!(first, 0.0);
        assert!(second > first);
        assert_eq!(shots.span(0), None, "there is no shot 0");
        assert_eq!(shots.span(1), Some((first, second)));
        assert_eq!(shots.span(2), Some((second, shots.end())));
        assert_eq!(shots.span(3), None);
        // The end is the last event when it is later than the recorded end time.
        let last = recording.events.last().unwrap().time;
        assert_eq!(shots.end(), recording.end_time.max(last));
    }

    #[test]
    fn strike_instants_belong_to_the_shot_they_start() {
        let shots = Shots::from_starts(vec![1.0, 3.0], 5.0);
        assert_eq!(shots.at(0.5), 0);
        assert_eq!(shots.at(1.0), 1);
        assert_eq!(shots.at(2.999), 1);
        assert_eq!(shots.at(3.0), 2);
        assert_eq!(shots.at(9.0), 2);
        assert_eq!(shots.next_start(1.0), Some(3.0));
        assert_eq!(shots.next_start(3.0), None);
        assert_eq!(shots.previous_start(3.0), Some(1.0));
        assert_eq!(shots.previous_start(1.0), None);
    }

    #[test]
    fn every_strike_input_is_a_strike_event_at_the_same_time() {
        // The spans come from the inputs; the events must agree (the command line used them).
        let recording = two_shots();
        let events: Vec<f64> = recording
            .events
            .iter()
            .filter(|e| matches!(e.kind, billiards_physics::EventKind::Strike { .. }))
            .map(|e| e.time)
            .collect();
        assert_eq!(Shots::of(&recording).starts(), events.as_slice());
    }
}
