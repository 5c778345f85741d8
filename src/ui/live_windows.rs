//! The windows of a game behind the one interface ([`LiveGame`]): the verdict with the
//! options the rules offer, the call of a ball and pocket, the nomination and concession,
//! and the end of a game. Every word comes from the game.

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
        ui.label(game.next_text());
        // Between two computers the verdict goes on by itself.
        if game.has_human() && ui.button("Continue (Enter)").clicked() {
            commands.write(TurnCommand::Continue);
        }
    }
}

/// The call (WPA 1.6, 3.8, 9.5): the ball and pocket the aim proposes, or a ball chosen and
/// its pocket clicked on the table; a safety, or no call.
pub(super) fn call(ui: &mut egui::Ui, game: &LiveGame, commands: &mut MessageWriter<TurnCommand>) {
    use billiards_rules::Declaration;
    let turn = game.rules.turn();
    let name = |ball: u8| game.rules.ball_name(ball);
    // What the aim sends into a pocket, one click to confirm.
    if let Some(call) = game.proposed
        && let Some(text) = call.text(&name)
    {
        if ui.button(format!("Call {text} (your aim)")).clicked() {
            commands.write(TurnCommand::Declare(call));
        }
        ui.label("or choose another:");
    }
    match turn.declare.callable.as_slice() {
        [only] => {
            ui.label(format!(
                "{}: click the pocket on the table.",
                capitalised(&name(*only))
            ));
        }
        callable => {
            ui.horizontal_wrapped(|ui| {
                ui.label("Ball:");
                for &ball in callable {
                    let chosen = game.call_ball == Some(ball);
                    let label = name(ball);
                    let label = label.strip_prefix("the ").unwrap_or(&label).to_owned();
                    if ui.selectable_label(chosen, label).clicked() {
                        commands.write(TurnCommand::CallBall(ball));
                    }
                }
            });
            ui.label("Then click the pocket on the table.");
        }
    }
    ui.horizontal(|ui| {
        if turn.declare.safety && ui.button("Call a safety").clicked() {
            commands.write(TurnCommand::Declare(Declaration::Safety));
        }
        if ui.button("No call").clicked() {
            commands.write(TurnCommand::Declare(Declaration::None));
        }
    });
}

/// `text` with its first letter in capitals ("the 8" as "The 8").
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars.next().map_or_else(String::new, |first| {
        first.to_uppercase().chain(chars).collect()
    })
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
    } else if ui.button(format!("Next {}", game.game_noun())).clicked() {
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
