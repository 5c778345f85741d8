//! The replay viewer: a recording opened from the recordings folder, a typed path, a file
//! dropped on the window or `billiards replay FILE`, shown on the table exactly as recorded.
//!
//! Opening a recording enters [`GameMode::Replay`]:
//! - the live solver does not advance and takes no commands (the simulation's and the cue's
//!   systems run only in [`GameMode::Play`]), so the live game waits untouched;
//! - the live balls are put aside ([`shelf`]) and one [`ReplayBall`] entity per recorded ball
//!   shows the recording at the replay time;
//! - positions and pockets are sampled exactly from the recording's history (no
//!   re-simulation) and written to the same [`BallMotion`](crate::table::balls::BallMotion) /
//!   [`Pocketed`](crate::table::balls::Pocketed) components the live game uses, so balls roll and
//!   drop into pockets as in play.
//!
//! Closing despawns those entities and leaves the mode; the shelf gives the live balls back. A
//! rack request while replaying closes the replay first.
//!
//! Everything is driven by [`ReplayCommand`] messages, applied by one exclusive system in
//! [`PreUpdate`]; the widgets (in `crate::ui`) only read [`Replay`] and write commands, so the
//! logic runs (and is tested) headless.
//!
//! - [`open`]: the loaded recording and navigation by event and shot;
//! - [`describe`]: events and verdicts in words;
//! - [`jobs`]: export and verification on background threads;
//! - [`balls`]: the entities that show the recorded balls;
//! - [`shelf`]: the live game put aside and restored.

pub mod balls;
pub mod describe;
pub mod jobs;
pub mod open;
pub mod shelf;

use std::path::{Path, PathBuf};

use bevy::{
    prelude::*,
    window::{FileDragAndDrop, RequestRedraw},
};
use billiards_physics::recording::{Recording, Verdict};
use billiards_replay::export::ExportOptions;

pub use self::{
    balls::ReplayBall,
    jobs::{ExportFormat, ExportJob, ExportRequest, ExportScope, VerifyJob},
    open::{OpenRecording, RulesLog},
};
use crate::{
    input::InputSystems,
    mode::GameMode,
    sim::{RackRequested, Solver},
    table::{balls::ShownTime, geometry::TableSpec},
};

/// Registers the replay logic (headless: no egui, no window needed; the widgets are in
/// `crate::ui`).
pub fn plugin(app: &mut App) {
    app.init_resource::<Replay>()
        .add_message::<ReplayCommand>()
        .add_message::<FileDragAndDrop>()
        .add_message::<RequestRedraw>()
        .add_plugins(shelf::plugin)
        .add_systems(
            PreUpdate,
            (open_dropped_files, close_on_rack, apply_replay)
                .chain()
                .in_set(ReplaySystems),
        )
        .add_systems(
            Update,
            replay_keys
                .in_set(InputSystems::Keyboard)
                .run_if(in_state(GameMode::Replay)),
        );
}

/// The replay systems in [`PreUpdate`]: commands applied, the replay clock advanced, the
/// recorded state written to the balls.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ReplaySystems;

/// Slowest replay speed, times real time.
pub const MIN_SPEED: f64 = 0.1;
/// Fastest replay speed, times real time.
pub const MAX_SPEED: f64 = 4.0;
/// Longest wall-clock frame the replay clock follows (a stalled window does not jump ahead).
const MAX_FRAME_SECONDS: f64 = 0.25;

/// What the timeline asks for. Written by the panel, the keys, drops and tests; applied in
/// [`PreUpdate`] in the order written.
#[derive(Message, Debug, Clone, PartialEq)]
pub enum ReplayCommand {
    /// Load a recording and show it (replacing one already open). A file that cannot be
    /// loaded leaves everything as it was and sets [`Replay::error`].
    Open(PathBuf),
    /// Back to the live game.
    Close,
    /// Play from the replay time (from the start when at the end).
    Play,
    /// Stop the replay clock.
    Pause,
    /// Play or pause.
    TogglePlay,
    /// Replay speed, times real time (clamped to [`MIN_SPEED`]..[`MAX_SPEED`]).
    SetSpeed(f64),
    /// Go to this simulated time (clamped to the recording).
    Seek(f64),
    /// Pause at the first event after the replay time.
    NextEvent,
    /// Pause at the last event before the replay time.
    PreviousEvent,
    /// Go to the next strike.
    NextShot,
    /// Go to the last strike before the replay time.
    PreviousShot,
    /// Re-simulate the recording on a background thread and compare bit for bit
    /// ([`Replay::verdict`] once done; [`Replay::verifying`] meanwhile).
    Verify,
    /// Start an export on a background thread ([`Replay::export`]).
    Export(ExportRequest),
    /// Stop the running export after the frame it is on (a GIF is then not written; the PNG
    /// frames written so far stay).
    CancelExport,
    /// The player has read why the last file could not be opened: the window saying so
    /// closes ([`Replay::error_to_show`]); the Recordings section keeps the reason.
    DismissError,
}

/// Opens this recording once the live game has been racked (`billiards replay FILE`).
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct OpenAtStart(pub PathBuf);

/// The replay viewer's state.
#[derive(Resource, Debug)]
pub struct Replay {
    /// The recording on the table, if any.
    pub open: Option<OpenRecording>,
    /// The replay time: simulated seconds since the recording's rack.
    pub time: f64,
    /// Whether the replay clock runs.
    pub playing: bool,
    /// Replay speed, times real time.
    pub speed: f64,
    /// Why the last recording could not be opened.
    pub error: Option<String>,
    /// Whether the player dismissed the window showing [`Replay::error`] (set anew, false,
    /// with each new error).
    pub error_dismissed: bool,
    /// The last verification of the open recording.
    pub verdict: Option<Result<Verdict, String>>,
    /// The rules' verdicts re-judged with that verification (a rules game only): how many
    /// matched the log, or the first difference.
    pub rules_verdict: Option<Result<usize, String>>,
    /// A verification running on its own thread (a long recording takes a while to
    /// re-simulate; the window stays responsive).
    pub verifying: Option<VerifyJob>,
    /// The export in progress.
    pub export: Option<ExportJob>,
    /// How the last export ended: what was written, or why not.
    pub export_result: Option<Result<String, String>>,
    /// The entities showing the open recording's balls, by recorded ball index.
    entities: Vec<Entity>,
    /// The live game's table while a recording on another table is shown.
    live_table: Option<TableSpec>,
}

impl Replay {
    /// Why the last file could not be opened, while the window saying so is up: `None` once
    /// the player dismissed it ([`ReplayCommand::DismissError`]) or a file opened.
    pub fn error_to_show(&self) -> Option<&str> {
        self.error.as_deref().filter(|_| !self.error_dismissed)
    }
}

impl Default for Replay {
    fn default() -> Self {
        Self {
            open: None,
            time: 0.0,
            playing: false,
            speed: 1.0,
            error: None,
            error_dismissed: false,
            verdict: None,
            rules_verdict: None,
            verifying: None,
            export: None,
            export_result: None,
            entities: Vec::new(),
            live_table: None,
        }
    }
}

impl Replay {
    /// The entity showing recorded ball `id` of the open recording.
    pub fn entity(&self, id: usize) -> Option<Entity> {
        self.entities.get(id).copied()
    }
}

fn open_dropped_files(
    mut drops: MessageReader<FileDragAndDrop>,
    mut replay: MessageWriter<ReplayCommand>,
) {
    for drop in drops.read() {
        if let FileDragAndDrop::DroppedFile { path_buf, .. } = drop {
            replay.write(ReplayCommand::Open(path_buf.clone()));
        }
    }
}

/// A new rack is asked for (the panel's rack buttons): the replay closes first, so the rack
/// reaches the live game in the same frame.
fn close_on_rack(
    mut racks: MessageReader<RackRequested>,
    mode: Res<State<GameMode>>,
    mut replay: MessageWriter<ReplayCommand>,
) {
    if racks.read().count() > 0 && *mode.get() == GameMode::Replay {
        replay.write(ReplayCommand::Close);
    }
}

/// Applies the frame's commands, runs the replay clock and shows the recording at the replay
/// time. Exclusive: it spawns and despawns balls.
fn apply_replay(world: &mut World) {
    let mut commands: Vec<ReplayCommand> = world
        .resource_mut::<Messages<ReplayCommand>>()
        .drain()
        .collect();
    if world.contains_resource::<Solver>()
        && let Some(OpenAtStart(path)) = world.remove_resource::<OpenAtStart>()
    {
        commands.insert(0, ReplayCommand::Open(path));
    }
    // A frame that moved the replay time on purpose does not also run the clock.
    let mut moved = false;
    for command in commands {
        moved |= apply_command(world, command);
    }
    let dt = world.resource::<Time<Real>>().delta_secs_f64();
    let busy = world.resource_scope(|world, mut replay: Mut<Replay>| {
        collect_finished_jobs(&mut replay);
        if let Some(open) = &replay.open {
            let end = open.end_time();
            if replay.playing && !moved {
                let time = replay.time + dt.min(MAX_FRAME_SECONDS) * replay.speed;
                replay.time = time.min(end);
                replay.playing = time < end;
            }
            if let Some(mut shown) = world.get_resource_mut::<ShownTime>() {
                shown.0 = replay.time;
            }
            let open = replay.open.as_ref().expect("checked above");
            for (id, &entity) in replay.entities.iter().enumerate() {
                balls::show_state(world, entity, &open.history.state_at(id, replay.time));
            }
        }
        replay.playing || replay.export.is_some() || replay.verifying.is_some()
    });
    if busy {
        world.write_message(RequestRedraw);
    }
}

/// Applies one command; true when it set the replay time or started the clock (the clock
/// then does not also run this frame).
fn apply_command(world: &mut World, command: ReplayCommand) -> bool {
    match command {
        ReplayCommand::Open(path) => {
            open(world, &path);
            return true;
        }
        ReplayCommand::Close => {
            close(world);
            return false;
        }
        ReplayCommand::DismissError => {
            world.resource_mut::<Replay>().error_dismissed = true;
            return false;
        }
        _ => {}
    }
    let mut replay = world.resource_mut::<Replay>();
    let replay = &mut *replay;
    let Some(open) = &replay.open else {
        return false;
    };
    let time = replay.time;
    let end = open.end_time();
    let jump = |target: Option<f64>| target.unwrap_or(time);
    match command {
        ReplayCommand::Open(_) | ReplayCommand::Close | ReplayCommand::DismissError => {
            unreachable!("handled above")
        }
        ReplayCommand::Play => {
            if time >= end {
                replay.time = 0.0;
            }
            replay.playing = true;
            // The clock starts next frame: this frame's delta may span an idle window.
            return true;
        }
        ReplayCommand::Pause => replay.playing = false,
        ReplayCommand::TogglePlay => {
            if !replay.playing && time >= end {
                replay.time = 0.0;
            }
            replay.playing = !replay.playing;
            return true;
        }
        ReplayCommand::SetSpeed(speed) => {
            if speed.is_finite() {
                replay.speed = speed.clamp(MIN_SPEED, MAX_SPEED);
            }
        }
        ReplayCommand::Seek(t) => {
            if t.is_finite() {
                replay.time = t.clamp(0.0, end);
            }
            return true;
        }
        ReplayCommand::NextEvent => {
            replay.time = jump(open.next_event_time(time));
            replay.playing = false;
            return true;
        }
        ReplayCommand::PreviousEvent => {
            replay.time = jump(open.previous_event_time(time));
            replay.playing = false;
            return true;
        }
        ReplayCommand::NextShot => {
            replay.time = jump(open.shots.next_start(time));
            return true;
        }
        ReplayCommand::PreviousShot => {
            replay.time = jump(open.shots.previous_start(time));
            return true;
        }
        ReplayCommand::Verify => start_verify(replay),
        ReplayCommand::Export(request) => start_export(replay, request),
        ReplayCommand::CancelExport => {
            if let Some(job) = &replay.export {
                job.cancel();
            }
        }
    }
    false
}

/// Loads a recording and puts it on the table; on failure only [`Replay::error`] changes.
fn open(world: &mut World, path: &Path) {
    let loaded = Recording::load(path)
        // A rules log opened by mistake is named as such, with its recording.
        .map_err(|error| {
            billiards_rules::RulesLog::mistaken_for_recording(path, "open")
                .unwrap_or_else(|| error.to_string())
        })
        .and_then(|recording| OpenRecording::new(path, recording));
    let opened = match loaded {
        Ok(opened) => opened,
        Err(error) => {
            warn!("replay not opened: {error}");
            let mut replay = world.resource_mut::<Replay>();
            replay.error = Some(error);
            // Said in a window over the table until read (src/ui/recordings.rs).
            replay.error_dismissed = false;
            return;
        }
    };
    let previous = std::mem::take(&mut world.resource_mut::<Replay>().entities);
    balls::despawn_all(world, &previous);
    // The recording's own table (7, 8 or 9 ft); the live one comes back on closing.
    let recorded = TableSpec::fitting(&opened.recording.table);
    if *world.resource::<TableSpec>() != recorded {
        let live = std::mem::replace(&mut *world.resource_mut::<TableSpec>(), recorded);
        // A second recording keeps the first one's live table to go back to.
        world
            .resource_mut::<Replay>()
            .live_table
            .get_or_insert(live);
    }
    let entities = balls::spawn_replay_balls(world, &opened);
    let mut replay = world.resource_mut::<Replay>();
    replay.open = Some(opened);
    replay.entities = entities;
    replay.time = 0.0;
    replay.playing = true;
    replay.error = None;
    replay.verdict = None;
    replay.rules_verdict = None;
    // Entering the mode (once, if it is not already on) shelves the live balls.
    let mut next = world.resource_mut::<NextState<GameMode>>();
    // The state's own `set_if_neq`, not change detection's of the same name.
    NextState::set_if_neq(&mut *next, GameMode::Replay);
}

/// Back to the live game: the recorded balls go; leaving the mode restores the live ones.
fn close(world: &mut World) {
    let mut replay = world.resource_mut::<Replay>();
    if replay.open.take().is_none() {
        return;
    }
    replay.playing = false;
    replay.time = 0.0;
    replay.verdict = None;
    replay.rules_verdict = None;
    let entities = std::mem::take(&mut replay.entities);
    let live_table = replay.live_table.take();
    balls::despawn_all(world, &entities);
    if let Some(live) = live_table {
        *world.resource_mut::<TableSpec>() = live;
    }
    let mut next = world.resource_mut::<NextState<GameMode>>();
    // The state's own `set_if_neq`, not change detection's of the same name.
    NextState::set_if_neq(&mut *next, GameMode::Play);
}

fn start_export(replay: &mut Replay, request: ExportRequest) {
    if replay.export.is_some() {
        replay.export_result = Some(Err("an export is already running".to_owned()));
        return;
    }
    let Some(open) = &replay.open else { return };
    let (shot, span) = open.export_span(request.scope, replay.time);
    let target = request
        .path
        .unwrap_or_else(|| open.default_export_path(request.format, shot));
    let options = ExportOptions {
        fps: request.fps,
        width: request.width,
        height: request.height,
        span,
    };
    let recording = open.recording.clone();
    match ExportJob::start(recording, request.format, options, target) {
        Ok(job) => {
            replay.export = Some(job);
            replay.export_result = None;
        }
        Err(error) => replay.export_result = Some(Err(error)),
    }
}

fn start_verify(replay: &mut Replay) {
    let Some(open) = &replay.open else { return };
    if replay.verifying.is_some() {
        return;
    }
    match VerifyJob::start(open.recording.clone()) {
        Ok(job) => {
            replay.verdict = None;
            replay.rules_verdict = None;
            replay.verifying = Some(job);
        }
        Err(error) => replay.verdict = Some(Err(error)),
    }
}

/// Collects a finished export's outcome, and a finished verification's verdict if it is still
/// about the open recording.
fn collect_finished_jobs(replay: &mut Replay) {
    if let Some(job) = replay.export.take_if(|job| job.is_finished()) {
        replay.export_result = Some(job.finish());
    }
    if let Some(job) = replay.verifying.take_if(|job| job.is_finished()) {
        let still_open = replay
            .open
            .as_ref()
            .is_some_and(|open| job.checks(&open.recording));
        let verdict = job.finish();
        if still_open {
            // The rules' verdicts are re-judged from the recorded events (a few ms).
            replay.rules_verdict = replay.open.as_ref().and_then(|o| o.check_verdicts());
            replay.verdict = Some(verdict);
        }
    }
}

/// The timeline's keys. Space: play or pause; Left/Right: previous/next event; Page Up/Down:
/// previous/next shot; Esc: close the replay.
/// Headless apps have no keyboard (`Option`).
fn replay_keys(
    keys: Option<Res<ButtonInput<KeyCode>>>,
    mut commands: MessageWriter<ReplayCommand>,
) {
    let Some(keys) = keys else { return };
    let bindings = [
        (KeyCode::Space, ReplayCommand::TogglePlay),
        (KeyCode::ArrowLeft, ReplayCommand::PreviousEvent),
        (KeyCode::ArrowRight, ReplayCommand::NextEvent),
        (KeyCode::PageUp, ReplayCommand::PreviousShot),
        (KeyCode::PageDown, ReplayCommand::NextShot),
        (KeyCode::Escape, ReplayCommand::Close),
    ];
    for (key, command) in bindings {
        if keys.just_pressed(key) {
            commands.write(command);
        }
    }
}
