//! Skill levels: how much execution noise the player's shots carry and how much search it
//! spends choosing them.

use crate::noise::Noise;
use billiards_physics::TipOffset;
use std::fmt;
use std::str::FromStr;

/// A skill level of the computer player.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Level {
    /// Three times the reference noise; pots only, few samples.
    Easy,
    /// Twice the reference noise; pots, banks and combinations, a short refinement.
    Medium,
    /// The reference noise (FastFiz magnitude 1); the whole one-ply search over a wider set
    /// of strokes (seven speeds, ten tips), then the best few shots valued two plies deep by
    /// a small search of the next shot ([`TwoPly`]); jump shots when every legal ball is
    /// hidden ([`Jumps`]).
    Hard,
    /// The reference noise; hard's search with a larger second ply (up to 5 s a decision).
    Expert,
    /// No execution noise (for analysis); hard's search (both plies), planned under half the
    /// reference noise so that it still prefers shots with room for error.
    Perfect,
}

/// How much search a level spends.
#[derive(Clone, Debug, PartialEq)]
pub struct Budget {
    /// Noisy samples of every candidate in the first round.
    pub samples: usize,
    /// Rounds of refinement, in order: the best `k` candidates so far get `m` more samples
    /// each (successive halving: many candidates cheaply, the few that matter well).
    pub rounds: &'static [(usize, usize)],
    /// Geometric aims kept (best analytic success probability first) before the variants.
    pub aims: usize,
    /// Cue speeds, as multiples of the speed an aim needs to reach its pocket.
    pub speeds: &'static [f64],
    /// Tip offsets tried on straight and cut shots (stun, follow, draw, english).
    pub tips: &'static [TipOffset],
    /// One-rail banks of the object ball, kicks of the cue ball and combinations.
    pub banks_kicks_combos: bool,
    /// Ball in hand: places of the cue ball searched in full.
    pub placements: usize,
    /// Aims corrected for throw by a noiseless secant search before sampling.
    pub correct_aim: bool,
    /// Safety candidates per legal ball.
    pub safeties: usize,
    /// The second ply: `None` values positions analytically (one ply).
    pub second: Option<TwoPly>,
    /// The break's search (the opening shot of a rack).
    pub breaks: Breaks,
    /// Jump shots when every legal ball is hidden ([`crate::jump`]); `None`: the cue stays
    /// level, as before issue 52 (the switch the measurement turns off).
    pub jumps: Option<Jumps>,
}

/// The jump shots a search adds when no legal ball can be reached in a straight line
/// ([`crate::jump`]): pots and full hits over the blocking balls, centre-ball strikes at
/// each elevation, at multiples of the least speed that clears the blockers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jumps {
    /// Jump pots kept (best analytic chance first, those a jump can reach).
    pub aims: usize,
    /// Cue elevations, degrees.
    pub elevations: &'static [f64],
    /// Cue speeds, as multiples of the least speed that clears every blocker at that
    /// elevation.
    pub speeds: &'static [f64],
    /// Legal balls (nearest first) given jump safeties: a full hit over the blockers.
    pub hits: usize,
}

/// Hard's, expert's and perfect's jumps: the three best pots and the two nearest legal
/// balls, at 30, 45 and 60 degrees, 5, 15 and 30 % above the least clearing speed: at most
/// 27 pots and 18 safeties, and only in a hidden position.
const JUMPS: Jumps = Jumps {
    aims: 3,
    elevations: &[30.0, 45.0, 60.0],
    speeds: &[1.05, 1.15, 1.3],
    hits: 2,
};

/// The break's search: candidates full on the apex ball from the head string's places, at
/// these speeds and tip heights; a break runs about ten times the events of a shot and its
/// outcome scatters widely, so it is sampled on its own budget.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Breaks {
    /// Cue ball places as fractions of the way from the head spot to a long cushion (both
    /// sides), those legal.
    pub places: &'static [f64],
    /// Cue ball speeds, m/s.
    pub speeds: &'static [f64],
    /// Tip heights (0 stun, negative draw), in ball radii.
    pub heights: &'static [f64],
    /// Noisy samples of every break candidate.
    pub samples: usize,
    /// Refinement rounds: the best `k` get `m` more samples each.
    pub rounds: &'static [(usize, usize)],
}

/// The break hard, expert and perfect search: the cue ball at the head spot, halfway and
/// three places near either long cushion (where the wing ball reaches the corner pocket),
/// 6.5 to 10 m/s, stun or a little draw; 12 samples each, the best eight 48 more and the best
/// three 192 more, because a break's outcome scatters widely. On 400 racks of the 9-ft table
/// (`examples/break_rate.rs`) hard's breaks foul 3 % of the time where the narrow search
/// fouls 8.5 %, leave the table dry 9.5 % instead of 13.8 %, and hard breaks and runs 36 %
/// instead of 25 %; it nearly always breaks at 6.5 to 7.5 m/s from 0.85 of the way out.
const BREAK_WIDE: Breaks = Breaks {
    places: &[0.0, 0.5, 0.75, 0.85, 0.95],
    speeds: &[6.5, 7.5, 8.5, 10.0],
    heights: &[0.0, -0.15],
    samples: 12,
    rounds: &[(8, 48), (3, 192)],
};

/// The break one ply (and medium) searches: five places, three speeds, stun and a little
/// draw, 8 samples each and the best three 32 more.
const BREAK_NARROW: Breaks = Breaks {
    places: &[0.0, 0.25, 0.75],
    speeds: &[8.0, 10.0, 12.0],
    heights: &[0.0, -0.2],
    samples: 8,
    rounds: &[(3, 32)],
};

/// The second ply (crate::twoply): after the rounds of [`Budget`], the `finalists` best
/// shots each have `outcomes` of their noisy runs (their first draws) valued by a search of
/// the shot that follows, from the side of whoever plays it, with the budget `reply`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoPly {
    /// Shots valued two plies deep (the best by their one-ply value).
    pub finalists: usize,
    /// Noisy outcomes of each searched for the next shot.
    pub outcomes: usize,
    /// The budget of each search of the next shot (its own `second` is ignored).
    pub reply: &'static Budget,
}

const STUN: TipOffset = TipOffset {
    side: 0.0,
    height: 0.0,
};
const FOLLOW: TipOffset = TipOffset {
    side: 0.0,
    height: 0.3,
};
const DRAW: TipOffset = TipOffset {
    side: 0.0,
    height: -0.3,
};
const DEEP_DRAW: TipOffset = TipOffset {
    side: 0.0,
    height: -0.45,
};
const LEFT: TipOffset = TipOffset {
    side: -0.25,
    height: 0.0,
};
const RIGHT: TipOffset = TipOffset {
    side: 0.25,
    height: 0.0,
};
const FOLLOW_LEFT: TipOffset = TipOffset {
    side: -0.2,
    height: 0.25,
};
const FOLLOW_RIGHT: TipOffset = TipOffset {
    side: 0.2,
    height: 0.25,
};
const DRAW_LEFT: TipOffset = TipOffset {
    side: -0.2,
    height: -0.3,
};
const DRAW_RIGHT: TipOffset = TipOffset {
    side: 0.2,
    height: -0.3,
};

/// The whole one-ply search: every candidate sampled 12 times, the best 48 32 more, the best
/// 12 of those 128 more.
const ONE_PLY: Budget = Budget {
    samples: 12,
    rounds: &[(48, 32), (12, 128)],
    aims: 14,
    speeds: &[0.8, 1.0, 1.5, 2.4],
    tips: &[STUN, FOLLOW, DRAW, DEEP_DRAW, LEFT, RIGHT],
    banks_kicks_combos: true,
    placements: 6,
    correct_aim: true,
    safeties: 9,
    second: None,
    breaks: BREAK_NARROW,
    jumps: None,
};

/// The two-ply levels' first ply: the one-ply search over a wider set of strokes for
/// position, seven speeds (0.8 to 3 times the speed that reaches the pocket) and ten tips
/// (stun, follow, draw, deep draw, left and right english, and follow and draw with either
/// english), 70 strokes an aim where one ply tries 24. Against the one-ply baseline this
/// took hard from 102 and 120 wins of 200 (seeds 2001, 2002; 55.5 %) to 138 and 131
/// (67.3 %), 2.75 and 2.91 balls an inning against 1.99 and 2.22 (crates/ai/README.md).
const TWO_PLY_FIRST: Budget = Budget {
    speeds: &[0.8, 1.0, 1.25, 1.5, 1.9, 2.4, 3.0],
    tips: &[
        STUN,
        FOLLOW,
        DRAW,
        DEEP_DRAW,
        LEFT,
        RIGHT,
        FOLLOW_LEFT,
        FOLLOW_RIGHT,
        DRAW_LEFT,
        DRAW_RIGHT,
    ],
    ..ONE_PLY
};

/// Hard's search of the next shot: the straight and cut pots of the four best aims, three
/// speeds and three tips, 4 samples each, the best four 32 more (the value read from the
/// search is its best mean: few finalists with many samples keep its noise and its upward
/// bias small); aims corrected for throw (without it a cut looked worse to leave than it
/// is: 104 and 123 wins of 200 against 102 and 120, fouls 0.034 and 0.031 a shot against
/// 0.044 and 0.033).
const HARD_REPLY: Budget = Budget {
    samples: 4,
    rounds: &[(4, 32)],
    aims: 4,
    speeds: &[1.0, 1.5, 2.4],
    tips: &[STUN, FOLLOW, DRAW],
    banks_kicks_combos: false,
    placements: 2,
    correct_aim: true,
    safeties: 3,
    second: None,
    breaks: BREAK_NARROW,
    jumps: None,
};

/// Hard's second ply: the best 4 shots, 16 outcomes each (against the one-ply baseline, 4
/// outcomes won 49 % of 80 dev games, 16 won 57.5 % of 200; 8 shots or 32 outcomes did no
/// better: crates/ai/README.md).
const HARD_SECOND: TwoPly = TwoPly {
    finalists: 4,
    outcomes: 16,
    reply: &HARD_REPLY,
};

/// Expert's search of the next shot: banks, kicks and combinations too (the opponent's
/// reply to a safety is often one), five aims in three speeds and five tips, 4 samples
/// each, the best six 16 more, the best three of those 48 more.
const EXPERT_REPLY: Budget = Budget {
    samples: 4,
    rounds: &[(6, 16), (3, 48)],
    aims: 5,
    speeds: &[1.0, 1.5, 2.4],
    tips: &[STUN, FOLLOW, DRAW, LEFT, RIGHT],
    banks_kicks_combos: true,
    placements: 3,
    correct_aim: true,
    safeties: 5,
    second: None,
    breaks: BREAK_NARROW,
    jumps: None,
};

/// Expert's second ply: the best 6 shots, 16 outcomes each.
const EXPERT_SECOND: TwoPly = TwoPly {
    finalists: 6,
    outcomes: 16,
    reply: &EXPERT_REPLY,
};

impl Level {
    /// Every level, weakest first (perfect, without noise in its hand, last).
    pub const ALL: [Level; 5] = [
        Level::Easy,
        Level::Medium,
        Level::Hard,
        Level::Expert,
        Level::Perfect,
    ];

    /// The noise on the shots this level plays.
    pub fn execution_noise(self) -> Noise {
        Noise {
            magnitude: match self {
                Level::Easy => 3.0,
                Level::Medium => 2.0,
                Level::Hard | Level::Expert => 1.0,
                Level::Perfect => 0.0,
            },
        }
    }

    /// The noise its search assumes (its own, except for [`Level::Perfect`]).
    pub fn planning_noise(self) -> Noise {
        match self {
            Level::Perfect => Noise { magnitude: 0.5 },
            _ => self.execution_noise(),
        }
    }

    /// The search budget.
    pub fn budget(self) -> Budget {
        match self {
            Level::Easy => Budget {
                samples: 8,
                rounds: &[],
                aims: 4,
                speeds: &[1.3],
                tips: &[STUN],
                banks_kicks_combos: false,
                placements: 3,
                correct_aim: false,
                safeties: 3,
                second: None,
                breaks: Breaks {
                    speeds: &[10.0],
                    ..BREAK_NARROW
                },
                jumps: None,
            },
            Level::Medium => Budget {
                samples: 12,
                rounds: &[(3, 36)],
                aims: 6,
                speeds: &[1.0, 1.8],
                tips: &[STUN, FOLLOW, DRAW],
                banks_kicks_combos: true,
                placements: 4,
                correct_aim: true,
                safeties: 5,
                second: None,
                breaks: BREAK_NARROW,
                jumps: None,
            },
            Level::Hard | Level::Perfect => Budget {
                second: Some(HARD_SECOND),
                breaks: BREAK_WIDE,
                jumps: Some(JUMPS),
                ..TWO_PLY_FIRST
            },
            Level::Expert => Budget {
                second: Some(EXPERT_SECOND),
                breaks: BREAK_WIDE,
                jumps: Some(JUMPS),
                ..TWO_PLY_FIRST
            },
        }
    }

    /// The one-ply search hard played before the second ply (the baseline
    /// [`crate::Player::OnePly`] plays it with hard's noise).
    pub fn one_ply() -> Budget {
        ONE_PLY
    }

    /// The level's name, as the command line spells it.
    pub fn name(self) -> &'static str {
        match self {
            Level::Easy => "easy",
            Level::Medium => "medium",
            Level::Hard => "hard",
            Level::Expert => "expert",
            Level::Perfect => "perfect",
        }
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A name that is not a level.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown level {0:?}: expected easy, medium, hard, expert or perfect")]
pub struct UnknownLevel(pub String);

impl FromStr for Level {
    type Err = UnknownLevel;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Level::ALL
            .into_iter()
            .find(|l| l.name() == s)
            .ok_or_else(|| UnknownLevel(s.to_string()))
    }
}
