//! Headless tests of the settings file: kept between runs, reset, a malformed file.

use bevy::{ecs::system::RunSystemOnce, prelude::*};
use billiards::{
    config::{self, Config, ConfigFile},
    settings::{self, GraphicsSettings, PhysicsSettings, ViewSettings},
};

fn app_with_config(path: &std::path::Path) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, settings::plugin, config::plugin));
    app.insert_resource(ConfigFile::at(path));
    app.update();
    app
}

fn temp_config(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-config-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir.join("billiards").join(config::FILE_NAME)
}

/// A change is written at once; the next run starts from it; "reset to defaults" goes back.
#[test]
fn settings_are_kept_between_runs_and_reset() {
    let path = temp_config("kept");
    {
        let mut app = app_with_config(&path);
        assert!(!path.exists(), "nothing written before a change");
        app.world_mut().resource_mut::<PhysicsSettings>().mu_slide = 0.3;
        app.world_mut().resource_mut::<ViewSettings>().aid_contacts = 4;
        *app.world_mut().resource_mut::<GraphicsSettings>() = GraphicsSettings::LOW;
        app.update();
        assert!(path.exists());
        // Pausing is not kept: nothing to write.
        let written = std::fs::read_to_string(&path).unwrap();
        app.world_mut().resource_mut::<PhysicsSettings>().paused = true;
        app.update();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), written);
    }
    let mut app = app_with_config(&path);
    assert_eq!(app.world().resource::<PhysicsSettings>().mu_slide, 0.3);
    assert_eq!(app.world().resource::<ViewSettings>().aid_contacts, 4);
    assert_eq!(
        *app.world().resource::<GraphicsSettings>(),
        GraphicsSettings::LOW
    );
    assert_eq!(app.world().resource::<ConfigFile>().error, None);

    app.world_mut()
        .run_system_once(
            |mut p: ResMut<PhysicsSettings>,
             mut v: ResMut<ViewSettings>,
             mut g: ResMut<GraphicsSettings>| {
                config::reset_to_defaults(&mut p, &mut v, &mut g);
            },
        )
        .unwrap();
    app.update();
    let text = std::fs::read_to_string(&path).unwrap();
    assert_eq!(Config::from_json(&text), Ok(Config::default()));
    let _ = std::fs::remove_dir_all(path.parent().unwrap().parent().unwrap());
}

/// A malformed file: the defaults are used, the panel gets a message naming the file, and the
/// file is left alone until the player changes something.
#[test]
fn a_malformed_file_falls_back_to_the_defaults_with_a_message() {
    let path = temp_config("malformed");
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(&path, "{ this is not json").unwrap();
    let mut app = app_with_config(&path);
    assert_eq!(
        *app.world().resource::<PhysicsSettings>(),
        PhysicsSettings::default()
    );
    let error = app.world().resource::<ConfigFile>().error.clone().unwrap();
    assert!(
        error.contains("settings.json") && error.contains("defaults"),
        "{error}"
    );
    app.update();
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        "{ this is not json"
    );
    app.world_mut().resource_mut::<ViewSettings>().show_vectors = false;
    app.update();
    let config = Config::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert!(!config.view.show_vectors);
    assert_eq!(app.world().resource::<ConfigFile>().error, None);
    let _ = std::fs::remove_dir_all(path.parent().unwrap().parent().unwrap());
}

/// The render scale is kept like the other graphics settings, and a value the game does not
/// offer (a hand-edited file) becomes the nearest one it does.
#[test]
fn the_render_scale_is_kept_and_a_bad_one_corrected() {
    let path = temp_config("render-scale");
    {
        let mut app = app_with_config(&path);
        assert_eq!(app.world().resource::<GraphicsSettings>().render_scale, 100);
        app.world_mut()
            .resource_mut::<GraphicsSettings>()
            .render_scale = 50;
        app.update();
    }
    let app = app_with_config(&path);
    assert_eq!(app.world().resource::<GraphicsSettings>().render_scale, 50);
    drop(app);
    for (written, read) in [(63, 75), (10, 50), (0, 50), (400, 100), (87, 75), (88, 100)] {
        std::fs::write(
            &path,
            format!(r#"{{"graphics": {{"render_scale": {written}}}}}"#),
        )
        .unwrap();
        let app = app_with_config(&path);
        let graphics = *app.world().resource::<GraphicsSettings>();
        assert_eq!(graphics.render_scale, read, "{written} in the file");
        // The rest of the section keeps its defaults.
        assert_eq!(
            GraphicsSettings {
                render_scale: 100,
                ..graphics
            },
            GraphicsSettings::default()
        );
        assert_eq!(app.world().resource::<ConfigFile>().error, None);
    }
    let _ = std::fs::remove_dir_all(path.parent().unwrap().parent().unwrap());
}
