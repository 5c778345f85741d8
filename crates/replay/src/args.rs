//! Argument types and parsers the subcommands share (racks, games, models, shots, calls,
//! pockets, sizes): here, not in the dispatcher (`cli.rs`), so every arrow points one way.

use billiards_physics::*;
use billiards_rules::{Call, Choice, Game};
use clap::ValueEnum;

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
    /// 8-ball, WPA rules.
    EightBall,
    /// The sandbox: no fouls, a scratch respots the cue ball.
    FreePlay,
    /// Snooker, WPBSA rules, on the 12-ft table, between two computer levels.
    Snooker,
}

impl GameArg {
    /// The pool game (`None`: snooker, which has an API of its own).
    pub fn pool(self) -> Option<Game> {
        match self {
            GameArg::NineBall => Some(Game::NineBall),
            GameArg::EightBall => Some(Game::EightBall),
            GameArg::FreePlay => Some(Game::FreePlay),
            GameArg::Snooker => None,
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

/// Degrees on the command line, radians in the shot.
pub(crate) fn parse_elevation(s: &str) -> Result<f64, String> {
    let degrees = s.trim().parse::<f64>().map_err(|e| format!("{s:?}: {e}"))?;
    let shot = Shot {
        elevation: degrees.to_radians(),
        ..Shot::new(0.0, 0.0)
    };
    limits::check_shot(&shot).map_err(|_| format!("elevation {s:?}: from 0 to 30 degrees"))?;
    Ok(shot.elevation)
}

pub(crate) fn parse_shot(s: &str) -> Result<Shot, String> {
    let v: Vec<f64> = s
        .split(':')
        .map(|x| x.trim().parse::<f64>().map_err(|e| format!("{x:?}: {e}")))
        .collect::<Result<_, _>>()?;
    let shot = match v[..] {
        [a, speed] => Shot::new(a.to_radians(), speed),
        [a, speed, side, height] => Shot {
            tip: TipOffset { side, height },
            ..Shot::new(a.to_radians(), speed)
        },
        _ => return Err("expected ANGLE_DEG:SPEED or ANGLE_DEG:SPEED:SIDE:HEIGHT".into()),
    };
    limits::check_shot(&shot).map_err(|e| e.to_string())?;
    Ok(shot)
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
