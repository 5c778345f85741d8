//! Drills (issue 39): a position, the goals a shot (or a visit of several) must meet from it,
//! and a count of tries. A drill is a JSON file (`assets/drills/*.json`, one a file):
//!
//! ```json
//! { "name": "Stop shot", "description": "...", "tries": 10, "shots": 1,
//!   "position": { "game": "free_play", "table": { ... }, "balls": [ ... ] },
//!   "goals": [ { "kind": "pocket", "ball": 1, "pocket": "foot_right" },
//!              { "kind": "cue_ball_in", "zone": { "shape": "circle", "centre": { "x": 0.7, "y": -0.2 }, "radius": 0.1 } } ] }
//! ```
//!
//! An attempt is judged from the solver's own record of its shots ([`DrillShot`]: the shot's
//! events summarised, and the balls where they came to rest), never from drawn frames:
//! [`Drill::judge`] returns an [`Attempt`] (success, a score out of 100, the reasons), and a
//! [`DrillScore`] keeps the tries, the successes and the best score, as the game's settings do.

mod definition;
mod goal;
mod judge;
mod shot;

pub use definition::{Drill, DrillError, Loaded, MAX_SHOTS};
pub use goal::{Goal, Zone};
pub use judge::{Attempt, DrillScore, hidden};
pub use shot::{DrillShot, resting};
