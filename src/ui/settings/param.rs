//! What the settings panel reads and edits ([`SettingsParam`]), and the flags the panel
//! keeps ([`OpenSections`], [`RackConfirm`]).

use bevy::prelude::*;
use billiards_physics::Rack;

use crate::{
    config::ConfigFile,
    settings::{
        ClampReport, GraphicsSettings, PhysicsSettings, ShotSettings, TableSetup, ViewSettings,
    },
    sim::{RackRequested, Referee, ShotRequested, SimStatus, Solver, StepRequested, UndoRequested},
    stress::StressMonitor,
    table::balls::{Ball, BallMotion, Pocketed},
    table::geometry::TableSpec,
    view::camera::OrbitCamera,
};

/// Open every section of the panel at start (`--open-sections`: screenshots, layout check).
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct OpenSections(pub bool);

/// A rack asked for while a game is in progress, waiting for the player's yes.
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RackConfirm(pub Option<Rack>);

/// Everything the settings panel edits or shows, bundled so the system stays readable.
#[derive(bevy::ecs::system::SystemParam)]
pub struct SettingsParam<'w, 's> {
    pub(super) shot: ResMut<'w, ShotSettings>,
    pub(super) physics: ResMut<'w, PhysicsSettings>,
    pub(super) view: ResMut<'w, ViewSettings>,
    pub(super) graphics: ResMut<'w, GraphicsSettings>,
    pub(super) report: ResMut<'w, ClampReport>,
    pub(super) orbit: ResMut<'w, OrbitCamera>,
    pub(super) status: Res<'w, SimStatus>,
    pub(super) solver: Option<Res<'w, Solver>>,
    pub(super) referee: Res<'w, Referee>,
    pub(super) config: Res<'w, ConfigFile>,
    pub(super) confirm: ResMut<'w, RackConfirm>,
    pub(super) open_all: Res<'w, OpenSections>,
    pub(super) racks: MessageWriter<'w, RackRequested>,
    pub(super) steps: MessageWriter<'w, StepRequested>,
    pub(super) shots: MessageWriter<'w, ShotRequested>,
    pub(super) undo: MessageWriter<'w, UndoRequested>,
    pub(super) spec: Res<'w, TableSpec>,
    pub(super) setup: ResMut<'w, TableSetup>,
    pub(super) stress: Res<'w, StressMonitor>,
    pub(super) cue_ball: Query<'w, 's, (&'static Ball, &'static mut BallMotion), Without<Pocketed>>,
}
