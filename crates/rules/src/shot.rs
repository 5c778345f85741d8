//! What one shot did, in the terms the rules use: the facts read from the solver's events
//! between a strike and the moment everything rests.
//!
//! Rule terms (WPA Rules of Play, section 8 "Definitions"):
//!
//! - a ball is "driven to a rail" when it touches a cushion; a **jaw counts as a rail**: the
//!   jaw is the rounded end of the cushion rubber at the pocket mouth (the solver's
//!   [`EventKind::Jaw`] is "the rounded end of a cushion"), so a ball rattled in the jaws has
//!   touched the cushion. Jaw contacts are also listed apart, for a HUD or a stricter reading.
//! - a ball "driven off the table" (WPA 6.5 "Ball Driven off the Table"; for the cue ball
//!   6.1 "Cue Ball Scratch or off the Table") is one the solver's spin model flies over a
//!   cushion's nose: its motion turns to [`Motion::OffTable`] by an
//!   [`EventKind::Transition`]. [`ShotSummary::off_table`] lists them; they are never
//!   pocketed balls (WPA 8.3: a ball is pocketed when it comes to rest in a pocket).
//! - a ball frozen to a cushion that is pushed along it without a cushion event is not
//!   "driven to" it, as the definitions require; the solver reports a contact only when the
//!   ball comes into the cushion, which matches.

use billiards_physics::{BallId, Event, EventKind, Motion, Pocket};
use serde::{Deserialize, Serialize};

/// The number of the cue ball in every rack of the project.
pub const CUE: u8 = 0;

/// The facts of one shot, with balls by the number painted on them.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct ShotSummary {
    /// The first object ball the cue ball touched (`None`: it hit no ball).
    pub first_contact: Option<u8>,
    /// Every ball (the cue ball included) that touched a cushion or a jaw after the cue ball's
    /// first contact with an object ball, each once, in the order of its first such touch
    /// (rule 6.3 "no rail after contact" reads this).
    pub rails_after_contact: Vec<u8>,
    /// Every ball that touched a cushion or a jaw at any time in the shot, each once, in order
    /// (the break's "four numbered balls to a rail" reads this).
    pub rails: Vec<u8>,
    /// The cue ball touched a cushion or a jaw (at any time in the shot).
    pub cue_rail: bool,
    /// Balls pocketed and where, in the order they dropped (the cue ball included).
    pub pocketed: Vec<(u8, Pocket)>,
    /// Jaw contacts, in order (ball, pocket of the jaw); they also count in the rail lists.
    pub jaws: Vec<(u8, Pocket)>,
    /// Balls driven off the table (the cue ball included), each once, in the order they
    /// left it (WPA 6.1, 6.5). Absent from logs written before flight: empty.
    #[serde(default)]
    pub off_table: Vec<u8>,
}

impl ShotSummary {
    /// Back to the summary of no shot ([`Default`]), keeping the lists' buffers.
    pub fn clear(&mut self) {
        // Every field named, so a new one cannot be missed.
        let ShotSummary {
            first_contact,
            rails_after_contact,
            rails,
            cue_rail,
            pocketed,
            jaws,
            off_table,
        } = self;
        *first_contact = None;
        rails_after_contact.clear();
        rails.clear();
        *cue_rail = false;
        pocketed.clear();
        jaws.clear();
        off_table.clear();
    }

    /// The cue ball was pocketed (rule 6.1).
    pub fn scratch(&self) -> bool {
        self.pocketed.iter().any(|&(b, _)| b == CUE)
    }

    /// The cue ball was driven off the table (WPA 6.1 "Cue Ball Scratch or off the Table").
    pub fn cue_off_table(&self) -> bool {
        self.off_table.contains(&CUE)
    }

    /// Object balls driven off the table, in order (WPA 6.5).
    pub fn off_table_object_balls(&self) -> impl Iterator<Item = u8> + '_ {
        self.off_table.iter().copied().filter(|&b| b != CUE)
    }

    /// Was ball `n` driven off the table?
    pub fn is_off_table(&self, n: u8) -> bool {
        self.off_table.contains(&n)
    }

    /// Object balls pocketed, in order.
    pub fn pocketed_object_balls(&self) -> impl Iterator<Item = u8> + '_ {
        self.pocketed.iter().map(|&(b, _)| b).filter(|&b| b != CUE)
    }

    /// Was this object ball pocketed, and where?
    pub fn pocket_of(&self, ball: u8) -> Option<Pocket> {
        self.pocketed
            .iter()
            .find(|&&(b, _)| b == ball)
            .map(|&(_, p)| p)
    }

    /// Number of distinct object balls that touched a rail during the shot.
    pub fn object_balls_to_rail(&self) -> usize {
        self.rails.iter().filter(|&&b| b != CUE).count()
    }

    /// Some ball (cue or object) touched a rail after the first contact.
    pub fn rail_after_contact(&self) -> bool {
        !self.rails_after_contact.is_empty()
    }
}

/// Summarises one shot from its events. `numbers[id]` is the number of the solver's ball
/// `id` (`Simulation::numbers`); the cue ball is number [`CUE`].
///
/// `events` are the shot's events, from its strike to rest (events before the strike, such as
/// the placement of the cue ball, are ignored; a second strike ends the shot).
pub fn summarise(events: &[Event], numbers: &[u8]) -> ShotSummary {
    let mut s = ShotSummary::default();
    for kind in after_strike(events) {
        s.record(&kind, numbers);
    }
    s
}

/// The kinds of a shot's events after its strike, up to the next strike (what came before
/// the strike, such as the cue ball's placement, left out).
pub(crate) fn after_strike(events: &[Event]) -> impl Iterator<Item = EventKind> + '_ {
    let start = events
        .iter()
        .position(|e| matches!(e.kind, EventKind::Strike { .. }))
        .map_or(events.len(), |i| i + 1);
    events[start..]
        .iter()
        .map(|e| e.kind)
        .take_while(|k| !matches!(k, EventKind::Strike { .. }))
}

impl ShotSummary {
    /// Adds one event that followed the shot's strike, as [`summarise`] does: a search that
    /// reads events one at a time ([`billiards_physics::Simulation::step_event`], no history)
    /// builds the same summary and may stop once the verdict it needs is known.
    pub fn record(&mut self, kind: &EventKind, numbers: &[u8]) {
        let number = |id: BallId| numbers.get(id).copied().unwrap_or(u8::MAX);
        let push = |list: &mut Vec<u8>, b: u8| {
            if !list.contains(&b) {
                list.push(b);
            }
        };
        match *kind {
            EventKind::BallBall { a, b } => {
                let (na, nb) = (number(a), number(b));
                if self.first_contact.is_none() {
                    if na == CUE {
                        self.first_contact = Some(nb);
                    } else if nb == CUE {
                        self.first_contact = Some(na);
                    }
                }
            }
            EventKind::Cushion { ball, .. } | EventKind::Jaw { ball, .. } => {
                let n = number(ball);
                push(&mut self.rails, n);
                if self.first_contact.is_some() {
                    push(&mut self.rails_after_contact, n);
                }
                self.cue_rail |= n == CUE;
                if let EventKind::Jaw { pocket, .. } = *kind {
                    self.jaws.push((n, pocket));
                }
            }
            EventKind::Pocketed { ball, pocket } => self.pocketed.push((number(ball), pocket)),
            EventKind::Transition {
                ball,
                to: Motion::OffTable,
                ..
            } => push(&mut self.off_table, number(ball)),
            EventKind::Strike { .. }
            | EventKind::Placed { .. }
            | EventKind::ParamsChanged
            | EventKind::Transition { .. } => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::{BallSetup, Params, Shot, Simulation, Table, Vec2};

    fn run(balls: &[BallSetup], shot: Shot) -> (ShotSummary, Simulation) {
        let table = Table::wpa_8ft().with_jaws(0.015);
        let mut sim = Simulation::new(table, Params::default(), balls).unwrap();
        sim.strike(0, shot).unwrap();
        sim.run_to_rest().unwrap();
        let s = summarise(sim.history().events(), sim.numbers());
        (s, sim)
    }

    #[test]
    fn a_straight_pot_names_the_ball_the_pocket_and_the_first_contact() {
        // Cue ball and the 3 on the line to the foot-left corner pocket.
        let table = Table::wpa_8ft();
        let corner = Vec2::new(table.length / 2.0, table.width / 2.0);
        let dir = corner.normalized().unwrap();
        let three = corner - dir * 0.5;
        let cue = three - dir * 0.5;
        let balls = [BallSetup::at(0, cue), BallSetup::at(3, three)];
        let (s, _) = run(&balls, Shot::new(dir.angle(), 2.0));
        assert_eq!(s.first_contact, Some(3));
        assert_eq!(s.pocketed, vec![(3, Pocket::FootLeft)]);
        assert!(!s.scratch());
        assert_eq!(s.pocket_of(3), Some(Pocket::FootLeft));
    }

    #[test]
    fn a_miss_hits_no_ball_and_counts_the_cue_ball_rails() {
        let balls = [
            BallSetup::at(0, Vec2::new(-0.5, 0.0)),
            BallSetup::at(5, Vec2::new(0.5, 0.4)),
        ];
        // Straight at the foot cushion, away from the 5.
        let (s, _) = run(&balls, Shot::new(0.0, 1.5));
        assert_eq!(s.first_contact, None);
        assert!(s.cue_rail);
        assert_eq!(s.rails, vec![0]);
        assert!(
            s.rails_after_contact.is_empty(),
            "no contact, so no rail after it"
        );
        assert!(s.pocketed.is_empty());
    }

    #[test]
    fn rails_after_contact_exclude_the_cue_balls_rail_before_it() {
        // A kick: the cue ball goes to the head cushion first, straight back to the 4.
        let balls = [
            BallSetup::at(0, Vec2::new(-0.4, 0.0)),
            BallSetup::at(4, Vec2::new(0.4, 0.0)),
        ];
        let (s, _) = run(&balls, Shot::new(std::f64::consts::PI, 3.0));
        assert_eq!(s.first_contact, Some(4));
        assert!(s.cue_rail);
        assert_eq!(s.rails[0], 0, "the cue ball's kick comes first");
        // The 4 is driven on towards the foot cushion after the contact.
        assert!(s.rails_after_contact.contains(&4), "{s:?}");
    }

    #[test]
    fn a_break_of_a_nine_ball_rack_drives_balls_to_rails() {
        let table = Table::wpa_8ft();
        let balls =
            billiards_physics::racks::nine_ball(&table, &billiards_physics::BallSpec::default());
        let (s, sim) = run(&balls, Shot::new(0.0, 9.0));
        assert_eq!(s.first_contact, Some(1));
        assert!(s.object_balls_to_rail() >= 4, "{s:?}");
        // Every pocketed ball is pocketed in the solver too, in the same pocket.
        for &(n, p) in &s.pocketed {
            let id = sim.numbers().iter().position(|&k| k == n).unwrap();
            assert_eq!(sim.ball(id).motion, billiards_physics::Motion::Pocketed(p));
        }
        // Every ball pocketed in the solver is listed.
        let dropped = sim.balls().filter(|b| !b.motion.on_table()).count();
        assert_eq!(dropped, s.pocketed.len());
    }

    #[test]
    fn events_before_the_strike_and_after_a_second_strike_are_ignored() {
        let balls = [
            BallSetup::at(0, Vec2::new(-0.5, 0.0)),
            BallSetup::at(2, Vec2::new(0.0, 0.0)),
        ];
        let table = Table::wpa_8ft();
        let mut sim = Simulation::new(table, Params::default(), &balls).unwrap();
        sim.strike(0, Shot::new(0.0, 2.0)).unwrap();
        sim.run_to_rest().unwrap();
        let first = sim.history().events().len();
        sim.strike(0, Shot::new(std::f64::consts::PI, 0.5))
            .unwrap_or(());
        sim.run_to_rest().unwrap();
        let all = sim.history().events();
        let whole = summarise(all, sim.numbers());
        assert_eq!(whole, summarise(&all[..first], sim.numbers()));
        assert_eq!(whole.first_contact, Some(2));
    }
}
