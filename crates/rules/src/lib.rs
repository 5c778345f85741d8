//! The rules of the game, in one place that the game, the command line (`billiards-cli`) and
//! the computer opponent all call. Pure Rust on top of `billiards-physics`: no Bevy, no I/O.
//!
//! - [`respot`]: where the cue ball goes back after a scratch (the head string) and where an
//!   object ball is spotted (the foot string, WPA 1.4);
//! - [`shots`]: what a "shot" of a recording is (from one strike to the next), numbered from 1
//!   everywhere a player sees a shot number;
//! - [`shot`]: the facts of one shot read from the solver's events ([`ShotSummary`]);
//! - [`racks`]: 8-ball, 9-ball and 10-ball racks with a real rack's small random gaps, from
//!   a seed;
//! - [`game`]: one rack of 8-ball, 9-ball, 10-ball (WPA rules) or free play:
//!   [`GameState::play`] judges a shot and returns its [`Verdict`] and the [`NextShot`];
//!   each game's rules in [`eight_ball`], [`nine_ball`] and [`ten_ball`];
//! - [`state`]: the state of one rack ([`GameState`]), which each game's rules move on;
//! - [`turn`]: the words of one turn ([`Seat`], [`Call`], [`NextShot`], [`Verdict`]);
//! - [`hand`]: whether a ball-in-hand placement is allowed;
//! - [`foul`]: fouls and the ends of games, with sentences a player can read;
//! - [`race`]: a match, race to N racks;
//! - [`log`]: the rules side of a recording (calls, choices, verdicts), kept beside it;
//! - [`breaks`]: one break judged by the rules and the counts over many (break statistics);
//! - [`snooker`]: snooker frames and matches under the WPBSA rules, an API of its own;
//! - [`three_cushion`]: three-cushion carom under the UMB rules, an API of its own;
//! - [`position`]: a position (game, table, balls, physics, shot) as a short text code;
//! - [`drill`]: drills, a position with goals and tries, judged from the solver's record;
//! - [`interface`]: the one interface every game implements ([`GameRules`]), with pool's
//!   games behind it in [`pool`] and snooker's in [`snooker::rules`];
//! - [`drill_game`]: a drill session behind the interface, a one-player game of tries;
//! - [`catalog`]: every game, found by its command-line id and started behind the interface.

pub mod breaks;
pub mod catalog;
pub mod drill;
pub mod drill_game;
pub mod eight_ball;
pub mod foul;
pub mod game;
pub mod hand;
pub mod interface;
pub mod log;
pub mod nine_ball;
pub mod pool;
pub mod position;
pub mod race;
pub mod racks;
pub mod replay_strokes;
pub mod respot;
mod rotation;
pub mod shot;
pub mod shots;
pub mod snooker;
pub mod state;
pub mod stroke_log;
pub mod ten_ball;
pub mod three_cushion;
pub mod turn;

pub use drill::{Attempt, Drill, DrillError, DrillScore, DrillShot, Goal, Zone};
pub use foul::{BallOn, Foul, Group, WinReason, pocket_name};
pub use game::{
    Call, CallRule, Choice, CueBall, Game, GameState, NextShot, Outcome, RuleError, Seat, Verdict,
    what_happened,
};
pub use hand::{PlacementError, check_place, check_placement};
pub use interface::{
    CueBallPlace, Declaration, Declarations, GameEnd, GameRules, HandRegion, Judgement, Need,
    RulesError, Setup, StrokeRecord, Turn, hand_place,
};
pub use log::{GameLog, LogError, LoggedShot, RulesLog};
pub use position::{PlacedBall, Position, PositionError};
pub use race::Match;
pub use racks::RackStyle;

pub use respot::{
    RESPOT_CLEARANCE, SPOT_CLEARANCE, cue_ball_spot, foot_spot_position, head_string_spot,
    object_ball_spot,
};
pub use shot::{CUE, ShotSummary, summarise};
pub use shots::Shots;
pub use stroke_log::{StrokeEntry, StrokeLog};
