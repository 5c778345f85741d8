//! Drill sessions in the game: a drill is a one-player game behind the one interface
//! ([`DrillGame`]: the position's rules and the drill's goals,
//! [`billiards_rules::Drill::judge`]), the game in play in [`Rules`] like any other, so the
//! game's own flow judges each stroke from the solver's events and logs each try beside its
//! recording. Here: the drill's position set up for each try, the notes, and the best session
//! of each drill kept in the settings file. The list of drills is in
//! [`super::drill_list`] (its items re-exported here).
use std::collections::BTreeMap;

use bevy::prelude::*;
use billiards_rules::{Drill, DrillScore, drill_game::DrillGame};
use serde::{Deserialize, Serialize};

pub use super::drill_list::{DrillList, USER_PREFIX, drills_folder, file_name, save_drill};
use super::{
    position::{Origin, PositionRequested},
    state::Practice,
};
use crate::{
    play::game::{DialogOpen, LiveGame, Rules},
    sim::{ShotFinished, SimStatus, Solver},
};

/// The best session of each drill, by file name: kept in the settings file.
#[derive(Resource, Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct DrillBests(pub BTreeMap<String, DrillScore>);

impl DrillBests {
    /// Keeps `session` for `drill` if it is better than the best so far
    /// ([`DrillScore::better`]); returns whether it is the new best.
    pub fn offer(&mut self, drill: &str, session: DrillScore) -> bool {
        let kept = self.0.get(drill).copied();
        let best = kept.map_or(session, |k| k.better(session));
        self.0.insert(drill.to_owned(), best);
        kept.is_none_or(|k| best != k)
    }
}

/// The drill `--drill NAME` starts (a key of the [`DrillList`], `.json` optional).
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct StartDrill(pub String);

/// Startup: the drill of `--drill`, found in the list, or why not in the note.
pub(super) fn start_drill_at_launch(
    start: Option<Res<StartDrill>>,
    list: Res<DrillList>,
    mut requests: MessageWriter<DrillRequested>,
    mut status: ResMut<SimStatus>,
) {
    let Some(start) = start else { return };
    let name = start.0.trim_end_matches(".json");
    match list
        .drills
        .iter()
        .position(|(key, _)| key.trim_end_matches(".json") == name)
    {
        Some(index) => {
            requests.write(DrillRequested { index });
        }
        None => {
            let keys: Vec<&str> = list.drills.iter().map(|(k, _)| k.as_str()).collect();
            status.note = Some(format!(
                "--drill: no drill {name:?}; the list has {}",
                keys.join(", ")
            ));
        }
    }
}

/// Starts a session of the drill at `index` in the [`DrillList`].
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct DrillRequested {
    /// Its place in the list.
    pub index: usize,
}

/// "Save as drill": the table as it stands, with these goals, into the player's drills
/// folder.
#[derive(Message, Debug, Clone, PartialEq)]
pub struct SaveDrillRequested {
    /// The drill's name (its file is named after it).
    pub name: String,
    /// Its goals.
    pub goals: Vec<billiards_rules::Goal>,
    /// Tries a session gives.
    pub tries: u32,
}

/// What the player does in a session.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub enum DrillCommand {
    /// The balls back in the drill's position for the next try.
    NextTry,
    /// A new session of the same drill.
    Restart,
    /// Back to free play.
    Leave,
}

/// A drill in session: which drill file it plays and how its session compared with the
/// best. The session itself is a one-player game behind the one interface ([`DrillGame`],
/// [`billiards_rules::GameRules::solo`]) held in [`Rules`] like every game, its strokes
/// judged and logged by the game's own flow; [`drill_game`] finds it there.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct DrillSession {
    /// The drill's file name (its key in [`DrillBests`]).
    pub file: String,
    /// The session ended with a new best.
    pub new_best: bool,
    /// The session's tally has been offered to the [`DrillBests`].
    pub kept: bool,
}

impl DrillSession {
    /// A session of the drill in file `file`, its tally not yet kept.
    pub fn new(file: &str) -> Self {
        Self {
            file: file.to_owned(),
            new_best: false,
            kept: false,
        }
    }
}

/// The drill session in play in `rules`, if the game in play is one.
pub fn drill_game(rules: &Rules) -> Option<&DrillGame> {
    rules
        .live
        .as_ref()?
        .rules
        .as_any()
        .downcast_ref::<DrillGame>()
}

/// A session of `drill` for `player`, as the game in play: a one-player game of the
/// interface, outside the catalog (its layout and table are the drill's position's).
fn drill_live(drill: Drill, player: String) -> Result<LiveGame, String> {
    let ball = drill.position.params.unwrap_or_default().ball;
    let game = DrillGame::new(drill, player, ball).map_err(|e| e.0)?;
    LiveGame::new(Box::new(game), None, [None, None], 0).map_err(|e| e.0)
}

/// Starts the requested drill: its session the game in play, its position on the table, the
/// dialog closed.
#[allow(clippy::too_many_arguments)]
pub(super) fn start_drill(
    mut requests: MessageReader<DrillRequested>,
    list: Res<DrillList>,
    mut positions: MessageWriter<PositionRequested>,
    mut commands: Commands,
    mut next: ResMut<NextState<Practice>>,
    mut dialog: ResMut<DialogOpen>,
    mut rules: ResMut<Rules>,
    mut status: ResMut<SimStatus>,
) {
    let Some(&DrillRequested { index }) = requests.read().last() else {
        return;
    };
    let Some((file, Ok(drill))) = list.drills.get(index) else {
        status.note = Some("that drill cannot be played (its file was refused)".to_owned());
        return;
    };
    // The player of the game in play takes the drill.
    let player = rules
        .live
        .as_ref()
        .map_or_else(|| "Player 1".to_owned(), |g| g.rules.players()[0].clone());
    let live = match drill_live(drill.clone(), player) {
        Ok(live) => live,
        Err(why) => {
            status.note = Some(format!("that drill cannot be played: {why}"));
            return;
        }
    };
    dialog.0 = false;
    rules.live = Some(live);
    positions.write(PositionRequested {
        position: drill.position.clone(),
        origin: Origin::Drill,
        own_physics: true,
    });
    status.note = Some(format!("drill: {}", drill.name));
    commands.insert_resource(DrillSession::new(file));
    next.set(Practice::Drill);
}

/// After each stroke, judged and logged by the game's flow like any game's
/// ([`crate::play::game`]): the note says whether the try goes on or how it ended, and at the
/// session's last try its tally is offered to the bests.
pub(super) fn after_stroke(
    mut finished: MessageReader<ShotFinished>,
    session: Option<ResMut<DrillSession>>,
    rules: Res<Rules>,
    mut bests: ResMut<DrillBests>,
    mut status: ResMut<SimStatus>,
) {
    if finished.read().count() == 0 {
        return;
    }
    let (Some(mut session), Some(game)) = (session, drill_game(&rules)) else {
        return;
    };
    if !game.shots.is_empty() {
        status.note = Some(format!("shot {} of the try: go on", game.shots.len()));
    } else if let Some(attempt) = game.last.as_ref().filter(|_| game.try_over()) {
        status.note = Some(format!(
            "{}: score {:.0}",
            if attempt.success { "made it" } else { "missed" },
            attempt.score
        ));
    }
    keep_if_over(&mut session, game, &mut bests);
}

/// At the session's end, its tally offered to the bests once.
fn keep_if_over(session: &mut DrillSession, game: &DrillGame, bests: &mut DrillBests) {
    if game.session_over() && !session.kept {
        session.new_best = bests.offer(&session.file, game.score);
        session.kept = true;
    }
}

/// A new game, a rack from the panel, the stress table or a position not the drill's own ends
/// the drill in session.
pub(super) fn end_drill_on_new_table(
    mut games: MessageReader<crate::play::game::NewGameRequested>,
    mut racks: MessageReader<crate::sim::RackRequested>,
    mut stress: MessageReader<crate::stress::StressRequested>,
    mut positions: MessageReader<PositionRequested>,
    session: Option<Res<DrillSession>>,
    mut commands: Commands,
    mut next: ResMut<NextState<Practice>>,
) {
    let other_position = positions.read().any(|p| p.origin != Origin::Drill);
    let new_table =
        games.read().count() + racks.read().count() + stress.read().count() > 0 || other_position;
    if new_table && session.is_some() {
        commands.remove_resource::<DrillSession>();
        next.set(Practice::Off);
    }
}

/// Enter is Next try while tries are left.
pub(super) fn drill_keys(
    keys: Res<ButtonInput<KeyCode>>,
    rules: Res<Rules>,
    mut commands: MessageWriter<DrillCommand>,
) {
    if keys.just_pressed(KeyCode::Enter) && drill_game(&rules).is_some_and(|g| !g.session_over()) {
        commands.write(DrillCommand::NextTry);
    }
}

/// The session's commands: the next try (the try in play given up first, counted as a miss,
/// if it has shots: [`billiards_rules::GameRules::concede`]), a new session, leaving.
#[allow(clippy::too_many_arguments)]
pub(super) fn drill_commands(
    mut requests: MessageReader<DrillCommand>,
    session: Option<ResMut<DrillSession>>,
    mut positions: MessageWriter<PositionRequested>,
    mut commands: Commands,
    mut next: ResMut<NextState<Practice>>,
    mut bests: ResMut<DrillBests>,
    (mut status, mut rules): (ResMut<SimStatus>, ResMut<Rules>),
) {
    let Some(&command) = requests.read().last() else {
        return;
    };
    let Some(mut session) = session else { return };
    let Some(drill) = drill_game(&rules).map(|g| g.drill.clone()) else {
        return;
    };
    if command == DrillCommand::Leave {
        commands.remove_resource::<DrillSession>();
        next.set(Practice::Off);
        rules.free_play();
        status.note = Some("drill left: free play".to_owned());
        return;
    }
    let Some(game) = rules.live.as_mut() else {
        return;
    };
    match command {
        DrillCommand::Restart => {
            match drill_live(drill.clone(), game.rules.players()[0].clone()) {
                Ok(fresh) => *game = fresh,
                Err(why) => {
                    status.note = Some(format!("the drill cannot restart: {why}"));
                    return;
                }
            }
            *session = DrillSession::new(&session.file);
        }
        _ => {
            if game.rules.concedes() {
                // The try in play given up after a shot: a miss in the tally.
                match game.rules.concede() {
                    Ok(end) => status.note = Some(end.reason),
                    Err(e) => status.note = Some(e.0),
                }
                if let Some(drill_game) = drill_game(&rules) {
                    keep_if_over(&mut session, drill_game, &mut bests);
                }
            }
            let Some(game) = rules.live.as_mut() else {
                return;
            };
            if game.rules.end().is_some_and(|end| end.match_over) {
                status.note = Some("the session is over: Restart for another".to_owned());
                return;
            }
            // A try over: the next one; a try not begun: its position set again.
            if game.rules.end().is_some()
                && let Err(error) = game.begin_next()
            {
                status.note = Some(error.0);
                return;
            }
        }
    }
    // The position again: a new recording, so a new log.
    if let Some(game) = rules.live.as_mut()
        && let Err(e) = game.restart_log()
    {
        status.note = Some(format!("the drill's log restarts empty: {e}"));
    }
    positions.write(PositionRequested {
        position: drill.position,
        origin: Origin::Drill,
        own_physics: true,
    });
}

/// "Save as drill": the table at rest (its balls, table, physics and the Shot section's
/// shot) with the asked goals, written into the player's drills folder and listed at once.
pub(super) fn save_as_drill(
    mut requests: MessageReader<SaveDrillRequested>,
    solver: Option<Res<Solver>>,
    (rules, shot): (
        Res<crate::play::game::Rules>,
        Res<crate::settings::ShotSettings>,
    ),
    mut list: ResMut<DrillList>,
    mut status: ResMut<SimStatus>,
) {
    let Some(request) = requests.read().last().cloned() else {
        return;
    };
    let Some(solver) = solver else { return };
    let outcome = (|| {
        let folder = list
            .user_folder
            .clone()
            .ok_or("there is no config folder to keep drills in")?;
        let name = request.name.trim();
        if name.is_empty() {
            return Err("give the drill a name".to_owned());
        }
        let position = super::position::current_position(&solver, &rules, true, Some(&shot))?;
        let goals: Vec<String> = request.goals.iter().map(|g| g.text()).collect();
        let drill = Drill {
            name: name.to_owned(),
            description: format!("{}.", goals.join(", ")),
            position,
            goals: request.goals.clone(),
            tries: request.tries.clamp(1, 100),
            shots: 1,
        };
        save_drill(&folder, &drill)
    })();
    status.note = Some(match outcome {
        Ok(path) => {
            list.reload();
            format!(
                "drill saved as {} (New game, free play lists it)",
                path.display()
            )
        }
        Err(why) => format!("drill not saved: {why}"),
    });
}

/// The drill's goals on the table: the pocket a ball must drop in ringed, the balls it
/// names ringed, the cue ball's zone outlined.
pub(super) fn draw_goals(
    rules: Res<Rules>,
    spec: Res<crate::table::geometry::TableSpec>,
    solver: Option<Res<Solver>>,
    mut gizmos: Gizmos,
) {
    use billiards_rules::{Goal, Zone};
    let Some(game) = drill_game(&rules) else {
        return;
    };
    let at = |p: bevy::math::DVec2| crate::table::geometry::to_world(p.extend(0.003));
    let flat = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    let gold = Color::srgb(1.0, 0.8, 0.1);
    let zone_colour = Color::srgb(0.3, 0.9, 1.0);
    let r = spec.ball_radius as f32;
    let ball_at = |n: u8| {
        solver.as_ref().and_then(|s| {
            let sim = s.simulation();
            sim.balls()
                .zip(sim.numbers())
                .find(|(b, k)| **k == n && b.motion.on_table())
                .map(|(b, _)| crate::sim::to_dvec2(b.position))
        })
    };
    for goal in &game.drill.goals {
        let ball = match *goal {
            Goal::Pocket { ball, pocket, .. } => {
                if let Some(hole) = pocket.and_then(|p| spec.pocket(p)) {
                    for k in [1.2, 1.35] {
                        gizmos
                            .circle(
                                Isometry3d::new(at(hole.centre), flat),
                                (k * hole.radius) as f32,
                                gold,
                            )
                            .resolution(40);
                    }
                }
                Some(ball)
            }
            Goal::FirstContact { ball, .. } | Goal::Hide { ball: Some(ball) } => Some(ball),
            Goal::CueBallIn { zone } => {
                let centre = at(crate::sim::to_dvec2(zone.centre()));
                match zone {
                    Zone::Circle { radius, .. } => {
                        gizmos
                            .circle(Isometry3d::new(centre, flat), radius as f32, zone_colour)
                            .resolution(48);
                    }
                    Zone::Rect { min, max } => {
                        let size = Vec2::new((max.x - min.x) as f32, (max.y - min.y) as f32);
                        gizmos.rect(Isometry3d::new(centre, flat), size, zone_colour);
                    }
                }
                None
            }
            _ => None,
        };
        if let Some(p) = ball.and_then(ball_at) {
            gizmos
                .circle(Isometry3d::new(at(p), flat), 1.3 * r, gold)
                .resolution(32);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A session is kept only when it beats the best: a better success rate first.
    #[test]
    fn the_best_session_is_kept() {
        let mut bests = DrillBests::default();
        let s = |tries, successes, best| DrillScore {
            tries,
            successes,
            best,
        };
        assert!(bests.offer("a", s(10, 3, 80.0)));
        assert!(!bests.offer("a", s(10, 2, 99.0)));
        assert_eq!(bests.0["a"], s(10, 3, 80.0));
        assert!(bests.offer("a", s(10, 5, 60.0)));
        assert_eq!(bests.0["a"], s(10, 5, 60.0));
    }
}
