//! The windows of a snooker frame: the nomination of a colour (or a free ball) and the
//! concession, the verdict with the offended player's choices, the end of a frame.

use bevy::prelude::*;
use bevy_egui::egui;

use crate::play::game::{Rules, TurnCommand, snooker};

/// Snooker, a human to play: the colour (or free ball) to nominate (2.12, 3.12; without one
/// the ball hit first is taken as nominated), and the concession of the frame (2.1(a)).
pub(super) fn snooker_nominate(
    ctx: &egui::Context,
    rules: &Rules,
    commands: &mut MessageWriter<TurnCommand>,
) {
    use billiards_rules::snooker::{BallOn, balls};
    let Some(game) = &rules.snooker else {
        return;
    };
    let next = game.next();
    let colour_on = matches!(next.on, BallOn::Colour { .. });
    let on = game.frame.balls_on(next.on);
    // A free ball may be any ball; the colours are offered (a red as a free ball is the one
    // hit first).
    let choices: Vec<u8> = if colour_on || next.free_ball {
        balls::COLOURS
            .iter()
            .copied()
            .filter(|c| game.frame.on_table.contains(c))
            .filter(|c| colour_on || !on.contains(c))
            .collect()
    } else {
        Vec::new()
    };
    // Nothing to nominate on the break-off (issue 48: the window opened at the first stroke
    // with nothing in it but the ball on, which the HUD says); later a collapsed "Frame"
    // window keeps the concession at hand.
    let first_stroke = game.log.strokes.is_empty();
    if choices.is_empty() && first_stroke {
        return;
    }
    let window = egui::Window::new(if choices.is_empty() {
        "Frame"
    } else {
        "Nominate"
    })
    .id(egui::Id::new("snooker nominate"))
    .collapsible(true)
    .default_open(!choices.is_empty())
    .resizable(false)
    .anchor(egui::Align2::RIGHT_BOTTOM, [-10.0, -10.0]);
    window.show(ctx, |ui| {
        if choices.is_empty() {
            ui.label(format!("ball on: {}", next.on));
        } else {
            ui.label(if colour_on {
                "Nominate a colour (else the one hit first):"
            } else {
                "Free ball: nominate one (else the one hit first):"
            });
            ui.horizontal(|ui| {
                for &c in &choices {
                    let chosen = game.nominated == Some(c);
                    if ui.selectable_label(chosen, balls::name(c)).clicked() {
                        commands.write(TurnCommand::Nominate(c));
                    }
                }
            });
        }
        if ui
            .button("Concede the frame")
            .on_hover_text("WPBSA 2.1(a): the opponent wins the frame")
            .clicked()
        {
            commands.write(TurnCommand::Concede);
        }
    });
}

/// Snooker's verdict: the sentence, then the incoming player's choices or Continue.
pub(super) fn snooker_verdict(
    ctx: &egui::Context,
    window: egui::Window,
    rules: &Rules,
    commands: &mut MessageWriter<TurnCommand>,
) {
    let Some(game) = &rules.snooker else {
        return;
    };
    window.show(ctx, |ui| {
        if let Some(verdict) = &game.last {
            ui.label(&verdict.text);
        }
        let next = game.next();
        let striker = game.name(next.striker);
        if !next.choices.is_empty() && game.computer(next.striker).is_some() {
            ui.label(format!("{striker} (computer) chooses next"));
        } else if !next.choices.is_empty() {
            ui.label(format!("{striker} chooses:"));
            ui.horizontal_wrapped(|ui| {
                for &choice in &next.choices {
                    if ui.button(snooker::choice_label(choice, game)).clicked() {
                        commands.write(TurnCommand::SnookerChoose(choice));
                    }
                }
            });
        } else {
            let hand = if next.in_hand {
                ", with the cue ball in hand in the D"
            } else {
                ""
            };
            let free = if next.free_ball {
                " (a free ball: any ball may be nominated)"
            } else {
                ""
            };
            ui.label(format!("{striker} plays next{hand}{free}"));
            if game.has_human() && ui.button("Continue (Enter)").clicked() {
                commands.write(TurnCommand::Continue);
            }
        }
    });
}

/// The end of a snooker frame: the winner, the frames, the next frame or a new game.
pub(super) fn snooker_frame_over(
    ctx: &egui::Context,
    window: egui::Window,
    rules: &Rules,
    commands: &mut MessageWriter<TurnCommand>,
) {
    let Some(game) = &rules.snooker else {
        return;
    };
    window.show(ctx, |ui| {
        if let Some(end) = game.frame.end {
            ui.label(snooker::end_text(game, end));
        }
        let f = &game.frame;
        ui.label(format!(
            "points {} {} - {} {}; highest breaks {} and {}",
            game.name(billiards_rules::Seat::A),
            f.scores[0],
            f.scores[1],
            game.name(billiards_rules::Seat::B),
            f.highest_break[0],
            f.highest_break[1]
        ));
        ui.label(format!(
            "frames {} - {} (best of {})",
            game.frames.frames[0], game.frames.frames[1], game.frames.best_of
        ));
        match game.frames.winner() {
            Some(winner) => {
                ui.label(format!("{} wins the match", game.name(winner)));
                if ui.button("New game...").clicked() {
                    commands.write(TurnCommand::OpenDialog);
                }
            }
            None => {
                if ui.button("Next frame").clicked() {
                    commands.write(TurnCommand::NextRack);
                }
            }
        }
    });
}
