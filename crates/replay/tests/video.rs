//! Video export through an external encoder: exactly the GIF's frames go down the pipe, with
//! the size and frame rate told; a missing or failing encoder is a clear error and leaves no
//! file. A stand-in `ffmpeg` (a shell script) takes the real one's place, so the test needs
//! none installed.

use billiards_physics::recording::{Recorder, Recording};
use billiards_physics::*;
use billiards_replay::export::{self, ExportError, ExportOptions};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

/// Held by each test for its whole body. Writing the stand-in script while the other test
/// forks its encoder lets the child inherit the script's write descriptor until its exec, and
/// running the script then fails with ETXTBSY ("Text file busy"): 6 runs in 300 did before.
static SPAWNS: Mutex<()> = Mutex::new(());

fn one_at_a_time() -> MutexGuard<'static, ()> {
    // A test that failed while holding it leaves it poisoned; the next still runs alone.
    SPAWNS.lock().unwrap_or_else(|e| e.into_inner())
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("billiards-video-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn recording() -> Recording {
    let table = Table::wpa_8ft();
    let params = Params::default();
    let mut rec =
        Recorder::new(table, params, Rack::NineBall.layout(&table, &params.ball)).unwrap();
    rec.strike(0, Shot::new(0.0, 6.0)).unwrap();
    rec.run_to_rest().unwrap();
    rec.recording()
}

const OPTS: ExportOptions = ExportOptions {
    fps: 10.0,
    width: 101,
    height: 60,
    span: (0.0, 0.5),
};

/// A stand-in encoder: writes its arguments to `args.txt` and what it reads to the output
/// file (its last argument); exits with `code`.
fn fake_ffmpeg(dir: &Path, code: i32) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let script = dir.join("ffmpeg");
    let args = dir.join("args.txt");
    std::fs::write(
        &script,
        format!(
            "#!/bin/sh\necho \"$@\" > '{}'\nfor last; do :; done\ncat > \"$last\"\nexit {code}\n",
            args.display()
        ),
    )
    .unwrap();
    std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o755)).unwrap();
    script
}

#[cfg(unix)]
#[test]
fn the_encoder_gets_every_frame_with_its_size_and_rate() {
    let _alone = one_at_a_time();
    let dir = temp("ok");
    let program = fake_ffmpeg(&dir, 0);
    let out = dir.join("break.mp4");
    let n = export::video_with(&program, &recording(), &OPTS, &out, &mut |_, _| {
        ControlFlow::Continue(())
    })
    .unwrap();
    // 0 to 0.5 s at 10 fps: six frames of 101 x 60 RGB.
    assert_eq!(n, 6);
    assert_eq!(std::fs::metadata(&out).unwrap().len(), 6 * 101 * 60 * 3);
    let args = std::fs::read_to_string(dir.join("args.txt")).unwrap();
    assert!(
        args.contains("-s 101x60") && args.contains("-r 10"),
        "{args}"
    );
    assert!(
        args.contains("libx264") && args.contains("-f mp4"),
        "{args}"
    );
    // WebM by its extension.
    let webm = dir.join("break.webm");
    export::video_with(&program, &recording(), &OPTS, &webm, &mut |_, _| {
        ControlFlow::Continue(())
    })
    .unwrap();
    let args = std::fs::read_to_string(dir.join("args.txt")).unwrap();
    assert!(
        args.contains("libvpx-vp9") && args.contains("-f webm"),
        "{args}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[cfg(unix)]
#[test]
fn a_missing_or_failing_encoder_is_a_clear_error_and_leaves_no_file() {
    let _alone = one_at_a_time();
    let dir = temp("err");
    let out = dir.join("break.mp4");
    let missing = dir.join("no-such-ffmpeg");
    match export::video_with(&missing, &recording(), &OPTS, &out, &mut |_, _| {
        ControlFlow::Continue(())
    }) {
        Err(ExportError::Encode(text)) => {
            assert!(
                text.contains("not found") && text.contains("ffmpeg"),
                "{text}"
            )
        }
        other => panic!("expected a clear error, got {other:?}"),
    }
    let failing = fake_ffmpeg(&dir, 3);
    let result = export::video_with(&failing, &recording(), &OPTS, &out, &mut |_, _| {
        ControlFlow::Continue(())
    });
    assert!(
        matches!(&result, Err(ExportError::Encode(text)) if text.contains("failed")),
        "{result:?}"
    );
    assert!(!out.exists());
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        2,
        "only the script and its log"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
