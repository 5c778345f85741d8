//! The settings panel's sections: the shot (angle, power, tip picker, ball in hand), friction
//! and restitution, the simulation clock and racks, the view; then clamp notes and controls.

use bevy::prelude::*;
use bevy_egui::egui::{self, Color32, RichText};

use super::layout::{TIP_PICKER_SIZE, WARNING};
use crate::{
    aim::AimPrediction,
    balls::{Ball, BallMotion, Pocketed},
    camera::{CameraMode, OrbitCamera},
    geometry::TableSpec,
    settings::{
        ClampReport, CushionChoice, PREDICTIONS, ParamRange, PhysicsModel, PhysicsSettings,
        ShotSettings, ViewSettings, apply_shot_edit, prediction_label,
    },
    sim::{
        RACKS, RackRequested, ShotRequested, SimStatus, StepRequested, move_ball_in_hand,
        rack_label,
    },
};

/// Everything the settings panel edits or shows, bundled so the system stays readable.
#[derive(bevy::ecs::system::SystemParam)]
pub struct SettingsParam<'w, 's> {
    shot: ResMut<'w, ShotSettings>,
    physics: ResMut<'w, PhysicsSettings>,
    view: ResMut<'w, ViewSettings>,
    report: ResMut<'w, ClampReport>,
    orbit: ResMut<'w, OrbitCamera>,
    status: Res<'w, SimStatus>,
    racks: MessageWriter<'w, RackRequested>,
    steps: MessageWriter<'w, StepRequested>,
    shots: MessageWriter<'w, ShotRequested>,
    aim: Res<'w, AimPrediction>,
    spec: Res<'w, TableSpec>,
    cue_ball: Query<'w, 's, (&'static Ball, &'static mut BallMotion), Without<Pocketed>>,
}

/// The panel's sections: shot, friction and restitution, simulation, view.
pub fn sections(ui: &mut egui::Ui, state: &mut SettingsParam) {
    ui.heading("Billiards");

    section(ui, "Shot", |ui| {
        let mut next = *state.shot;
        let mut degrees = next.angle.to_degrees();
        ui.add(
            egui::Slider::new(&mut degrees, 0.0..=360.0)
                .text("angle")
                .suffix(" deg")
                .max_decimals(2)
                .clamping(egui::SliderClamping::Never),
        );
        next.angle = degrees.to_radians();
        param_slider(ui, &mut next.power, ShotSettings::POWER);
        // The tip offset only matters to the spin model.
        ui.add_enabled_ui(state.physics.model == PhysicsModel::Spin, |ui| {
            ui.horizontal(|ui| {
                tip_picker(ui, &mut next.tip);
                ui.vertical(|ui| {
                    ui.label("Cue tip: click or drag\non the ball.");
                    ui.label(RichText::new("above: follow\nbelow: draw\nsides: english").weak());
                    if ui.small_button("centre").clicked() {
                        next.tip = Default::default();
                    }
                });
            });
            param_slider(ui, &mut next.tip.side, ShotSettings::TIP_SIDE);
            param_slider(ui, &mut next.tip.height, ShotSettings::TIP_HEIGHT);
        });
        if state.status.ball_in_hand == Some(billiards_rules::CueBall::Respot)
            && let Some(mut motion) = state
                .cue_ball
                .iter_mut()
                .find(|(b, _)| b.number == 0)
                .map(|(_, m)| m)
        {
            let limit = state.spec.width / 2.0 - state.spec.ball_radius;
            let mut y = motion.position.y;
            ui.add(
                egui::Slider::new(&mut y, -limit..=limit)
                    .text("ball in hand: along the head string")
                    .suffix(" m")
                    .max_decimals(3),
            );
            if y != motion.position.y {
                move_ball_in_hand(&state.spec, &mut motion, y);
            }
        }
        if let Some(note) = &state.aim.note {
            ui.colored_label(WARNING, note);
        }
        apply_shot_edit(next, &mut state.shot, &mut state.report);
        ui.horizontal(|ui| {
            let shoot = ui.add_enabled(state.status.at_rest, egui::Button::new("Shoot (Space)"));
            if shoot.clicked() {
                state.shots.write(ShotRequested::from_settings(&state.shot));
            }
            ui.label(RichText::new("when every ball rests").weak());
        });
    });

    section(ui, "Friction and restitution", |ui| {
        let mut next = *state.physics;
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
        if next.model == PhysicsModel::Spin {
            param_slider(ui, &mut next.mu_spin, PhysicsSettings::MU_SPIN);
            param_slider(ui, &mut next.mu_ball, PhysicsSettings::MU_BALL);
            egui::ComboBox::from_label("cushion")
                .selected_text(next.cushion.label())
                .show_ui(ui, |ui| {
                    for choice in CushionChoice::ALL {
                        ui.selectable_value(&mut next.cushion, choice, choice.label());
                    }
                });
            ui.add_enabled_ui(next.cushion == CushionChoice::Han2005, |ui| {
                param_slider(ui, &mut next.mu_cushion, PhysicsSettings::MU_CUSHION);
                param_slider(
                    ui,
                    &mut next.cushion_height,
                    PhysicsSettings::CUSHION_HEIGHT,
                );
            });
            param_slider(ui, &mut next.cue_mass, PhysicsSettings::CUE_MASS);
        }
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
                ui.add(egui::DragValue::new(&mut next.randomization.seed));
            });
        });
        ui.separator();
        egui::ComboBox::from_label("model")
            .selected_text(next.model.label())
            .show_ui(ui, |ui| {
                for model in PhysicsModel::ALL {
                    ui.selectable_value(&mut next.model, model, model.label());
                }
            });
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
    });

    section(ui, "Simulation", |ui| {
        let mut next = *state.physics;
        param_slider(ui, &mut next.time_scale, PhysicsSettings::TIME_SCALE);
        ui.horizontal(|ui| {
            let label = if next.paused { "Resume" } else { "Pause" };
            if ui.button(label).clicked() {
                next.paused = !next.paused;
            }
            let step = ui.add_enabled(next.paused, egui::Button::new("Step to next event"));
            if step.clicked() {
                state.steps.write(StepRequested);
            }
        });
        apply_physics_edit(next, state);
        ui.horizontal_wrapped(|ui| {
            for rack in RACKS {
                if ui.button(rack_label(rack)).clicked() {
                    state.racks.write(RackRequested(rack));
                }
            }
        });
    });

    section(ui, "View", |ui| {
        ui.checkbox(
            &mut state.view.show_vectors,
            "show vectors (cue red, velocity blue)",
        );
        ui.checkbox(
            &mut state.view.show_aim,
            "aiming aid (path, ghost ball, paths after contact)",
        );
        ui.add_enabled(
            state.view.show_aim,
            egui::Slider::new(&mut state.view.aid_contacts, ViewSettings::AID_CONTACTS)
                .text("contacts followed"),
        );
        ui.horizontal(|ui| {
            let mut mode = state.orbit.mode;
            ui.selectable_value(&mut mode, CameraMode::Free, "orbit");
            ui.selectable_value(&mut mode, CameraMode::Top, "top (T)");
            ui.selectable_value(&mut mode, CameraMode::FollowCue, "follow cue (F)");
            if mode != state.orbit.mode {
                *state.orbit = match mode {
                    CameraMode::Top => OrbitCamera::top_view(),
                    CameraMode::Free => OrbitCamera::default(),
                    CameraMode::FollowCue => OrbitCamera {
                        mode,
                        ..*state.orbit
                    },
                };
            }
        });
    });
}

/// The clamp notes (what was clamped and to what) and the list of controls, at the end of the
/// panel.
pub fn notes_and_controls(ui: &mut egui::Ui, state: &mut SettingsParam) {
    if !state.report.notes.is_empty() {
        ui.separator();
        for note in &state.report.notes {
            ui.colored_label(WARNING, note.to_string());
        }
        if ui.small_button("dismiss").clicked() {
            state.report.notes.clear();
        }
    }

    egui::CollapsingHeader::new("Controls")
        .default_open(false)
        .show(ui, |ui| {
            ui.label(
                "Left drag on the table: aim\n\
                 Shift + left drag down, Shift + wheel: power\n\
                 Arrows: aim (Shift: fine) and power\n\
                 Space: shoot\n\
                 Right or middle drag: orbit; wheel: zoom\n\
                 T: top view; F: follow the cue ball; Home: reset view",
            );
        });
}

/// The cue ball seen from behind the cue: click or drag where the tip should strike. The red
/// ring is the miscue limit; the blue dot is the tip (drawn to scale, 13 mm across).
fn tip_picker(ui: &mut egui::Ui, tip: &mut billiards_physics::TipOffset) {
    let size = TIP_PICKER_SIZE;
    let (response, painter) =
        ui.allocate_painter(egui::vec2(size, size), egui::Sense::click_and_drag());
    let centre = response.rect.center();
    let radius = size / 2.0 - 2.0;
    let enabled = ui.is_enabled();
    let ball = if enabled {
        Color32::from_rgb(240, 238, 228)
    } else {
        Color32::from_gray(120)
    };
    painter.circle_filled(centre, radius, ball);
    painter.circle_stroke(centre, radius, (1.0, Color32::DARK_GRAY));
    let limit = ShotSettings::tip_limit() as f32;
    painter.circle_stroke(
        centre,
        radius * limit,
        (1.0, Color32::from_rgb(200, 70, 70)),
    );
    let cross = Color32::from_gray(170);
    painter.line_segment(
        [
            centre - egui::vec2(radius, 0.0),
            centre + egui::vec2(radius, 0.0),
        ],
        (0.5, cross),
    );
    painter.line_segment(
        [
            centre - egui::vec2(0.0, radius),
            centre + egui::vec2(0.0, radius),
        ],
        (0.5, cross),
    );
    if enabled
        && (response.clicked() || response.dragged())
        && let Some(pointer) = response.interact_pointer_pos()
    {
        let offset = (pointer - centre) / radius;
        tip.side = f64::from(offset.x);
        tip.height = f64::from(-offset.y);
    }
    let at = centre + egui::vec2(tip.side as f32, -tip.height as f32) * radius;
    // A 13 mm tip on a 57.15 mm ball.
    painter.circle_filled(
        at,
        radius * 0.0065 / 0.028575,
        Color32::from_rgb(40, 90, 200),
    );
}

fn section(ui: &mut egui::Ui, title: &str, add_contents: impl FnOnce(&mut egui::Ui)) {
    egui::CollapsingHeader::new(title)
        .default_open(true)
        .show(ui, add_contents);
}

/// A slider with an editable number. Typing a value outside the physical range is allowed
/// here so that the clamp can be reported rather than silently swallowed.
fn param_slider(ui: &mut egui::Ui, value: &mut f64, range: ParamRange) {
    ui.add(
        egui::Slider::new(value, range.as_range())
            .text(range.label)
            .suffix(range.unit)
            .max_decimals(4)
            .clamping(egui::SliderClamping::Never),
    );
}

fn apply_physics_edit(mut next: PhysicsSettings, state: &mut SettingsParam) {
    if next == *state.physics {
        return;
    }
    let notes = next.clamp_to_physical();
    if !notes.is_empty() {
        state.report.notes = notes;
    }
    *state.physics = next;
}
