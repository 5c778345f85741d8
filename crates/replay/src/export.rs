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
    // Players show a GIF delay under 2 cs as 10 cs: a faster GIF would play slowly.
    if opts.fps > GIF_MAX_FPS {
        return Err(ExportError::Options(format!(
            "fps {} is above {GIF_MAX_FPS} a GIF can play (delays under 2 cs are shown as \
             10 cs); use a lower frame rate or PNG frames",
            opts.fps
        )));
    }
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

/// The highest frame rate a GIF plays at its speed: 2 cs a frame.
pub const GIF_MAX_FPS: f64 = 50.0;

/// The delay of GIF frame `k` at `fps`, in the format's hundredths of a second: the rounded
/// end time of the frame minus the rounded start, so the delays alternate where `100 / fps` is
/// not whole (3, 3, 4 cs at 30 fps) and the animation keeps real time; a constant rounded
/// delay played 30 fps 11 % fast.
pub fn gif_delay(fps: f64, k: usize) -> u16 {
    let at = |k: usize| (k as f64 * 100.0 / fps).round();
    (at(k + 1) - at(k)).max(1.0) as u16
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
    let n = prepared.each(progress, |k, f| {
        let mut frame = gif::Frame::from_rgb_speed(w, h, &f.rgb, 10);
        frame.delay = gif_delay(opts.fps, k);
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

/// Writes a video of the recording for sharing: MP4 (H.264), or WebM (VP9) when `out` ends
/// in `.webm`, the same frames as the GIF at any frame rate, encoded by the `ffmpeg` found on
/// the PATH (or named by `BILLIARDS_FFMPEG`). A missing `ffmpeg` is a clear error, and the
/// file appears only once it is complete.
pub fn video(
    rec: &Recording,
    opts: &ExportOptions,
    out: &Path,
    progress: Progress,
) -> Result<usize, ExportError> {
    let program = std::env::var_os("BILLIARDS_FFMPEG").unwrap_or_else(|| "ffmpeg".into());
    video_with(Path::new(&program), rec, opts, out, progress)
}

/// [`video`] with the encoder program given.
pub fn video_with(
    program: &Path,
    rec: &Recording,
    opts: &ExportOptions,
    out: &Path,
    progress: Progress,
) -> Result<usize, ExportError> {
    use std::process::{Command, Stdio};
    let prepared = Prepared::new(rec, opts)?;
    let webm = out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("webm"));
    let (container, codec): (&str, &[&str]) = if webm {
        ("webm", &["-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "32"])
    } else {
        // yuv420p: what every player decodes; it needs even sides, hence the pad.
        (
            "mp4",
            &["-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20"],
        )
    };
    let name = out
        .file_name()
        .map_or_else(|| "export".into(), |n| n.to_string_lossy().into_owned());
    let part = out.with_file_name(format!(".{name}.part"));
    let mut child = Command::new(program)
        .args(["-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo"])
        .args(["-pix_fmt", "rgb24", "-s"])
        .arg(format!("{}x{}", opts.width, opts.height))
        .arg("-r")
        .arg(opts.fps.to_string())
        .args(["-i", "-", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"])
        .args(codec)
        .args(["-f", container])
        .arg(&part)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| match e.kind() {
            std::io::ErrorKind::NotFound => ExportError::Encode(format!(
                "{} not found: install ffmpeg (Debian: apt-get install ffmpeg) or set \
                 BILLIARDS_FFMPEG, or export a GIF or PNG frames",
                program.display()
            )),
            _ => ExportError::Encode(format!("{}: {e}", program.display())),
        })?;
    let mut stdin = child.stdin.take().expect("piped stdin");
    let written = prepared.each(progress, |_, f| {
        stdin
            .write_all(&f.rgb)
            .map_err(|e| ExportError::Encode(format!("{} stopped reading: {e}", program.display())))
    });
    drop(stdin);
    let output = child
        .wait_with_output()
        .map_err(|e| ExportError::Encode(format!("{}: {e}", program.display())));
    let result = written.and_then(|n| {
        let output = output?;
        if !output.status.success() {
            let says = String::from_utf8_lossy(&output.stderr);
            return Err(ExportError::Encode(format!(
                "{} failed ({}): {}",
                program.display(),
                output.status,
                says.trim()
            )));
        }
        std::fs::rename(&part, out).map_err(|e| ExportError::Io(out.to_path_buf(), e))?;
        Ok(n)
    });
    if result.is_err() {
        std::fs::remove_file(&part).ok();
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A GIF keeps real time: its delays add up to the frames' span to the hundredth of a
    /// second, at frame rates whose frame time is not whole in hundredths (the old constant
    /// 3 cs played 30 fps 11 % fast).
    #[test]
    fn gif_delays_add_up_to_real_time() {
        for fps in [30.0, 24.0, 25.0, 15.0, 50.0, 12.5] {
            for frames in [1usize, 7, 30, 301] {
                let total: u32 = (0..frames).map(|k| u32::from(gif_delay(fps, k))).sum();
                let want = frames as f64 * 100.0 / fps;
                assert!(
                    (f64::from(total) - want).abs() <= 0.5,
                    "{fps} fps, {frames}: {total}"
                );
            }
        }
        assert_eq!(
            (0..3).map(|k| gif_delay(30.0, k)).collect::<Vec<_>>(),
            [3, 4, 3]
        );
    }
}
