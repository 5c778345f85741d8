//! `--count-idle-frames SECONDS`: how many frames the window draws while nothing happens
//! (the render test's measure of the reactive window). Once every render pipeline has been
//! ready for a moment, a thread wakes the event loop twice, `SECONDS` apart; the frames
//! between the two wake-ups are the idle frames. Prints `idle frames: N in S s`, then exits.

use std::{
    sync::{
        Arc,
        atomic::{AtomicU8, Ordering},
    },
    time::Duration,
};

use bevy::{
    diagnostic::FrameCount,
    prelude::*,
    winit::{EventLoopProxyWrapper, WinitUserEvent},
};

use crate::pipelines::PipelineProgress;

/// Counts the frames drawn in `seconds` of idle, prints them and exits.
#[derive(Debug, Clone)]
pub struct IdleCountPlugin {
    /// Length of the idle interval.
    pub seconds: Duration,
}

/// After the pipelines are ready, how long the last start-up frames get to finish.
const SETTLE: Duration = Duration::from_secs(3);

impl Plugin for IdleCountPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(IdleCount {
            seconds: self.seconds,
            phase: Arc::default(),
            started: false,
            first_frame: None,
        })
        .add_systems(Last, count_idle_frames);
    }
}

#[derive(Resource, Debug)]
struct IdleCount {
    seconds: Duration,
    /// 0: waiting to start, 1: the interval runs, 2: it is over (set by the thread).
    phase: Arc<AtomicU8>,
    started: bool,
    first_frame: Option<u32>,
}

fn count_idle_frames(
    mut count: ResMut<IdleCount>,
    progress: Res<PipelineProgress>,
    frames: Res<FrameCount>,
    proxy: Option<Res<EventLoopProxyWrapper>>,
    mut exit: MessageWriter<AppExit>,
) {
    let (total, waiting) = progress.counts();
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
        let seconds = count.seconds;
        std::thread::spawn(move || {
            for (next, wait) in [(1, SETTLE), (2, seconds)] {
                std::thread::sleep(wait);
                phase.store(next, Ordering::SeqCst);
                let _ = proxy.send_event(WinitUserEvent::WakeUp);
            }
        });
        return;
    }
    match (count.phase.load(Ordering::SeqCst), count.first_frame) {
        (1, None) => count.first_frame = Some(frames.0),
        (2, Some(first)) => {
            // Neither wake-up frame counts.
            let idle = frames.0.saturating_sub(first).saturating_sub(1);
            println!("idle frames: {idle} in {} s", count.seconds.as_secs_f64());
            exit.write(AppExit::Success);
        }
        _ => {}
    }
}
