//! The settings panel's sections, play first: the shot (angle, power, tip picker, ball in
//! hand, shoot and undo), play (clock, racks), the view, graphics; then the physics in its own
//! section, the settings file and the controls.
//!
//! Rows keep their place: nothing in the panel appears or disappears with the game's state
//! (a row that does not apply is shown disabled), and notes (clamps, a miscue) go to the HUD,
//! so a click never lands on a widget that moved under the pointer.

mod file;
mod param;
mod physics;
mod play;
mod shot;
mod view;
mod widgets;

use bevy_egui::egui;
use physics::physics_section;
use play::play_section;
use shot::shot_section;
use view::{graphics_section, view_section};

pub use file::{config_error_window, file_and_controls, rack_confirm_window};
pub use param::{OpenSections, RackConfirm, SettingsParam};
pub use play::{table_in_play, table_on_label};
pub(crate) use widgets::section;

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
