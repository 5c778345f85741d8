//! The earliest of the per-ball cached predictions, kept in a tournament tree so finding it
//! costs O(1) and updating one ball O(log n), instead of a scan over every ball per event.

/// A tournament tree over `n` slots holding optional keys, each with an integer rank (lower
/// wins; ties go to the lower slot). Ranks are plain integers so that replaying the matches
/// of one slot costs a few instructions per level.
#[derive(Debug)]
pub struct Tournament<K: Copy> {
    size: usize,
    keys: Vec<Option<K>>,
    /// For every node (`1..size` internal, `size..2 size` the slots): the rank and the slot of
    /// the best key below. A replay carries its winner up and reads only the other side.
    nodes: Vec<(u128, usize)>,
}

clone_reusing!(Tournament<K: Copy> { size, keys, nodes });

impl<K: Copy> Tournament<K> {
    /// Rank of an empty slot: loses to every key.
    pub const EMPTY: u128 = u128::MAX;

    /// `n` empty slots.
    pub fn new(n: usize) -> Self {
        let size = n.max(1).next_power_of_two();
        let mut nodes = vec![(Self::EMPTY, 0); 2 * size];
        for (i, node) in nodes[size..].iter_mut().enumerate() {
            node.1 = i;
        }
        // All empty: every internal node holds its leftmost slot.
        for node in (1..size).rev() {
            nodes[node] = nodes[2 * node];
        }
        Self {
            size,
            keys: vec![None; size],
            nodes,
        }
    }

    /// Key of slot `i`.
    pub fn get(&self, i: usize) -> Option<K> {
        self.keys[i]
    }

    /// Rank of slot `i` ([`Self::EMPTY`] if it is empty).
    pub fn rank(&self, i: usize) -> u128 {
        self.nodes[self.size + i].0
    }

    /// Sets slot `i` to `key` with rank `rank` ([`Self::EMPTY`] for `None`) and replays its
    /// matches up to the root.
    pub fn set(&mut self, i: usize, key: Option<K>, rank: u128) {
        debug_assert_eq!(key.is_none(), rank == Self::EMPTY);
        self.keys[i] = key;
        let mut node = self.size + i;
        let mut best = (rank, i);
        self.nodes[node] = best;
        // Every level is replayed, with selects rather than branches: which side wins is as
        // good as random, and a mispredicted branch costs more than the few levels an early
        // stop (when the winner above is unchanged) would save.
        while node > 1 {
            let other = self.nodes[node ^ 1];
            // Ties go to the left child, whose slots are all lower: the lower (rank, slot)
            // wins. So the rank alone decides, and an equal rank only from the left (`node`
            // is a right child): one comparison of ranks, not of (rank, slot) pairs.
            let right = node & 1 == 1;
            let take = (other.0 < best.0) | ((other.0 == best.0) & right);
            best = std::hint::select_unpredictable(take, other, best);
            node /= 2;
            self.nodes[node] = best;
        }
    }

    /// The best key and its slot.
    pub fn best(&self) -> Option<(usize, K)> {
        let i = self.nodes[1].1;
        self.keys[i].map(|k| (i, k))
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
}
