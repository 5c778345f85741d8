//! The new-game dialog's form, kept between frames and set from every new game started (the
//! dialog opens on the match in play).

use bevy::prelude::*;
use bevy_egui::egui;
use billiards_ai::Level;

use crate::{
    play::game::{GameChoice, NewGameRequested},
    settings::TableSetup,
};

/// What the new-game dialog holds between frames.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct NewGameForm {
    /// The game chosen.
    pub game: GameChoice,
    /// The players' names.
    pub players: [String; 2],
    /// Racks to win.
    pub race_to: u32,
    /// Each seat: a human (`None`) or the computer at a level.
    pub computer: [Option<Level>; 2],
    /// The table and rack style; `None` until the dialog first opens, then the table in play.
    pub setup: Option<TableSetup>,
    /// Start was pressed over a game in progress: the dialog asks before ending it.
    pub confirm: bool,
    /// In free play, the drill to start (its place in the
    /// [`DrillList`](crate::practice::drill_list::DrillList)).
    pub drill: Option<usize>,
}

impl Default for NewGameForm {
    fn default() -> Self {
        Self {
            game: GameChoice::Catalog("nine-ball"),
            players: ["Player 1".to_owned(), "Player 2".to_owned()],
            race_to: 3,
            computer: [None, Some(Level::Medium)],
            setup: None,
            confirm: false,
            drill: None,
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
            setup: Some(r.setup),
            confirm: false,
            drill: None,
        };
    }
}

/// The players' rows (name, human or the computer at a level) and the race: racks, or
/// frames of a snooker match (best of an odd number, WPBSA 2.1).
pub(super) fn seat_rows(ui: &mut egui::Ui, form: &mut NewGameForm) {
    for (k, (name, seat)) in form
        .players
        .iter_mut()
        .zip(form.computer.iter_mut())
        .enumerate()
    {
        ui.horizontal(|ui| {
            ui.label(format!("Player {}:", k + 1));
            ui.add(egui::TextEdit::singleline(name).desired_width(140.0));
            // A list, not a row of choices: every level fits, however many there are.
            let label = |seat: Option<Level>| match seat {
                None => "human".to_owned(),
                Some(level) => format!("computer, {level}"),
            };
            egui::ComboBox::from_id_salt(("seat", k))
                .selected_text(label(*seat))
                .width(160.0)
                .show_ui(ui, |ui| {
                    ui.selectable_value(seat, None, label(None));
                    for level in Level::ALL {
                        ui.selectable_value(seat, Some(level), label(Some(level)));
                    }
                });
        });
    }
    if !form.game.pool_table() {
        // A game on its own table says what its length counts ("points to", "best of").
        let (unit, _) = form.game.length();
        ui.horizontal(|ui| {
            let mut unit = unit.to_owned();
            if let Some(first) = unit.get_mut(..1) {
                first.make_ascii_uppercase();
            }
            ui.label(&unit);
            ui.add(
                egui::DragValue::new(&mut form.race_to)
                    .update_while_editing(false)
                    .range(1..=200),
            );
            // WPBSA 2.1: a match is the best of an odd number of frames.
            if unit == "Best of" && form.race_to.is_multiple_of(2) {
                form.race_to += 1;
            }
            ui.label(format!("{}; player 1 opens", form.game.length_noun()));
        });
        return;
    }
    ui.horizontal(|ui| {
        ui.label("Race to");
        ui.add(
            egui::DragValue::new(&mut form.race_to)
                .update_while_editing(false)
                .range(1..=15),
        );
        ui.label("racks; player 1 breaks first, then the break alternates");
    });
}

#[cfg(test)]
mod tests {
    // Named from the crate root: a `super::` path reads as a use of `ui` in the layout test.
    use crate::play::game::NewGameRequested;
    use crate::ui::new_game::{NewGameForm, remember_new_game};
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
            game: Game::EightBall.into(),
            players: ["Ann".to_owned(), "Bob".to_owned()],
            race_to: 5,
            seed: 1,
            computer: [Some(Level::Hard), Some(Level::Easy)],
            setup: crate::settings::TableSetup::default(),
        });
        app.update();
        let form = app.world().resource::<NewGameForm>();
        assert_eq!(form.game, Game::EightBall.into());
        assert_eq!(form.players, ["Ann".to_owned(), "Bob".to_owned()]);
        assert_eq!(form.race_to, 5);
        assert_eq!(form.computer, [Some(Level::Hard), Some(Level::Easy)]);
    }
}
