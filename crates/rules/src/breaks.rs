//! Break statistics: one break of a seeded 9-ball or 8-ball rack, judged by the rules, and
//! the counts over many. What `examples/break_stats/` prints and `billiards-cli breaks`
//! computes (per game, table, rack, speed and cue position, sharded over processes).
//!
//! A break draws, in this order, from the random stream it is given: the rack's seed, the
//! cue ball's place ([`Cue`]), the speed (uniform in the spec's range) and, with an aim
//! error, one standard normal. The same stream gives the same break, bit for bit.
//!
//! Physics: the game's defaults (spin model, Mathavan 2010 cushion with e 0.98 and mu 0.14 as
//! in `src/settings/physics.rs`, 15 mm jaws, cluster impacts) unless [`params`] is told
//! otherwise ([`params_with`] takes another cushion).

use crate::{Call, Foul, Game, GameState, Seat, summarise};
use billiards_physics::{
    BallFriction, BallSetup, CushionModel, Model, Params, Shot, Simulation, SpinModel, Table,
    TableChoice, TipOffset, Vec2,
};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// Where the cue ball starts.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Cue {
    /// The break box: behind the head string, within one diamond of it and of the long axis
    /// (`x` in `[head string - L/8, head string]`, `|y| <= W/4`).
    Box,
    /// Anywhere behind the head string.
    Kitchen,
    /// On the head string.
    String,
    /// On the head string within half a diamond (`W/8`) of a long cushion, either side: the
    /// 9-ball side break (Alciatore, "How to Rack and Break 9-Ball Like a Pro").
    Side,
    /// On the head string at `f` times the largest distance from the long axis (0: the head
    /// spot, 1: frozen to a long cushion), either side.
    Across(f64),
}

impl fmt::Display for Cue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Cue::Box => f.write_str("box"),
            Cue::Kitchen => f.write_str("kitchen"),
            Cue::String => f.write_str("string"),
            Cue::Side => f.write_str("side"),
            Cue::Across(x) => write!(f, "y:{x}"),
        }
    }
}

impl FromStr for Cue {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Ok(match s {
            "box" => Cue::Box,
            "kitchen" => Cue::Kitchen,
            "string" => Cue::String,
            "side" => Cue::Side,
            v => match v.strip_prefix("y:").map(str::parse::<f64>) {
                Some(Ok(f)) if (0.0..=1.0).contains(&f) => Cue::Across(f),
                _ => {
                    return Err(format!(
                        "{s:?}: expected box, kitchen, string, side or y:F (0 <= F <= 1)"
                    ));
                }
            },
        })
    }
}

/// The physical constants [`params`] may change.
pub const SETTABLE: [&str; 10] = [
    "mu_slide",
    "mu_roll",
    "e_ball",
    "mu_ball",
    "e_cushion",
    "mu_cushion",
    "young",
    "poisson",
    "mu_ball_slip",
    "cushion_height",
];

/// The game's cushion (`src/settings/physics.rs`: Mathavan et al. 2010 with their fitted
/// e 0.98 and mu 0.14; docs/realism.md, "Cushion").
pub const GAME_CUSHION: CushionModel = CushionModel::MATHAVAN_2010;

/// A cushion model by name: `mathavan` (the game's, e 0.98, mu 0.14), `han` (Han 2005, e
/// 0.85, mu 0.2: the solver's own default) or `reflect` (e 0.85).
pub fn cushion_by_name(name: &str) -> Result<CushionModel, String> {
    Ok(match name {
        "mathavan" | "mathavan2010" => CushionModel::MATHAVAN_2010,
        "han" | "han2005" => CushionModel::Han2005 { e: 0.85, mu: 0.2 },
        "reflect" => CushionModel::Reflect { e: 0.85 },
        _ => return Err(format!("{name:?}: expected mathavan, han or reflect")),
    })
}

/// The game's physics ([`GAME_CUSHION`]) with `set` applied; see [`params_with`].
pub fn params(pairwise: bool, set: &[(String, f64)]) -> Result<Params, String> {
    params_with(GAME_CUSHION, pairwise, set)
}

/// The game's physics with the cushion `cushion` and `set` applied (name, value; names from [`SETTABLE`]: `mu_ball`
/// makes ball friction a constant, `mu_ball_slip` is a factor on Alciatore's slip-dependent
/// fit, 0 for the constant `mu_ball`), and with `pairwise` every contact resolved pair by
/// pair (no cluster impacts). An unknown name or a value out of the physical ranges is an
/// error. `e_cushion` and `mu_cushion` set the chosen cushion's constants; `e_ball` also
/// sets the Hertz damping of cluster impacts, which is calibrated to it.
pub fn params_with(
    cushion: CushionModel,
    pairwise: bool,
    set: &[(String, f64)],
) -> Result<Params, String> {
    let mut model = SpinModel {
        cushion,
        ..SpinModel::default()
    };
    if pairwise {
        model.cluster = None;
    }
    for (k, v) in set {
        let v = *v;
        if !SETTABLE.contains(&k.as_str()) {
            return Err(format!("{k:?}: a constant is one of {SETTABLE:?}"));
        }
        match (k.as_str(), &mut model.cushion) {
            ("mu_slide", _) => model.mu_slide = v,
            ("mu_roll", _) => model.mu_roll = v,
            ("e_ball", _) => model.e_ball = v,
            ("mu_ball", _) => {
                model.mu_ball = v;
                model.ball_friction = BallFriction::Constant;
            }
            // 0: the constant mu_ball; otherwise Alciatore's fit scaled by v.
            ("mu_ball_slip", _) => {
                model.ball_friction = match BallFriction::ALCIATORE {
                    BallFriction::SpeedDependent { a, b, c } if v > 0.0 => {
                        BallFriction::SpeedDependent {
                            a: a * v,
                            b: b * v,
                            c,
                        }
                    }
                    _ => BallFriction::Constant,
                }
            }
            (
                "e_cushion",
                CushionModel::Han2005 { e, .. }
                | CushionModel::Mathavan2010 { e, .. }
                | CushionModel::Reflect { e },
            ) => *e = v,
            (
                "mu_cushion",
                CushionModel::Han2005 { mu, .. } | CushionModel::Mathavan2010 { mu, .. },
            ) => *mu = v,
            ("cushion_height", _) => model.cushion_height = v,
            ("young", _) => {
                if let Some(h) = model.cluster.as_mut() {
                    h.young = v;
                }
            }
            ("poisson", _) => {
                if let Some(h) = model.cluster.as_mut() {
                    h.poisson = v;
                }
            }
            _ => {}
        }
    }
    let p = Params {
        model: Model::Spin(model),
        ..Params::default()
    };
    p.validate().map_err(|e| format!("--set: {e}"))?;
    Ok(p)
}

/// The cue ball's start on `table` for balls of radius `r`.
pub fn cue_position(table: &Table, cue: Cue, r: f64, rng: &mut ChaCha8Rng) -> Vec2 {
    let b = table.centre_bounds(r);
    let string = table.head_spot().x;
    match cue {
        Cue::Box => Vec2::new(
            rng.random_range(string - table.length / 8.0..=string),
            rng.random_range(-table.width / 4.0..=table.width / 4.0),
        ),
        Cue::Kitchen => Vec2::new(
            rng.random_range(-b.x..=string),
            rng.random_range(-b.y..=b.y),
        ),
        Cue::String => Vec2::new(string, rng.random_range(-b.y..=b.y)),
        Cue::Side => {
            let y = rng.random_range(b.y - table.width / 8.0..=b.y);
            Vec2::new(string, if rng.random::<bool>() { y } else { -y })
        }
        Cue::Across(f) => {
            let y = f * b.y;
            Vec2::new(string, if rng.random::<bool>() { y } else { -y })
        }
    }
}

/// One kind of break: everything but the random draws.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BreakSpec {
    /// 9-ball or 8-ball.
    pub game: Game,
    /// The table (with 15 mm jaws).
    pub table: TableChoice,
    /// The rack lattice's slack, metres (neighbours end 0 to twice it apart).
    pub gap: f64,
    /// Where the cue ball starts.
    pub cue: Cue,
    /// The cue ball's speed, uniform in `[min, max]`, m/s.
    pub speed: (f64, f64),
    /// Standard deviation of a Gaussian aim error, radians (0: at the head ball's centre).
    pub aim_sd: f64,
    /// Tip height as a fraction of the radius (0: centre ball, negative: draw).
    pub tip_height: f64,
    /// Cue elevation, radians (0: level; the strike keeps the ball on the table).
    #[serde(default)]
    pub elevation: f64,
    /// 9-ball: the rack moved two rows towards the head so that the 9, not the 1, is on the
    /// foot spot ("9 on the spot", a racking rule of some professional events).
    #[serde(default)]
    pub nine_on_spot: bool,
}

/// What one break did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct BreakOutcome {
    /// Object balls pocketed.
    pub balls: usize,
    /// The cue ball went down.
    pub scratch: bool,
    /// The break was legal (no illegal-break foul).
    pub legal: bool,
    /// A ball down and the verdict legal.
    pub success: bool,
    /// The 9 (9-ball) or the 8 (8-ball) went down.
    pub money_ball: bool,
    /// Solver events to rest.
    pub events: usize,
}

/// Why a break could not be played (a spec whose rack or shot the solver refuses).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("break not played: {0}")]
pub struct BreakError(pub String);

/// One break of `spec` under `params`, every random draw from `rng`.
pub fn one_break(
    spec: &BreakSpec,
    params: &Params,
    rng: &mut ChaCha8Rng,
) -> Result<BreakOutcome, BreakError> {
    let err = |e: &dyn fmt::Display| BreakError(e.to_string());
    let sim = break_run(spec, params, rng)?;
    let summary = summarise(sim.history().events(), sim.numbers());
    let verdict = GameState::new(spec.game, Seat::A)
        .play(&summary, Call::None)
        .map_err(|e| err(&e))?;
    let down = summary.pocketed_object_balls().count();
    let illegal = verdict
        .fouls
        .iter()
        .any(|f| matches!(f, Foul::IllegalBreak { .. }));
    let money = match spec.game {
        Game::NineBall => 9,
        Game::TenBall => 10,
        Game::EightBall | Game::FreePlay => 8,
    };
    Ok(BreakOutcome {
        balls: down,
        scratch: summary.scratch(),
        legal: !illegal,
        success: down > 0 && verdict.legal(),
        money_ball: summary.pocket_of(money).is_some(),
        events: sim.history().events().len(),
    })
}

/// [`one_break`]'s break run to rest, with its history, not judged: the same draws from
/// `rng`, for a study of what the balls did.
pub fn break_run(
    spec: &BreakSpec,
    params: &Params,
    rng: &mut ChaCha8Rng,
) -> Result<Simulation, BreakError> {
    let err = |e: &dyn fmt::Display| BreakError(e.to_string());
    let table = spec.table.table().with_jaws(0.015);
    let mut balls = rack(spec, &table, params, rng.random());
    let cue = cue_position(&table, spec.cue, params.ball.radius, rng);
    balls[0].position = cue;
    let speed = rng.random_range(spec.speed.0..=spec.speed.1);
    let mut aim = (balls[1].position - cue).angle();
    if spec.aim_sd > 0.0 {
        // Box-Muller: one standard normal draw (none without an aim error, so the runs
        // without one keep their published numbers).
        let (u1, u2): (f64, f64) = (rng.random(), rng.random());
        let normal = (-2.0 * (1.0 - u1).ln()).sqrt() * (std::f64::consts::TAU * u2).cos();
        aim += spec.aim_sd * normal;
    }
    let mut sim = Simulation::new(table, *params, &balls).map_err(|e| err(&e))?;
    let shot = Shot {
        tip: TipOffset {
            side: 0.0,
            height: spec.tip_height,
        },
        elevation: spec.elevation,
        ..Shot::new(aim, speed)
    };
    sim.strike(0, shot).map_err(|e| err(&e))?;
    sim.run_to_rest().map_err(|e| err(&e))?;
    Ok(sim)
}

/// The rack of `spec` on `table` from `seed`, the cue ball first (on the head spot).
pub fn rack(spec: &BreakSpec, table: &Table, params: &Params, seed: u64) -> Vec<BallSetup> {
    let mut balls: Vec<BallSetup> = match spec.game {
        Game::NineBall => crate::racks::nine_ball_spaced(table, &params.ball, seed, spec.gap),
        Game::TenBall => crate::racks::ten_ball_spaced(table, &params.ball, seed, spec.gap),
        Game::EightBall | Game::FreePlay => {
            crate::racks::eight_ball_spaced(table, &params.ball, seed, spec.gap)
        }
    };
    if spec.nine_on_spot && spec.game == Game::NineBall {
        // The 9 is two rows behind the apex; rows are sqrt(3)/2 of a spacing apart.
        let back = 3f64.sqrt() * (2.0 * params.ball.radius + spec.gap);
        for b in balls.iter_mut().skip(1) {
            b.position.x -= back;
        }
    }
    balls
}

/// Counts over a set of breaks: whole numbers only, so sets add up in any order.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct BreakStats {
    /// Breaks.
    pub breaks: usize,
    /// Breaks with at least one object ball down.
    pub with_ball: usize,
    /// Object balls down, in all.
    pub balls: usize,
    /// Sum of the squares of the balls down per break.
    pub balls_sq: usize,
    /// Scratches.
    pub scratches: usize,
    /// Legal breaks.
    pub legal: usize,
    /// Successful breaks (a ball down, legal).
    pub success: usize,
    /// Breaks that sank the money ball (9 or 8).
    pub money_ball: usize,
    /// Solver events, in all.
    pub events: usize,
}

impl BreakStats {
    /// Counts `o` in.
    pub fn add(&mut self, o: &BreakOutcome) {
        self.breaks += 1;
        self.with_ball += usize::from(o.balls > 0);
        self.balls += o.balls;
        self.balls_sq += o.balls * o.balls;
        self.scratches += usize::from(o.scratch);
        self.legal += usize::from(o.legal);
        self.success += usize::from(o.success);
        self.money_ball += usize::from(o.money_ball);
        self.events += o.events;
    }

    /// Both sets together.
    pub fn merged(self, o: BreakStats) -> BreakStats {
        BreakStats {
            breaks: self.breaks + o.breaks,
            with_ball: self.with_ball + o.with_ball,
            balls: self.balls + o.balls,
            balls_sq: self.balls_sq + o.balls_sq,
            scratches: self.scratches + o.scratches,
            legal: self.legal + o.legal,
            success: self.success + o.success,
            money_ball: self.money_ball + o.money_ball,
            events: self.events + o.events,
        }
    }

    /// Mean balls down per break and the half width of its 95 % interval.
    pub fn balls_per_break(&self) -> (f64, f64) {
        let n = self.breaks.max(1) as f64;
        let mean = self.balls as f64 / n;
        let sd = (self.balls_sq as f64 / n - mean * mean).max(0.0).sqrt();
        (mean, 1.96 * sd / n.sqrt())
    }
}

/// Wilson's 95 % interval of `k` successes in `n`, in percent.
pub fn wilson(k: usize, n: usize) -> (f64, f64) {
    let (n, p, z) = (n.max(1) as f64, k as f64 / n.max(1) as f64, 1.96);
    let d = 1.0 + z * z / n;
    let c = (p + z * z / (2.0 * n)) / d;
    let h = z * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt() / d;
    (100.0 * (c - h), 100.0 * (c + h))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn cue_places_parse_and_print_back() {
        for s in ["box", "kitchen", "string", "side", "y:0.75"] {
            assert_eq!(s.parse::<Cue>().unwrap().to_string(), s);
        }
        assert!("y:2".parse::<Cue>().is_err());
        assert!("middle".parse::<Cue>().is_err());
    }

    #[test]
    fn a_break_is_a_function_of_its_stream() {
        let spec = BreakSpec {
            game: Game::NineBall,
            table: "9ft".parse().unwrap(),
            gap: crate::RackStyle::Triangle.gap(),
            cue: Cue::Box,
            speed: (10.0, 12.0),
            aim_sd: 0.0,
            tip_height: 0.0,
            elevation: 0.0,
            nine_on_spot: false,
        };
        let p = params(false, &[]).unwrap();
        let a = one_break(&spec, &p, &mut ChaCha8Rng::seed_from_u64(3)).unwrap();
        let b = one_break(&spec, &p, &mut ChaCha8Rng::seed_from_u64(3)).unwrap();
        assert_eq!(a, b);
        assert!(a.events > 10);
        let mut s = BreakStats::default();
        s.add(&a);
        assert_eq!(s.merged(s).breaks, 2);
        assert!(params(false, &[("nope".into(), 1.0)]).is_err());
    }

    fn cushion_of(p: &Params) -> CushionModel {
        match p.model {
            Model::Spin(m) => m.cushion,
            Model::Paper(_) => panic!("the spin model"),
        }
    }

    #[test]
    fn the_break_uses_the_game_cushion_and_sets_its_constants() {
        assert_eq!(cushion_of(&params(false, &[]).unwrap()), GAME_CUSHION);
        let p = params(
            false,
            &[("e_cushion".into(), 0.9), ("mu_cushion".into(), 0.1)],
        );
        assert_eq!(
            cushion_of(&p.unwrap()),
            CushionModel::Mathavan2010 { e: 0.9, mu: 0.1 }
        );
        let han = cushion_by_name("han").unwrap();
        assert_eq!(han, CushionModel::default());
        assert_eq!(cushion_of(&params_with(han, false, &[]).unwrap()), han);
        assert!(cushion_by_name("felt").is_err());
        let p = params(false, &[("poisson".into(), 0.3)]).unwrap();
        let Model::Spin(m) = p.model else { panic!() };
        assert_eq!(m.cluster.unwrap().poisson, 0.3);
    }

    #[test]
    fn nine_on_the_spot_puts_the_9_on_the_foot_spot() {
        let mut spec = BreakSpec {
            game: Game::NineBall,
            table: "9ft".parse().unwrap(),
            gap: 0.0,
            cue: Cue::Box,
            speed: (10.0, 12.0),
            aim_sd: 0.0,
            tip_height: 0.0,
            elevation: 0.0,
            nine_on_spot: false,
        };
        let table = spec.table.table();
        let p = params(false, &[]).unwrap();
        let at =
            |balls: &[BallSetup], n: u8| balls.iter().find(|b| b.number == n).unwrap().position;
        let normal = rack(&spec, &table, &p, 5);
        assert!((at(&normal, 1) - table.foot_spot()).length() < 1e-12);
        spec.nine_on_spot = true;
        let moved = rack(&spec, &table, &p, 5);
        assert!((at(&moved, 9) - table.foot_spot()).length() < 1e-12);
        assert_eq!(normal.len(), moved.len());
    }
}
