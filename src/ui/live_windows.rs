//! The windows of a game behind the one interface ([`LiveGame`]): the verdict with the
//! options the rules offer, and the end of a game. Every word comes from the game.

use bevy::prelude::*;
use bevy_egui::egui;

use crate::play::game::{LiveGame, TurnCommand};

/// The verdict: the judgement's sentence, then the options offered (one button each) or
/// who plays next and Continue.
pub(super) fn verdict(
    ui: &mut egui::Ui,
    game: &LiveGame,
    commands: &mut MessageWriter<TurnCommand>,
) {
    if let Some(last) = &game.last {
        ui.label(game.verdict_text(last));
    }
    let turn = game.rules.turn();
    let striker = game.name(turn.striker);
    if !turn.choices.is_empty() && game.computer(turn.striker).is_some() {
        ui.label(format!("{striker} (computer) chooses next"));
    } else if !turn.choices.is_empty() {
        ui.label(format!("{striker} chooses:"));
        ui.horizontal_wrapped(|ui| {
            for (index, choice) in turn.choices.iter().enumerate() {
                if ui.button(choice).clicked() {
                    commands.write(TurnCommand::ChooseOption(index));
                }
            }
        });
    } else {
        ui.label(format!(
            "{striker} plays the {} next",
            game.rules.ball_name(turn.cue_ball)
        ));
        if game.has_human() && ui.button("Continue (Enter)").clicked() {
            commands.write(TurnCommand::Continue);
        }
    }
}

/// The end of a game: the winner and why, the score, then the next game of the match or,
/// once the match is won, a new game.
pub(super) fn game_over(
    ui: &mut egui::Ui,
    game: &LiveGame,
    commands: &mut MessageWriter<TurnCommand>,
) {
    if let Some(text) = game.end_text() {
        ui.label(text);
    }
    ui.label(game.rules.score_line());
    let match_over = game.rules.end().is_none_or(|end| end.match_over);
    if match_over {
        if ui.button("New game...").clicked() {
            commands.write(TurnCommand::OpenDialog);
        }
    } else if ui.button("Next game").clicked() {
        commands.write(TurnCommand::NextRack);
    }
}
