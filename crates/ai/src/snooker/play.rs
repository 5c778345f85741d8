//! A whole snooker frame between two computer players, headless: what `billiards-cli
//! tournament --game snooker` runs on every core and `simulate --game snooker` records.
//!
//! The table is the WPBSA 12-ft table with [`Params::snooker`]; the balls start as 3.2 sets
//! them, the cue ball in the D. Every stroke: the choices the rules offer, the player's
//! decision, the cue ball placed in the D when in hand, the strike with the player's
//! execution noise, run to rest, judged by [`Frame::play`], the verdict's colours spotted
//! (3.6); a replace (3.14) puts every ball back. With a recording every placement is an input,
//! so [`FrameLog::check`] re-judges the frame from it.

use super::{SnookerDecision, SnookerPlan, decide_snooker};
use crate::level::Level;
use crate::noise::stream;
use billiards_physics::recording::{Recorder, Recording};
use billiards_physics::snooker::{default_cue_position, layout};
use billiards_physics::{BallId, Params, Shot, Simulation, Table, Vec2, Vec3};
use billiards_rules::snooker::balls::WHITE;
use billiards_rules::snooker::geometry::replace_moves;
use billiards_rules::snooker::{Choice, Frame, FrameLog, LoggedStroke, Stroke, Verdict};
use billiards_rules::{Seat, ShotSummary, summarise};
use rand::Rng;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Most strokes a frame may take; then it is decided on points (a tie: no winner).
pub const MAX_STROKES: usize = 400;

/// The snooker table and parameters: the WPBSA 12-ft table, [`Params::snooker`].
pub fn snooker_table() -> (Table, Params) {
    (Table::snooker_12ft(), Params::snooker())
}

/// One player's figures in one frame.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct FrameTally {
    /// Strokes played.
    pub strokes: usize,
    /// Fouls committed.
    pub fouls: usize,
    /// Points scored by pots (penalties not included).
    pub potted_points: u32,
    /// Every break of at least one point (2.8), in order.
    pub breaks: Vec<u32>,
    /// Decisions taken (strokes and choices).
    pub decisions: usize,
    /// Seconds spent deciding, in all.
    pub decision_secs: f64,
    /// The longest decision, seconds.
    pub max_decision_secs: f64,
    /// Noisy simulations the decisions ran.
    pub simulations: usize,
}

/// The record of one frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrameRecord {
    /// The frame's index in its tournament.
    pub index: u64,
    /// The seed of every random draw in it.
    pub seed: u64,
    /// Who broke off, 0 or 1.
    pub breaker: usize,
    /// The winner, 0 or 1; `None`: level after [`MAX_STROKES`] strokes.
    pub winner: Option<usize>,
    /// The final scores.
    pub scores: [u32; 2],
    /// Strokes played.
    pub strokes: usize,
    /// How the frame ended.
    pub reason: String,
    /// Each player's figures.
    pub players: [FrameTally; 2],
}

/// A frame played: its record, the frame at the end, its rules log and, when asked for, the
/// recording of every input.
#[derive(Clone, Debug)]
pub struct FrameRun {
    /// The figures.
    pub record: FrameRecord,
    /// The frame as it ended.
    pub frame: Frame,
    /// The rules log (one stroke per strike).
    pub log: FrameLog,
    /// The recording (with `record`).
    pub recording: Option<Recording>,
}

/// The table of a frame: lean, or recorded input by input.
enum Table2 {
    Lean(Box<Simulation>),
    Recorded(Box<Recorder>),
}

impl Table2 {
    fn sim(&self) -> &Simulation {
        match self {
            Table2::Lean(s) => s,
            Table2::Recorded(r) => r.sim(),
        }
    }

    fn place(&mut self, id: BallId, p: Vec2) -> Result<(), String> {
        match self {
            Table2::Lean(s) => s.place(id, p, Vec2::ZERO, Vec3::ZERO),
            Table2::Recorded(r) => r.place(id, p, Vec2::ZERO, Vec3::ZERO),
        }
        .map_err(|e| format!("place ball {id} at ({:.4}, {:.4}): {e}", p.x, p.y))
    }

    /// Strikes the cue ball and runs to rest; the stroke's summary.
    fn strike(&mut self, id: BallId, shot: Shot) -> Result<ShotSummary, String> {
        match self {
            Table2::Lean(s) => {
                s.strike(id, shot).map_err(|e| e.to_string())?;
                let mut summary = ShotSummary::default();
                while let Some(e) = s.step_event() {
                    summary.record(&e.kind, s.numbers());
                }
                Ok(summary)
            }
            Table2::Recorded(r) => {
                let first = r.sim().history().events().len();
                r.strike(id, shot).map_err(|e| e.to_string())?;
                r.run_to_rest().map_err(|e| e.to_string())?;
                let sim = r.sim();
                Ok(summarise(&sim.history().events()[first..], sim.numbers()))
            }
        }
    }

    fn id(&self, n: u8) -> Result<BallId, String> {
        self.sim()
            .numbers()
            .iter()
            .position(|&m| m == n)
            .ok_or_else(|| format!("no ball {n}"))
    }

    /// Every ball of `balls` where it says, as the rules' replace asks (3.14), in the order
    /// of [`replace_moves`] (no placement on another ball).
    fn set_layout(&mut self, balls: &[(u8, Vec2)]) -> Result<(), String> {
        let sim = self.sim();
        let moves = replace_moves(&on_table(sim), balls, sim.params().ball.radius, sim.table())
            .ok_or("no room to move a ball aside for the replace")?;
        for (n, p) in moves {
            let id = self.id(n)?;
            self.place(id, p)?;
        }
        Ok(())
    }
}

fn on_table(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}

/// The choices the rules offer, taken one by one (a replace sets its layout), then the
/// stroke: each decision timed into `tally`, seeded by the `decisions` count.
fn plan_next(
    frame: &mut Frame,
    t: &mut Table2,
    levels: [Level; 2],
    seed: u64,
    decisions: &mut u64,
    tally: &mut [FrameTally; 2],
) -> Result<(SnookerPlan, Vec<Choice>), String> {
    let mut made = Vec::new();
    loop {
        let who = frame.next.striker.index();
        let started = Instant::now();
        let d = decide_snooker(
            frame,
            t.sim(),
            levels[who],
            stream(seed, 1, *decisions).random(),
        )
        .map_err(|e| format!("{}: {e}", levels[who]))?;
        *decisions += 1;
        let secs = started.elapsed().as_secs_f64();
        let tl = &mut tally[who];
        tl.decisions += 1;
        tl.decision_secs += secs;
        tl.max_decision_secs = tl.max_decision_secs.max(secs);
        match d {
            SnookerDecision::Choose { choice, .. } => {
                let chosen = frame.choose(choice).map_err(|e| e.to_string())?;
                if let Some(l) = chosen.layout {
                    t.set_layout(&l)?;
                }
                made.push(choice);
            }
            SnookerDecision::Shoot(plan) => return Ok((plan, made)),
        }
    }
}

/// Plays one frame between `levels` (`levels[0]` is seat A) named `names`, `breaker`
/// breaking off, every random draw from `seed`; with `record`, every input is recorded.
pub fn play_frame(
    levels: [Level; 2],
    names: [String; 2],
    index: u64,
    seed: u64,
    breaker: Seat,
    record: bool,
) -> Result<FrameRun, String> {
    let (table, params) = snooker_table();
    let marks = billiards_physics::SnookerMarks::of(&table)?;
    let balls = layout(&table, &params.ball, default_cue_position(&marks))?;
    let mut t = if record {
        Table2::Recorded(Box::new(
            Recorder::new(table, params, balls).map_err(|e| e.to_string())?,
        ))
    } else {
        let mut s = Simulation::new(table, params, &balls).map_err(|e| e.to_string())?;
        s.set_record_history(false);
        Table2::Lean(Box::new(s))
    };
    let mut frame =
        Frame::new(names.clone(), table, &params.ball, breaker).map_err(|e| e.to_string())?;
    let mut log = FrameLog::new(names, breaker);
    let mut tally: [FrameTally; 2] = Default::default();
    let mut current = [0u32; 2];
    let cue = t.id(WHITE)?;
    let mut strokes = 0;
    let mut decisions = 0u64;
    while frame.end.is_none() && strokes < MAX_STROKES {
        let (plan, made) = plan_next(&mut frame, &mut t, levels, seed, &mut decisions, &mut tally)
            .map_err(|e| format!("stroke {}: {e}", strokes + 1))?;
        let who = frame.next.striker.index();
        tally[who].simulations += plan.simulations;
        if let Some(p) = plan.place {
            t.place(cue, p)?;
        }
        let before = on_table(t.sim());
        let shot = plan.executed(
            levels[who].execution_noise(),
            t.sim().params(),
            stream(seed, 2, strokes as u64).random(),
        );
        let summary = t.strike(cue, shot)?;
        let after = on_table(t.sim());
        let verdict = frame
            .play(Stroke {
                summary: &summary,
                nominated: plan.nominated,
                before: &before,
                after: &after,
            })
            .map_err(|e| format!("stroke {}: {e}", strokes + 1))?;
        strokes += 1;
        count_stroke(&mut tally[who], &mut current[who], &verdict);
        for &(c, p) in &verdict.spots {
            let id = t.id(c)?;
            t.place(id, p)?;
        }
        log.strokes.push(LoggedStroke {
            choices: made,
            nominated: plan.nominated,
            verdict,
        });
    }
    for (who, c) in current.iter().enumerate() {
        if *c > 0 {
            tally[who].breaks.push(*c);
        }
    }
    let (winner, reason) = frame_winner(&frame);
    let recording = match &t {
        Table2::Recorded(r) => Some(r.recording()),
        Table2::Lean(_) => None,
    };
    Ok(FrameRun {
        record: FrameRecord {
            index,
            seed,
            breaker: breaker.index(),
            winner,
            scores: frame.scores,
            strokes,
            reason,
            players: tally,
        },
        frame,
        log,
        recording,
    })
}

/// Adds one judged stroke to its player's figures; a stroke that scores nothing ends the
/// player's break (`current`), which is then recorded, since breaks are counted as visits.
fn count_stroke(tl: &mut FrameTally, current: &mut u32, verdict: &Verdict) {
    tl.strokes += 1;
    tl.fouls += usize::from(!verdict.fair());
    tl.potted_points += verdict.points;
    if verdict.points > 0 {
        *current += verdict.points;
    } else if *current > 0 {
        tl.breaks.push(*current);
        *current = 0;
    }
}

/// The winner's seat index and how the frame ended; a frame cut off at [`MAX_STROKES`] goes
/// to the player ahead on points (none on a tie), so a stalled frame still has a result.
fn frame_winner(frame: &Frame) -> (Option<usize>, String) {
    match frame.end {
        Some((w, how)) => (Some(w.index()), how.to_string()),
        None => {
            let [a, b] = frame.scores;
            let w = (a != b).then_some(if a > b { 0 } else { 1 });
            (w, format!("on points after {MAX_STROKES} strokes"))
        }
    }
}
