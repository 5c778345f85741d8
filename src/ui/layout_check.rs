//! A check of the UI's text, read from egui's own layout (`--check-layout PATH`, used by the
//! render test): every text drawn must be whole, on screen and not cut by its clip rectangle
//! at the sides. Problems (or none) are written to the file after every egui pass, then the
//! place of each HUD button's label (`place: LABEL at X,Y`), which must not move between
//! states (issue 28, item 1), then every text drawn (`text: …`), by which the render test
//! knows the state it checked is the one it asked for.

use std::path::PathBuf;

use super::game::HUD_BUTTONS;
use bevy::prelude::*;
use bevy_egui::{
    EguiFullOutput, EguiPostUpdateSet, PrimaryEguiContext,
    egui::{Rect, Shape, epaint::ClippedShape},
};

/// Adds the check when the resource [`LayoutReport`] is present.
pub fn plugin(app: &mut App) {
    app.add_systems(
        PostUpdate,
        check_text
            .run_if(resource_exists::<LayoutReport>)
            .after(EguiPostUpdateSet::EndPass)
            .before(EguiPostUpdateSet::ProcessOutput),
    );
}

/// Where the layout check writes what it found.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct LayoutReport(pub PathBuf);

/// Pixels of slack (anti-aliasing, rounding) before a text counts as cut.
const SLACK: f32 = 1.0;

/// What is wrong with one drawn text inside `screen`, if anything.
pub fn text_problem(
    text: &str,
    rect: Rect,
    clip: Rect,
    elided: bool,
    screen: Rect,
) -> Option<String> {
    if elided {
        return Some(format!("elided: {text:?}"));
    }
    if rect.min.x < clip.min.x - SLACK || rect.max.x > clip.max.x + SLACK {
        return Some(format!(
            "cut at the side of its area: {text:?} at {rect:?}, area {clip:?}"
        ));
    }
    // Vertically a scroll area clips on purpose; what shows must still be on screen.
    let shown = rect.intersect(clip);
    if shown.is_positive() && !screen.expand(SLACK).contains_rect(shown) {
        return Some(format!(
            "off screen: {text:?} at {rect:?}, screen {screen:?}"
        ));
    }
    None
}

fn check_text(
    mut contexts: Query<(&EguiFullOutput, &mut bevy_egui::EguiContext), With<PrimaryEguiContext>>,
    report: Res<LayoutReport>,
    hud: Option<Res<super::hud::HudFit>>,
) {
    let Ok((output, mut context)) = contexts.single_mut() else {
        return;
    };
    let Some(output) = &output.0 else { return };
    let screen = context.get_mut().viewport_rect();
    let mut texts = 0;
    let mut problems = Vec::new();
    let mut places = Vec::new();
    let mut words_seen = Vec::new();
    #[allow(clippy::too_many_arguments)]
    fn visit(
        shape: &Shape,
        clip: Rect,
        screen: Rect,
        texts: &mut usize,
        problems: &mut Vec<String>,
        places: &mut Vec<String>,
        words_seen: &mut Vec<String>,
    ) {
        match shape {
            Shape::Vec(shapes) => {
                for shape in shapes {
                    visit(shape, clip, screen, texts, problems, places, words_seen);
                }
            }
            Shape::Text(text) if text.angle == 0.0 && !text.galley.is_empty() => {
                *texts += 1;
                let rect = text.galley.rect.translate(text.pos.to_vec2());
                let words = text.galley.text();
                words_seen.push(format!("text: {}", words.replace('\n', " ")));
                if let Some(problem) = text_problem(words, rect, clip, text.galley.elided, screen) {
                    problems.push(problem);
                }
                if HUD_BUTTONS.contains(&words) {
                    places.push(format!(
                        "place: {words} at {:.0},{:.0}",
                        rect.min.x, rect.min.y
                    ));
                }
            }
            _ => {}
        }
    }
    for ClippedShape { clip_rect, shape } in &output.shapes {
        visit(
            shape,
            *clip_rect,
            screen,
            &mut texts,
            &mut problems,
            &mut places,
            &mut words_seen,
        );
    }
    // A HUD line hidden below the strip is cut too, though nothing is drawn of it (issue 48).
    if let Some(hud) = hud
        && hud.needed > hud.height + SLACK
    {
        problems.push(format!(
            "HUD cut: its lines need {:.0} px, it has {:.0}",
            hud.needed, hud.height
        ));
    }
    let mut out = format!("texts checked: {texts}\n");
    places.sort();
    for line in problems.into_iter().chain(places).chain(words_seen) {
        out.push_str(&line);
        out.push('\n');
    }
    if let Err(error) = std::fs::write(&report.0, out) {
        warn!("layout report not written: {error}");
    }
}

#[cfg(test)]
mod tests {
    // Named from the crate root: a `super::` path reads as a use of `ui` in the layout test.
    use crate::ui::layout_check::text_problem;
    use bevy_egui::egui::{Rect, pos2};

    #[test]
    fn cut_elided_and_off_screen_texts_are_found() {
        let screen = Rect::from_min_max(pos2(0.0, 0.0), pos2(100.0, 100.0));
        let area = Rect::from_min_max(pos2(0.0, 0.0), pos2(50.0, 100.0));
        let inside = Rect::from_min_max(pos2(5.0, 5.0), pos2(40.0, 20.0));
        assert_eq!(text_problem("a", inside, area, false, screen), None);
        assert!(text_problem("a", inside, area, true, screen).is_some());
        let wide = Rect::from_min_max(pos2(5.0, 5.0), pos2(60.0, 20.0));
        assert!(text_problem("a", wide, area, false, screen).is_some());
        // Scrolled half out of its area at the bottom: fine.
        let low = Rect::from_min_max(pos2(5.0, 95.0), pos2(40.0, 110.0));
        assert_eq!(text_problem("a", low, area, false, screen), None);
        // A window running off the bottom of the screen: its text is not seen.
        let tall = Rect::from_min_max(pos2(0.0, 0.0), pos2(50.0, 200.0));
        assert!(text_problem("a", low, tall, false, screen).is_some());
    }
}
