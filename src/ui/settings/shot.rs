//! The Shot section and its tip picker.

use bevy_egui::egui::{self, Color32, RichText};

use super::param::SettingsParam;
use super::widgets::{param_slider, range_slider};
use crate::ui::layout::{BUTTON_WIDTH, TIP_PICKER_SIZE};
use crate::{
    settings::{PhysicsModel, ShotSettings, apply_shot_edit, shown_degrees},
    sim::{ShotRequested, UndoRequested, move_ball_in_hand},
};

/// The Shot section: angle, power, the tip, ball in hand, shoot and undo.
pub(super) fn shot_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
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
                undoable > 0 && state.referee.edits,
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

/// The cue ball seen from behind the cue: click or drag where the tip should strike. The red
/// ring is the miscue limit; the blue dot is the tip (drawn to scale, 13 mm across).
pub(super) fn tip_picker(ui: &mut egui::Ui, tip: &mut billiards_physics::TipOffset) {
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
