//! `--count-idle-frames SECONDS`: how many frames the window draws while nothing happens
//! (the render test's measure of the reactive window). Once every render pipeline is ready,
//! the last two frames asked for no other and the window has drawn nothing for a few seconds
//! (the start-up frames are over), a thread wakes the event loop twice, `SECONDS` apart; the
//! frames between the two wake-ups are the idle frames. Prints `idle frames: N in S s`, then one line for each idle frame naming what
//! woke it (window and input events, `RequestRedraw` messages, egui's repaint causes, the
//! pipeline counts), then exits.

use std::{
    sync::{
        Arc,
        atomic::{AtomicBool, AtomicU8, AtomicU32, Ordering},
    },
    time::{Duration, Instant},
};

use bevy::{
    diagnostic::FrameCount,
    prelude::*,
    window::{RequestRedraw, WindowEvent},
    winit::{EventLoopProxyWrapper, WinitUserEvent},
};

use crate::view::pipelines::PipelineProgress;

/// What made egui ask for the frame now running (its repaint causes, "file:line reason"),
/// written by the UI plugin only while this counter reads it (`--count-idle-frames`).
#[derive(Resource, Debug, Default, Clone, PartialEq, Eq)]
pub struct RepaintCauses(pub String);

/// Counts the frames drawn in `seconds` of idle, prints them and exits.
#[derive(Debug, Clone)]
pub struct IdleCountPlugin {
    /// Length of the idle interval.
    pub seconds: Duration,
}

/// How long the window must have drawn nothing before the interval starts.
const QUIET: Duration = Duration::from_secs(3);

impl Plugin for IdleCountPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(IdleCount {
            seconds: self.seconds,
            phase: Arc::default(),
            frame: Arc::default(),
            settled: Arc::default(),
            redraw_free: 0,
            started: false,
            first_frame: None,
            trace: Vec::new(),
        })
        .init_resource::<RepaintCauses>()
        .add_systems(Last, count_idle_frames);
    }
}

#[derive(Resource, Debug)]
struct IdleCount {
    seconds: Duration,
    /// 0: waiting to start, 1: the interval runs, 2: it is over (set by the thread).
    phase: Arc<AtomicU8>,
    /// The last frame drawn, for the thread to see when drawing has stopped.
    frame: Arc<AtomicU32>,
    /// Whether the app has asked for no further frame: every pipeline ready and no
    /// `RequestRedraw` in the last two frames (the runner reads a message in the frame after
    /// it too). A slow frame still being drawn is not taken for idle: the thread waits for
    /// this state, not only for the clock.
    settled: Arc<AtomicBool>,
    /// Frames in a row that wrote no `RequestRedraw`.
    redraw_free: u32,
    started: bool,
    first_frame: Option<u32>,
    /// What woke each frame of the interval, one line a frame.
    trace: Vec<String>,
}

#[expect(
    clippy::too_many_arguments,
    reason = "a diagnostic that reads every wake-up source"
)]
fn count_idle_frames(
    mut count: ResMut<IdleCount>,
    progress: Res<PipelineProgress>,
    frames: Res<FrameCount>,
    proxy: Option<Res<EventLoopProxyWrapper>>,
    mut window_events: MessageReader<WindowEvent>,
    mut redraws: MessageReader<RequestRedraw>,
    causes: Res<RepaintCauses>,
    mut exit: MessageWriter<AppExit>,
) {
    count.frame.store(frames.0, Ordering::SeqCst);
    // Read every frame, so that a frame reports only what arrived since the last one.
    let events = window_events.read().map(event_name).collect::<Vec<_>>();
    let redraw_count = redraws.read().count();
    let (total, waiting) = progress.counts();
    count.redraw_free = if redraw_count == 0 {
        count.redraw_free.saturating_add(1)
    } else {
        0
    };
    let settled = total > 0 && waiting == 0 && count.redraw_free >= 2;
    count.settled.store(settled, Ordering::SeqCst);
    if !count.started {
        if total == 0 || waiting > 0 {
            return;
        }
        let Some(proxy) = proxy else {
            error!("no event loop to wake: cannot count idle frames");
            exit.write(AppExit::error());
            return;
        };
        count.started = true;
        let proxy = (**proxy).clone();
        let phase = count.phase.clone();
        let frame = count.frame.clone();
        let settled = count.settled.clone();
        let seconds = count.seconds;
        std::thread::spawn(move || {
            // Wait until the app has settled and no frame has been drawn for QUIET (late
            // window events of the start-up are over).
            let (mut last, mut since) = (frame.load(Ordering::SeqCst), Instant::now());
            while since.elapsed() < QUIET || !settled.load(Ordering::SeqCst) {
                std::thread::sleep(Duration::from_millis(100));
                let now = frame.load(Ordering::SeqCst);
                if now != last {
                    (last, since) = (now, Instant::now());
                }
            }
            phase.store(1, Ordering::SeqCst);
            let _ = proxy.send_event(WinitUserEvent::WakeUp);
            std::thread::sleep(seconds);
            phase.store(2, Ordering::SeqCst);
            let _ = proxy.send_event(WinitUserEvent::WakeUp);
        });
        return;
    }
    match (count.phase.load(Ordering::SeqCst), count.first_frame) {
        (1, None) => count.first_frame = Some(frames.0),
        (1, Some(_)) => {
            let causes = &causes.0;
            let line = format!(
                "idle frame {}: window events [{}]; RequestRedraw written: {redraw_count}; \
                 UI repaint causes [{causes}]; pipelines {total} ({waiting} waiting)",
                frames.0,
                events.join(", ")
            );
            count.trace.push(line);
        }
        (2, Some(first)) => {
            // Neither wake-up frame counts.
            let idle = frames.0.saturating_sub(first).saturating_sub(1);
            println!("idle frames: {idle} in {} s", count.seconds.as_secs_f64());
            for line in &count.trace {
                println!("{line}");
            }
            exit.write(AppExit::Success);
        }
        _ => {}
    }
}

/// The kind of a window event, with the details that tell its source.
fn event_name(event: &WindowEvent) -> String {
    match event {
        WindowEvent::CursorMoved(e) => format!("CursorMoved({:?})", e.position),
        WindowEvent::WindowFocused(e) => format!("WindowFocused({})", e.focused),
        WindowEvent::WindowOccluded(e) => format!("WindowOccluded({})", e.occluded),
        WindowEvent::KeyboardInput(e) => format!("KeyboardInput({:?})", e.key_code),
        WindowEvent::MouseButtonInput(e) => format!("MouseButtonInput({:?})", e.button),
        other => {
            let debug = format!("{other:?}");
            debug.split('(').next().unwrap_or_default().to_owned()
        }
    }
}
