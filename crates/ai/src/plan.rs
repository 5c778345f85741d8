//! What the computer decides, in every game it searches: take a choice the rules offer, or
//! play a shot ([`Plan`]). One type for pool and snooker (issue 50: no copy per game): a
//! plan's per-game part is what goes with the shot to the rules (pool's [`Called`] call,
//! snooker's nomination), and a decision's choice is the game's own.

use crate::candidates::ShotKind;
use crate::noise::{self, Noise};
use billiards_physics::{Params, Shot, Vec2};
use billiards_rules::{Call, Choice};
use std::ops::Deref;

/// What the player does next; `C` is the game's choice, `P` the per-game part of its plan
/// (pool's by default: [`Choice`] and [`Called`]).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Decision<C = Choice, P = Called> {
    /// Take one of the choices the rules offer (pool's `GameState::choose`, snooker's
    /// `Frame::choose`).
    Choose {
        /// The choice.
        choice: C,
        /// Pool: the estimated success probability of the best shot the choice leads to;
        /// snooker: the search's value of the table it leads to, in points for the chooser.
        estimate: f64,
    },
    /// Play this shot.
    Shoot(Plan<P>),
}

/// A shot decided on; `P` is what goes with it to the rules, by game. Its fields are read
/// through the plan ([`Deref`]): `plan.call` at pool, `plan.nominated` at snooker.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Plan<P = Called> {
    /// The strike meant (angle, speed, tip), before execution noise.
    pub shot: Shot,
    /// Ball in hand: where to put the cue ball first (at snooker, inside the D).
    pub place: Option<Vec2>,
    /// What goes with the shot to the rules, by game (flattened: its fields are the plan's
    /// own in JSON).
    #[serde(flatten)]
    pub part: P,
    /// What the shot tries.
    pub kind: ShotKind,
    /// Estimated probability of a legal pot (or of winning): the hint's number.
    pub success: f64,
    /// Estimated probability of a foul.
    pub foul: f64,
    /// The search's mean value of the shot: pool -1 (loses) to 1 (wins); snooker in
    /// points for the striker.
    pub value: f64,
    /// Noisy samples behind the estimates of this shot.
    pub samples: usize,
    /// Noisy simulations the whole decision ran.
    pub simulations: usize,
    /// Solver events those simulations processed.
    pub events: usize,
}

/// Pool's part of a plan: the call that goes with the shot.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Called {
    /// The call (8-ball ball and pocket, safety; 9-ball push out).
    pub call: Call,
}

impl<P> Deref for Plan<P> {
    type Target = P;

    /// The per-game part, so that its fields read as the plan's (`plan.call`).
    fn deref(&self) -> &P {
        &self.part
    }
}

impl<P> Plan<P> {
    /// The shot as a player of execution noise `noise` strikes it, from the stream of
    /// `seed` (a function of the seed only).
    pub fn executed(&self, noise: Noise, params: &Params, seed: u64) -> Shot {
        noise.apply(self.shot, params, &mut noise::stream(seed, u64::MAX, 0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(call: Call) -> Plan {
        Plan {
            shot: Shot::new(0.5, 2.0),
            place: Some(Vec2::new(0.1, -0.2)),
            part: Called { call },
            kind: ShotKind::Break,
            success: 0.25,
            foul: 0.125,
            value: -0.5,
            samples: 8,
            simulations: 40,
            events: 900,
        }
    }

    #[test]
    fn a_pool_plan_reads_and_writes_its_call_as_its_own_field() {
        // The per-game part is flattened: the JSON has "call" at the plan's top level, as
        // the pool plan had before the part was split off, and `plan.call` reads through.
        let p = plan(Call::Safety);
        assert_eq!(p.call, Call::Safety);
        let json = serde_json::to_value(&p).unwrap();
        assert!(json.get("call").is_some(), "{json}");
        assert!(json.get("part").is_none(), "{json}");
        let back: Plan = serde_json::from_value(json).unwrap();
        assert_eq!(back, p);
    }
}
