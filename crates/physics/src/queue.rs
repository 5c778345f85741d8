//! The earliest of the per-ball cached predictions, kept in a tournament tree so finding it
//! costs O(1) and updating one ball O(log n), instead of a scan over every ball per event.

/// A tournament tree over `n` slots holding optional keys, each with an integer rank (lower
/// wins; ties go to the lower slot). A rank's high 64 bits (the time, in `Pending::rank`) sit
/// in the tree beside the slot, 16 bytes a node; its low 64 bits (the tie order) are read
/// from the slots only where two high halves are equal, which events seldom are. The order
/// is that of the whole 128-bit ranks, so the same key wins as with ranks in the nodes.
#[derive(Debug)]
pub struct Tournament<K: Copy> {
    size: usize,
    /// Each slot's key and the low 64 bits of its rank, side by side, so that setting a
    /// slot writes one place (issue 53: a cache miss fewer a set in large scenes).
    slots: Vec<(u64, Option<K>)>,
    /// For every node (`1..size` internal, `size..2 size` the slots): the high 64 bits of the
    /// rank of the best key below, and its slot. A replay carries its winner up and reads
    /// only the other side.
    nodes: Vec<(u64, usize)>,
}

clone_reusing!(Tournament<K: Copy> { size, slots, nodes });

impl<K: Copy> Tournament<K> {
    /// Rank of an empty slot: loses to every key.
    pub const EMPTY: u128 = u128::MAX;

    /// `n` empty slots.
    pub fn new(n: usize) -> Self {
        let size = n.max(1).next_power_of_two();
        let mut nodes = vec![(u64::MAX, 0); 2 * size];
        for (i, node) in nodes[size..].iter_mut().enumerate() {
            node.1 = i;
        }
        // All empty: every internal node holds its leftmost slot.
        for node in (1..size).rev() {
            nodes[node] = nodes[2 * node];
        }
        Self {
            size,
            slots: vec![(u64::MAX, None); size],
            nodes,
        }
    }

    /// Key of slot `i`.
    pub fn get(&self, i: usize) -> Option<K> {
        self.slots[i].1
    }

    /// Rank of slot `i` ([`Self::EMPTY`] if it is empty).
    pub fn rank(&self, i: usize) -> u128 {
        u128::from(self.nodes[self.size + i].0) << 64 | u128::from(self.slots[i].0)
    }

    /// Sets slot `i` to `key` with rank `rank` ([`Self::EMPTY`] for `None`) and replays its
    /// matches up to the root.
    pub fn set(&mut self, i: usize, key: Option<K>, rank: u128) {
        debug_assert_eq!(key.is_none(), rank == Self::EMPTY);
        self.slots[i] = (rank as u64, key);
        // Indices masked to the tree's `2 size` nodes (a power of two, so the mask changes
        // none of them): the compiler then drops the bounds checks of the replay.
        let mask = 2 * self.size - 1;
        let nodes = &mut self.nodes[..=mask];
        let slots = &self.slots[..self.size];
        let mut node = self.size + i;
        let mut best = ((rank >> 64) as u64, i);
        nodes[node & mask] = best;
        // Every level is replayed, with selects rather than branches: which side wins is as
        // good as random, and a mispredicted branch costs more than the few levels an early
        // stop (when the winner above is unchanged) would save.
        while node > 1 {
            let other = nodes[(node ^ 1) & mask];
            // Ties go to the left child, whose slots are all lower: the lower (rank, slot)
            // wins. So the rank alone decides, and an equal rank only from the left (`node`
            // is a right child). Equal high halves (rare: two events at one instant, or two
            // empty slots) are decided by the low halves.
            let right = node & 1 == 1;
            let take = if other.0 != best.0 {
                other.0 < best.0
            } else {
                let (a, b) = (slots[other.1].0, slots[best.1].0);
                (a < b) | ((a == b) & right)
            };
            best = std::hint::select_unpredictable(take, other, best);
            node /= 2;
            nodes[node & mask] = best;
        }
    }

    /// The best key and its slot.
    pub fn best(&self) -> Option<(usize, K)> {
        let i = self.nodes[1].1;
        self.slots[i].1.map(|k| (i, k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn best_is_the_minimum_after_any_sequence_of_updates() {
        let mut t = Tournament::new(5);
        let set = |t: &mut Tournament<i32>, i: usize, k: Option<i32>| {
            t.set(
                i,
                k,
                k.map_or(Tournament::<i32>::EMPTY, |k| (k + 100) as u128),
            )
        };
        assert_eq!(t.best(), None);
        set(&mut t, 3, Some(7));
        set(&mut t, 1, Some(4));
        set(&mut t, 4, Some(9));
        assert_eq!(t.best(), Some((1, 4)));
        set(&mut t, 1, None);
        assert_eq!(t.best(), Some((3, 7)));
        set(&mut t, 0, Some(-1));
        assert_eq!(t.best(), Some((0, -1)));
        // Ties keep the lower slot.
        set(&mut t, 2, Some(-1));
        assert_eq!(t.best(), Some((0, -1)));
    }

    /// Ranks equal in their high 64 bits (events at one instant) are ordered by their low
    /// 64 bits, then by slot, exactly as whole 128-bit ranks: against a scan for the least
    /// (rank, slot) over 5,000 random updates of 37 slots whose ranks share few high halves.
    #[test]
    fn equal_high_halves_are_ordered_by_the_low_halves_then_the_slot() {
        let n = 37;
        let mut t = Tournament::<u128>::new(n);
        let mut ranks = vec![Tournament::<u128>::EMPTY; n];
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for _ in 0..5000 {
            let i = (next() % n as u64) as usize;
            let (hi, lo) = (next() % 4, next() % 3);
            let rank = if next() % 5 == 0 {
                Tournament::<u128>::EMPTY
            } else {
                u128::from(hi) << 64 | u128::from(lo)
            };
            let key = (rank != Tournament::<u128>::EMPTY).then_some(rank);
            t.set(i, key, rank);
            ranks[i] = rank;
            let k = (0..n).min_by_key(|&k| (ranks[k], k)).expect("slots");
            let want = (ranks[k] != Tournament::<u128>::EMPTY).then_some((k, ranks[k]));
            assert_eq!(t.best(), want);
            assert_eq!(t.rank(i), rank);
        }
    }
}
