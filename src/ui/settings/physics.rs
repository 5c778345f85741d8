//! The Physics section.

use bevy_egui::egui;

use super::param::SettingsParam;
use super::widgets::{apply_physics_edit, param_slider};
use crate::settings::{
    BallFrictionChoice, CushionChoice, PREDICTIONS, PhysicsModel, PhysicsSettings, ShaftChoice,
    prediction_label,
};

/// The Physics section: the model, the friction and restitution constants, the predictions.
pub(super) fn physics_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
    let mut next = *state.physics;
    egui::ComboBox::from_label("model")
        .selected_text(next.model.label())
        .show_ui(ui, |ui| {
            for model in PhysicsModel::ALL {
                ui.selectable_value(&mut next.model, model, model.label());
            }
        });
    param_slider(ui, &mut next.mu_slide, PhysicsSettings::MU_SLIDE);
    param_slider(ui, &mut next.mu_roll, PhysicsSettings::MU_ROLL);
    // Only the paper's model switches friction at a threshold speed.
    ui.add_enabled_ui(next.model == PhysicsModel::Paper, |ui| {
        param_slider(
            ui,
            &mut next.slide_roll_speed,
            PhysicsSettings::SLIDE_ROLL_SPEED,
        );
    });
    param_slider(ui, &mut next.e_ball, PhysicsSettings::E_BALL);
    param_slider(ui, &mut next.e_cushion, PhysicsSettings::E_CUSHION);
    // The spin model's constants: shown disabled under the paper's model, so rows stay.
    ui.add_enabled_ui(next.model == PhysicsModel::Spin, |ui| {
        param_slider(ui, &mut next.mu_spin, PhysicsSettings::MU_SPIN);
        egui::ComboBox::from_label("ball friction")
            .selected_text(next.ball_friction.label())
            .show_ui(ui, |ui| {
                for choice in BallFrictionChoice::ALL {
                    ui.selectable_value(&mut next.ball_friction, choice, choice.label());
                }
            });
        ui.add_enabled_ui(next.ball_friction == BallFrictionChoice::Constant, |ui| {
            param_slider(ui, &mut next.mu_ball, PhysicsSettings::MU_BALL);
        });
        let before = next.cushion;
        egui::ComboBox::from_label("cushion")
            .selected_text(next.cushion.label())
            .show_ui(ui, |ui| {
                for choice in CushionChoice::ALL {
                    ui.selectable_value(&mut next.cushion, choice, choice.label());
                }
            });
        // The sliders are shared: a newly chosen model starts from its authors' fit.
        if next.cushion != before
            && let Some((e, mu)) = next.cushion.fitted()
        {
            (next.e_cushion, next.mu_cushion) = (e, mu);
        }
        ui.add_enabled_ui(next.cushion != CushionChoice::Reflect, |ui| {
            param_slider(ui, &mut next.mu_cushion, PhysicsSettings::MU_CUSHION);
            param_slider(
                ui,
                &mut next.cushion_height,
                PhysicsSettings::CUSHION_HEIGHT,
            );
        });
        param_slider(ui, &mut next.cue_mass, PhysicsSettings::CUE_MASS);
        egui::ComboBox::from_label("shaft (squirt)")
            .selected_text(next.shaft.label())
            .show_ui(ui, |ui| {
                for choice in ShaftChoice::ALL {
                    ui.selectable_value(&mut next.shaft, choice, choice.label());
                }
            });
    });
    ui.checkbox(&mut next.jaws, "rounded pocket jaws (from the next rack)");
    ui.separator();
    ui.checkbox(
        &mut next.randomization.enabled,
        "randomize collision normals",
    );
    ui.add_enabled_ui(next.randomization.enabled, |ui| {
        param_slider(
            ui,
            &mut next.randomization.spread_degrees,
            PhysicsSettings::SPREAD,
        );
        ui.horizontal(|ui| {
            ui.label("seed");
            ui.add(egui::DragValue::new(&mut next.randomization.seed).update_while_editing(false));
        });
    });
    ui.separator();
    egui::ComboBox::from_label("contact times")
        .selected_text(prediction_label(next.prediction))
        .show_ui(ui, |ui| {
            for prediction in PREDICTIONS {
                ui.selectable_value(
                    &mut next.prediction,
                    prediction,
                    prediction_label(prediction),
                );
            }
        });
    apply_physics_edit(next, state);
}
