//! How far the renderer is with its shader pipelines. On a software renderer they compile for
//! seconds, and until they have, frames come out blank. The render world reports how many
//! pipelines exist and how many are still compiling; the main world reads the counts: the
//! screenshot waits for them, and the window keeps drawing until they are all ready (it
//! redraws only on demand afterwards, so without this it could stay blank until the first
//! input).

use std::sync::{
    Arc,
    atomic::{AtomicUsize, Ordering},
};

use bevy::{
    prelude::*,
    render::{Render, RenderApp, RenderSystems, render_resource::PipelineCache},
    window::RequestRedraw,
};

/// Registers the pipeline counts in both worlds.
pub fn plugin(app: &mut App) {
    let progress = PipelineProgress::default();
    app.insert_resource(progress.clone());
    if let Some(render_app) = app.get_sub_app_mut(RenderApp) {
        render_app
            .insert_resource(progress)
            .add_systems(Render, report_pipelines.in_set(RenderSystems::Cleanup));
    } else {
        warn!("no render app: pipeline progress stays unknown");
    }
}

/// Keeps the window drawing until every pipeline is ready and a few frames after, so the
/// first complete picture reaches the screen without waiting for input.
pub fn redraw_until_ready(
    progress: Res<PipelineProgress>,
    mut frames_since_ready: Local<u32>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    // Frames drawn after the last pipeline became ready (the swap chain may lag a frame).
    const FRAMES_AFTER_READY: u32 = 3;
    let (total, waiting) = progress.counts();
    if total == 0 || waiting > 0 {
        *frames_since_ready = 0;
    } else if *frames_since_ready < FRAMES_AFTER_READY {
        *frames_since_ready += 1;
    } else {
        return;
    }
    redraw.write(RequestRedraw);
}

/// Pipeline counts, written by the render world and read by the main world.
#[derive(Resource, Debug, Clone, Default)]
pub struct PipelineProgress(Arc<PipelineCounts>);

#[derive(Debug, Default)]
struct PipelineCounts {
    total: AtomicUsize,
    waiting: AtomicUsize,
}

impl PipelineProgress {
    /// Pipelines known to the renderer, and how many of them are still compiling.
    pub fn counts(&self) -> (usize, usize) {
        (
            self.0.total.load(Ordering::Relaxed),
            self.0.waiting.load(Ordering::Relaxed),
        )
    }
}

fn report_pipelines(cache: Res<PipelineCache>, progress: Res<PipelineProgress>) {
    progress
        .0
        .total
        .store(cache.pipelines().count(), Ordering::Relaxed);
    progress
        .0
        .waiting
        .store(cache.waiting_pipelines().count(), Ordering::Relaxed);
}
