//! A whole snooker frame between two computer players, headless: what `billiards-cli
//! tournament --game snooker` runs on every core and `simulate --game snooker` records.
//!
//! The table is the WPBSA 12-ft table with [`Params::snooker`]; the frame is a
//! [`SnookerGame`] of one frame played by the match loop every game shares
//! ([`crate::any_match`]): the options the rules offer, the player's decision, the cue ball
//! placed in the D when in hand, the strike with the player's execution noise, judged
//! through the interface, the colours spotted (3.6), a replace (3.14) set ball by ball.
//! With a recording every placement is an input, so [`StrokeLog::check`] re-judges the frame
//! from it.

use crate::Player;
use crate::any_match::{Seating, play_match};
use crate::level::Level;
use billiards_physics::recording::Recording;
use billiards_physics::{Params, Table};
use billiards_rules::snooker::Frame;
use billiards_rules::snooker::rules::SnookerGame;
use billiards_rules::{GameRules, Seat, StrokeLog};
use serde::{Deserialize, Serialize};

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

/// A frame played: its record, the frame at the end and, when asked for, the recording of
/// every input and its rules log.
#[derive(Clone, Debug)]
pub struct FrameRun {
    /// The figures.
    pub record: FrameRecord,
    /// The frame as it ended.
    pub frame: Frame,
    /// The recording and its rules log (with `record`).
    pub recorded: Option<(Recording, StrokeLog)>,
}

/// Plays one frame between `levels` (`levels[0]` is player 0) named `names`, `breaker`
/// breaking off, every random draw from `seed`; with `record`, every input is recorded; each
/// stroke's verdict and option taken goes to `say`. The breaker sits in seat A, as the rules'
/// frame starts; the figures are given back by player.
pub fn play_frame(
    levels: [Level; 2],
    names: [String; 2],
    (index, seed): (u64, u64),
    breaker: Seat,
    record: bool,
    say: &mut dyn FnMut(String),
) -> Result<FrameRun, String> {
    let (table, params) = snooker_table();
    // Player `k` sits in seat `seat_of(k)`.
    let seat_of = |k: usize| if k == breaker.index() { 0 } else { 1 };
    let player_of = |seat: usize| {
        if seat == 0 {
            breaker.index()
        } else {
            1 - breaker.index()
        }
    };
    let seats = [player_of(0), player_of(1)];
    let mut game = SnookerGame::new(seats.map(|k| names[k].clone()), 1, table, params.ball)
        .map_err(|e| e.0)?;
    let seating = Seating {
        record,
        ..Seating::new(
            seats.map(|k| Player::Computer(levels[k])),
            params,
            seed,
            MAX_STROKES,
        )
    };
    let run = play_match(&mut game, &seating, say)?;
    let tally = |k: usize| {
        let t = &run.tally[seat_of(k)];
        FrameTally {
            strokes: t.strokes,
            fouls: t.fouls,
            potted_points: t.points,
            breaks: t.runs.clone(),
            decisions: t.decisions,
            decision_secs: t.decision_secs,
            max_decision_secs: t.max_decision_secs,
            simulations: t.simulations,
        }
    };
    let (winner, reason) = frame_winner(&game.frame);
    let scores = game.points();
    Ok(FrameRun {
        record: FrameRecord {
            index,
            seed,
            breaker: breaker.index(),
            winner: winner.map(player_of),
            scores: [scores[seat_of(0)], scores[seat_of(1)]],
            strokes: run.strokes,
            reason,
            players: [tally(0), tally(1)],
        },
        frame: game.frame,
        recorded: run.recorded.into_iter().next(),
    })
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
