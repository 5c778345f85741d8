//! The Stress table section of the panel: the ball count, friction, seed and table size, and
//! the button that racks it (free play; asks first when a game is in progress). Typed values
//! beyond the sliders are passed on, so the physics crate's refusal (no balls, too many for
//! the table) is what the player reads, here and in the HUD.

use bevy::prelude::*;
use bevy_egui::egui;

use super::layout::{BUTTON_WIDTH, WARNING};
use crate::{
    sim::{Referee, Solver},
    stress::{BALLS, SCALES, StressMonitor, StressRequested, StressSettings},
};
use billiards_physics::{Table, racks::stress_scale};

/// A stress table asked for while a game is in progress, waiting for the player's yes.
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StressConfirm(pub bool);

/// What the section edits and shows.
#[derive(bevy::ecs::system::SystemParam)]
pub struct StressParam<'w> {
    settings: ResMut<'w, StressSettings>,
    monitor: Res<'w, StressMonitor>,
    referee: Res<'w, Referee>,
    solver: Option<Res<'w, Solver>>,
    confirm: ResMut<'w, StressConfirm>,
    requests: MessageWriter<'w, StressRequested>,
    open_all: Res<'w, super::settings::OpenSections>,
}

/// The section's rows (always the same rows, so nothing moves under the pointer).
pub fn section(ui: &mut egui::Ui, state: &mut StressParam) {
    let open = state.open_all.0;
    super::settings::section(ui, "Stress table", open, |ui| rows(ui, state));
}

fn rows(ui: &mut egui::Ui, state: &mut StressParam) {
    let free_play = state.referee.edits;
    let mut next = *state.settings;
    ui.add_enabled_ui(free_play, |ui| {
        ui.add(
            egui::Slider::new(&mut next.balls, BALLS)
                .logarithmic(true)
                .update_while_editing(false)
                .clamping(egui::SliderClamping::Never)
                .text("balls"),
        );
        ui.horizontal(|ui| {
            ui.checkbox(&mut next.friction, "friction");
            ui.label("seed");
            ui.add(egui::DragValue::new(&mut next.seed).update_while_editing(false));
        });
        let mut auto = next.scale.is_none();
        ui.checkbox(&mut auto, "table grows with the count (16 balls per 8-ft)");
        let mut scale = next.scale.unwrap_or_else(|| stress_scale(next.balls));
        ui.add_enabled(
            !auto,
            egui::Slider::new(&mut scale, SCALES)
                .update_while_editing(false)
                .clamping(egui::SliderClamping::Never)
                .max_decimals(2)
                .text("x the 8-ft table"),
        );
        next.scale = (!auto).then_some(scale);
        let eight = Table::wpa_8ft();
        ui.label(format!(
            "table {:.1} x {:.1} m, pockets closed",
            eight.length * scale,
            eight.width * scale
        ));
        let button = egui::Button::new("Rack the stress table")
            .min_size(egui::vec2(BUTTON_WIDTH + 40.0, 0.0));
        if ui.add(button).clicked() {
            // A table that will be refused asks nothing first: the refusal says why at once.
            let builds = billiards_physics::racks::stress(&next.spec()).is_ok();
            if builds && state.solver.as_ref().is_some_and(|s| s.in_progress()) {
                state.confirm.0 = true;
            } else {
                state.requests.write(StressRequested);
            }
        }
    });
    // One line always: the refusal, or what is on the table, or how to start.
    let (line, colour) = match (&state.monitor.refused, &state.monitor.built) {
        (Some(why), _) => (why.clone(), Some(WARNING)),
        (None, Some(built)) if state.monitor.active => (
            format!(
                "on the table: {} balls, {}, seed {}",
                built.balls,
                if built.friction {
                    "friction"
                } else {
                    "frictionless"
                },
                built.seed
            ),
            None,
        ),
        _ if !free_play => ("free play only: not during a match".to_owned(), None),
        _ => ("the HUD shows its costs and checks".to_owned(), None),
    };
    match colour {
        Some(colour) => ui.colored_label(colour, line),
        None => ui.label(line),
    };
    state.settings.set_if_neq(next);
}

/// The question before the stress table replaces a game in progress.
pub fn confirm_window(ctx: &egui::Context, state: &mut StressParam) {
    if !state.confirm.0 {
        return;
    }
    egui::Window::new("Stress table?")
        .collapsible(false)
        .resizable(false)
        .anchor(egui::Align2::CENTER_CENTER, [0.0, 0.0])
        .show(ctx, |ui| {
            ui.label("Rack the stress table and end the game in progress? It is saved in the recordings.");
            ui.horizontal(|ui| {
                if ui.button("Rack").clicked() {
                    state.requests.write(StressRequested);
                    state.confirm.0 = false;
                }
                if ui.button("Cancel").clicked() {
                    state.confirm.0 = false;
                }
            });
        });
}
