//! The replay viewer: a recording opened from the recordings folder, a typed path, a file
//! dropped on the window or `billiards replay FILE`, shown on the table exactly as recorded.
//!
//! While a recording is open the game is in [`AppMode::Replay`]:
//! - the live solver does not advance and takes no commands (the simulation's system sets
//!   [`SimSystems`] do not run; the cue's input is off), so the live game waits untouched;
//! - the live ball entities are shelved (hidden, their [`Ball`] component put aside) and one
//!   [`ReplayBall`] entity per recorded ball shows the recording at the replay time;
//! - positions and pockets are sampled exactly from the recording's [`History`] (no
//!   re-simulation) and written to the same [`BallMotion`] / [`Pocketed`] components the live
//!   game uses, so balls roll and drop into pockets as in play.
//!
//! Closing the replay despawns those entities, gives the live balls their components back and
//! re-syncs them from the live [`Solver`]. A rack request while replaying closes the replay
//! first.
//!
//! Everything is driven by [`ReplayCommand`] messages, applied by one exclusive system in
//! [`PreUpdate`]; the egui parts in [`panel`] only read [`Replay`] and write commands, so the
//! logic runs (and is tested) headless.

pub mod panel;

use std::{
    path::{Path, PathBuf},
    sync::{
        Arc,
        atomic::{AtomicBool, AtomicUsize, Ordering},
    },
    thread::JoinHandle,
};

use bevy::{
    camera::visibility::VisibilitySystems,
    prelude::*,
    window::{FileDragAndDrop, RequestRedraw},
};
use billiards_physics::{
    BallState, Cushion, Event, EventKind, History, Motion, Pocket,
    recording::{Action, Recording, Verdict},
};
use billiards_replay::export::{self, ExportOptions};

use crate::{
    balls::{Ball, BallMotion, Pocketed},
    cue::CueStick,
    geometry::TableSpec,
    sim::{RackRequested, SimSystems, Solver, ball_motion},
};

/// Registers the replay logic (headless: no egui, no window needed; see [`panel::plugin`] for
/// the widgets).
pub fn plugin(app: &mut App) {
    app.init_resource::<AppMode>()
        .init_resource::<Replay>()
        .add_message::<ReplayCommand>()
        .add_message::<FileDragAndDrop>()
        .add_message::<RequestRedraw>()
        .configure_sets(Update, SimSystems::Step.run_if(playing))
        .configure_sets(Update, SimSystems::Flow.run_if(playing))
        .configure_sets(Update, SimSystems::Commands.run_if(playing))
        .add_systems(
            PreUpdate,
            (open_dropped_files, close_on_rack, apply_replay)
                .chain()
                .in_set(ReplaySystems),
        )
        .add_systems(
            PostUpdate,
            (
                restore_transforms.before(TransformSystems::Propagate),
                hide_cue_while_replaying.before(VisibilitySystems::VisibilityPropagate),
            ),
        );
}

/// The replay systems in [`PreUpdate`]: commands applied, the replay clock advanced, the
/// recorded state written to the balls.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ReplaySystems;

/// Whether the table shows the live game or a recording.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AppMode {
    /// The live game: the solver runs, the cue takes input.
    #[default]
    Play,
    /// A recording is open: the live game waits.
    Replay,
}

/// Run condition: the live game is on (no recording open).
pub fn playing(mode: Option<Res<AppMode>>) -> bool {
    mode.is_none_or(|mode| *mode == AppMode::Play)
}

/// Run condition: a recording is open.
pub fn replaying(mode: Option<Res<AppMode>>) -> bool {
    !playing(mode)
}

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
}

/// What an export writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ExportFormat {
    /// One animated GIF file.
    #[default]
    Gif,
    /// A folder of numbered PNG files.
    PngSequence,
}

/// Which part of the recording an export covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ExportScope {
    /// The shot under the replay time: from its strike to the next (or the end).
    #[default]
    CurrentShot,
    /// Everything from the rack to the end.
    WholeGame,
}

/// An export of the open recording.
#[derive(Debug, Clone, PartialEq)]
pub struct ExportRequest {
    /// GIF or PNG sequence.
    pub format: ExportFormat,
    /// Current shot or whole game.
    pub scope: ExportScope,
    /// Frames per second of simulated time.
    pub fps: f64,
    /// Frame width, pixels.
    pub width: u32,
    /// Frame height, pixels.
    pub height: u32,
    /// Where to write; `None`: next to the recording ([`OpenRecording::default_export_path`]).
    pub path: Option<PathBuf>,
}

/// Opens this recording once the live game has been racked (`billiards replay FILE`).
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct OpenAtStart(pub PathBuf);

/// Marks the entities that show a recorded ball (despawned when the replay closes).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReplayBall;

/// A recording loaded for replay, with its history rebuilt for exact sampling.
#[derive(Debug)]
pub struct OpenRecording {
    /// The file it was loaded from.
    pub path: PathBuf,
    /// The recording (shared with export threads).
    pub recording: Arc<Recording>,
    /// Every ball's closed-form trajectory, rebuilt from the recorded events.
    pub history: History,
    /// Times of the strikes (the `Strike` inputs), in order: shot `k` (from 1) starts at
    /// `shots[k - 1]`.
    pub shots: Vec<f64>,
    /// Where the replay ends: the recording's end time (or its last event, if later).
    pub end_time: f64,
    entities: Vec<Entity>,
}

impl OpenRecording {
    /// Rebuilds the history of a loaded recording.
    pub fn new(path: &Path, recording: Recording) -> Result<Self, String> {
        let history = recording
            .history()
            .map_err(|error| format!("{}: {error}", path.display()))?;
        let shots = recording
            .inputs
            .iter()
            .filter(|input| matches!(input.action, Action::Strike { .. }))
            .map(|input| input.time)
            .collect();
        let last_event = history.events().last().map_or(0.0, |event| event.time);
        Ok(Self {
            path: path.to_path_buf(),
            end_time: recording.end_time.max(last_event),
            recording: Arc::new(recording),
            history,
            shots,
            entities: Vec::new(),
        })
    }

    /// The events, in time order.
    pub fn events(&self) -> &[Event] {
        self.history.events()
    }

    /// The number printed on recorded ball `id`.
    pub fn number(&self, id: usize) -> u8 {
        self.recording.balls.get(id).map_or(0, |ball| ball.number)
    }

    /// The entity showing recorded ball `id`.
    pub fn entity(&self, id: usize) -> Option<Entity> {
        self.entities.get(id).copied()
    }

    /// The last event at or before `t`, with its index.
    pub fn event_at(&self, t: f64) -> Option<(usize, &Event)> {
        let events = self.events();
        let after = events.partition_point(|event| event.time <= t);
        after.checked_sub(1).map(|i| (i, &events[i]))
    }

    /// The time of the first event after `t`.
    pub fn next_event_time(&self, t: f64) -> Option<f64> {
        let events = self.events();
        events
            .get(events.partition_point(|event| event.time <= t))
            .map(|event| event.time)
    }

    /// The time of the last event before `t`.
    pub fn previous_event_time(&self, t: f64) -> Option<f64> {
        let events = self.events();
        let before = events.partition_point(|event| event.time < t);
        before.checked_sub(1).map(|i| events[i].time)
    }

    /// The shot under `t`, counted from 1 (0 before the first strike).
    pub fn shot_at(&self, t: f64) -> usize {
        self.shots.partition_point(|&start| start <= t)
    }

    /// Simulated time span of shot `k` (from 1): its strike to the next strike or the end.
    pub fn shot_span(&self, k: usize) -> Option<(f64, f64)> {
        let start = *self.shots.get(k.checked_sub(1)?)?;
        let end = self.shots.get(k).copied().unwrap_or(self.end_time);
        Some((start, end))
    }

    /// The time of the first strike after `t`.
    pub fn next_shot_time(&self, t: f64) -> Option<f64> {
        self.shots.iter().copied().find(|&start| start > t)
    }

    /// The time of the last strike before `t`.
    pub fn previous_shot_time(&self, t: f64) -> Option<f64> {
        self.shots.iter().rev().copied().find(|&start| start < t)
    }

    /// The shot an export of `scope` at replay time `t` covers (`None`: the whole game), and
    /// its time span.
    pub fn export_span(&self, scope: ExportScope, t: f64) -> (Option<usize>, (f64, f64)) {
        let whole = (None, (0.0, self.end_time));
        match scope {
            ExportScope::WholeGame => whole,
            ExportScope::CurrentShot => {
                let k = self.shot_at(t).max(1);
                self.shot_span(k).map_or(whole, |span| (Some(k), span))
            }
        }
    }

    /// Where an export goes unless told otherwise: next to the recording, named after it
    /// (`<name>.gif`, `<name>_shot3.gif`, `<name>_frames/`, `<name>_shot3_frames/`).
    pub fn default_export_path(&self, format: ExportFormat, shot: Option<usize>) -> PathBuf {
        let stem = self
            .path
            .file_stem()
            .map_or_else(|| "replay".into(), |stem| stem.to_string_lossy());
        let name = match shot {
            Some(k) => format!("{stem}_shot{k}"),
            None => stem.into_owned(),
        };
        let dir = self.path.parent().unwrap_or(Path::new(""));
        match format {
            ExportFormat::Gif => dir.join(format!("{name}.gif")),
            ExportFormat::PngSequence => dir.join(format!("{name}_frames")),
        }
    }

    /// What happened at an event, with the balls by number (`"ball 3 hit the foot cushion"`).
    pub fn describe(&self, event: &Event) -> String {
        let ball = |id: usize| match self.number(id) {
            0 => "cue ball".to_owned(),
            n => format!("ball {n}"),
        };
        match event.kind {
            EventKind::Strike { ball: id, shot } => format!(
                "strike: {} at {:.1} deg, {:.2} m/s",
                ball(id),
                shot.angle.to_degrees(),
                shot.speed
            ),
            EventKind::Placed { ball: id } => format!("{} placed", ball(id)),
            EventKind::ParamsChanged => "parameters changed".to_owned(),
            EventKind::Transition { ball: id, from, to } => {
                format!(
                    "{}: {} to {}",
                    ball(id),
                    motion_label(from),
                    motion_label(to)
                )
            }
            EventKind::Cushion { ball: id, cushion } => {
                format!("{} hit the {} cushion", ball(id), cushion_label(cushion))
            }
            EventKind::Jaw { ball: id, pocket } => {
                format!(
                    "{} hit a jaw of the {} pocket",
                    ball(id),
                    pocket_label(pocket)
                )
            }
            EventKind::Pocketed { ball: id, pocket } => {
                format!(
                    "{} pocketed in the {} pocket",
                    ball(id),
                    pocket_label(pocket)
                )
            }
            EventKind::BallBall { a, b } => format!("{} hit {}", ball(a), ball(b)),
        }
    }

    /// The outcome of [`Recording::verify`] for the player.
    pub fn verdict_text(&self, verdict: &Result<Verdict, String>) -> String {
        let event = |e: &Option<Box<Event>>| {
            e.as_ref().map_or("nothing".to_owned(), |e| {
                format!("{} at {:.6} s", self.describe(e), e.time)
            })
        };
        match verdict {
            Ok(Verdict::Reproduced { events }) => {
                format!("reproduced bit for bit ({events} events)")
            }
            Ok(Verdict::Differs {
                index,
                recorded,
                replayed,
            }) => format!(
                "differs at event {index}: recorded {}, re-simulated {}",
                event(recorded),
                event(replayed)
            ),
            Err(error) => format!("cannot re-simulate: {error}"),
        }
    }
}

fn cushion_label(cushion: Cushion) -> &'static str {
    match cushion {
        Cushion::Head => "head",
        Cushion::Foot => "foot",
        Cushion::Left => "left",
        Cushion::Right => "right",
    }
}

fn pocket_label(pocket: Pocket) -> &'static str {
    match pocket {
        Pocket::HeadLeft => "head-left corner",
        Pocket::HeadRight => "head-right corner",
        Pocket::SideLeft => "left side",
        Pocket::SideRight => "right side",
        Pocket::FootLeft => "foot-left corner",
        Pocket::FootRight => "foot-right corner",
    }
}

fn motion_label(motion: Motion) -> &'static str {
    match motion {
        Motion::Stationary => "rest",
        Motion::Sliding => "sliding",
        Motion::Rolling => "rolling",
        Motion::Spinning => "spinning in place",
        Motion::Pocketed(_) => "pocketed",
    }
}

/// An export running on its own thread.
#[derive(Debug)]
pub struct ExportJob {
    /// The file or folder being written.
    pub target: PathBuf,
    done: Arc<AtomicUsize>,
    total: Arc<AtomicUsize>,
    /// Set to stop the export after its current frame.
    cancel: Arc<AtomicBool>,
    handle: JoinHandle<Result<usize, String>>,
}

impl ExportJob {
    /// Frames rendered so far and frames in all (0 until the export knows).
    pub fn progress(&self) -> (usize, usize) {
        (
            self.done.load(Ordering::Relaxed),
            self.total.load(Ordering::Relaxed),
        )
    }

    /// Rendered share of the frames, 0 to 1.
    pub fn fraction(&self) -> f32 {
        let (done, total) = self.progress();
        if total == 0 {
            0.0
        } else {
            done as f32 / total as f32
        }
    }
}

/// A live ball put aside while a recording is shown.
#[derive(Debug, Clone, Copy)]
struct ShelvedBall {
    entity: Entity,
    ball: Ball,
    visibility: Visibility,
    transform: Transform,
}

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
    /// The last verification of the open recording.
    pub verdict: Option<Result<Verdict, String>>,
    /// A verification running on its own thread (a long recording takes a while to
    /// re-simulate; the window stays responsive).
    pub verifying: Option<VerifyJob>,
    /// The export in progress.
    pub export: Option<ExportJob>,
    /// How the last export ended: what was written, or why not.
    pub export_result: Option<Result<String, String>>,
    shelf: Vec<ShelvedBall>,
}

impl Default for Replay {
    fn default() -> Self {
        Self {
            open: None,
            time: 0.0,
            playing: false,
            speed: 1.0,
            error: None,
            verdict: None,
            verifying: None,
            export: None,
            export_result: None,
            shelf: Vec::new(),
        }
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
    mode: Res<AppMode>,
    mut replay: MessageWriter<ReplayCommand>,
) {
    if racks.read().count() > 0 && *mode == AppMode::Replay {
        replay.write(ReplayCommand::Close);
    }
}

/// Applies the frame's commands, runs the replay clock and shows the recording at the replay
/// time. Exclusive: it shelves, spawns and despawns balls.
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
        finish_export(&mut replay);
        finish_verify(&mut replay);
        if let Some(open) = &replay.open {
            let end = open.end_time;
            if replay.playing && !moved {
                let time = replay.time + dt.min(MAX_FRAME_SECONDS) * replay.speed;
                replay.time = time.min(end);
                replay.playing = time < end;
            }
            if let Some(mut shown) = world.get_resource_mut::<crate::balls::ShownTime>() {
                shown.0 = replay.time;
            }
            let open = replay.open.as_ref().expect("checked above");
            for (id, &entity) in open.entities.iter().enumerate() {
                show_state(world, entity, &open.history.state_at(id, replay.time));
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
        _ => {}
    }
    let mut replay = world.resource_mut::<Replay>();
    let replay = &mut *replay;
    let Some(open) = &replay.open else {
        return false;
    };
    let time = replay.time;
    let jump = |target: Option<f64>| target.unwrap_or(time);
    match command {
        ReplayCommand::Open(_) | ReplayCommand::Close => unreachable!("handled above"),
        ReplayCommand::Play => {
            if time >= open.end_time {
                replay.time = 0.0;
            }
            replay.playing = true;
            // The clock starts next frame: this frame's delta may span an idle window.
            return true;
        }
        ReplayCommand::Pause => replay.playing = false,
        ReplayCommand::TogglePlay => {
            if !replay.playing && time >= open.end_time {
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
                replay.time = t.clamp(0.0, open.end_time);
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
            replay.time = jump(open.next_shot_time(time));
            return true;
        }
        ReplayCommand::PreviousShot => {
            replay.time = jump(open.previous_shot_time(time));
            return true;
        }
        ReplayCommand::Verify => start_verify(replay),
        ReplayCommand::Export(request) => start_export(replay, request),
        ReplayCommand::CancelExport => {
            if let Some(job) = &replay.export {
                job.cancel.store(true, Ordering::Relaxed);
            }
        }
    }
    false
}

/// Loads a recording and puts it on the table; on failure only [`Replay::error`] changes.
fn open(world: &mut World, path: &Path) {
    let loaded = Recording::load(path)
        .map_err(|error| error.to_string())
        .and_then(|recording| OpenRecording::new(path, recording));
    let mut opened = match loaded {
        Ok(opened) => opened,
        Err(error) => {
            warn!("replay not opened: {error}");
            world.resource_mut::<Replay>().error = Some(error);
            return;
        }
    };
    match world.resource_mut::<Replay>().open.take() {
        Some(previous) => despawn_all(world, &previous.entities),
        None => shelve_live_balls(world),
    }
    opened.entities = spawn_replay_balls(world, &opened);
    let mut replay = world.resource_mut::<Replay>();
    replay.open = Some(opened);
    replay.time = 0.0;
    replay.playing = true;
    replay.error = None;
    replay.verdict = None;
    *world.resource_mut::<AppMode>() = AppMode::Replay;
}

/// Back to the live game, exactly as it was left.
fn close(world: &mut World) {
    let (open, shelf) = {
        let mut replay = world.resource_mut::<Replay>();
        let Some(open) = replay.open.take() else {
            return;
        };
        replay.playing = false;
        replay.time = 0.0;
        replay.verdict = None;
        (open, std::mem::take(&mut replay.shelf))
    };
    despawn_all(world, &open.entities);
    for shelved in shelf {
        let Ok(mut entity) = world.get_entity_mut(shelved.entity) else {
            continue;
        };
        let visibility = if entity.contains::<Pocketed>() {
            Visibility::Hidden
        } else {
            shelved.visibility
        };
        // The ball's look is attached anew (`Added<Ball>`), which turns it number-up; its
        // rotation is put back after that, in `PostUpdate`.
        entity.insert((
            shelved.ball,
            visibility,
            shelved.transform,
            RestoreTransform(shelved.transform),
        ));
    }
    // The live balls were not touched; re-sync them from the solver all the same.
    if world.contains_resource::<Solver>() {
        world.resource_scope(|world, solver: Mut<Solver>| {
            for id in 0..solver.simulation().ball_count() {
                if let Some(entity) = solver.entity(id) {
                    show_state(world, entity, &solver.simulation().ball(id));
                }
            }
        });
    }
    *world.resource_mut::<AppMode>() = AppMode::Play;
    world.write_message(RequestRedraw);
}

/// Hides the live balls and takes their [`Ball`] component away, so every system that works
/// on balls (drawing, the HUD, the camera) sees the recorded ones only.
fn shelve_live_balls(world: &mut World) {
    let live: Vec<ShelvedBall> = world
        .query_filtered::<(Entity, &Ball, &Visibility, &Transform), Without<ReplayBall>>()
        .iter(world)
        .map(|(entity, &ball, &visibility, &transform)| ShelvedBall {
            entity,
            ball,
            visibility,
            transform,
        })
        .collect();
    for shelved in &live {
        world
            .entity_mut(shelved.entity)
            .remove::<Ball>()
            .insert(Visibility::Hidden);
    }
    world.resource_mut::<Replay>().shelf = live;
}

fn spawn_replay_balls(world: &mut World, open: &OpenRecording) -> Vec<Entity> {
    let spec = world.resource::<TableSpec>().clone();
    (0..open.history.ball_count())
        .map(|id| {
            let number = open.number(id);
            let state = open.history.state_at(id, 0.0);
            let motion = ball_motion(&state);
            let mut ball = world.spawn((
                Ball { id, number },
                motion,
                Transform::from_translation(spec.ball_world_position(motion.position)),
                Name::new(format!("Replay ball {number}")),
                ReplayBall,
            ));
            if let Motion::Pocketed(pocket) = state.motion {
                ball.insert((Pocketed { pocket }, Visibility::Hidden));
            }
            ball.id()
        })
        .collect()
}

fn despawn_all(world: &mut World, entities: &[Entity]) {
    for &entity in entities {
        if let Ok(entity) = world.get_entity_mut(entity) {
            entity.despawn();
        }
    }
}

/// Writes a solver state to a ball's components: [`BallMotion`] only when it differs (so
/// balls at rest are not redrawn) and [`Pocketed`] as the state says.
fn show_state(world: &mut World, entity: Entity, state: &BallState) {
    let Ok(mut ball) = world.get_entity_mut(entity) else {
        return;
    };
    let pocket = match state.motion {
        Motion::Pocketed(pocket) => Some(pocket),
        _ => None,
    };
    let was_pocketed = ball.contains::<Pocketed>();
    if let Some(mut motion) = ball.get_mut::<BallMotion>()
        && !motion.set_if_neq(ball_motion(state))
        && was_pocketed
        && pocket.is_none()
    {
        // Back from a pocket where it dropped: drawn at its place again.
        motion.set_changed();
    }
    match (pocket, was_pocketed) {
        (Some(pocket), false) => {
            ball.insert(Pocketed { pocket });
        }
        (None, true) => {
            ball.remove::<Pocketed>();
        }
        _ => {}
    }
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
    let recording = Arc::clone(&open.recording);
    let done = Arc::new(AtomicUsize::new(0));
    let total = Arc::new(AtomicUsize::new(0));
    let cancel = Arc::new(AtomicBool::new(false));
    let (thread_done, thread_total, out) = (done.clone(), total.clone(), target.clone());
    let thread_cancel = cancel.clone();
    let format = request.format;
    let spawned = std::thread::Builder::new()
        .name("replay export".to_owned())
        .spawn(move || {
            let mut progress = |frames_done: usize, frames: usize| {
                thread_total.store(frames, Ordering::Relaxed);
                thread_done.store(frames_done, Ordering::Relaxed);
                if thread_cancel.load(Ordering::Relaxed) {
                    std::ops::ControlFlow::Break(())
                } else {
                    std::ops::ControlFlow::Continue(())
                }
            };
            match format {
                ExportFormat::Gif => export::gif(&recording, &options, &out, &mut progress),
                ExportFormat::PngSequence => {
                    export::png_sequence(&recording, &options, &out, &mut progress)
                }
            }
            .map_err(|error| error.to_string())
        });
    match spawned {
        Ok(handle) => {
            replay.export = Some(ExportJob {
                target,
                done,
                total,
                cancel,
                handle,
            });
            replay.export_result = None;
        }
        Err(error) => replay.export_result = Some(Err(format!("export not started: {error}"))),
    }
}

/// A verification of a recording running on its own thread.
#[derive(Debug)]
pub struct VerifyJob {
    /// The recording it re-simulates (its verdict is dropped if another one is open by then).
    recording: Arc<Recording>,
    handle: JoinHandle<Result<Verdict, String>>,
}

fn start_verify(replay: &mut Replay) {
    let Some(open) = &replay.open else { return };
    if replay.verifying.is_some() {
        return;
    }
    let recording = Arc::clone(&open.recording);
    let thread_recording = Arc::clone(&recording);
    let spawned = std::thread::Builder::new()
        .name("replay verify".to_owned())
        .spawn(move || thread_recording.verify());
    match spawned {
        Ok(handle) => {
            replay.verdict = None;
            replay.verifying = Some(VerifyJob { recording, handle });
        }
        Err(error) => replay.verdict = Some(Err(format!("verification not started: {error}"))),
    }
}

/// Collects a finished verification's verdict, if it is still about the open recording.
fn finish_verify(replay: &mut Replay) {
    let Some(job) = replay.verifying.take_if(|job| job.handle.is_finished()) else {
        return;
    };
    let verdict = job
        .handle
        .join()
        .unwrap_or_else(|_| Err("the verification thread panicked".to_owned()));
    if replay
        .open
        .as_ref()
        .is_some_and(|open| Arc::ptr_eq(&open.recording, &job.recording))
    {
        replay.verdict = Some(verdict);
    }
}

/// Collects a finished export's outcome.
fn finish_export(replay: &mut Replay) {
    let Some(job) = replay.export.take_if(|job| job.handle.is_finished()) else {
        return;
    };
    let result = job
        .handle
        .join()
        .unwrap_or_else(|_| Err("the export thread panicked".to_owned()));
    replay.export_result =
        Some(result.map(|frames| format!("{}: {frames} frames", job.target.display())));
}

/// The transform a live ball had when it was shelved, put back after its look was attached.
#[derive(Component, Debug, Clone, Copy)]
struct RestoreTransform(Transform);

fn restore_transforms(
    mut commands: Commands,
    mut balls: Query<(Entity, &RestoreTransform, &mut Transform)>,
) {
    for (entity, restore, mut transform) in &mut balls {
        *transform = restore.0;
        commands.entity(entity).remove::<RestoreTransform>();
    }
}

/// No cue over a recording.
fn hide_cue_while_replaying(mode: Res<AppMode>, mut cue: Query<&mut Visibility, With<CueStick>>) {
    if *mode == AppMode::Replay {
        for mut visibility in &mut cue {
            visibility.set_if_neq(Visibility::Hidden);
        }
    }
}
