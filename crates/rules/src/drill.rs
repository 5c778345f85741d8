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

use crate::game::{Game, GameState, Seat};
use crate::position::Position;
use crate::shot::{CUE, ShotSummary};
use billiards_physics::{BallSetup, Event, EventKind, Params, Pocket, Simulation, Vec2};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Most shots one attempt may take (a run-out of fifteen balls).
pub const MAX_SHOTS: u32 = 15;

/// A region of the table, in table coordinates (metres, origin at the centre).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "shape", rename_all = "snake_case")]
pub enum Zone {
    /// The disc of `radius` about `centre`.
    Circle {
        /// Centre.
        centre: Vec2,
        /// Radius, metres.
        radius: f64,
    },
    /// The rectangle between two corners.
    Rect {
        /// The corner of least x and y.
        min: Vec2,
        /// The corner of greatest x and y.
        max: Vec2,
    },
}

impl Zone {
    /// The zone holds the ball centre `p` (its edge included).
    pub fn contains(&self, p: Vec2) -> bool {
        match *self {
            Zone::Circle { centre, radius } => (p - centre).length() <= radius,
            Zone::Rect { min, max } => {
                (min.x..=max.x).contains(&p.x) && (min.y..=max.y).contains(&p.y)
            }
        }
    }

    /// The zone's centre.
    pub fn centre(&self) -> Vec2 {
        match *self {
            Zone::Circle { centre, .. } => centre,
            Zone::Rect { min, max } => (min + max) * 0.5,
        }
    }

    /// How close `p` is to the centre, 1 at the centre to 0 at the edge (the rectangle's
    /// edge by the larger of the two normalised offsets); 0 outside.
    pub fn closeness(&self, p: Vec2) -> f64 {
        let c = self.centre();
        let d = match *self {
            Zone::Circle { radius, .. } => (p - c).length() / radius,
            Zone::Rect { min, max } => {
                let h = (max - min) * 0.5;
                ((p.x - c.x).abs() / h.x).max((p.y - c.y).abs() / h.y)
            }
        };
        (1.0 - d).clamp(0.0, 1.0)
    }

    fn valid(&self) -> bool {
        match *self {
            Zone::Circle { centre, radius } => {
                centre.x.is_finite() && centre.y.is_finite() && radius.is_finite() && radius > 0.0
            }
            Zone::Rect { min, max } => {
                [min.x, min.y, max.x, max.y].iter().all(|v| v.is_finite())
                    && min.x < max.x
                    && min.y < max.y
            }
        }
    }
}

/// What an attempt must do; a drill's goals must all be met.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Goal {
    /// Pocket `ball` (in `pocket` if named), after it has touched at least `cushions`
    /// cushions (a bank: 1; a jaw is not counted here, so a rattle is no bank).
    Pocket {
        /// The ball.
        ball: u8,
        /// The pocket it must drop in (`None`: any).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pocket: Option<Pocket>,
        /// Cushions it must touch before it drops.
        #[serde(default)]
        cushions: u32,
    },
    /// The cue ball comes to rest on the table inside `zone` after the attempt's last shot.
    CueBallIn {
        /// The zone.
        zone: Zone,
    },
    /// The cue ball's first contact is `ball`, after at least `cushions` cushion contacts of
    /// the cue ball (a kick: 1).
    FirstContact {
        /// The ball hit first.
        ball: u8,
        /// Cushions the cue ball touches before it.
        #[serde(default)]
        cushions: u32,
    },
    /// Every shot legal under the game's rules (WPA 6.1 to 6.3 in 8-ball and 9-ball); in free
    /// play, no scratch and an object ball hit.
    NoFoul,
    /// No ball is pocketed (a safety).
    NoPocket,
    /// At rest, the cue ball has no straight path to `ball` (`None`: the ball the game says is
    /// on: 9-ball's lowest, WPA 6.2): its centre line to the ball's centre passes within a
    /// ball's diameter of another ball's centre (the opponent is hidden: a safety).
    Hide {
        /// The ball hidden (`None`: the ball on).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        ball: Option<u8>,
    },
    /// Every object ball pocketed in one visit: each shot legal and pocketing a ball, in
    /// 9-ball the lowest ball hit first every time (WPA 2.1, 6.2).
    RunOut,
}

impl Goal {
    /// The goal in words ("pocket the 1 in the foot right corner").
    pub fn text(&self) -> String {
        match *self {
            Goal::Pocket {
                ball,
                pocket,
                cushions,
            } => {
                let mut s = format!("pocket the {ball}");
                if let Some(p) = pocket {
                    s += &format!(" in the {}", crate::foul::pocket_name(p));
                }
                if cushions > 0 {
                    s += &format!(" off {cushions} cushion(s)");
                }
                s
            }
            Goal::CueBallIn { .. } => "leave the cue ball in the zone".into(),
            Goal::FirstContact { ball, cushions: 0 } => format!("hit the {ball} first"),
            Goal::FirstContact { ball, cushions } => {
                format!("hit the {ball} first after {cushions} cushion(s)")
            }
            Goal::NoFoul => "no foul".into(),
            Goal::NoPocket => "pocket nothing".into(),
            Goal::Hide { ball: Some(b) } => format!("hide the {b} from the cue ball"),
            Goal::Hide { ball: None } => "hide the ball on from the cue ball".into(),
            Goal::RunOut => "run out the table".into(),
        }
    }
}

fn one() -> u32 {
    1
}

fn ten() -> u32 {
    10
}

/// A drill: a position, its goals and the tries a session gives.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Drill {
    /// Its name in the drills list.
    pub name: String,
    /// What to do, in a sentence or two.
    #[serde(default)]
    pub description: String,
    /// The position it starts from (the cue ball, number 0, on the table).
    pub position: Position,
    /// Every goal must be met.
    pub goals: Vec<Goal>,
    /// Tries in a session (default 10).
    #[serde(default = "ten")]
    pub tries: u32,
    /// Most shots one attempt takes (default 1; a run-out takes several, one visit).
    #[serde(default = "one")]
    pub shots: u32,
}

/// A file of a drills folder: its name and its drill, or why it was refused.
pub type Loaded = (String, Result<Drill, DrillError>);

/// Why a drill file was refused.
#[derive(Debug, thiserror::Error)]
pub enum DrillError {
    /// The file could not be read.
    #[error("{0}")]
    Io(String),
    /// Not JSON, or not a drill's fields.
    #[error("not a drill: {0}")]
    Json(String),
    /// The position is not one a simulation starts from.
    #[error("the drill's position is not valid: {0}")]
    Position(String),
    /// No cue ball.
    #[error("the drill's position has no cue ball (number 0)")]
    NoCueBall,
    /// No goal.
    #[error("the drill has no goal")]
    NoGoal,
    /// A goal names a ball that is not on the table.
    #[error("the goal \"{goal}\" names the {ball}, which is not on the table")]
    NoSuchBall {
        /// The goal in words.
        goal: String,
        /// The ball.
        ball: u8,
    },
    /// A zone of no area, or not finite.
    #[error("the goal \"{0}\" has an empty or invalid zone")]
    BadZone(String),
    /// Zero tries, or zero or too many shots.
    #[error("the drill needs {0}")]
    Count(String),
    /// Goals no attempt can meet together.
    #[error("the drill's goals contradict each other: {0}")]
    Contradiction(String),
}

/// One shot of an attempt as the solver recorded it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DrillShot {
    /// The rules' summary of its events.
    pub summary: ShotSummary,
    /// Cushion contacts of the cue ball before its first contact with a ball (jaws apart).
    pub cue_cushions_before_contact: u32,
    /// Cushion contacts (jaws apart) of each ball before it was pocketed (or in the shot),
    /// by number; balls without any are left out.
    pub cushions: Vec<(u8, u32)>,
    /// The balls on the table at rest after the shot, by number.
    pub rest: Vec<(u8, Vec2)>,
}

impl DrillShot {
    /// The shot of `events` (from its strike to rest; see [`crate::summarise`]) with the
    /// balls resting at `rest` afterwards.
    pub fn from_events(events: &[Event], numbers: &[u8], rest: Vec<(u8, Vec2)>) -> Self {
        let mut s = DrillShot {
            rest,
            ..Default::default()
        };
        for kind in crate::shot::after_strike(events) {
            s.record(&kind, numbers);
        }
        s
    }

    /// Adds one event after the strike (the lean solver's way, one event at a time).
    pub fn record(&mut self, kind: &EventKind, numbers: &[u8]) {
        // Cushion noses only: a ball rattled in the jaws on its way in is no bank.
        if let EventKind::Cushion { ball, .. } = *kind {
            let n = numbers.get(ball).copied().unwrap_or(u8::MAX);
            if n == CUE && self.summary.first_contact.is_none() {
                self.cue_cushions_before_contact += 1;
            }
            match self.cushions.iter_mut().find(|c| c.0 == n) {
                Some(c) => c.1 += 1,
                None => self.cushions.push((n, 1)),
            }
        }
        self.summary.record(kind, numbers);
    }

    /// The shot just played on `sim` (with a history), from event `first` (the history's
    /// length before the strike) to now, the balls at rest.
    pub fn of(sim: &Simulation, first: usize) -> Self {
        let events = &sim.history().events()[first..];
        Self::from_events(events, sim.numbers(), resting(sim))
    }

    /// Cushions ball `n` touched.
    pub fn cushions_of(&self, n: u8) -> u32 {
        self.cushions.iter().find(|c| c.0 == n).map_or(0, |c| c.1)
    }
}

/// The balls of `sim` on the table, by number and centre.
pub fn resting(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}

/// The judgement of one attempt.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Attempt {
    /// Every goal met.
    pub success: bool,
    /// 0 to 100: each goal's share, a met goal in full, a zone goal met by how close the
    /// cue ball is to the zone's centre (half for the edge, all for the centre), a run-out by
    /// the share of balls pocketed in one visit.
    pub score: f64,
    /// One line per goal: "met: ..." or "missed: ... (why)".
    pub reasons: Vec<String>,
    /// Shots the attempt took.
    pub shots: usize,
}

/// A drill's tally over tries: what the game keeps in its settings.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DrillScore {
    /// Attempts judged.
    pub tries: u32,
    /// Attempts that met every goal.
    pub successes: u32,
    /// The best score of an attempt.
    pub best: f64,
}

impl DrillScore {
    /// Counts one attempt.
    pub fn add(&mut self, a: &Attempt) {
        self.tries += 1;
        self.successes += u32::from(a.success);
        self.best = self.best.max(a.score);
    }

    /// The better of two sessions' tallies (more successes, then the better best score; a
    /// session's rate is compared, not its length): the one to keep as the best.
    pub fn better(self, other: DrillScore) -> DrillScore {
        let rate = |s: DrillScore| f64::from(s.successes) / f64::from(s.tries.max(1));
        let key = |s: DrillScore| (rate(s), s.best);
        if key(other) > key(self) { other } else { self }
    }
}

impl Drill {
    /// A drill from its JSON text, checked ([`Drill::check`]).
    pub fn from_json(text: &str) -> Result<Self, DrillError> {
        let d: Drill = serde_json::from_str(text).map_err(|e| DrillError::Json(e.to_string()))?;
        d.check()?;
        Ok(d)
    }

    /// The drill in the file `path`.
    pub fn load(path: &Path) -> Result<Self, DrillError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| DrillError::Io(format!("{}: {e}", path.display())))?;
        Self::from_json(&text)
    }

    /// Every `*.json` drill in `dir`, by file name; a bad file is reported with its name.
    pub fn load_dir(dir: &Path) -> Result<Vec<Loaded>, DrillError> {
        let mut names: Vec<_> = std::fs::read_dir(dir)
            .map_err(|e| DrillError::Io(format!("{}: {e}", dir.display())))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "json"))
            .collect();
        names.sort();
        Ok(names
            .into_iter()
            .map(|p| {
                let name = p
                    .file_name()
                    .unwrap_or_default()
                    .to_string_lossy()
                    .into_owned();
                (name, Self::load(&p))
            })
            .collect())
    }

    /// The drill is playable: a valid position with a cue ball, at least one goal, each
    /// naming balls on the table and zones of some area, tries and shots in range.
    pub fn check(&self) -> Result<(), DrillError> {
        self.position
            .check()
            .map_err(|e| DrillError::Position(e.to_string()))?;
        let on = |n: u8| self.position.balls.iter().any(|b| b.number == n);
        if !on(CUE) {
            return Err(DrillError::NoCueBall);
        }
        if self.goals.is_empty() {
            return Err(DrillError::NoGoal);
        }
        if self.tries == 0 {
            return Err(DrillError::Count("at least one try".into()));
        }
        if self.shots == 0 || self.shots > MAX_SHOTS {
            return Err(DrillError::Count(format!(
                "1 to {MAX_SHOTS} shots an attempt"
            )));
        }
        for g in &self.goals {
            let ball = match *g {
                Goal::Pocket { ball, .. }
                | Goal::FirstContact { ball, .. }
                | Goal::Hide { ball: Some(ball) } => Some(ball),
                _ => None,
            };
            if let Some(ball) = ball
                && (ball == CUE || !on(ball))
            {
                return Err(DrillError::NoSuchBall {
                    goal: g.text(),
                    ball,
                });
            }
            if let Goal::CueBallIn { zone } = g
                && !zone.valid()
            {
                return Err(DrillError::BadZone(g.text()));
            }
        }
        let pots = self
            .goals
            .iter()
            .any(|g| matches!(g, Goal::Pocket { .. } | Goal::RunOut));
        if pots && self.goals.contains(&Goal::NoPocket) {
            return Err(DrillError::Contradiction(
                "a ball must be pocketed and none may be".into(),
            ));
        }
        if self.goals.contains(&Goal::RunOut) && self.object_balls().is_empty() {
            return Err(DrillError::Contradiction(
                "a run-out with no object ball".into(),
            ));
        }
        Ok(())
    }

    /// The object balls of the position, ascending.
    pub fn object_balls(&self) -> Vec<u8> {
        let mut v: Vec<u8> = self
            .position
            .balls
            .iter()
            .map(|b| b.number)
            .filter(|&n| n != CUE)
            .collect();
        v.sort_unstable();
        v
    }

    /// A simulation of the position under `params` (the drill's own, if it carries them).
    pub fn simulation(&self, params: Params) -> Result<Simulation, DrillError> {
        let setups: Vec<BallSetup> = self
            .position
            .balls
            .iter()
            .map(|b| BallSetup::at(b.number, b.position))
            .collect();
        Simulation::new(
            self.position.table,
            self.position.params.unwrap_or(params),
            &setups,
        )
        .map_err(|e| DrillError::Position(e.to_string()))
    }

    /// The rules' state of the position: player A at the table, the cue ball as it lies.
    pub fn game_state(&self) -> GameState {
        GameState::in_progress(self.position.game, Seat::A, self.object_balls())
    }

    /// Whether the attempt goes on after `shots`: the visit continues (every shot legal and
    /// pocketing a ball), object balls are left and the drill allows another shot.
    pub fn continues(&self, shots: &[DrillShot]) -> bool {
        if shots.is_empty() {
            return true;
        }
        if shots.len() >= self.shots as usize {
            return false;
        }
        let visit = self.visit(shots);
        visit.shots == shots.len() && visit.left > 0
    }

    /// Judges an attempt from its shots, in order.
    pub fn judge(&self, shots: &[DrillShot]) -> Attempt {
        let mut reasons = Vec::new();
        let mut total = 0.0;
        let mut success = true;
        let pocketed: Vec<(u8, Pocket)> = shots
            .iter()
            .flat_map(|s| s.summary.pocketed.iter().copied())
            .collect();
        let last = shots.last();
        for g in &self.goals {
            let (share, why) = self.goal(g, shots, &pocketed, last);
            let met = why.is_none();
            success &= met;
            total += share;
            reasons.push(match why {
                None => format!("met: {}", g.text()),
                Some(w) => format!("missed: {} ({w})", g.text()),
            });
        }
        Attempt {
            success,
            score: 100.0 * total / self.goals.len().max(1) as f64,
            reasons,
            shots: shots.len(),
        }
    }

    /// One goal's share (0 to 1) and, if missed, why.
    fn goal(
        &self,
        g: &Goal,
        shots: &[DrillShot],
        pocketed: &[(u8, Pocket)],
        last: Option<&DrillShot>,
    ) -> (f64, Option<String>) {
        let Some(last) = last else {
            return (0.0, Some("no shot was played".into()));
        };
        let verdict = |ok: bool, why: String| if ok { (1.0, None) } else { (0.0, Some(why)) };
        match *g {
            Goal::Pocket {
                ball,
                pocket,
                cushions,
            } => {
                let Some(&(_, p)) = pocketed.iter().find(|&&(b, _)| b == ball) else {
                    return verdict(false, format!("the {ball} stayed on the table"));
                };
                if let Some(want) = pocket
                    && want != p
                {
                    return verdict(
                        false,
                        format!(
                            "the {ball} went in the {}, not the {}",
                            crate::foul::pocket_name(p),
                            crate::foul::pocket_name(want)
                        ),
                    );
                }
                let shot = shots.iter().find(|s| s.summary.pocket_of(ball).is_some());
                let touched = shot.map_or(0, |s| s.cushions_of(ball));
                verdict(
                    touched >= cushions,
                    format!("it touched {touched} cushion(s) before dropping"),
                )
            }
            Goal::CueBallIn { zone } => match last.rest.iter().find(|b| b.0 == CUE) {
                None => verdict(false, "the cue ball was pocketed".into()),
                Some(&(_, p)) if zone.contains(p) => (0.5 + 0.5 * zone.closeness(p), None),
                Some(&(_, p)) => {
                    let d = (p - zone.centre()).length();
                    (
                        0.0,
                        Some(format!(
                            "it stopped {:.0} cm from the zone's centre",
                            100.0 * d
                        )),
                    )
                }
            },
            Goal::FirstContact { ball, cushions } => {
                let s = &shots[0];
                match s.summary.first_contact {
                    Some(b) if b != ball => verdict(false, format!("the {b} was hit first")),
                    None => verdict(false, "no ball was hit".into()),
                    Some(_) => verdict(
                        s.cue_cushions_before_contact >= cushions,
                        format!(
                            "the cue ball touched {} cushion(s) before it",
                            s.cue_cushions_before_contact
                        ),
                    ),
                }
            }
            Goal::NoFoul => {
                let fouls = self.fouls(shots);
                verdict(fouls.is_empty(), fouls.join("; "))
            }
            Goal::NoPocket => verdict(
                pocketed.is_empty(),
                format!("the {} was pocketed", pocketed.first().map_or(0, |p| p.0)),
            ),
            Goal::Hide { ball } => {
                let target = ball.or_else(|| self.ball_on(shots));
                let Some(target) = target else {
                    return verdict(false, "no ball is left to hide".into());
                };
                match hidden(&last.rest, target, self.radius()) {
                    Some(true) => (1.0, None),
                    Some(false) => verdict(false, format!("the {target} can be seen")),
                    None => verdict(false, format!("the cue ball or the {target} is down")),
                }
            }
            Goal::RunOut => {
                let v = self.visit(shots);
                let all = self.object_balls().len();
                let share = (all - v.left) as f64 / all as f64;
                let ok = v.left == 0 && v.shots == shots.len();
                if ok {
                    (1.0, None)
                } else {
                    let why = v.why.unwrap_or_else(|| format!("{} ball(s) left", v.left));
                    (share, Some(why))
                }
            }
        }
    }

    /// The ball radius of the drill's physics.
    fn radius(&self) -> f64 {
        self.position.params.unwrap_or_default().ball.radius
    }

    /// The ball on after `shots` (9-ball, 10-ball: the lowest on the table; other games:
    /// none).
    fn ball_on(&self, shots: &[DrillShot]) -> Option<u8> {
        let mut state = self.game_state();
        for s in shots {
            let _ = state.play(&s.summary, crate::game::Call::None);
        }
        match self.position.game {
            Game::NineBall | Game::TenBall => state.on_table.first().copied(),
            _ => None,
        }
    }

    /// The fouls of every shot, in words, by the game's rules (free play: a scratch, no ball
    /// hit).
    fn fouls(&self, shots: &[DrillShot]) -> Vec<String> {
        let mut out = Vec::new();
        let mut state = self.game_state();
        for (k, s) in shots.iter().enumerate() {
            let n = k + 1;
            if self.position.game == Game::FreePlay {
                if s.summary.scratch() {
                    out.push(format!("shot {n}: the cue ball was pocketed"));
                }
                if s.summary.first_contact.is_none() {
                    out.push(format!("shot {n}: no ball was hit"));
                }
                continue;
            }
            match state.play(&s.summary, crate::game::Call::None) {
                Ok(v) if !v.legal() => out.push(format!("shot {n}: {}", v.reason())),
                Ok(_) => {}
                Err(e) => out.push(format!("shot {n}: {e}")),
            }
        }
        out
    }

    /// The visit: how many shots in a row were legal and pocketed a ball, balls left.
    fn visit(&self, shots: &[DrillShot]) -> Visit {
        let mut state = self.game_state();
        let mut left: Vec<u8> = self.object_balls();
        let free = self.position.game == Game::FreePlay;
        for (k, s) in shots.iter().enumerate() {
            let stop = |left: &[u8], why: String| Visit {
                shots: k,
                left: left.len(),
                why: Some(why),
            };
            let legal = if free {
                !s.summary.scratch() && s.summary.first_contact.is_some()
            } else {
                matches!(state.play(&s.summary, crate::game::Call::None), Ok(v) if v.legal())
            };
            if !legal {
                return stop(&left, format!("shot {} was a foul", k + 1));
            }
            let before = left.len();
            left.retain(|b| s.summary.pocket_of(*b).is_none());
            if left.len() == before {
                return stop(&left, format!("shot {} pocketed nothing", k + 1));
            }
        }
        Visit {
            shots: shots.len(),
            left: left.len(),
            why: None,
        }
    }
}

struct Visit {
    shots: usize,
    left: usize,
    why: Option<String>,
}

/// Whether the cue ball's straight path to `target` is blocked by another ball at rest
/// (`None`: one of the two is not on the table).
pub fn hidden(rest: &[(u8, Vec2)], target: u8, radius: f64) -> Option<bool> {
    let find = |n: u8| rest.iter().find(|b| b.0 == n).map(|b| b.1);
    let (a, b) = (find(CUE)?, find(target)?);
    let seg = b - a;
    let len2 = seg.dot(seg).max(1e-18);
    Some(rest.iter().any(|&(n, c)| {
        if n == CUE || n == target {
            return false;
        }
        let t = ((c - a).dot(seg) / len2).clamp(0.0, 1.0);
        (a + seg * t - c).length() < 2.0 * radius
    }))
}
