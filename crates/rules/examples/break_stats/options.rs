//! The example's command-line options (the module documentation of `main.rs` lists them).

use billiards_physics::{CushionModel, TableChoice};
use billiards_rules::breaks::{Cue, GAME_CUSHION, SETTABLE, cushion_by_name};
use billiards_rules::{Game, RackStyle};

/// The options of one run.
#[derive(Clone, Debug)]
pub struct Options {
    /// Breaks a row (per seed).
    pub breaks: usize,
    /// The first seed.
    pub seed: u64,
    /// The games, a block of rows each.
    pub games: Vec<Game>,
    /// The table (default: the game's own).
    pub table: Option<TableChoice>,
    /// The rack style.
    pub rack: RackStyle,
    /// Rack lattice slacks, metres, one row each (instead of the rack style's).
    pub gaps: Option<Vec<f64>>,
    /// Cue ball speed range, m/s (uniform).
    pub speed: (f64, f64),
    /// Where the cue ball starts.
    pub cue: Cue,
    /// Every contact pair by pair (no cluster impacts).
    pub pairwise: bool,
    /// Run the standard comparison.
    pub suite: bool,
    /// Changes to the game's physics, for sensitivity: (name, value).
    pub set: Vec<(String, f64)>,
    /// Tip height as a fraction of the radius (0: centre ball, negative: draw).
    pub tip_height: f64,
    /// Standard deviation of a Gaussian error of the aim, radians (0: exactly at the ball).
    pub aim_sd: f64,
    /// The cushion model (default: the game's, Mathavan 2010).
    pub cushion: CushionModel,
    /// Cue elevation, radians.
    pub elevation: f64,
    /// 9-ball: the 9 on the foot spot instead of the 1.
    pub nine_on_spot: bool,
    /// Random streams a row (seeds `seed`, `seed + 1`, ...), `breaks` each.
    pub seeds: u64,
    /// Print the sensitivity study (one change at a time from these options).
    pub study: bool,
    /// Write the study's plot here (SVG).
    pub svg: Option<String>,
}

impl Default for Options {
    /// The defaults the module documentation lists.
    fn default() -> Self {
        Options {
            breaks: 1000,
            seed: 1,
            games: vec![Game::NineBall, Game::EightBall],
            table: None,
            rack: RackStyle::Triangle,
            gaps: None,
            speed: (10.0, 12.0),
            cue: Cue::Box,
            pairwise: false,
            suite: false,
            set: Vec::new(),
            tip_height: 0.0,
            aim_sd: 0.0,
            cushion: GAME_CUSHION,
            elevation: 0.0,
            nine_on_spot: false,
            seeds: 1,
            study: false,
            svg: None,
        }
    }
}

/// The options of the command line, from the defaults.
pub fn options() -> Result<Options, String> {
    let mut o = Options::default();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        match flag.as_str() {
            "--pairwise" => {
                o.pairwise = true;
                continue;
            }
            "--suite" => {
                o.suite = true;
                continue;
            }
            "--study" => {
                o.study = true;
                continue;
            }
            "--nine-on-spot" => {
                o.nine_on_spot = true;
                continue;
            }
            _ => {}
        }
        let value = it.next().ok_or(format!("{flag} needs a value"))?;
        let bad = |e: &dyn std::fmt::Display| format!("{flag} {value}: {e}");
        match flag.as_str() {
            "--breaks" => o.breaks = value.parse().map_err(|e| bad(&e))?,
            "--seed" => o.seed = value.parse().map_err(|e| bad(&e))?,
            "--game" => {
                o.games = match value.as_str() {
                    "nine" | "nine-ball" => vec![Game::NineBall],
                    "ten" | "ten-ball" => vec![Game::TenBall],
                    "eight" | "eight-ball" => vec![Game::EightBall],
                    "both" => vec![Game::NineBall, Game::EightBall],
                    _ => return Err(bad(&"expected nine, ten, eight or both")),
                }
            }
            "--table" => o.table = Some(value.parse().map_err(|e: String| bad(&e))?),
            "--rack" => o.rack = value.parse().map_err(|e: String| bad(&e))?,
            "--gaps-mm" => {
                let gaps: Result<Vec<f64>, _> =
                    value.split(',').map(|g| g.trim().parse::<f64>()).collect();
                let gaps = gaps.map_err(|e| bad(&e))?;
                if gaps.iter().any(|g| !(0.0..=10.0).contains(g)) {
                    return Err(bad(&"gaps in [0, 10] mm"));
                }
                o.gaps = Some(gaps.into_iter().map(|g| g * 1e-3).collect());
            }
            "--speed" => {
                let (a, b) = value.split_once(':').ok_or(bad(&"expected MIN:MAX"))?;
                let (a, b): (f64, f64) = (
                    a.parse().map_err(|e| bad(&e))?,
                    b.parse().map_err(|e| bad(&e))?,
                );
                if !(0.0 < a && a <= b && b <= 100.0) {
                    return Err(bad(&"expected 0 < MIN <= MAX <= 100 m/s"));
                }
                o.speed = (a, b);
            }
            "--cue" => o.cue = value.parse().map_err(|e: String| bad(&e))?,
            "--set" => {
                let (k, v) = value.split_once('=').ok_or(bad(&"expected NAME=VALUE"))?;
                if !SETTABLE.contains(&k) {
                    return Err(bad(&format!("NAME is one of {SETTABLE:?}")));
                }
                o.set.push((k.into(), v.parse().map_err(|e| bad(&e))?));
            }
            "--cushion" => o.cushion = cushion_by_name(value).map_err(|e| bad(&e))?,
            "--elevation-deg" => {
                let d: f64 = value.parse().map_err(|e| bad(&e))?;
                if !(0.0..=30.0).contains(&d) {
                    return Err(bad(&"expected 0 to 30 degrees"));
                }
                o.elevation = d.to_radians();
            }
            "--seeds" => o.seeds = value.parse().map_err(|e| bad(&e))?,
            "--svg" => o.svg = Some(value.clone()),
            "--tip-height" => o.tip_height = value.parse().map_err(|e| bad(&e))?,
            "--aim-sd-deg" => {
                let d: f64 = value.parse().map_err(|e| bad(&e))?;
                if !(0.0..=10.0).contains(&d) {
                    return Err(bad(&"expected 0 to 10 degrees"));
                }
                o.aim_sd = d.to_radians();
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(o)
}
