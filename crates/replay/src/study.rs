//! `study`: the success probability of one shot (a ball into a pocket) from every cell of a
//! grid of cue-ball positions, under a player's execution noise: the hint's number, mapped.
//!
//! In each cell the cue ball stands at the cell's centre; the shot is the computer's own
//! candidate for that ball and pocket ([`billiards_ai::candidates::direct_aims`]: the ghost
//! ball, its speed, or `--speed`), its aim corrected for throw and spin as the search does
//! ([`billiards_ai::evaluate::Search::correct_aim`]), then struck `--samples` times with the
//! player's execution noise ([`billiards_ai::Noise`]) in the solver's lean mode. A sample
//! succeeds when the cue ball hits the ball first, the ball drops in the pocket and the cue
//! ball stays up. Cell `i` (row by row from the head-right corner) draws sample `k` from the
//! stream `(seed, i, k)`, so the cells split into shards ([`crate::shard`]) and merge to
//! one process's result exactly. `--svg` draws the map.

use crate::shard::{Batch, Shard, parse_shard};
use billiards_ai::candidates::{Candidate, Layout, direct_aims};
use billiards_ai::evaluate::{Mode, Search};
use billiards_ai::noise::stream;
use billiards_ai::position::aim_probability;
use billiards_ai::{Noise, Player, ShotKind};
use billiards_physics::{
    BallSetup, Pocket, Shot, Simulation, Table, TableChoice, TipOffset, Vec2, table::INCH,
};
use billiards_rules::{Call, Game, GameState, Seat, ShotSummary};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Most events one sample may take (a pot takes 10 to 50).
const MAX_EVENTS: usize = 2000;

/// `study` options.
#[derive(clap::Args, Debug)]
pub struct StudyArgs {
    /// The table: `7ft`, `8ft` or `9ft`, optionally `-wide` or `-tight` pockets.
    #[arg(long, default_value = "8ft")]
    pub table: TableChoice,
    /// An object ball, `NUMBER:X:Y` in metres from the table's centre (x towards the foot,
    /// y towards the left); repeatable. Default: the 1 at 0.6:0.3.
    #[arg(long = "ball", value_parser = parse_ball)]
    pub balls: Vec<(u8, f64, f64)>,
    /// The ball to pot (default: the first `--ball`).
    #[arg(long)]
    pub target: Option<u8>,
    /// The pocket: head-left, head-right, side-left, side-right, foot-left, foot-right.
    #[arg(long, value_parser = crate::args::parse_pocket, default_value = "foot-left")]
    pub pocket: Pocket,
    /// The player whose execution noise the shot is struck with: easy, medium, hard,
    /// expert, perfect, greedy or one-ply.
    #[arg(long, default_value = "hard")]
    pub player: Player,
    /// Cue speed in m/s (default: the computer's speed for the shot from each cell).
    #[arg(long)]
    pub speed: Option<f64>,
    /// Tip offset `SIDE:HEIGHT` in ball radii.
    #[arg(long, value_parser = parse_tip, default_value = "0:0", allow_hyphen_values = true)]
    pub tip: TipOffset,
    /// Noisy samples per cell.
    #[arg(long, default_value_t = 100)]
    pub samples: u64,
    /// Cells along the table and across it, `NXxNY`.
    #[arg(long, value_parser = crate::args::parse_size, default_value = "32x16")]
    pub grid: (u32, u32),
    /// Seed of the noise.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Draw the heat map as SVG here.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Run only slice K of M (`K/M`) of the cells.
    #[arg(long, value_parser = parse_shard, conflicts_with = "merge")]
    pub shard: Option<Shard>,
    /// Combine these shard files (written by `--out`) instead of running.
    #[arg(long, num_args = 1..)]
    pub merge: Vec<PathBuf>,
    /// Write the result as JSON here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

fn parse_ball(s: &str) -> Result<(u8, f64, f64), String> {
    let bad = || format!("{s:?}: expected NUMBER:X:Y (metres from the centre)");
    let v: Vec<&str> = s.split(':').collect();
    let [n, x, y] = v[..] else { return Err(bad()) };
    let n: u8 = n.trim().parse().map_err(|_| bad())?;
    let (x, y): (f64, f64) = (
        x.trim().parse().map_err(|_| bad())?,
        y.trim().parse().map_err(|_| bad())?,
    );
    if n == 0 || n > 15 || !x.is_finite() || !y.is_finite() {
        return Err(format!("{s:?}: a ball from 1 to 15 at a finite place"));
    }
    Ok((n, x, y))
}

fn parse_tip(s: &str) -> Result<TipOffset, String> {
    let (a, b) = s
        .split_once(':')
        .ok_or_else(|| format!("{s:?}: expected SIDE:HEIGHT"))?;
    Ok(TipOffset {
        side: a.trim().parse().map_err(|e| format!("{s:?}: {e}"))?,
        height: b.trim().parse().map_err(|e| format!("{s:?}: {e}"))?,
    })
}

/// What a cell holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CellState {
    /// The shot was sampled.
    Sampled,
    /// The cue ball does not fit there (a ball or a cushion is in the way).
    NoRoom,
    /// No straight or cut shot of the ball into the pocket from there (blocked, a cut
    /// beyond 80 degrees, or the ball would meet the pocket too steeply).
    NoShot,
}

/// One cell of the grid.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cell {
    /// Its index (row by row, `iy * nx + ix`).
    pub index: u64,
    /// The cue ball's place, metres from the centre.
    pub x: f64,
    /// See `x`.
    pub y: f64,
    /// Whether it was sampled.
    pub state: CellState,
    /// The shot struck before noise (aim corrected), when sampled.
    pub shot: Option<Shot>,
    /// Samples that succeeded.
    pub pots: u64,
    /// Samples run.
    pub samples: u64,
    /// The analytic estimate of the search's position value
    /// ([`billiards_ai::position::aim_probability`]), for comparison.
    pub analytic: f64,
}

impl Cell {
    /// The measured success probability (`None` when not sampled).
    pub fn success(&self) -> Option<f64> {
        (self.state == CellState::Sampled).then(|| self.pots as f64 / self.samples.max(1) as f64)
    }
}

/// A study's result (or one shard's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StudyResult {
    /// `"study"`.
    pub command: String,
    /// The slice of the cells run here; `None`: all of them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
    /// The table.
    pub table: TableChoice,
    /// The object balls: number, x, y.
    pub balls: Vec<(u8, f64, f64)>,
    /// The ball to pot.
    pub target: u8,
    /// Into this pocket.
    pub pocket: Pocket,
    /// Whose noise.
    pub player: Player,
    /// Its magnitude.
    pub noise: Noise,
    /// Fixed cue speed, if any.
    pub speed: Option<f64>,
    /// Tip offset.
    pub tip: TipOffset,
    /// Samples per cell.
    pub samples: u64,
    /// Cells along and across.
    pub grid: (u32, u32),
    /// Seed.
    pub seed: u64,
    /// The cells run, by index.
    pub cells: Vec<Cell>,
}

impl Batch for StudyResult {
    const COMMAND: &'static str = "study";

    fn shard(&self) -> Option<Shard> {
        self.shard
    }

    fn set_shard(&mut self, shard: Option<Shard>) {
        self.shard = shard;
    }

    fn arguments(&self) -> serde_json::Value {
        serde_json::json!({
            "table": self.table,
            "balls": self.balls,
            "target": self.target,
            "pocket": self.pocket,
            "player": self.player,
            "speed": self.speed,
            "tip": self.tip,
            "samples": self.samples,
            "grid": self.grid,
            "seed": self.seed,
        })
    }

    fn check_items(&self) -> Result<(), String> {
        let n = u64::from(self.grid.0) * u64::from(self.grid.1);
        let want: Vec<u64> = crate::shard::items(self.shard.unwrap_or(Shard::WHOLE), n).collect();
        let have: Vec<u64> = self.cells.iter().map(|c| c.index).collect();
        if have != want {
            return Err(format!("{} of its {} cells", have.len(), want.len()));
        }
        if let Some(c) = self
            .cells
            .iter()
            .find(|c| c.state == CellState::Sampled && c.samples != self.samples)
        {
            return Err(format!(
                "cell {} has {} samples, not {}",
                c.index, c.samples, self.samples
            ));
        }
        Ok(())
    }

    fn absorb(&mut self, other: Self) {
        self.cells.extend(other.cells);
    }

    fn finish(&mut self) {
        self.cells.sort_by_key(|c| c.index);
    }
}

/// The setup every cell shares.
struct Setup {
    table: Table,
    params: billiards_physics::Params,
    balls: Vec<(u8, Vec2)>,
    target: u8,
    pocket: Pocket,
    noise: Noise,
    speed: Option<f64>,
    tip: TipOffset,
    samples: u64,
    seed: u64,
    state: GameState,
}

impl Setup {
    /// The cue ball's place in cell `i` of an `nx` by `ny` grid.
    fn place(&self, i: u64, (nx, ny): (u32, u32)) -> Vec2 {
        let b = self.table.centre_bounds(self.params.ball.radius);
        let (ix, iy) = ((i % u64::from(nx)) as f64, (i / u64::from(nx)) as f64);
        Vec2::new(
            -b.x + (ix + 0.5) * 2.0 * b.x / f64::from(nx),
            -b.y + (iy + 0.5) * 2.0 * b.y / f64::from(ny),
        )
    }

    /// Cell `i`: its shot sampled.
    fn cell(&self, i: u64, grid: (u32, u32)) -> Cell {
        let cue = self.place(i, grid);
        let mut cell = Cell {
            index: i,
            x: cue.x,
            y: cue.y,
            state: CellState::NoRoom,
            shot: None,
            pots: 0,
            samples: 0,
            analytic: 0.0,
        };
        let setups: Vec<BallSetup> = std::iter::once(BallSetup::at(0, cue))
            .chain(self.balls.iter().map(|&(n, p)| BallSetup::at(n, p)))
            .collect();
        let Ok(mut base) = Simulation::new(self.table, self.params, &setups) else {
            return cell;
        };
        base.set_record_history(false);
        let layout = Layout {
            table: self.table,
            radius: self.params.ball.radius,
            cue,
            balls: self.balls.clone(),
        };
        let want = ShotKind::Pot {
            ball: self.target,
            pocket: self.pocket,
        };
        let Some(aim) = direct_aims(&layout, &[self.target])
            .into_iter()
            .find(|a| a.kind == want)
        else {
            cell.state = CellState::NoShot;
            return cell;
        };
        cell.analytic = aim_probability(&aim, self.noise);
        let search = Search {
            state: &self.state,
            base,
            cue: 0,
            noise: self.noise,
            seed: self.seed,
            mode: Mode::Lean,
        };
        let cand = search.correct_aim(Candidate {
            kind: want,
            shot: Shot {
                angle: aim.angle,
                speed: self.speed.unwrap_or(aim.speed),
                tip: self.tip,
                elevation: 0.0,
            },
            call: Call::None,
            place: None,
            object: Some((self.target, aim.object_dir)),
        });
        let mut sim = search.base.clone();
        for k in 0..self.samples {
            sim.clone_from(&search.base);
            let shot = self
                .noise
                .apply(cand.shot, &self.params, &mut stream(self.seed, i, k));
            if sim.strike(0, shot).is_ok() && self.pots(&mut sim) {
                cell.pots += 1;
            }
        }
        cell.state = CellState::Sampled;
        cell.shot = Some(cand.shot);
        cell.samples = self.samples;
        cell
    }

    /// Runs a struck shot to rest: whether the target dropped in the pocket, hit first, the
    /// cue ball still up.
    fn pots(&self, sim: &mut Simulation) -> bool {
        let mut summary = ShotSummary::default();
        for _ in 0..MAX_EVENTS {
            let Some(e) = sim.step_event() else { break };
            summary.record(&e.kind, sim.numbers());
            if summary.scratch() || summary.first_contact.is_some_and(|b| b != self.target) {
                return false;
            }
        }
        summary.first_contact == Some(self.target)
            && summary.pocket_of(self.target) == Some(self.pocket)
            && !summary.scratch()
    }
}

/// Runs the cells of shard `part` (`None`: all of them), on all cores.
pub fn study(a: &StudyArgs, part: Option<Shard>) -> Result<StudyResult, String> {
    let shard = part.unwrap_or(Shard::WHOLE);
    let (table, params) = billiards_ai::play::table_and_params_on(a.table);
    let balls = if a.balls.is_empty() {
        vec![(1, 0.6, 0.3)]
    } else {
        a.balls.clone()
    };
    let target = a.target.unwrap_or(balls[0].0);
    if !balls.iter().any(|b| b.0 == target) {
        return Err(format!("--target {target}: no such --ball"));
    }
    if a.grid.0 == 0 || a.grid.1 == 0 || a.samples == 0 {
        return Err("--grid and --samples must not be 0".into());
    }
    if let Some(v) = a.speed
        && !(v > 0.0 && v <= 14.0)
    {
        return Err(format!("--speed {v}: expected 0 < V <= 14 m/s"));
    }
    let object: Vec<(u8, Vec2)> = balls
        .iter()
        .map(|&(n, x, y)| (n, Vec2::new(x, y)))
        .collect();
    // The object balls must fit on the table by themselves.
    let alone: Vec<BallSetup> = object.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
    Simulation::new(table, params, &alone).map_err(|e| format!("--ball: {e}"))?;
    let setup = Setup {
        table,
        params,
        balls: object,
        target,
        pocket: a.pocket,
        noise: a.player.execution_noise(),
        speed: a.speed,
        tip: a.tip,
        samples: a.samples,
        seed: a.seed,
        state: GameState::new(Game::NineBall, Seat::A),
    };
    let n = u64::from(a.grid.0) * u64::from(a.grid.1);
    let cells: Vec<Cell> = crate::shard::items(shard, n)
        .collect::<Vec<_>>()
        .into_par_iter()
        .map(|i| setup.cell(i, a.grid))
        .collect();
    Ok(StudyResult {
        command: StudyResult::COMMAND.into(),
        shard: part,
        table: a.table,
        balls,
        target,
        pocket: a.pocket,
        player: a.player,
        noise: setup.noise,
        speed: a.speed,
        tip: a.tip,
        samples: a.samples,
        grid: a.grid,
        seed: a.seed,
        cells,
    })
}

/// The result in words: the best cells and the mean over the sampled ones.
pub fn report(r: &StudyResult) -> String {
    let sampled: Vec<&Cell> = r
        .cells
        .iter()
        .filter(|c| c.state == CellState::Sampled)
        .collect();
    let mean =
        sampled.iter().filter_map(|c| c.success()).sum::<f64>() / sampled.len().max(1) as f64;
    let mut out = format!(
        "the {} into {} on a {} table, {} noise ({}), {} samples a cell: {} of {} cells \
         sampled, mean success {:.1} %\n",
        r.target,
        crate::args::pocket_arg(r.pocket),
        r.table,
        r.player,
        r.noise.magnitude,
        r.samples,
        sampled.len(),
        r.cells.len(),
        100.0 * mean
    );
    let mut best = sampled.clone();
    best.sort_by(|a, b| b.pots.cmp(&a.pots).then(a.index.cmp(&b.index)));
    for c in best.iter().take(5) {
        out += &format!(
            "  cue ball at ({:+.3}, {:+.3}) m: {:.1} % (analytic {:.1} %)\n",
            c.x,
            c.y,
            100.0 * c.success().unwrap_or(0.0),
            100.0 * c.analytic
        );
    }
    out
}

/// A colour for success `p` in [0, 1]: dark red through yellow to green.
fn colour(p: f64) -> plotters::style::RGBColor {
    let p = p.clamp(0.0, 1.0);
    let (r, g) = if p < 0.5 {
        (0.6 + 0.8 * p, 1.6 * p)
    } else {
        (1.0 - 1.6 * (p - 0.5), 0.8 + 0.2 * (p - 0.5))
    };
    let c = |x: f64| (255.0 * x.clamp(0.0, 1.0)).round() as u8;
    plotters::style::RGBColor(c(r), c(g), c(0.15))
}

/// Draws the heat map of `r` as SVG at `path`.
pub fn heat_map(r: &StudyResult, path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let e = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let (table, params) = billiards_ai::play::table_and_params_on(r.table);
    let (hx, hy) = (0.5 * table.length, 0.5 * table.width);
    let scale = 900.0 / table.length;
    let (w, h) = (
        (2.0 * hx * scale) as u32 + 80,
        (2.0 * hy * scale) as u32 + 110,
    );
    let root = SVGBackend::new(path, (w, h)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let px = |x: f64, y: f64| {
        (
            (40.0 + (x + hx) * scale) as i32,
            (50.0 + (hy - y) * scale) as i32,
        )
    };
    root.draw(&Text::new(
        format!(
            "P(the {} into {}) from each cue-ball place, {} noise, {} samples a cell",
            r.target,
            crate::args::pocket_arg(r.pocket),
            r.player,
            r.samples
        ),
        (40, 15),
        ("sans-serif", 18).into_font(),
    ))
    .map_err(|x| e(&x))?;
    root.draw(&Rectangle::new(
        [px(-hx, hy), px(hx, -hy)],
        RGBColor(30, 90, 50).filled(),
    ))
    .map_err(|x| e(&x))?;
    let b = table.centre_bounds(params.ball.radius);
    let (dx, dy) = (b.x / f64::from(r.grid.0), b.y / f64::from(r.grid.1));
    for c in &r.cells {
        let fill = match c.success() {
            Some(p) => colour(p).filled(),
            None => RGBColor(90, 90, 90).filled(),
        };
        root.draw(&Rectangle::new(
            [px(c.x - dx, c.y + dy), px(c.x + dx, c.y - dy)],
            fill,
        ))
        .map_err(|x| e(&x))?;
    }
    let rad = (params.ball.radius * scale).round() as i32;
    for &(n, x, y) in &r.balls {
        root.draw(&Circle::new(px(x, y), rad, WHITE.filled()))
            .map_err(|x| e(&x))?;
        root.draw(&Circle::new(px(x, y), rad, BLACK.stroke_width(1)))
            .map_err(|x| e(&x))?;
        let (cx, cy) = px(x, y);
        root.draw(&Text::new(
            n.to_string(),
            (cx - 4, cy - 6),
            ("sans-serif", 12).into_font(),
        ))
        .map_err(|x| e(&x))?;
    }
    let (target, _) = billiards_ai::candidates::pocket_target(&table, params.ball.radius, r.pocket);
    root.draw(&Circle::new(
        px(target.x, target.y),
        (2.5 * INCH * scale) as i32,
        BLUE.stroke_width(3),
    ))
    .map_err(|x| e(&x))?;
    // The scale: 0 to 100 % in ten steps.
    let y0 = 60 + (2.0 * hy * scale) as i32;
    for s in 0..=10 {
        let x0 = 40 + s * 45;
        root.draw(&Rectangle::new(
            [(x0, y0), (x0 + 45, y0 + 18)],
            colour(f64::from(s) / 10.0).filled(),
        ))
        .map_err(|x| e(&x))?;
        root.draw(&Text::new(
            format!("{}", s * 10),
            (x0 + 12, y0 + 22),
            ("sans-serif", 12).into_font(),
        ))
        .map_err(|x| e(&x))?;
    }
    root.draw(&Text::new(
        "% success (grey: no room or no shot; blue ring: the pocket)",
        (40 + 11 * 45 + 10, y0 + 2),
        ("sans-serif", 13).into_font(),
    ))
    .map_err(|x| e(&x))?;
    root.present().map_err(|x| e(&x))
}

/// Runs `study`; returns the exit code.
pub fn run(a: StudyArgs) -> ExitCode {
    let result = if a.merge.is_empty() {
        if let Err(e) = crate::shard::fail_once("study", a.shard) {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
        match study(&a, a.shard) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        match crate::shard::merge::<StudyResult>(&a.merge) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    };
    if let Some(path) = &a.out
        && let Err(e) = crate::shard::write_json(&result, path)
    {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    if let Some(path) = &a.svg
        && let Err(e) = heat_map(&result, path)
    {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    print!("{}", report(&result));
    ExitCode::SUCCESS
}
