//! A shot's flight for its summary: every take-off, bounce, landing and flight off the table
//! (or into a pocket) of the balls in the air, read from the shot's events (the physics'
//! `Motion::Airborne`; crates/physics/README.md, "balls in the air").

use billiards_physics::*;
use serde::Serialize;

/// What a ball in the air did.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FlightKind {
    /// It left the cloth (the strike's slate rebound, or struck from above by another ball).
    TakeOff,
    /// It met the slate and rose again.
    Bounce,
    /// It met the slate and stayed on the cloth.
    Landing,
    /// It flew over a cushion: out of play.
    OffTable,
    /// It dropped into a pocket from the air.
    Pocketed,
}

impl FlightKind {
    fn label(self) -> &'static str {
        match self {
            Self::TakeOff => "take-off",
            Self::Bounce => "bounce",
            Self::Landing => "landing",
            Self::OffTable => "off the table",
            Self::Pocketed => "pocketed from the air",
        }
    }
}

/// One flight event of a shot.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FlightEvent {
    /// Seconds after the shot's strike.
    pub time: f64,
    /// The ball's number.
    pub ball: u8,
    /// What it did.
    pub kind: FlightKind,
    /// Where its centre was, metres from the table's centre.
    pub position: Vec2,
    /// Its upward speed just after, m/s (0 once it is down).
    pub vertical: f64,
}

impl std::fmt::Display for FlightEvent {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let p = self.position;
        write!(
            f,
            "ball {} {} at {:.3} s, ({:.3}, {:.3}) m",
            self.ball,
            self.kind.label(),
            self.time,
            p.x,
            p.y
        )?;
        if self.vertical > 0.0 {
            write!(f, ", rising at {:.3} m/s", self.vertical)?;
        }
        Ok(())
    }
}

/// The flight events among `events` (a shot's, from its strike at `start`), for balls
/// numbered `numbers`, given which balls were in the air before them (`in_air`, by index).
pub fn flight_events(
    events: &[Event],
    numbers: &[u8],
    start: f64,
    mut in_air: Vec<bool>,
) -> Vec<FlightEvent> {
    let mut out = Vec::new();
    for e in events {
        for (slot, id) in e.kind.balls().enumerate() {
            let after = e.after[slot];
            let (was, now) = (in_air[id], after.motion == Motion::Airborne);
            in_air[id] = now;
            let bounce = matches!(
                e.kind,
                EventKind::Transition {
                    from: Motion::Airborne,
                    to: Motion::Airborne,
                    ..
                }
            );
            let kind = match (was, now, after.motion) {
                (false, true, _) => FlightKind::TakeOff,
                (true, true, _) if bounce => FlightKind::Bounce,
                (true, false, Motion::OffTable) => FlightKind::OffTable,
                (true, false, Motion::Pocketed(_)) => FlightKind::Pocketed,
                (true, false, _) => FlightKind::Landing,
                _ => continue,
            };
            out.push(FlightEvent {
                time: e.time - start,
                ball: numbers[id],
                kind,
                position: after.position,
                vertical: after.vertical,
            });
        }
    }
    out
}

/// Which balls of `sim` are in the air now (before a strike: none after a shot that rested).
pub fn airborne(sim: &Simulation) -> Vec<bool> {
    (0..sim.numbers().len())
        .map(|id| sim.ball(id).motion == Motion::Airborne)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn event(time: f64, kind: EventKind, motion: Motion, vertical: f64) -> Event {
        let s = BallState {
            motion,
            vertical,
            ..BallState::default()
        };
        Event {
            time,
            kind,
            after: [s, BallState::default()],
        }
    }

    /// A jump: take-off at the strike, a bounce, a landing; then a second flight off the
    /// table, and a third into a pocket. Events that keep a ball on the cloth or in the air
    /// are not listed.
    #[test]
    fn take_off_bounce_landing_and_off_the_table_are_told_apart() {
        use Motion::*;
        let t = |from, to| EventKind::Transition { ball: 0, from, to };
        let strike = EventKind::Strike {
            ball: 0,
            shot: Shot::new(0.0, 3.0),
        };
        let pocketed = EventKind::Pocketed {
            ball: 0,
            pocket: Pocket::SideLeft,
        };
        let events = [
            event(1.0, strike, Airborne, 1.0),
            event(1.2, t(Airborne, Airborne), Airborne, 0.5),
            event(1.3, t(Airborne, Sliding), Sliding, 0.0),
            event(1.5, t(Sliding, Rolling), Rolling, 0.0),
            event(2.0, strike, Airborne, 2.0),
            event(2.1, t(Airborne, OffTable), OffTable, 0.0),
            event(3.0, strike, Airborne, 1.0),
            event(3.1, pocketed, Pocketed(Pocket::SideLeft), 0.0),
        ];
        let got = flight_events(&events, &[7], 1.0, vec![false]);
        let kinds: Vec<FlightKind> = got.iter().map(|f| f.kind).collect();
        let (up, bounce, down) = (FlightKind::TakeOff, FlightKind::Bounce, FlightKind::Landing);
        let (off, dropped) = (FlightKind::OffTable, FlightKind::Pocketed);
        assert_eq!(kinds, [up, bounce, down, up, off, up, dropped]);
        assert_eq!(
            (got[1].time, got[1].ball, got[1].vertical),
            (1.2 - 1.0, 7, 0.5)
        );
        assert!(got[0].to_string().contains("ball 7 take-off at 0.000 s"));
    }
}
