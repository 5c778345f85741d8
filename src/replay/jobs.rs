//! The replay's background jobs: an export (GIF, PNG sequence or MP4) and a verification, each on
//! its own thread so a long recording never freezes the window. The viewer starts them, polls
//! [`ExportJob::is_finished`] / [`VerifyJob::is_finished`] each frame and collects the result.

use std::{
    ops::ControlFlow,
    path::PathBuf,
    sync::{
        Arc,
        atomic::{AtomicBool, AtomicUsize, Ordering},
    },
    thread::JoinHandle,
};

use billiards_physics::recording::{Recording, Verdict};
use billiards_replay::export::{self, ExportOptions};

/// What an export writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ExportFormat {
    /// One animated GIF file.
    #[default]
    Gif,
    /// A folder of numbered PNG files.
    PngSequence,
    /// An MP4 video for sharing, encoded by the `ffmpeg` on the PATH.
    Video,
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
    /// GIF, PNG sequence or MP4.
    pub format: ExportFormat,
    /// Current shot or whole game.
    pub scope: ExportScope,
    /// Frames per second of simulated time.
    pub fps: f64,
    /// Frame width, pixels.
    pub width: u32,
    /// Frame height, pixels.
    pub height: u32,
    /// Where to write; `None`: next to the recording
    /// ([`super::OpenRecording::default_export_path`]).
    pub path: Option<PathBuf>,
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
    /// Starts writing `span` of `recording` to `target` on a new thread.
    pub fn start(
        recording: Arc<Recording>,
        format: ExportFormat,
        options: ExportOptions,
        target: PathBuf,
    ) -> Result<Self, String> {
        let done = Arc::new(AtomicUsize::new(0));
        let total = Arc::new(AtomicUsize::new(0));
        let cancel = Arc::new(AtomicBool::new(false));
        let (thread_done, thread_total, out) = (done.clone(), total.clone(), target.clone());
        let thread_cancel = cancel.clone();
        let handle = std::thread::Builder::new()
            .name("replay export".to_owned())
            .spawn(move || {
                let mut progress = |frames_done: usize, frames: usize| {
                    thread_total.store(frames, Ordering::Relaxed);
                    thread_done.store(frames_done, Ordering::Relaxed);
                    if thread_cancel.load(Ordering::Relaxed) {
                        ControlFlow::Break(())
                    } else {
                        ControlFlow::Continue(())
                    }
                };
                match format {
                    ExportFormat::Gif => export::gif(&recording, &options, &out, &mut progress),
                    ExportFormat::PngSequence => {
                        export::png_sequence(&recording, &options, &out, &mut progress)
                    }
                    ExportFormat::Video => export::video(&recording, &options, &out, &mut progress),
                }
                .map_err(|error| error.to_string())
            })
            .map_err(|error| format!("export not started: {error}"))?;
        Ok(Self {
            target,
            done,
            total,
            cancel,
            handle,
        })
    }

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

    /// Asks the export to stop after the frame it is on.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Whether the thread has ended (then [`ExportJob::finish`] does not block).
    pub fn is_finished(&self) -> bool {
        self.handle.is_finished()
    }

    /// What was written (`"<target>: N frames"`), or why not.
    pub fn finish(self) -> Result<String, String> {
        let frames = self
            .handle
            .join()
            .unwrap_or_else(|_| Err("the export thread panicked".to_owned()))?;
        Ok(format!("{}: {frames} frames", self.target.display()))
    }
}

/// A verification of a recording running on its own thread.
#[derive(Debug)]
pub struct VerifyJob {
    /// The recording it re-simulates (its verdict is dropped if another one is open by then).
    recording: Arc<Recording>,
    handle: JoinHandle<Result<Verdict, String>>,
}

impl VerifyJob {
    /// Starts re-simulating `recording` on a new thread.
    pub fn start(recording: Arc<Recording>) -> Result<Self, String> {
        let thread_recording = Arc::clone(&recording);
        let handle = std::thread::Builder::new()
            .name("replay verify".to_owned())
            .spawn(move || thread_recording.verify())
            .map_err(|error| format!("verification not started: {error}"))?;
        Ok(Self { recording, handle })
    }

    /// Whether this job checks `recording` (the same shared recording, not an equal copy).
    pub fn checks(&self, recording: &Arc<Recording>) -> bool {
        Arc::ptr_eq(&self.recording, recording)
    }

    /// Whether the thread has ended (then [`VerifyJob::finish`] does not block).
    pub fn is_finished(&self) -> bool {
        self.handle.is_finished()
    }

    /// The verdict.
    pub fn finish(self) -> Result<Verdict, String> {
        self.handle
            .join()
            .unwrap_or_else(|_| Err("the verification thread panicked".to_owned()))
    }
}
