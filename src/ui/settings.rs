//! The settings panel's sections, play first: the shot (angle, power, tip picker, ball in
//! hand, shoot and undo), play (clock, racks), the view, graphics; then the physics in its own
//! section, the settings file and the controls.
//!
//! Rows keep their place: nothing in the panel appears or disappears with the game's state
//! (a row that does not apply is shown disabled), and notes (clamps, a miscue) go to the HUD,
//! so a click never lands on a widget that moved under the pointer.

use bevy::prelude::*;
use bevy_egui::egui::{self, Color32, RichText};
use billiards_physics::Rack;

use super::layout::{BUTTON_WIDTH, TIP_PICKER_SIZE, WARNING};
use crate::{
    config::{ConfigFile, reset_to_defaults},
    settings::{
        BallFrictionChoice, ClampReport, CushionChoice, GraphicsSettings, PREDICTIONS, ParamRange,
        PhysicsModel, PhysicsSettings, ShaftChoice, ShotSettings, TableSetup, ViewSettings,
        apply_shot_edit, prediction_label, shown_degrees, table_choices, table_label,
    },
    sim::{
        RACKS, RackRequested, Referee, ShotRequested, SimStatus, Solver, StepRequested,
        UndoRequested, clock_seed, move_ball_in_hand, rack_label,
    },
    stress::StressMonitor,
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
    view::camera::{CameraMode, OrbitCamera},
};

/// Open every section of the panel at start (`--open-sections`: screenshots, layout check).
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct OpenSections(pub bool);

/// A rack asked for while a game is in progress, waiting for the player's yes.
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RackConfirm(pub Option<Rack>);

/// Everything the settings panel edits or shows, bundled so the system stays readable.
#[derive(bevy::ecs::system::SystemParam)]
pub struct SettingsParam<'w, 's> {
    shot: ResMut<'w, ShotSettings>,
    physics: ResMut<'w, PhysicsSettings>,
    view: ResMut<'w, ViewSettings>,
    graphics: ResMut<'w, GraphicsSettings>,
    report: ResMut<'w, ClampReport>,
    orbit: ResMut<'w, OrbitCamera>,
    status: Res<'w, SimStatus>,
    solver: Option<Res<'w, Solver>>,
    referee: Res<'w, Referee>,
    config: Res<'w, ConfigFile>,
    confirm: ResMut<'w, RackConfirm>,
    open_all: Res<'w, OpenSections>,
    racks: MessageWriter<'w, RackRequested>,
    steps: MessageWriter<'w, StepRequested>,
    shots: MessageWriter<'w, ShotRequested>,
    undo: MessageWriter<'w, UndoRequested>,
    spec: Res<'w, TableSpec>,
    setup: ResMut<'w, TableSetup>,
    stress: Res<'w, StressMonitor>,
    cue_ball: Query<'w, 's, (&'static Ball, &'static mut BallMotion), Without<Pocketed>>,
}

/// The panel's sections, play options first, the physics after them.
pub fn sections(ui: &mut egui::Ui, state: &mut SettingsParam) {
    ui.heading("Billiards");
    let all = state.open_all.0;
    section(ui, "Shot", true, |ui| shot_section(ui, state));
    section(ui, "Play", true, |ui| play_section(ui, state));
    section(ui, "View", true, |ui| view_section(ui, state));
    section(ui, "Graphics", all, |ui| graphics_section(ui, state));
    section(ui, "Physics", all, |ui| physics_section(ui, state));
}

fn shot_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
    let mut next = *state.shot;
    let shown = shown_degrees(next.angle);
    let mut degrees = shown;
    ui.add(
        egui::Slider::new(&mut degrees, 0.0..=360.0)
            .update_while_editing(false)
            .text("angle")
            .suffix(" deg")
            .fixed_decimals(2)
            .clamping(egui::SliderClamping::Never),
    );
    // Only an edit moves the aim: the shown value is rounded.
    if degrees != shown {
        next.angle = degrees.to_radians();
    }
    // Power with two decimals, as the HUD, the hint and the replay show it.
    ui.add(range_slider(&mut next.power, ShotSettings::POWER).fixed_decimals(2));
    // The tip offset only matters to the spin model.
    ui.add_enabled_ui(state.physics.model == PhysicsModel::Spin, |ui| {
        ui.horizontal(|ui| {
            tip_picker(ui, &mut next.tip);
            ui.vertical(|ui| {
                ui.label("Cue tip: click or drag on the ball.");
                ui.label(RichText::new("above: follow\nbelow: draw\nsides: english").weak());
                if ui.small_button("centre").clicked() {
                    next.tip = Default::default();
                }
            });
        });
        param_slider(ui, &mut next.tip.side, ShotSettings::TIP_SIDE);
        param_slider(ui, &mut next.tip.height, ShotSettings::TIP_HEIGHT);
        // Raised butt: with english the ball curves (swerve); the aiming aid draws the curve.
        param_slider(ui, &mut next.elevation, ShotSettings::ELEVATION);
    });
    // Always there, disabled unless the cue ball is in hand after a free-play scratch, so the
    // rows below never move.
    let in_hand = state.status.ball_in_hand == Some(crate::sim::HandRule::Respot);
    let limit = state.spec.width / 2.0 - state.spec.ball_radius;
    let cue = state
        .cue_ball
        .iter_mut()
        .find(|(b, _)| b.number == 0)
        .map(|(_, m)| m);
    // Greyed out, it shows the head spot's 0 rather than the moving cue ball's y, which
    // changed under the pointer while nothing could be done with it.
    let mut y = cue
        .as_ref()
        .filter(|_| in_hand)
        .map_or(0.0, |m| m.position.y);
    ui.add_enabled_ui(in_hand && cue.is_some(), |ui| {
        ui.label("ball in hand, along the head string:");
        ui.add(
            egui::Slider::new(&mut y, -limit..=limit)
                .update_while_editing(false)
                .suffix(" m")
                .max_decimals(3),
        );
    });
    if let Some(mut motion) = cue
        && in_hand
        && y != motion.position.y
    {
        move_ball_in_hand(&state.spec, &mut motion, y);
    }
    apply_shot_edit(next, &mut state.shot, &mut state.report);
    ui.horizontal(|ui| {
        let shoot = ui
            .add_enabled(
                state.status.at_rest && !state.referee.rack_over,
                egui::Button::new("Shoot (Space)").min_size(egui::vec2(BUTTON_WIDTH, 0.0)),
            )
            .on_hover_text("when every ball rests (after a rack, start the next one first)");
        if shoot.clicked() {
            state.shots.write(ShotRequested::from_settings(&state.shot));
        }
        let undoable = state.solver.as_ref().map_or(0, |s| s.undoable_shots());
        let undo = ui
            .add_enabled(
                undoable > 0 && !state.referee.active,
                egui::Button::new("Undo shot").min_size(egui::vec2(BUTTON_WIDTH, 0.0)),
            )
            .on_hover_text(
                "practice: every ball back where it was before the last shot, the cue lined \
                 up to retry it (kept in the recording; not in a match)",
            );
        if undo.clicked() {
            state.undo.write(UndoRequested);
        }
    });
}

fn play_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
    let mut next = *state.physics;
    param_slider(ui, &mut next.time_scale, PhysicsSettings::TIME_SCALE);
    ui.horizontal(|ui| {
        // One width for both labels: the button next to it stays where it is.
        let label = if next.paused { "Resume" } else { "Pause" };
        let size = egui::vec2(BUTTON_WIDTH, 0.0);
        if ui.add(egui::Button::new(label).min_size(size)).clicked() {
            next.paused = !next.paused;
        }
        let step = ui.add_enabled(
            next.paused,
            egui::Button::new("Step to next event").min_size(size),
        );
        if step.clicked() {
            state.steps.write(StepRequested);
        }
    });
    apply_physics_edit(next, state);
    ui.add_space(6.0);
    ui.label("New rack (asks first when a game is in progress):");
    let in_progress = state.solver.as_ref().is_some_and(|s| s.in_progress());
    egui::Grid::new("racks")
        .num_columns(2)
        .spacing([8.0, 4.0])
        .show(ui, |ui| {
            for (k, rack) in RACKS.into_iter().enumerate() {
                let button =
                    egui::Button::new(rack_label(rack)).min_size(egui::vec2(BUTTON_WIDTH, 0.0));
                if ui.add(button).clicked() {
                    if in_progress {
                        state.confirm.0 = Some(rack);
                    } else {
                        state.racks.write(RackRequested::fresh(rack, clock_seed()));
                    }
                }
                if k % 2 == 1 {
                    ui.end_row();
                }
            }
        });
    // Free play only: a match's table is chosen in its new-game dialog. Changing it racks the
    // same rack afresh on the new table.
    let free_play = !state.referee.active;
    ui.add_enabled_ui(free_play, |ui| {
        ui.horizontal(|ui| {
            ui.label("Table:");
            let mut table = state.setup.table;
            // The table really on (the stress table, snooker's, a recording's), not only the
            // pool table last chosen.
            egui::ComboBox::from_id_salt("free-play-table")
                .selected_text(table_in_play(table, &state.spec, &state.stress))
                .width(230.0)
                .show_ui(ui, |ui| {
                    for choice in table_choices() {
                        ui.selectable_value(&mut table, choice, table_label(choice));
                    }
                });
            if table != state.setup.table {
                state.setup.table = table;
            }
        });
    });
}

/// The name of the table on now, for the Play section: the stress table while `stress` says
/// it is on, else the table `spec` draws ([`table_on_label`]).
pub fn table_in_play(
    chosen: billiards_physics::TableChoice,
    spec: &TableSpec,
    stress: &StressMonitor,
) -> String {
    let on = stress
        .built
        .filter(|_| stress.active)
        .map(|built| (stress.table.0, stress.table.1, built.balls));
    table_on_label(chosen, spec, on)
}

/// The name of the table on, for the Play section: `stress` (length, width in metres, balls)
/// when the stress table is on ("stress table: 3.2 x 1.6 m, 300 balls"); the snooker table
/// ("12-ft snooker table"); the pool table `spec` draws, by its name when it is one of the
/// choices (`chosen` first: "8-ft, WPA pockets (4.5 in)"), else by its size.
pub fn table_on_label(
    chosen: billiards_physics::TableChoice,
    spec: &TableSpec,
    stress: Option<(f64, f64, usize)>,
) -> String {
    if let Some((length, width, balls)) = stress {
        return format!("stress table: {length:.1} x {width:.1} m, {balls} balls");
    }
    if spec.is_snooker() {
        return "12-ft snooker table".to_owned();
    }
    let same = |other: &TableSpec| {
        let close = |a: f64, b: f64| (a - b).abs() < 1e-6;
        close(other.length, spec.length)
            && close(other.width, spec.width)
            && close(other.corner_mouth, spec.corner_mouth)
            && close(other.side_mouth, spec.side_mouth)
    };
    std::iter::once(chosen)
        .chain(table_choices())
        .find(|&choice| same(&TableSpec::of(choice)))
        .map_or_else(
            || format!("{:.2} x {:.2} m table", spec.length, spec.width),
            table_label,
        )
}

fn view_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
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

fn graphics_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
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

fn physics_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
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
    if super::layout::warning_window(ctx, "Settings file", error, hud_bottom) {
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

pub(super) fn section(
    ui: &mut egui::Ui,
    title: &str,
    open: bool,
    add_contents: impl FnOnce(&mut egui::Ui),
) {
    egui::CollapsingHeader::new(title)
        .default_open(open)
        .show(ui, add_contents);
}

/// A slider with an editable number. Typing a value outside the physical range is allowed
/// here so that the clamp can be reported rather than silently swallowed.
fn param_slider(ui: &mut egui::Ui, value: &mut f64, range: ParamRange) {
    ui.add(range_slider(value, range).max_decimals(4));
}

/// A slider over a physical range: typed values apply when the edit is committed, and a value
/// beyond the range is not clamped here but by the settings, which say so.
fn range_slider(value: &mut f64, range: ParamRange) -> egui::Slider<'_> {
    egui::Slider::new(value, range.as_range())
        .update_while_editing(false)
        .text(range.label)
        .suffix(range.unit)
        .clamping(egui::SliderClamping::Never)
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

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::{PocketCut, TableChoice, TableSize};

    /// Issue 48: the Play section named the chosen pool table ("8-ft, WPA pockets (4.5 in)")
    /// on the stress table and on the snooker table; it names the table really on.
    #[test]
    fn the_play_section_names_the_table_really_on() {
        let eight = TableChoice::default();
        assert_eq!(table_label(eight), "8-ft, WPA pockets (4.5 in)");
        let stress = table_on_label(eight, &TableSpec::default(), Some((3.2, 1.6, 300)));
        assert_eq!(stress, "stress table: 3.2 x 1.6 m, 300 balls");
        assert_eq!(
            table_on_label(eight, &TableSpec::snooker(), None),
            "12-ft snooker table"
        );
        assert_eq!(
            table_on_label(eight, &TableSpec::of(eight), None),
            "8-ft, WPA pockets (4.5 in)"
        );
        // A pool table other than the one chosen (a recording's): named as it is.
        let nine = TableChoice {
            size: TableSize::Nine,
            pockets: PocketCut::Tight,
        };
        assert_eq!(
            table_on_label(eight, &TableSpec::of(nine), None),
            table_label(nine)
        );
        assert!(table_label(nine).starts_with("9-ft"));
        // A table that is none of the choices: by its size.
        let odd = TableSpec {
            length: 2.0,
            width: 1.0,
            ..TableSpec::default()
        };
        assert_eq!(table_on_label(eight, &odd, None), "2.00 x 1.00 m table");
    }
    use egui::{Event, Key, Modifiers, PointerButton, Pos2, RawInput, Rect, Shape, vec2};

    /// One egui pass showing the sliding-friction slider over `value`, with `events`; returns
    /// where the value's text was drawn.
    fn pass(ctx: &egui::Context, events: Vec<Event>, value: &mut f64) -> Option<Rect> {
        let input = RawInput {
            events,
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, vec2(600.0, 200.0))),
            ..Default::default()
        };
        let output = ctx.run_ui(input, |ui| {
            param_slider(ui, value, PhysicsSettings::MU_SLIDE);
        });
        fn find(shape: &Shape) -> Option<Rect> {
            match shape {
                Shape::Vec(shapes) => shapes.iter().find_map(find),
                Shape::Text(text) if text.galley.text().parse::<f64>().is_ok() => {
                    Some(text.galley.rect.translate(text.pos.to_vec2()))
                }
                _ => None,
            }
        }
        output.shapes.iter().find_map(|s| find(&s.shape))
    }

    fn click(at: Pos2) -> Vec<Event> {
        [true, false]
            .map(|pressed| Event::PointerButton {
                pos: at,
                button: PointerButton::Primary,
                pressed,
                modifiers: Modifiers::NONE,
            })
            .into()
    }

    /// A typed value applies when the edit is committed (issue 28, item 3: typing "0.2" into
    /// sliding friction gave 0.15, the "0" clamped on its keystroke); one beyond the range is
    /// passed on unclamped, for the settings to clamp and say so.
    #[test]
    fn a_typed_value_applies_on_enter_not_per_keystroke() {
        let ctx = egui::Context::default();
        let mut value = 0.3;
        let text = pass(&ctx, Vec::new(), &mut value).expect("the value is drawn");
        let mut events = vec![Event::PointerMoved(text.center())];
        events.extend(click(text.center()));
        pass(&ctx, events, &mut value);
        assert!(
            ctx.memory(|m| m.focused().is_some()),
            "a click edits the value"
        );
        for typed in ["0", ".", "2"] {
            pass(&ctx, vec![Event::Text(typed.to_owned())], &mut value);
            assert_eq!(value, 0.3, "nothing applies while typing ({typed:?})");
        }
        let enter = Event::Key {
            key: Key::Enter,
            physical_key: None,
            pressed: true,
            repeat: false,
            modifiers: Modifiers::NONE,
        };
        pass(&ctx, vec![enter.clone()], &mut value);
        assert_eq!(value, 0.2, "Enter commits the typed value");
        // Beyond the range: the slider does not clamp it (the settings do, with a note).
        let text = pass(&ctx, Vec::new(), &mut value).unwrap();
        let mut events = vec![Event::PointerMoved(text.center())];
        events.extend(click(text.center()));
        pass(&ctx, events, &mut value);
        for typed in ["0", ".", "0", "5"] {
            pass(&ctx, vec![Event::Text(typed.to_owned())], &mut value);
        }
        pass(&ctx, vec![enter], &mut value);
        assert_eq!(value, 0.05);
    }
}
