//! Argument types and parsers the subcommands share (racks, games, models, shots, calls,
//! pockets, sizes), and the options of `simulate` and `tournament`, which their dispatchers
//! hand on to `game.rs` and `snooker.rs`: here, not in the dispatchers (`cli.rs`,
//! `simulate.rs`, `tournament.rs`), so every arrow points one way.

use crate::shard::{Shard, parse_shard};
use billiards_physics::*;
use billiards_rules::{Call, Choice, Game};
use clap::ValueEnum;
use std::path::PathBuf;

/// Standard racks.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum RackArg {
    /// The paper's default layout: the cue ball alone.
    PaperDefault,
    /// The paper's 15-ball rack, 1/10 in apart.
    FifteenBall,
    /// A tight 15-ball rack.
    Tight,
    /// A 9-ball diamond.
    NineBall,
}

/// Games with rules.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum GameArg {
    /// 9-ball, WPA rules.
    NineBall,
    /// 10-ball, WPA rules (every shot but the break called).
    TenBall,
    /// 8-ball, WPA rules.
    EightBall,
    /// The sandbox: no fouls, a scratch respots the cue ball.
    FreePlay,
    /// Snooker, WPBSA rules, on the 12-ft table, between two computer levels.
    Snooker,
    /// Three-cushion carom, UMB rules, on the 2.84 m carom table, played through the one
    /// game interface alone.
    ThreeCushion,
}

impl GameArg {
    /// The pool game (`None`: snooker, which has an API of its own).
    pub fn pool(self) -> Option<Game> {
        match self {
            GameArg::NineBall => Some(Game::NineBall),
            GameArg::TenBall => Some(Game::TenBall),
            GameArg::EightBall => Some(Game::EightBall),
            GameArg::FreePlay => Some(Game::FreePlay),
            GameArg::Snooker | GameArg::ThreeCushion => None,
        }
    }

    /// The game's id in the catalog ([`billiards_rules::catalog::find`]).
    pub fn id(self) -> &'static str {
        match self {
            GameArg::NineBall => "nine-ball",
            GameArg::TenBall => "ten-ball",
            GameArg::EightBall => "eight-ball",
            GameArg::FreePlay => "free-play",
            GameArg::Snooker => "snooker",
            GameArg::ThreeCushion => "three-cushion",
        }
    }
}

/// Physics models.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum ModelArg {
    /// The paper's model.
    Paper,
    /// The spin model.
    Spin,
}

/// Ball–ball friction of the spin model.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum BallFrictionArg {
    /// A constant coefficient (the model's `mu_ball`).
    Constant,
    /// `a + b exp(-c v)` of the sliding speed `v` (Alciatore, TP ).
    SpeedDependent,
}

/// Cushion models of the spin model.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum CushionArg {
    /// Han (2005): one impulse at the nose height, e = 0.85, mu = 0.2 (the default).
    Han2005,
    /// Mathavan, Jackson & Parkin (2010): the impact integrated, e = 0.98, mu = 0.14.
    Mathavan2010,
    /// Plain reflection, e = 0.85.
    Reflect,
}

pub(crate) fn parse_end_mass(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(kg) if kg.is_finite() && kg > 0.0 && kg < 1.0 => Ok(kg),
        _ => Err(format!(
            "end mass {s:?}: a positive mass in kg below 1 (e.g. 0.008)"
        )),
    }
}

/// Degrees on the command line, radians in the shot: from 0 to 85 degrees
/// ([`limits::MAX_ELEVATION`]), else the contract's error with the degrees given.
pub(crate) fn parse_elevation(s: &str) -> Result<f64, String> {
    let degrees = s.trim().parse::<f64>().map_err(|e| format!("{s:?}: {e}"))?;
    elevation_of(degrees)
}

fn elevation_of(degrees: f64) -> Result<f64, String> {
    let shot = Shot {
        elevation: degrees.to_radians(),
        ..Shot::new(0.0, 0.0)
    };
    limits::check_shot(&shot).map_err(|e| {
        format!("cue elevation {degrees} degrees: from 0 to 85 degrees (the contract: {e})")
    })?;
    Ok(shot.elevation)
}

/// A `--shot`: the shot, and whether it gave its own elevation (which `--elevation` does
/// not override).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShotArg {
    /// The shot (its elevation 0 unless given).
    pub shot: Shot,
    /// The shot's own elevation, radians, from its fifth field.
    pub elevation: Option<f64>,
}

/// `ANGLE_DEG:SPEED[:SIDE:HEIGHT[:ELEVATION_DEG]]`, every value checked against the physics
/// contract ([`limits::check_shot`]).
pub(crate) fn parse_shot(s: &str) -> Result<ShotArg, String> {
    let v: Vec<f64> = s
        .split(':')
        .map(|x| x.trim().parse::<f64>().map_err(|e| format!("{x:?}: {e}")))
        .collect::<Result<_, _>>()?;
    let tipped = |a: f64, speed, side, height| Shot {
        tip: TipOffset { side, height },
        ..Shot::new(f64::to_radians(a), speed)
    };
    let (shot, elevation) = match v[..] {
        [a, speed] => (Shot::new(a.to_radians(), speed), None),
        [a, speed, side, height] => (tipped(a, speed, side, height), None),
        [a, speed, side, height, degrees] => {
            (tipped(a, speed, side, height), Some(elevation_of(degrees)?))
        }
        _ => {
            return Err("expected ANGLE_DEG:SPEED, ANGLE_DEG:SPEED:SIDE:HEIGHT or \
                 ANGLE_DEG:SPEED:SIDE:HEIGHT:ELEVATION_DEG"
                .into());
        }
    };
    let shot = Shot {
        elevation: elevation.unwrap_or(0.0),
        ..shot
    };
    limits::check_shot(&shot).map_err(|e| e.to_string())?;
    Ok(ShotArg { shot, elevation })
}

pub(crate) fn parse_pocket(s: &str) -> Result<Pocket, String> {
    Pocket::ALL
        .into_iter()
        .find(|&p| pocket_arg(p) == s)
        .ok_or_else(|| format!("{s:?}: expected one of head-left, head-right, side-left, side-right, foot-left, foot-right"))
}

pub(crate) fn pocket_arg(p: Pocket) -> &'static str {
    match p {
        Pocket::HeadLeft => "head-left",
        Pocket::HeadRight => "head-right",
        Pocket::SideLeft => "side-left",
        Pocket::SideRight => "side-right",
        Pocket::FootLeft => "foot-left",
        Pocket::FootRight => "foot-right",
    }
}

pub(crate) fn parse_call(s: &str) -> Result<(usize, Call), String> {
    let parts: Vec<&str> = s.split(':').collect();
    let shot = |k: &str| k.parse::<usize>().map_err(|e| format!("shot {k:?}: {e}"));
    match parts[..] {
        [k, "safety"] => Ok((shot(k)?, Call::Safety)),
        [k, "push-out"] => Ok((shot(k)?, Call::PushOut)),
        [k, ball, pocket] => Ok((
            shot(k)?,
            Call::Ball {
                ball: ball.parse().map_err(|e| format!("ball {ball:?}: {e}"))?,
                pocket: parse_pocket(pocket)?,
            },
        )),
        _ => Err("expected K:BALL:POCKET, K:safety or K:push-out".into()),
    }
}

pub(crate) fn parse_choice(s: &str) -> Result<Choice, String> {
    match s {
        "shoot" => Ok(Choice::ShootFromHere),
        "pass" => Ok(Choice::PassBack),
        "spot-eight" => Ok(Choice::SpotEightAndShoot),
        _ => Err(format!("{s:?}: expected shoot, pass or spot-eight")),
    }
}

pub(crate) fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or("expected WIDTHxHEIGHT")?;
    Ok((
        w.parse().map_err(|e| format!("width: {e}"))?,
        h.parse().map_err(|e| format!("height: {e}"))?,
    ))
}

/// `simulate` options.
#[derive(clap::Args, Debug)]
pub struct SimulateArgs {
    /// A scene file (JSON, see crates/physics/README.md); its shots are played first.
    #[arg(long, conflicts_with = "rack")]
    pub scene: Option<PathBuf>,
    /// A standard rack on the table of `--table`.
    #[arg(long, value_enum, default_value = "fifteen-ball")]
    pub rack: RackArg,
    /// The table: `7ft`, `8ft` or `9ft` (WPA playing areas 78 x 39, 92 x 46, 100 x 50 in),
    /// optionally `-wide` (4.625 in corner, 5.125 in side mouths) or `-tight` (4 in corner)
    /// pockets instead of the WPA 4.5 in and 5 in; saved in the recording.
    #[arg(long, default_value = "8ft", conflicts_with = "scene")]
    pub table: TableChoice,
    /// How a game's rack is racked: `template` (every ball frozen) or `triangle` (the small
    /// seeded gaps of a hand-racked triangle).
    #[arg(long, default_value = "triangle", requires = "game")]
    pub rack_style: billiards_rules::RackStyle,
    /// The physics model (with a rack).
    #[arg(long, value_enum, default_value = "spin")]
    pub model: ModelArg,
    /// Ball–ball friction (spin model; overrides a scene file's).
    #[arg(long, value_enum)]
    pub ball_friction: Option<BallFrictionArg>,
    /// Cushion model with its published constants (spin model; overrides a scene file's).
    #[arg(long, value_enum)]
    pub cushion: Option<CushionArg>,
    /// Effective end mass of the shaft in kg, for squirt (spin model; TP A-31): about 0.008
    /// for a standard shaft, 0.004 for a low-deflection one. Without it, no squirt.
    #[arg(long, value_parser = parse_end_mass)]
    pub end_mass: Option<f64>,
    /// A shot of the cue ball, `ANGLE_DEG:SPEED[:SIDE:HEIGHT[:ELEVATION_DEG]]`; repeat for
    /// several shots, each played once everything rests. SPEED in m/s: 0 or from 1e-10 to 100
    /// (a hard break is 12); ANGLE_DEG any finite; SIDE and HEIGHT in ball radii, within the
    /// miscue limit; ELEVATION_DEG the cue's, from 0 to 85 (default `--elevation`): steep and
    /// hard, the cue ball jumps (spin model; the summary lists its flight).
    #[arg(long = "shot", value_parser = parse_shot)]
    pub shots: Vec<ShotArg>,
    /// Cue elevation in degrees for every `--shot` without its own and every batch break, from
    /// 0 (level, the default) to 85; with side english the cue ball swerves towards it, steep
    /// and hard it jumps (spin model). A scene file's shots keep their own `elevation`
    /// (radians).
    #[arg(long, value_parser = parse_elevation, default_value = "0")]
    pub elevation: f64,
    /// Seed of the collision-normal randomization (off if absent).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Write the recording here (rewritten atomically after every shot).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
    /// Batch mode: play this many random break shots from the start position, in parallel,
    /// and report the best (most balls pocketed).
    #[arg(long)]
    pub batch: Option<usize>,
    /// Worker threads for batch mode (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Play a game under its rules: its seeded rack (not `--rack`), every shot judged, the
    /// verdicts printed and, with `--out`, logged beside the recording (`NAME.game.json`).
    #[arg(long, value_enum, conflicts_with_all = ["scene", "batch"])]
    pub game: Option<GameArg>,
    /// Seed of the game's rack (default: `--seed`, else 0).
    #[arg(long, requires = "game")]
    pub rack_seed: Option<u64>,
    /// The two players' names, `NAME,NAME`; the first breaks.
    #[arg(long, default_value = "A,B", requires = "game")]
    pub players: String,
    /// A call for shot K: `K:BALL:POCKET` (8-ball, 10-ball; pockets head-left, head-right,
    /// side-left, side-right, foot-left, foot-right), `K:safety` (8-ball, 10-ball) or
    /// `K:push-out` (9-ball, 10-ball).
    #[arg(long = "call", value_parser = parse_call, requires = "game")]
    pub calls: Vec<(usize, Call)>,
    /// Choices to take when the rules offer some, in order: `shoot`, `pass`, `spot-eight`
    /// (default: the first offered). Re-racks are not supported here (one rack a recording).
    #[arg(long = "choice", value_parser = parse_choice, requires = "game")]
    pub choices: Vec<Choice>,
    /// Without `--shot`: the computer players of the game, `A,B` (easy, medium, hard, expert,
    /// perfect; greedy and one-ply at pool's games; default hard,hard); its draws come from
    /// `--rack-seed`.
    #[arg(long, requires = "game")]
    pub computer: Option<String>,
}

/// `tournament` options.
#[derive(clap::Args, Debug)]
pub struct TournamentArgs {
    /// The game: nine-ball, ten-ball, eight-ball, snooker, three-cushion (snooker's and
    /// carom's players are computer levels only).
    #[arg(long, value_enum, default_value = "nine-ball")]
    pub game: GameArg,
    /// The two players, `A,B`: easy, medium, hard, expert, perfect, greedy or one-ply. A
    /// breaks the even games.
    #[arg(long, default_value = "hard,easy")]
    pub players: String,
    /// Games in the whole tournament (every shard counts the same).
    #[arg(long, default_value_t = 200)]
    pub games: u64,
    /// Seed of the whole tournament: game `g`'s rack and draws come from it and `g`.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Play only slice K of M (`K/M`, 1 <= K <= M).
    #[arg(long, value_parser = parse_shard, conflicts_with = "merge")]
    pub shard: Option<Shard>,
    /// Combine these results files (written by `--out`) instead of playing.
    #[arg(long, num_args = 1..)]
    pub merge: Vec<PathBuf>,
    /// Write the results as JSON here.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// The table: `7ft`, `8ft` or `9ft`, optionally `-wide` or `-tight` pockets.
    #[arg(long, default_value = "8ft")]
    pub table: billiards_physics::TableChoice,
    /// How the racks are racked: `template` (frozen) or `triangle` (small seeded gaps).
    #[arg(long, default_value = "triangle")]
    pub rack_style: billiards_rules::RackStyle,
    /// Each match's length in the game's unit (racks to win, frames best of, points); default
    /// one game: a rack, a frame, a carom game of 40 points (the UMB distance).
    #[arg(long)]
    pub length: Option<u32>,
}
