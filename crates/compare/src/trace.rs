//! What a solver run leaves behind: sampled states, contacts, and diagnostics of what went
//! wrong (overlaps, tunnelling, balls off the table). Every solver fills the same types, so one
//! comparison routine measures them all.

use billiards_physics::{Pocket, Vec2};

/// One ball at one sample time.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sample {
    /// Centre, metres.
    pub position: Vec2,
    /// Velocity, m/s.
    pub velocity: Vec2,
    /// Pocket the ball fell into, if it is out of play.
    pub pocketed: Option<Pocket>,
}

/// What touched what: the key by which a solver's contacts are matched to the exact ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ContactKey {
    /// Two balls, lower index first.
    Pair(usize, usize),
    /// A ball and a cushion (which cushion is not part of the key: solvers that infer
    /// contacts cannot always tell two cushions of a corner apart).
    Cushion(usize),
    /// A ball left play through a pocket mouth.
    Pocket(usize),
}

impl ContactKey {
    /// The key of a pair of balls in either order.
    pub fn pair(a: usize, b: usize) -> Self {
        ContactKey::Pair(a.min(b), a.max(b))
    }
}

/// One contact, at the time the solver resolved it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// Simulation time, seconds.
    pub time: f64,
    /// What touched what.
    pub key: ContactKey,
}

/// Failures a solver shows in its own output states, independent of any reference.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Diagnostics {
    /// Pairs that passed through each other without a contact being resolved between them.
    pub tunnelled: usize,
    /// Episodes in which two balls in the solver's output states overlap by more than
    /// [`OVERLAP_TOLERANCE`].
    pub overlaps: usize,
    /// Deepest overlap seen in the output states, metres.
    pub max_overlap: f64,
    /// Ball–ball collisions resolved while the balls were not touching: apart by more than
    /// [`CONTACT_TOLERANCE`] (an impulse at a distance) or overlapping by more.
    pub gap_contacts: usize,
    /// Largest distance from touching (gap or overlap) at which a ball–ball collision was
    /// resolved, metres; NaN where the solver does not say where it resolved (Rapier).
    pub max_contact_gap: f64,
    /// Balls seen off the table while in play: centre beyond the cushion nose, so at least
    /// half the ball is through the cushion (or the position is not finite).
    pub off_table: usize,
}

/// Penetration (metres) below which two balls or a ball and a cushion count as touching, not
/// overlapping: far above rounding, far below anything a player could see.
pub const OVERLAP_TOLERANCE: f64 = 1e-6;

/// Distance from touching (metres) within which a collision counts as resolved at contact:
/// rounding of positions of order one metre is about 1e-16 m.
pub const CONTACT_TOLERANCE: f64 = 1e-9;

/// The record of one solver run.
#[derive(Clone, Debug, Default)]
pub struct Trace {
    /// `samples[k][i]`: ball `i` at sample time `k * interval`.
    pub samples: Vec<Vec<Sample>>,
    /// Contacts in the order resolved.
    pub contacts: Vec<Contact>,
    /// Failures seen (only filled by diagnostic runs).
    pub diagnostics: Diagnostics,
}

/// Tracks overlaps and escapes in a sequence of output states (one call per state).
#[derive(Clone, Debug, Default)]
pub struct OverlapWatch {
    /// Pairs overlapping in the previous state, so an episode is counted once.
    overlapping: Vec<bool>,
    /// Balls already counted as off the table.
    escaped: Vec<bool>,
    /// The running counts.
    pub diagnostics: Diagnostics,
}

impl OverlapWatch {
    /// A watch over `n` balls.
    pub fn new(n: usize) -> Self {
        Self {
            overlapping: vec![false; n * n],
            escaped: vec![false; n],
            diagnostics: Diagnostics::default(),
        }
    }

    /// Looks at one output state. `bounds` are the half extents the centres must stay within.
    /// Returns the pairs whose overlap episode started in this state.
    pub fn observe(&mut self, balls: &[Sample], radius: f64, bounds: Vec2) -> Vec<(usize, usize)> {
        let n = balls.len();
        let mut started = Vec::new();
        for (i, a) in balls.iter().enumerate() {
            if a.pocketed.is_some() {
                continue;
            }
            let out = a.position.x.abs() > bounds.x + radius
                || a.position.y.abs() > bounds.y + radius
                || !a.position.is_finite();
            if out && !self.escaped[i] {
                self.escaped[i] = true;
                self.diagnostics.off_table += 1;
            }
            for (j, b) in balls.iter().enumerate().skip(i + 1) {
                if b.pocketed.is_some() {
                    continue;
                }
                let depth = 2.0 * radius - (b.position - a.position).length();
                let now = depth > OVERLAP_TOLERANCE;
                let slot = &mut self.overlapping[i * n + j];
                if now {
                    self.diagnostics.max_overlap = self.diagnostics.max_overlap.max(depth);
                    if !*slot {
                        self.diagnostics.overlaps += 1;
                        started.push((i, j));
                    }
                }
                *slot = now;
            }
        }
        started
    }
}

/// Total kinetic energy of the balls in play, joules.
pub fn kinetic_energy(balls: &[Sample], mass: f64) -> f64 {
    balls
        .iter()
        .filter(|b| b.pocketed.is_none())
        .map(|b| 0.5 * mass * b.velocity.length_squared())
        .sum()
}
