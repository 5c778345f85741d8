//! The Place tool (free play): a ball picked with the pointer is dragged (or, once picked,
//! put where the next click falls), snapped within [`SNAP`] to the spots and the 15-ball
//! rack's places (Shift held: placed freely), and refused on another ball, off the cloth or
//! over a pocket's hole. Balls are added, removed and cleared; every edit goes on an undo
//! list.
//!
//! A move is a placement the recorder logs (the recording replays it bit for bit); adding or
//! removing a ball changes the set of balls, so it sets a new layout up (the game before it
//! is saved first, as before any rack).

use bevy::{math::DVec2, prelude::*};
use billiards_physics::{BallSetup, Simulation};

use super::state::Practice;
use crate::{
    play::{cue::PointerInput, game::Rules},
    sim::{SimStatus, Solver, layout_now, to_dvec2},
    table::geometry::{TableSpec, to_world},
};

/// A ball dropped this close to a spot (m) goes on the spot.
pub const SNAP: f64 = 0.015;

/// The highest ball number the Place tool adds (pool's balls: the cue ball and 1 to 15).
pub const MAX_NUMBER: u8 = 15;

/// An edit of the layout.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub enum EditRequested {
    /// Ball `number` to `to` (table metres), snapped to a spot or rack place within
    /// [`SNAP`] unless `free`.
    Move {
        /// The ball.
        number: u8,
        /// Where, on the table plane.
        to: DVec2,
        /// Placed exactly at `to` (Shift held while dropping).
        free: bool,
    },
    /// Ball `number` onto the table, at `at` or, without it, on the first free spot.
    Add {
        /// The ball.
        number: u8,
        /// Where.
        at: Option<DVec2>,
    },
    /// Ball `number` off the table.
    Remove {
        /// The ball.
        number: u8,
    },
    /// Every object ball off the table; the cue ball stays (on the head spot if it was
    /// down), so the table is one a shot can be played on.
    Clear,
    /// The last edit taken back.
    Undo,
}

/// One edit done, as the undo list keeps it.
#[derive(Debug, Clone, PartialEq)]
pub enum Edit {
    /// A ball moved from `from`.
    Moved {
        /// The ball.
        number: u8,
        /// Where it was.
        from: DVec2,
    },
    /// A ball added.
    Added {
        /// The ball.
        number: u8,
    },
    /// A ball removed from `at`.
    Removed {
        /// The ball.
        number: u8,
        /// Where it was.
        at: DVec2,
    },
    /// The table cleared; the balls as they lay before.
    Cleared {
        /// The layout before.
        before: Vec<BallSetup>,
    },
}

/// The Place tool's state: the ball picked, a drag in progress and its target, the edits.
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct Placing {
    /// The ball picked (by number).
    pub selected: Option<u8>,
    /// A drag started on the picked ball and the button is still down.
    pub dragging: bool,
    /// Where the dragged ball would go now and whether it may.
    pub target: Option<(DVec2, Result<(), String>)>,
    /// The edits, oldest first.
    pub undo: Vec<Edit>,
}

/// The spots a placed ball snaps to: the head spot, the centre spot and the foot spot.
pub fn spots(spec: &TableSpec) -> [DVec2; 3] {
    [spec.head_spot(), DVec2::ZERO, spec.foot_spot()]
}

/// The places of a 15-ball rack on this table (apex on the foot spot, balls touching), the
/// other places a ball snaps to: a rack rebuilt by hand lines up as the referee racks it.
pub fn rack_places(spec: &TableSpec) -> Vec<DVec2> {
    billiards_physics::racks::tight_rack(&spec.physics_table(), &spec.ball())
        .into_iter()
        .filter(|b| b.number != 0)
        .map(|b| to_dvec2(b.position))
        .collect()
}

/// `p`, or the spot or rack place within [`SNAP`] of it (the nearest).
pub fn snap(spec: &TableSpec, p: DVec2) -> DVec2 {
    spots(spec)
        .into_iter()
        .chain(rack_places(spec))
        .filter(|s| s.distance(p) <= SNAP)
        .min_by(|a, b| a.distance(p).total_cmp(&b.distance(p)))
        .unwrap_or(p)
}

/// Why ball `number` cannot be set down at `p` (the ball itself, if on the table, does not
/// count as in the way): off the cloth, its centre over a pocket's hole, or on another ball.
pub fn spot_error(sim: &Simulation, spec: &TableSpec, number: u8, p: DVec2) -> Result<(), String> {
    let r = sim.params().ball.radius;
    let q = billiards_physics::Vec2::new(p.x, p.y);
    if !p.is_finite()
        || billiards_physics::check::outside_by(sim.table(), r, q)
            > billiards_physics::sim::PLACEMENT_TOLERANCE
    {
        return Err("off the cloth".to_owned());
    }
    if let Some(pocket) = billiards_physics::Pocket::ALL.into_iter().find(|&k| {
        spec.pocket(k)
            .is_some_and(|hole| hole.centre.distance(p) < hole.radius)
    }) {
        return Err(format!("over the {}", billiards_rules::pocket_name(pocket)));
    }
    let blocker = sim
        .balls()
        .zip(sim.numbers())
        .filter(|(b, n)| **n != number && b.motion.on_table())
        .find(|(b, _)| to_dvec2(b.position).distance(p) < 2.0 * r);
    if let Some((_, n)) = blocker {
        return Err(format!("on the {}", ball_name(*n)));
    }
    Ok(())
}

/// "cue ball", "3 ball".
pub fn ball_name(number: u8) -> String {
    if number == 0 {
        "cue ball".to_owned()
    } else {
        format!("{number} ball")
    }
}

/// The numbers the Place tool may add: those of 0 to [`MAX_NUMBER`] not on the table.
pub fn missing_numbers(sim: &Simulation) -> Vec<u8> {
    let on: Vec<u8> = layout_now(sim).iter().map(|b| b.number).collect();
    (0..=MAX_NUMBER).filter(|n| !on.contains(n)).collect()
}

/// The first free place for a new ball: a spot (foot, centre, head), else a point of a grid
/// over the cloth.
pub fn free_spot(sim: &Simulation, spec: &TableSpec, number: u8) -> Option<DVec2> {
    let [head, centre, foot] = spots(spec);
    let h = spec.half_extents() - DVec2::splat(2.0 * spec.ball_radius);
    let grid = (0..=16).flat_map(move |i| {
        (0..=8).map(move |j| {
            DVec2::new(
                -h.x + 2.0 * h.x * f64::from(i) / 16.0,
                -h.y + 2.0 * h.y * f64::from(j) / 8.0,
            )
        })
    });
    [foot, centre, head]
        .into_iter()
        .chain(grid)
        .find(|&p| spot_error(sim, spec, number, p).is_ok())
}

/// The ball under the pointer: the nearest on the table within 1.2 radii.
fn ball_under(sim: &Simulation, p: DVec2) -> Option<u8> {
    let r = sim.params().ball.radius;
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, to_dvec2(b.position).distance(p)))
        .filter(|&(_, d)| d < 1.2 * r)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(n, _)| n)
}

/// The pointer: a press on a ball picks it and starts a drag (the ball goes where the button
/// is let go); a click on the cloth with a ball picked puts that ball there.
pub(super) fn pick_and_drag(
    input: PointerInput,
    (buttons, keys): (Res<ButtonInput<MouseButton>>, Res<ButtonInput<KeyCode>>),
    solver: Option<Res<Solver>>,
    spec: Res<TableSpec>,
    status: Res<SimStatus>,
    mut placing: ResMut<Placing>,
    mut edits: MessageWriter<EditRequested>,
) {
    let Some(solver) = solver else { return };
    let sim = solver.simulation();
    let Some(point) = input.table_point(spec.ball_radius as f32) else {
        return;
    };
    // Shift places the ball exactly where the pointer is, spots or not.
    let free = keys.any_pressed([KeyCode::ShiftLeft, KeyCode::ShiftRight]);
    let place = |p: DVec2| if free { p } else { snap(&spec, p) };
    if buttons.just_pressed(MouseButton::Left) {
        match ball_under(sim, point) {
            Some(n) => {
                placing.selected = Some(n);
                placing.dragging = true;
            }
            None => {
                if let Some(number) = placing.selected
                    && status.at_rest
                {
                    edits.write(EditRequested::Move {
                        number,
                        to: point,
                        free,
                    });
                }
            }
        }
    }
    let Some(number) = placing.selected.filter(|_| placing.dragging) else {
        placing.target = None;
        return;
    };
    let target = place(point);
    placing.target = Some((target, spot_error(sim, &spec, number, target)));
    if !buttons.pressed(MouseButton::Left) {
        placing.dragging = false;
        placing.target = None;
        let from = layout_now(sim)
            .into_iter()
            .find(|b| b.number == number)
            .map(|b| to_dvec2(b.position));
        // A click on a ball picks it; only a drag away from it moves it.
        if from.is_some_and(|f| f.distance(target) > 0.5 * spec.ball_radius) {
            edits.write(EditRequested::Move {
                number,
                to: point,
                free,
            });
        }
    }
}

/// Keys of the Place tool: Delete removes the picked ball, Ctrl+Z undoes the last edit,
/// Escape lets the ball go (and a second Escape leaves the tool).
pub(super) fn placing_keys(
    keys: Res<ButtonInput<KeyCode>>,
    mut placing: ResMut<Placing>,
    mut edits: MessageWriter<EditRequested>,
    mut next: ResMut<NextState<Practice>>,
) {
    if keys.any_just_pressed([KeyCode::Delete, KeyCode::Backspace])
        && let Some(number) = placing.selected
    {
        edits.write(EditRequested::Remove { number });
    }
    let ctrl = keys.any_pressed([KeyCode::ControlLeft, KeyCode::ControlRight]);
    if ctrl && keys.just_pressed(KeyCode::KeyZ) {
        edits.write(EditRequested::Undo);
    }
    if keys.just_pressed(KeyCode::Escape) {
        if placing.selected.is_some() {
            placing.selected = None;
            placing.dragging = false;
        } else {
            next.set(Practice::Off);
        }
    }
}

/// The Place tool is for free play: a match started from the dialog closes it.
pub(super) fn leave_placing_in_a_match(
    rules: Res<Rules>,
    state: Res<State<Practice>>,
    mut next: ResMut<NextState<Practice>>,
) {
    if rules.in_match() && *state.get() == Practice::Placing {
        next.set(Practice::Off);
    }
}

/// Leaving the tool lets the picked ball go.
pub(super) fn clear_selection(mut placing: ResMut<Placing>) {
    placing.selected = None;
    placing.dragging = false;
    placing.target = None;
}

/// The picked ball's ring, the dragged ball's target (green where it may go, red where not)
/// and the spots.
pub(super) fn draw_placing(
    placing: Res<Placing>,
    spec: Res<TableSpec>,
    solver: Option<Res<Solver>>,
    mut gizmos: Gizmos,
) {
    let lift = 0.003;
    let at = |p: DVec2| to_world(p.extend(lift));
    let flat = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    let r = spec.ball_radius as f32;
    for s in spots(&spec) {
        gizmos.cross(
            Isometry3d::new(at(s), flat),
            0.4 * r,
            Color::srgba(1.0, 1.0, 1.0, 0.7),
        );
    }
    for s in rack_places(&spec) {
        gizmos
            .circle(
                Isometry3d::new(at(s), flat),
                0.15 * r,
                Color::srgba(1.0, 1.0, 1.0, 0.35),
            )
            .resolution(8);
    }
    if let Some(solver) = solver
        && let Some(number) = placing.selected
        && let Some(b) = layout_now(solver.simulation())
            .into_iter()
            .find(|b| b.number == number)
    {
        gizmos
            .circle(
                Isometry3d::new(at(to_dvec2(b.position)), flat),
                1.25 * r,
                Color::srgb(1.0, 0.85, 0.1),
            )
            .resolution(32);
    }
    if let Some((p, ok)) = &placing.target {
        let colour = if ok.is_ok() {
            Color::srgb(0.3, 1.0, 0.4)
        } else {
            Color::srgb(1.0, 0.3, 0.3)
        };
        gizmos
            .circle(Isometry3d::new(at(*p), flat), r, colour)
            .resolution(32);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::{Params, Table};

    fn table_with(balls: &[(u8, f64, f64)]) -> (Simulation, TableSpec) {
        let spec = TableSpec::default();
        let setups: Vec<BallSetup> = balls
            .iter()
            .map(|&(n, x, y)| BallSetup::at(n, billiards_physics::Vec2::new(x, y)))
            .collect();
        let params = Params {
            ball: spec.ball(),
            ..Params::default()
        };
        let table: Table = spec.physics_table();
        (Simulation::new(table, params, &setups).unwrap(), spec)
    }

    /// A drop near a spot lands on it; farther than [`SNAP`] it stays where it fell.
    #[test]
    fn drops_near_a_spot_snap_to_it() {
        let spec = TableSpec::default();
        let foot = spec.foot_spot();
        assert_eq!(snap(&spec, foot + DVec2::new(0.01, -0.005)), foot);
        let off = foot + DVec2::new(SNAP + 0.001, 0.0);
        assert_eq!(snap(&spec, off), off);
        assert_eq!(snap(&spec, DVec2::new(0.0, 0.012)), DVec2::ZERO);
    }

    /// The rack's places are snap points too: one ball-diameter behind the apex (the second
    /// row, at x = foot + sqrt(3) r and y = +-r) a drop 1 cm off goes onto the place.
    #[test]
    fn drops_near_a_rack_place_snap_to_it() {
        let spec = TableSpec::default();
        let places = rack_places(&spec);
        assert_eq!(places.len(), 15);
        let r = spec.ball_radius;
        let second = spec.foot_spot() + DVec2::new(3f64.sqrt() * r, r);
        let place = places
            .iter()
            .copied()
            .min_by(|a, b| a.distance(second).total_cmp(&b.distance(second)))
            .unwrap();
        assert!(place.distance(second) < 1e-9, "{place} against {second}");
        assert_eq!(snap(&spec, second + DVec2::new(0.0, 0.01)), place);
    }

    /// A ball may not go on another, off the cloth or over a hole; its own spot is free.
    #[test]
    fn a_spot_on_a_ball_off_the_cloth_or_over_a_hole_is_refused() {
        let (sim, spec) = table_with(&[(0, -0.5, 0.0), (1, 0.5, 0.0)]);
        let r = spec.ball_radius;
        assert!(spot_error(&sim, &spec, 0, DVec2::new(-0.5, 0.0)).is_ok());
        assert!(
            spot_error(&sim, &spec, 0, DVec2::new(0.5 + 1.9 * r, 0.0))
                .unwrap_err()
                .contains("1 ball")
        );
        assert!(spot_error(&sim, &spec, 0, DVec2::new(0.5 + 2.01 * r, 0.0)).is_ok());
        let h = spec.half_extents();
        assert!(
            spot_error(&sim, &spec, 0, DVec2::new(0.0, h.y))
                .unwrap_err()
                .contains("cloth")
        );
        assert!(spot_error(&sim, &spec, 0, DVec2::new(f64::NAN, 0.0)).is_err());
        let hole = spec
            .pocket(billiards_physics::Pocket::FootRight)
            .unwrap()
            .centre;
        assert!(spot_error(&sim, &spec, 0, hole).is_err());
    }

    /// The numbers offered to add are those not on the table, and a new ball's free spot is
    /// the foot spot unless it is taken.
    #[test]
    fn a_new_ball_goes_on_the_first_free_spot() {
        let (sim, spec) = table_with(&[(0, -0.5, 0.0), (3, 0.5, 0.3)]);
        let missing = missing_numbers(&sim);
        assert_eq!(missing.len(), 14);
        assert!(!missing.contains(&0) && !missing.contains(&3) && missing.contains(&15));
        assert_eq!(free_spot(&sim, &spec, 1), Some(spec.foot_spot()));
        let foot = spec.foot_spot().x;
        let (sim, spec) = table_with(&[(0, -0.5, 0.0), (3, foot, 0.0)]);
        assert_eq!(free_spot(&sim, &spec, 1), Some(DVec2::ZERO));
    }
}
