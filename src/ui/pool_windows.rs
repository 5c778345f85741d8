//! The windows of a pool match's phases: the verdict with the player's choices, the call of
//! a ball and pocket, the end of a rack. Each writes [`TurnCommand`]s only.

use bevy::prelude::*;
use bevy_egui::egui;
use billiards_rules::{Call, CallRule};

use crate::play::game::{GameInPlay, TurnCommand};

/// The verdict of the last shot, then what comes next: the next shot, the computer's
/// choice, or the player's choices (WPA 1.6, 2.4).
pub(super) fn verdict(
    ui: &mut egui::Ui,
    game: &GameInPlay,
    commands: &mut MessageWriter<TurnCommand>,
) {
    if let Some(verdict) = &game.last {
        ui.label(format!(
            "{}: {}",
            game.name(verdict.shooter),
            game.verdict_text(verdict)
        ));
        if let Some(group) = verdict.assigned {
            ui.label(format!(
                "{} takes the {}",
                game.name(verdict.shooter),
                group.name()
            ));
        }
    }
    let next = game.next();
    if game.computer(next.shooter).is_some() && !next.choices.is_empty() {
        ui.label(format!(
            "{} (computer) chooses next",
            game.name(next.shooter)
        ));
    } else if next.choices.is_empty() {
        ui.label(game.next_text());
        // Between two computers the verdict goes on by itself.
        if game.has_human() && ui.button("Continue (Enter)").clicked() {
            commands.write(TurnCommand::Continue);
        }
    } else {
        ui.label(format!("{} chooses:", game.name(next.shooter)));
        ui.horizontal(|ui| {
            for &choice in &next.choices {
                if ui.button(choice.label()).clicked() {
                    commands.write(TurnCommand::Choose(choice));
                }
            }
        });
    }
}

/// The call: the ball and pocket the aim proposes, or a ball chosen and its pocket clicked on
/// the table; a safety or no call.
pub(super) fn call(
    ui: &mut egui::Ui,
    game: &GameInPlay,
    commands: &mut MessageWriter<TurnCommand>,
) {
    let next = game.next();
    // What the aim sends into a pocket, one click to confirm.
    if let Some(call) = game.proposed
        && let Some(text) = call.text()
    {
        if ui.button(format!("Call {text} (your aim)")).clicked() {
            commands.write(TurnCommand::Call(call));
        }
        ui.label("or choose another:");
    }
    if next.call == CallRule::EightPocket {
        ui.label("The 8: click the pocket on the table.");
    } else {
        ui.horizontal(|ui| {
            ui.label("Ball:");
            // 10-ball calls any ball on the table (WPA 9.5), others the legal.
            let callable = match next.call {
                CallRule::BallAndPocket => &game.rack().on_table,
                _ => &next.legal_first,
            };
            for &ball in callable {
                let chosen = game.call_ball == Some(ball);
                if ui.selectable_label(chosen, ball.to_string()).clicked() {
                    commands.write(TurnCommand::CallBall(ball));
                }
            }
        });
        ui.label("Then click the pocket on the table.");
    }
    ui.horizontal(|ui| {
        let safety = matches!(next.call, CallRule::Optional | CallRule::BallAndPocket);
        if safety && ui.button("Call a safety").clicked() {
            commands.write(TurnCommand::Call(Call::Safety));
        }
        if ui.button("No call").clicked() {
            commands.write(TurnCommand::Call(Call::None));
        }
    });
}

/// The end of a rack: its winner and why, the match's score, the next rack or a new game.
pub(super) fn rack_over(
    ui: &mut egui::Ui,
    game: &GameInPlay,
    commands: &mut MessageWriter<TurnCommand>,
) {
    if let Some((winner, reason)) = game.rack().over {
        ui.label(format!("{} wins the rack: {reason}", game.name(winner)));
    }
    let play = &game.play;
    ui.label(format!(
        "{} {} - {} {} (race to {})",
        play.players[0], play.score[0], play.score[1], play.players[1], play.race_to
    ));
    match play.winner() {
        Some(winner) => {
            ui.label(format!("{} wins the match", game.name(winner)));
            if ui.button("New game...").clicked() {
                commands.write(TurnCommand::OpenDialog);
            }
        }
        None => {
            if ui.button("Next rack").clicked() {
                commands.write(TurnCommand::NextRack);
            }
        }
    }
}
