//! Every egui part of the game, and nothing else: the settings panel on the left, the HUD,
//! the Recordings section and the replay timeline. Widgets only read resources and write
//! settings or messages; the game's logic runs without them (the headless tests).
//!
//! - [`layout`]: shared sizes and colours;
//! - `clicks`: pointer clicks fed to egui one frame at a time, none on a layout the player
//!   had not seen;
//! - [`settings`]: the panel's shot, physics, simulation and view sections;
//! - [`practice`]: the Position section (placing balls, position codes) and the drill window;
//! - [`stress`]: the Stress table section (ball count, friction, seed, table size);
//! - [`recordings`]: the Recordings section (open a recording);
//! - [`timeline`]: the replay timeline strip and the Export form;
//! - [`hud`]: the HUD in the top-right corner;
//! - [`new_game`]: the new-game dialog's form, kept between frames;
//! - `live_windows`: any game's verdict, call, nomination and concession, and its end;
//! - [`game`]: the match's HUD lines, the new-game dialog, the verdict, the call, the end of
//!   a rack.
//!
//! The 3D view is fitted to the part of the window right of the panel (the panel's width goes
//! to [`crate::view`]), so the panel never covers the table; below 100 % render scale the
//! table's image is drawn here, under everything else. While egui has claimed the pointer or
//! the keyboard, the game's input systems ([`InputSystems`]) do not run, so input meant for a
//! widget never reaches the table.

mod clicks;
pub mod game;
pub mod hud;
pub mod layout;
pub mod layout_check;
mod live_windows;
pub mod new_game;
pub mod practice;
pub mod recordings;
pub mod settings;
pub mod stress;
pub mod timeline;

use bevy::{
    camera::{CameraOutputMode, visibility::RenderLayers},
    prelude::*,
    render::render_resource::BlendState,
    window::{PrimaryWindow, RequestRedraw},
};
use bevy_egui::{
    EguiContexts, EguiGlobalSettings, EguiInput, EguiPlugin, EguiPostUpdateSet, EguiPreUpdateSet,
    EguiPrimaryContextPass, EguiRenderOutput, EguiTextureHandle, PrimaryEguiContext, egui,
    input::egui_wants_any_keyboard_input,
};

pub use layout::{HUD_HEIGHT, PANEL_WIDTH};
pub use settings::OpenSections;

use clicks::{PassRects, allow_slow_clicks, record_pass_rects, split_one_frame_clicks};

use crate::{
    input::InputSystems,
    mode::GameMode,
    view::{SceneTarget, ViewInset, idle::RepaintCauses},
};

/// Adds egui, registers the panels and windows, and keeps the game's input away from them.
pub fn plugin(app: &mut App) {
    app.add_plugins(EguiPlugin::default())
        .init_resource::<recordings::RecordingsForm>()
        .init_resource::<timeline::ExportForm>()
        .init_resource::<new_game::NewGameForm>()
        .init_resource::<settings::RackConfirm>()
        .init_resource::<stress::StressConfirm>()
        .init_resource::<practice::PositionForm>()
        .init_resource::<hud::HudFit>()
        .init_resource::<game::VerdictStrip>()
        .init_resource::<settings::OpenSections>()
        .add_plugins(layout_check::plugin)
        .configure_sets(
            Update,
            (
                InputSystems::Pointer.run_if(not(pointer_on_ui)),
                InputSystems::Keyboard.run_if(not(egui_wants_any_keyboard_input)),
            ),
        )
        .add_systems(
            PreUpdate,
            (
                drop_unchanged_modifiers,
                split_one_frame_clicks,
                allow_slow_clicks,
            )
                .after(EguiPreUpdateSet::ProcessInput)
                .before(EguiPreUpdateSet::BeginPass),
        )
        .init_resource::<PointerOnUi>()
        .add_systems(Update, find_pointer_on_ui.before(InputSystems::Pointer))
        .add_systems(Update, new_game::remember_new_game)
        .add_systems(
            PostUpdate,
            redraw_after_texture_change
                .after(EguiPostUpdateSet::ProcessOutput)
                .before(EguiPostUpdateSet::PostProcessOutput),
        )
        .init_resource::<PassRects>()
        .add_systems(
            PostUpdate,
            record_pass_rects
                .after(EguiPostUpdateSet::EndPass)
                .before(EguiPostUpdateSet::PostProcessOutput),
        )
        .add_systems(
            PostUpdate,
            record_repaint_causes
                .run_if(resource_exists::<RepaintCauses>)
                .after(EguiPostUpdateSet::EndPass),
        )
        .add_systems(Startup, spawn_ui_camera)
        .add_systems(
            EguiPrimaryContextPass,
            whole_pixel_glyphs.before(show_scene_image),
        )
        .add_systems(
            EguiPrimaryContextPass,
            (
                show_scene_image,
                // The HUD and timeline strips start where the panel ends.
                (left_panel, (hud::hud, timeline::timeline_strip)).chain(),
                game::game_windows
                    .run_if(in_state(GameMode::Play))
                    .before(timeline::timeline_strip),
            ),
        );
}

/// Whether the pointer is, this frame, over a panel or window of the UI.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct PointerOnUi(pub bool);

/// egui's own verdict (`egui_wants_any_pointer_input`) comes from its last pass, which saw
/// the pointer where it was a frame ago: a pointer that jumps onto a button and clicks within
/// one frame (one frame is a second on a software renderer) reached the table too and re-aimed
/// the cue, and one that jumps from a window onto the table and clicks lost the click (a
/// pocket call needed two clicks). Here the pointer's current position is looked up in the
/// areas egui laid out; a drag egui is still handling (a slider pulled off the panel) counts
/// as on the UI too.
fn find_pointer_on_ui(
    mut contexts: EguiContexts,
    window: Single<&Window, With<PrimaryWindow>>,
    mut on_ui: ResMut<PointerOnUi>,
) -> Result {
    let ctx = contexts.ctx_mut()?;
    // Window coordinates are logical pixels; egui points are those over its zoom factor.
    let over = window.cursor_position().is_some_and(|cursor| {
        let at = egui::pos2(cursor.x, cursor.y) / ctx.zoom_factor();
        ctx.layer_id_at(at)
            .is_some_and(|layer| layer.order != egui::Order::Background)
    }) || ctx.egui_is_using_pointer();
    on_ui.set_if_neq(PointerOnUi(over));
    Ok(())
}

/// A frame that changes egui's textures (new glyphs in the font atlas) can draw its text before
/// the new texels are there: played under Xvfb, letters were missing ("ne t", "15-ball. son")
/// and, the idle window drawing only on change, stayed missing until the next input. One more
/// frame draws them.
fn redraw_after_texture_change(
    outputs: Query<&EguiRenderOutput>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    if outputs.iter().any(|o| !o.textures_delta.set.is_empty()) {
        redraw.write(RequestRedraw);
    }
}

/// egui draws each glyph at one of four sub-pixel offsets and rasterizes a variant the first
/// time text lands on it. The HUD's numbers change every frame and shift the text after them,
/// so a frame woken by input kept finding new variants, changing the font texture and, through
/// [`redraw_after_texture_change`], asking for the next frame: an idle window drew up to 8
/// frames after a single wake-up (issue 22, traced with `--count-idle-frames`). Glyphs on whole
/// pixels need one bitmap per character, all rasterized in the first frames.
fn whole_pixel_glyphs(mut contexts: EguiContexts, mut done: Local<bool>) -> Result {
    if !*done {
        contexts
            .ctx_mut()?
            .all_styles_mut(|style| style.visuals.text_options.subpixel_binning = false);
        *done = true;
    }
    Ok(())
}

/// egui's causes are those of its last pass, which asked for this frame.
fn record_repaint_causes(mut contexts: EguiContexts, mut causes: ResMut<RepaintCauses>) -> Result {
    causes.0 = contexts
        .ctx_mut()?
        .repaint_causes()
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    Ok(())
}

fn pointer_on_ui(on_ui: Res<PointerOnUi>) -> bool {
    on_ui.0
}

/// bevy_egui 0.42 puts a `ModifiersChanged` event into every frame's input, changed or not,
/// and egui answers any input event with a request for an immediate repaint: the idle window
/// redrew without end (a frame every few seconds of full CPU under a software renderer). Only a
/// real change of the modifier keys is passed on; egui keeps the last modifiers between frames.
fn drop_unchanged_modifiers(
    mut inputs: Query<&mut EguiInput>,
    mut last: Local<Option<egui::Modifiers>>,
) {
    for mut input in &mut inputs {
        input.events.retain(|event| match event {
            egui::Event::ModifiersChanged(modifiers) => {
                let changed = *last != Some(*modifiers);
                *last = Some(*modifiers);
                changed
            }
            _ => true,
        });
    }
}

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

/// The settings panel on the left, with the Recordings section; the 3D view goes beside it.
fn left_panel(
    mut contexts: EguiContexts,
    mut state: settings::SettingsParam,
    mut recordings: recordings::RecordingsParam,
    mut stress: stress::StressParam,
    mut practice: practice::PracticeParam,
    mut inset: ResMut<ViewInset>,
    mut read_error: Local<Option<String>>,
) -> Result {
    let ctx = contexts.ctx_mut()?.clone();
    // The panel sits in an egui Area, not in a bare root `Ui` on the background layer: egui
    // knows an area's rect, so it reports the pointer as over the panel and the game's pointer
    // input (aim, camera) stays off there. A bare root `Ui` is registered nowhere, so clicks and
    // the wheel on the panel used to reach the table as well.
    let panel_width = egui::Area::new(egui::Id::new("settings panel"))
        .order(egui::Order::Middle)
        .fixed_pos(ctx.viewport_rect().min)
        .movable(false)
        .constrain(false)
        .show(&ctx, |area| {
            area.set_max_size(ctx.viewport_rect().size());
            egui::Panel::left("settings")
                .resizable(false)
                .exact_size(PANEL_WIDTH)
                .show(area, |ui| {
                    // A scroll bar that is always there and takes its own width: one that
                    // appeared on hover narrowed the panel and re-wrapped its rows.
                    ui.style_mut().spacing.scroll = egui::style::ScrollStyle::solid();
                    egui::ScrollArea::vertical()
                        .scroll_bar_visibility(
                            egui::scroll_area::ScrollBarVisibility::AlwaysVisible,
                        )
                        .auto_shrink(false)
                        .show(ui, |ui| {
                            settings::sections(ui, &mut state);
                            practice::section(ui, &mut practice);
                            stress::section(ui, &mut stress);
                            recordings::section(ui, &mut recordings);
                            settings::file_and_controls(ui, &mut state);
                        });
                })
                .response
                .rect
                .width()
        })
        .inner;
    settings::rack_confirm_window(&ctx, &mut state);
    stress::confirm_window(&ctx, &mut stress);
    practice::drill_window(&ctx, &mut practice, inset.top);
    // Below the HUD, however tall it has grown (the last pass's height).
    settings::config_error_window(&ctx, &state, &mut read_error, inset.top);
    recordings::error_window(&ctx, &mut recordings, inset.top);
    // The 3D view takes the window right of the panel (src/view.rs).
    if inset.left != panel_width {
        inset.left = panel_width;
    }
    Ok(())
}

/// Below 100 % render scale the table camera draws into an image; it is stretched over the
/// whole window on egui's background layer, under every panel and window, so the UI itself
/// is still drawn at the window's full resolution.
fn show_scene_image(mut contexts: EguiContexts, scene: Res<SceneTarget>) -> Result {
    let Some(image) = &scene.image else {
        return Ok(());
    };
    // Registered by id: the image goes when src/view.rs drops it, and bevy_egui then forgets
    // it too.
    let texture = contexts.add_image(EguiTextureHandle::Weak(image.id()));
    let ctx = contexts.ctx_mut()?;
    let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
    ctx.layer_painter(egui::LayerId::background()).image(
        texture,
        ctx.viewport_rect(),
        uv,
        egui::Color32::WHITE,
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use bevy::{prelude::*, window::RequestRedraw};
    use bevy_egui::EguiRenderOutput;
    use bevy_egui::egui;

    /// Frames whose egui output changes a texture ask for one more frame; others do not.
    #[test]
    fn a_texture_change_asks_for_one_more_frame() {
        let mut app = App::new();
        app.add_message::<RequestRedraw>()
            .add_systems(Update, super::redraw_after_texture_change);
        let context = app.world_mut().spawn(EguiRenderOutput::default()).id();
        let requests = |app: &mut App| {
            app.update();
            let messages = app.world().resource::<Messages<RequestRedraw>>();
            messages.iter_current_update_messages().count()
        };
        assert_eq!(requests(&mut app), 0, "nothing changed");
        let glyphs = egui::epaint::ImageDelta::full(
            egui::ColorImage::filled([1, 1], egui::Color32::WHITE),
            egui::TextureOptions::LINEAR,
        );
        let mut output = EguiRenderOutput::default();
        output
            .textures_delta
            .set
            .insert(egui::TextureId::default(), [glyphs].into_iter().collect());
        app.world_mut().entity_mut(context).insert(output);
        assert_eq!(requests(&mut app), 1, "new glyphs");
    }
}
