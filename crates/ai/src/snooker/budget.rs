//! How much a level searches at snooker: the first ply's candidates and rounds, the second
//! ply and the search behind a choice.

use crate::level::Level;
use billiards_physics::TipOffset;

/// How much search a level spends at snooker: the pool budget's shape ([`Level::budget`]),
/// trimmed for a 22-ball table (more balls on, longer runs).
#[derive(Clone, Debug, PartialEq)]
pub struct SnookerBudget {
    /// Noisy samples of every candidate in the first round.
    pub samples: usize,
    /// Rounds of refinement: the best `k` get `m` more samples each.
    pub rounds: Vec<(usize, usize)>,
    /// Pot aims kept (best analytic value first) before speeds and tips.
    pub aims: usize,
    /// Cue speeds, as multiples of the speed an aim needs.
    pub speeds: Vec<f64>,
    /// Tip offsets of straight and cut pots.
    pub tips: Vec<TipOffset>,
    /// Banks, kicks and red-on-red plants.
    pub banks: bool,
    /// Places in the D searched with the cue ball in hand.
    pub placements: usize,
    /// Pot aims corrected for throw before sampling.
    pub correct_aim: bool,
    /// Balls on that safeties are played at (the nearest in view).
    pub safety_balls: usize,
    /// Contacts per safety ball, from full to thin on either side.
    pub safety_hits: usize,
    /// The budget of the search behind each choice after a foul (`None`: this one).
    pub choice: Option<Box<SnookerBudget>>,
    /// The second ply (`None`: positions valued analytically, one ply).
    pub second: Option<SnookerTwoPly>,
}

/// The second ply at snooker, as [`crate::twoply`] at pool: the `finalists` best strokes
/// each struck `outcomes` more times (one stream common to them), run to rest and judged;
/// from each table the next stroke is searched with `reply`, for whoever plays it.
#[derive(Clone, Debug, PartialEq)]
pub struct SnookerTwoPly {
    /// Strokes valued two plies deep (the best by their one-ply value).
    pub finalists: usize,
    /// Noisy outcomes of each, searched for the next stroke.
    pub outcomes: usize,
    /// The budget of each search of the next stroke.
    pub reply: Box<SnookerBudget>,
}

impl SnookerBudget {
    /// The budget of `level`.
    pub fn of(level: Level) -> Self {
        let b = level.budget();
        let reply = SnookerBudget {
            samples: 4,
            rounds: vec![(4, 12)],
            aims: 4,
            speeds: vec![1.0, 1.6],
            tips: b.tips.iter().copied().take(3).collect(),
            banks: false,
            placements: 2,
            correct_aim: false,
            safety_balls: 2,
            safety_hits: 3,
            choice: None,
            second: None,
        };
        let second = |finalists, outcomes| SnookerTwoPly {
            finalists,
            outcomes,
            reply: Box::new(reply.clone()),
        };
        match level {
            Level::Easy | Level::Medium => SnookerBudget {
                samples: b.samples.min(8),
                rounds: b.rounds.iter().map(|&(k, m)| (k, m.min(24))).collect(),
                aims: b.aims,
                speeds: b.speeds.to_vec(),
                tips: b.tips.to_vec(),
                banks: b.banks_kicks_combos,
                placements: b.placements.min(3),
                correct_aim: b.correct_aim,
                safety_balls: 2,
                safety_hits: b.safeties.min(5),
                choice: Some(Box::new(reply.clone())),
                second: None,
            },
            Level::Hard | Level::Expert | Level::Perfect => SnookerBudget {
                samples: 6,
                rounds: vec![(20, 18), (6, 48)],
                aims: 8,
                speeds: vec![0.8, 1.1, 1.6, 2.4],
                tips: b.tips.iter().copied().take(4).collect(),
                banks: true,
                placements: 3,
                correct_aim: true,
                safety_balls: if level == Level::Expert { 5 } else { 4 },
                safety_hits: 7,
                choice: Some(Box::new(reply.clone())),
                second: Some(if level == Level::Expert {
                    second(4, 16)
                } else {
                    second(4, 8)
                }),
            },
        }
    }
}
