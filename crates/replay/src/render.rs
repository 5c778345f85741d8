//! A software top view of the table, for exports that must not need a GPU.

use billiards_physics::{BallState, Table, Vec2};

/// An RGB image, row-major, 3 bytes per pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Pixels, `3 * width * height` bytes.
    pub rgb: Vec<u8>,
}

/// Colours of the cloth, the rails and the pockets.
pub const CLOTH: [u8; 3] = [22, 110, 60];
/// Rail colour (wood).
pub const RAIL: [u8; 3] = [92, 52, 26];
/// Pocket colour.
pub const POCKET: [u8; 3] = [10, 10, 10];

/// Standard colours: 1 yellow, 2 blue, 3 red, 4 purple, 5 orange, 6 green, 7 maroon, 8 black;
/// 9–15 are the stripes of 1–7.
pub fn ball_colour(number: u8) -> [u8; 3] {
    match number % 8 {
        _ if number == 0 => [245, 245, 235],
        1 => [250, 200, 20],
        2 => [20, 60, 200],
        3 => [210, 30, 30],
        4 => [90, 30, 140],
        5 => [245, 120, 20],
        6 => [20, 130, 60],
        7 => [120, 20, 30],
        _ => [15, 15, 15],
    }
}

/// Maps table coordinates (metres, x along the length) to pixels, the whole table with its
/// rails fitted into the frame.
struct View {
    scale: f64,
    centre: (f64, f64),
}

impl View {
    fn new(table: &Table, width: u32, height: u32) -> Self {
        let rail = 0.1;
        let (w, h) = (table.length + 2.0 * rail, table.width + 2.0 * rail);
        let scale = (f64::from(width) / w).min(f64::from(height) / h);
        Self {
            scale,
            centre: (f64::from(width) / 2.0, f64::from(height) / 2.0),
        }
    }

    fn px(&self, p: Vec2) -> (f64, f64) {
        // +y (left of the table) is up in the picture.
        (
            self.centre.0 + p.x * self.scale,
            self.centre.1 - p.y * self.scale,
        )
    }
}

impl Frame {
    fn new(width: u32, height: u32, fill: [u8; 3]) -> Self {
        let rgb = fill
            .iter()
            .copied()
            .cycle()
            .take(3 * width as usize * height as usize)
            .collect();
        Self { width, height, rgb }
    }

    /// The colour at pixel `(x, y)`.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = 3 * (y as usize * self.width as usize + x as usize);
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    fn put(&mut self, x: i64, y: i64, c: [u8; 3]) {
        if x >= 0 && y >= 0 && (x as u32) < self.width && (y as u32) < self.height {
            let i = 3 * (y as usize * self.width as usize + x as usize);
            self.rgb[i..i + 3].copy_from_slice(&c);
        }
    }

    fn rect(&mut self, (x0, y0): (f64, f64), (x1, y1): (f64, f64), c: [u8; 3]) {
        for y in y0.min(y1).round() as i64..y0.max(y1).round() as i64 {
            for x in x0.min(x1).round() as i64..x0.max(x1).round() as i64 {
                self.put(x, y, c);
            }
        }
    }

    /// A filled disc; `band` paints the middle third of its height (stripes) in `c` and the
    /// rest white.
    fn disc(&mut self, (cx, cy): (f64, f64), r: f64, c: [u8; 3], band: bool) {
        let r = r.max(1.0);
        for y in (cy - r).floor() as i64..=(cy + r).ceil() as i64 {
            for x in (cx - r).floor() as i64..=(cx + r).ceil() as i64 {
                let (dx, dy) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
                if dx * dx + dy * dy <= r * r {
                    let white = band && dy.abs() > r / 3.0;
                    self.put(x, y, if white { [245, 245, 235] } else { c });
                }
            }
        }
    }
}

/// Draws the table and the balls in play, seen from above.
pub fn draw(
    table: &Table,
    radius: f64,
    balls: &[BallState],
    numbers: &[u8],
    width: u32,
    height: u32,
) -> Frame {
    let view = View::new(table, width, height);
    let mut f = Frame::new(width, height, [30, 30, 30]);
    let (hx, hy) = (0.5 * table.length, 0.5 * table.width);
    let rail = 0.08;
    f.rect(
        view.px(Vec2::new(-hx - rail, hy + rail)),
        view.px(Vec2::new(hx + rail, -hy - rail)),
        RAIL,
    );
    f.rect(
        view.px(Vec2::new(-hx, hy)),
        view.px(Vec2::new(hx, -hy)),
        CLOTH,
    );
    for p in billiards_physics::Pocket::ALL {
        let mouth = if p.is_corner() {
            table.corner_mouth
        } else {
            table.side_mouth
        };
        f.disc(
            view.px(table.pocket_position(p)),
            0.5 * mouth * view.scale,
            POCKET,
            false,
        );
    }
    for (s, &n) in balls.iter().zip(numbers) {
        if s.motion.on_table() {
            f.disc(
                view.px(s.position),
                radius * view.scale,
                ball_colour(n),
                n > 8,
            );
        }
    }
    f
}
