//! The HUD: a strip along the top of the 3D view, right of the panel, that the table's
//! viewport leaves free ([`ViewInset::top`]), so it never covers a pocket, a ball or the
//! computer's aim. Its buttons come first and keep their places in every state (disabled when
//! they do not apply); then three columns of text: the match in play (`super::game`), the
//! table (shots, pocketed balls, what it is doing) and the solver with the notes (the last
//! one of the simulation, a miscue, a clamped value). The strip grows to hold its tallest
//! column (issue 48: lines were cut mid-sentence in a foul, a call, the computer's turn), up
//! to [`HUD_MAX_SHARE`] of the window, past which a column scrolls; the table's viewport
//! starts below it ([`ViewInset::top`]).

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

/// The most of the window's height the HUD takes; past it a column scrolls.
pub const HUD_MAX_SHARE: f32 = 0.4;

/// The HUD's height and what its lines need, for the layout check: every line of every
/// column shows whole when `needed <= height`.
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq)]
pub struct HudFit {
    /// The strip's height now (logical pixels).
    pub height: f32,
    /// The height its tallest column needs.
    pub needed: f32,
}

/// The strip's height for content that needs `needed` in a window `screen` high: at least
/// [`HUD_HEIGHT`], at most [`HUD_MAX_SHARE`] of the window.
pub fn hud_height(needed: f32, screen: f32) -> f32 {
    let cap = (HUD_MAX_SHARE * screen).max(HUD_HEIGHT);
    needed.clamp(HUD_HEIGHT, cap)
}

/// The HUD strip along the top of the 3D view.
pub fn hud(
    mut contexts: EguiContexts,
    mut state: HudParam,
    mut game: super::game::GameParam,
    (mut inset, mut fit): (ResMut<ViewInset>, ResMut<HudFit>),
) -> Result {
    let ctx = contexts.ctx_mut()?.clone();
    let status = state.status.clone();
    // Sized by what the last pass needed: a growing HUD takes one more pass (asked for below).
    let height = hud_height(fit.needed, ctx.viewport_rect().height());
    let place = (inset.left, Edge::Top, height);
    let mut needed = fit.needed;
    strip(&ctx, "hud", place, |ui| {
        let replay = *state.mode.get() == GameMode::Replay;
        let strip_top = ui.min_rect().top();
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
        // Above the columns: the buttons and the frame's margin below them.
        let above = ui.cursor().top() - strip_top + 12.0;
        ui.horizontal_top(|ui| {
            let a = column(ui, "hud-match", widths[0], height, &match_lines);
            ui.separator();
            let mut table = table_lines;
            let names = super::game::table_game(&game);
            table.extend(table_state_lines(&state, &status, (replay, names)));
            let b = column(ui, "hud-table", widths[1], height, &table);
            ui.separator();
            let solver = solver_lines(&state, &status, replay);
            // The rest of the strip, whatever the separators took.
            let rest = ui.available_width();
            ui.vertical(|ui| {
                ui.set_width(rest.max(40.0));
                let dismiss = !state.report.notes.is_empty();
                // Room for the dismiss button only when it is shown: reserved always, it
                // cut the last line of a scratch note that the height below said fitted.
                let button = if dismiss { 20.0 } else { 0.0 };
                let c = column(ui, "hud-solver", rest, height - button, &solver);
                if dismiss && ui.small_button("dismiss").clicked() {
                    state.report.notes.clear();
                }
                needed = above + a.max(b).max(c + button);
            });
        });
    });
    // A change of a pixel or more resizes the strip at the next pass: egui's multi-pass mode
    // discards this one, so no frame shows the HUD cut (and the next frame if egui has no
    // pass left this frame).
    if (needed - fit.needed).abs() >= 1.0 {
        ctx.request_discard("the HUD's lines changed its height");
        ctx.request_repaint();
    }
    fit.set_if_neq(HudFit { height, needed });
    if inset.top != height {
        inset.top = height;
    }
    Ok(())
}

/// One column of lines, wrapped to `width`, scrolling past `height`; the height its lines
/// need.
fn column(ui: &mut egui::Ui, id: &str, width: f32, height: f32, lines: &[HudLine]) -> f32 {
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
            })
            .content_size
            .y
    })
    .inner
}

/// How to aim and shoot, in the HUD whenever a human may: a newcomer should not have to find
/// the Controls section at the bottom of the panel (issue 28, item 8).
const HOW_TO_SHOOT: &str = "aim: drag on the table or Left/Right; power: Up/Down or Shift+wheel; cue elevation: E/D; \
     shoot: Space";

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
fn table_state_lines(
    state: &HudParam,
    status: &SimStatus,
    (replay, names): (bool, &billiards_rules::catalog::GameEntry),
) -> Vec<HudLine> {
    let mut pocketed: Vec<u8> = state.pocketed.iter().map(|b| b.number).collect();
    pocketed.sort_unstable();
    // Named by the game whose table it is (issue 48: "pocketed: 12" read as a count).
    let list = names.list_words(&pocketed);
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
            // A replay's HUD is the recording's: the live stress table waits below it.
            .then(|| stress_lines(&state.stress))
            .filter(|_| !replay)
            .into_iter()
            .flatten(),
    )
    .collect()
}

/// The solver and the frames, then the notes.
fn solver_lines(state: &HudParam, status: &SimStatus, replay: bool) -> Vec<HudLine> {
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
    if state.stress.active && !replay {
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

#[cfg(test)]
mod tests {
    // Named from the crate root: a `super::` path reads as a use of `ui` in the layout test.
    use crate::ui::hud::{HUD_MAX_SHARE, hud_height};
    use crate::ui::layout::HUD_HEIGHT;

    /// The HUD holds what its lines need, from its own height up to its share of the window.
    #[test]
    fn the_hud_grows_to_its_lines_within_its_share() {
        assert_eq!(hud_height(0.0, 720.0), HUD_HEIGHT);
        assert_eq!(hud_height(200.0, 720.0), 200.0);
        assert_eq!(hud_height(1000.0, 720.0), HUD_MAX_SHARE * 720.0);
        // A window too small for the share still gets the HUD's own height.
        assert_eq!(hud_height(1000.0, 200.0), HUD_HEIGHT);
    }
}
