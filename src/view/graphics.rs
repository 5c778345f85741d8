//! Graphics quality ([`GraphicsSettings`]: shadows, shadow resolution, MSAA) applied to the
//! lamps and cameras, and the frame rate the HUD shows.

use std::collections::VecDeque;

use bevy::{light::PointLightShadowMap, prelude::*, render::view::Msaa};

use crate::settings::GraphicsSettings;

/// Applies the graphics settings when they change and measures the frame rate.
pub fn plugin(app: &mut App) {
    app.init_resource::<FrameRate>()
        .add_systems(Update, (apply_graphics, measure_frame_rate));
}

/// Frames per second over the last second of continuous drawing.
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct FrameRate {
    /// Real times of the recent frames, seconds since start.
    recent: VecDeque<f64>,
    /// The rate, once a few frames came in a row; `None` after an idle gap (the window draws
    /// only on input or motion, so an idle rate means nothing).
    pub fps: Option<f64>,
}

/// A gap this long between two frames means the window was idle, not slow (a software
/// renderer takes seconds per frame).
const IDLE_GAP: f64 = 5.0;

fn measure_frame_rate(time: Res<Time<Real>>, mut rate: ResMut<FrameRate>) {
    let now = time.elapsed_secs_f64();
    if rate
        .recent
        .back()
        .is_some_and(|&last| now - last > IDLE_GAP)
    {
        rate.recent.clear();
    }
    rate.recent.push_back(now);
    // At least the last second, and at least three frames (slow machines).
    while rate.recent.len() > 3 && now - rate.recent[0] > 1.0 {
        rate.recent.pop_front();
    }
    let span = now - rate.recent[0];
    rate.fps =
        (rate.recent.len() >= 3 && span > 0.0).then(|| (rate.recent.len() - 1) as f64 / span);
}

fn apply_graphics(
    mut commands: Commands,
    settings: Res<GraphicsSettings>,
    mut lamps: Query<&mut SpotLight>,
    cameras: Query<Entity, With<Camera>>,
    added: Query<(), Added<Camera>>,
) {
    // Cameras spawned after a change (the first frame) get the settings too.
    if !settings.is_changed() && added.is_empty() {
        return;
    }
    for mut lamp in &mut lamps {
        lamp.shadow_maps_enabled = settings.shadows;
    }
    commands.insert_resource(PointLightShadowMap {
        size: settings.shadow_resolution as usize,
    });
    let msaa = match settings.msaa_samples {
        0 | 1 => Msaa::Off,
        2 => Msaa::Sample2,
        _ => Msaa::Sample4,
    };
    // Every camera drawing into the window uses the same sample count.
    for camera in &cameras {
        commands.entity(camera).insert(msaa);
    }
}
