//! The replay timeline, a strip along the bottom of the window right of the panel while a
//! recording is open (the table's viewport ends above it, [`ViewInset::bottom`], so it covers
//! nothing of the table): transport buttons, speed, Verify, Close, a scrub bar, the event
//! under the replay time and the verdicts. The Export form is in the panel's Recordings
//! section ([`export_section`]). It only reads [`Replay`] and writes [`ReplayCommand`]s.

use std::path::PathBuf;

use bevy::prelude::*;
use bevy_egui::{
    EguiContexts,
    egui::{self, RichText},
};

use super::layout::{Edge, SUCCESS, TIMELINE_HEIGHT, WARNING, strip};
use crate::{
    practice::{PendingPosition, ShotAsPositionRequested},
    replay::{
        ExportFormat, ExportRequest, ExportScope, MAX_SPEED, MIN_SPEED, OpenRecording, Replay,
        ReplayCommand,
    },
    view::ViewInset,
};

/// What the Export form edits between frames.
#[derive(Resource, Debug, Clone, PartialEq)]
pub struct ExportForm {
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

impl Default for ExportForm {
    fn default() -> Self {
        Self {
            format: ExportFormat::Gif,
            scope: ExportScope::CurrentShot,
            fps: 30.0,
            width: 640,
            height: 360,
            export_path: String::new(),
        }
    }
}

/// The running export's progress bar, or how the last one ended.
pub fn export_status(ui: &mut egui::Ui, replay: &Replay) {
    export_status_or(ui, replay, None);
}

/// [`export_status`], or `idle` when there is nothing to say: a line that is always there
/// keeps the window's size (an anchored window that grew ran off the bottom of the screen).
fn export_status_or(ui: &mut egui::Ui, replay: &Replay, idle: Option<&str>) {
    if let Some(job) = &replay.export {
        let (done, total) = job.progress();
        ui.add(
            egui::ProgressBar::new(job.fraction())
                .text(format!("exporting: {done}/{total} frames")),
        );
    } else if let Some(result) = &replay.export_result {
        match result {
            Ok(written) => ui.label(format!("exported {written}")),
            Err(error) => ui.colored_label(WARNING, error),
        };
    } else if let Some(idle) = idle {
        ui.label(RichText::new(idle).weak());
    }
}

/// The timeline strip along the bottom of the window, right of the panel, while a recording
/// is open; the table's view ends above it. Without one it takes no room.
pub fn timeline_strip(
    mut contexts: EguiContexts,
    replay: Res<Replay>,
    mut commands: MessageWriter<ReplayCommand>,
    (mut as_position, pending): (MessageWriter<ShotAsPositionRequested>, Res<PendingPosition>),
    (mut inset, verdict): (ResMut<ViewInset>, Res<super::game::VerdictStrip>),
) -> Result {
    // Without a replay the bottom is the docked verdict's, if one is shown.
    let height = if replay.open.is_some() {
        TIMELINE_HEIGHT
    } else {
        verdict.0
    };
    if inset.bottom != height {
        inset.bottom = height;
    }
    let Some(open) = &replay.open else {
        return Ok(());
    };
    let ctx = contexts.ctx_mut()?.clone();
    let place = (inset.left, Edge::Bottom, TIMELINE_HEIGHT);
    strip(&ctx, "replay timeline", place, |ui| {
        timeline(
            ui,
            &replay,
            open,
            &mut commands,
            (&mut as_position, &pending),
        );
    });
    Ok(())
}

fn timeline(
    ui: &mut egui::Ui,
    replay: &Replay,
    open: &OpenRecording,
    commands: &mut MessageWriter<ReplayCommand>,
    (as_position, pending): (
        &mut MessageWriter<ShotAsPositionRequested>,
        &PendingPosition,
    ),
) {
    timeline_header(ui, replay, open, commands, (as_position, pending));
    transport_row(ui, replay, commands);
    let t = replay.time;
    ui.scope(|ui| {
        ui.spacing_mut().slider_width = (ui.available_width() - 10.0).max(100.0);
        let mut scrub = t;
        let slider = egui::Slider::new(&mut scrub, 0.0..=open.end_time().max(1e-9))
            .show_value(false)
            .smart_aim(false);
        if ui.add(slider).changed() {
            commands.write(ReplayCommand::Seek(scrub));
        }
    });
    ui.label(format!(
        "time {t:.4} s of {:.3} s    shot {} of {}",
        open.end_time(),
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
    if let Some(line) = open.game_line(t) {
        ui.label(RichText::new(line).strong());
    }
    // The verdicts on lines of their own, always there, so nothing moves under the pointer.
    if replay.verifying.is_some() {
        ui.label("re-simulating…");
    } else if let Some(verdict) = &replay.verdict {
        let colour = if matches!(
            verdict,
            Ok(billiards_physics::recording::Verdict::Reproduced { .. })
        ) {
            SUCCESS
        } else {
            WARNING
        };
        ui.colored_label(colour, open.verdict_text(verdict));
    } else {
        ui.label(RichText::new("not verified yet").weak());
    }
    // A rules game: the verdicts re-judged with the verification, on a line always there.
    if open.game.is_some() {
        match &replay.rules_verdict {
            Some(Ok(n)) => {
                let s = if *n == 1 { "" } else { "s" };
                ui.colored_label(SUCCESS, format!("{n} verdict{s} re-judged alike"))
            }
            Some(Err(e)) => ui.colored_label(WARNING, format!("verdicts: {e}")),
            None => ui.label(RichText::new("verdicts not re-judged yet").weak()),
        };
    }
}

/// The replay's title and its buttons on the right: Close, Verify, Open shot as position.
fn timeline_header(
    ui: &mut egui::Ui,
    replay: &Replay,
    open: &OpenRecording,
    commands: &mut MessageWriter<ReplayCommand>,
    (as_position, pending): (
        &mut MessageWriter<ShotAsPositionRequested>,
        &PendingPosition,
    ),
) {
    ui.horizontal(|ui| {
        ui.label(RichText::new(format!("Replay: {}", open.file_name())).strong());
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            if ui.button("Close replay").on_hover_text("Esc").clicked() {
                commands.write(ReplayCommand::Close);
            }
            if replay.verifying.is_some() {
                ui.spinner();
            }
            if ui
                .add_enabled(replay.verifying.is_none(), egui::Button::new("Verify"))
                .on_hover_text("re-simulate the inputs and compare every event bit for bit")
                .clicked()
            {
                commands.write(ReplayCommand::Verify);
            }
            if ui
                .button("Open shot as position")
                .on_hover_text("the balls where this shot was struck, live, with its shot lined up")
                .clicked()
            {
                as_position.write(ShotAsPositionRequested);
            }
            if let Some(why) = &pending.refused {
                ui.colored_label(WARNING, why);
            }
        });
    });
}

/// The transport: previous shot and event, Play/Pause, next event and shot, the speed.
fn transport_row(ui: &mut egui::Ui, replay: &Replay, commands: &mut MessageWriter<ReplayCommand>) {
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
            .update_while_editing(false)
            .logarithmic(true)
            .text("speed")
            .suffix("x")
            .max_decimals(2);
        if ui.add(slider).changed() {
            commands.write(ReplayCommand::SetSpeed(speed));
        }
    });
}

/// The Export form of the open replay, in the panel's Recordings section: format and scope,
/// frame rate and size, the file, Export or Cancel, and how the last export went.
pub fn export_section(
    ui: &mut egui::Ui,
    replay: &Replay,
    open: &OpenRecording,
    form: &mut ExportForm,
    commands: &mut MessageWriter<ReplayCommand>,
) {
    egui::CollapsingHeader::new("Export")
        .default_open(true)
        .show(ui, |ui| export_form(ui, replay, open, form, commands));
}

fn export_form(
    ui: &mut egui::Ui,
    replay: &Replay,
    open: &OpenRecording,
    form: &mut ExportForm,
    commands: &mut MessageWriter<ReplayCommand>,
) {
    let (shot, _) = open.export_span(ExportScope::CurrentShot, replay.time);
    ui.horizontal(|ui| {
        ui.selectable_value(&mut form.format, ExportFormat::Gif, "GIF");
        ui.selectable_value(&mut form.format, ExportFormat::PngSequence, "PNG sequence");
        ui.selectable_value(&mut form.format, ExportFormat::Video, "MP4 (ffmpeg)")
            .on_hover_text("needs ffmpeg on the PATH; any frame rate");
    });
    ui.horizontal(|ui| {
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
                .update_while_editing(false)
                .range(1.0..=120.0)
                .suffix(" fps"),
        );
        ui.separator();
        ui.add(
            egui::DragValue::new(&mut form.width)
                .update_while_editing(false)
                .range(16..=4096),
        );
        ui.label("x");
        ui.add(
            egui::DragValue::new(&mut form.height)
                .update_while_editing(false)
                .range(16..=4096),
        );
        ui.label("pixels");
    });
    let (scope_shot, _) = open.export_span(form.scope, replay.time);
    let default = open.default_export_path(form.format, scope_shot);
    ui.horizontal(|ui| {
        ui.label("to");
        ui.add(
            egui::TextEdit::singleline(&mut form.export_path)
                .hint_text("beside the recording")
                .desired_width(f32::INFINITY),
        );
    });
    // The default file on a wrapped line of its own: as the field's hint it was cut off in
    // the panel.
    if form.export_path.trim().is_empty() {
        let name = default.file_name().unwrap_or_default().to_string_lossy();
        ui.add(egui::Label::new(RichText::new(format!("default: {name}")).weak()).wrap())
            .on_hover_text(default.display().to_string());
    }
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
    export_status_or(ui, replay, Some("no export running"));
}
