//! Run time against error: the exact event-driven solver of `billiards-physics` against the
//! paper's linear prediction, fixed-step integration of the same model (discrete and swept
//! collision detection) and Rapier, on the same scenes.
//!
//! The binary (`cargo run --release -p billiards-compare`) writes a CSV and an SVG plot; the
//! library is here so the integration test can run the quick mode.

pub mod analytic;
pub mod bench;
pub mod exact;
pub mod fixed_step;
pub mod measure;
pub mod plot;
pub mod rapier;
pub mod realism;
pub mod report;
pub mod scaling;
pub mod scene;
pub mod trace;
