//! The panel's shared widgets: a collapsing section, a slider over a physical range, and
//! the physics edit they feed.

use bevy_egui::egui;

use super::param::SettingsParam;
use crate::settings::{ParamRange, PhysicsSettings};

/// A collapsing section of the panel, open at start when `open` says so.
pub(crate) fn section(
    ui: &mut egui::Ui,
    title: &str,
    open: bool,
    add_contents: impl FnOnce(&mut egui::Ui),
) {
    egui::CollapsingHeader::new(title)
        .default_open(open)
        .show(ui, add_contents);
}

/// A slider with an editable number. Typing a value outside the physical range is allowed
/// here so that the clamp can be reported rather than silently swallowed.
pub(super) fn param_slider(ui: &mut egui::Ui, value: &mut f64, range: ParamRange) {
    ui.add(range_slider(value, range).max_decimals(4));
}

/// A slider over a physical range: typed values apply when the edit is committed, and a value
/// beyond the range is not clamped here but by the settings, which say so.
pub(super) fn range_slider(value: &mut f64, range: ParamRange) -> egui::Slider<'_> {
    egui::Slider::new(value, range.as_range())
        .update_while_editing(false)
        .text(range.label)
        .suffix(range.unit)
        .clamping(egui::SliderClamping::Never)
}

/// Takes an edit of the physics settings: clamped to the physical ranges (the notes go to
/// the HUD), applied only if something changed.
pub(super) fn apply_physics_edit(mut next: PhysicsSettings, state: &mut SettingsParam) {
    if next == *state.physics {
        return;
    }
    let notes = next.clamp_to_physical();
    if !notes.is_empty() {
        state.report.notes = notes;
    }
    *state.physics = next;
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::{Event, Key, Modifiers, PointerButton, Pos2, RawInput, Rect, Shape, vec2};

    /// One egui pass showing the sliding-friction slider over `value`, with `events`; returns
    /// where the value's text was drawn.
    fn pass(ctx: &egui::Context, events: Vec<Event>, value: &mut f64) -> Option<Rect> {
        let input = RawInput {
            events,
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, vec2(600.0, 200.0))),
            ..Default::default()
        };
        let output = ctx.run_ui(input, |ui| {
            param_slider(ui, value, PhysicsSettings::MU_SLIDE);
        });
        fn find(shape: &Shape) -> Option<Rect> {
            match shape {
                Shape::Vec(shapes) => shapes.iter().find_map(find),
                Shape::Text(text) if text.galley.text().parse::<f64>().is_ok() => {
                    Some(text.galley.rect.translate(text.pos.to_vec2()))
                }
                _ => None,
            }
        }
        output.shapes.iter().find_map(|s| find(&s.shape))
    }

    fn click(at: Pos2) -> Vec<Event> {
        [true, false]
            .map(|pressed| Event::PointerButton {
                pos: at,
                button: PointerButton::Primary,
                pressed,
                modifiers: Modifiers::NONE,
            })
            .into()
    }

    /// A typed value applies when the edit is committed (issue 28, item 3: typing "0.2" into
    /// sliding friction gave 0.15, the "0" clamped on its keystroke); one beyond the range is
    /// passed on unclamped, for the settings to clamp and say so.
    #[test]
    fn a_typed_value_applies_on_enter_not_per_keystroke() {
        let ctx = egui::Context::default();
        let mut value = 0.3;
        let text = pass(&ctx, Vec::new(), &mut value).expect("the value is drawn");
        let mut events = vec![Event::PointerMoved(text.center())];
        events.extend(click(text.center()));
        pass(&ctx, events, &mut value);
        assert!(
            ctx.memory(|m| m.focused().is_some()),
            "a click edits the value"
        );
        for typed in ["0", ".", "2"] {
            pass(&ctx, vec![Event::Text(typed.to_owned())], &mut value);
            assert_eq!(value, 0.3, "nothing applies while typing ({typed:?})");
        }
        let enter = Event::Key {
            key: Key::Enter,
            physical_key: None,
            pressed: true,
            repeat: false,
            modifiers: Modifiers::NONE,
        };
        pass(&ctx, vec![enter.clone()], &mut value);
        assert_eq!(value, 0.2, "Enter commits the typed value");
        // Beyond the range: the slider does not clamp it (the settings do, with a note).
        let text = pass(&ctx, Vec::new(), &mut value).unwrap();
        let mut events = vec![Event::PointerMoved(text.center())];
        events.extend(click(text.center()));
        pass(&ctx, events, &mut value);
        for typed in ["0", ".", "0", "5"] {
            pass(&ctx, vec![Event::Text(typed.to_owned())], &mut value);
        }
        pass(&ctx, vec![enter], &mut value);
        assert_eq!(value, 0.05);
    }
}
