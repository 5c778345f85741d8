//! The game's windows: the HUD lines of a match in play (drawn inside the HUD), the
//! new-game dialog, the verdict with its options, the call of a pocket and the end of a rack.
//! They read [`Rules`] and the [`Turn`] and write [`TurnCommand`] / [`NewGameRequested`] only.

use bevy::prelude::*;
use bevy_egui::{EguiContexts, egui};
use billiards_ai::Level;
use billiards_rules::{Call, CallRule, Game};

use super::layout::{INFO, PANEL_WIDTH, WARNING};
use crate::{
    computer::{Computer, HintRequested},
    game::{NewGameRequested, Rules, Turn, TurnCommand, clock_seed},
};

/// What the new-game dialog holds between frames.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct NewGameForm {
    /// The game chosen.
    pub game: Game,
    /// The players' names.
    pub players: [String; 2],
    /// Racks to win.
    pub race_to: u32,
    /// Each seat: a human (`None`) or the computer at a level.
    pub computer: [Option<Level>; 2],
}

impl Default for NewGameForm {
    fn default() -> Self {
        Self {
            game: Game::NineBall,
            players: ["Player 1".to_owned(), "Player 2".to_owned()],
            race_to: 3,
            computer: [None, Some(Level::Medium)],
        }
    }
}

/// Copies every new game (from the dialog, `--game` at launch, a test) into the dialog's
/// form, so that the dialog opens on the match in play rather than on its defaults.
pub fn remember_new_game(
    mut requests: MessageReader<NewGameRequested>,
    mut form: ResMut<NewGameForm>,
) {
    for r in requests.read() {
        *form = NewGameForm {
            game: r.game,
            players: r.players.clone(),
            race_to: r.race_to,
            computer: r.computer,
        };
    }
}

/// What the game's windows read and write.
#[derive(bevy::ecs::system::SystemParam)]
pub struct GameParam<'w> {
    rules: Res<'w, Rules>,
    turn: Option<Res<'w, State<Turn>>>,
    form: ResMut<'w, NewGameForm>,
    commands: MessageWriter<'w, TurnCommand>,
    new_games: MessageWriter<'w, NewGameRequested>,
    computer: Res<'w, Computer>,
    hints: MessageWriter<'w, HintRequested>,
}

/// The match's lines and the buttons of the phase, inside the HUD window.
pub fn hud_section(ui: &mut egui::Ui, state: &mut GameParam) {
    let Some(turn) = state.turn.as_ref().map(|t| *t.get()) else {
        return;
    };
    match &state.rules.game {
        None => {
            ui.label("free play");
        }
        Some(game) => {
            for (k, line) in game.hud_lines(turn).into_iter().enumerate() {
                if k == 1 {
                    ui.colored_label(INFO, line);
                } else if line.starts_with("last foul") {
                    ui.colored_label(WARNING, line);
                } else {
                    ui.label(line);
                }
            }
            let next = game.next();
            let human = game.computer(next.shooter).is_none();
            if let Some(doing) = &state.computer.doing {
                ui.colored_label(INFO, doing);
            }
            if let Some((key, hint)) = &state.computer.hint
                && *key == game.turn_key()
            {
                ui.colored_label(INFO, hint);
            }
            if human && matches!(turn, Turn::Aiming | Turn::BallInHand) {
                ui.horizontal(|ui| {
                    if ui
                        .button("Hint")
                        .on_hover_text("the computer's choice for you, shown as your aim")
                        .clicked()
                    {
                        state.hints.write(HintRequested);
                    }
                    if next.call != CallRule::NotUsed && ui.button("Call a pocket").clicked() {
                        state.commands.write(TurnCommand::StartCalling);
                    }
                    if game.call != Call::None && ui.button("Clear the call").clicked() {
                        state.commands.write(TurnCommand::Call(Call::None));
                    }
                    if next.push_out_allowed
                        && game.call != Call::PushOut
                        && ui.button("Declare a push out").clicked()
                    {
                        state.commands.write(TurnCommand::Call(Call::PushOut));
                    }
                });
            }
        }
    }
    if turn != Turn::NewGame && ui.button("New game...").clicked() {
        state.commands.write(TurnCommand::OpenDialog);
    }
    ui.separator();
}

/// The windows of the phase: new game, verdict, calling, game over.
pub fn game_windows(mut contexts: EguiContexts, mut state: GameParam) -> Result {
    let ctx = contexts.ctx_mut()?.clone();
    let Some(turn) = state.turn.as_ref().map(|t| *t.get()) else {
        return Ok(());
    };
    let centre = |title: &str| {
        egui::Window::new(title.to_owned())
            .collapsible(false)
            .resizable(false)
            // Centred on the 3D view, right of the panel (which is drawn over windows).
            .anchor(egui::Align2::CENTER_BOTTOM, [PANEL_WIDTH / 2.0, -40.0])
    };
    match turn {
        Turn::NewGame => {
            centre("New game").show(&ctx, |ui| new_game_form(ui, &mut state));
        }
        Turn::Verdict => {
            let Some(game) = &state.rules.game else {
                return Ok(());
            };
            centre("Verdict").show(&ctx, |ui| {
                if let Some(verdict) = &game.last {
                    ui.label(format!(
                        "{}: {}",
                        game.name(verdict.shooter),
                        verdict.reason()
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
                if game.computer(next.shooter).is_some() {
                    ui.label(format!(
                        "{} (computer) {} next",
                        game.name(next.shooter),
                        if next.choices.is_empty() {
                            "shoots"
                        } else {
                            "chooses"
                        }
                    ));
                } else if next.choices.is_empty() {
                    ui.label(format!("{} shoots next", game.name(next.shooter)));
                    if ui.button("Continue (Enter)").clicked() {
                        state.commands.write(TurnCommand::Continue);
                    }
                } else {
                    ui.label(format!("{} chooses:", game.name(next.shooter)));
                    ui.horizontal(|ui| {
                        for &choice in &next.choices {
                            if ui.button(choice.label()).clicked() {
                                state.commands.write(TurnCommand::Choose(choice));
                            }
                        }
                    });
                }
            });
        }
        Turn::Calling => {
            let Some(game) = &state.rules.game else {
                return Ok(());
            };
            centre("Call").show(&ctx, |ui| {
                let next = game.next();
                if next.call == CallRule::EightPocket {
                    ui.label("The 8: click the pocket on the table.");
                } else {
                    ui.horizontal(|ui| {
                        ui.label("Ball:");
                        for &ball in &next.legal_first {
                            let chosen = game.call_ball == Some(ball);
                            if ui.selectable_label(chosen, ball.to_string()).clicked() {
                                state.commands.write(TurnCommand::CallBall(ball));
                            }
                        }
                    });
                    ui.label("Then click the pocket on the table.");
                }
                ui.horizontal(|ui| {
                    if next.call == CallRule::Optional && ui.button("Call a safety").clicked() {
                        state.commands.write(TurnCommand::Call(Call::Safety));
                    }
                    if ui.button("No call").clicked() {
                        state.commands.write(TurnCommand::Call(Call::None));
                    }
                });
            });
        }
        Turn::GameOver => {
            let Some(game) = &state.rules.game else {
                return Ok(());
            };
            centre("Rack over").show(&ctx, |ui| {
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
                            state.commands.write(TurnCommand::OpenDialog);
                        }
                    }
                    None => {
                        if ui.button("Next rack").clicked() {
                            state.commands.write(TurnCommand::NextRack);
                        }
                    }
                }
            });
        }
        Turn::Aiming | Turn::BallInHand | Turn::ShotInPlay => {}
    }
    Ok(())
}

fn new_game_form(ui: &mut egui::Ui, state: &mut GameParam) {
    let form = &mut *state.form;
    ui.horizontal(|ui| {
        ui.label("Game:");
        ui.selectable_value(&mut form.game, Game::NineBall, "9-ball");
        ui.selectable_value(&mut form.game, Game::EightBall, "8-ball");
        ui.selectable_value(&mut form.game, Game::FreePlay, "free play");
    });
    if form.game != Game::FreePlay {
        for (k, (name, seat)) in form
            .players
            .iter_mut()
            .zip(form.computer.iter_mut())
            .enumerate()
        {
            ui.horizontal(|ui| {
                ui.label(format!("Player {}:", k + 1));
                ui.add(egui::TextEdit::singleline(name).desired_width(140.0));
                ui.selectable_value(seat, None, "human");
                for level in Level::ALL {
                    ui.selectable_value(seat, Some(level), format!("computer {level}"));
                }
            });
        }
        ui.horizontal(|ui| {
            ui.label("Race to");
            ui.add(egui::DragValue::new(&mut form.race_to).range(1..=15));
            ui.label("racks; player 1 breaks first, then the break alternates");
        });
    }
    ui.horizontal(|ui| {
        if ui.button("Start").clicked() {
            let request = NewGameRequested {
                game: form.game,
                players: form.players.clone(),
                race_to: form.race_to,
                seed: clock_seed(),
                computer: form.computer,
            };
            state.new_games.write(request);
        }
        if ui.button("Cancel").clicked() {
            state.commands.write(TurnCommand::CloseDialog);
        }
    });
}

#[cfg(test)]
mod tests {
    // Named from the crate root: a `super::` path reads as a use of `ui` in the layout test.
    use crate::game::NewGameRequested;
    use crate::ui::game::{NewGameForm, remember_new_game};
    use bevy::prelude::*;
    use billiards_ai::Level;
    use billiards_rules::Game;

    /// A match started from outside the dialog (`--game eight-ball`, hard against easy)
    /// is what the dialog shows next, not its defaults (9-ball, a human against medium).
    #[test]
    fn the_dialog_opens_on_the_match_in_play() {
        let mut app = App::new();
        app.add_message::<NewGameRequested>()
            .init_resource::<NewGameForm>()
            .add_systems(Update, remember_new_game);
        app.world_mut().write_message(NewGameRequested {
            game: Game::EightBall,
            players: ["Ann".to_owned(), "Bob".to_owned()],
            race_to: 5,
            seed: 1,
            computer: [Some(Level::Hard), Some(Level::Easy)],
        });
        app.update();
        let form = app.world().resource::<NewGameForm>();
        assert_eq!(form.game, Game::EightBall);
        assert_eq!(form.players, ["Ann".to_owned(), "Bob".to_owned()]);
        assert_eq!(form.race_to, 5);
        assert_eq!(form.computer, [Some(Level::Hard), Some(Level::Easy)]);
    }
}
