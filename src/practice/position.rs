//! A position on the table and as a code: [`PositionRequested`] sets one up (pasted, from
//! `--position CODE`, from a replay's shot, a drill's), [`current_position`] reads the table
//! as one, and [`Clipboard`] is the system clipboard (arboard: X11 and Wayland without
//! system headers).

use std::sync::Mutex;

use bevy::prelude::*;
use billiards_physics::{Rack, TableChoice};
use billiards_rules::{Game, Position};

use crate::{
    play::game::Rules,
    replay::{Replay, ReplayCommand, RulesLog},
    settings::{ClampReport, PhysicsSettings, ShotSettings, TableSetup, apply_shot_edit},
    sim::{LayoutRequested, SceneRequested, SimStatus, Solver, params_for},
    table::geometry::TableSpec,
};

/// What names a recording of a position set up by hand or pasted.
pub const POSITION_NAME: &str = "position";

/// Where a position comes from: how the note names it, and whether a drill goes on.
#[derive(Debug, Clone, PartialEq)]
pub enum Origin {
    /// Pasted from the clipboard or typed into the panel.
    Pasted,
    /// `--position CODE` on the command line.
    Launch,
    /// Shot `k` of a recording, opened from the replay.
    Replay(usize),
    /// A drill's start, or its next try.
    Drill,
}

/// Asks for `position` on the table: its balls, its table, its physics (if it carries them
/// and `own_physics`) and its shot in the Shot section. Ends a match in play (it stays in
/// the recordings) and, unless it is the drill's own, a drill session.
#[derive(Message, Debug, Clone, PartialEq)]
pub struct PositionRequested {
    /// The position.
    pub position: Position,
    /// Where it comes from.
    pub origin: Origin,
    /// Play it under the physics it carries (a frozen scene), not the player's settings.
    pub own_physics: bool,
}

/// The position `--position CODE` opens at start.
#[derive(Resource, Debug, Clone, PartialEq)]
pub struct StartPosition(pub Position);

/// Startup: the position of `--position`, if any.
pub(super) fn start_position(
    start: Option<Res<StartPosition>>,
    mut requests: MessageWriter<PositionRequested>,
) {
    if let Some(start) = start {
        requests.write(PositionRequested {
            position: start.0.clone(),
            origin: Origin::Launch,
            own_physics: true,
        });
    }
}

/// The player's table whose size and mouths are `table`'s (pockets as the settings say).
pub fn table_choice_of(table: &billiards_physics::Table) -> Option<TableChoice> {
    crate::settings::table_choices().find(|&choice| {
        let t = TableSpec::of(choice).physics_table();
        t.length == table.length
            && t.width == table.width
            && t.corner_mouth == table.corner_mouth
            && t.side_mouth == table.side_mouth
    })
}

/// Sets the requested position up: a standard table with the player's physics becomes a
/// layout on it (the Physics settings keep applying); its own physics or a table of its own
/// make a scene (as the stress table is: its table and parameters, frozen until the next rack).
#[allow(clippy::too_many_arguments)]
pub(super) fn load_position(
    mut requests: MessageReader<PositionRequested>,
    mut layouts: MessageWriter<LayoutRequested>,
    mut scenes: MessageWriter<SceneRequested>,
    (mut setup, mut spec, settings): (ResMut<TableSetup>, ResMut<TableSpec>, Res<PhysicsSettings>),
    (mut shot, mut report): (ResMut<ShotSettings>, ResMut<ClampReport>),
    mut rules: ResMut<Rules>,
    (mut status, mut kept): (ResMut<SimStatus>, ResMut<super::state::KeptNote>),
) {
    let Some(request) = requests.read().last().cloned() else {
        return;
    };
    let p = &request.position;
    if let Err(error) = p.check() {
        status.note = Some(format!("position not opened: {error}"));
        return;
    }
    let ended_match = rules.in_match();
    // A drill's own position: its session is the game in play already (drill.rs).
    if request.origin != Origin::Drill {
        rules.free_play();
    }
    // A drill in session ends (drill::end_drill_on_new_table) unless this is its own.
    let own = request.own_physics && p.params.is_some();
    match table_choice_of(&p.table).filter(|_| !own) {
        Some(choice) => {
            // The table first, as a new game sets it: the layout below is set on it.
            setup.set_if_neq(TableSetup {
                table: choice,
                ..*setup
            });
            spec.set_if_neq(TableSpec::of(choice));
            layouts.write(LayoutRequested {
                balls: p.setups(),
                rack: Rack::FifteenBall,
                name: POSITION_NAME,
            });
        }
        None => {
            let params = match p.params.filter(|_| request.own_physics) {
                Some(params) => params,
                None => params_for(&TableSpec::fitting(&p.table), &settings),
            };
            scenes.write(SceneRequested {
                table: p.table,
                params,
                balls: p.setups(),
                name: POSITION_NAME,
            });
        }
    }
    if let Some(s) = p.shot {
        let next_shot = ShotSettings {
            angle: s.angle.rem_euclid(std::f64::consts::TAU),
            power: s.speed,
            tip: s.tip,
            elevation: s.elevation.to_degrees(),
        };
        apply_shot_edit(next_shot, &mut shot, &mut report);
    }
    let from = match request.origin {
        Origin::Pasted => "pasted".to_owned(),
        Origin::Launch => "from the command line".to_owned(),
        Origin::Replay(k) => format!("from shot {k} of the replay"),
        Origin::Drill => return,
    };
    let mut note = format!(
        "position {from}: {} balls{}{}",
        p.balls.len(),
        if own { ", its own physics" } else { "" },
        if p.shot.is_some() {
            ", its shot lined up"
        } else {
            ""
        },
    );
    if p.game != Game::FreePlay {
        note.push_str(&format!(
            " (set up for {}; free play)",
            crate::play::game::GameChoice::from(p.game).label()
        ));
    }
    if ended_match {
        note.push_str("; the match in play ended (it stays in the recordings)");
    }
    status.note = Some(note);
    // The new table resets the status at SimSystems::Commands: the note is said again after.
    kept.0.clone_from(&status.note);
}

/// The table now as a position: every ball on the table (at rest), the game in play, the
/// solver's physics if `with_params` and the Shot section's shot if `shot` is given.
pub fn current_position(
    solver: &Solver,
    rules: &Rules,
    with_params: bool,
    shot: Option<&ShotSettings>,
) -> Result<Position, String> {
    let sim = solver.simulation();
    if !sim.is_at_rest() {
        return Err("wait until every ball rests".to_owned());
    }
    // A position code knows pool's games only; any other game's table is set up as free
    // play.
    let game = rules
        .live
        .as_ref()
        .and_then(|g| {
            g.rules
                .as_any()
                .downcast_ref::<billiards_rules::pool::PoolMatch>()
        })
        .map_or(Game::FreePlay, |g| g.play.game);
    let mut p = Position::of_simulation(sim, game, with_params);
    p.shot = shot.map(|s| s.shot());
    p.check().map_err(|e| e.to_string())?;
    Ok(p)
}

/// The system clipboard, opened on first use. Without a display (headless, a test) it is
/// unavailable and says so; nothing panics.
#[derive(Resource, Default)]
pub struct Clipboard(Mutex<Option<arboard::Clipboard>>);

impl Clipboard {
    fn with<T>(
        &self,
        f: impl FnOnce(&mut arboard::Clipboard) -> Result<T, arboard::Error>,
    ) -> Result<T, String> {
        let mut guard = self
            .0
            .lock()
            .map_err(|_| "the clipboard is unavailable".to_owned())?;
        if guard.is_none() {
            *guard = Some(
                arboard::Clipboard::new()
                    .map_err(|e| format!("the clipboard is unavailable ({e})"))?,
            );
        }
        let clipboard = guard.as_mut().expect("opened above");
        f(clipboard).map_err(|e| format!("clipboard: {e}"))
    }

    /// Puts `text` on the clipboard (kept there while the game runs).
    pub fn set_text(&self, text: &str) -> Result<(), String> {
        self.with(|c| c.set_text(text.to_owned()))
    }

    /// The clipboard's text.
    pub fn text(&self) -> Result<String, String> {
        self.with(|c| c.get_text())
    }
}

/// The panel's position code: the code last copied, or the one typed or pasted to open.
#[derive(Resource, Debug, Clone, Default, PartialEq, Eq)]
pub struct PositionCode(pub String);

/// What the panel's Position rows ask for.
#[derive(Message, Debug, Clone, PartialEq, Eq)]
pub enum PositionCommand {
    /// The table as a code, onto the clipboard and into the code field.
    Copy {
        /// The solver's physics go with it.
        with_params: bool,
        /// The Shot section's shot goes with it.
        with_shot: bool,
    },
    /// The clipboard's code opened.
    Paste {
        /// Played under the physics it carries.
        own_physics: bool,
    },
    /// The code field's code opened.
    Open {
        /// Played under the physics it carries.
        own_physics: bool,
    },
}

/// Carries the panel's Copy, Paste and Open out; every refusal is the note's, never a panic
/// (no display for the clipboard, a malformed code, balls still rolling).
pub(super) fn position_commands(
    mut requests: MessageReader<PositionCommand>,
    solver: Option<Res<Solver>>,
    (rules, shot): (Res<Rules>, Res<ShotSettings>),
    clipboard: Res<Clipboard>,
    mut code: ResMut<PositionCode>,
    mut positions: MessageWriter<PositionRequested>,
    mut status: ResMut<SimStatus>,
) {
    let Some(request) = requests.read().last().cloned() else {
        return;
    };
    let open = |text: &str, own_physics: bool| -> Result<PositionRequested, String> {
        let position = Position::decode(text.trim()).map_err(|e| format!("not a position: {e}"))?;
        Ok(PositionRequested {
            position,
            origin: Origin::Pasted,
            own_physics,
        })
    };
    let outcome = match request {
        PositionCommand::Copy {
            with_params,
            with_shot,
        } => {
            let Some(solver) = solver else { return };
            current_position(&solver, &rules, with_params, with_shot.then_some(&*shot))
                .and_then(|p| p.encode().map_err(|e| e.to_string()))
                .map(|text| {
                    let kept = clipboard.set_text(&text);
                    // The code itself is in the Position section's field: a 500-character
                    // code filled the HUD when the note carried it (played under Xvfb).
                    let size = text.len();
                    let note = match kept {
                        Ok(()) => format!(
                            "position copied: {size} characters on the clipboard and in the \
                             Position section's field"
                        ),
                        Err(why) => format!(
                            "{why}; the code ({size} characters) is in the Position section's field"
                        ),
                    };
                    code.0 = text;
                    note
                })
        }
        PositionCommand::Paste { own_physics } => clipboard.text().and_then(|text| {
            code.0 = text.trim().to_owned();
            open(&text, own_physics).map(|r| {
                positions.write(r);
                String::new()
            })
        }),
        PositionCommand::Open { own_physics } => open(&code.0, own_physics).map(|r| {
            positions.write(r);
            String::new()
        }),
    };
    match outcome {
        // An opened position's note is load_position's.
        Ok(note) if note.is_empty() => {}
        Ok(note) => status.note = Some(note),
        Err(why) => status.note = Some(why),
    }
}

/// The replay's "Open shot as position": the shot under the replay time, set up live.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShotAsPositionRequested;

/// A replay's shot on its way to the live table (the replay closes first), or why it was
/// refused (the timeline shows it).
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct PendingPosition {
    /// The position to set up once the live game is back.
    pub request: Option<PositionRequested>,
    /// Why the last shot could not be opened.
    pub refused: Option<String>,
}

/// In the replay: the shot under the replay time as a position (where the balls rested at
/// its strike, the physics then, the shot), kept for the live game, and the replay closed.
pub(super) fn shot_as_position(
    mut requests: MessageReader<ShotAsPositionRequested>,
    replay: Res<Replay>,
    mut pending: ResMut<PendingPosition>,
    mut replay_commands: MessageWriter<ReplayCommand>,
) {
    if requests.read().count() == 0 {
        return;
    }
    let Some(open) = &replay.open else { return };
    let k = open.shot_at(replay.time).max(1);
    let game = match &open.game {
        Some(Ok(RulesLog::Pool(log))) => log.game,
        _ => Game::FreePlay,
    };
    match Position::from_recording(&open.recording, &open.history, k, game) {
        Ok(position) => {
            pending.request = Some(PositionRequested {
                position,
                origin: Origin::Replay(k),
                own_physics: true,
            });
            pending.refused = None;
            replay_commands.write(ReplayCommand::Close);
        }
        Err(error) => pending.refused = Some(format!("shot {k} not opened: {error}")),
    }
}

/// Back in the live game: the replay's shot, if one waits (a refusal is the closed
/// replay's, forgotten).
pub(super) fn open_pending(
    mut pending: ResMut<PendingPosition>,
    mut positions: MessageWriter<PositionRequested>,
) {
    if pending.refused.is_some() {
        pending.refused = None;
    }
    if let Some(request) = pending.request.take() {
        positions.write(request);
    }
}
