//! The "Recordings" section of the left panel: the recordings folder's files with an Open
//! button each, a path field, why the last file could not be opened, the open replay and a
//! running export; and the window that says over the table why a file could not be opened.
//! It only reads [`Replay`] and writes [`ReplayCommand`]s.

use std::path::PathBuf;

use bevy::{ecs::system::SystemParam, prelude::*};
use bevy_egui::egui::{self, RichText};

use super::{
    layout::{PATH_FIELD_WIDTH, RECORDINGS_LIST_HEIGHT},
    timeline::{ExportForm, export_section, export_status},
};
use crate::{
    recording::{Autosave, RecordingsFolder, list_recordings},
    replay::{Replay, ReplayCommand},
};

/// What the Recordings section edits between frames.
#[derive(Resource, Debug, Clone, PartialEq, Default)]
pub struct RecordingsForm {
    /// The path typed into the "open" field.
    pub path: String,
    /// The recordings folder's files, newest first, as last listed.
    pub files: Vec<PathBuf>,
    /// Whether `files` has been listed at all.
    pub listed: bool,
}

/// What the "Recordings" section of the left panel needs.
#[derive(SystemParam)]
pub struct RecordingsParam<'w> {
    replay: Res<'w, Replay>,
    form: ResMut<'w, RecordingsForm>,
    folder: Res<'w, RecordingsFolder>,
    autosave: Option<Res<'w, Autosave>>,
    commands: MessageWriter<'w, ReplayCommand>,
    export: ResMut<'w, ExportForm>,
}

/// Most recordings listed in the panel at once (the newest).
const LISTED: usize = 50;

/// The "Recordings" section of the left panel: the folder's files with an Open button each,
/// a path field, the last error, the open replay and a running export.
pub fn section(ui: &mut egui::Ui, param: &mut RecordingsParam) {
    egui::CollapsingHeader::new("Recordings")
        .default_open(true)
        .show(ui, |ui| recordings(ui, param));
}

fn recordings(ui: &mut egui::Ui, param: &mut RecordingsParam) {
    let RecordingsParam {
        replay,
        form,
        folder,
        autosave,
        commands,
        export,
    } = param;
    let saved_since = autosave
        .as_ref()
        .is_some_and(|autosave| autosave.is_changed());
    match &folder.0 {
        None => {
            ui.label(RichText::new("not recording (--no-record)").weak());
        }
        Some(dir) => {
            if !form.listed || saved_since {
                form.files = list_recordings(dir);
                form.listed = true;
            }
            ui.horizontal(|ui| {
                ui.label(RichText::new(dir.display().to_string()).weak());
                if ui.small_button("refresh").clicked() {
                    form.files = list_recordings(dir);
                }
            });
            if form.files.is_empty() {
                ui.label(RichText::new("no recordings yet: every shot is saved").weak());
            }
            egui::ScrollArea::vertical()
                .id_salt("recordings list")
                .max_height(RECORDINGS_LIST_HEIGHT)
                .show(ui, |ui| {
                    for file in form.files.iter().take(LISTED) {
                        ui.horizontal(|ui| {
                            if ui.small_button("Open").clicked() {
                                commands.write(ReplayCommand::Open(file.clone()));
                            }
                            let name = file.file_name().unwrap_or_default().to_string_lossy();
                            ui.label(name).on_hover_text(file.display().to_string());
                        });
                    }
                });
        }
    }
    ui.horizontal(|ui| {
        let field = ui.add(
            egui::TextEdit::singleline(&mut form.path)
                .hint_text("recording.json (or drop a file)")
                .desired_width(PATH_FIELD_WIDTH),
        );
        let entered = field.lost_focus() && ui.input(|input| input.key_pressed(egui::Key::Enter));
        let path = form.path.trim();
        if (ui.button("Open").clicked() || entered) && !path.is_empty() {
            commands.write(ReplayCommand::Open(PathBuf::from(path)));
        }
    });
    if let Some(error) = &replay.error {
        super::layout::warning_label(ui, error);
    }
    if let Some(open) = &replay.open {
        // The name on a line of its own: beside it the button ran past the panel's edge.
        ui.label(format!("replaying {}", open.file_name()));
        if ui.button("Close replay").clicked() {
            commands.write(ReplayCommand::Close);
        }
    }
    // The open replay's Export form, whose last line is the export's progress; with the
    // replay closed, only how the last export went.
    match &replay.open {
        Some(open) => export_section(ui, replay, open, export, commands),
        None => export_status(ui, replay),
    }
}

/// A file that could not be opened for replay (`billiards replay BAD.json`, a drop, the Open
/// button) is said where it is seen, over the table, as a bad settings file is, until the
/// player dismisses it (the Recordings section keeps the reason).
pub fn error_window(ctx: &egui::Context, param: &mut RecordingsParam, hud_bottom: f32) {
    let Some(error) = param.replay.error_to_show() else {
        return;
    };
    if super::layout::warning_window(ctx, "Recording not opened", error, hud_bottom) {
        param.commands.write(ReplayCommand::DismissError);
    }
}
