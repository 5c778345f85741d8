//! The earliest of the per-ball cached predictions, kept in a tournament tree so finding it
//! costs O(1) and updating one ball O(log n), instead of a scan over every ball per event.

/// A tournament tree over `n` slots holding optional keys, each with an integer rank (lower
/// wins; ties go to the lower slot). Ranks are plain integers so that replaying the matches
/// of one slot costs a few instructions per level.
#[derive(Clone, Debug)]
pub struct Tournament<K: Copy> {
    size: usize,
    keys: Vec<Option<K>>,
    ranks: Vec<u128>,
    /// `winner[node]` for internal nodes `1..size`: the slot of the best key below.
    winner: Vec<usize>,
}

impl<K: Copy> Tournament<K> {
    /// Rank of an empty slot: loses to every key.
    pub const EMPTY: u128 = u128::MAX;

    /// `n` empty slots.
    pub fn new(n: usize) -> Self {
        let size = n.max(1).next_power_of_two();
        // Every internal node starts pointing at a slot of its own subtree (all empty).
        let leftmost = |mut node: usize| {
            while node > 0 && node < size {
                node *= 2;
            }
            node.saturating_sub(size)
        };
        Self {
            size,
            keys: vec![None; size],
            ranks: vec![Self::EMPTY; size],
            winner: (0..size).map(leftmost).collect(),
        }
    }

    /// Key of slot `i`.
    pub fn get(&self, i: usize) -> Option<K> {
        self.keys[i]
    }

    /// Rank of slot `i` ([`Self::EMPTY`] if it is empty).
    pub fn rank(&self, i: usize) -> u128 {
        self.ranks[i]
    }

    /// Sets slot `i` to `key` with rank `rank` ([`Self::EMPTY`] for `None`) and replays its
    /// matches up to the root.
    pub fn set(&mut self, i: usize, key: Option<K>, rank: u128) {
        debug_assert_eq!(key.is_none(), rank == Self::EMPTY);
        self.keys[i] = key;
        self.ranks[i] = rank;
        let mut node = (self.size + i) / 2;
        while node >= 1 {
            let (l, r) = (self.slot(2 * node), self.slot(2 * node + 1));
            let (old, new) = (
                self.winner[node],
                if self.ranks[r] < self.ranks[l] { r } else { l },
            );
            self.winner[node] = new;
            // Slot `i` neither won nor wins here: nothing above changes.
            if old == new && new != i {
                break;
            }
            node /= 2;
        }
    }

    #[inline]
    fn slot(&self, node: usize) -> usize {
        if node >= self.size {
            node - self.size
        } else {
            self.winner[node]
        }
    }

    /// The best key and its slot.
    pub fn best(&self) -> Option<(usize, K)> {
        let i = self.slot(1);
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
