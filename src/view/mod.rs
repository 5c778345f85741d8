//! The 3D view: where the table camera draws and at what resolution.
//!
//! The view takes the window right of the settings panel ([`ViewInset`]). At a render scale of
//! 100 % ([`GraphicsSettings::render_scale`]) the table camera draws straight into the window.
//! Below it draws into an image of the window's physical size times the scale
//! ([`SceneTarget`]), which the UI stretches over the whole window under its panels: the 3D
//! view costs a quarter of the pixels at 50 % while the UI's text stays sharp. A pointer
//! position in the window is mapped into that image by [`cursor_in_target`]. Anti-aliasing
//! works the same on the image: Bevy resolves the camera's multisampled texture before it
//! writes the target. Screenshots of the window include the image, drawn by the UI.

pub mod camera;
pub mod display;
pub mod graphics;
pub mod idle;
pub mod lighting;
pub mod pipelines;
pub mod screenshot;

use bevy::{
    camera::{ImageRenderTarget, RenderTarget, Viewport},
    gizmos::config::{DefaultGizmoConfigGroup, GizmoConfigStore},
    image::ToExtents,
    prelude::*,
    render::render_resource::TextureFormat,
    window::PrimaryWindow,
};

use crate::{settings::GraphicsSettings, view::camera::TableCamera};

/// Keeps the table camera's target and viewport fitted to the window and the render scale.
pub fn plugin(app: &mut App) {
    app.init_resource::<ViewInset>()
        .init_resource::<SceneTarget>()
        .add_systems(Update, fit_table_camera);
}

/// How much of the window the UI covers, in logical pixels: the settings panel from the left
/// edge, the HUD strip from the top edge right of the panel and, in a replay, the timeline
/// strip from the bottom edge. The 3D view takes the rest, so nothing of the UI lies over the
/// table. Written by the UI.
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq)]
pub struct ViewInset {
    /// The panel's width.
    pub left: f32,
    /// The HUD strip's height.
    pub top: f32,
    /// The replay timeline strip's height (0 outside a replay).
    pub bottom: f32,
}

impl ViewInset {
    /// Every edge times `scale` (logical to physical pixels).
    pub fn scaled(self, scale: f32) -> Self {
        Self {
            left: self.left * scale,
            top: self.top * scale,
            bottom: self.bottom * scale,
        }
    }
}

/// Where the table camera draws.
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct SceneTarget {
    /// The image it draws into below 100 %, which the UI shows over the whole window;
    /// `None` while it draws straight into the window.
    pub image: Option<Handle<Image>>,
    /// The target's size in physical pixels (the window's own at 100 %).
    pub size: UVec2,
}

/// Gizmo lines are this wide (Bevy's default) in window pixels, whatever the scale.
const GIZMO_LINE_WIDTH: f32 = 2.0;

/// The size of the image that covers a window of `window` physical pixels at `percent`
/// (at least one pixel each way).
pub fn scaled_size(window: UVec2, percent: u32) -> UVec2 {
    (window.as_vec2() * percent as f32 / 100.0)
        .round()
        .as_uvec2()
        .max(UVec2::ONE)
}

/// The 3D view inside a target of `target` physical pixels stretched over a window of `window`
/// physical pixels, clear of what `inset` covers (here in the window's physical pixels); at
/// least one pixel each way.
pub fn view_viewport(window: UVec2, target: UVec2, inset: ViewInset) -> Viewport {
    let window = window.max(UVec2::ONE);
    let target = target.max(UVec2::ONE);
    let (sx, sy) = (
        target.x as f32 / window.x as f32,
        target.y as f32 / window.y as f32,
    );
    let left = ((inset.left * sx).round() as u32).min(target.x - 1);
    let top = ((inset.top * sy).round() as u32).min(target.y - 1);
    let bottom = ((inset.bottom * sy).round() as u32).min(target.y - top - 1);
    Viewport {
        physical_position: UVec2::new(left, top),
        physical_size: UVec2::new(target.x - left, target.y - top - bottom),
        ..default()
    }
}

/// A cursor position in the window (logical pixels, as `Window::cursor_position` gives it)
/// in the logical pixels of a camera target of `target` physical pixels (scale factor
/// `target_scale`) stretched over the whole window, the coordinates
/// `Camera::viewport_to_world` expects. The identity for the window itself.
pub fn cursor_in_target(
    cursor: Vec2,
    window_scale: f32,
    window: UVec2,
    target: UVec2,
    target_scale: f32,
) -> Vec2 {
    cursor * window_scale * target.as_vec2() / window.max(UVec2::ONE).as_vec2() / target_scale
}

/// An image the table camera can draw into: sampled by the UI, never read on the CPU.
fn target_image(size: UVec2) -> Image {
    let mut image = Image::new_target_texture(size.x, size.y, TextureFormat::Rgba8UnormSrgb, None);
    // Only the GPU writes it: no zeroed copy in memory, none uploaded or copied on a resize.
    image.data = None;
    image.copy_on_resize = false;
    image
}

/// Retargets the table camera when the render scale changes, resizes its image with the
/// window, and fits its viewport beside the panel. Touches nothing when nothing changed, so
/// an idle window stays idle.
fn fit_table_camera(
    settings: Res<GraphicsSettings>,
    inset: Res<ViewInset>,
    window: Single<&Window, With<PrimaryWindow>>,
    camera: Single<(&mut Camera, &mut RenderTarget, &mut Projection), With<TableCamera>>,
    mut images: ResMut<Assets<Image>>,
    mut scene: ResMut<SceneTarget>,
    gizmos: Option<ResMut<GizmoConfigStore>>,
) {
    let (mut camera, mut target, mut projection) = camera.into_inner();
    let window_size = window.physical_size().max(UVec2::ONE);
    let scaled = settings.render_scale < 100;
    let size = if scaled {
        scaled_size(window_size, settings.render_scale)
    } else {
        window_size
    };
    let mut retargeted = false;
    match (&scene.image, scaled) {
        (Some(image), true) if scene.size != size => {
            if let Some(mut image) = images.get_mut(image) {
                image.resize(size.to_extents());
            }
            retargeted = true;
        }
        (None, true) => {
            let image = images.add(target_image(size));
            *target = RenderTarget::Image(ImageRenderTarget {
                handle: image.clone(),
                scale_factor: 1.0,
            });
            scene.image = Some(image);
            retargeted = true;
        }
        (Some(_), false) => {
            // The image is dropped with its last handle (the target's and this one).
            *target = RenderTarget::default();
            scene.image = None;
            retargeted = true;
        }
        _ => {}
    }
    if scene.size != size {
        scene.size = size;
    }
    let scale = window.scale_factor();
    let viewport = view_viewport(window_size, size, inset.scaled(scale));
    let unchanged = camera.viewport.as_ref().is_some_and(|current| {
        current.physical_position == viewport.physical_position
            && current.physical_size == viewport.physical_size
    });
    if !unchanged {
        camera.viewport = Some(viewport);
    }
    if retargeted {
        // Bevy recomputes the camera's target size when the window or its projection
        // changes, not its target: without this it would keep the old size for a frame.
        projection.set_changed();
    }
    if settings.is_changed()
        && let Some(mut gizmos) = gizmos
    {
        // Lines as wide on screen at every scale (the image is stretched).
        let (config, _) = gizmos.config_mut::<DefaultGizmoConfigGroup>();
        config.line.width = GIZMO_LINE_WIDTH * settings.render_fraction();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inset(left: f32, top: f32, bottom: f32) -> ViewInset {
        ViewInset { left, top, bottom }
    }

    /// At 50 % of a 1280x720 window with the panel's 340 px on the left, the pointer at the
    /// centre of the 3D view is at the centre of the image's viewport; at 100 % nothing moves.
    #[test]
    fn the_view_centre_maps_to_the_image_view_centre() {
        for window_scale in [1.0, 2.0] {
            let logical = Vec2::new(1280.0, 720.0);
            let window = (logical * window_scale).as_uvec2();
            let (inset, top) = (340.0, 120.0);
            let centre = Vec2::new((inset + logical.x) / 2.0, (top + logical.y) / 2.0);
            let image = scaled_size(window, 50);
            assert_eq!(image, window / 2);
            let covered = super::ViewInset {
                left: inset,
                top,
                bottom: 0.0,
            };
            let viewport = view_viewport(window, image, covered.scaled(window_scale));
            let view_centre =
                viewport.physical_position.as_vec2() + viewport.physical_size.as_vec2() / 2.0;
            let mapped = cursor_in_target(centre, window_scale, window, image, 1.0);
            assert!(
                mapped.distance(view_centre) < 1e-3,
                "{mapped} vs {view_centre} at scale factor {window_scale}"
            );
            // The window itself: window coordinates are already its logical ones.
            let same = cursor_in_target(centre, window_scale, window, window, window_scale);
            assert!(same.distance(centre) < 1e-3);
        }
    }

    #[test]
    fn odd_sizes_round_and_never_vanish() {
        assert_eq!(scaled_size(UVec2::new(1281, 721), 75), UVec2::new(961, 541));
        assert_eq!(scaled_size(UVec2::new(1, 1), 50), UVec2::ONE);
        // A panel wider than the window leaves the view one pixel.
        let viewport = view_viewport(
            UVec2::new(300, 200),
            UVec2::new(150, 100),
            inset(400.0, 0.0, 0.0),
        );
        assert_eq!(viewport.physical_position.x, 149);
        assert_eq!(viewport.physical_size, UVec2::new(1, 100));
        // A strip taller than the window too.
        let viewport = view_viewport(
            UVec2::new(300, 200),
            UVec2::new(150, 100),
            inset(0.0, 300.0, 0.0),
        );
        assert_eq!(viewport.physical_position, UVec2::new(0, 99));
        assert_eq!(viewport.physical_size, UVec2::new(150, 1));
        // Strips at the top and the bottom that meet leave one pixel between them.
        let viewport = view_viewport(
            UVec2::new(300, 200),
            UVec2::new(150, 100),
            inset(0.0, 120.0, 120.0),
        );
        assert_eq!(viewport.physical_position, UVec2::new(0, 60));
        assert_eq!(viewport.physical_size, UVec2::new(150, 1));
    }

    /// The replay's timeline strip takes the bottom of the view: the table draws above it
    /// (issue 28: the export panel covered the lower third of the table).
    #[test]
    fn a_bottom_strip_shortens_the_view_from_below() {
        let window = UVec2::new(1280, 720);
        let viewport = view_viewport(window, window, inset(340.0, 128.0, 170.0));
        assert_eq!(viewport.physical_position, UVec2::new(340, 128));
        assert_eq!(viewport.physical_size, UVec2::new(940, 720 - 128 - 170));
    }
}
