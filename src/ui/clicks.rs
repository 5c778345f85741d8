//! Pointer clicks fed to egui one frame at a time: one change of a button a frame, and no
//! click on a layout the player had not seen (the interactive rectangles of the last passes);
//! egui's click time limit grown by a slow frame's length.

use bevy::{prelude::*, window::RequestRedraw};
use bevy_egui::{EguiContexts, EguiInput, egui};

/// Where a pointer event was aimed: the interactive rectangles (buttons, sliders, headers,
/// windows) under it in the layout the player saw, or `None` when that layout is not known.
type Aim = Option<Vec<egui::Rect>>;

/// An egui input event held back for a later frame, with where it was aimed.
#[derive(Debug, Clone, PartialEq)]
struct Held {
    event: egui::Event,
    /// For a button press: the targets under it in every layout the player may have seen
    /// when pressing (`None`: those layouts differed there, so the press is dropped).
    aim: Aim,
}

/// The click state of one egui context between frames.
#[derive(Debug, Default)]
struct ClickQueue {
    /// Events not yet given to egui, oldest first.
    held: Vec<Held>,
    /// Buttons whose press was dropped: their next release is dropped too.
    dropping: [bool; egui::NUM_POINTER_BUTTONS],
}

impl ClickQueue {
    /// The events egui reads this frame, `arrived` having come in since the last one and
    /// `passes` being the rectangles of the last two passes ([`tag_arrivals`],
    /// [`take_for_frame`]); and how many presses were dropped.
    fn next_frame(
        &mut self,
        arrived: Vec<egui::Event>,
        passes: &Passes,
    ) -> (Vec<egui::Event>, usize) {
        self.held
            .extend(tag_arrivals(arrived, &passes.before, &passes.last));
        take_for_frame(self, &passes.last)
    }
}

/// The click queues, by egui context.
#[derive(Default)]
pub(super) struct ClickQueues(Vec<(Entity, ClickQueue)>);

/// The interactive rectangles of an egui context's last two passes.
#[derive(Debug, Default, Clone, PartialEq)]
struct Passes {
    /// The pass before the last.
    before: Vec<egui::Rect>,
    /// The last pass.
    last: Vec<egui::Rect>,
}

impl Passes {
    /// Records the rectangles of the pass just ended; whether they differ from the last's.
    fn record(&mut self, rects: Vec<egui::Rect>) -> bool {
        let changed = !same_targets(&self.last, &rects);
        self.before = std::mem::replace(&mut self.last, rects);
        changed
    }
}

/// Each egui context's [`Passes`], recorded once a frame after its pass
/// ([`record_pass_rects`]) and read by the next frame's input ([`split_one_frame_clicks`]).
#[derive(Resource, Debug, Default)]
pub(super) struct PassRects(Vec<(Entity, Passes)>);

/// Rectangles of `rects` containing `pos`, back to front.
fn under(rects: &[egui::Rect], pos: egui::Pos2) -> Vec<egui::Rect> {
    rects.iter().filter(|r| r.contains(pos)).copied().collect()
}

/// Whether two lists of targets are the same, to half a point.
fn same_targets(a: &[egui::Rect], b: &[egui::Rect]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(a, b)| (a.min - b.min).length() <= 0.5 && (a.max - b.max).length() <= 0.5)
}

/// Tags newly read `events` with where they were aimed: a press arriving now was made while
/// the last pass (`now`) or, if the press came while that pass was still being drawn, the
/// one before it (`before`) was on screen; where they differ under the press, the player's
/// target is unknown.
fn tag_arrivals(events: Vec<egui::Event>, before: &[egui::Rect], now: &[egui::Rect]) -> Vec<Held> {
    events
        .into_iter()
        .map(|event| {
            let aim = match event {
                egui::Event::PointerButton {
                    pos, pressed: true, ..
                } => {
                    let (seen, last) = (under(before, pos), under(now, pos));
                    same_targets(&seen, &last).then_some(last)
                }
                _ => Some(Vec::new()),
            };
            Held { event, aim }
        })
        .collect()
}

/// Takes from `queue` the events egui reads this frame, its last pass's interactive
/// rectangles being `now`; what is left waits for the next frame. A frame reads at most one
/// change of a button: it stops before the release of a button pressed in it (egui's slider
/// senses drags only, so a press and release read in one frame did nothing on a slider's
/// rail), and before a press after a release (the click's effect is drawn first). A press
/// whose targets under it differ from those the player saw is dropped with its release: the
/// layout moved under it (issue 48: a second click on a slow frame landed on what the
/// first had opened). Returns the events and how many presses were dropped.
fn take_for_frame(queue: &mut ClickQueue, now: &[egui::Rect]) -> (Vec<egui::Event>, usize) {
    let mut out = Vec::new();
    let mut dropped = 0;
    let mut pressed = [false; egui::NUM_POINTER_BUTTONS];
    let mut released = false;
    let mut rest = std::mem::take(&mut queue.held).into_iter();
    for held in rest.by_ref() {
        if let egui::Event::PointerButton {
            button,
            pressed: down,
            pos,
            ..
        } = held.event
        {
            let b = button as usize;
            if down {
                if released {
                    queue.held.push(held);
                    break;
                }
                let aimed = held
                    .aim
                    .as_deref()
                    .is_some_and(|aim| same_targets(aim, &under(now, pos)));
                if !aimed {
                    queue.dropping[b] = true;
                    dropped += 1;
                    continue;
                }
                pressed[b] = true;
            } else {
                if std::mem::take(&mut queue.dropping[b]) {
                    continue;
                }
                if pressed[b] {
                    queue.held.push(held);
                    break;
                }
                released = true;
            }
        }
        out.push(held.event);
    }
    queue.held.extend(rest);
    (out, dropped)
}

/// Gives egui each frame the input events it should read then ([`take_for_frame`]): one
/// change of a pointer button a frame, and no click on a layout the player had not seen.
/// While events wait, the next frame is asked for.
pub(super) fn split_one_frame_clicks(
    mut inputs: Query<(Entity, &mut EguiInput)>,
    passes: Res<PassRects>,
    mut queues: Local<ClickQueues>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    let mut waiting = false;
    let none = Passes::default();
    for (entity, mut input) in &mut inputs {
        let index = match queues.0.iter().position(|(e, _)| *e == entity) {
            Some(index) => index,
            None => {
                queues.0.push((entity, ClickQueue::default()));
                queues.0.len() - 1
            }
        };
        let queue = &mut queues.0[index].1;
        let passes = passes
            .0
            .iter()
            .find(|(e, _)| *e == entity)
            .map_or(&none, |(_, p)| p);
        let (events, dropped) = queue.next_frame(std::mem::take(&mut input.events), passes);
        if dropped > 0 {
            debug!("{dropped} click(s) dropped: the layout under them changed");
        }
        input.events = events;
        waiting |= !queue.held.is_empty();
    }
    queues.0.retain(|(e, _)| inputs.contains(*e));
    if waiting {
        redraw.write(RequestRedraw);
    }
}

/// Records each context's interactive rectangles after its pass ([`PassRects`]). A pass that
/// moved something the pointer can act on is followed by one more frame: the idle window's
/// last two passes then agree, and a click long after the change is not taken for one made
/// while the layout moved ([`tag_arrivals`]; played: the New game button did nothing after
/// a drop-down had been closed with Escape, no frame having followed).
pub(super) fn record_pass_rects(
    mut contexts: Query<(Entity, &mut bevy_egui::EguiContext)>,
    mut recorded: ResMut<PassRects>,
    mut redraw: MessageWriter<RequestRedraw>,
) {
    let mut changed = false;
    for (entity, mut context) in &mut contexts {
        let rects = context.get_mut().interactive_rects_last_pass();
        let index = match recorded.0.iter().position(|(e, _)| *e == entity) {
            Some(index) => index,
            None => {
                recorded.0.push((entity, Passes::default()));
                recorded.0.len() - 1
            }
        };
        changed |= recorded.0[index].1.record(rects);
    }
    recorded.0.retain(|(e, _)| contexts.contains(*e));
    if changed {
        redraw.write(RequestRedraw);
    }
}

/// egui's own limit on how long a click's button may be held (`InputOptions`), seconds.
const EGUI_CLICK_SECONDS: f64 = 0.8;

/// The longest press egui counts as a click after a frame of `frame_seconds`: its own limit
/// plus that frame. egui times a press by the real time of the frames that read its down and
/// up events; on a slow frame (a second or more under a software renderer) a click's press
/// wakes the idle window and its release is read a frame later, a frame's time after.
fn max_click_duration(frame_seconds: f64) -> f64 {
    EGUI_CLICK_SECONDS + frame_seconds.max(0.0)
}

/// Played under Xvfb at 0.5 fps, the new-game dialog's buttons needed two clicks: the first
/// was held "2 s" by egui's clock. The click limit now grows by the last frame's time (on a
/// 60 fps machine it is egui's own, give or take 17 ms).
pub(super) fn allow_slow_clicks(mut contexts: EguiContexts, time: Res<Time<Real>>) -> Result {
    let limit = max_click_duration(time.delta_secs_f64());
    contexts
        .ctx_mut()?
        .options_mut(|o| o.input_options.max_click_duration = limit);
    Ok(())
}

#[cfg(test)]
mod tests {
    use bevy_egui::egui::{self, Event, PointerButton, pos2, vec2};

    /// Runs one egui pass with `events` over a button at (100, 100); whether it was clicked.
    fn pass(ctx: &egui::Context, events: Vec<Event>) -> bool {
        timed_pass(ctx, None, events, |ui| ui.button("Shoot").clicked())
    }

    /// One egui pass of an 800x600 screen at `time` (egui's own clock when `None`) with
    /// `events`, `widget` in an area at (100, 100); what `widget` returned.
    fn timed_pass<R: Default>(
        ctx: &egui::Context,
        time: Option<f64>,
        events: Vec<Event>,
        mut widget: impl FnMut(&mut egui::Ui) -> R,
    ) -> R {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                pos2(0.0, 0.0),
                vec2(800.0, 600.0),
            )),
            time,
            events,
            ..Default::default()
        };
        let mut out = R::default();
        let _ = ctx.run_ui(input, |ui| {
            egui::Area::new(egui::Id::new("area"))
                .fixed_pos(pos2(100.0, 100.0))
                .show(ui.ctx(), |ui| out = widget(ui));
        });
        out
    }

    fn button(pos: egui::Pos2, pressed: bool) -> Event {
        Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers: Default::default(),
        }
    }

    /// Runs frames of `ui` (in an area at (100, 100), egui's clock at 1 s a frame from
    /// `time`) the way the game does: `batches[k]` arrive before frame k and go through
    /// [`super::take_for_frame`]; then frames until nothing waits. The number of frames run.
    fn frames(
        ctx: &egui::Context,
        time: &mut f64,
        batches: Vec<Vec<Event>>,
        mut ui: impl FnMut(&mut egui::Ui),
    ) -> usize {
        // A click held over frames of a second (as `allow_slow_clicks` allows in the game).
        ctx.options_mut(|o| o.input_options.max_click_duration = 10.0);
        let mut queue = super::ClickQueue::default();
        let mut passes = super::Passes::default();
        passes.record(ctx.interactive_rects_last_pass());
        passes.record(ctx.interactive_rects_last_pass());
        let mut batches = batches.into_iter();
        let mut count = 0;
        loop {
            let arrived = batches.next();
            if arrived.is_none() && queue.held.is_empty() {
                return count;
            }
            let (events, _) = queue.next_frame(arrived.unwrap_or_default(), &passes);
            *time += 1.0;
            timed_pass(ctx, Some(*time), events, &mut ui);
            passes.record(ctx.interactive_rects_last_pass());
            count += 1;
        }
    }

    /// A click on a slider's rail moves it once the release is read a frame after the press
    /// (`take_for_frame`), and not when egui reads press and release in one frame.
    #[test]
    fn a_click_on_a_slider_rail_moves_it_when_split() {
        // 90 % along the rail (the slider is 100 points wide by default).
        let at = pos2(190.0, 109.0);
        for split in [false, true] {
            let ctx = egui::Context::default();
            let mut value: f64 = 1.0;
            let mut slider = |ui: &mut egui::Ui| {
                ui.add(egui::Slider::new(&mut value, 0.0..=4.0).show_value(false));
            };
            let mut time = 0.0;
            let settle = vec![Vec::new(), vec![Event::PointerMoved(at)], Vec::new()];
            frames(&ctx, &mut time, settle, &mut slider);
            let click = vec![button(at, true), button(at, false)];
            if split {
                assert_eq!(frames(&ctx, &mut time, vec![click], &mut slider), 2);
            } else {
                timed_pass(&ctx, Some(time + 1.0), click, &mut slider);
            }
            let moved = (value - 3.6).abs() < 0.2;
            assert_eq!(moved, split, "split {split}: value {value}");
        }
    }

    /// A frame reads one change of a button: a release after its press waits a frame, and
    /// so does a press after a release; other events keep their order around them.
    #[test]
    fn one_change_of_a_button_a_frame() {
        let p = pos2(1.0, 1.0);
        let mut queue = super::ClickQueue::default();
        let events = vec![
            button(p, true),
            Event::PointerMoved(p),
            button(p, false),
            Event::Text("a".to_owned()),
            button(p, true),
            button(p, false),
        ];
        queue.held = super::tag_arrivals(events, &[], &[]);
        let (first, _) = super::take_for_frame(&mut queue, &[]);
        assert_eq!(first, vec![button(p, true), Event::PointerMoved(p)]);
        let (second, _) = super::take_for_frame(&mut queue, &[]);
        assert_eq!(second, vec![button(p, false), Event::Text("a".to_owned())]);
        let (third, _) = super::take_for_frame(&mut queue, &[]);
        assert_eq!(third, vec![button(p, true)]);
        let (fourth, dropped) = super::take_for_frame(&mut queue, &[]);
        assert_eq!((fourth, dropped), (vec![button(p, false)], 0));
        assert!(queue.held.is_empty());
    }

    /// Issue 48: two clicks made on one slow frame, the first opening a header, the second
    /// aimed at a button the opened header pushes down. The second lands on neither that
    /// button (moved) nor what took its place (the player never saw it): it is dropped. Two
    /// clicks on a layout that does not move both land.
    #[test]
    fn a_click_on_a_layout_the_player_had_not_seen_is_dropped() {
        let (header, below) = (pos2(130.0, 108.0), pos2(130.0, 132.0));
        let mut clicked: Vec<&str> = Vec::new();
        let mut ui = |ui: &mut egui::Ui| {
            egui::CollapsingHeader::new("Physics").show(ui, |ui| {
                if ui.button("Inside").clicked() {
                    clicked.push("Inside");
                }
                ui.add_space(60.0);
            });
            if ui.button("Below").clicked() {
                clicked.push("Below");
            }
        };
        let ctx = egui::Context::default();
        ctx.all_styles_mut(|s| s.animation_time = 0.0);
        let mut time = 0.0;
        frames(&ctx, &mut time, vec![Vec::new(); 3], &mut ui);
        let rects = ctx.interactive_rects_last_pass();
        assert!(
            rects.iter().any(|r| r.contains(below)),
            "Below is at {below:?}"
        );
        let both = vec![vec![
            Event::PointerMoved(header),
            button(header, true),
            button(header, false),
            Event::PointerMoved(below),
            button(below, true),
            button(below, false),
        ]];
        frames(&ctx, &mut time, both, &mut ui);
        // The header opened: where "Below" was is now inside its body.
        let moved = ctx.interactive_rects_last_pass();
        assert!(moved.len() > rects.len(), "the header did not open");
        assert!(clicked.is_empty(), "clicked {clicked:?}");

        // The same two clicks on "Below" alone: nothing moves, both land.
        let mut count = 0;
        let mut still = |ui: &mut egui::Ui| {
            if ui.button("Below").clicked() {
                count += 1;
            }
        };
        let ctx = egui::Context::default();
        frames(&ctx, &mut time, vec![Vec::new(); 3], &mut still);
        let at = pos2(110.0, 108.0);
        let twice = vec![vec![
            Event::PointerMoved(at),
            button(at, true),
            button(at, false),
            button(at, true),
            button(at, false),
        ]];
        frames(&ctx, &mut time, twice, &mut still);
        assert_eq!(count, 2);
    }

    /// A click whose press and release egui reads in two frames 2 s apart (the press woke
    /// an idle window whose frame took 2 s) is lost at egui's own limit and counted with the
    /// limit of `max_click_duration` for that frame.
    #[test]
    fn a_click_split_over_a_slow_frame_clicks_the_button() {
        let on = pos2(110.0, 108.0);
        let run = |ctx: &egui::Context, time: f64, events: Vec<Event>| {
            timed_pass(ctx, Some(time), events, |ui| ui.button("Start").clicked())
        };
        for (limit, expected) in [
            (super::EGUI_CLICK_SECONDS, false),
            (super::max_click_duration(2.0), true),
        ] {
            let ctx = egui::Context::default();
            ctx.options_mut(|o| o.input_options.max_click_duration = limit);
            assert!(!run(&ctx, 9.0, Vec::new()));
            assert!(!run(&ctx, 10.0, vec![Event::PointerMoved(on)]));
            assert!(!run(&ctx, 12.0, vec![button(on, true)]));
            let clicked = run(&ctx, 14.0, vec![button(on, false)]);
            assert_eq!(clicked, expected, "limit {limit} s");
        }
    }

    /// A pointer that jumps onto a button and clicks within one frame (a 1 fps machine, or
    /// `xdotool mousemove X Y click 1`) clicks it, whatever the order and positions of the
    /// events egui gets in that frame: bevy_egui 0.42 hands them over in the window's order
    /// (the move, then the press at the new position), and egui picks the widget under the
    /// frame's last pointer position even for a press still at the old one or a press and
    /// release before the move. A click lost this way was the table's, not egui's (see
    /// `input::held_or_clicked`).
    #[test]
    fn a_jump_and_click_within_one_frame_clicks_the_button() {
        let (away, on) = (pos2(700.0, 500.0), pos2(110.0, 108.0));
        let orders = [
            vec![Event::PointerMoved(on), button(on, true), button(on, false)],
            vec![
                Event::PointerMoved(on),
                button(away, true),
                button(on, false),
            ],
            vec![
                button(away, true),
                button(away, false),
                Event::PointerMoved(on),
            ],
        ];
        for events in orders {
            let ctx = egui::Context::default();
            assert!(!pass(&ctx, vec![Event::PointerMoved(away)]));
            assert!(!pass(&ctx, Vec::new()));
            assert!(pass(&ctx, events.clone()), "not clicked: {events:?}");
            // Nothing more without a new click.
            assert!(!pass(&ctx, Vec::new()));
        }
    }
}
