//! Sizes and colours shared by the game's panels and windows, so they line up and agree.

use bevy_egui::egui::{self, Color32};

/// Where a strip of the window goes, right of the panel: along the top or the bottom edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    /// The HUD.
    Top,
    /// The replay timeline.
    Bottom,
}

/// A strip `height` high along `edge` of the window, right of the panel's `left`, framed like
/// a panel: it neither moves nor grows with what it holds (the table's viewport leaves it
/// free, [`crate::view::ViewInset`]).
pub fn strip(
    ctx: &egui::Context,
    id: &str,
    (left, edge, height): (f32, Edge, f32),
    add: impl FnOnce(&mut egui::Ui),
) {
    let screen = ctx.viewport_rect();
    let size = egui::vec2((screen.width() - left).max(1.0), height);
    let top = match edge {
        Edge::Top => screen.min.y,
        Edge::Bottom => screen.max.y - height,
    };
    egui::Area::new(egui::Id::new(id))
        .order(egui::Order::Middle)
        .fixed_pos(egui::pos2(screen.min.x + left, top))
        .movable(false)
        .constrain(false)
        .show(ctx, |area| {
            egui::Frame::side_top_panel(&ctx.global_style()).show(area, |ui| {
                let inner = size - egui::vec2(16.0, 12.0);
                ui.set_min_size(inner);
                ui.set_max_size(inner);
                add(ui);
            });
        });
}

/// Width of the settings panel on the left, in logical pixels. The 3D view takes the rest.
pub const PANEL_WIDTH: f32 = 340.0;

/// Height of the HUD strip along the top of the 3D view; the table's viewport starts below.
pub const HUD_HEIGHT: f32 = 128.0;

/// Width of each of the HUD's buttons, so they keep their places whatever their state.
pub const HUD_BUTTON_WIDTH: f32 = 104.0;

/// Height of the replay timeline strip along the bottom; the table's viewport ends above it.
pub const TIMELINE_HEIGHT: f32 = 176.0;

/// Height of the list of recordings before it scrolls.
pub const RECORDINGS_LIST_HEIGHT: f32 = 140.0;

/// Width of the path fields (recording to open).
pub const PATH_FIELD_WIDTH: f32 = 200.0;

/// Width of the panel's paired buttons, so a label change (Pause, Resume) moves nothing.
pub const BUTTON_WIDTH: f32 = 140.0;

/// Side of the cue-ball tip picker.
pub const TIP_PICKER_SIZE: f32 = 96.0;

/// Something the player should read: a clamp, an error, a refused input.
pub const WARNING: Color32 = Color32::from_rgb(255, 170, 60);

/// Something went as asked (a verification reproduced).
pub const SUCCESS: Color32 = Color32::from_rgb(120, 220, 120);

/// A mode note (replaying a recording).
pub const INFO: Color32 = Color32::from_rgb(120, 190, 255);

/// A line of the HUD and its colour (`None`: the text colour).
pub type HudLine = (String, Option<Color32>);

/// A warning that may hold a path: wrapped to the width available, breaking a word with no
/// space to wrap at (a path) anywhere rather than running past the edge.
pub fn warning_label(ui: &mut egui::Ui, text: &str) {
    let mut job = egui::text::LayoutJob::single_section(
        text.to_owned(),
        egui::TextFormat {
            font_id: egui::TextStyle::Body.resolve(ui.style()),
            color: WARNING,
            ..Default::default()
        },
    );
    job.wrap.break_anywhere = true;
    ui.label(job);
}

/// A window over the table that says what went wrong with a file (`title`, `text`), below
/// the HUD strip (`hud_bottom`), centred on the view right of the panel; true when its OK
/// was clicked.
pub fn warning_window(ctx: &egui::Context, title: &str, text: &str, hud_bottom: f32) -> bool {
    let mut ok = false;
    egui::Window::new(title)
        .collapsible(false)
        .resizable(false)
        .anchor(
            egui::Align2::CENTER_TOP,
            [PANEL_WIDTH / 2.0, hud_bottom + 12.0],
        )
        .order(egui::Order::Foreground)
        .show(ctx, |ui| {
            ui.set_max_width(420.0);
            warning_label(ui, text);
            ok = ui.button("OK").clicked();
        });
    ok
}
