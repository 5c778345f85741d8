//! Test-only access to a simulation's insides, for the invariant monitor's tests.

use super::Simulation;

impl Simulation {
    /// The history and the balls' current segments, to write into: the invariant monitor's
    /// tests forge histories and states the solver never makes (`check/tests.rs`).
    pub(crate) fn forge(&mut self) -> (&mut crate::History, &mut [crate::Segment]) {
        (&mut self.history, &mut self.segments)
    }
}
