//! Every egui part of the game, and nothing else: the settings panel on the left, the HUD,
//! the Recordings section and the replay timeline. Widgets only read resources and write
//! settings or messages; the game's logic runs without them (the headless tests).
//!
//! - [`layout`]: shared sizes and colours;
//! - [`settings`]: the panel's shot, physics, simulation and view sections;
//! - [`practice`]: the Position section (placing balls, position codes) and the drill window;
//! - [`stress`]: the Stress table section (ball count, friction, seed, table size);
//! - [`recordings`]: the Recordings section (open a recording);
//! - [`timeline`]: the replay timeline strip and the Export form;
//! - [`hud`]: the HUD in the top-right corner;
//! - [`game`]: the match's HUD lines, the new-game dialog, the verdict, the call, the end of
//!   a rack.
//!
//! The 3D view is fitted to the part of the window right of the panel (the panel's width goes
//! to [`crate::view`]), so the panel never covers the table; below 100 % render scale the
//! table's image is drawn here, under everything else. While egui has claimed the pointer or
//! the keyboard, the game's input systems ([`InputSystems`]) do not run, so input meant for a
//! widget never reaches the table.

pub mod game;
pub mod hud;
pub mod layout;
pub mod layout_check;
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
        .init_resource::<game::NewGameForm>()
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
        .add_systems(Update, game::remember_new_game)
        .add_systems(
            PostUpdate,
            redraw_after_texture_change
                .after(EguiPostUpdateSet::ProcessOutput)
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

/// The pointer-button releases (and what follows them) held back for the next frame, by egui
/// context.
#[derive(Default)]
struct HeldEvents(Vec<(Entity, Vec<egui::Event>)>);

/// Splits `events` (after the ones held back from the last frame, `held`) where a button is
/// released that was pressed earlier in them: what comes from there on is returned, to be
/// read next frame.
fn split_at_click(held: Vec<egui::Event>, events: &mut Vec<egui::Event>) -> Vec<egui::Event> {
    let mut all = held;
    all.append(events);
    let mut pressed = [false; egui::NUM_POINTER_BUTTONS];
    let split = all.iter().position(|event| match *event {
        egui::Event::PointerButton {
            button, pressed: p, ..
        } => {
            let released_after_press = !p && pressed[button as usize];
            pressed[button as usize] |= p;
            released_after_press
        }
        _ => false,
    });
    let later = split.map_or_else(Vec::new, |k| all.split_off(k));
    *events = all;
    later
}

/// egui's slider senses drags only: a press and its release read in one frame (a click on a
/// slow frame, a second under a software renderer) is no drag, and a click on a slider's
/// rail did nothing (the time scale, played under Xvfb). The release of a button pressed in
/// the same frame, and every event after it, is read one frame later, and that frame is asked
/// for. Buttons take their click a frame later; nothing else changes.
fn split_one_frame_clicks(
    mut inputs: Query<(Entity, &mut EguiInput)>,
    mut held: Local<HeldEvents>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    let mut next = Vec::new();
    for (entity, mut input) in &mut inputs {
        let from_last = held
            .0
            .iter_mut()
            .find(|(e, _)| *e == entity)
            .map(|(_, events)| std::mem::take(events))
            .unwrap_or_default();
        let later = split_at_click(from_last, &mut input.events);
        if !later.is_empty() {
            next.push((entity, later));
        }
    }
    if !next.is_empty() {
        redraw.write(RequestRedraw);
    }
    held.0 = next;
}

/// egui's own limit on how long a click's button may be held (`InputOptions`), seconds.
const EGUI_CLICK_SECONDS: f64 = 0.8;

/// The longest press egui counts as a click after a frame of `frame_seconds`: its own limit
/// plus that frame. egui times a press by the real time of the frames that read its down and
/// up events; on a slow frame (a second or more under a software renderer) a click's press
/// wakes the idle window and its release is read a frame later, a frame's time after.
fn max_click_duration(frame_seconds: f64) -> f64 {
    EGUI_CLICK_SECONDS + frame_seconds.max(0.0)
}

/// Played under Xvfb at 0.5 fps, the new-game dialog's buttons needed two clicks: the first
/// was held "2 s" by egui's clock. The click limit now grows by the last frame's time (on a
/// 60 fps machine it is egui's own, give or take 17 ms).
fn allow_slow_clicks(mut contexts: EguiContexts, time: Res<Time<Real>>) -> Result {
    let limit = max_click_duration(time.delta_secs_f64());
    contexts
        .ctx_mut()?
        .options_mut(|o| o.input_options.max_click_duration = limit);
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
    use bevy_egui::egui::{self, Event, PointerButton, pos2, vec2};

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

    /// Runs one egui pass with `events` over a button at (100, 100); whether it was clicked.
    fn pass(ctx: &egui::Context, events: Vec<Event>) -> bool {
        timed_pass(ctx, None, events, |ui| ui.button("Shoot").clicked())
    }

    /// One egui pass of an 800x600 screen at `time` (egui's own clock when `None`) with
    /// `events`, `widget` in an area at (100, 100); what `widget` returned.
    fn timed_pass<R: Default>(
        ctx: &egui::Context,
        time: Option<f64>,
        events: Vec<Event>,
        mut widget: impl FnMut(&mut egui::Ui) -> R,
    ) -> R {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                pos2(0.0, 0.0),
                vec2(800.0, 600.0),
            )),
            time,
            events,
            ..Default::default()
        };
        let mut out = R::default();
        let _ = ctx.run_ui(input, |ui| {
            egui::Area::new(egui::Id::new("area"))
                .fixed_pos(pos2(100.0, 100.0))
                .show(ui.ctx(), |ui| out = widget(ui));
        });
        out
    }

    fn button(pos: egui::Pos2, pressed: bool) -> Event {
        Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers: Default::default(),
        }
    }

    /// A click on a slider's rail moves it once the release is held back a frame
    /// (`split_at_click`), and not when egui reads press and release in one frame.
    #[test]
    fn a_click_on_a_slider_rail_moves_it_when_split() {
        let run = |ctx: &egui::Context, time: f64, events: Vec<Event>, value: &mut f64| {
            timed_pass(ctx, Some(time), events, |ui| {
                ui.add(egui::Slider::new(value, 0.0..=4.0).show_value(false));
            })
        };
        // 90 % along the rail (the slider is 100 points wide by default).
        let at = pos2(190.0, 109.0);
        for split in [false, true] {
            let ctx = egui::Context::default();
            let mut value = 1.0;
            run(&ctx, 1.0, Vec::new(), &mut value);
            run(&ctx, 2.0, vec![Event::PointerMoved(at)], &mut value);
            let mut events = vec![button(at, true), button(at, false)];
            let later = if split {
                super::split_at_click(Vec::new(), &mut events)
            } else {
                Vec::new()
            };
            run(&ctx, 3.0, events, &mut value);
            let mut next = Vec::new();
            let held = super::split_at_click(later, &mut next);
            assert!(held.is_empty());
            run(&ctx, 4.0, next, &mut value);
            let moved = (value - 3.6).abs() < 0.2;
            assert_eq!(moved, split, "split {split}: value {value}");
        }
    }

    /// Only a release after a press of the same button in the same frame is held back, with
    /// what follows it; held events come first next frame.
    #[test]
    fn only_a_release_after_its_press_is_held_back() {
        let p = pos2(1.0, 1.0);
        let mut events = vec![button(p, false), Event::PointerMoved(p), button(p, true)];
        assert!(super::split_at_click(Vec::new(), &mut events).is_empty());
        assert_eq!(events.len(), 3);
        let mut events = vec![
            button(p, true),
            Event::PointerMoved(p),
            button(p, false),
            Event::Text("a".to_owned()),
        ];
        let later = super::split_at_click(Vec::new(), &mut events);
        assert_eq!(events, vec![button(p, true), Event::PointerMoved(p)]);
        assert_eq!(later, vec![button(p, false), Event::Text("a".to_owned())]);
        let mut next = vec![Event::PointerMoved(p)];
        assert!(super::split_at_click(later, &mut next).is_empty());
        assert_eq!(next[0], button(p, false));
        assert_eq!(next.len(), 3);
    }

    /// A click whose press and release egui reads in two frames 2 s apart (the press woke
    /// an idle window whose frame took 2 s) is lost at egui's own limit and counted with the
    /// limit of `max_click_duration` for that frame.
    #[test]
    fn a_click_split_over_a_slow_frame_clicks_the_button() {
        let on = pos2(110.0, 108.0);
        let run = |ctx: &egui::Context, time: f64, events: Vec<Event>| {
            timed_pass(ctx, Some(time), events, |ui| ui.button("Start").clicked())
        };
        for (limit, expected) in [
            (super::EGUI_CLICK_SECONDS, false),
            (super::max_click_duration(2.0), true),
        ] {
            let ctx = egui::Context::default();
            ctx.options_mut(|o| o.input_options.max_click_duration = limit);
            assert!(!run(&ctx, 9.0, Vec::new()));
            assert!(!run(&ctx, 10.0, vec![Event::PointerMoved(on)]));
            assert!(!run(&ctx, 12.0, vec![button(on, true)]));
            let clicked = run(&ctx, 14.0, vec![button(on, false)]);
            assert_eq!(clicked, expected, "limit {limit} s");
        }
    }

    /// A pointer that jumps onto a button and clicks within one frame (a 1 fps machine, or
    /// `xdotool mousemove X Y click 1`) clicks it, whatever the order and positions of the
    /// events egui gets in that frame: bevy_egui 0.42 hands them over in the window's order
    /// (the move, then the press at the new position), and egui picks the widget under the
    /// frame's last pointer position even for a press still at the old one or a press and
    /// release before the move. A click lost this way was the table's, not egui's (see
    /// `input::held_or_clicked`).
    #[test]
    fn a_jump_and_click_within_one_frame_clicks_the_button() {
        let (away, on) = (pos2(700.0, 500.0), pos2(110.0, 108.0));
        let orders = [
            vec![Event::PointerMoved(on), button(on, true), button(on, false)],
            vec![
                Event::PointerMoved(on),
                button(away, true),
                button(on, false),
            ],
            vec![
                button(away, true),
                button(away, false),
                Event::PointerMoved(on),
            ],
        ];
        for events in orders {
            let ctx = egui::Context::default();
            assert!(!pass(&ctx, vec![Event::PointerMoved(away)]));
            assert!(!pass(&ctx, Vec::new()));
            assert!(pass(&ctx, events.clone()), "not clicked: {events:?}");
            // Nothing more without a new click.
            assert!(!pass(&ctx, Vec::new()));
        }
    }
}
