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
            "{striker} plays {} next",
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

/// A human to play: the balls the rules let them nominate (snooker's colour after a red or
/// free ball, 2.12, 3.12; without one the ball hit first counts), and the concession where
/// the game has one (snooker's frame, 2.1(a)). Nothing on the opening stroke unless either
/// applies (issue 48: an empty window at the break-off).
pub(super) fn declare(
    ctx: &egui::Context,
    game: &LiveGame,
    commands: &mut MessageWriter<TurnCommand>,
) {
    use billiards_rules::Declaration;
    let turn = game.rules.turn();
    let nominate = &turn.declare.nominate;
    let concession = !turn.opening && game.rules.concedes();
    if nominate.is_empty() && !concession {
        return;
    }
    let title = if nominate.is_empty() {
        "Game"
    } else {
        "Nominate"
    };
    egui::Window::new(title)
        .id(egui::Id::new("live declare"))
        .collapsible(true)
        .default_open(!nominate.is_empty())
        .resizable(false)
        .anchor(egui::Align2::RIGHT_BOTTOM, [-10.0, -10.0])
        .show(ctx, |ui| {
            ui.label(format!("ball on: {}", turn.ball_on));
            if !nominate.is_empty() {
                ui.label("Nominate a ball (else the one hit first counts):");
                ui.horizontal_wrapped(|ui| {
                    // One button a name: fifteen reds are one "red" (the one hit first).
                    let mut seen: Vec<String> = Vec::new();
                    for &ball in nominate {
                        let name = game.rules.ball_name(ball);
                        if seen.contains(&name) {
                            continue;
                        }
                        seen.push(name.clone());
                        let chosen = game.declared == Declaration::Nominate { ball };
                        if ui.selectable_label(chosen, name).clicked() {
                            commands.write(TurnCommand::Declare(Declaration::Nominate { ball }));
                        }
                    }
                });
            }
            if concession
                && ui
                    .button("Concede")
                    .on_hover_text("the opponent wins this game (WPBSA 2.1(a) in snooker)")
                    .clicked()
            {
                commands.write(TurnCommand::Concede);
            }
        });
}
