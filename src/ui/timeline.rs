//! The replay viewer's egui parts: the "Recordings" section of the left panel and the
//! timeline window shown while a recording is open, plus the replay keys. They only read
//! [`Replay`] and write [`ReplayCommand`]s; the systems in [`super`] apply them.

use std::path::PathBuf;

use bevy::{ecs::system::SystemParam, prelude::*};
use bevy_egui::{
    EguiContexts, EguiPrimaryContextPass,
    egui::{self, Color32, RichText},
    input::egui_wants_any_keyboard_input,
};

use super::{
    ExportFormat, ExportRequest, ExportScope, MAX_SPEED, MIN_SPEED, OpenRecording, Replay,
    ReplayCommand, replaying,
};
use crate::recording::{Autosave, RecordingsFolder, list_recordings};

/// Registers the timeline window and the replay keys (needs egui and a window; the replay
/// logic itself is [`super::plugin`]).
pub fn plugin(app: &mut App) {
    app.init_resource::<ReplayForm>()
        .add_systems(EguiPrimaryContextPass, timeline_window.run_if(replaying))
        .add_systems(
            Update,
            replay_keys
                .run_if(replaying)
                .run_if(not(egui_wants_any_keyboard_input)),
        );
}

/// What the replay widgets edit between frames.
#[derive(Resource, Debug, Clone, PartialEq)]
pub struct ReplayForm {
    /// The path typed into the "open" field.
    pub path: String,
    /// The recordings folder's files, newest first, as last listed.
    pub files: Vec<PathBuf>,
    /// Whether `files` has been listed at all.
    pub listed: bool,
    /// Export format.
    pub format: ExportFormat,
    /// Export scope.
    pub scope: ExportScope,
    /// Export frames per second of simulated time.
    pub fps: f64,
    /// Export frame width, pixels.
    pub width: u32,
    /// Export frame height, pixels.
    pub height: u32,
    /// Export target typed by the player; empty: next to the recording.
    pub export_path: String,
}

impl Default for ReplayForm {
    fn default() -> Self {
        Self {
            path: String::new(),
            files: Vec::new(),
            listed: false,
            format: ExportFormat::Gif,
            scope: ExportScope::CurrentShot,
            fps: 30.0,
            width: 640,
            height: 360,
            export_path: String::new(),
        }
    }
}

/// What the "Recordings" section of the left panel needs.
#[derive(SystemParam)]
pub struct RecordingsParam<'w> {
    replay: Res<'w, Replay>,
    form: ResMut<'w, ReplayForm>,
    folder: Res<'w, RecordingsFolder>,
    autosave: Option<Res<'w, Autosave>>,
    commands: MessageWriter<'w, ReplayCommand>,
}

/// Most recordings listed in the panel at once (the newest).
const LISTED: usize = 50;

/// The "Recordings" section of the left panel: the folder's files with an Open button each,
/// a path field, the last error, the open replay and a running export.
pub fn recordings_section(ui: &mut egui::Ui, param: &mut RecordingsParam) {
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
                .max_height(140.0)
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
                .desired_width(200.0),
        );
        let entered = field.lost_focus() && ui.input(|input| input.key_pressed(egui::Key::Enter));
        let path = form.path.trim();
        if (ui.button("Open").clicked() || entered) && !path.is_empty() {
            commands.write(ReplayCommand::Open(PathBuf::from(path)));
        }
    });
    if let Some(error) = &replay.error {
        ui.colored_label(Color32::from_rgb(255, 170, 60), error);
    }
    if let Some(open) = &replay.open {
        ui.horizontal(|ui| {
            ui.label(format!("replaying {}", file_name(open)));
            if ui.button("Close replay").clicked() {
                commands.write(ReplayCommand::Close);
            }
        });
    }
    export_status(ui, replay);
}

fn file_name(open: &OpenRecording) -> String {
    open.path
        .file_name()
        .unwrap_or(open.path.as_os_str())
        .to_string_lossy()
        .into_owned()
}

/// The running export's progress bar, or how the last one ended.
fn export_status(ui: &mut egui::Ui, replay: &Replay) {
    if let Some(job) = &replay.export {
        let (done, total) = job.progress();
        ui.add(
            egui::ProgressBar::new(job.fraction())
                .text(format!("exporting: {done}/{total} frames")),
        );
    } else if let Some(result) = &replay.export_result {
        match result {
            Ok(written) => ui.label(format!("exported {written}")),
            Err(error) => ui.colored_label(Color32::from_rgb(255, 170, 60), error),
        };
    }
}

/// The timeline, anchored at the bottom of the 3D view.
fn timeline_window(
    mut contexts: EguiContexts,
    replay: Res<Replay>,
    mut form: ResMut<ReplayForm>,
    mut commands: MessageWriter<ReplayCommand>,
) -> Result {
    let Some(open) = &replay.open else {
        return Ok(());
    };
    let ctx = contexts.ctx_mut()?.clone();
    egui::Window::new(format!("Replay: {}", file_name(open)))
        .id(egui::Id::new("replay timeline"))
        .anchor(
            egui::Align2::CENTER_BOTTOM,
            [crate::ui::PANEL_WIDTH / 2.0, -10.0],
        )
        .resizable(false)
        .default_width(620.0)
        .show(&ctx, |ui| {
            timeline(ui, &replay, open, &mut form, &mut commands);
        });
    Ok(())
}

fn timeline(
    ui: &mut egui::Ui,
    replay: &Replay,
    open: &OpenRecording,
    form: &mut ReplayForm,
    commands: &mut MessageWriter<ReplayCommand>,
) {
    let t = replay.time;
    ui.horizontal(|ui| {
        let buttons = [
            (
                "|< shot",
                "previous shot (Page Up)",
                ReplayCommand::PreviousShot,
            ),
            (
                "< event",
                "previous event (Left)",
                ReplayCommand::PreviousEvent,
            ),
        ];
        for (label, hover, command) in buttons {
            if ui.button(label).on_hover_text(hover).clicked() {
                commands.write(command);
            }
        }
        let play = if replay.playing { "Pause" } else { "Play" };
        if ui.button(play).on_hover_text("Space").clicked() {
            commands.write(ReplayCommand::TogglePlay);
        }
        let buttons = [
            ("event >", "next event (Right)", ReplayCommand::NextEvent),
            ("shot >|", "next shot (Page Down)", ReplayCommand::NextShot),
        ];
        for (label, hover, command) in buttons {
            if ui.button(label).on_hover_text(hover).clicked() {
                commands.write(command);
            }
        }
        ui.separator();
        let mut speed = replay.speed;
        let slider = egui::Slider::new(&mut speed, MIN_SPEED..=MAX_SPEED)
            .logarithmic(true)
            .text("speed")
            .suffix("x")
            .max_decimals(2);
        if ui.add(slider).changed() {
            commands.write(ReplayCommand::SetSpeed(speed));
        }
    });
    ui.scope(|ui| {
        ui.spacing_mut().slider_width = (ui.available_width() - 10.0).max(100.0);
        let mut scrub = t;
        let slider = egui::Slider::new(&mut scrub, 0.0..=open.end_time.max(1e-9))
            .show_value(false)
            .smart_aim(false);
        if ui.add(slider).changed() {
            commands.write(ReplayCommand::Seek(scrub));
        }
    });
    ui.label(format!(
        "time {t:.4} s of {:.3} s    shot {} of {}",
        open.end_time,
        open.shot_at(t),
        open.shots.len()
    ));
    match open.event_at(t) {
        Some((index, event)) => ui.label(format!(
            "event {} of {} at {:.6} s: {}",
            index + 1,
            open.events().len(),
            event.time,
            open.describe(event)
        )),
        None => ui.label(RichText::new("before the first event").weak()),
    };
    ui.horizontal(|ui| {
        if ui
            .add_enabled(replay.verifying.is_none(), egui::Button::new("Verify"))
            .on_hover_text("re-simulate the inputs and compare every event bit for bit")
            .clicked()
        {
            commands.write(ReplayCommand::Verify);
        }
        if replay.verifying.is_some() {
            ui.spinner();
            ui.label("re-simulating…");
        } else if let Some(verdict) = &replay.verdict {
            let colour = if matches!(
                verdict,
                Ok(billiards_physics::recording::Verdict::Reproduced { .. })
            ) {
                Color32::from_rgb(120, 220, 120)
            } else {
                Color32::from_rgb(255, 170, 60)
            };
            ui.colored_label(colour, open.verdict_text(verdict));
        }
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            if ui.button("Close replay").on_hover_text("Esc").clicked() {
                commands.write(ReplayCommand::Close);
            }
        });
    });
    egui::CollapsingHeader::new("Export")
        .default_open(false)
        .show(ui, |ui| export_form(ui, replay, open, form, commands));
}

fn export_form(
    ui: &mut egui::Ui,
    replay: &Replay,
    open: &OpenRecording,
    form: &mut ReplayForm,
    commands: &mut MessageWriter<ReplayCommand>,
) {
    let (shot, _) = open.export_span(ExportScope::CurrentShot, replay.time);
    ui.horizontal(|ui| {
        ui.selectable_value(&mut form.format, ExportFormat::Gif, "GIF");
        ui.selectable_value(&mut form.format, ExportFormat::PngSequence, "PNG sequence");
        ui.separator();
        let current = match shot {
            Some(k) => format!("shot {k}"),
            None => "current shot".to_owned(),
        };
        ui.selectable_value(&mut form.scope, ExportScope::CurrentShot, current);
        ui.selectable_value(&mut form.scope, ExportScope::WholeGame, "whole game");
    });
    ui.horizontal(|ui| {
        ui.add(
            egui::DragValue::new(&mut form.fps)
                .range(1.0..=120.0)
                .suffix(" fps"),
        );
        ui.separator();
        ui.add(egui::DragValue::new(&mut form.width).range(16..=4096));
        ui.label("x");
        ui.add(egui::DragValue::new(&mut form.height).range(16..=4096));
        ui.label("pixels");
    });
    let (scope_shot, _) = open.export_span(form.scope, replay.time);
    let default = open.default_export_path(form.format, scope_shot);
    ui.horizontal(|ui| {
        ui.label("to");
        ui.add(
            egui::TextEdit::singleline(&mut form.export_path)
                .hint_text(default.display().to_string())
                .desired_width(f32::INFINITY),
        );
    });
    let running = replay.export.is_some();
    if running {
        if ui
            .button("Cancel export")
            .on_hover_text("stop after the current frame: a GIF is not written, PNGs so far stay")
            .clicked()
        {
            commands.write(ReplayCommand::CancelExport);
        }
    } else if ui.button("Export").clicked() {
        let path = form.export_path.trim();
        commands.write(ReplayCommand::Export(ExportRequest {
            format: form.format,
            scope: form.scope,
            fps: form.fps,
            width: form.width,
            height: form.height,
            path: (!path.is_empty()).then(|| PathBuf::from(path)),
        }));
    }
    export_status(ui, replay);
}

/// Space: play or pause; Left/Right: previous/next event; Page Up/Down: previous/next shot;
/// Esc: close the replay.
fn replay_keys(keys: Res<ButtonInput<KeyCode>>, mut commands: MessageWriter<ReplayCommand>) {
    let bindings = [
        (KeyCode::Space, ReplayCommand::TogglePlay),
        (KeyCode::ArrowLeft, ReplayCommand::PreviousEvent),
        (KeyCode::ArrowRight, ReplayCommand::NextEvent),
        (KeyCode::PageUp, ReplayCommand::PreviousShot),
        (KeyCode::PageDown, ReplayCommand::NextShot),
        (KeyCode::Escape, ReplayCommand::Close),
    ];
    for (key, command) in bindings {
        if keys.just_pressed(key) {
            commands.write(command);
        }
    }
}
