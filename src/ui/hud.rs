//! The HUD in the top-right corner of the 3D view: the match in play (`super::game`), shots,
//! simulated time, events, the solver's cost per frame, the pocketed balls, what the table
//! is doing, the frame rate, and the notes (the last one of the simulation, a miscue, a
//! clamped value): transient text goes here, at the bottom of the HUD, where it pushes nothing.

use bevy::{diagnostic::FrameCount, prelude::*};
use bevy_egui::{EguiContexts, egui};

use super::layout::{HUD_WIDTH, INFO, WARNING, WINDOW_MARGIN};
use crate::{
    aim::AimPrediction,
    balls::{Ball, Pocketed},
    graphics::FrameRate,
    mode::GameMode,
    settings::{ClampReport, PhysicsSettings},
    sim::SimStatus,
};

/// Opacity of the HUD's background (its text stays opaque).
const HUD_OPACITY: f32 = 0.6;

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
}

/// The HUD in the top-right corner: shot count, times, events, solver cost, pocketed balls.
pub fn hud(
    mut contexts: EguiContexts,
    mut state: HudParam,
    mut game: super::game::GameParam,
) -> Result {
    let ctx = contexts.ctx_mut()?.clone();
    let status = state.status.clone();
    // See-through: at 1280x720 the HUD lies over the foot-right corner of the table, and a
    // player aiming there (or following a hint there) must see the pocket and the balls.
    let frame = egui::Frame::window(&ctx.global_style()).multiply_with_opacity(HUD_OPACITY);
    egui::Window::new("HUD")
        .title_bar(false)
        .frame(frame)
        .resizable(false)
        // One width, whatever the text: long notes wrap inside it instead of running off.
        .min_width(HUD_WIDTH)
        .max_width(HUD_WIDTH)
        .anchor(egui::Align2::RIGHT_TOP, [-WINDOW_MARGIN, WINDOW_MARGIN])
        .show(&ctx, |ui| {
            if *state.mode.get() == GameMode::Replay {
                ui.colored_label(INFO, "replaying a recording: the live game below waits");
            } else {
                super::game::hud_section(ui, &mut game);
            }
            // Two lines at most each, so the HUD covers as little of the table as it can. The
            // frame number shows whether the window redraws at idle (it should not); the
            // frame time is the last frame's, from its input to this one.
            let fps = match state.rate.fps {
                Some(fps) => format!("{fps:.1} fps"),
                None => "idle (draws only on change)".to_owned(),
            };
            ui.label(format!(
                "frame {}: {:.1} ms, {fps}",
                state.frames.0,
                state.time.delta_secs_f64() * 1e3
            ));
            ui.label(format!(
                "simulated {:.3} s, {} events this shot, solver {:.3} ms/frame",
                status.sim_time,
                status.events_this_shot,
                status.solver_seconds_last_frame * 1e3
            ));
            let mut pocketed: Vec<u8> = state.pocketed.iter().map(|b| b.number).collect();
            pocketed.sort_unstable();
            let list = if pocketed.is_empty() {
                "none".to_owned()
            } else {
                pocketed
                    .iter()
                    .map(|n| {
                        if *n == 0 {
                            "cue".to_owned()
                        } else {
                            n.to_string()
                        }
                    })
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            ui.label(format!("shots: {}, pocketed: {list}", status.shots));
            let state_text = if state.physics.paused {
                "paused"
            } else if status.at_rest {
                "at rest: ready to shoot"
            } else {
                "balls moving"
            };
            ui.label(state_text);
            if let Some(note) = &status.note {
                ui.colored_label(WARNING, note);
            }
            if let Some(note) = &state.aim.note {
                ui.colored_label(WARNING, format!("aim: {note}"));
            }
            if !state.report.notes.is_empty() {
                for note in &state.report.notes {
                    ui.colored_label(WARNING, note.to_string());
                }
                if ui.small_button("dismiss").clicked() {
                    state.report.notes.clear();
                }
            }
        });
    Ok(())
}
