//! The egui panels: shot and physics settings on the left, the HUD on the right.
//!
//! The 3D view is fitted to the part of the window right of the panel, so the panel never
//! covers the table and a drag on the table never lands on the panel.

use bevy::{
    camera::{CameraOutputMode, Viewport, visibility::RenderLayers},
    prelude::*,
    render::render_resource::BlendState,
    window::PrimaryWindow,
};
use bevy_egui::{
    EguiContexts, EguiGlobalSettings, EguiPrimaryContextPass, PrimaryEguiContext,
    egui::{self, Color32, RichText},
};

use crate::{
    balls::{Ball, Pocketed},
    camera::{CameraMode, OrbitCamera, TableCamera},
    cue::apply_shot_edit,
    settings::{
        ClampReport, PREDICTIONS, ParamRange, PhysicsModel, PhysicsSettings, ShotSettings,
        ViewSettings, prediction_label,
    },
    sim::{RACKS, RackRequested, ShotRequested, SimStatus, StepRequested, rack_label},
};

/// Registers the panels.
pub fn plugin(app: &mut App) {
    app.add_systems(Startup, spawn_ui_camera)
        .add_systems(EguiPrimaryContextPass, panels);
}

/// Width of the settings panel, in logical pixels.
pub const PANEL_WIDTH: f32 = 310.0;

/// The egui context gets a camera of its own that draws nothing but the UI, on top of the
/// table camera; the table camera can then take a viewport beside the panel.
fn spawn_ui_camera(mut commands: Commands, mut egui_settings: ResMut<EguiGlobalSettings>) {
    egui_settings.auto_create_primary_context = false;
    commands.spawn((
        Name::new("UI camera"),
        PrimaryEguiContext,
        Camera2d,
        RenderLayers::none(),
        Camera {
            order: 1,
            output_mode: CameraOutputMode::Write {
                blend_state: Some(BlendState::ALPHA_BLENDING),
                clear_color: ClearColorConfig::None,
            },
            clear_color: ClearColorConfig::Custom(Color::NONE),
            ..default()
        },
    ));
}

/// Everything the panels edit or show, bundled so the system stays readable.
#[derive(bevy::ecs::system::SystemParam)]
struct PanelState<'w, 's> {
    shot: ResMut<'w, ShotSettings>,
    physics: ResMut<'w, PhysicsSettings>,
    view: ResMut<'w, ViewSettings>,
    report: ResMut<'w, ClampReport>,
    orbit: ResMut<'w, OrbitCamera>,
    status: Res<'w, SimStatus>,
    racks: MessageWriter<'w, RackRequested>,
    steps: MessageWriter<'w, StepRequested>,
    shots: MessageWriter<'w, ShotRequested>,
    pocketed: Query<'w, 's, &'static Ball, With<Pocketed>>,
    replay: crate::replay::panel::RecordingsParam<'w>,
}

fn panels(
    mut contexts: EguiContexts,
    mut state: PanelState,
    window: Single<&Window, With<PrimaryWindow>>,
    mut camera: Single<&mut Camera, With<TableCamera>>,
) -> Result {
    let ctx = contexts.ctx_mut()?.clone();
    let mut root = egui::Ui::new(
        ctx.clone(),
        "root".into(),
        egui::UiBuilder::new()
            .layer_id(egui::LayerId::background())
            .max_rect(ctx.viewport_rect()),
    );
    let panel_width = egui::Panel::left("settings")
        .resizable(false)
        .exact_size(PANEL_WIDTH)
        .show(&mut root, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| settings_panel(ui, &mut state));
        })
        .response
        .rect
        .width();
    hud(&ctx, &state);
    fit_viewport(&window, &mut camera, panel_width);
    Ok(())
}

/// Gives the table camera the window area right of the panel.
fn fit_viewport(window: &Window, camera: &mut Camera, panel_width: f32) {
    let left = ((panel_width * window.scale_factor()) as u32).min(window.physical_width() - 1);
    let viewport = Viewport {
        physical_position: UVec2::new(left, 0),
        physical_size: UVec2::new(
            window.physical_width() - left,
            window.physical_height().max(1),
        ),
        ..default()
    };
    let unchanged = camera.viewport.as_ref().is_some_and(|current| {
        current.physical_position == viewport.physical_position
            && current.physical_size == viewport.physical_size
    });
    if !unchanged {
        camera.viewport = Some(viewport);
    }
}

fn settings_panel(ui: &mut egui::Ui, state: &mut PanelState) {
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
        apply_shot_edit(next, &mut state.shot, &mut state.report);
        ui.horizontal(|ui| {
            let shoot = ui.add_enabled(state.status.at_rest, egui::Button::new("Shoot (Space)"));
            if shoot.clicked() {
                state.shots.write(ShotRequested {
                    angle: state.shot.angle,
                    speed: state.shot.power,
                });
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

    crate::replay::panel::recordings_section(ui, &mut state.replay);

    if !state.report.notes.is_empty() {
        ui.separator();
        for note in &state.report.notes {
            ui.colored_label(Color32::from_rgb(255, 170, 60), note.to_string());
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

fn apply_physics_edit(mut next: PhysicsSettings, state: &mut PanelState) {
    if next == *state.physics {
        return;
    }
    let notes = next.clamp_to_physical();
    if !notes.is_empty() {
        state.report.notes = notes;
    }
    *state.physics = next;
}

/// The HUD in the top-right corner: shot count, times, events, solver cost, pocketed balls.
fn hud(ctx: &egui::Context, state: &PanelState) {
    let status = &*state.status;
    egui::Window::new("HUD")
        .title_bar(false)
        .resizable(false)
        .anchor(egui::Align2::RIGHT_TOP, [-10.0, 10.0])
        .show(ctx, |ui| {
            ui.label(format!("shots: {}", status.shots));
            ui.label(format!("simulated time: {:.3} s", status.sim_time));
            ui.label(format!("events this shot: {}", status.events_this_shot));
            ui.label(format!(
                "solver: {:.3} ms/frame",
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
            ui.label(format!("pocketed: {list}"));
            let state_text = if state.physics.paused {
                "paused"
            } else if status.at_rest {
                "at rest: ready to shoot"
            } else {
                "balls moving"
            };
            ui.label(state_text);
            if let Some(note) = &status.note {
                ui.colored_label(Color32::from_rgb(255, 170, 60), note);
            }
        });
}
