//! The earliest of the per-ball cached predictions, kept in a tournament tree so finding it
//! costs O(1) and updating one ball O(log n), instead of a scan over every ball per event.

/// A tournament tree over `n` slots holding optional keys; `better(a, b)` says `a` wins.
#[derive(Clone, Debug)]
pub struct Tournament<K: Copy> {
    size: usize,
    keys: Vec<Option<K>>,
    /// `winner[node]` for internal nodes `1..size`: the slot of the best key below.
    winner: Vec<usize>,
}

impl<K: Copy> Tournament<K> {
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
            winner: (0..size).map(leftmost).collect(),
        }
    }

    /// Key of slot `i`.
    pub fn get(&self, i: usize) -> Option<K> {
        self.keys[i]
    }

    /// Sets slot `i` and replays its matches up to the root.
    pub fn set(&mut self, i: usize, key: Option<K>, better: impl Fn(&K, &K) -> bool) {
        self.keys[i] = key;
        let mut node = (self.size + i) / 2;
        while node >= 1 {
            let (l, r) = (self.slot(2 * node), self.slot(2 * node + 1));
            self.winner[node] = match (self.keys[l], self.keys[r]) {
                (Some(a), Some(b)) => {
                    if better(&b, &a) {
                        r
                    } else {
                        l
                    }
                }
                (None, Some(_)) => r,
                _ => l,
            };
            node /= 2;
        }
    }

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
        let lt = |a: &i32, b: &i32| a < b;
        assert_eq!(t.best(), None);
        t.set(3, Some(7), lt);
        t.set(1, Some(4), lt);
        t.set(4, Some(9), lt);
        assert_eq!(t.best(), Some((1, 4)));
        t.set(1, None, lt);
        assert_eq!(t.best(), Some((3, 7)));
        t.set(0, Some(-1), lt);
        assert_eq!(t.best(), Some((0, -1)));
        // Ties keep the lower slot.
        t.set(2, Some(-1), lt);
        assert_eq!(t.best(), Some((0, -1)));
    }
}
