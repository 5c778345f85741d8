//! The balls: their components, their look (generated number textures) and how their
//! state is drawn (at their height when in the air).
//!
//! The simulation owns [`BallMotion`]; this plugin only reads it, so the same components
//! work headless (no meshes) and in the game.

use bevy::{
    asset::RenderAssetUsages,
    math::{DVec2, DVec3},
    prelude::*,
    render::render_resource::{Extent3d, TextureDimension, TextureFormat},
};

use crate::table::geometry::{TableKind, TableSpec, table_dir_to_world, to_world};

/// Adds ball visuals and the writeback from [`BallMotion`] to [`Transform`].
pub fn plugin(app: &mut App) {
    app.init_resource::<ShownTime>()
        .add_systems(Startup, create_ball_assets)
        .add_systems(
            Update,
            (
                attach_visuals.in_set(BallSystems::Visuals),
                start_pocket_drops,
                animate_pocket_drops,
                restore_respotted,
            ),
        )
        .add_systems(
            PostUpdate,
            draw_ball_motion.before(TransformSystems::Propagate),
        );
}

/// The balls' systems that other plugins order themselves against.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BallSystems {
    /// New balls get their mesh and material.
    Visuals,
}

/// A pool ball. Spawned by the simulation together with [`BallMotion`].
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
#[require(Transform, Visibility)]
pub struct Ball {
    /// Index of the ball in the solver's ball list.
    pub id: usize,
    /// The number printed on the ball; 0 is the cue ball.
    pub number: u8,
}

impl Ball {
    /// What kind of ball this is, from its number.
    pub fn kind(&self) -> BallKind {
        BallKind::of(self.number)
    }
}

/// How a ball is marked, which decides its look (and, for game rules, its group).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BallKind {
    /// The white cue ball.
    Cue,
    /// Balls 1-7: one colour all over.
    Solid,
    /// The black 8 ball.
    Eight,
    /// Balls 9-15: white with a coloured band.
    Stripe,
}

impl BallKind {
    /// The kind of the ball with this number (numbers above 15 count as stripes).
    pub fn of(number: u8) -> Self {
        match number {
            0 => Self::Cue,
            1..=7 => Self::Solid,
            8 => Self::Eight,
            _ => Self::Stripe,
        }
    }
}

/// How a ball is moving, as the solver classifies it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MotionState {
    /// At rest.
    #[default]
    Stationary,
    /// Sliding over the cloth (kinetic friction).
    Sliding,
    /// Rolling without slipping (rolling resistance).
    Rolling,
    /// In the air, on its parabola (spin model, issue 51).
    Airborne,
    /// Out of play off the table: it flew over a cushion (drawn fallen to the floor).
    OffTable,
}

/// A ball's state in the physics table plane (see [`crate::table::geometry`] for the axes).
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct BallMotion {
    /// Centre of the ball in the table plane, metres.
    pub position: DVec2,
    /// Velocity of the centre, m/s.
    pub velocity: DVec2,
    /// Sliding, rolling or at rest.
    pub state: MotionState,
    /// Angular velocity, rad/s, in the table's axes (z up); zero under the paper's model.
    pub spin: DVec3,
    /// Height of the centre above where it rests on the cloth, metres (0 on the cloth).
    pub height: f64,
}

/// Marks a ball that has dropped into a pocket and left play.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pocketed {
    /// The pocket it dropped into.
    pub pocket: billiards_physics::Pocket,
}

/// The standard colours of balls 1-8 (9-15 repeat 1-7 as stripes), in sRGB.
pub fn ball_colour(number: u8) -> Color {
    match number {
        0 => Color::srgb(0.96, 0.95, 0.90),
        1 | 9 => Color::srgb(0.98, 0.76, 0.05),
        2 | 10 => Color::srgb(0.05, 0.22, 0.70),
        3 | 11 => Color::srgb(0.85, 0.08, 0.06),
        4 | 12 => Color::srgb(0.33, 0.12, 0.52),
        5 | 13 => Color::srgb(0.98, 0.40, 0.06),
        6 | 14 => Color::srgb(0.04, 0.45, 0.20),
        7 | 15 => Color::srgb(0.45, 0.10, 0.08),
        _ => Color::srgb(0.03, 0.03, 0.03),
    }
}

/// The snooker balls' colours (WPBSA 1.2: fifteen reds, six colours, the white), by the
/// solver's numbers ([`billiards_physics::snooker`]): 0 white, 1-15 red, 16 yellow,
/// 17 green, 18 brown, 19 blue, 20 pink, 21 black.
pub fn snooker_colour(number: u8) -> Color {
    match number {
        0 => Color::srgb(0.96, 0.95, 0.90),
        1..=15 => Color::srgb(0.72, 0.03, 0.04),
        16 => Color::srgb(0.98, 0.85, 0.08),
        17 => Color::srgb(0.02, 0.42, 0.16),
        18 => Color::srgb(0.40, 0.20, 0.08),
        19 => Color::srgb(0.05, 0.20, 0.75),
        20 => Color::srgb(0.98, 0.50, 0.62),
        _ => Color::srgb(0.03, 0.03, 0.03),
    }
}

/// The carom balls' colours (UMB Art. 12: two white balls, one of them marked, and a red; the
/// yellow ball is the usual second cue ball now), by the numbers of
/// `billiards_rules::three_cushion`: 0 white (player A's), 1 yellow (player B's), 2 red.
pub fn carom_colour(number: u8) -> Color {
    match number {
        0 => Color::srgb(0.96, 0.95, 0.90),
        1 => Color::srgb(0.98, 0.82, 0.10),
        _ => Color::srgb(0.80, 0.05, 0.05),
    }
}

/// Largest carom ball number (the red).
const CAROM_MAX: u8 = 2;

/// The meshes (pool, snooker and carom sizes) and one material per number of each set.
#[derive(Resource, Debug)]
struct BallAssets {
    mesh: Handle<Mesh>,
    materials: Vec<Handle<StandardMaterial>>,
    snooker_mesh: Handle<Mesh>,
    snooker_materials: Vec<Handle<StandardMaterial>>,
    carom_mesh: Handle<Mesh>,
    carom_materials: Vec<Handle<StandardMaterial>>,
}

/// Largest snooker ball number (the black).
const SNOOKER_MAX: u8 = 21;

/// Largest ball number with its own texture.
const MAX_NUMBER: u8 = 15;

fn create_ball_assets(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut images: ResMut<Assets<Image>>,
) {
    let pool = TableSpec::default();
    let mesh = meshes.add(Sphere::new(pool.ball_radius as f32).mesh().uv(48, 24));
    let mut sphere = |radius: f64| meshes.add(Sphere::new(radius as f32).mesh().uv(48, 24));
    let snooker_mesh = sphere(billiards_physics::BallSpec::snooker().radius);
    let carom_mesh = sphere(billiards_physics::BallSpec::carom().radius);
    // Snooker and carom balls carry no numbers: one plain colour each.
    let mut plain = |colour: fn(u8) -> Color, max: u8| -> Vec<Handle<StandardMaterial>> {
        (0..=max)
            .map(|number| {
                materials.add(StandardMaterial {
                    base_color: colour(number),
                    perceptual_roughness: 0.12,
                    reflectance: 0.5,
                    ..default()
                })
            })
            .collect()
    };
    let snooker_materials = plain(snooker_colour, SNOOKER_MAX);
    let carom_materials = plain(carom_colour, CAROM_MAX);
    let materials = (0..=MAX_NUMBER)
        .map(|number| {
            let texture = images.add(ball_texture(number));
            materials.add(StandardMaterial {
                base_color_texture: Some(texture),
                // Phenolic resin: smooth and glossy, not metallic.
                perceptual_roughness: 0.12,
                reflectance: 0.5,
                ..default()
            })
        })
        .collect();
    commands.insert_resource(BallAssets {
        mesh,
        materials,
        snooker_mesh,
        snooker_materials,
        carom_mesh,
        carom_materials,
    });
}

/// Gives newly spawned balls their mesh and material, and turns them so that their number
/// faces up (the texture's number sits on the mesh's local +Y; its top on local +Z).
fn attach_visuals(
    mut commands: Commands,
    assets: Option<Res<BallAssets>>,
    spec: Res<TableSpec>,
    balls: Query<(Entity, &Ball, &mut Transform), Added<Ball>>,
) {
    let Some(assets) = assets else { return };
    for (entity, ball, mut transform) in balls {
        let (mesh, materials, max) = match spec.kind {
            TableKind::Pool => (&assets.mesh, &assets.materials, MAX_NUMBER),
            TableKind::Snooker => (&assets.snooker_mesh, &assets.snooker_materials, SNOOKER_MAX),
            TableKind::Carom => (&assets.carom_mesh, &assets.carom_materials, CAROM_MAX),
        };
        let material = &materials[usize::from(ball.number.min(max))];
        // Local +Y (number) up, local +Z (top of the digits) toward the foot rail, so the
        // numbers read upright from the head end where the player stands.
        transform.rotation = Quat::from_mat3(&Mat3::from_cols(Vec3::NEG_Z, Vec3::Y, Vec3::X));
        commands
            .entity(entity)
            .insert((Mesh3d(mesh.clone()), MeshMaterial3d(material.clone())));
    }
}

/// Balls that left play this frame.
type NewlyPocketed = (With<Ball>, Added<Pocketed>);

/// Balls in play whose table state changed.
type MovedOnTable = (With<Ball>, Without<Pocketed>, Changed<BallMotion>);

/// A pocketed ball on its way down: it rolls over the hole's centre and sinks out of sight.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
struct PocketDrop {
    /// Where the ball was when it left play.
    from: Vec3,
    /// The centre of the hole at cloth level.
    over: Vec3,
    /// Seconds since the drop started.
    elapsed: f32,
}

/// How long a pocketed ball takes to disappear.
const DROP_SECONDS: f32 = 0.35;

fn start_pocket_drops(
    mut commands: Commands,
    spec: Res<TableSpec>,
    balls: Query<(Entity, &Pocketed, &Transform), NewlyPocketed>,
) {
    for (entity, pocketed, transform) in &balls {
        // A table without pockets drops nothing: the ball sinks where it is.
        let over = spec
            .pocket(pocketed.pocket)
            .map_or(transform.translation, |hole| {
                spec.ball_world_position(hole.centre)
            });
        commands.entity(entity).insert(PocketDrop {
            from: transform.translation,
            over,
            elapsed: 0.0,
        });
    }
}

/// Moves dropping balls over the hole (first half) and down into it (second half), then hides
/// them. Uses virtual time, so the drop pauses with the game.
fn animate_pocket_drops(
    mut commands: Commands,
    time: Res<Time>,
    spec: Res<TableSpec>,
    mut balls: Query<(Entity, &mut PocketDrop, &mut Transform, &mut Visibility)>,
    mut redraw: MessageWriter<bevy::window::RequestRedraw>,
) {
    for (entity, mut drop, mut transform, mut visibility) in &mut balls {
        drop.elapsed += time.delta_secs();
        let t = (drop.elapsed / DROP_SECONDS).min(1.0);
        let depth = 3.0 * spec.ball_radius as f32;
        transform.translation = if t < 0.5 {
            drop.from.lerp(drop.over, t * 2.0)
        } else {
            drop.over - Vec3::Y * depth * (t * 2.0 - 1.0).powi(2)
        };
        if t >= 1.0 {
            *visibility = Visibility::Hidden;
            commands.entity(entity).remove::<PocketDrop>();
        } else {
            redraw.write(bevy::window::RequestRedraw);
        }
    }
}

/// A ball taken out of a pocket (a respotted cue ball) is shown again.
fn restore_respotted(
    mut commands: Commands,
    mut respotted: RemovedComponents<Pocketed>,
    mut balls: Query<&mut Visibility, With<Ball>>,
) {
    for entity in respotted.read() {
        if let Ok(mut visibility) = balls.get_mut(entity) {
            *visibility = Visibility::Inherited;
            commands.entity(entity).remove::<PocketDrop>();
        }
    }
}

/// The simulated time the balls on the table show: the solver's in play, the replay clock's
/// in a replay. Balls turn by their spin over its steps, so a replay at 0.1x turns them at
/// 0.1x and a paused clock does not turn them.
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq)]
pub struct ShownTime(pub f64);

/// Longest step of [`ShownTime`] a ball is turned over: a jump (a rack, a scrub, opening a
/// replay) is not a motion.
const MAX_TURN_STEP: f64 = 0.25;

/// Writes moved balls to their transforms. Under the spin model a ball turns by its own
/// angular velocity over the step of [`ShownTime`] (so draw, follow and english show); under the paper's
/// model, which carries no spin, a moving ball is turned as if it rolled without slipping
/// along its displacement. A ball placed at rest (racked, respotted) is moved without turning.
fn draw_ball_motion(
    spec: Res<TableSpec>,
    shown: Res<ShownTime>,
    mut last_shown: Local<f64>,
    mut balls: Query<(&BallMotion, &mut Transform), MovedOnTable>,
) {
    let dt = (shown.0 - *last_shown).clamp(-MAX_TURN_STEP, MAX_TURN_STEP);
    *last_shown = shown.0;
    for (motion, mut transform) in &mut balls {
        // A ball in the air is drawn at its height ([`super::flight`] draws its shadow).
        let target = spec.ball_world_position(motion.position) + Vec3::Y * motion.height as f32;
        let step = target - transform.translation;
        let distance = step.length();
        if motion.spin != DVec3::ZERO {
            // The table-to-world map is a rotation, so it carries rotation vectors too.
            let turn = to_world(motion.spin * dt);
            let angle = turn.length();
            if angle > 0.0 {
                transform.rotation =
                    Quat::from_axis_angle(turn / angle, angle) * transform.rotation;
            }
        } else if distance > 0.0 && motion.state != MotionState::Stationary {
            let axis = Vec3::Y.cross(step / distance);
            let angle = distance / spec.ball_radius as f32;
            transform.rotation = Quat::from_axis_angle(axis, angle) * transform.rotation;
        }
        transform.translation = target;
    }
}

/// The world direction a ball moves in, for drawing velocity vectors.
pub fn world_velocity(motion: &BallMotion) -> Vec3 {
    table_dir_to_world(motion.velocity)
}

/// Texture size: an equirectangular map, twice as wide as high so that a degree is the same
/// number of pixels in both directions (the number circles stay round on the equator).
const TEXTURE_WIDTH: usize = 512;
const TEXTURE_HEIGHT: usize = TEXTURE_WIDTH / 2;

/// How one ball is painted: what [`ball_texture`] samples at every texel.
#[derive(Debug, Clone, PartialEq)]
struct BallPaint {
    kind: BallKind,
    /// The number as text ("" for the cue ball).
    label: String,
    /// The ball's colour, sRGB.
    colour: [f32; 3],
    /// The white of stripes and number circles, sRGB.
    white: [f32; 3],
    /// Angular radius of the number circles, radians.
    circle_radius: f32,
    /// Half the angular width of a stripe's band, radians.
    stripe_half_width: f32,
}

impl BallPaint {
    fn new(number: u8) -> Self {
        let colour = ball_colour(number).to_srgba();
        Self {
            kind: BallKind::of(number),
            label: number.to_string(),
            colour: [colour.red, colour.green, colour.blue],
            white: [0.97, 0.96, 0.92],
            // The number circle is about 1 inch across on a 2.25 inch ball.
            circle_radius: 25f32.to_radians(),
            stripe_half_width: 36f32.to_radians(),
        }
    }

    /// The colour at texture coordinates (u, v) of Bevy's UV sphere: u runs around the
    /// equator, v from the top pole (0) to the bottom pole (1).
    fn colour_at(&self, u: f32, v: f32) -> [f32; 3] {
        use std::f32::consts::{PI, TAU};
        let latitude = (0.5 - v) * PI;
        let base = match self.kind {
            BallKind::Cue => return self.colour,
            BallKind::Solid | BallKind::Eight => self.colour,
            BallKind::Stripe if latitude.abs() < self.stripe_half_width => self.colour,
            BallKind::Stripe => self.white,
        };
        // Number circles centred on the equator at u = 1/4 and u = 3/4.
        for centre_u in [0.25f32, 0.75] {
            let dx = (u - centre_u) * TAU; // radians of longitude (= arc length on the equator)
            let dy = -latitude; // radians, growing downward like v
            if (dx * dx + dy * dy).sqrt() < self.circle_radius {
                // Digits fill 65 % of the circle's height.
                let glyph_height = 1.3 * self.circle_radius;
                let covered = text_covers(&self.label, dx / glyph_height, dy / glyph_height + 0.5);
                return if covered { [0.05; 3] } else { self.white };
            }
        }
        base
    }
}

/// Paints ball `number`'s texture: its colour (all over for solids, a band for stripes) and
/// two white circles with the number, on opposite sides of the equator.
pub fn ball_texture(number: u8) -> Image {
    let paint = BallPaint::new(number);
    let mut data = Vec::with_capacity(TEXTURE_WIDTH * TEXTURE_HEIGHT * 4);
    for row in 0..TEXTURE_HEIGHT {
        for column in 0..TEXTURE_WIDTH {
            // Supersample 3x3 so circle edges and digits are smooth.
            let mut sum = [0.0f32; 3];
            for sy in 0..3 {
                for sx in 0..3 {
                    let u = (column as f32 + (sx as f32 + 0.5) / 3.0) / TEXTURE_WIDTH as f32;
                    let v = (row as f32 + (sy as f32 + 0.5) / 3.0) / TEXTURE_HEIGHT as f32;
                    for (s, c) in sum.iter_mut().zip(paint.colour_at(u, v)) {
                        *s += c / 9.0;
                    }
                }
            }
            data.extend(sum.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8));
            data.push(255);
        }
    }
    Image::new(
        Extent3d {
            width: TEXTURE_WIDTH as u32,
            height: TEXTURE_HEIGHT as u32,
            depth_or_array_layers: 1,
        },
        TextureDimension::D2,
        data,
        TextureFormat::Rgba8UnormSrgb,
        RenderAssetUsages::RENDER_WORLD,
    )
}

/// 5x7 bitmap digits, one row per byte, most significant of the low five bits on the left.
const DIGITS: [[u8; 7]; 10] = [
    [0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E],
    [0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E],
    [0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F],
    [0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E],
    [0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02],
    [0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E],
    [0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E],
    [0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08],
    [0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E],
    [0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C],
];

/// Whether the text, centred horizontally at x = 0 with its top at y = 0 and its bottom at
/// y = 1 (units of the glyph height), covers the point (x, y).
fn text_covers(text: &str, x: f32, y: f32) -> bool {
    // A glyph cell is 5 columns plus 1 of spacing, in a 7-row height.
    let cell = 1.0 / 7.0;
    let advance = 6.0 * cell;
    let width = text.len() as f32 * advance - cell;
    let gx = x + width / 2.0;
    if !(0.0..1.0).contains(&y) || gx < 0.0 {
        return false;
    }
    let index = (gx / advance) as usize;
    let Some(digit) = text.as_bytes().get(index).and_then(|b| b.checked_sub(b'0')) else {
        return false;
    };
    let Some(glyph) = DIGITS.get(usize::from(digit)) else {
        return false;
    };
    let column = ((gx - index as f32 * advance) / cell) as usize;
    let row = (y / cell) as usize;
    column < 5 && row < 7 && glyph[row] & (0x10 >> column) != 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_follow_numbers() {
        assert_eq!(BallKind::of(0), BallKind::Cue);
        assert_eq!(BallKind::of(7), BallKind::Solid);
        assert_eq!(BallKind::of(8), BallKind::Eight);
        assert_eq!(BallKind::of(9), BallKind::Stripe);
        assert_eq!(BallKind::of(15), BallKind::Stripe);
    }

    #[test]
    fn glyphs_cover_their_strokes() {
        // The middle of a "1" is its vertical stroke; left of it is empty.
        assert!(text_covers("1", 0.0, 0.5));
        assert!(!text_covers("1", -0.25, 0.5));
        // Outside the text box nothing is covered.
        assert!(!text_covers("8", 0.0, 1.2));
        assert!(!text_covers("12", 2.0, 0.5));
    }

    #[test]
    fn textures_show_colour_and_number() {
        let pixel = |image: &Image, u: f32, v: f32| {
            let x = ((u * TEXTURE_WIDTH as f32) as usize).min(TEXTURE_WIDTH - 1);
            let y = ((v * TEXTURE_HEIGHT as f32) as usize).min(TEXTURE_HEIGHT - 1);
            let data = image.data.as_ref().unwrap();
            let i = (y * TEXTURE_WIDTH + x) * 4;
            [data[i], data[i + 1], data[i + 2]]
        };
        let three = ball_texture(3);
        // Away from the circles a solid is its colour (red), the circle rim is white.
        let red = pixel(&three, 0.0, 0.5);
        assert!(red[0] > 150 && red[1] < 60 && red[2] < 60, "{red:?}");
        let rim = pixel(&three, 0.25 + 0.055, 0.5);
        assert!(rim.iter().all(|&c| c > 200), "{rim:?}");
        // A stripe is white at the poles and coloured at the equator.
        let eleven = ball_texture(11);
        assert!(pixel(&eleven, 0.0, 0.05).iter().all(|&c| c > 200));
        assert!(pixel(&eleven, 0.0, 0.5)[0] > 150);
    }

    #[test]
    fn carom_balls_are_white_yellow_and_red_by_number() {
        // billiards_rules::three_cushion::Ball::index: white 0, yellow 1, red 2.
        let rgb = |n: u8| carom_colour(n).to_srgba();
        let (white, yellow, red) = (rgb(0), rgb(1), rgb(2));
        assert!(white.red > 0.9 && white.green > 0.9 && white.blue > 0.8);
        assert!(yellow.red > 0.9 && yellow.green > 0.7 && yellow.blue < 0.2);
        assert!(red.red > 0.7 && red.green < 0.1 && red.blue < 0.1);
        use billiards_rules::three_cushion::Ball as Carom;
        assert_eq!(usize::from(CAROM_MAX) + 1, Carom::ALL.len());
    }
}
