//! A predicted event and the order in which events are processed: by time, and at equal
//! times by a documented tie order (pooltool's priority of event kinds), so that a run never
//! depends on how the predictions were found.

use crate::ball::BallId;
use crate::grid::Side;
use crate::queue::Tournament;
use crate::table::Cushion;

/// A predicted event, cached per ball until one of its balls changes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pending {
    /// Absolute time, seconds.
    pub time: f64,
    /// What happens, to which balls.
    pub kind: PendingKind,
}

/// What a predicted event is, in tie order (see [`Pending::key`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum PendingKind {
    /// Internal: the ball leaves its grid cell (no physical effect, not recorded).
    Crossing(BallId, Side),
    /// The ball's motion changes by itself (slide to roll, roll to rest).
    Transition(BallId),
    /// The ball's centre crosses pocket opening `k` of the table's openings.
    Opening(BallId, usize),
    /// The ball meets a cushion.
    Cushion(BallId, Cushion),
    /// Contact with jaw `k` of the table's jaws.
    Jaw(BallId, usize),
    /// Two balls touch, the lower index first.
    Pair(BallId, BallId),
}

impl Pending {
    /// Tie order between events at equal times: grid crossings (bookkeeping, so that a
    /// contact at the same instant is seen), state transitions, pocket openings, cushions,
    /// jaws, then ball pairs (after pooltool); within a kind by ball index, then by the
    /// second index (side, opening, cushion, jaw, or the pair's other ball).
    pub fn key(&self) -> (u8, BallId, usize) {
        match self.kind {
            PendingKind::Crossing(b, s) => (0, b, s as usize),
            PendingKind::Transition(b) => (1, b, 0),
            PendingKind::Opening(b, k) => (2, b, k),
            PendingKind::Cushion(b, c) => (3, b, c as usize),
            PendingKind::Jaw(b, k) => (4, b, k),
            PendingKind::Pair(a, b) => (5, a, b),
        }
    }

    /// The order of events as one integer: the time (its bits mapped so that integer order
    /// is `f64::total_cmp` order), then the tie order of [`Pending::key`].
    #[inline]
    pub fn rank(&self) -> u128 {
        let time = time_order(self.time);
        let (kind, a, b) = self.key();
        debug_assert!(
            a < 1 << 30 && b < 1 << 30,
            "ball and part indices fit in 30 bits"
        );
        let tie = (kind as u64) << 60 | (a as u64) << 30 | b as u64;
        (time as u128) << 64 | tie as u128
    }

    /// Is this event processed before `other`?
    #[inline]
    pub fn precedes(&self, other: &Pending) -> bool {
        // Times nearly always differ: compare them first, in the same order as `rank`.
        let (a, b) = (time_order(self.time), time_order(other.time));
        if a != b {
            return a < b;
        }
        self.rank() < other.rank()
    }

    /// The other ball of a pair event, seen from `id`.
    #[inline]
    pub fn partner(&self, id: BallId) -> Option<BallId> {
        match self.kind {
            PendingKind::Pair(a, b) if a == id => Some(b),
            PendingKind::Pair(a, b) if b == id => Some(a),
            _ => None,
        }
    }

    /// Does this event change ball `id`?
    #[inline]
    pub fn involves(&self, id: BallId) -> bool {
        match self.kind {
            PendingKind::Crossing(b, _)
            | PendingKind::Transition(b)
            | PendingKind::Cushion(b, _)
            | PendingKind::Jaw(b, _)
            | PendingKind::Opening(b, _) => b == id,
            PendingKind::Pair(a, b) => a == id || b == id,
        }
    }
}

/// The bits of a time mapped so that integer order is `f64::total_cmp` order.
#[inline]
fn time_order(t: f64) -> u64 {
    let bits = t.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

/// Rank of an optional prediction in the tournament (see [`Pending::rank`]).
#[inline]
pub(crate) fn rank(p: Option<Pending>) -> u128 {
    p.map_or(Tournament::<Pending>::EMPTY, |p| p.rank())
}

/// The one of two optional predictions processed first.
#[inline]
pub(crate) fn earlier(a: Option<Pending>, b: Option<Pending>) -> Option<Pending> {
    match (a, b) {
        (Some(x), Some(y)) => Some(if y.precedes(&x) { y } else { x }),
        (x, None) => x,
        (None, y) => y,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(time: f64, kind: PendingKind) -> Pending {
        Pending { time, kind }
    }

    /// One event of each kind, in the documented tie order, the higher kinds on lower balls
    /// so that a key ordered by ball first would get them wrong.
    fn one_of_each_kind() -> [PendingKind; 6] {
        [
            PendingKind::Crossing(9, Side::YMinus),
            PendingKind::Transition(8),
            PendingKind::Opening(7, 5),
            PendingKind::Cushion(6, Cushion::Right),
            PendingKind::Jaw(5, 11),
            PendingKind::Pair(0, 1),
        ]
    }

    /// `precedes`, `rank` and `earlier` must all give the same verdict.
    fn assert_before(x: Pending, y: Pending) {
        assert!(x.precedes(&y), "{x:?} before {y:?}");
        assert!(!y.precedes(&x), "{y:?} not before {x:?}");
        assert!(x.rank() < y.rank(), "{x:?} ranks before {y:?}");
        assert_eq!(earlier(Some(x), Some(y)), Some(x));
        assert_eq!(earlier(Some(y), Some(x)), Some(x));
    }

    #[test]
    fn the_earlier_time_wins_whatever_the_kind() {
        let t: f64 = 0.25;
        let later = f64::from_bits(t.to_bits() + 1);
        for first in one_of_each_kind() {
            for second in one_of_each_kind() {
                assert_before(at(t, first), at(later, second));
            }
        }
        // Negative times and zeros follow `f64::total_cmp` (-0 before +0).
        let pair = PendingKind::Pair(0, 1);
        let crossing = PendingKind::Crossing(0, Side::XPlus);
        assert_before(at(-1.0, pair), at(-0.5, crossing));
        assert_before(at(-0.0, pair), at(0.0, crossing));
        assert_before(at(0.0, pair), at(f64::INFINITY, crossing));
    }

    #[test]
    fn at_equal_times_crossings_transitions_openings_cushions_jaws_then_pairs() {
        let kinds = one_of_each_kind();
        for (i, &x) in kinds.iter().enumerate() {
            for &y in &kinds[i + 1..] {
                assert_before(at(1.5, x), at(1.5, y));
            }
        }
    }

    #[test]
    fn within_a_kind_the_lower_ball_then_the_lower_part_wins() {
        let t = 2.0;
        use PendingKind::{Crossing, Jaw, Opening, Pair, Transition};
        let orders = [
            (Crossing(1, Side::YMinus), Crossing(2, Side::XPlus)),
            (Crossing(3, Side::XPlus), Crossing(3, Side::XMinus)),
            (Crossing(3, Side::YPlus), Crossing(3, Side::YMinus)),
            (Transition(0), Transition(1)),
            (Opening(1, 5), Opening(2, 0)),
            (Opening(1, 0), Opening(1, 5)),
            (
                PendingKind::Cushion(1, Cushion::Right),
                PendingKind::Cushion(2, Cushion::Head),
            ),
            (Jaw(4, 11), Jaw(5, 0)),
            (Jaw(4, 0), Jaw(4, 1)),
            // A pair by its lower ball, then by its higher one.
            (Pair(1, 9), Pair(2, 3)),
            (Pair(1, 3), Pair(1, 9)),
        ];
        for (x, y) in orders {
            assert_before(at(t, x), at(t, y));
        }
        // Cushions in the order of `Cushion::ALL`.
        for (i, &c) in Cushion::ALL.iter().enumerate() {
            for &d in &Cushion::ALL[i + 1..] {
                assert_before(
                    at(t, PendingKind::Cushion(4, c)),
                    at(t, PendingKind::Cushion(4, d)),
                );
            }
        }
    }

    #[test]
    fn rank_orders_by_time_then_key() {
        let times = [
            -3.0,
            -0.0,
            0.0,
            1e-300,
            0.1,
            0.1 + 1e-17,
            7.0,
            f64::INFINITY,
        ];
        let mut all = Vec::new();
        for &t in &times {
            for kind in one_of_each_kind() {
                all.push(at(t, kind));
            }
        }
        for x in &all {
            for y in &all {
                let by_fields = x.time.total_cmp(&y.time).then(x.key().cmp(&y.key()));
                assert_eq!(x.rank().cmp(&y.rank()), by_fields, "{x:?} against {y:?}");
                assert_eq!(x.precedes(y), by_fields.is_lt(), "{x:?} against {y:?}");
            }
        }
    }

    #[test]
    fn nothing_loses_to_none_and_empty_ranks_last() {
        let p = at(1.0, PendingKind::Transition(0));
        assert_eq!(earlier(Some(p), None), Some(p));
        assert_eq!(earlier(None, Some(p)), Some(p));
        assert_eq!(earlier(None, None), None);
        assert_eq!(rank(None), Tournament::<Pending>::EMPTY);
        assert!(rank(Some(at(f64::INFINITY, PendingKind::Pair(0, 1)))) < rank(None));
    }

    #[test]
    fn a_pair_event_names_its_partner_and_involves_both_balls() {
        let p = at(1.0, PendingKind::Pair(2, 7));
        assert_eq!(
            (p.partner(2), p.partner(7), p.partner(3)),
            (Some(7), Some(2), None)
        );
        assert!(p.involves(2) && p.involves(7) && !p.involves(3));
        let c = at(1.0, PendingKind::Cushion(4, Cushion::Head));
        assert_eq!(c.partner(4), None);
        assert!(c.involves(4) && !c.involves(2));
    }
}
