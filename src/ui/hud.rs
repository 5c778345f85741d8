//! The HUD: a strip along the top of the 3D view, right of the panel, that the table's
//! viewport leaves free ([`ViewInset::top`]), so it never covers a pocket, a ball or the
//! computer's aim. Its buttons come first and keep their places in every state (disabled when
//! they do not apply); then three columns of text: the match in play (`super::game`), the
//! table (shots, pocketed balls, what it is doing) and the solver with the notes (the last
//! one of the simulation, a miscue, a clamped value). A column that overflows scrolls; the
//! strip never grows.

use bevy::{diagnostic::FrameCount, prelude::*};
use bevy_egui::{EguiContexts, egui};

use super::layout::{Edge, HUD_HEIGHT, HudLine, INFO, WARNING, strip};
use crate::{
    mode::GameMode,
    play::aim::AimPrediction,
    settings::{ClampReport, PhysicsSettings},
    sim::SimStatus,
    stress::{ENERGY_RISE_WARNING, OVERLAP_WARNING, StressMonitor},
    table::balls::{Ball, Pocketed},
    view::{ViewInset, graphics::FrameRate, pipelines::PipelineProgress},
};

/// What the HUD shows.
#[derive(bevy::ecs::system::SystemParam)]
pub struct HudParam<'w, 's> {
    status: Res<'w, SimStatus>,
    physics: Res<'w, PhysicsSettings>,
    pocketed: Query<'w, 's, &'static Ball, With<Pocketed>>,
    mode: Res<'w, State<GameMode>>,
    frames: Res<'w, FrameCount>,
    time: Res<'w, Time<Real>>,
    rate: Res<'w, FrameRate>,
    aim: Res<'w, AimPrediction>,
    report: ResMut<'w, ClampReport>,
    pipelines: Option<Res<'w, PipelineProgress>>,
    stress: Res<'w, StressMonitor>,
}

/// The HUD strip along the top of the 3D view.
pub fn hud(
    mut contexts: EguiContexts,
    mut state: HudParam,
    mut game: super::game::GameParam,
    mut inset: ResMut<ViewInset>,
) -> Result {
    let ctx = contexts.ctx_mut()?.clone();
    let status = state.status.clone();
    let place = (inset.left, Edge::Top, HUD_HEIGHT);
    strip(&ctx, "hud", place, |ui| {
        let replay = *state.mode.get() == GameMode::Replay;
        let (mut match_lines, table_lines) = if replay {
            let replay = "replaying a recording: the live game below waits";
            (vec![(replay.to_owned(), Some(INFO))], Vec::new())
        } else {
            super::game::hud_lines(&game)
        };
        if let Some(line) = loading_line(state.pipelines.as_deref()) {
            match_lines.insert(0, (line, Some(WARNING)));
        }
        let may_shoot = super::game::human_to_shoot(&game) || super::game::free_play(&game);
        if may_shoot && !replay {
            match_lines.push((HOW_TO_SHOOT.to_owned(), None));
        }
        // The buttons first, always in the same places.
        super::game::hud_buttons(ui, &mut game);
        let height = ui.available_height();
        let width = ui.available_width();
        let widths = [0.36 * width, 0.30 * width];
        ui.horizontal_top(|ui| {
            column(ui, "hud-match", widths[0], height, &match_lines);
            ui.separator();
            let mut table = table_lines;
            table.extend(table_state_lines(&state, &status));
            column(ui, "hud-table", widths[1], height, &table);
            ui.separator();
            let solver = solver_lines(&state, &status);
            // The rest of the strip, whatever the separators took.
            let rest = ui.available_width();
            ui.vertical(|ui| {
                ui.set_width(rest.max(40.0));
                column(ui, "hud-solver", rest, height - 20.0, &solver);
                if !state.report.notes.is_empty() && ui.small_button("dismiss").clicked() {
                    state.report.notes.clear();
                }
            });
        });
    });
    if inset.top != HUD_HEIGHT {
        inset.top = HUD_HEIGHT;
    }
    Ok(())
}

/// One column of lines, wrapped to `width`, scrolling past `height`.
fn column(ui: &mut egui::Ui, id: &str, width: f32, height: f32, lines: &[HudLine]) {
    ui.vertical(|ui| {
        ui.set_width(width.max(40.0));
        egui::ScrollArea::vertical()
            .id_salt(id)
            .max_height(height.max(20.0))
            .auto_shrink([false, true])
            .show(ui, |ui| {
                ui.spacing_mut().item_spacing.y = 1.0;
                for (text, colour) in lines {
                    match colour {
                        Some(colour) => ui.colored_label(*colour, text),
                        None => ui.label(text),
                    };
                }
            });
    });
}

/// How to aim and shoot, in the HUD whenever a human may: a newcomer should not have to find
/// the Controls section at the bottom of the panel (issue 28, item 8).
const HOW_TO_SHOOT: &str =
    "aim: drag on the table or Left/Right; power: Up/Down or Shift+wheel; shoot: Space";

/// While the renderer still compiles its shaders (seconds on a software renderer) the table
/// is drawn unlit: say so, with the progress.
fn loading_line(progress: Option<&PipelineProgress>) -> Option<String> {
    let (total, waiting) = progress?.counts();
    (total == 0 || waiting > 0).then(|| {
        format!(
            "preparing the renderer: {} of {total} shaders ready (the table looks unlit until then)",
            total - waiting
        )
    })
}

/// The table: shots, pocketed balls, what it is doing.
fn table_state_lines(state: &HudParam, status: &SimStatus) -> Vec<HudLine> {
    let mut pocketed: Vec<u8> = state.pocketed.iter().map(|b| b.number).collect();
    pocketed.sort_unstable();
    let list = if pocketed.is_empty() {
        "none".to_owned()
    } else {
        pocketed
            .iter()
            .map(|&n| {
                if n == 0 {
                    "cue".to_owned()
                } else {
                    n.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let doing = if state.physics.paused {
        "paused"
    } else if status.at_rest {
        "at rest: ready to shoot"
    } else {
        "balls moving"
    };
    vec![
        (format!("shots: {}, pocketed: {list}", status.shots), None),
        (doing.to_owned(), None),
    ]
    .into_iter()
    .chain(
        state
            .stress
            .active
            .then(|| stress_lines(&state.stress))
            .into_iter()
            .flatten(),
    )
    .collect()
}

/// The solver and the frames, then the notes.
fn solver_lines(state: &HudParam, status: &SimStatus) -> Vec<HudLine> {
    // The frame number shows whether the window redraws at idle (it should not); the frame
    // time is the last frame's, from its input to this one.
    let fps = match state.rate.fps {
        Some(fps) => format!("{fps:.1} fps"),
        None if status.at_rest => "idle: draws only on change".to_owned(),
        None => "measuring".to_owned(),
    };
    let mut lines = vec![
        (
            format!(
                "frame {}: {:.1} ms, {fps}",
                state.frames.0,
                state.time.delta_secs_f64() * 1e3
            ),
            None,
        ),
        (
            format!(
                "simulated {:.3} s, {} events this shot, solver {:.3} ms/frame",
                status.sim_time,
                status.events_this_shot,
                status.solver_seconds_last_frame * 1e3
            ),
            None,
        ),
    ];
    if state.stress.active {
        let m = &state.stress;
        let share = if m.frame_ms > 0.0 {
            format!(" ({:.1} % of the frame)", 100.0 * m.solver_ms / m.frame_ms)
        } else {
            String::new()
        };
        lines.insert(
            1,
            (
                format!(
                    "stress: {:.0} events/s, solver {:.2} ms{share}, checks {:.2} ms",
                    m.events_per_second, m.solver_ms, m.checks_ms
                ),
                Some(INFO),
            ),
        );
    }
    if let Some(note) = &status.note {
        lines.push((note.clone(), Some(WARNING)));
    }
    if let Some(note) = &state.aim.note {
        lines.push((format!("aim: {note}"), Some(WARNING)));
    }
    for note in &state.report.notes {
        lines.push((note.to_string(), Some(WARNING)));
    }
    lines
}

/// The stress table's live checks: the balls, the energy (it may only fall, and without
/// friction stays) and the deepest overlap; its costs are in the solver's column.
fn stress_lines(m: &StressMonitor) -> Vec<HudLine> {
    let rise_bad = m.worst_energy_rise > ENERGY_RISE_WARNING;
    let overlap_bad = m.worst_overlap > OVERLAP_WARNING;
    vec![
        (
            format!(
                "stress table: {} balls, {:.1} x {:.1} m",
                m.on_table, m.table.0, m.table.1
            ),
            Some(INFO),
        ),
        (
            format!(
                "energy {:.3} J (from {:.3}), worst rise {:.0e}{}",
                m.energy,
                m.energy_start,
                m.worst_energy_rise,
                if rise_bad { ": it rose!" } else { ": ok" }
            ),
            rise_bad.then_some(WARNING),
        ),
        (
            if m.worst_overlap > 0.0 {
                format!(
                    "overlap now {:.0e} m, worst {:.0e} m{}",
                    m.overlap,
                    m.worst_overlap,
                    if overlap_bad { ": balls overlap!" } else { "" }
                )
            } else {
                "overlap: none (a sweep each frame)".to_owned()
            },
            overlap_bad.then_some(WARNING),
        ),
    ]
}
