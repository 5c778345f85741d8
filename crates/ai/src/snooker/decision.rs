//! What the computer decides at snooker: the one plan and decision of every game
//! ([`crate::plan`]) with snooker's choice and its per-game part, the nomination. The search
//! (`search.rs`) returns it and `mod.rs` hands it on; it lives here, below both, so that the
//! search need not import its caller (issue 50).

use crate::plan::{Decision, Plan};
use billiards_rules::snooker::Choice;

/// Snooker's part of a plan: the ball nominated with the stroke.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Nominated {
    /// The colour nominated after a red (2.12) or the free ball (3.12): pass it as
    /// `Stroke::nominated`.
    pub nominated: Option<u8>,
}

/// What the computer does next at snooker: a choice after a foul
/// ([`Frame::choose`](billiards_rules::snooker::Frame::choose)) or a stroke.
pub type SnookerDecision = Decision<Choice, Nominated>;

/// A stroke decided on at snooker (`plan.nominated` the nomination).
pub type SnookerPlan = Plan<Nominated>;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::candidates::ShotKind;
    use billiards_physics::{Shot, Vec2};

    #[test]
    fn a_snooker_plan_reads_and_writes_its_nomination_as_its_own_field() {
        // The nomination (2.12) is the plan's own "nominated" key in JSON, as the snooker
        // plan had before it became the one plan's part, and `plan.nominated` reads through.
        let p: SnookerPlan = Plan {
            shot: Shot::new(1.0, 3.0),
            place: Some(Vec2::new(-1.2, 0.1)),
            part: Nominated { nominated: Some(7) },
            kind: ShotKind::Break,
            success: 0.5,
            foul: 0.0,
            value: 4.5,
            samples: 6,
            simulations: 60,
            events: 1200,
        };
        assert_eq!(p.nominated, Some(7));
        let json = serde_json::to_value(&p).unwrap();
        assert_eq!(json["nominated"], 7, "{json}");
        assert!(json.get("call").is_none(), "{json}");
        let back: SnookerPlan = serde_json::from_value(json).unwrap();
        assert_eq!(back, p);
    }
}
