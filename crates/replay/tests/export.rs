//! The exports (GIF, PNG sequence), end to end: frames, timing, cancellation, bad options.

mod common;

use billiards_replay::export::{self, ExportOptions};
use common::*;
use std::ops::ControlFlow;

#[test]
fn exported_gif_frames_show_the_balls_moving() {
    let rec = break_recording();
    let dir = temp("gif");
    let out = dir.join("break.gif");
    let opts = ExportOptions {
        fps: 10.0,
        width: 200,
        height: 110,
        span: (0.0, 1.0),
    };
    let n = export::gif(&rec, &opts, &out, &mut |_, _| ControlFlow::Continue(())).unwrap();
    assert_eq!(n, 11);
    // Decode and compare: between the first and the sixth frame (0.5 s into a 9 m/s break)
    // the cue ball and the rack have moved, so many pixels changed; the background did not.
    let mut dec = gif::DecodeOptions::new();
    dec.set_color_output(gif::ColorOutput::RGBA);
    let mut d = dec.read_info(std::fs::File::open(&out).unwrap()).unwrap();
    let mut frames = Vec::new();
    while let Some(f) = d.read_next_frame().unwrap() {
        frames.push(f.buffer.to_vec());
    }
    assert_eq!(frames.len(), 11);
    let changed = frames[0]
        .chunks(4)
        .zip(frames[5].chunks(4))
        .filter(|(a, b)| a != b)
        .count();
    assert!(changed > 50, "only {changed} pixels changed");
    assert!(
        changed < 200 * 110 / 4,
        "{changed} pixels changed: more than the balls"
    );
    let white = |f: &Vec<u8>| {
        f.chunks(4)
            .filter(|p| p[0] > 220 && p[1] > 220 && p[2] > 200)
            .count()
    };
    assert!(white(&frames[0]) > 0, "the cue ball is drawn");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn png_sequence_is_numbered_and_timed_by_simulated_time() {
    let rec = break_recording();
    let dir = temp("png");
    let opts = ExportOptions {
        fps: 4.0,
        width: 64,
        height: 40,
        span: (0.0, 2.0),
    };
    let n = export::png_sequence(&rec, &opts, &dir, &mut |_, _| ControlFlow::Continue(())).unwrap();
    assert_eq!(n, 9);
    assert!(dir.join("frame_00008.png").exists() && !dir.join("frame_00009.png").exists());
    std::fs::remove_dir_all(dir).ok();
}

/// A cancelled GIF export stops at once, says after how many frames, and leaves neither a
/// truncated GIF nor its temporary file; an earlier complete GIF at the same path survives.
#[test]
fn cancelled_gif_export_leaves_no_partial_file() {
    let rec = break_recording();
    let dir = temp("cancel-gif");
    let out = dir.join("break.gif");
    let opts = ExportOptions {
        fps: 10.0,
        width: 64,
        height: 40,
        span: (0.0, 2.0),
    };
    let mut calls = 0;
    let mut stop_at_3 = |done: usize, _| {
        calls += 1;
        if done == 3 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    match export::gif(&rec, &opts, &out, &mut stop_at_3) {
        Err(export::ExportError::Cancelled(3)) => {}
        other => panic!("expected a cancel after 3 frames, got {other:?}"),
    }
    assert_eq!(calls, 3, "no frame is rendered after the cancel");
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert!(left.is_empty(), "left behind: {left:?}");

    // A complete export, then a cancelled one over it: the complete one is still there.
    assert_eq!(
        export::gif(&rec, &opts, &out, &mut |_, _| ControlFlow::Continue(())).unwrap(),
        21
    );
    let before = std::fs::read(&out).unwrap();
    assert!(export::gif(&rec, &opts, &out, &mut |_, _| ControlFlow::Break(())).is_err());
    assert_eq!(std::fs::read(&out).unwrap(), before);
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    std::fs::remove_dir_all(dir).ok();
}

/// A cancelled PNG export keeps the frames it wrote, and only those.
#[test]
fn cancelled_png_export_keeps_the_frames_written() {
    let rec = break_recording();
    let dir = temp("cancel-png");
    let opts = ExportOptions {
        fps: 4.0,
        width: 64,
        height: 40,
        span: (0.0, 2.0),
    };
    let mut stop_at_2 = |done: usize, _| {
        if done == 2 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    assert!(matches!(
        export::png_sequence(&rec, &opts, &dir, &mut stop_at_2),
        Err(export::ExportError::Cancelled(2))
    ));
    assert!(dir.join("frame_00001.png").exists() && !dir.join("frame_00002.png").exists());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn bad_export_options_are_errors() {
    let rec = break_recording();
    for opts in [
        ExportOptions {
            fps: 0.0,
            width: 64,
            height: 40,
            span: (0.0, 1.0),
        },
        ExportOptions {
            fps: f64::NAN,
            width: 64,
            height: 40,
            span: (0.0, 1.0),
        },
        ExportOptions {
            fps: 10.0,
            width: 1,
            height: 40,
            span: (0.0, 1.0),
        },
        ExportOptions {
            fps: 10.0,
            width: 64,
            height: 40,
            span: (2.0, 1.0),
        },
    ] {
        assert!(
            export::frames(&rec, &opts, &mut |_, _| ControlFlow::Continue(())).is_err(),
            "{opts:?}"
        );
    }
}
