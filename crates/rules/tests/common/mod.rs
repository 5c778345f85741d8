//! Helpers shared by the rule scenario tests.
#![allow(dead_code)]

use billiards_physics::Pocket;
use billiards_rules::*;

/// A hand-made shot: the first ball hit, the balls to a rail after it (also the shot's rail
/// list) and the balls pocketed in order (0 is the cue ball).
pub fn shot(first: Option<u8>, rails: &[u8], pocketed: &[(u8, Pocket)]) -> ShotSummary {
    ShotSummary {
        first_contact: first,
        rails_after_contact: if first.is_some() {
            rails.to_vec()
        } else {
            Vec::new()
        },
        rails: rails.to_vec(),
        cue_rail: rails.contains(&0),
        pocketed: pocketed.to_vec(),
        jaws: Vec::new(),
        off_table: Vec::new(),
    }
}

/// A rack after a legal break by A that pocketed nothing and drove four balls to a rail:
/// B is at the table (in 9-ball, with the push out allowed).
pub fn after_break(game: Game) -> GameState {
    let mut g = GameState::new(game, Seat::A);
    let v = g
        .play(&shot(Some(1), &[2, 3, 4, 5], &[]), Call::None)
        .expect("legal break");
    assert!(v.legal());
    assert_eq!(g.next.shooter, Seat::B);
    g
}
