//! Every game is recorded without being asked: the solver's [`Recorder`] logs each input, and
//! after every shot the recording (setup, inputs, exact event history) is written atomically to
//! one file per game (from a rack to the next) in the recordings folder.
//!
//! [`Recorder`]: billiards_physics::recording::Recorder

use std::{
    path::{Path, PathBuf},
    time::{SystemTime, UNIX_EPOCH},
};

use bevy::prelude::*;

use crate::sim::{
    LayoutRequested, RackRequested, SceneRequested, ShotFinished, ShotUndone, SimStatus,
    SimSystems, Solver,
};

/// Registers the autosave.
pub fn plugin(app: &mut App) {
    app.init_resource::<RecordingsFolder>()
        .init_resource::<Autosave>()
        .add_systems(Update, save_finished_shot.in_set(SimSystems::Flow))
        // After the flow and the tools that ask for a new table (they order themselves before
        // it), before Commands, where the rack replaces the game.
        .configure_sets(
            Update,
            SaveBeforeRack
                .after(SimSystems::Flow)
                .before(SimSystems::Commands),
        )
        .add_systems(Update, save_before_rack.in_set(SaveBeforeRack))
        // An undo is placements in the recording: saved as soon as it is made.
        .add_systems(Update, save_undo.after(SimSystems::Commands));
}

/// Where the game is saved before a rack, a layout or a scene replaces it: a system that asks
/// for one after [`SimSystems::Flow`] runs before this set, so its request is seen.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SaveBeforeRack;

/// Where recordings are written and listed. `None` turns the autosave off.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct RecordingsFolder(pub Option<PathBuf>);

impl Default for RecordingsFolder {
    fn default() -> Self {
        Self(Some(PathBuf::from(DEFAULT_FOLDER)))
    }
}

/// The folder recordings go to unless `--recordings DIR` says otherwise.
pub const DEFAULT_FOLDER: &str = "recordings";

/// What the autosave did last.
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct Autosave {
    /// The file of the game in progress, once its first shot is saved.
    pub file: Option<PathBuf>,
    /// Shots in that file.
    pub shots: u32,
    /// Inputs in that file (a paused shot is an input before it is a finished shot).
    pub inputs: usize,
    /// The last failure, if the last save failed (the game goes on; the next shot retries).
    pub error: Option<String>,
}

/// After every shot, writes the whole game so far to its file (temporary file, then rename:
/// a crash loses at most the shot in flight).
fn save_finished_shot(
    mut finished: MessageReader<ShotFinished>,
    folder: Res<RecordingsFolder>,
    solver: Option<Res<Solver>>,
    status: Res<SimStatus>,
    mut autosave: ResMut<Autosave>,
) {
    if finished.read().count() == 0 {
        return;
    }
    if let (Some(folder), Some(solver)) = (&folder.0, solver) {
        save_game(folder, &solver, status.shots, &mut autosave);
    }
}

/// After an undo, writes the game with its placements.
fn save_undo(
    mut undone: MessageReader<ShotUndone>,
    folder: Res<RecordingsFolder>,
    solver: Option<Res<Solver>>,
    status: Res<SimStatus>,
    mut autosave: ResMut<Autosave>,
) {
    if undone.read().count() == 0 {
        return;
    }
    if let (Some(folder), Some(solver)) = (&folder.0, solver) {
        save_game(folder, &solver, status.shots, &mut autosave);
    }
}

/// Before a rack, a layout (a new game, a position, a ball added or removed) or a scene
/// replaces the game, writes every input not yet in its file (a shot struck while paused, a
/// placement, a settings change), so nothing the player did is lost.
fn save_before_rack(
    (mut racks, mut layouts, mut scenes): (
        MessageReader<RackRequested>,
        MessageReader<LayoutRequested>,
        MessageReader<SceneRequested>,
    ),
    folder: Res<RecordingsFolder>,
    solver: Option<Res<Solver>>,
    status: Res<SimStatus>,
    mut autosave: ResMut<Autosave>,
) {
    let replaced = racks.read().count() + layouts.read().count() + scenes.read().count();
    if replaced == 0 {
        return;
    }
    let (Some(folder), Some(solver)) = (&folder.0, solver) else {
        return;
    };
    let inputs = solver.recorder().recording().inputs.len();
    let path = game_file(folder, solver.started(), solver.name());
    let saved = autosave.file.as_ref() == Some(&path) && autosave.inputs == inputs;
    if inputs > 0 && !saved {
        save_game(folder, &solver, status.shots, &mut autosave);
    }
}

/// Writes the game in `solver` to its file in `folder` and notes what was written.
fn save_game(folder: &Path, solver: &Solver, shots: u32, autosave: &mut Autosave) {
    let path = game_file(folder, solver.started(), solver.name());
    let recording = solver.recorder().recording();
    let result = std::fs::create_dir_all(folder)
        .map_err(|error| format!("{}: {error}", folder.display()))
        .and_then(|()| recording.save(&path).map_err(|error| error.to_string()));
    match result {
        Ok(()) => {
            *autosave = Autosave {
                file: Some(path),
                shots,
                inputs: recording.inputs.len(),
                error: None,
            };
        }
        Err(error) => {
            warn!("recording not saved: {error}");
            autosave.error = Some(error);
        }
    }
}

/// Writes a rules log (`log`, JSON) beside the solver's recording in `folder`, at the path
/// `beside` makes of the recording's (`NAME.game.json`, pool's and snooker's alike): through a
/// temporary file and a rename, so a crash never leaves half a log. A failure is warned and
/// put in the status note; the game goes on.
pub fn save_rules_log(
    folder: &RecordingsFolder,
    solver: &Solver,
    beside: impl Fn(&Path) -> PathBuf,
    log: &impl serde::Serialize,
    status: &mut SimStatus,
) {
    let Some(folder) = &folder.0 else { return };
    let path = beside(&game_file(folder, solver.started(), solver.name()));
    let result = std::fs::create_dir_all(folder)
        .map_err(|e| e.to_string())
        .and_then(|()| serde_json::to_string_pretty(log).map_err(|e| e.to_string()))
        .and_then(|json| {
            let temporary = path.with_extension("tmp");
            std::fs::write(&temporary, json)
                .and_then(|()| std::fs::rename(&temporary, &path))
                .map_err(|e| e.to_string())
        });
    if let Err(error) = result {
        warn!("game log not saved: {error}");
        status.note = Some(format!("game log not saved: {error}"));
    }
}

/// The file of the game that started at `started` from the rack named `name` ("9-ball"):
/// `YYYY-MM-DD_HH-MM-SS.mmm_<name>.json` (UTC), so a folder listing sorts by date.
pub fn game_file(folder: &Path, started: SystemTime, name: &str) -> PathBuf {
    let since_epoch = started.duration_since(UNIX_EPOCH).unwrap_or_default();
    let secs = since_epoch.as_secs();
    let (year, month, day) = civil_from_days((secs / 86_400) as i64);
    let of_day = secs % 86_400;
    folder.join(format!(
        "{year:04}-{month:02}-{day:02}_{:02}-{:02}-{:02}.{:03}_{}.json",
        of_day / 3600,
        of_day / 60 % 60,
        of_day % 60,
        since_epoch.subsec_millis(),
        name,
    ))
}

/// Proleptic Gregorian date of a day count since 1970-01-01 (H. Hinnant's `civil_from_days`).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let month = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let year = yoe + era * 400 + i64::from(month <= 2);
    (year, month, day)
}

/// The recordings in `folder`, newest first (by name, which starts with the date).
pub fn list_recordings(folder: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(folder) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .filter_map(|entry| entry.ok().map(|entry| entry.path()))
        .filter(|path| path.extension().is_some_and(|ext| ext == "json"))
        // A game's rules log sits beside its recording (`NAME.game.json`, pool's and
        // snooker's); it is not a recording. Older builds saved snooker's as
        // `NAME.snooker.json`: those are skipped too, so old folders list as before.
        .filter(|path| {
            let name = path.to_string_lossy();
            !name.ends_with(".game.json") && !name.ends_with(".snooker.json")
        })
        .collect();
    files.sort_unstable_by(|a, b| b.cmp(a));
    files
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn dates_match_known_days() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        // 2000-02-29 is day 11016; 2026-11-22 is day 20779.
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        assert_eq!(civil_from_days(20_779), (2026, 11, 22));
        assert_eq!(civil_from_days(-1), (1969, 12, 31));
    }

    #[test]
    fn file_names_sort_by_start_time() {
        let folder = Path::new("r");
        let at = |s: u64, ms: u64| {
            game_file(
                folder,
                UNIX_EPOCH + Duration::from_millis(s * 1000 + ms),
                "9-ball",
            )
        };
        assert_eq!(
            at(20_779 * 86_400 + 3 * 3600 + 25 * 60 + 7, 42),
            folder.join("2026-11-22_03-25-07.042_9-ball.json")
        );
        assert!(at(100, 999) < at(101, 0));
    }

    /// The listing shows recordings only: every game's rules log (`NAME.game.json`, pool's
    /// and snooker's) and a snooker log an older build saved (`NAME.snooker.json`) are skipped;
    /// a recording whose rack is snooker (`..._snooker.json`) is listed.
    #[test]
    fn the_listing_skips_rules_logs_new_and_old() {
        let dir = std::env::temp_dir().join(format!("billiards-list-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        for name in [
            "a_9-ball.json",
            "a_9-ball.game.json",
            "b_snooker.json",
            "b_snooker.game.json",
            "c_snooker.json",
            "c_snooker.snooker.json",
            "notes.txt",
        ] {
            std::fs::write(dir.join(name), "{}").unwrap();
        }
        let listed: Vec<String> = list_recordings(&dir)
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(
            listed,
            ["c_snooker.json", "b_snooker.json", "a_9-ball.json"]
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
