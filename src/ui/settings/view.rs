//! The View and Graphics sections.

use bevy::prelude::*;
use bevy_egui::egui::{self, RichText};

use super::param::SettingsParam;
use crate::{
    settings::{GraphicsSettings, ViewSettings},
    view::camera::{CameraMode, OrbitCamera},
};

/// The View section: the vectors, the aiming aid and the camera mode.
pub(super) fn view_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
    ui.checkbox(
        &mut state.view.show_vectors,
        "show vectors (cue red, velocity blue)",
    );
    ui.checkbox(
        &mut state.view.show_aim,
        "aiming aid (path, ghost ball, paths after contact)",
    );
    ui.add_enabled_ui(state.view.show_aim, |ui| {
        ui.label("follow each ball after the first contact for:");
        ui.add(
            egui::Slider::new(&mut state.view.aid_contacts, ViewSettings::AID_CONTACTS)
                .update_while_editing(false)
                .suffix(" contacts"),
        );
    });
    ui.horizontal_wrapped(|ui| {
        let mut mode = state.orbit.mode;
        ui.selectable_value(&mut mode, CameraMode::Free, "orbit");
        ui.selectable_value(&mut mode, CameraMode::Top, "top (T)");
        ui.selectable_value(&mut mode, CameraMode::FollowCue, "follow cue (F)");
        if mode != state.orbit.mode {
            *state.orbit = match mode {
                CameraMode::Top => OrbitCamera::top_view().scaled(state.orbit.reach),
                CameraMode::Free => OrbitCamera::default().scaled(state.orbit.reach),
                CameraMode::FollowCue => OrbitCamera {
                    mode,
                    ..*state.orbit
                },
            };
        }
    });
}

/// The Graphics section: shadows, anti-aliasing, render scale.
pub(super) fn graphics_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
    let mut next = *state.graphics;
    ui.checkbox(&mut next.shadows, "shadows");
    ui.add_enabled_ui(next.shadows, |ui| {
        ui.horizontal(|ui| {
            ui.label("shadow map:");
            for size in GraphicsSettings::SHADOW_RESOLUTIONS {
                ui.selectable_value(&mut next.shadow_resolution, size, size.to_string());
            }
        });
    });
    ui.horizontal(|ui| {
        ui.label("anti-aliasing:");
        for samples in GraphicsSettings::MSAA_SAMPLES {
            let label = if samples == 1 {
                "off".to_owned()
            } else {
                format!("{samples}x")
            };
            ui.selectable_value(&mut next.msaa_samples, samples, label);
        }
    });
    ui.horizontal(|ui| {
        ui.label("render scale:");
        for percent in GraphicsSettings::RENDER_SCALES {
            ui.selectable_value(&mut next.render_scale, percent, format!("{percent} %"))
                .on_hover_text("the 3D view's resolution; the panels stay sharp");
        }
    });
    ui.horizontal(|ui| {
        if ui.button("Fastest").clicked() {
            next = GraphicsSettings::LOW;
        }
        if ui.button("Best").clicked() {
            next = GraphicsSettings::default();
        }
    });
    ui.label(RichText::new("the frame rate is in the HUD").weak());
    if next != *state.graphics {
        *state.graphics = next;
    }
}
