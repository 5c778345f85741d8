//! Judging an attempt from its shots ([`Drill::judge`]) and the tally of a session
//! ([`DrillScore`]).

use super::definition::Drill;
use super::goal::Goal;
use super::shot::DrillShot;
use crate::game::Game;
use crate::shot::CUE;
use billiards_physics::{Pocket, Vec2};
use serde::{Deserialize, Serialize};

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
                if s.summary.cue_off_table() {
                    out.push(format!("shot {n}: the cue ball was driven off the table"));
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
                !s.summary.scratch()
                    && !s.summary.cue_off_table()
                    && s.summary.first_contact.is_some()
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
