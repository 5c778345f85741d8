//! Exact event-driven billiards physics.
//!
//! This crate implements Anderson's "Realistic Billiards Simulation with Variable Time-Step":
//! the simulation never takes a fixed step; it advances exactly to the next event, resolves
//! it, and continues with the time left. Unlike the paper, contact times are exact for the
//! decelerating motion the balls really follow (quadratic roots for cushions, quartic for ball
//! pairs); the paper's linear prediction is kept as [`Prediction::PaperLinear`] for comparison.
//!
//! Units are SI; the table plane is `x` (head to foot) by `y` (left positive), `z` up.
//!
//! ```
//! use billiards_physics::{Params, Rack, Shot, Simulation, Table};
//! let table = Table::wpa_8ft();
//! let params = Params::default();
//! let balls = Rack::FifteenBall.layout(&table, &params.ball);
//! let mut sim = Simulation::new(table, params, &balls).unwrap();
//! sim.strike(0, Shot::new(0.0, 10.0)).unwrap();
//! sim.run_to_rest().unwrap();
//! assert!(sim.is_at_rest());
//! ```

/// `Clone` for a struct, field by field, with a `clone_from` that reuses the fields' own
/// buffers: a search that resets a simulation to a base state thousands of times a second
/// then allocates nothing (`#[derive(Clone)]` keeps the default `clone_from`, which clones
/// anew and drops the old value).
macro_rules! clone_reusing {
    ($ty:ident $(<$g:ident: $b:path>)? { $($field:ident),* $(,)? }) => {
        impl$(<$g: $b>)? Clone for $ty$(<$g>)? {
            fn clone(&self) -> Self {
                Self { $($field: self.$field.clone()),* }
            }
            fn clone_from(&mut self, source: &Self) {
                $(self.$field.clone_from(&source.$field);)*
            }
        }
    };
}

pub mod ball;
pub mod bounds;
pub mod carom;
pub mod check;
pub mod detect;
pub mod event;
pub mod grid;
pub mod history;
pub mod limits;
pub mod math;
pub mod motion;
pub mod params;
pub mod poly;
pub mod queue;
pub mod racks;
pub mod recording;
pub mod resolve;
pub mod scene;
pub mod sim;
pub mod snooker;
pub mod soak;
pub mod table;

pub use ball::{BallId, BallState, Motion, Segment};
pub use event::{Event, EventKind, Shot, TipOffset};
pub use history::History;
pub use limits::LimitError;
pub use math::{Vec2, Vec3};
pub use params::{
    BallFriction, BallSpec, CushionModel, G, HertzContact, Model, PaperModel, ParamError, Params,
    Prediction, Randomization, SpinModel,
};
pub use racks::Rack;
pub use resolve::cue::Miscue;
pub use sim::{Advance, BallSetup, SetupError, SimError, Simulation};
pub use snooker::SnookerMarks;
pub use table::{
    Cushion, Jaw, Opening, Pocket, PocketCut, PocketShape, SNOOKER_JAW_RADIUS, Table, TableChoice,
    TableError, TableSize,
};
