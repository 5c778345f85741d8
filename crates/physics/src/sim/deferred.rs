//! Re-prediction left for later: with the history off, [`Simulation::step_event`] hands out
//! an event before its balls' next events are predicted, and the simulation predicts them
//! when it goes on. A caller that stops reading events there (the computer's lean search
//! stops each sample once its verdict is known) saves that prediction; one that goes on gets
//! every event exactly as before. With the history on (the game, replays, the checks) the
//! predictions are made at once, so [`Simulation::next_event_time`] between steps (the
//! game's aim preview) stays as cheap as it was.

use super::Simulation;
use super::scene::Scene;
use crate::ball::BallId;

impl Simulation {
    /// Re-predicts the balls of the last event [`Simulation::step_event`] handed out, if it
    /// left them (`stale`). Every entry point that reads or changes the predictions calls it
    /// first.
    pub(super) fn flush(&mut self) {
        match self.stale.take() {
            Some((a, Some(b))) => self.repredict([a, b]),
            Some((a, None)) => self.repredict([a]),
            None => {}
        }
    }

    /// Re-predicts ball `a` (and `b`) after the event being processed changed them, or leaves
    /// them `stale` while [`Simulation::step_event`] processes it.
    #[inline]
    pub(super) fn repredict_event(&mut self, a: BallId, b: Option<BallId>) {
        debug_assert!(self.stale.is_none(), "one event at a time");
        match (self.defer, b) {
            (true, _) => self.stale = Some((a, b)),
            (false, Some(b)) => self.repredict([a, b]),
            (false, None) => self.repredict([a]),
        }
    }

    /// [`Simulation::next_event_time`] with balls left `stale`: predicted on a copy of the
    /// predictions, as the simulation will predict them (it cannot change them from `&self`).
    pub(super) fn next_event_time_stale(&self) -> Option<f64> {
        let mut predictions = self.predictions.clone();
        let scene = Scene {
            segments: &self.segments,
            params: &self.params,
            bodies: &self.bodies,
        };
        match self.stale {
            Some((a, Some(b))) => predictions.repredict(&scene, [a, b], self.time),
            Some((a, None)) => predictions.repredict(&scene, [a], self.time),
            None => {}
        }
        predictions.next().map(|p| p.time)
    }
}

#[cfg(test)]
mod tests {
    use crate::{Params, Rack, Shot, Simulation, Table};

    /// Stepping event by event, with the history off (predictions deferred) or on, reading
    /// the next event's time between steps, gives the same events to the bit as running to
    /// rest, and the time read is the next event's; a copy taken mid-way runs on the same.
    #[test]
    fn deferred_predictions_change_no_event() {
        let table = Table::wpa_8ft().with_jaws(0.015);
        let params = Params::default();
        let balls = Rack::FifteenBall.layout(&table, &params.ball);
        let mut whole = Simulation::new(table, params, &balls).unwrap();
        whole.strike(0, Shot::new(0.02, 8.0)).unwrap();
        let start = whole.clone();
        whole.run_to_rest().unwrap();
        // The whole run's history starts with the strike.
        let want = &whole.history().events()[1..];
        for history in [false, true] {
            let mut stepped = start.clone();
            stepped.set_record_history(history);
            let mut events = Vec::new();
            while let Some(t) = stepped.next_event_time() {
                let e = stepped.step_event().unwrap();
                assert_eq!(e.time, t);
                events.push(e);
                assert_eq!(stepped.stale.is_some(), !history);
                if events.len() == 20 {
                    let mut copy = stepped.clone();
                    copy.set_record_history(true);
                    copy.run_to_rest().unwrap();
                    // Its history starts now (off before) or holds the events so far (on).
                    let got = copy.history().events();
                    assert_eq!(got[got.len() + 20 - want.len()..], want[20..]);
                }
            }
            assert!(events.len() > 50, "{}", events.len());
            assert_eq!(events, want);
        }
    }
}
