//! A uniform grid of cells over the table, so a ball is tested only against balls in the nine
//! cells around it (cell lists, as in event-driven molecular dynamics).
//!
//! Two balls can touch only if their centres are within 2R, and cells are wider than that, so
//! touching balls are always in the same or adjacent cells. A ball leaving its cell is an
//! internal event (no physical effect, not recorded): it is then tested against its new
//! neighbours. Small scenes use a single cell and never pay for crossings.

use crate::ball::BallId;
use crate::math::Vec2;

/// Scenes with fewer balls than this use one cell (the pair table): below it, crossings cost
/// more than they save. Measured on the frictionless gas (`examples/profile_break gas`): the
/// pair table is faster at 200 balls (1.6 against 1.8 us an event), the grid at 300 (1.9
/// against 2.3 us).
const MIN_BALLS_FOR_GRID: usize = 250;

/// Balls per cell on average. Smaller cells mean fewer pairs to test a prediction and more
/// crossings; a crossing tests only the three cells it brings in, so the best is near one
/// ball a cell (measured on the frictionless gas of 100 to 10,000 balls: `examples/scaling`).
const BALLS_PER_CELL: f64 = 1.0;

/// Which side of its cell a ball leaves through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Towards +x.
    XPlus,
    /// Towards -x.
    XMinus,
    /// Towards +y.
    YPlus,
    /// Towards -y.
    YMinus,
}

impl Side {
    /// All four, in tie order.
    pub const ALL: [Side; 4] = [Side::XPlus, Side::XMinus, Side::YPlus, Side::YMinus];
}

/// Cell index of a ball along x and y.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cell {
    /// Column.
    pub x: usize,
    /// Row.
    pub y: usize,
}

/// The grid and which balls are in each cell.
#[derive(Clone, Debug)]
pub struct Grid {
    min: Vec2,
    size: Vec2,
    nx: usize,
    ny: usize,
    cells: Vec<Vec<BallId>>,
    of: Vec<Option<Cell>>,
}

impl Grid {
    /// A grid over the rectangle of half extents `half` for `count` balls of radius `radius`:
    /// about one ball per cell on average (`BALLS_PER_CELL`), cells never narrower than `4R`.
    pub fn new(half: Vec2, radius: f64, count: usize) -> Self {
        Self::with_cells(half, radius, count, count >= MIN_BALLS_FOR_GRID)
    }

    /// [`Grid::new`] split into cells however few the balls (to test the cell lists on scenes
    /// small enough for the pair table).
    pub(crate) fn split(half: Vec2, radius: f64, count: usize) -> Self {
        Self::with_cells(half, radius, count, true)
    }

    fn with_cells(half: Vec2, radius: f64, count: usize, split: bool) -> Self {
        let (w, h) = (2.0 * half.x, 2.0 * half.y);
        let (nx, ny) = if !split {
            (1, 1)
        } else {
            let side = (w * h * BALLS_PER_CELL / count as f64)
                .sqrt()
                .max(4.0 * radius);
            (((w / side) as usize).max(1), ((h / side) as usize).max(1))
        };
        Self {
            min: -half,
            size: Vec2::new(w / nx as f64, h / ny as f64),
            nx,
            ny,
            cells: vec![Vec::new(); nx * ny],
            of: vec![None; count],
        }
    }

    /// Is there more than one cell (so crossings matter)?
    pub fn is_split(&self) -> bool {
        self.nx * self.ny > 1
    }

    fn locate(&self, p: Vec2) -> Cell {
        let f = |v: f64, min: f64, size: f64, n: usize| {
            (((v - min) / size).floor().max(0.0) as usize).min(n - 1)
        };
        Cell {
            x: f(p.x, self.min.x, self.size.x, self.nx),
            y: f(p.y, self.min.y, self.size.y, self.ny),
        }
    }

    /// Puts ball `id` in the cell containing `p` (or takes it out of the grid with `None`).
    pub fn set(&mut self, id: BallId, p: Option<Vec2>) {
        let cell = p.map(|p| self.locate(p));
        self.move_to(id, cell);
    }

    fn move_to(&mut self, id: BallId, cell: Option<Cell>) {
        if self.of[id] == cell {
            return;
        }
        if let Some(old) = self.of[id] {
            let v = &mut self.cells[old.y * self.nx + old.x];
            if let Some(k) = v.iter().position(|&b| b == id) {
                v.swap_remove(k);
            }
        }
        if let Some(new) = cell {
            self.cells[new.y * self.nx + new.x].push(id);
        }
        self.of[id] = cell;
    }

    /// Moves ball `id` one cell through `side` (set explicitly, not re-derived from a
    /// position that may sit a rounding error short of the boundary); whether it moved (not
    /// at the grid's edge).
    pub fn cross(&mut self, id: BallId, side: Side) -> bool {
        let Some(c) = self.of[id] else { return false };
        let next = match side {
            Side::XPlus => Cell {
                x: (c.x + 1).min(self.nx - 1),
                ..c
            },
            Side::XMinus => Cell {
                x: c.x.saturating_sub(1),
                ..c
            },
            Side::YPlus => Cell {
                y: (c.y + 1).min(self.ny - 1),
                ..c
            },
            Side::YMinus => Cell {
                y: c.y.saturating_sub(1),
                ..c
            },
        };
        self.move_to(id, Some(next));
        next != c
    }

    /// The balls in the cells that came into ball `id`'s neighbourhood when it crossed into
    /// its cell through `side`: the row or column of three beyond it (fewer at the edge).
    pub fn entered(&self, id: BallId, side: Side) -> impl Iterator<Item = BallId> + '_ {
        let c = self.of[id];
        // (columns, rows) of the new cells; empty ranges when there are none.
        #[allow(clippy::reversed_empty_ranges)]
        let (xs, ys) = match c {
            Some(c) => {
                let cols = c.x.saturating_sub(1)..=(c.x + 1).min(self.nx - 1);
                let rows = c.y.saturating_sub(1)..=(c.y + 1).min(self.ny - 1);
                match side {
                    Side::XPlus if c.x + 1 < self.nx => (c.x + 1..=c.x + 1, rows),
                    Side::XMinus if c.x > 0 => (c.x - 1..=c.x - 1, rows),
                    Side::YPlus if c.y + 1 < self.ny => (cols, c.y + 1..=c.y + 1),
                    Side::YMinus if c.y > 0 => (cols, c.y - 1..=c.y - 1),
                    _ => (1..=0, 1..=0),
                }
            }
            None => (1..=0, 1..=0),
        };
        ys.flat_map(move |y| xs.clone().map(move |x| y * self.nx + x))
            .flat_map(move |k| self.cells[k].iter().copied())
    }

    /// The boundaries of ball `id`'s cell that are interior to the table, as
    /// `(side, coordinate)`: a ball can cross only these.
    pub fn exits(&self, id: BallId) -> impl Iterator<Item = (Side, f64)> + '_ {
        let c = self.of[id];
        Side::ALL.into_iter().filter_map(move |side| {
            let c = c?;
            match side {
                Side::XPlus if c.x + 1 < self.nx => {
                    Some((side, self.min.x + (c.x + 1) as f64 * self.size.x))
                }
                Side::XMinus if c.x > 0 => Some((side, self.min.x + c.x as f64 * self.size.x)),
                Side::YPlus if c.y + 1 < self.ny => {
                    Some((side, self.min.y + (c.y + 1) as f64 * self.size.y))
                }
                Side::YMinus if c.y > 0 => Some((side, self.min.y + c.y as f64 * self.size.y)),
                _ => None,
            }
        })
    }

    /// Balls in the cells around ball `id`'s cell (including its own, and itself).
    pub fn neighbours(&self, id: BallId) -> impl Iterator<Item = BallId> + '_ {
        let c = self.of[id];
        let (xs, ys) = match c {
            Some(c) => (
                c.x.saturating_sub(1)..=(c.x + 1).min(self.nx - 1),
                c.y.saturating_sub(1)..=(c.y + 1).min(self.ny - 1),
            ),
            #[allow(clippy::reversed_empty_ranges)]
            None => (1..=0, 1..=0),
        };
        ys.flat_map(move |y| xs.clone().map(move |x| y * self.nx + x))
            .flat_map(move |k| self.cells[k].iter().copied())
    }
}
