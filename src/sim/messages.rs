//! The simulation's messages and its status for the HUD and the game flow.

use std::time::{SystemTime, UNIX_EPOCH};

use bevy::prelude::*;
use billiards_physics::{self as physics, Rack};

/// The racks the panel offers, in its order.
pub const RACKS: [Rack; 4] = [
    Rack::PaperDefault,
    Rack::FifteenBall,
    Rack::Tight,
    Rack::NineBall,
];

/// The name of a rack shown to the player.
pub fn rack_label(rack: Rack) -> &'static str {
    match rack {
        Rack::PaperDefault => "Paper default",
        Rack::FifteenBall => "15-ball rack",
        Rack::Tight => "Tight 15",
        Rack::NineBall => "9-ball rack",
    }
}

/// The rack on the table when the game starts: the paper's 15 balls 1/10 in apart, with the
/// cue ball on the head spot.
pub const STARTING_RACK: Rack = Rack::FifteenBall;

/// A short name of a rack for file names.
pub fn rack_slug(rack: Rack) -> &'static str {
    match rack {
        Rack::PaperDefault => "paper",
        Rack::FifteenBall => "15-ball",
        Rack::Tight => "tight-15",
        Rack::NineBall => "9-ball",
    }
}

/// Asks for the table to be cleared and racked anew.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RackRequested {
    /// The rack.
    pub rack: Rack,
    /// `None`: the standard layout, the same every time. `Some(seed)`: the 15-ball and 9-ball
    /// racks as a player sets them ([`crate::settings::TableSetup::rack_style`]), their balls
    /// and gaps drawn from the seed, so no two racks break alike.
    pub seed: Option<u64>,
}

impl RackRequested {
    /// The standard layout of `rack`.
    pub fn standard(rack: Rack) -> Self {
        Self { rack, seed: None }
    }

    /// `rack` set by hand, from `seed` (see [`RackRequested::seed`]).
    pub fn fresh(rack: Rack, seed: u64) -> Self {
        Self {
            rack,
            seed: Some(seed),
        }
    }
}

/// A seed from the wall clock: each new match and each fresh rack gets its own.
pub fn clock_seed() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64)
}

/// Asks for the table to be cleared and set up with these balls (a rules game's seeded rack,
/// [`billiards_rules::Game::rack`]); `rack` names the recording. Wins over a
/// [`RackRequested`] of the same frame.
#[derive(Message, Debug, Clone, PartialEq)]
pub struct LayoutRequested {
    /// The balls, the cue ball first.
    pub balls: Vec<physics::BallSetup>,
    /// The standard rack closest to it.
    pub rack: Rack,
    /// What names the recording file: "9-ball", "8-ball".
    pub name: &'static str,
}

/// Asks for the table to be cleared and set up as a whole scene that brings its own table and
/// parameters (the stress table, `crate::stress`): the table drawn is the scene's, and the
/// Physics settings leave it alone until the next rack. Wins over a [`RackRequested`] or a
/// [`LayoutRequested`] of the same frame.
#[derive(Message, Debug, Clone, PartialEq)]
pub struct SceneRequested {
    /// The table.
    pub table: physics::Table,
    /// The parameters.
    pub params: physics::Params,
    /// The balls, the cue ball first.
    pub balls: Vec<physics::BallSetup>,
    /// What names the recording file: "stress".
    pub name: &'static str,
}

/// What the game in play (`crate::play::game`, behind the one interface) asks of the
/// simulation: whether the table may be set by hand, and whether a shot must wait (a choice
/// or a call is pending, the game is over). A scratch's cue ball is the rules' to put back
/// (their judgement's `put`). The default: the table the player's.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct Referee {
    /// The table may be set by hand: balls placed, racks from the panel, scenes, a shot taken
    /// back (free play's sandbox, or no game); a match's table is its own.
    pub edits: bool,
    /// Why the next shot may not be taken yet, if it may not.
    pub refuse_shot: Option<String>,
    /// The rack is over: no shot until the next rack (the cue is put away).
    pub rack_over: bool,
}

impl Default for Referee {
    fn default() -> Self {
        Self {
            edits: true,
            refuse_shot: None,
            rack_over: false,
        }
    }
}

/// Asks for the cue ball to be struck. Only honoured while every ball rests.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ShotRequested {
    /// Direction in the table plane, radians counter-clockwise from +x.
    pub angle: f64,
    /// Cue-ball speed given by the cue, m/s.
    pub speed: f64,
    /// Where the tip strikes (spin model).
    pub tip: physics::TipOffset,
    /// How far the cue's butt is raised, radians (0 level; swerve with side spin).
    pub elevation: f64,
}

impl ShotRequested {
    /// The request for the shot the settings describe.
    pub fn from_settings(shot: &crate::settings::ShotSettings) -> Self {
        shot.shot().into()
    }

    /// The solver's shot.
    pub fn shot(&self) -> physics::Shot {
        physics::Shot {
            angle: self.angle,
            speed: self.speed,
            tip: self.tip,
            elevation: self.elevation,
        }
    }
}

impl From<physics::Shot> for ShotRequested {
    fn from(shot: physics::Shot) -> Self {
        Self {
            angle: shot.angle,
            speed: shot.speed,
            tip: shot.tip,
            elevation: shot.elevation,
        }
    }
}

/// Asks for the last shot to be taken back (practice: free play only). Every ball goes back to
/// where it rested before the strike through placements the recorder logs, so a recording
/// with undos replays and verifies bit for bit like any other. Also while balls still move.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct UndoRequested;

/// A shot was taken back; carries it, so the panel can line it up again (retry).
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ShotUndone {
    /// The shot taken back.
    pub shot: ShotRequested,
}

/// Asks the paused simulation to advance exactly to its next event.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StepRequested;

/// The cue struck a ball.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct CueStruck {
    /// The ball.
    pub ball: Entity,
    /// The speed the cue gave it, m/s.
    pub speed: f64,
    /// Simulation time, seconds.
    pub time: f64,
}

/// Two balls collided.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct BallContact {
    /// The ball with the lower solver index.
    pub a: Entity,
    /// The other ball.
    pub b: Entity,
    /// Their relative speed just after the contact, m/s (how hard it sounds).
    pub speed: f64,
    /// Simulation time of the contact, seconds.
    pub time: f64,
}

/// What part of the table's edge a ball hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CushionPart {
    /// The straight nose of a cushion.
    Cushion(physics::Cushion),
    /// The rounded jaw at the mouth of a pocket.
    Jaw(physics::Pocket),
}

/// A ball hit a cushion or a pocket jaw.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct CushionHit {
    /// The ball.
    pub ball: Entity,
    /// What it hit.
    pub part: CushionPart,
    /// The ball's speed just after the hit, m/s.
    pub speed: f64,
    /// Simulation time of the hit, seconds.
    pub time: f64,
}

/// A ball dropped into a pocket.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct BallPocketed {
    /// The ball.
    pub ball: Entity,
    /// Its number.
    pub number: u8,
    /// The pocket.
    pub pocket: physics::Pocket,
    /// Simulation time, seconds.
    pub time: f64,
}

/// Every ball has come to rest after a shot.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShotFinished {
    /// Whether the cue ball went into a pocket.
    pub scratch: bool,
}

/// What the simulation reports to the HUD and to the game flow.
#[derive(Resource, Debug, Clone, PartialEq, Default)]
pub struct SimStatus {
    /// Whether every ball is at rest (a shot may be taken).
    pub at_rest: bool,
    /// Shots taken since the last rack.
    pub shots: u32,
    /// Simulated time since the last rack, seconds, less the time of shots taken back by
    /// Undo ([`crate::sim::Solver::game_time`]).
    pub sim_time: f64,
    /// Events the solver resolved since the last strike (the strike itself not counted).
    pub events_this_shot: usize,
    /// Wall time the solver took in the last frame that ran it, seconds.
    pub solver_seconds_last_frame: f64,
    /// A message for the player about the simulation's state, if any.
    pub note: Option<String>,
    /// Until the next shot, the cue ball is in hand: after a free-play scratch
    /// ([`HandRule::Respot`]: it slides along the head string), or under the rules behind the
    /// head string, anywhere, or in the D.
    pub ball_in_hand: Option<HandRule>,
}

/// Where the cue ball in hand may go.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HandRule {
    /// Free play after a scratch: along the head string.
    Respot,
    /// Anywhere on the table (WPA 1.5).
    Anywhere,
    /// Behind the head string (WPA 2.3, 3.3).
    BehindHeadString,
    /// In the D (snooker, WPBSA 3.4).
    InD,
}

impl HandRule {
    /// The interface's place of the cue ball as a placement rule (`None`: not in hand).
    pub fn of_place(place: billiards_rules::CueBallPlace) -> Option<Self> {
        use billiards_rules::{CueBallPlace, HandRegion};
        match place {
            CueBallPlace::InHand { region } => Some(match region {
                HandRegion::Anywhere => Self::Anywhere,
                HandRegion::BehindHeadString => Self::BehindHeadString,
                HandRegion::D => Self::InD,
            }),
            // Put back by the rules (free play's respot): it may slide along the head string.
            CueBallPlace::Placed => Some(Self::Respot),
            CueBallPlace::AsItLies => None,
        }
    }
}
