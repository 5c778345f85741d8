//! Settings kept between runs: the physics, view and graphics settings and the table, in a
//! JSON file in the platform's config directory (`$XDG_CONFIG_HOME/billiards/settings.json`,
//! else `~/.config/billiards/settings.json`; `~/Library/Application Support/billiards` on macOS,
//! `%APPDATA%\billiards` on Windows).
//!
//! Read once at start; written (atomically: a temporary file, then a rename) whenever what it
//! holds changes. A file that cannot be read or parsed is reported in the panel and the
//! defaults are used; it is replaced only at the next change. Missing fields take their
//! defaults, so files from older builds keep loading.

use std::{
    ffi::OsString,
    path::{Path, PathBuf},
};

use bevy::prelude::*;
use serde::{Deserialize, Serialize};

use crate::{
    practice::{DrillBests, DrillList},
    settings::{GraphicsSettings, PhysicsSettings, TableSetup, ViewSettings},
    table::geometry::TableSpec,
};

/// Loads the settings file at start and saves it on every change.
pub fn plugin(app: &mut App) {
    app.init_resource::<ConfigFile>()
        .add_systems(PreStartup, load_config)
        .add_systems(Last, save_config);
}

/// Where the settings are kept and how the last read or write went. `path: None` keeps
/// nothing (no config directory, or `--no-config`).
#[derive(Resource, Debug, Clone, PartialEq, Default)]
pub struct ConfigFile {
    /// The file.
    pub path: Option<PathBuf>,
    /// Why the file could not be read or written, for the panel.
    pub error: Option<String>,
    /// The text last read or written, so an unchanged setting writes nothing.
    written: Option<String>,
}

impl ConfigFile {
    /// Keeps the settings in `path`.
    pub fn at(path: impl Into<PathBuf>) -> Self {
        Self {
            path: Some(path.into()),
            ..default()
        }
    }

    /// The platform's settings file (see the module docs), if a config directory is known.
    pub fn platform_default() -> Self {
        Self {
            path: config_dir(|name| std::env::var_os(name)).map(|dir| dir.join(FILE_NAME)),
            ..default()
        }
    }
}

/// The settings file's name in the game's config directory.
pub const FILE_NAME: &str = "settings.json";

/// Everything the file holds. Every part defaults, so a partial file loads.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Config {
    /// Friction, restitution, model, time scale.
    pub physics: PhysicsSettings,
    /// Overlays and the aiming aid.
    pub view: ViewSettings,
    /// Graphics quality.
    pub graphics: GraphicsSettings,
    /// The table and the rack style.
    pub table: TableSetup,
    /// The best session of each drill, by its file name (issue 39).
    pub drills: DrillBests,
}

impl Config {
    /// Parses a settings file's text; the error names the line and column.
    pub fn from_json(text: &str) -> Result<Self, String> {
        let mut config: Self = serde_json::from_str(text).map_err(|e| e.to_string())?;
        // Out-of-range values from a hand-edited file are pulled into range, as in the panel.
        config.physics.clamp_to_physical();
        config.graphics = config.graphics.sanitized();
        config.view.aid_contacts = config.view.aid_contacts.clamp(
            *ViewSettings::AID_CONTACTS.start(),
            *ViewSettings::AID_CONTACTS.end(),
        );
        Ok(config)
    }

    /// The file's text.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("settings serialize")
    }
}

/// The game's config directory from the environment (`var` reads a variable): XDG on Linux
/// and other Unixes, Application Support on macOS, `%APPDATA%` on Windows.
pub fn config_dir(var: impl Fn(&str) -> Option<OsString>) -> Option<PathBuf> {
    let absolute = |name: &str| {
        var(name)
            .map(PathBuf::from)
            .filter(|path| path.is_absolute())
    };
    let base = if cfg!(windows) {
        absolute("APPDATA")
    } else if cfg!(target_os = "macos") {
        absolute("HOME").map(|home| home.join("Library/Application Support"))
    } else {
        // XDG: a relative XDG_CONFIG_HOME is invalid and ignored.
        absolute("XDG_CONFIG_HOME").or_else(|| absolute("HOME").map(|home| home.join(".config")))
    };
    base.map(|dir| dir.join("billiards"))
}

/// Reads `path`: `Ok(None)` when there is no file yet.
pub fn read(path: &Path) -> Result<Option<Config>, String> {
    match std::fs::read_to_string(path) {
        Ok(text) => Config::from_json(&text)
            .map(Some)
            .map_err(|e| format!("{}: {e}", path.display())),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(format!("{}: {e}", path.display())),
    }
}

/// Writes `text` to `path` atomically (a temporary file beside it, then a rename).
fn write(path: &Path, text: &str) -> Result<(), String> {
    let fail = |e: std::io::Error| format!("{}: {e}", path.display());
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(fail)?;
    }
    let tmp = path.with_extension(format!("json.tmp{}", std::process::id()));
    std::fs::write(&tmp, text).map_err(fail)?;
    std::fs::rename(&tmp, path).map_err(fail)
}

fn load_config(
    mut file: ResMut<ConfigFile>,
    mut physics: ResMut<PhysicsSettings>,
    mut view: ResMut<ViewSettings>,
    mut graphics: ResMut<GraphicsSettings>,
    (mut table, spec): (ResMut<TableSetup>, Option<ResMut<TableSpec>>),
    (drills, list): (Option<ResMut<DrillBests>>, Option<ResMut<DrillList>>),
) {
    let Some(path) = file.path.clone() else {
        return;
    };
    // The player's own drills live beside the settings file (issue 47).
    if let (Some(mut list), Some(dir)) = (list, path.parent()) {
        list.user_folder = Some(dir.join("drills"));
        list.reload();
    }
    match read(&path) {
        Ok(Some(config)) => {
            *physics = config.physics;
            *view = config.view;
            *graphics = config.graphics;
            *table = config.table;
            if let Some(mut drills) = drills {
                *drills = config.drills.clone();
            }
            // The first rack and the table's meshes already follow the kept table.
            if let Some(mut spec) = spec {
                spec.set_if_neq(TableSpec::of(table.table));
            }
            file.written = Some(config.to_json());
        }
        // Nothing yet: the file appears at the first change.
        Ok(None) => file.written = Some(Config::default().to_json()),
        Err(error) => {
            let error = format!(
                "settings not loaded, defaults used ({error}); the file is replaced at the next change"
            );
            warn!("{error}");
            file.error = Some(error);
            // As if the defaults were on disk: the broken file is replaced only once the
            // player changes something.
            file.written = Some(Config::default().to_json());
        }
    }
}

fn save_config(
    mut file: ResMut<ConfigFile>,
    physics: Res<PhysicsSettings>,
    view: Res<ViewSettings>,
    graphics: Res<GraphicsSettings>,
    table: Res<TableSetup>,
    drills: Option<Res<DrillBests>>,
) {
    let drills_changed = drills.as_ref().is_some_and(|d| d.is_changed());
    if !(physics.is_changed()
        || view.is_changed()
        || graphics.is_changed()
        || table.is_changed()
        || drills_changed)
    {
        return;
    }
    let Some(path) = file.path.clone() else {
        return;
    };
    let text = Config {
        physics: *physics,
        view: *view,
        graphics: *graphics,
        table: *table,
        drills: drills.map(|d| d.clone()).unwrap_or_default(),
    }
    .to_json();
    // Pausing, or a slider back where it was, changes nothing kept.
    if file.written.as_ref() == Some(&text) {
        return;
    }
    match write(&path, &text) {
        Ok(()) => {
            file.written = Some(text);
            file.error = None;
        }
        Err(error) => {
            warn!("settings not saved: {error}");
            file.error = Some(format!("settings not saved: {error}"));
        }
    }
}

/// Puts every kept setting back to its default (the file follows at once).
pub fn reset_to_defaults(
    physics: &mut PhysicsSettings,
    view: &mut ViewSettings,
    graphics: &mut GraphicsSettings,
) {
    let paused = physics.paused;
    *physics = PhysicsSettings {
        paused,
        ..default()
    };
    *view = default();
    *graphics = default();
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env<'a>(vars: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<OsString> + 'a {
        move |name| {
            vars.iter()
                .find(|(n, _)| *n == name)
                .map(|(_, v)| OsString::from(v))
        }
    }

    #[cfg(all(unix, not(target_os = "macos")))]
    #[test]
    fn xdg_config_home_wins_over_home() {
        let both = [("XDG_CONFIG_HOME", "/x/cfg"), ("HOME", "/home/p")];
        assert_eq!(
            config_dir(env(&both)),
            Some(PathBuf::from("/x/cfg/billiards"))
        );
        let home = [("HOME", "/home/p"), ("XDG_CONFIG_HOME", "relative")];
        assert_eq!(
            config_dir(env(&home)),
            Some(PathBuf::from("/home/p/.config/billiards"))
        );
        assert_eq!(config_dir(env(&[])), None);
    }

    #[test]
    fn a_config_round_trips_and_a_partial_one_takes_defaults() {
        let mut config = Config::default();
        config.physics.mu_slide = 0.3;
        config.view.aid_contacts = 5;
        config.graphics = GraphicsSettings::LOW;
        assert_eq!(Config::from_json(&config.to_json()), Ok(config.clone()));
        let partial = Config::from_json(r#"{"view": {"show_vectors": false}}"#).unwrap();
        assert!(!partial.view.show_vectors);
        assert_eq!(partial.physics, PhysicsSettings::default());
    }

    #[test]
    fn a_malformed_file_is_an_error_naming_the_file_not_a_panic() {
        let dir = std::env::temp_dir().join(format!("billiards-config-{}", std::process::id()));
        let path = dir.join(FILE_NAME);
        std::fs::create_dir_all(&dir).unwrap();
        assert_eq!(read(&path), Ok(None));
        std::fs::write(&path, "{\"physics\": {\"mu_slide\": \"much\"}}").unwrap();
        let error = read(&path).unwrap_err();
        assert!(
            error.contains("settings.json") && error.contains("line 1"),
            "{error}"
        );
        // Out of range is clamped, not refused.
        std::fs::write(&path, r#"{"physics": {"mu_slide": 9.0}}"#).unwrap();
        let config = read(&path).unwrap().unwrap();
        assert_eq!(config.physics.mu_slide, PhysicsSettings::MU_SLIDE.max);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
