//! The Position section of the panel (the Place tool, position codes) and the drill window.
//! Widgets only write messages and the form; `crate::practice` carries them out.

use bevy::{ecs::system::SystemParam, prelude::*};
use bevy_egui::egui;

use super::layout::{BUTTON_WIDTH, PATH_FIELD_WIDTH, SUCCESS, WARNING};
use crate::{
    play::game::Rules,
    practice::{
        DrillBests, DrillCommand, DrillSession, EditRequested, Placing, PositionCode,
        PositionCommand, Practice, SaveDrillRequested,
        drill::drill_game,
        placing::{ball_name, missing_numbers},
    },
    sim::{Referee, Solver},
};

/// What a drill saved from the table asks (one goal, with or without "no foul").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GoalChoice {
    /// Pocket a ball, in a named pocket or any.
    Pocket,
    /// Hit a ball first.
    FirstContact,
    /// Pocket nothing and hide the ball: a safety.
    Safety,
}

/// The Position rows' choices, kept between frames.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct PositionForm {
    /// The ball the Add button puts on the table.
    pub add: u8,
    /// Copy puts the solver's physics in the code.
    pub with_params: bool,
    /// Copy puts the Shot section's shot in the code.
    pub with_shot: bool,
    /// A code that carries physics is played under them.
    pub own_physics: bool,
    /// "Save as drill": its name.
    pub drill_name: String,
    /// Its goal.
    pub goal: GoalChoice,
    /// The ball the goal names.
    pub goal_ball: u8,
    /// The pocket a Pocket goal names (`None`: any).
    pub goal_pocket: Option<billiards_physics::Pocket>,
    /// "No foul" goes with the goal.
    pub no_foul: bool,
    /// Tries a session gives.
    pub tries: u32,
}

impl Default for PositionForm {
    fn default() -> Self {
        Self {
            add: 0,
            with_params: false,
            with_shot: true,
            own_physics: true,
            drill_name: String::new(),
            goal: GoalChoice::Pocket,
            goal_ball: 1,
            goal_pocket: None,
            no_foul: true,
            tries: 10,
        }
    }
}

/// What the section and the drill window read and write.
#[derive(SystemParam)]
pub struct PracticeParam<'w> {
    state: Res<'w, State<Practice>>,
    next: ResMut<'w, NextState<Practice>>,
    placing: Res<'w, Placing>,
    edits: MessageWriter<'w, EditRequested>,
    positions: MessageWriter<'w, PositionCommand>,
    code: ResMut<'w, PositionCode>,
    form: ResMut<'w, PositionForm>,
    session: Option<Res<'w, DrillSession>>,
    rules: Res<'w, Rules>,
    drills: MessageWriter<'w, DrillCommand>,
    save_drill: MessageWriter<'w, SaveDrillRequested>,
    bests: Res<'w, DrillBests>,
    solver: Option<Res<'w, Solver>>,
    referee: Res<'w, Referee>,
}

/// The Position section: open, since placing balls and sharing a position are play.
pub fn section(ui: &mut egui::Ui, state: &mut PracticeParam) {
    super::settings::section(ui, "Position", true, |ui| rows(ui, state));
}

fn rows(ui: &mut egui::Ui, state: &mut PracticeParam) {
    let mode = *state.state.get();
    let free_play = state.referee.edits && mode != Practice::Drill;
    let at_rest = state
        .solver
        .as_ref()
        .is_some_and(|s| s.simulation().is_at_rest());
    ui.add_enabled_ui(free_play, |ui| {
        let mut placing = mode == Practice::Placing;
        if ui
            .toggle_value(&mut placing, "Place balls (P)")
            .on_hover_text("click a ball to pick it, then drag it or click where it goes")
            .changed()
        {
            state.next.set(if placing {
                Practice::Placing
            } else {
                Practice::Off
            });
        }
    });
    if mode == Practice::Placing {
        placing_rows(ui, state, at_rest);
    } else if !free_play {
        let why = if mode == Practice::Drill {
            "leave the drill to place balls"
        } else {
            "free play only: not during a match"
        };
        ui.label(why);
    }
    ui.separator();
    ui.horizontal(|ui| {
        ui.checkbox(&mut state.form.with_shot, "with the shot");
        ui.checkbox(&mut state.form.with_params, "with the physics");
    });
    ui.horizontal(|ui| {
        let copy = egui::Button::new("Copy code").min_size(egui::vec2(BUTTON_WIDTH * 0.7, 0.0));
        if ui
            .add_enabled(at_rest, copy)
            .on_disabled_hover_text("wait until every ball rests")
            .clicked()
        {
            state.positions.write(PositionCommand::Copy {
                with_params: state.form.with_params,
                with_shot: state.form.with_shot,
            });
        }
        if ui.button("Paste and open").clicked() {
            state.positions.write(PositionCommand::Paste {
                own_physics: state.form.own_physics,
            });
        }
    });
    ui.horizontal(|ui| {
        ui.add(
            egui::TextEdit::singleline(&mut state.code.0)
                .hint_text("position code")
                .desired_width(PATH_FIELD_WIDTH),
        );
        let open = egui::Button::new("Open");
        if ui
            .add_enabled(!state.code.0.trim().is_empty(), open)
            .clicked()
        {
            state.positions.write(PositionCommand::Open {
                own_physics: state.form.own_physics,
            });
        }
    });
    ui.checkbox(
        &mut state.form.own_physics,
        "play a code under the physics it carries",
    );
    ui.separator();
    ui.add_enabled_ui(free_play && at_rest, |ui| save_drill_rows(ui, state));
}

/// "Save as drill": a name, one goal (and "no foul"), the tries; the table as it stands with
/// the Shot section's shot and the physics goes into the player's drills folder.
fn save_drill_rows(ui: &mut egui::Ui, state: &mut PracticeParam) {
    use billiards_physics::Pocket;
    use billiards_rules::Goal;
    let on_table: Vec<u8> = state
        .solver
        .as_ref()
        .map(|s| {
            crate::sim::layout_now(s.simulation())
                .iter()
                .map(|b| b.number)
                .filter(|&n| n != 0)
                .collect()
        })
        .unwrap_or_default();
    let form = &mut *state.form;
    if !on_table.contains(&form.goal_ball) {
        form.goal_ball = on_table.first().copied().unwrap_or(1);
    }
    ui.horizontal(|ui| {
        ui.label("Save as drill:");
        ui.add(
            egui::TextEdit::singleline(&mut form.drill_name)
                .hint_text("its name")
                .desired_width(150.0),
        );
    });
    // One choice a row: the panel is narrow.
    ui.horizontal(|ui| {
        ui.label("goal:");
        egui::ComboBox::from_id_salt("drill goal")
            .selected_text(match form.goal {
                GoalChoice::Pocket => "pocket",
                GoalChoice::FirstContact => "hit first",
                GoalChoice::Safety => "safety: hide",
            })
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut form.goal, GoalChoice::Pocket, "pocket");
                ui.selectable_value(&mut form.goal, GoalChoice::FirstContact, "hit first");
                ui.selectable_value(&mut form.goal, GoalChoice::Safety, "safety: hide");
            });
        egui::ComboBox::from_id_salt("drill goal ball")
            .selected_text(ball_name(form.goal_ball))
            .show_ui(ui, |ui| {
                for &n in &on_table {
                    ui.selectable_value(&mut form.goal_ball, n, ball_name(n));
                }
            });
    });
    if form.goal == GoalChoice::Pocket {
        ui.horizontal(|ui| {
            ui.label("in:");
            let name = |p: Option<Pocket>| p.map_or("any pocket", billiards_rules::pocket_name);
            egui::ComboBox::from_id_salt("drill goal pocket")
                .selected_text(name(form.goal_pocket))
                .width(150.0)
                .show_ui(ui, |ui| {
                    ui.selectable_value(&mut form.goal_pocket, None, name(None));
                    for p in Pocket::ALL {
                        ui.selectable_value(&mut form.goal_pocket, Some(p), name(Some(p)));
                    }
                });
        });
    }
    ui.horizontal(|ui| {
        ui.checkbox(&mut form.no_foul, "no foul");
        ui.add(
            egui::DragValue::new(&mut form.tries)
                .range(1..=100)
                .suffix(" tries"),
        );
        let ready = !form.drill_name.trim().is_empty() && !on_table.is_empty();
        if ui
            .add_enabled(ready, egui::Button::new("Save as drill"))
            .on_disabled_hover_text("name it, with an object ball on the table")
            .clicked()
        {
            let ball = form.goal_ball;
            let mut goals = match form.goal {
                GoalChoice::Pocket => vec![Goal::Pocket {
                    ball,
                    pocket: form.goal_pocket,
                    cushions: 0,
                }],
                GoalChoice::FirstContact => vec![Goal::FirstContact { ball, cushions: 0 }],
                GoalChoice::Safety => vec![Goal::NoPocket, Goal::Hide { ball: Some(ball) }],
            };
            if form.no_foul {
                goals.push(Goal::NoFoul);
            }
            state.save_drill.write(SaveDrillRequested {
                name: form.drill_name.clone(),
                goals,
                tries: form.tries,
            });
        }
    });
}

fn placing_rows(ui: &mut egui::Ui, state: &mut PracticeParam, at_rest: bool) {
    let placing = &*state.placing;
    match (&placing.target, placing.selected) {
        (Some((_, Err(why))), _) => {
            ui.colored_label(WARNING, format!("not there: {why}"));
        }
        (_, Some(n)) => {
            ui.label(format!(
                "{} picked: drag it or click where it goes",
                ball_name(n)
            ));
        }
        (_, None) => {
            ui.label("click a ball to pick it");
        }
    }
    let missing = state
        .solver
        .as_ref()
        .map(|s| missing_numbers(s.simulation()))
        .unwrap_or_default();
    if !missing.contains(&state.form.add) {
        state.form.add = missing.first().copied().unwrap_or(0);
    }
    ui.add_enabled_ui(at_rest, |ui| {
        ui.horizontal(|ui| {
            egui::ComboBox::from_id_salt("add ball")
                .selected_text(ball_name(state.form.add))
                .show_ui(ui, |ui| {
                    for &n in &missing {
                        ui.selectable_value(&mut state.form.add, n, ball_name(n));
                    }
                });
            if ui
                .add_enabled(!missing.is_empty(), egui::Button::new("Add"))
                .clicked()
            {
                state.edits.write(EditRequested::Add {
                    number: state.form.add,
                    at: None,
                });
            }
        });
        ui.horizontal(|ui| {
            let picked = placing.selected;
            if ui
                .add_enabled(picked.is_some(), egui::Button::new("Remove picked (Del)"))
                .clicked()
                && let Some(number) = picked
            {
                state.edits.write(EditRequested::Remove { number });
            }
            if ui
                .add_enabled(!placing.undo.is_empty(), egui::Button::new("Undo (Ctrl+Z)"))
                .clicked()
            {
                state.edits.write(EditRequested::Undo);
            }
        });
        ui.horizontal(|ui| {
            if ui
                .button("Clear")
                .on_hover_text("every object ball off; the cue ball stays")
                .clicked()
            {
                state.edits.write(EditRequested::Clear);
            }
            ui.label("Shift: drop without snapping");
        });
    });
}

/// The drill in session: its goals, the try, the last attempt's reasons, the tally and the
/// best, and its buttons (Enter is Next try); its top below the HUD's `hud_bottom`.
pub fn drill_window(ctx: &egui::Context, state: &mut PracticeParam, hud_bottom: f32) {
    let (Some(session), Some(game)) = (state.session.as_deref(), drill_game(&state.rules)) else {
        return;
    };
    let drill = &game.drill;
    let mut command = None;
    egui::Window::new(format!("Drill: {}", drill.name))
        .id(egui::Id::new("drill window"))
        .collapsible(true)
        .resizable(false)
        .default_width(300.0)
        // Below the HUD, however tall it has grown.
        .anchor(egui::Align2::RIGHT_TOP, [-8.0, hud_bottom + 8.0])
        .show(ctx, |ui| {
            ui.label(&drill.description);
            for goal in &drill.goals {
                ui.label(format!("- {}", goal.text()));
            }
            ui.separator();
            ui.label(game.try_text());
            if let Some(last) = game.last.as_ref().filter(|_| game.try_over()) {
                let (verdict, colour) = if last.success {
                    ("made it", SUCCESS)
                } else {
                    ("missed", WARNING)
                };
                ui.colored_label(colour, format!("{verdict}: score {:.0}", last.score));
                for reason in &last.reasons {
                    ui.label(reason);
                }
            } else if !game.shots.is_empty() {
                ui.label(format!("shot {} of the try: go on", game.shots.len()));
            }
            let s = game.score;
            ui.label(format!(
                "this session: {} of {} made, best score {:.0}",
                s.successes, s.tries, s.best
            ));
            match state.bests.0.get(&session.file) {
                Some(best) if session.new_best => {
                    ui.colored_label(
                        SUCCESS,
                        format!("a new best: {} of {}", best.successes, best.tries),
                    );
                }
                Some(best) => {
                    ui.label(format!(
                        "best session: {} of {}, best score {:.0}",
                        best.successes, best.tries, best.best
                    ));
                }
                None => {
                    ui.label("no session finished yet");
                }
            }
            let over = game.session_over();
            if over {
                ui.label("the session is over");
            }
            ui.horizontal(|ui| {
                let next = egui::Button::new("Next try (Enter)");
                let hover = if game.shots.is_empty() {
                    "the drill's position for the next try"
                } else {
                    "gives this try up: it counts as missed"
                };
                if ui.add_enabled(!over, next).on_hover_text(hover).clicked() {
                    command = Some(DrillCommand::NextTry);
                }
                if ui.button("Restart").clicked() {
                    command = Some(DrillCommand::Restart);
                }
                if ui.button("Leave").clicked() {
                    command = Some(DrillCommand::Leave);
                }
            });
        });
    if let Some(command) = command {
        state.drills.write(command);
    }
}
