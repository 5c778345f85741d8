//! The settings file and the controls at the end of the panel, and the windows over the
//! table: the settings file's error, the rack confirmation.

use bevy::prelude::*;
use bevy_egui::egui::{self, RichText};

use super::param::SettingsParam;
use super::widgets::section;
use crate::ui::layout::WARNING;
use crate::{
    config::reset_to_defaults,
    sim::{RackRequested, clock_seed, rack_label},
};

/// A settings file that could not be read or written is said where it is seen, over the table,
/// until the player has read it (the panel's "Settings file" section keeps the message).
pub fn config_error_window(
    ctx: &egui::Context,
    state: &SettingsParam,
    read: &mut Option<String>,
    hud_bottom: f32,
) {
    let Some(error) = &state.config.error else {
        return;
    };
    if read.as_ref() == Some(error) {
        return;
    }
    if crate::ui::layout::warning_window(ctx, "Settings file", error, hud_bottom) {
        *read = Some(error.clone());
    }
}

/// The settings file (where it is, why it could not be read), the reset, and the list of
/// controls, at the end of the panel.
pub fn file_and_controls(ui: &mut egui::Ui, state: &mut SettingsParam) {
    let all = state.open_all.0;
    section(ui, "Settings file", all, |ui| {
        match &state.config.path {
            Some(path) => ui.label(RichText::new(format!("kept in {}", path.display())).weak()),
            None => ui.label(RichText::new("not kept (--no-config)").weak()),
        };
        if let Some(error) = &state.config.error {
            ui.colored_label(WARNING, error);
        }
        if ui
            .button("Reset to defaults")
            .on_hover_text("physics, view and graphics settings (not the shot)")
            .clicked()
        {
            reset_to_defaults(&mut state.physics, &mut state.view, &mut state.graphics);
            state.report.notes.clear();
        }
    });
    section(ui, "Controls", all, |ui| {
        ui.label(
            "Left drag on the table: aim\n\
             Shift + left drag down, Shift + wheel: power\n\
             Arrows: aim (Shift: fine) and power\n\
             E / D: raise / lower the cue (a jump, a masse)\n\
             Space: shoot\n\
             Right or middle drag: orbit; wheel: zoom\n\
             T: top view; F: follow the cue ball; Home: reset view",
        );
    });
}

/// The question before a rack replaces a game in progress, in a window of its own (it pushes
/// nothing in the panel).
pub fn rack_confirm_window(ctx: &egui::Context, state: &mut SettingsParam) {
    let Some(rack) = state.confirm.0 else {
        return;
    };
    egui::Window::new("New rack?")
        .collapsible(false)
        .resizable(false)
        .anchor(egui::Align2::CENTER_CENTER, [0.0, 0.0])
        .show(ctx, |ui| {
            ui.label(format!(
                "Rack the {} and end the game in progress? It is saved in the recordings.",
                rack_label(rack)
            ));
            ui.horizontal(|ui| {
                if ui.button("Rack").clicked() {
                    state.racks.write(RackRequested::fresh(rack, clock_seed()));
                    state.confirm.0 = None;
                }
                if ui.button("Cancel").clicked() {
                    state.confirm.0 = None;
                }
            });
        });
}
