//! The Place tool's edits applied ([`apply_edits`]): a ball moved, added or removed, the
//! table cleared, the last edit undone; each done edit goes on the undo list.

use bevy::{math::DVec2, prelude::*};
use billiards_physics::{BallSetup, Rack, Simulation};

use super::placing::{Edit, EditRequested, Placing, ball_name, free_spot, snap, spot_error};
use super::position::POSITION_NAME;
use crate::{
    play::game::Rules,
    sim::{LayoutRequested, SimStatus, Solver, layout_now, to_dvec2},
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
};

/// Why an edit was not done: the note to say (`None`: nothing to say).
type Refused = Option<String>;

/// The table an edit works on: the simulation at rest, the table's geometry, its balls as
/// they lie, and the rack a new layout keeps.
struct Layout<'a> {
    sim: &'a Simulation,
    spec: &'a TableSpec,
    balls: Vec<BallSetup>,
    rack: Rack,
}

impl Layout<'_> {
    /// Where ball `number` lies, if on the table.
    fn at(&self, number: u8) -> Option<DVec2> {
        self.balls
            .iter()
            .find(|b| b.number == number)
            .map(|b| to_dvec2(b.position))
    }

    /// A new layout of `balls` asked of the simulation (the same rack, named a position).
    fn request(&self, balls: Vec<BallSetup>) -> LayoutRequested {
        LayoutRequested {
            balls,
            rack: self.rack,
            name: POSITION_NAME,
        }
    }
}

/// Carries the last edit asked for this frame out (free play only, every ball at rest). A
/// move edits the ball's [`BallMotion`] (the solver places it and the recorder logs it);
/// adding and removing set the new layout up.
#[allow(clippy::too_many_arguments)]
pub(super) fn apply_edits(
    mut requests: MessageReader<EditRequested>,
    solver: Option<Res<Solver>>,
    spec: Res<TableSpec>,
    mut balls: Query<(&Ball, &mut BallMotion), Without<Pocketed>>,
    mut layouts: MessageWriter<LayoutRequested>,
    mut status: ResMut<SimStatus>,
    mut placing: ResMut<Placing>,
    (rules, mut kept): (Res<Rules>, ResMut<super::state::KeptNote>),
) {
    let Some(solver) = solver else {
        requests.clear();
        return;
    };
    // One edit a frame: a layout edit replaces the solver only at the Commands below.
    let Some(&request) = requests.read().last() else {
        return;
    };
    if rules.in_match() {
        status.note =
            Some("placing balls is for free play: a match's balls lie as they are".into());
        return;
    }
    let sim = solver.simulation();
    if !sim.is_at_rest() {
        status.note = Some("wait until every ball rests".to_owned());
        return;
    }
    let table = Layout {
        sim,
        spec: &spec,
        balls: layout_now(sim),
        rack: solver.rack(),
    };
    let (request, undoing) = match request {
        EditRequested::Undo => match placing.undo.pop().map(undoing) {
            None => {
                status.note = Some("no edit to undo".to_owned());
                return;
            }
            Some(Ok(inverse)) => (inverse, true),
            Some(Err(before)) => {
                layouts.write(table.request(before));
                status.note = Some("edit undone".to_owned());
                kept.0.clone_from(&status.note);
                return;
            }
        },
        other => (other, false),
    };
    let done = match request {
        EditRequested::Move { number, to, free } => move_ball(&table, &mut balls, number, to, free),
        EditRequested::Add { number, at } => {
            add_ball(&table, number, at, &mut layouts, &mut placing)
        }
        EditRequested::Remove { number } => remove_ball(table, number, &mut layouts, &mut placing),
        EditRequested::Clear => clear_table(table, &mut layouts, &mut placing),
        EditRequested::Undo => return,
    };
    let done = match done {
        Ok(done) => done,
        Err(note) => {
            if note.is_some() {
                status.note = note;
            }
            return;
        }
    };
    status.note = Some(if undoing {
        "edit undone".to_owned()
    } else {
        done_note(&done)
    });
    // A new layout resets the status at SimSystems::Commands: the note is said again after.
    kept.0.clone_from(&status.note);
    if !undoing {
        placing.undo.push(done);
    }
}

/// The request that takes `edit` back (a move back exactly where the ball was, a ball
/// removed or put back), or for a cleared table the layout it had.
fn undoing(edit: Edit) -> Result<EditRequested, Vec<BallSetup>> {
    match edit {
        Edit::Moved { number, from } => Ok(EditRequested::Move {
            number,
            to: from,
            free: true,
        }),
        Edit::Added { number } => Ok(EditRequested::Remove { number }),
        Edit::Removed { number, at } => Ok(EditRequested::Add {
            number,
            at: Some(at),
        }),
        Edit::Cleared { before } => Err(before),
    }
}

/// A ball moved to `to` (snapped unless `free`): a placement of its motion, which the
/// recorder logs.
fn move_ball(
    table: &Layout,
    balls: &mut Query<(&Ball, &mut BallMotion), Without<Pocketed>>,
    number: u8,
    to: DVec2,
    free: bool,
) -> Result<Edit, Refused> {
    // An undo puts the ball back exactly where it was.
    let to = if free { to } else { snap(table.spec, to) };
    let Some(from) = table.at(number) else {
        return Err(Some(format!(
            "the {} is not on the table",
            ball_name(number)
        )));
    };
    if let Err(why) = spot_error(table.sim, table.spec, number, to) {
        return Err(Some(format!(
            "the {} cannot go there: {why}",
            ball_name(number)
        )));
    }
    let Some((_, mut motion)) = balls.iter_mut().find(|(b, _)| b.number == number) else {
        return Err(None);
    };
    motion.position = to;
    motion.velocity = DVec2::ZERO;
    Ok(Edit::Moved { number, from })
}

/// A ball added at `spot` (or the first free spot): a new layout, the ball picked.
fn add_ball(
    table: &Layout,
    number: u8,
    spot: Option<DVec2>,
    layouts: &mut MessageWriter<LayoutRequested>,
    placing: &mut Placing,
) -> Result<Edit, Refused> {
    if table.at(number).is_some() {
        return Err(Some(format!(
            "the {} is on the table already",
            ball_name(number)
        )));
    }
    let spot = match spot {
        Some(p) => spot_error(table.sim, table.spec, number, p).map(|()| p),
        None => free_spot(table.sim, table.spec, number).ok_or_else(|| "no free spot".to_owned()),
    };
    let p =
        spot.map_err(|why| Some(format!("the {} cannot go there: {why}", ball_name(number))))?;
    let mut balls = table.balls.clone();
    balls.push(BallSetup::at(
        number,
        billiards_physics::Vec2::new(p.x, p.y),
    ));
    // The cue ball first, as every layout has it.
    balls.sort_by_key(|b| b.number);
    layouts.write(table.request(balls));
    placing.selected = Some(number);
    Ok(Edit::Added { number })
}

/// A ball taken off: a new layout without it, unpicked if it was picked.
fn remove_ball(
    table: Layout,
    number: u8,
    layouts: &mut MessageWriter<LayoutRequested>,
    placing: &mut Placing,
) -> Result<Edit, Refused> {
    let Some(from) = table.at(number) else {
        return Err(Some(format!(
            "the {} is not on the table",
            ball_name(number)
        )));
    };
    let balls: Vec<BallSetup> = table
        .balls
        .iter()
        .copied()
        .filter(|b| b.number != number)
        .collect();
    layouts.write(table.request(balls));
    if placing.selected == Some(number) {
        placing.selected = None;
    }
    Ok(Edit::Removed { number, at: from })
}

/// Every object ball off: the cue ball alone, where it lies or (if down) on the head spot or
/// the first free spot.
fn clear_table(
    table: Layout,
    layouts: &mut MessageWriter<LayoutRequested>,
    placing: &mut Placing,
) -> Result<Edit, Refused> {
    let cue = match table.at(0) {
        Some(p) => p,
        None => [table.spec.head_spot()]
            .into_iter()
            .chain(free_spot(table.sim, table.spec, 0))
            .find(|&p| spot_error(table.sim, table.spec, 0, p).is_ok())
            .ok_or_else(|| Some("no free spot for the cue ball".to_owned()))?,
    };
    if table.balls.len() == 1 && table.at(0).is_some() {
        return Err(Some("only the cue ball is on the table".to_owned()));
    }
    layouts.write(table.request(vec![BallSetup::at(
        0,
        billiards_physics::Vec2::new(cue.x, cue.y),
    )]));
    placing.selected = None;
    Ok(Edit::Cleared {
        before: table.balls,
    })
}

/// What a done edit says.
fn done_note(done: &Edit) -> String {
    match done {
        Edit::Moved { number, .. } => format!("{} placed", ball_name(*number)),
        Edit::Added { number } => format!("{} added", ball_name(*number)),
        Edit::Removed { number, .. } => format!("{} removed", ball_name(*number)),
        Edit::Cleared { .. } => "table cleared: the cue ball alone".to_owned(),
    }
}
