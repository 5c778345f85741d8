//! `--screenshot PATH`: wait until the scene has really been drawn, save it, exit.
//!
//! On a software renderer shader pipelines compile for seconds, and until they have, frames
//! come out blank. Once every pipeline has been ready ([`crate::view::pipelines`]; and no new one has
//! appeared) for the settle time and for [`SETTLE_FRAMES`] frames, the primary window is
//! captured: the frame count, not the clock, is what a loaded machine cannot cut short. The process exits with status 0 once the PNG
//! is written, 1 if it could not be, and 3 if the scene never became ready.

use std::{path::PathBuf, time::Duration};

use bevy::{
    prelude::*,
    render::view::screenshot::{Screenshot, ScreenshotCaptured, save_to_disk},
    winit::WinitSettings,
};

use crate::view::pipelines::PipelineProgress;

/// Captures the primary window once the scene is drawn, then exits.
#[derive(Debug, Clone)]
pub struct ScreenshotPlugin {
    /// Where the PNG goes.
    pub path: PathBuf,
    /// How long every pipeline must have been ready before the capture.
    pub settle: Duration,
}

/// While set, the capture waits: something asked at launch is still under way (a launch
/// script's moves, `crate::play::script`).
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CaptureHeld(pub bool);

/// Frames drawn with every pipeline ready before the capture: the first such frame can still
/// lack egui's new glyphs (one more frame after a texture change, [`crate::ui`]), and the swap
/// chain may lag a frame.
pub const SETTLE_FRAMES: u32 = 4;

/// Give up if the pipelines are still compiling after this long.
const TIMEOUT: Duration = Duration::from_secs(180);

impl Plugin for ScreenshotPlugin {
    fn build(&self, app: &mut App) {
        // Keep updating even though nothing moves and the window may be unfocused.
        app.insert_resource(WinitSettings::continuous())
            .init_resource::<CaptureHeld>()
            .insert_resource(Capture {
                path: self.path.clone(),
                settle: self.settle,
                phase: CapturePhase::WaitingForPipelines {
                    ready_since: None,
                    ready_frames: 0,
                    pipelines: 0,
                },
            })
            .add_systems(Update, capture_when_drawn);
    }
}

#[derive(Resource, Debug)]
struct Capture {
    path: PathBuf,
    settle: Duration,
    phase: CapturePhase,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum CapturePhase {
    /// Watching the pipeline counts; `ready_since` is when they last became all ready, and
    /// `ready_frames` how many frames have run since.
    WaitingForPipelines {
        ready_since: Option<Duration>,
        ready_frames: u32,
        pipelines: usize,
    },
    /// The screenshot has been requested; the observer exits when it is saved.
    Requested,
}

fn capture_when_drawn(
    mut commands: Commands,
    time: Res<Time<Real>>,
    progress: Res<PipelineProgress>,
    mut capture: ResMut<Capture>,
    held: Res<CaptureHeld>,
    mut exit: MessageWriter<AppExit>,
) {
    let CapturePhase::WaitingForPipelines {
        ready_since,
        ready_frames,
        pipelines,
    } = capture.phase
    else {
        return;
    };
    let now = time.elapsed();
    let (total, waiting) = progress.counts();
    // A new pipeline appearing restarts the wait: it may belong to something not yet drawn.
    let ready = total > 0 && waiting == 0 && total == pipelines && !held.0;
    let (ready_since, ready_frames) = if ready {
        (ready_since.or(Some(now)), ready_frames + 1)
    } else {
        (None, 0)
    };
    if let Some(since) = ready_since
        && now - since >= capture.settle
        && ready_frames > SETTLE_FRAMES
    {
        info!(
            "{total} pipelines ready for {:.1} s and {ready_frames} frames after {:.1} s: \
             capturing {}",
            (now - since).as_secs_f64(),
            now.as_secs_f64(),
            capture.path.display()
        );
        let path = capture.path.clone();
        // A file left by an earlier run must not pass for this run's capture.
        if let Err(error) = std::fs::remove_file(&path)
            && error.kind() != std::io::ErrorKind::NotFound
        {
            warn!("could not remove the old {}: {error}", path.display());
        }
        let mut save = save_to_disk(path.clone());
        commands.spawn(Screenshot::primary_window()).observe(
            move |captured: On<ScreenshotCaptured>, mut exit: MessageWriter<AppExit>| {
                // Bevy's saver logs its own errors; whether the file exists decides the
                // exit status.
                save(captured);
                let written = std::fs::metadata(&path).is_ok_and(|m| m.len() > 0);
                exit.write(if written {
                    AppExit::Success
                } else {
                    error!("screenshot {} was not written", path.display());
                    AppExit::error()
                });
            },
        );
        capture.phase = CapturePhase::Requested;
        return;
    }
    if now > TIMEOUT {
        if held.0 {
            error!("the launch script still waits after {TIMEOUT:?}: giving up");
        } else {
            error!(
                "render pipelines still compiling after {TIMEOUT:?} ({waiting} of {total}): \
                 giving up"
            );
        }
        exit.write(AppExit::from_code(3));
        return;
    }
    capture.phase = CapturePhase::WaitingForPipelines {
        ready_since,
        ready_frames,
        pipelines: total,
    };
}
