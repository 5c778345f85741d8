//! Snooker's systems in the game's flow: judging a finished stroke, a replace.

use bevy::prelude::*;
use billiards_physics::{EventKind, Vec2};
use billiards_rules::snooker::{FrameLog, LoggedStroke, Stroke};
use billiards_rules::summarise;

use super::{free_place_in_d, layout_at, nomination, set_balls};
use crate::{
    play::game::state::Rules,
    recording::{RecordingsFolder, save_rules_log},
    sim::{ShotFinished, SimStatus, Solver},
    table::balls::{BallMotion, Pocketed},
};

/// On a finished stroke of a snooker match: summarise, judge, spot the colours, put a cue
/// ball in hand into the D.
#[allow(clippy::too_many_arguments)]
pub(crate) fn judge_stroke(
    mut commands: Commands,
    mut finished: MessageReader<ShotFinished>,
    mut rules: ResMut<Rules>,
    solver: Option<ResMut<Solver>>,
    mut balls: Query<(&mut BallMotion, Has<Pocketed>)>,
    mut status: ResMut<SimStatus>,
    folder: Res<RecordingsFolder>,
) {
    if finished.read().count() == 0 {
        return;
    }
    let (Some(game), Some(mut solver)) = (rules.snooker.as_mut(), solver) else {
        return;
    };
    let sim = solver.simulation();
    let events = sim.history().events();
    let Some(strike) = events
        .iter()
        .rposition(|e| matches!(e.kind, EventKind::Strike { .. }))
    else {
        return;
    };
    let summary = summarise(&events[strike..], sim.numbers());
    let before = layout_at(sim, Some(events[strike].time));
    let after = layout_at(sim, None);
    let nominated = nomination(&game.frame, game.nominated.take(), summary.first_contact);
    let verdict = match game.frame.play(Stroke {
        summary: &summary,
        nominated,
        before: &before,
        after: &after,
    }) {
        Ok(verdict) => verdict,
        Err(error) => {
            status.note = Some(format!("the rules refused the stroke: {error}"));
            return;
        }
    };
    game.log.strokes.push(LoggedStroke {
        choices: std::mem::take(&mut game.choices),
        nominated,
        verdict: verdict.clone(),
    });
    save_rules_log(
        &folder,
        &solver,
        FrameLog::path_beside,
        &game.log,
        &mut status,
    );
    if !verdict.fair() {
        // From the fouls, not the verdict's sentence, whose "foul: " would read "last foul:
        // foul: ..." (issue 48).
        let fouls: Vec<String> = verdict.fouls.iter().map(ToString::to_string).collect();
        game.last_foul = Some(format!(
            "{}{}: {} points to {}",
            fouls.join("; "),
            if verdict.miss { " (and a miss)" } else { "" },
            verdict.penalty,
            game.name(verdict.striker.other())
        ));
    }
    let spots = verdict.spots.clone();
    let in_hand = verdict.next.as_ref().is_some_and(|n| n.in_hand);
    game.last = Some(verdict);
    game.verdict_shown = true;
    game.count_the_frame();
    let mut moves: Vec<(u8, Vec2)> = spots;
    if in_hand && let Some(at) = free_place_in_d(solver.simulation()) {
        moves.push((0, at));
    }
    set_balls(
        &mut commands,
        &mut solver,
        &moves,
        &mut balls,
        &mut status,
        &|n| billiards_rules::snooker::balls::name(n).to_owned(),
    );
}

/// 3.14: a replace chosen: the balls go back where they were before the foul.
pub(crate) fn replace_balls(
    mut commands: Commands,
    mut rules: ResMut<Rules>,
    solver: Option<ResMut<Solver>>,
    mut balls: Query<(&mut BallMotion, Has<Pocketed>)>,
    mut status: ResMut<SimStatus>,
) {
    let (Some(game), Some(mut solver)) = (rules.snooker.as_mut(), solver) else {
        return;
    };
    let Some(layout) = game.pending_layout.take() else {
        return;
    };
    // Balls on the table now but not in the layout were potted then: none can be, as a
    // stroke pots balls and never adds one; the layout is every ball to set.
    set_balls(
        &mut commands,
        &mut solver,
        &layout,
        &mut balls,
        &mut status,
        &|n| billiards_rules::snooker::balls::name(n).to_owned(),
    );
}
