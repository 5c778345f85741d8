//! A 3D pool game on Bevy, on top of the exact event-driven solver `billiards-physics`.
//!
//! One plugin per feature; [`GamePlugin`] puts them together with Bevy's. The game's modes are
//! [`mode::GameMode`]; every egui part lives in [`ui`], which also adds egui itself.

pub mod config;
pub mod input;
pub mod mode;
pub mod options;
pub mod play;
pub mod practice;
pub mod recording;
pub mod replay;
pub mod settings;
pub mod sim;
pub mod sound;
pub mod stress;
pub mod table;
pub mod ui;
pub mod view;

use std::time::Duration;

use bevy::{
    prelude::*,
    window::WindowResolution,
    winit::{UpdateMode, WinitSettings},
};

pub use options::{ArgsError, LaunchOptions};

/// The whole game: Bevy's default plugins and the game's feature plugins.
#[derive(Debug, Clone, Default)]
pub struct GamePlugin {
    /// What the command line asked for.
    pub options: LaunchOptions,
}

impl Plugin for GamePlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins(DefaultPlugins.set(WindowPlugin {
            primary_window: Some(Window {
                title: "Billiards".into(),
                resolution: match self.options.size {
                    Some((width, height)) => WindowResolution::new(width, height),
                    None => WindowResolution::new(1280, 720),
                },
                ..default()
            }),
            ..default()
        }))
        .add_plugins((mode::plugin, view::pipelines::plugin))
        .add_plugins((
            settings::plugin,
            sim::plugin,
            table::plugin,
            table::balls::plugin,
            play::cue::plugin,
            play::aim::plugin,
            view::camera::plugin,
            view::lighting::plugin,
            ui::plugin,
            recording::plugin,
            replay::plugin,
            play::game::plugin,
            play::game::table_plugin,
            play::computer::plugin,
            play::script::plugin,
        ))
        .add_plugins((
            config::plugin,
            view::graphics::plugin,
            view::plugin,
            stress::plugin,
            practice::plugin,
        ));
        #[cfg(feature = "sound")]
        app.add_plugins(sound::plugin);
        self.insert_options(app);
        match &self.options.screenshot {
            Some(path) => {
                app.add_plugins(view::screenshot::ScreenshotPlugin {
                    path: path.clone(),
                    settle: self.options.screenshot_settle,
                });
            }
            // Redraw only on input or when something asks for it (moving balls, the camera
            // easing): an idle table costs no CPU.
            None => {
                app.add_systems(Update, view::pipelines::redraw_until_ready);
                // No periodic wake-up either (`desktop_app` updates every 5 s at idle): a frame
                // is drawn only for input, a window event or a `RequestRedraw`.
                app.insert_resource(WinitSettings {
                    focused_mode: UpdateMode::reactive(Duration::MAX),
                    unfocused_mode: UpdateMode::reactive_low_power(Duration::MAX),
                });
            }
        }
    }
}

impl GamePlugin {
    /// The command line's options as resources the plugins read at startup (the game, the
    /// script, a position or drill, the stress table, the recordings folder, the config file,
    /// the layout check, the view).
    fn insert_options(&self, app: &mut App) {
        if let Some(file) = &self.options.replay {
            app.insert_resource(replay::OpenAtStart(file.clone()));
        }
        if let Some(game) = self.options.game {
            app.insert_resource(play::game::StartGame {
                game,
                computer: self.options.computer,
                seed: self.options.seed,
            });
        }
        if !self.options.script.is_empty() {
            app.insert_resource(play::script::LaunchScript(
                self.options.script.iter().copied().collect(),
            ));
        }
        if let Some(position) = &self.options.position {
            app.insert_resource(practice::StartPosition(position.clone()));
        }
        if let Some(name) = &self.options.drill {
            app.insert_resource(practice::StartDrill(name.clone()));
        }
        if let Some(balls) = self.options.stress {
            app.insert_resource(stress::StartStress(balls));
        }
        if self.options.no_record {
            app.insert_resource(recording::RecordingsFolder(None));
        } else if let Some(folder) = &self.options.recordings {
            app.insert_resource(recording::RecordingsFolder(Some(folder.clone())));
        }
        app.insert_resource(if self.options.no_config {
            config::ConfigFile::default()
        } else {
            config::ConfigFile::platform_default()
        });
        if let Some(path) = &self.options.check_layout {
            app.insert_resource(ui::layout_check::LayoutReport(path.clone()));
        }
        if self.options.open_sections {
            app.insert_resource(ui::OpenSections(true));
        }
        if let Some(seconds) = self.options.count_idle_frames {
            app.add_plugins(view::idle::IdleCountPlugin { seconds });
        }
        if self.options.top_view {
            app.insert_resource(view::camera::OrbitCamera::top_view());
        }
    }
}
