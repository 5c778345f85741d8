//! Why a shot was a foul and why a game ended, each with a sentence a player can read; and
//! the fouls every pool game shares (`common_fouls`).

use crate::shot::ShotSummary;
use billiards_physics::Pocket;
use serde::{Deserialize, Serialize};
use std::fmt;

/// An 8-ball group (WPA 3.1): the solids 1–7 or the stripes 9–15.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Group {
    /// Balls 1 to 7.
    Solids,
    /// Balls 9 to 15.
    Stripes,
}

impl Group {
    /// The group of ball `n` (`None` for the cue ball and the 8).
    pub fn of(n: u8) -> Option<Group> {
        match n {
            1..=7 => Some(Group::Solids),
            9..=15 => Some(Group::Stripes),
            _ => None,
        }
    }

    /// Does the group hold ball `n`?
    pub fn contains(self, n: u8) -> bool {
        Group::of(n) == Some(self)
    }

    /// The other group.
    pub fn other(self) -> Group {
        match self {
            Group::Solids => Group::Stripes,
            Group::Stripes => Group::Solids,
        }
    }

    /// "solids" or "stripes".
    pub fn name(self) -> &'static str {
        match self {
            Group::Solids => "solids",
            Group::Stripes => "stripes",
        }
    }
}

/// What the cue ball had to hit first on a shot, for the wrong-ball-first foul.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BallOn {
    /// 9-ball and 10-ball: the lowest-numbered ball on the table (WPA 2.5, 9.5, 6.2).
    Lowest(u8),
    /// 8-ball, open table: any ball but the 8 (WPA 3.5).
    AnyButEight,
    /// 8-ball: a ball of the shooter's group (WPA 3.6, 6.2).
    Group(Group),
    /// 8-ball: the shooter's group is cleared, the 8 is on (WPA 3.6).
    Eight,
}

/// One foul of a shot. A shot can commit several; a verdict lists them all.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Foul {
    /// WPA 6.1: the cue ball was pocketed.
    Scratch,
    /// WPA 6.2: the cue ball touched no object ball.
    NoBallHit,
    /// WPA 6.2: the first ball the cue ball touched was not a legal one.
    WrongBallFirst {
        /// The ball hit first.
        hit: u8,
        /// What was on.
        on: BallOn,
    },
    /// WPA 6.3: no ball was pocketed and no ball touched a rail after the first contact.
    NoRail,
    /// WPA 6.5 "Ball Driven off the Table" (an object ball) or 6.1 "Cue Ball Scratch or off
    /// the Table" (the cue ball, number 0): whether the ball is spotted is each game's rule.
    OffTable {
        /// The ball driven off the table.
        ball: u8,
    },
    /// WPA 2.3 / 3.3 / 9.3: on the break no ball was pocketed and fewer than four object balls
    /// were driven to a rail.
    IllegalBreak {
        /// Object balls that touched a rail.
        to_rail: usize,
    },
}

impl fmt::Display for Foul {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Foul::Scratch => write!(f, "the cue ball was pocketed"),
            Foul::NoBallHit => write!(f, "the cue ball hit no ball"),
            Foul::OffTable { ball: 0 } => write!(f, "the cue ball was driven off the table"),
            Foul::OffTable { ball } => write!(f, "the {ball} was driven off the table"),
            Foul::WrongBallFirst { hit, on } => match on {
                BallOn::Lowest(low) => {
                    write!(f, "the {hit} was hit first, the {low} was the lowest ball")
                }
                BallOn::AnyButEight => write!(f, "the 8 was hit first on an open table"),
                BallOn::Group(g) => write!(f, "the {hit} was hit first, {} were on", g.name()),
                BallOn::Eight => write!(f, "the {hit} was hit first, the 8 was on"),
            },
            Foul::NoRail => write!(
                f,
                "no ball was pocketed and no ball touched a rail after the contact"
            ),
            Foul::IllegalBreak { to_rail } => write!(
                f,
                "illegal break: no ball pocketed and {to_rail} ball{} to a rail, 4 needed",
                if to_rail == 1 { "" } else { "s" }
            ),
        }
    }
}

/// Why a game ended (from the winner's side).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum WinReason {
    /// WPA 2.5: the winner pocketed the 9 on a legal shot (a combination or the break too).
    NinePocketed,
    /// WPA 9.5: the winner pocketed the called 10 in the called pocket on a legal shot.
    TenPocketed,
    /// WPA 2.8, 9.11, 6.14: the loser fouled three times in a row.
    ThreeFouls,
    /// WPA 3.6: the winner pocketed the 8 in the called pocket after clearing the group.
    EightPocketed,
    /// WPA 3.8: the loser pocketed the 8 before clearing the group.
    EightEarly,
    /// WPA 3.8: the loser fouled on the shot that pocketed the 8.
    EightOnFoul,
    /// WPA 3.8 (loss of rack): the loser drove the 8 off the table (games.md, "Balls off
    /// the table": "the 8 off the table loses the game").
    EightOffTable,
    /// WPA 3.8: the loser pocketed the 8 in a pocket other than the called one.
    EightWrongPocket {
        /// The pocket called (none called).
        called: Option<Pocket>,
        /// Where the 8 went.
        went: Pocket,
    },
}

impl fmt::Display for WinReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            WinReason::NinePocketed => write!(f, "the 9 was pocketed on a legal shot"),
            WinReason::TenPocketed => write!(f, "the called 10 was pocketed in the called pocket"),
            WinReason::ThreeFouls => write!(f, "three fouls in a row"),
            WinReason::EightPocketed => write!(f, "the 8 was pocketed in the called pocket"),
            WinReason::EightEarly => write!(f, "the 8 was pocketed before the group was cleared"),
            WinReason::EightOnFoul => write!(f, "the 8 was pocketed on a foul"),
            WinReason::EightOffTable => write!(f, "the 8 was driven off the table"),
            WinReason::EightWrongPocket { called, went } => match called {
                Some(c) => write!(
                    f,
                    "the 8 went into the {}, the {} was called",
                    pocket_name(went),
                    pocket_name(c)
                ),
                None => write!(
                    f,
                    "the 8 went into the {} without a called pocket",
                    pocket_name(went)
                ),
            },
        }
    }
}

/// A pocket's name for players ("foot-left corner").
pub fn pocket_name(p: Pocket) -> &'static str {
    match p {
        Pocket::HeadLeft => "head-left corner",
        Pocket::HeadRight => "head-right corner",
        Pocket::SideLeft => "left side pocket",
        Pocket::SideRight => "right side pocket",
        Pocket::FootLeft => "foot-left corner",
        Pocket::FootRight => "foot-right corner",
    }
}

/// The common fouls of a shot (WPA 6.1, 6.5, 6.2, 6.3), the scratch and the balls driven
/// off the table first (they are fouls on a push out too); `on` is what the cue
/// ball had to hit first and `allowed` the balls that satisfy it. `rails` is false for a push
/// out, which needs no contact and no rail (WPA 2.4).
pub(crate) fn common_fouls(
    shot: &ShotSummary,
    on: BallOn,
    allowed: &[u8],
    contact_and_rail: bool,
) -> Vec<Foul> {
    let mut fouls = Vec::new();
    if shot.scratch() {
        fouls.push(Foul::Scratch);
    }
    // WPA 6.1 (the cue ball) and 6.5 (an object ball): driven off the table.
    fouls.extend(shot.off_table.iter().map(|&ball| Foul::OffTable { ball }));
    if !contact_and_rail {
        return fouls;
    }
    match shot.first_contact {
        None => fouls.push(Foul::NoBallHit),
        Some(hit) => {
            if !allowed.contains(&hit) {
                fouls.push(Foul::WrongBallFirst { hit, on });
            }
            if shot.pocketed_object_balls().next().is_none() && !shot.rail_after_contact() {
                fouls.push(Foul::NoRail);
            }
        }
    }
    fouls
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fouls_read_as_sentences_naming_the_balls() {
        let wrong = Foul::WrongBallFirst {
            hit: 3,
            on: BallOn::Lowest(2),
        };
        assert_eq!(
            wrong.to_string(),
            "the 3 was hit first, the 2 was the lowest ball"
        );
        let group = Foul::WrongBallFirst {
            hit: 11,
            on: BallOn::Group(Group::Solids),
        };
        assert_eq!(group.to_string(), "the 11 was hit first, solids were on");
        assert_eq!(
            Foul::IllegalBreak { to_rail: 1 }.to_string(),
            "illegal break: no ball pocketed and 1 ball to a rail, 4 needed"
        );
        let lost = WinReason::EightWrongPocket {
            called: Some(Pocket::HeadLeft),
            went: Pocket::FootRight,
        };
        assert_eq!(
            lost.to_string(),
            "the 8 went into the foot-right corner, the head-left corner was called"
        );
    }

    #[test]
    fn groups_hold_their_numbers_and_not_the_8() {
        assert_eq!(Group::of(1), Some(Group::Solids));
        assert_eq!(Group::of(7), Some(Group::Solids));
        assert_eq!(Group::of(8), None);
        assert_eq!(Group::of(0), None);
        assert_eq!(Group::of(15), Some(Group::Stripes));
        assert!(Group::Stripes.contains(9) && !Group::Stripes.contains(8));
        assert_eq!(Group::Solids.other(), Group::Stripes);
    }
}
