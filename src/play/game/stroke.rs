//! The last stroke on the table judged by a game behind the interface: the solver's events
//! from its strike and the layouts at the strike and at rest, as a [`StrokeRecord`]. The
//! match's flow and a drill session judge their strokes through it, and log them.

use billiards_physics::{EventKind, Simulation};
use billiards_rules::{
    Declaration, GameRules, Judgement, RulesError, StrokeEntry, StrokeLog, StrokeRecord,
};

use super::put::layout_at;
use crate::{
    recording::{RecordingsFolder, save_rules_log},
    sim::{SimStatus, Solver},
};

/// Judges the last stroke of `sim` (from its last strike) with `game`, `declared` having
/// been declared for it; `None` when nothing was struck.
pub fn judge_last_stroke(
    game: &mut dyn GameRules,
    sim: &Simulation,
    declared: Declaration,
) -> Option<Result<Judgement, RulesError>> {
    let events = sim.history().events();
    let strike = events
        .iter()
        .rposition(|e| matches!(e.kind, EventKind::Strike { .. }))?;
    let before = layout_at(sim, Some(events[strike].time));
    let after = layout_at(sim, None);
    Some(game.judge(&StrokeRecord {
        events: &events[strike..],
        numbers: sim.numbers(),
        before: &before,
        after: &after,
        declared,
    }))
}

/// Adds a judged stroke (`entry`) to the recording's `log` and saves the log beside the
/// recording (a failure is said in the status line).
pub fn log_stroke(
    log: &mut StrokeLog,
    entry: StrokeEntry,
    (folder, solver): (&RecordingsFolder, &Solver),
    status: &mut SimStatus,
) {
    log.strokes.push(entry);
    save_rules_log(folder, solver, StrokeLog::path_beside, log, status);
}
