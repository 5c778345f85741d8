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

/// Balls a cell holds in its own [`Slots`]; more spill over into a list of the cell's own
/// (rare: at about one ball a cell on average, eight or more in one cell has a Poisson
/// chance of about 1e-5).
const INLINE: usize = 7;

/// A cell's balls in 32 bytes, two cells a cache line, so the cells a crossing searches are
/// read where they are listed (issue 53: a `Vec` a cell sent each search to one heap block
/// a cell). Logically one list, `ids[..min(len, INLINE)]` and then the cell's spill list,
/// which `push` and `swap_remove` keep in the order a `Vec` would, so every search visits
/// the same balls in the same order as with a `Vec` a cell.
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(32))]
struct Slots {
    len: u32,
    ids: [u32; INLINE],
}

/// The grid and which balls are in each cell.
#[derive(Clone, Debug)]
pub struct Grid {
    min: Vec2,
    size: Vec2,
    nx: usize,
    ny: usize,
    cells: Vec<Slots>,
    /// Each cell's balls beyond its first [`INLINE`] (empty nearly always).
    spill: Vec<Vec<BallId>>,
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
            cells: vec![Slots::default(); nx * ny],
            spill: vec![Vec::new(); nx * ny],
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

    /// Moves ball `id` from cell `from` (`None`: in no cell) to the cell containing `p` (or
    /// out of the grid with `None`); its cell now. The caller keeps each ball's cell (the
    /// cell lists, in the ball's record: issue 53, a line fewer a crossing than an index
    /// here).
    pub fn set(&mut self, id: BallId, from: Option<Cell>, p: Option<Vec2>) -> Option<Cell> {
        let cell = p.map(|p| self.locate(p));
        self.move_to(id, from, cell);
        cell
    }

    fn move_to(&mut self, id: BallId, old: Option<Cell>, cell: Option<Cell>) {
        if old == cell {
            return;
        }
        if let Some(old) = old {
            self.remove(old.y * self.nx + old.x, id);
        }
        if let Some(new) = cell {
            self.push(new.y * self.nx + new.x, id);
        }
    }

    /// Appends ball `id` to cell `k`'s list, as `Vec::push`.
    fn push(&mut self, k: usize, id: BallId) {
        let cell = &mut self.cells[k];
        let n = cell.len as usize;
        if n < INLINE {
            cell.ids[n] = id as u32;
        } else {
            self.spill[k].push(id);
        }
        cell.len += 1;
    }

    /// Takes ball `id` out of cell `k`'s list, as `Vec::swap_remove` at its position (the
    /// last ball takes its place), if it is there.
    fn remove(&mut self, k: usize, id: BallId) {
        let n = self.cells[k].len as usize;
        let at = |g: &Self, i: usize| {
            if i < INLINE {
                g.cells[k].ids[i] as usize
            } else {
                g.spill[k][i - INLINE]
            }
        };
        let Some(pos) = (0..n).find(|&i| at(self, i) == id) else {
            return;
        };
        let last = at(self, n - 1);
        if n > INLINE {
            self.spill[k].pop();
        }
        if pos < INLINE {
            self.cells[k].ids[pos] = last as u32;
        } else if pos < n - 1 {
            self.spill[k][pos - INLINE] = last;
        }
        self.cells[k].len -= 1;
    }

    /// The balls of cell `k`, in list order.
    #[inline]
    fn balls(&self, k: usize) -> impl Iterator<Item = BallId> + '_ {
        let cell = &self.cells[k];
        let n = cell.len as usize;
        let spill: &[BallId] = if n > INLINE { &self.spill[k] } else { &[] };
        cell.ids[..n.min(INLINE)]
            .iter()
            .map(|&b| b as usize)
            .chain(spill.iter().copied())
    }

    /// Moves ball `id` from cell `c` one cell through `side` (set explicitly, not re-derived
    /// from a position that may sit a rounding error short of the boundary); its cell now (`c`
    /// itself at the grid's edge).
    pub fn cross(&mut self, id: BallId, c: Cell, side: Side) -> Cell {
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
        self.move_to(id, Some(c), Some(next));
        next
    }

    /// The balls in the cells that came into a ball's neighbourhood when it crossed into cell
    /// `c` through `side`: the row or column of three beyond it (fewer at the edge; none
    /// for `None`).
    pub fn entered(&self, c: Option<Cell>, side: Side) -> impl Iterator<Item = BallId> + '_ {
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
            .flat_map(move |k| self.balls(k))
    }

    /// The boundaries of cell `c` that are interior to the table, as `(side, coordinate)`: a
    /// ball can cross only these (none for `None`).
    pub fn exits(&self, c: Option<Cell>) -> impl Iterator<Item = (Side, f64)> + '_ {
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

    /// Balls in the cells around cell `c` (including `c`; none for `None`).
    pub fn neighbours(&self, c: Option<Cell>) -> impl Iterator<Item = BallId> + '_ {
        let (xs, ys) = match c {
            Some(c) => (
                c.x.saturating_sub(1)..=(c.x + 1).min(self.nx - 1),
                c.y.saturating_sub(1)..=(c.y + 1).min(self.ny - 1),
            ),
            #[allow(clippy::reversed_empty_ranges)]
            None => (1..=0, 1..=0),
        };
        ys.flat_map(move |y| xs.clone().map(move |x| y * self.nx + x))
            .flat_map(move |k| self.balls(k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cell's balls come out in the order a `Vec` kept under `push` and `swap_remove`
    /// (the order the cell lists' searches depend on, bit for bit), also past the
    /// [`INLINE`] balls a cell holds in place: eleven balls into one cell of a 6 x 6 grid,
    /// taken out at the front, the middle, the spill and the end, against a `Vec` model.
    #[test]
    fn cell_order_is_a_vecs_past_the_inline_slots() {
        let mut grid = Grid::with_cells(Vec2::new(1.5, 1.5), 0.01, 40, true);
        assert_eq!((grid.nx, grid.ny), (6, 6), "cells of sqrt(9 / 40) m, 0.5 m");
        let centre = Vec2::new(0.25, 0.25);
        let k = 3 * 6 + 3;
        let mut model: Vec<BallId> = Vec::new();
        let order = [4, 0, 9, 3, 12, 7, 1, 18, 5, 11, 2];
        let mut cell = None;
        for &id in &order {
            cell = grid.set(id, None, Some(centre));
            model.push(id);
        }
        let cell = cell.expect("the centre is on the grid");
        assert_eq!((cell.x, cell.y), (3, 3));
        assert!(model.len() > INLINE, "the spill list is used");
        let seen = |g: &Grid| g.balls(k).collect::<Vec<_>>();
        assert_eq!(seen(&grid), model);
        // Front (an inline slot takes a spilled ball), spill middle, last, middle.
        for id in [4, 5, 2, 7, 11, 0] {
            assert_eq!(grid.set(id, Some(cell), None), None, "ball {id} in no cell");
            let pos = model.iter().position(|&b| b == id).expect("in the model");
            model.swap_remove(pos);
            assert_eq!(seen(&grid), model, "after taking out ball {id}");
        }
        // Back past the inline slots, then one ball crossing out and back.
        for id in [30, 31, 32] {
            assert_eq!(grid.set(id, None, Some(centre)), Some(cell));
            model.push(id);
        }
        assert_eq!(seen(&grid), model);
        let next = grid.cross(9, cell, Side::XPlus);
        assert_eq!((next.x, next.y), (4, 3), "not at the grid's edge");
        let pos = model.iter().position(|&b| b == 9).expect("in the model");
        model.swap_remove(pos);
        assert_eq!(seen(&grid), model);
        assert_eq!(
            grid.balls(k + 1).collect::<Vec<_>>(),
            vec![9],
            "the cell to +x"
        );
        assert_eq!(grid.cross(9, next, Side::XMinus), cell);
        model.push(9);
        assert_eq!(seen(&grid), model);
        // The nine cells around the centre hold exactly the model's balls.
        assert_eq!(grid.neighbours(Some(cell)).collect::<Vec<_>>(), model);
        // A ball come back to the centre through -x: the column at x = 2 is new, and empty.
        assert_eq!(grid.entered(Some(cell), Side::XMinus).count(), 0);
        assert_eq!(grid.entered(Some(next), Side::XPlus).count(), 0);
        assert_eq!(
            grid.entered(Some(next), Side::XMinus).collect::<Vec<_>>(),
            model,
            "the column at x = 3 is new to a ball come to x = 4 through -x"
        );
    }
}
