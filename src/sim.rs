//! The simulation's interface to the rest of the game, and (for now) a placeholder for it.
//!
//! The interface stays: [`Rack`], the request messages ([`RackRequested`], [`ShotRequested`],
//! [`StepRequested`]), the [`SimStatus`] resource and the clock settings (pause, time scale).
//!
//! PLACEHOLDER: until `billiards-physics` lands, [`plugin`] only spawns the balls of a rack
//! at their positions and never moves them. A shot or a step request is answered with a note
//! in [`SimStatus`] saying that no solver is connected. The rack layouts below stand in for
//! the library's `racks` module and go away with this placeholder.

use bevy::{math::DVec2, prelude::*};

use crate::{
    balls::{Ball, BallMotion, MotionState},
    geometry::{INCH, TableSpec},
    settings::PhysicsSettings,
};

/// Registers the simulation interface and the placeholder systems.
pub(crate) fn plugin(app: &mut App) {
    app.add_message::<RackRequested>()
        .add_message::<ShotRequested>()
        .add_message::<StepRequested>()
        .init_resource::<SimStatus>()
        .add_systems(Startup, request_default_rack)
        .add_systems(
            Update,
            (
                apply_clock_settings,
                rack_balls,
                answer_without_solver,
            ),
        );
}

/// The ball layouts the player can rack.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Rack {
    /// The paper's default layout: the cue ball on the head spot and 15 balls racked 1/10 in
    /// apart with the apex on the foot spot.
    #[default]
    PaperDefault,
    /// A tight 15-ball (eight-ball) rack: 8 in the centre, a solid and a stripe in the back
    /// corners.
    FifteenBall,
    /// A tight nine-ball diamond: 1 at the apex, 9 in the centre.
    NineBall,
}

impl Rack {
    /// Every rack, in the order the panel lists them.
    pub const ALL: [Self; 3] = [Self::PaperDefault, Self::FifteenBall, Self::NineBall];

    /// The name shown to the player.
    pub fn label(self) -> &'static str {
        match self {
            Self::PaperDefault => "Paper default",
            Self::FifteenBall => "15-ball rack",
            Self::NineBall => "9-ball rack",
        }
    }
}

/// Asks for the table to be cleared and racked anew.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RackRequested(pub Rack);

/// Asks for the cue ball to be struck. Only honoured while every ball rests.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ShotRequested {
    /// Direction in the table plane, radians counter-clockwise from +x.
    pub angle: f64,
    /// Cue-ball speed given by the cue, m/s.
    pub speed: f64,
}

/// Asks the paused simulation to advance exactly to its next event.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct StepRequested;

/// What the simulation reports to the HUD and to the game flow.
#[derive(Resource, Debug, Clone, PartialEq, Default)]
pub struct SimStatus {
    /// Whether every ball is at rest (a shot may be taken).
    pub at_rest: bool,
    /// Shots taken since the last rack.
    pub shots: u32,
    /// Simulated time since the last rack, seconds.
    pub sim_time: f64,
    /// Events the solver resolved during the current (or last) shot.
    pub events_this_shot: u32,
    /// Wall time the solver took in the last frame that ran it, seconds.
    pub solver_seconds_last_frame: f64,
    /// A message for the player about the simulation's state, if any.
    pub note: Option<String>,
}

/// Applies the pause and time-scale settings to the virtual clock the solver advances by.
fn apply_clock_settings(settings: Res<PhysicsSettings>, mut time: ResMut<Time<Virtual>>) {
    if !settings.is_changed() {
        return;
    }
    time.set_relative_speed_f64(settings.time_scale);
    if settings.paused {
        time.pause();
    } else {
        time.unpause();
    }
}

fn request_default_rack(mut racks: MessageWriter<RackRequested>) {
    racks.write(RackRequested(Rack::default()));
}

/// PLACEHOLDER: despawns every ball and spawns the requested layout at rest.
fn rack_balls(
    mut commands: Commands,
    mut requests: MessageReader<RackRequested>,
    spec: Res<TableSpec>,
    balls: Query<Entity, With<Ball>>,
    mut status: ResMut<SimStatus>,
) {
    let Some(&RackRequested(rack)) = requests.read().last() else {
        return;
    };
    for entity in &balls {
        commands.entity(entity).despawn();
    }
    for (id, (number, position)) in rack_layout(rack, &spec).into_iter().enumerate() {
        commands.spawn((
            Ball { id, number },
            BallMotion {
                position,
                velocity: DVec2::ZERO,
                state: MotionState::Stationary,
            },
            Transform::from_translation(spec.ball_world_position(position)),
            Name::new(format!("Ball {number}")),
        ));
    }
    *status = SimStatus {
        at_rest: true,
        ..default()
    };
}

/// PLACEHOLDER: there is no solver to strike or step yet; say so instead of pretending.
fn answer_without_solver(
    mut shots: MessageReader<ShotRequested>,
    mut steps: MessageReader<StepRequested>,
    mut status: ResMut<SimStatus>,
) {
    let shot = shots.read().count() > 0;
    let step = steps.read().count() > 0;
    if shot || step {
        let note = "No physics solver is connected yet: balls stay where they are.";
        warn!("{note}");
        status.note = Some(note.to_owned());
    }
}

/// PLACEHOLDER for the library's `racks`: ball numbers and table-plane positions of a rack,
/// the cue ball (number 0) first.
pub fn rack_layout(rack: Rack, spec: &TableSpec) -> Vec<(u8, DVec2)> {
    // Rows of ball numbers, from the apex toward the foot rail, listed from +y to -y.
    let (rows, gap): (&[&[u8]], f64) = match rack {
        Rack::PaperDefault => (
            &[
                &[1],
                &[2, 3],
                &[4, 5, 6],
                &[7, 8, 9, 10],
                &[11, 12, 13, 14, 15],
            ],
            0.1 * INCH,
        ),
        Rack::FifteenBall => (
            &[
                &[1],
                &[9, 2],
                &[10, 8, 3],
                &[11, 4, 12, 5],
                &[6, 13, 14, 7, 15],
            ],
            TIGHT_GAP,
        ),
        Rack::NineBall => (&[&[1], &[2, 3], &[4, 9, 5], &[6, 7], &[8]], TIGHT_GAP),
    };
    let pitch = 2.0 * spec.ball_radius + gap;
    let row_spacing = pitch * 3f64.sqrt() / 2.0;
    let mut layout = vec![(0, spec.head_spot())];
    for (k, row) in rows.iter().enumerate() {
        let x = spec.foot_spot().x + k as f64 * row_spacing;
        let half_span = (row.len() - 1) as f64 / 2.0;
        for (j, &number) in row.iter().enumerate() {
            let y = (half_span - j as f64) * pitch;
            layout.push((number, DVec2::new(x, y)));
        }
    }
    layout
}

/// Space left between racked balls in a "tight" rack, so that no two balls start exactly in
/// contact (an exactly touching pair is a degenerate case for any contact solver).
const TIGHT_GAP: f64 = 1e-4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn racks_are_on_the_table_and_do_not_overlap() {
        let spec = TableSpec::default();
        for rack in Rack::ALL {
            let layout = rack_layout(rack, &spec);
            let expected = if rack == Rack::NineBall { 10 } else { 16 };
            assert_eq!(layout.len(), expected, "{rack:?}");
            assert_eq!(layout[0], (0, spec.head_spot()));
            for (i, &(number, p)) in layout.iter().enumerate() {
                assert!(spec.contains_ball_centre(p), "{rack:?} ball {number} at {p}");
                for &(_, q) in &layout[i + 1..] {
                    assert!(p.distance(q) > 2.0 * spec.ball_radius, "{rack:?}");
                }
            }
            let mut numbers: Vec<u8> = layout.iter().map(|&(n, _)| n).collect();
            numbers.sort_unstable();
            numbers.dedup();
            assert_eq!(numbers.len(), layout.len(), "{rack:?}: numbers repeat");
        }
    }

    #[test]
    fn eight_sits_in_the_middle_of_the_fifteen_ball_rack() {
        let spec = TableSpec::default();
        let layout = rack_layout(Rack::FifteenBall, &spec);
        let (_, eight) = layout.iter().find(|&&(n, _)| n == 8).copied().unwrap();
        let apex = spec.foot_spot();
        assert_eq!(eight.y, 0.0);
        assert!(eight.x > apex.x);
    }
}
