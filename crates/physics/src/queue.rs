//! The earliest of the per-ball cached predictions, kept in a tournament tree so finding it
//! costs O(1) and updating one ball O(log n), instead of a scan over every ball per event.

/// A tournament over `n` slots holding optional keys, each with an integer rank (lower wins;
/// ties go to the lower slot). A rank's high 64 bits (the time, in `Pending::rank`) sit in
/// an array of their own; its low 64 bits (the tie order) sit beside each slot's key and are
/// read only where two high halves are equal, which events seldom are. The order is that of
/// the whole 128-bit ranks, so the same key wins as with whole ranks compared.
///
/// The slots come in blocks of `2^shift` (one for the small scenes), each
/// block's best kept at a leaf of a binary tree over the blocks (issue 53): setting a slot
/// that neither beats its block's best nor was it leaves the tree alone, and otherwise
/// replays a tree of `n / 2^shift` leaves, which at 100,000 balls in blocks of 16 is 256 kB
/// (in the L2 cache) where a tree over the slots is 4 MB (a cache miss a level near its
/// leaves). Only a block's best that gets worse costs a scan of the block's high halves
/// (128 bytes in one run of memory).
#[derive(Debug)]
pub struct Tournament<K: Copy> {
    /// Leaves of the tree over the blocks (a power of two).
    size: usize,
    /// log2 of the slots a block.
    shift: u32,
    /// Each slot's key and the low 64 bits of its rank, side by side, so that setting a
    /// slot writes one place (issue 53: a cache miss fewer a set in large scenes).
    slots: Vec<(u64, Option<K>)>,
    /// The high 64 bits of each slot's rank, in one run a block for its scan (empty in
    /// blocks of one, whose leaves hold them).
    highs: Vec<u64>,
    /// For every node (`1..size` internal, `size..2 size` the blocks): the high 64 bits of
    /// the rank of the best key below, and its slot. A replay carries its winner up and
    /// reads only the other side.
    nodes: Vec<(u64, usize)>,
}

clone_reusing!(Tournament<K: Copy> { size, shift, slots, highs, nodes });

impl<K: Copy> Tournament<K> {
    /// Rank of an empty slot: loses to every key.
    pub const EMPTY: u128 = u128::MAX;

    /// `n` empty slots, a block each (a plain tournament tree: the pair table's scenes).
    pub fn new(n: usize) -> Self {
        Self::with_blocks(n, 0)
    }

    /// `n` empty slots in blocks of `2^shift` (the cell lists' large scenes).
    pub fn with_blocks(n: usize, shift: u32) -> Self {
        let size = n.max(1).div_ceil(1 << shift).next_power_of_two();
        let mut nodes = vec![(u64::MAX, 0); 2 * size];
        for (b, node) in nodes[size..].iter_mut().enumerate() {
            node.1 = b << shift;
        }
        // All empty: every internal node holds its leftmost slot.
        for node in (1..size).rev() {
            nodes[node] = nodes[2 * node];
        }
        Self {
            size,
            shift,
            slots: vec![(u64::MAX, None); size << shift],
            // A block of one is its own best: its high half is the leaf's, kept there alone.
            highs: if shift == 0 {
                Vec::new()
            } else {
                vec![u64::MAX; size << shift]
            },
            nodes,
        }
    }

    /// Key of slot `i`.
    pub fn get(&self, i: usize) -> Option<K> {
        self.slots[i].1
    }

    /// Rank of slot `i` ([`Self::EMPTY`] if it is empty).
    pub fn rank(&self, i: usize) -> u128 {
        let high = if self.shift == 0 {
            self.nodes[self.size + i].0
        } else {
            self.highs[i]
        };
        u128::from(high) << 64 | u128::from(self.slots[i].0)
    }

    /// Sets slot `i` to `key` with rank `rank` ([`Self::EMPTY`] for `None`) and, if its
    /// block's best changed, replays the block's matches up to the root.
    pub fn set(&mut self, i: usize, key: Option<K>, rank: u128) {
        debug_assert_eq!(key.is_none(), rank == Self::EMPTY);
        let (high, low) = ((rank >> 64) as u64, rank as u64);
        let leaf = self.size + (i >> self.shift);
        let best = if self.shift == 0 {
            self.slots[i] = (low, key);
            (high, i)
        } else {
            // The block's best before: the new rank takes its place if it is lower in
            // (rank, slot), the same order as the tree's (equal ranks to the lower slot).
            let held = self.nodes[leaf];
            let beats = high < held.0
                || (high == held.0 && {
                    let low_held = self.slots[held.1].0;
                    low < low_held || (low == low_held && i <= held.1)
                });
            self.slots[i] = (low, key);
            self.highs[i] = high;
            if beats {
                (high, i)
            } else if held.1 == i {
                // The best got worse: another slot of the block may now lead.
                self.scan(i >> self.shift)
            } else {
                // Neither the best before nor now: the block's best and the tree stand.
                return;
            }
        };
        self.replay(leaf, best);
    }

    /// The least (rank, slot) of block `b`: the least high half, first where it occurs,
    /// unless it occurs twice (rare: events at one instant, or empty slots), where the low
    /// halves decide.
    fn scan(&self, b: usize) -> (u64, usize) {
        let start = b << self.shift;
        let highs = &self.highs[start..start + (1 << self.shift)];
        let (mut least, mut at, mut tied) = (highs[0], 0, false);
        for (k, &high) in highs.iter().enumerate().skip(1) {
            // A strictly lower high half leads alone; an equal one marks a tie.
            tied = (tied & (high >= least)) | (high == least);
            at = if high < least { k } else { at };
            least = least.min(high);
        }
        if tied {
            // Strictly lower only: an equal rank stays with the lower slot.
            let low = |k: usize| self.slots[start + k].0;
            for (k, &high) in highs.iter().enumerate().skip(at + 1) {
                if high == least && low(k) < low(at) {
                    at = k;
                }
            }
        }
        (least, start + at)
    }

    /// Puts `best` at node `leaf` and replays its matches up to the root.
    fn replay(&mut self, leaf: usize, mut best: (u64, usize)) {
        // Indices masked to the tree's `2 size` nodes (a power of two, so the mask changes
        // none of them): the compiler then drops the bounds checks of the replay.
        let mask = 2 * self.size - 1;
        let nodes = &mut self.nodes[..=mask];
        let slots = &self.slots[..];
        let mut node = leaf;
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
    /// (rank, slot) over 5,000 random updates of 37 slots whose ranks share few high halves,
    /// in blocks of 1, 2, 4, 8 and 64 slots (several blocks, a last one part empty, and one
    /// block holding every slot: its best beaten, kept, and worsened into a scan).
    #[test]
    fn equal_high_halves_are_ordered_by_the_low_halves_then_the_slot() {
        for shift in [0, 1, 2, 3, 6] {
            let n = 37;
            let mut t = Tournament::<u128>::with_blocks(n, shift);
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
                assert_eq!(t.best(), want, "blocks of {}", 1 << shift);
                assert_eq!(t.rank(i), rank);
            }
        }
    }
}
