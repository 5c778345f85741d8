//! The command line: `simulate`, `verify`, `export` (and `replay`, which the game binary
//! handles). Errors go to stderr with a non-zero exit code.

use crate::export::{self, ExportOptions};
use billiards_physics::recording::{Recorder, Recording, Verdict};
use billiards_physics::scene::Scene;
use billiards_physics::*;
use billiards_rules::{Call, Choice, Game, Shots, Verdict as RulesVerdict};
use clap::{Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use rand::{Rng, SeedableRng};
use serde::Serialize;
use std::path::PathBuf;
use std::process::ExitCode;

/// Billiards: exact event-driven pool physics, headless tools.
#[derive(Parser, Debug)]
#[command(name = "billiards", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Simulate shots from a rack or a scene file; write a recording and print a summary.
    Simulate(SimulateArgs),
    /// Re-simulate a recording and check it reproduces its history bit for bit.
    Verify {
        /// The recording.
        file: PathBuf,
    },
    /// Export a recording (or one shot of it) as an animated GIF or a PNG sequence.
    Export(ExportArgs),
    /// Whole racks between two computer players on all cores: win rates and figures.
    Tournament(crate::tournament::TournamentArgs),
    /// The break study: breaks per game, table, rack, speed and cue position, judged by the
    /// rules; sharded (`--shard K/M`, `--merge`).
    Breaks(crate::breaks::BreaksArgs),
    /// The physics soak: seeded random scenes with every event checked; sharded.
    Soak(crate::soak::SoakArgs),
    /// The stress table: up to 10,000 seeded balls on a larger table, run in 60 Hz frames:
    /// events, events a second, the solver's cost per frame, energy and overlap checks.
    Stress(crate::stress::StressArgs),
    /// The success probability of one shot from every cell of a grid of cue-ball places,
    /// under a player's execution noise, with an SVG heat map; sharded.
    Study(crate::study::StudyArgs),
    /// Open the game on a recording (needs the game binary: `billiards replay FILE`).
    Replay {
        /// The recording.
        file: PathBuf,
    },
}

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
    /// A shot of the cue ball, `ANGLE_DEG:SPEED[:SIDE:HEIGHT]`; repeat for several shots,
    /// each played once everything rests. SPEED in m/s: 0 or from 1e-10 to 100 (a hard break
    /// is 12); ANGLE_DEG any finite; SIDE and HEIGHT in ball radii, within the miscue limit.
    #[arg(long = "shot", value_parser = parse_shot)]
    pub shots: Vec<Shot>,
    /// Cue elevation in degrees for every `--shot` and batch break, from 0 (level, the
    /// default) to 30; with side english the cue ball swerves towards it (spin model). A
    /// scene file's shots keep their own `elevation` (radians).
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
    /// A call for shot K: `K:BALL:POCKET` (8-ball; pockets head-left, head-right, side-left,
    /// side-right, foot-left, foot-right), `K:safety` (8-ball) or `K:push-out` (9-ball).
    #[arg(long = "call", value_parser = parse_call, requires = "game")]
    pub calls: Vec<(usize, Call)>,
    /// Choices to take when the rules offer some, in order: `shoot`, `pass`, `spot-eight`
    /// (default: the first offered). Re-racks are not supported here (one rack a recording).
    #[arg(long = "choice", value_parser = parse_choice, requires = "game")]
    pub choices: Vec<Choice>,
    /// Snooker: the computer levels of the two players, `A,B` (easy, medium, hard, expert,
    /// perfect); the frame's draws come from `--rack-seed`.
    #[arg(long, default_value = "hard,hard", requires = "game")]
    pub computer: String,
}

/// `export` options.
#[derive(clap::Args, Debug)]
pub struct ExportArgs {
    /// The recording.
    pub file: PathBuf,
    /// Write an animated GIF here.
    #[arg(long)]
    pub gif: Option<PathBuf>,
    /// Write a numbered PNG sequence into this folder.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write a video here: MP4, or WebM for a `.webm` name (needs `ffmpeg` on the PATH).
    #[arg(long)]
    pub video: Option<PathBuf>,
    /// Frames per second of simulated time.
    #[arg(long, default_value_t = 30.0)]
    pub fps: f64,
    /// Frame size, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "640x360", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Export only this shot, counted from 1 as in the game's timeline; default the whole game.
    #[arg(long)]
    pub shot: Option<usize>,
}

fn parse_end_mass(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(kg) if kg.is_finite() && kg > 0.0 && kg < 1.0 => Ok(kg),
        _ => Err(format!(
            "end mass {s:?}: a positive mass in kg below 1 (e.g. 0.008)"
        )),
    }
}

/// Degrees on the command line, radians in the shot.
fn parse_elevation(s: &str) -> Result<f64, String> {
    let degrees = s.trim().parse::<f64>().map_err(|e| format!("{s:?}: {e}"))?;
    let shot = Shot {
        elevation: degrees.to_radians(),
        ..Shot::new(0.0, 0.0)
    };
    limits::check_shot(&shot).map_err(|_| format!("elevation {s:?}: from 0 to 30 degrees"))?;
    Ok(shot.elevation)
}

/// The command line's shots, at the cue elevation of `--elevation`.
fn command_line_shots(a: &SimulateArgs) -> impl Iterator<Item = Shot> + '_ {
    a.shots.iter().map(|s| Shot {
        elevation: a.elevation,
        ..*s
    })
}

fn parse_shot(s: &str) -> Result<Shot, String> {
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

fn parse_call(s: &str) -> Result<(usize, Call), String> {
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

fn parse_choice(s: &str) -> Result<Choice, String> {
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

/// One shot's outcome.
#[derive(Serialize, Debug)]
pub struct ShotSummary {
    /// The shot.
    pub shot: Shot,
    /// Events it produced.
    pub events: usize,
    /// Numbers of the balls it pocketed.
    pub pocketed: Vec<u8>,
    /// Seconds of simulated time until everything rested.
    pub time_to_rest: f64,
    /// The rules' verdict (with `--game`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verdict: Option<RulesVerdict>,
}

/// Runs the command line; returns the process exit code.
pub fn run(cli: Cli) -> ExitCode {
    let result = match cli.command {
        Command::Simulate(a) => simulate(a),
        Command::Verify { file } => verify(&file),
        Command::Export(a) => export_cmd(a),
        Command::Tournament(a) => return crate::tournament::run(a),
        Command::Breaks(a) => return crate::breaks::run(a),
        Command::Soak(a) => return crate::soak::run(a),
        Command::Stress(a) => return crate::stress::run(a),
        Command::Study(a) => return crate::study::run(a),
        Command::Replay { file } => Err(format!(
            "{}: replay opens the game: run `billiards replay {}`",
            file.display(),
            file.display()
        )),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

pub(crate) fn setup(
    a: &SimulateArgs,
) -> Result<(Table, Params, Vec<BallSetup>, Vec<Shot>), String> {
    let randomization = a.seed.map(|seed| Randomization {
        spread: 0.005,
        seed,
    });
    if let Some(path) = &a.scene {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let scene = Scene::from_json(&text).map_err(|e| format!("{}: {e}", path.display()))?;
        let params = with_choices(
            Params {
                randomization: randomization.or(scene.params.randomization),
                ..scene.params
            },
            a,
        )?;
        let shots = scene
            .shots
            .iter()
            .map(|s| s.shot)
            .chain(command_line_shots(a))
            .collect();
        return Ok((scene.table, params, scene.balls(), shots));
    }
    let model = match a.model {
        ModelArg::Paper => Model::Paper(PaperModel::default()),
        ModelArg::Spin => Model::Spin(SpinModel::default()),
    };
    let table = match a.model {
        ModelArg::Paper => a.table.table(),
        ModelArg::Spin => a.table.table().with_jaws(0.015),
    };
    let params = with_choices(
        Params {
            model,
            randomization,
            ..Params::default()
        },
        a,
    )?;
    let rack = match a.rack {
        RackArg::PaperDefault => Rack::PaperDefault,
        RackArg::FifteenBall => Rack::FifteenBall,
        RackArg::Tight => Rack::Tight,
        RackArg::NineBall => Rack::NineBall,
    };
    Ok((
        table,
        params,
        rack.layout(&table, &params.ball),
        command_line_shots(a).collect(),
    ))
}

/// `params` with the model choices of the command line applied: they need the spin model.
fn with_choices(params: Params, a: &SimulateArgs) -> Result<Params, String> {
    if a.ball_friction.is_none() && a.cushion.is_none() && a.end_mass.is_none() {
        return Ok(params);
    }
    let Model::Spin(mut m) = params.model else {
        return Err(
            "--ball-friction, --cushion and --end-mass need the spin model (--model spin)".into(),
        );
    };
    if let Some(kg) = a.end_mass {
        m.end_mass = Some(kg);
    }
    if let Some(friction) = a.ball_friction {
        m.ball_friction = match friction {
            BallFrictionArg::Constant => BallFriction::Constant,
            BallFrictionArg::SpeedDependent => BallFriction::ALCIATORE,
        };
    }
    if let Some(cushion) = a.cushion {
        m.cushion = match cushion {
            CushionArg::Han2005 => CushionModel::default(),
            CushionArg::Mathavan2010 => CushionModel::MATHAVAN_2010,
            CushionArg::Reflect => CushionModel::Reflect { e: 0.85 },
        };
    }
    Ok(Params {
        model: Model::Spin(m),
        ..params
    })
}

/// After a scratch the cue ball goes back on the head string: the rule of
/// [`billiards_rules::respot`], the same as the game's.
pub(crate) fn respot_cue_ball(rec: &mut Recorder) -> Result<(), String> {
    if rec.sim().ball(0).motion.on_table() {
        return Ok(());
    }
    let spot = billiards_rules::cue_ball_spot(rec.sim(), 0)
        .ok_or("no free place on the head string for the cue ball")?;
    rec.place(0, spot, Vec2::ZERO, Vec3::ZERO)
        .map_err(|e| e.to_string())
}

fn play(rec: &mut Recorder, shot: Shot) -> Result<ShotSummary, String> {
    respot_cue_ball(rec)?;
    let start = rec.sim().time();
    let first = rec.sim().history().events().len();
    rec.strike(0, shot).map_err(|e| e.to_string())?;
    rec.run_to_rest().map_err(|e| e.to_string())?;
    let sim = rec.sim();
    let events = &sim.history().events()[first..];
    let pocketed = events
        .iter()
        .filter_map(|e| match e.kind {
            EventKind::Pocketed { ball, .. } => Some(sim.numbers()[ball]),
            _ => None,
        })
        .collect();
    Ok(ShotSummary {
        shot,
        events: events.len(),
        pocketed,
        time_to_rest: sim.time() - start,
        verdict: None,
    })
}

fn simulate(a: SimulateArgs) -> Result<(), String> {
    if let Some(game) = a.game {
        return match game.pool() {
            Some(game) => crate::game::play_game(&a, game),
            None => crate::snooker::simulate(&a),
        };
    }
    let (table, params, balls, shots) = setup(&a)?;
    if let Some(n) = a.batch {
        return batch(table, params, balls, n, &a);
    }
    if shots.is_empty() {
        return Err(
            "no shots: give --shot ANGLE_DEG:SPEED (or a scene with shots), or --batch N".into(),
        );
    }
    let mut rec = Recorder::new(table, params, balls).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    // Shots count from 1, as in the game and `export --shot K` (billiards_rules::shots).
    for (k, shot) in (1..).zip(shots) {
        let s = play(&mut rec, shot).map_err(|e| format!("shot {k}: {e}"))?;
        out.push(s);
        if let Some(path) = &a.out {
            // After every shot: a crash loses at most the shot in flight.
            rec.recording().save(path).map_err(|e| e.to_string())?;
        }
    }
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&out).map_err(|e| e.to_string())?
        );
    } else {
        for (k, s) in (1..).zip(&out) {
            println!(
                "shot {k}: {} events, pocketed {:?}, rest after {:.3} s",
                s.events, s.pocketed, s.time_to_rest
            );
        }
    }
    Ok(())
}

fn batch(
    table: Table,
    params: Params,
    balls: Vec<BallSetup>,
    n: usize,
    a: &SimulateArgs,
) -> Result<(), String> {
    let threads = a
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(a.seed.unwrap_or(0));
    let shots: Vec<Shot> = (0..n)
        .map(|_| Shot {
            elevation: a.elevation,
            ..Shot::new(rng.random_range(-0.3..0.3), rng.random_range(4.0..11.0))
        })
        .collect();
    let bar = ProgressBar::new(n as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} shots {eta}").expect("template"),
    );
    let start = Recorder::new(table, params, balls).map_err(|e| e.to_string())?;
    let chunk = n.div_ceil(threads).max(1);
    let results: Vec<Result<ShotSummary, String>> = std::thread::scope(|s| {
        let handles: Vec<_> = shots
            .chunks(chunk)
            .map(|part| {
                let (bar, start) = (&bar, &start);
                s.spawn(move || {
                    part.iter()
                        .map(|&shot| {
                            let r = play(&mut start.clone(), shot);
                            bar.inc(1);
                            r
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("worker"))
            .collect()
    });
    bar.finish_and_clear();
    let ok: Vec<ShotSummary> = results.into_iter().collect::<Result<_, _>>()?;
    let best = ok
        .iter()
        .max_by_key(|s| s.pocketed.len())
        .ok_or("no shots")?;
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&serde_json::json!({ "shots": ok, "best": best }))
                .map_err(|e| e.to_string())?
        );
    } else {
        let events: usize = ok.iter().map(|s| s.events).sum();
        println!(
            "{n} shots, {events} events; best: angle {:.4} rad, speed {:.2} m/s pocketed {:?}",
            best.shot.angle, best.shot.speed, best.pocketed
        );
    }
    Ok(())
}

fn verify(file: &std::path::Path) -> Result<(), String> {
    let rec = Recording::load(file).map_err(|e| e.to_string())?;
    match rec
        .verify()
        .map_err(|e| format!("{}: {e}", file.display()))?
    {
        Verdict::Reproduced { events } => {
            println!(
                "{}: reproduced bit for bit ({events} events)",
                file.display()
            );
            // The rules' log, when the game was played under rules (kept beside the file).
            crate::game::check_log(file, &rec)?;
            crate::snooker::check_log(file, &rec)
        }
        Verdict::Differs {
            index,
            recorded,
            replayed,
        } => Err(format!(
            "{}: differs at event {index}:\n  recorded: {recorded:?}\n  replayed: {replayed:?}",
            file.display()
        )),
    }
}

fn export_cmd(a: ExportArgs) -> Result<(), String> {
    let rec = Recording::load(&a.file).map_err(|e| e.to_string())?;
    let shots = Shots::of(&rec);
    let span = match a.shot {
        Some(k) => shots.span(k).ok_or_else(|| {
            format!(
                "{}: there is no shot {k} (shots count from 1; this recording has {})",
                a.file.display(),
                shots.len()
            )
        })?,
        None => shots.whole(),
    };
    let opts = ExportOptions {
        fps: a.fps,
        width: a.size.0,
        height: a.size.1,
        span,
    };
    if a.gif.is_none() && a.png.is_none() && a.video.is_none() {
        return Err("nothing to export: give --gif FILE, --png DIR and/or --video FILE".into());
    }
    let bar = ProgressBar::new(0);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} frames").expect("template"));
    let mut progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
        std::ops::ControlFlow::Continue(())
    };
    if let Some(out) = &a.gif {
        let n = export::gif(&rec, &opts, out, &mut progress).map_err(|e| e.to_string())?;
        bar.finish_and_clear();
        println!("{}: {n} frames", out.display());
    }
    if let Some(dir) = &a.png {
        let n = export::png_sequence(&rec, &opts, dir, &mut progress).map_err(|e| e.to_string())?;
        bar.finish_and_clear();
        println!("{}: {n} frames", dir.display());
    }
    if let Some(out) = &a.video {
        let n = export::video(&rec, &opts, out, &mut progress).map_err(|e| e.to_string())?;
        bar.finish_and_clear();
        println!("{}: {n} frames", out.display());
    }
    Ok(())
}
