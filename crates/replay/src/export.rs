//! Exports of a recording as an animated GIF or a numbered PNG sequence, timed by simulated
//! time (frame k shows the exact state at `start + k / fps`), so the animation is smooth
//! however slowly it is rendered.

use crate::render::{self, Frame};
use billiards_physics::recording::Recording;
use std::io::{BufWriter, Write};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};

/// Told (frames done, frames in all) after each frame; `ControlFlow::Break` cancels the
/// export.
pub type Progress<'a> = &'a mut dyn FnMut(usize, usize) -> ControlFlow<()>;

/// What to export.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExportOptions {
    /// Frames per second of simulated time.
    pub fps: f64,
    /// Frame width, pixels.
    pub width: u32,
    /// Frame height, pixels.
    pub height: u32,
    /// Simulated time span to export, seconds.
    pub span: (f64, f64),
}

/// Why an export failed.
#[derive(Debug)]
pub enum ExportError {
    /// Bad options (fps, size, span).
    Options(String),
    /// The recording's history could not be rebuilt.
    Recording(String),
    /// Writing failed.
    Io(PathBuf, std::io::Error),
    /// The encoder failed.
    Encode(String),
    /// Cancelled after this many frames (a GIF is then not written at all; the PNG frames
    /// written so far stay).
    Cancelled(usize),
}

impl std::fmt::Display for ExportError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ExportError::Options(s) => write!(f, "bad export options: {s}"),
            ExportError::Recording(s) => write!(f, "recording: {s}"),
            ExportError::Io(p, e) => write!(f, "{}: {e}", p.display()),
            ExportError::Encode(s) => write!(f, "encoding: {s}"),
            ExportError::Cancelled(done) => write!(f, "cancelled after {done} frames"),
        }
    }
}

impl std::error::Error for ExportError {}

impl ExportOptions {
    fn check(&self) -> Result<usize, ExportError> {
        let (a, b) = self.span;
        if !(self.fps.is_finite() && self.fps > 0.0 && self.fps <= 240.0) {
            return Err(ExportError::Options(format!(
                "fps {} must be in (0, 240]",
                self.fps
            )));
        }
        if !(16..=4096).contains(&self.width) || !(16..=4096).contains(&self.height) {
            return Err(ExportError::Options(format!(
                "size {}x{} must be 16..4096 each way",
                self.width, self.height
            )));
        }
        if !(a.is_finite() && b.is_finite() && a >= 0.0 && b >= a) {
            return Err(ExportError::Options(format!(
                "time span {a}..{b} is not a span of simulated time"
            )));
        }
        Ok(((b - a) * self.fps).floor() as usize + 1)
    }
}

/// An export checked and ready to render: its frame count and the recording's history.
struct Prepared<'a> {
    rec: &'a Recording,
    opts: &'a ExportOptions,
    count: usize,
    history: billiards_physics::History,
    numbers: Vec<u8>,
}

impl<'a> Prepared<'a> {
    fn new(rec: &'a Recording, opts: &'a ExportOptions) -> Result<Self, ExportError> {
        let count = opts.check()?;
        let history = rec.history().map_err(ExportError::Recording)?;
        let numbers = rec.balls.iter().map(|b| b.number).collect();
        Ok(Self {
            rec,
            opts,
            count,
            history,
            numbers,
        })
    }

    /// Frame `k`: the exact state at `start + k / fps`.
    fn frame(&self, k: usize) -> Frame {
        let t = self.opts.span.0 + k as f64 / self.opts.fps;
        render::draw(
            &self.rec.table,
            self.rec.params.ball.radius,
            &self.history.states_at(t),
            &self.numbers,
            self.opts.width,
            self.opts.height,
        )
    }

    /// Renders the frames one at a time into `sink` (so a long export never holds them all),
    /// calling `progress` with (done, total) after each and stopping when it says so.
    fn each(
        &self,
        progress: Progress,
        mut sink: impl FnMut(usize, Frame) -> Result<(), ExportError>,
    ) -> Result<usize, ExportError> {
        for k in 0..self.count {
            sink(k, self.frame(k))?;
            if progress(k + 1, self.count).is_break() {
                return Err(ExportError::Cancelled(k + 1));
            }
        }
        Ok(self.count)
    }
}

/// The frames of an export, each sampled exactly from the recording's history; `progress`
/// is told (done, total) and may cancel.
pub fn frames(
    rec: &Recording,
    opts: &ExportOptions,
    progress: Progress,
) -> Result<Vec<Frame>, ExportError> {
    let prepared = Prepared::new(rec, opts)?;
    let mut frames = Vec::with_capacity(prepared.count);
    prepared.each(progress, |_, f| {
        frames.push(f);
        Ok(())
    })?;
    Ok(frames)
}

/// Writes an animated GIF, encoding each frame as soon as it is rendered. The frames go to a
/// temporary file next to `out`, renamed over it once complete: a failed or cancelled export
/// leaves no truncated GIF (and an earlier file at `out` untouched).
pub fn gif(
    rec: &Recording,
    opts: &ExportOptions,
    out: &Path,
    progress: Progress,
) -> Result<usize, ExportError> {
    let prepared = Prepared::new(rec, opts)?;
    let name = out
        .file_name()
        .map_or_else(|| "export.gif".into(), |n| n.to_string_lossy().into_owned());
    let part = out.with_file_name(format!(".{name}.part"));
    let written = write_gif(&prepared, opts, &part, progress).and_then(|n| {
        std::fs::rename(&part, out).map_err(|e| ExportError::Io(out.to_path_buf(), e))?;
        Ok(n)
    });
    if written.is_err() {
        // Nothing to keep of a partial file; it may not even exist.
        std::fs::remove_file(&part).ok();
    }
    written
}

fn write_gif(
    prepared: &Prepared,
    opts: &ExportOptions,
    path: &Path,
    progress: Progress,
) -> Result<usize, ExportError> {
    let io = |e| ExportError::Io(path.to_path_buf(), e);
    let file = std::fs::File::create(path).map_err(io)?;
    let (w, h) = (opts.width as u16, opts.height as u16);
    let mut enc = gif::Encoder::new(BufWriter::new(file), w, h, &[])
        .map_err(|e| ExportError::Encode(e.to_string()))?;
    enc.set_repeat(gif::Repeat::Infinite)
        .map_err(|e| ExportError::Encode(e.to_string()))?;
    // GIF delays are in hundredths of a second.
    let delay = (100.0 / opts.fps).round().max(1.0) as u16;
    let n = prepared.each(progress, |_, f| {
        let mut frame = gif::Frame::from_rgb_speed(w, h, &f.rgb, 10);
        frame.delay = delay;
        enc.write_frame(&frame)
            .map_err(|e| ExportError::Encode(e.to_string()))
    })?;
    // The trailer, then every byte on disk before the rename.
    let mut file = enc
        .into_inner()
        .map_err(|e| ExportError::Encode(e.to_string()))?;
    file.flush().map_err(io)?;
    file.get_ref().sync_all().map_err(io)?;
    Ok(n)
}

/// Writes `frame_00000.png`, `frame_00001.png`, ... into `dir`, each as soon as it is
/// rendered.
pub fn png_sequence(
    rec: &Recording,
    opts: &ExportOptions,
    dir: &Path,
    progress: Progress,
) -> Result<usize, ExportError> {
    let prepared = Prepared::new(rec, opts)?;
    std::fs::create_dir_all(dir).map_err(|e| ExportError::Io(dir.to_path_buf(), e))?;
    prepared.each(progress, |k, f| {
        write_png(&f, &dir.join(format!("frame_{k:05}.png")))
    })
}

/// Writes one frame as a PNG.
pub fn write_png(f: &Frame, path: &Path) -> Result<(), ExportError> {
    let io = |e| ExportError::Io(path.to_path_buf(), e);
    let file = std::fs::File::create(path).map_err(io)?;
    let mut enc = png::Encoder::new(BufWriter::new(file), f.width, f.height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut w = enc
        .write_header()
        .map_err(|e| ExportError::Encode(e.to_string()))?;
    w.write_image_data(&f.rgb)
        .map_err(|e| ExportError::Encode(e.to_string()))
}
