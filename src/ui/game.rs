//! The game's windows: the HUD lines of a match in play (drawn inside the HUD), the
//! new-game dialog, the verdict with its options, the call of a pocket and the end of a rack.
//! They read [`Rules`] and the [`Turn`] and write [`TurnCommand`] / [`NewGameRequested`] (or,
//! for a drill, [`DrillRequested`]) only.

use bevy::prelude::*;
use bevy_egui::{EguiContexts, egui};

use super::layout::{HUD_BUTTON_WIDTH, HudLine, INFO, PANEL_WIDTH, WARNING};
use super::live_windows;
use super::new_game::{NewGameForm, seat_rows};
use crate::{
    play::computer::{Computer, HintRequested},
    play::game::{FREE_PLAY, GameChoice, NewGameRequested, Rules, Turn, TurnCommand},
    practice::{DrillBests, DrillList, DrillRequested},
    settings::{TableSetup, rack_style_label, table_choices, table_label},
    sim::{Solver, clock_seed},
    view::camera::OrbitCamera,
};

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
    setup: Res<'w, TableSetup>,
    solver: Option<Res<'w, Solver>>,
    view: Res<'w, OrbitCamera>,
    drills: Res<'w, DrillList>,
    bests: Res<'w, DrillBests>,
    drill_requests: MessageWriter<'w, DrillRequested>,
    shot: Res<'w, crate::settings::ShotSettings>,
}

/// The HUD's buttons' labels, in their order (the layout check finds them by these).
pub const HUD_BUTTONS: [&str; 5] = [
    "New game...",
    "Hint",
    "Call a pocket",
    "Clear the call",
    "Push out",
];

/// Whether a human is to shoot in the match in play (aiming, or with the ball in hand).
pub fn human_to_shoot(state: &GameParam) -> bool {
    let turn = state.turn.as_ref().map(|t| *t.get());
    matches!(turn, Some(Turn::Aiming | Turn::BallInHand))
        && state
            .rules
            .to_play()
            .is_some_and(|(level, _)| level.is_none())
}

/// Whether the table is in free play (no match in play).
pub fn free_play(state: &GameParam) -> bool {
    !state.rules.in_match()
}

/// The game whose own table is on screen (snooker's, three-cushion's, else pool's): it names
/// the balls where no game is in hand (a replay; [`billiards_rules::catalog::of_table`]).
pub fn table_game(state: &GameParam) -> &'static billiards_rules::catalog::GameEntry {
    let table = state
        .solver
        .as_ref()
        .map_or_else(billiards_physics::Table::wpa_8ft, |s| {
            *s.simulation().table()
        });
    billiards_rules::catalog::of_table(&table)
}

/// The HUD's buttons, one row, each always in its place: disabled when it does not apply
/// (free play, the computer's turn, a replay), never moved or hidden.
pub fn hud_buttons(ui: &mut egui::Ui, state: &mut GameParam) {
    use billiards_rules::{Declaration, Need};
    let turn = state.turn.as_ref().map(|t| *t.get());
    let game = state.rules.live.as_ref();
    let declare = game.map(|g| g.rules.turn().declare);
    let declared = game.map_or(Declaration::None, |g| g.declared);
    let human_to_shoot = human_to_shoot(state);
    let size = egui::vec2(HUD_BUTTON_WIDTH, 0.0);
    ui.horizontal(|ui| {
        let new_game = ui.add_enabled(
            turn.is_some_and(|t| t != Turn::NewGame),
            egui::Button::new(HUD_BUTTONS[0]).min_size(size),
        );
        if new_game.clicked() {
            state.commands.write(TurnCommand::OpenDialog);
        }
        let hint = ui
            .add_enabled(
                human_to_shoot,
                egui::Button::new(HUD_BUTTONS[1]).min_size(size),
            )
            .on_hover_text("the computer's choice for you, shown as your aim (and its call)");
        if hint.clicked() {
            state.hints.write(HintRequested);
        }
        let can_call = human_to_shoot
            && declare
                .as_ref()
                .is_some_and(|d| d.pocket != Need::NotUsed && !d.callable.is_empty());
        if ui
            .add_enabled(can_call, egui::Button::new(HUD_BUTTONS[2]).min_size(size))
            .on_hover_text("pool: the ball and pocket, proposed from your aim")
            .clicked()
        {
            state.commands.write(TurnCommand::StartCalling);
        }
        // A nomination has its own window; this clears pool's calls.
        let called = !matches!(declared, Declaration::None | Declaration::Nominate { .. });
        if ui
            .add_enabled(
                human_to_shoot && called,
                egui::Button::new(HUD_BUTTONS[3]).min_size(size),
            )
            .clicked()
        {
            state
                .commands
                .write(TurnCommand::Declare(Declaration::None));
        }
        let push_out = human_to_shoot
            && declare.as_ref().is_some_and(|d| d.push_out)
            && declared != Declaration::PushOut;
        if ui
            .add_enabled(push_out, egui::Button::new(HUD_BUTTONS[4]).min_size(size))
            .on_hover_text("9-ball, 10-ball, right after the break: declare a push out (WPA 2.4)")
            .clicked()
        {
            state
                .commands
                .write(TurnCommand::Declare(Declaration::PushOut));
        }
    });
}

/// The HUD's lines about the match: who is to do what, the computer's plan and the hint
/// (first column); the balls on, groups, call, fouls and the last verdict (second column).
pub fn hud_lines(state: &GameParam) -> (Vec<HudLine>, Vec<HudLine>) {
    let Some(turn) = state.turn.as_ref().map(|t| *t.get()) else {
        return (Vec::new(), Vec::new());
    };
    let Some(game) = &state.rules.live else {
        return (vec![("free play".to_owned(), None)], Vec::new());
    };
    // Balls the shot in play has dropped so far: "balls left" counts them off at once.
    let dropped: Vec<u8> = match (&state.solver, turn) {
        (Some(solver), Turn::ShotInPlay) => {
            let sim = solver.simulation();
            (0..sim.ball_count())
                .filter(|&id| !sim.ball(id).motion.on_table())
                .map(|id| sim.numbers()[id])
                .collect()
        }
        _ => Vec::new(),
    };
    let lines = game.hud_lines(turn, &dropped);
    split_lines(state, lines, 1, |_, _| false, game.turn_key())
}

/// The match's HUD lines in two columns: up to the turn's line (at `turn_line`, in the info
/// colour) in the first, with the computer's doing and the hint after it; the rest in the
/// second, the last foul and what `warn` picks in the warning colour.
fn split_lines(
    state: &GameParam,
    lines: Vec<String>,
    turn_line: usize,
    warn: impl Fn(usize, &str) -> bool,
    key: crate::play::computer::TurnKey,
) -> (Vec<HudLine>, Vec<HudLine>) {
    let (mut first, mut second) = (Vec::new(), Vec::new());
    for (k, line) in lines.into_iter().enumerate() {
        let colour = if k == turn_line {
            Some(INFO)
        } else if line.starts_with("last foul") || warn(k, &line) {
            Some(WARNING)
        } else {
            None
        };
        if k <= turn_line {
            first.push((line, colour));
        } else {
            second.push((line, colour));
        }
    }
    if let Some(doing) = &state.computer.doing {
        first.push((doing.clone(), Some(INFO)));
    }
    if let Some((hint_key, hint)) = &state.computer.hint
        && *hint_key == key
    {
        // A hint's odds are those of its own aim (issue 48: "61 % to succeed" stayed after
        // the aim moved): once the player's aim or nomination leaves it, it says so.
        let game = state.rules.live.as_ref();
        let text = if hint_left(hint, &state.shot, game) {
            "hint: your aim has left the hint's shot (Hint again for its odds)".to_owned()
        } else {
            hint.text(game.map(|g| g.rules.as_ref()), &state.view)
        };
        first.push((text, Some(INFO)));
    }
    (first, second)
}

/// Whether the player's aim (angle, power, tip, elevation) or nomination (in `game`, the
/// game in play: snooker's colour after a red) is no longer the hint's.
pub fn hint_left(
    hint: &crate::play::computer::Hint,
    shot: &crate::settings::ShotSettings,
    game: Option<&crate::play::game::LiveGame>,
) -> bool {
    use crate::play::computer::Hint;
    use billiards_ai::any_game::Move;
    use billiards_rules::Declaration;
    let Hint::Decided(decision) = hint else {
        return false;
    };
    if let Some(game) = game
        && let Some(Move::Strike(stroke)) = decision.as_move(game.rules.as_ref())
        && matches!(stroke.declared, Declaration::Nominate { .. })
        && stroke.declared != game.declared
    {
        return true;
    }
    let Some((aim, _)) = decision.aim() else {
        return false;
    };
    let turn = (shot.angle - aim.angle).rem_euclid(std::f64::consts::TAU);
    // A thousandth of a radian (0.06 degree) or 1 cm/s: a key tap moves more than either.
    let angle_moved = turn.min(std::f64::consts::TAU - turn) > 1e-3;
    let tip_moved = (shot.tip.side - aim.tip.side).abs() > 1e-3
        || (shot.tip.height - aim.tip.height).abs() > 1e-3;
    angle_moved
        || (shot.power - aim.speed).abs() > 0.01
        || tip_moved
        || (shot.elevation - aim.elevation.to_degrees()).abs() > 0.05
}

/// The height of the strip the table's view leaves free at the bottom for the docked
/// verdict or end-of-rack window (0: none); the timeline strip reads it.
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq)]
pub struct VerdictStrip(pub f32);

/// The docked window's margin from the window's edge.
const DOCK_MARGIN: f32 = 8.0;

/// The strip's height before its window has been laid out once.
const VERDICT_STRIP_MIN: f32 = 90.0;

/// The windows of the phase: new game, verdict, calling, game over.
pub fn game_windows(
    mut contexts: EguiContexts,
    mut state: GameParam,
    mut strip: ResMut<VerdictStrip>,
) -> Result {
    let ctx = contexts.ctx_mut()?.clone();
    let turn = state.turn.as_ref().map(|t| *t.get());
    // The verdict and the end of a rack sit in a strip the table's view leaves free at the
    // bottom (issue 48: the verdict window covered balls on the cloth), as tall as the
    // window was at its last pass; the new-game dialog, modal, sits over the table.
    let docked = match turn {
        Some(Turn::Verdict) => Some("Verdict"),
        Some(Turn::GameOver) => Some("Game over"),
        _ => None,
    };
    let height = docked.map_or(0.0, |title| {
        ctx.memory(|m| m.area_rect(egui::Id::new(title)))
            .map_or(VERDICT_STRIP_MIN, |r| {
                (r.height() + 2.0 * DOCK_MARGIN).max(VERDICT_STRIP_MIN)
            })
    });
    if (strip.0 - height).abs() >= 1.0 {
        strip.0 = height;
        // Laid out again at once (egui's multi-pass mode): no frame shows it over the table.
        ctx.request_discard("the docked window changed its height");
        ctx.request_repaint();
    }
    let Some(turn) = turn else {
        return Ok(());
    };
    let centre = |title: &str| {
        let window = egui::Window::new(title.to_owned())
            .id(egui::Id::new(title))
            .collapsible(false)
            .resizable(false);
        if docked == Some(title) {
            // In the strip below the table's view, centred right of the panel.
            window.anchor(
                egui::Align2::CENTER_BOTTOM,
                [PANEL_WIDTH / 2.0, -DOCK_MARGIN],
            )
        } else {
            // Centred on the 3D view, right of the panel (which is drawn over windows).
            window.anchor(egui::Align2::CENTER_BOTTOM, [PANEL_WIDTH / 2.0, -40.0])
        }
    };
    match turn {
        Turn::NewGame => {
            centre("New game").show(&ctx, |ui| new_game_form(ui, &mut state));
        }
        Turn::Verdict if let Some(game) = &state.rules.live => {
            centre("Verdict").show(&ctx, |ui| {
                live_windows::verdict(ui, game, &mut state.commands)
            });
        }
        // A drill's try over: the drill's own window offers the next try.
        Turn::GameOver
            if let Some(game) = &state.rules.live
                && !game.rules.solo() =>
        {
            centre("Game over").show(&ctx, |ui| {
                live_windows::game_over(ui, game, &mut state.commands)
            });
        }
        Turn::Calling if let Some(game) = &state.rules.live => {
            centre("Call").show(&ctx, |ui| live_windows::call(ui, game, &mut state.commands));
        }
        Turn::Verdict | Turn::GameOver | Turn::Calling => {}
        Turn::Aiming | Turn::BallInHand if human_to_shoot(&state) => {
            if let Some(game) = &state.rules.live {
                live_windows::declare(&ctx, game, &mut state.commands);
            }
        }
        Turn::Aiming | Turn::BallInHand | Turn::ShotInPlay => {}
    }
    Ok(())
}

/// The new-game dialog: the game, the table and rack, the players or free play's drill, then
/// Start (asking first over a game in progress) or Cancel.
fn new_game_form(ui: &mut egui::Ui, state: &mut GameParam) {
    let form = &mut *state.form;
    let before = form.game;
    ui.horizontal(|ui| {
        ui.label("Game:");
        for choice in GameChoice::ALL {
            ui.selectable_value(&mut form.game, choice, choice.label());
        }
    });
    if form.game != before {
        // Each game's own usual length: three-cushion's 40 points, not a race to 3.
        form.race_to = form.game.length().1;
    }
    let own_table = !form.game.pool_table();
    let setup = form.setup.get_or_insert(*state.setup);
    // A game with its own table (snooker, three-cushion) and layout: the pool rows give way
    // to it.
    if let GameChoice::Catalog(id) = form.game
        && own_table
    {
        ui.label(own_table_text(id));
    } else {
        ui.horizontal(|ui| {
            ui.label("Table:");
            egui::ComboBox::from_id_salt("new-game-table")
                .selected_text(table_label(setup.table))
                .width(230.0)
                .show_ui(ui, |ui| {
                    for choice in table_choices() {
                        ui.selectable_value(&mut setup.table, choice, table_label(choice));
                    }
                });
        });
    }
    // The drills are played from free play's table (their own position, their own tries).
    if form.game == FREE_PLAY {
        drill_row(ui, form, &state.drills, &state.bests);
    } else {
        form.drill = None;
        if !own_table {
            ui.horizontal(|ui| {
                ui.label("Rack:");
                for style in billiards_rules::RackStyle::ALL {
                    ui.selectable_value(&mut setup.rack_style, style, rack_style_label(style));
                }
            });
        }
        seat_rows(ui, form);
    }
    // A game with shots in it ends only when the player says so (as the rack buttons ask).
    let in_progress = state.solver.as_ref().is_some_and(|s| s.in_progress());
    if form.confirm {
        ui.colored_label(
            WARNING,
            "This ends the game in progress (it stays in the recordings).",
        );
    }
    ui.horizontal(|ui| {
        let start = if form.confirm {
            "End it and start"
        } else {
            "Start"
        };
        let clicked = ui.button(start).clicked();
        if clicked && in_progress && !form.confirm {
            form.confirm = true;
        } else if clicked && let Some(index) = form.drill {
            form.confirm = false;
            state.drill_requests.write(DrillRequested { index });
        } else if clicked {
            form.confirm = false;
            let request = NewGameRequested {
                game: form.game,
                players: form.players.clone(),
                race_to: form.race_to,
                seed: clock_seed(),
                computer: form.computer,
                setup: form.setup.unwrap_or(*state.setup),
            };
            state.new_games.write(request);
        }
        if ui.button("Cancel").clicked() {
            form.confirm = false;
            state.commands.write(TurnCommand::CloseDialog);
        }
    });
}

/// A catalog game's own table in words: "Table: 2.84 x 1.42 m without pockets, 61.5 mm
/// balls".
fn own_table_text(id: &str) -> String {
    match billiards_rules::catalog::find(id) {
        Ok(entry) => {
            let (table, ball) = (entry.equipment)();
            let pockets = if table.pockets == billiards_physics::PocketShape::Pocketless {
                " without pockets"
            } else {
                ""
            };
            format!(
                "Table: {:.2} x {:.2} m{pockets}, {:.1} mm balls",
                table.length,
                table.width,
                ball.radius * 2000.0
            )
        }
        Err(error) => format!("Table: {error}"),
    }
}

/// Free play's drill choice: none, or a drill of the list with its best session. A refused
/// file is listed, greyed, with why.
fn drill_row(ui: &mut egui::Ui, form: &mut NewGameForm, drills: &DrillList, bests: &DrillBests) {
    let label = |choice: Option<usize>| match choice.and_then(|k| drills.drills.get(k)) {
        None => "none: free play".to_owned(),
        Some((_, Ok(drill))) => drill.name.clone(),
        Some((file, Err(_))) => file.clone(),
    };
    ui.horizontal(|ui| {
        ui.label("Drill:");
        egui::ComboBox::from_id_salt("new-game-drill")
            .selected_text(label(form.drill))
            .width(230.0)
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut form.drill, None, label(None));
                for (k, (file, drill)) in drills.drills.iter().enumerate() {
                    let text = match (drill, bests.0.get(file)) {
                        (Ok(d), Some(b)) => {
                            format!("{}  (best {} of {})", d.name, b.successes, b.tries)
                        }
                        (Ok(d), None) => d.name.clone(),
                        (Err(why), _) => format!("{file}: {why}"),
                    };
                    ui.add_enabled_ui(drill.is_ok(), |ui| {
                        ui.selectable_value(&mut form.drill, Some(k), text);
                    });
                }
            });
    });
    if let Some(Some((_, Ok(drill)))) = form.drill.map(|k| drills.drills.get(k)) {
        ui.label(format!("{} ({} tries)", drill.description, drill.tries));
    }
}
