//! The drills the game lists: the standard set (the `assets/drills/` folder, or built in for
//! a binary run away from it) and the player's own folder; a drill saved under a file name
//! made from its name.

use std::path::{Path, PathBuf};

use bevy::prelude::*;
use billiards_rules::Drill;

/// The standard drills, built in for a binary run away from its `assets` folder.
const BUILT_IN: [(&str, &str); 11] = [
    (
        "01-stop-shot.json",
        include_str!("../../assets/drills/01-stop-shot.json"),
    ),
    (
        "02-draw-shot.json",
        include_str!("../../assets/drills/02-draw-shot.json"),
    ),
    (
        "03-follow-shot.json",
        include_str!("../../assets/drills/03-follow-shot.json"),
    ),
    (
        "04-cut-30.json",
        include_str!("../../assets/drills/04-cut-30.json"),
    ),
    (
        "05-thin-cut.json",
        include_str!("../../assets/drills/05-thin-cut.json"),
    ),
    (
        "06-bank.json",
        include_str!("../../assets/drills/06-bank.json"),
    ),
    (
        "07-kick.json",
        include_str!("../../assets/drills/07-kick.json"),
    ),
    (
        "08-run-out-789.json",
        include_str!("../../assets/drills/08-run-out-789.json"),
    ),
    (
        "09-safety.json",
        include_str!("../../assets/drills/09-safety.json"),
    ),
    (
        "10-position-zone.json",
        include_str!("../../assets/drills/10-position-zone.json"),
    ),
    (
        "11-long-pot.json",
        include_str!("../../assets/drills/11-long-pot.json"),
    ),
];

/// The drills the new-game dialog lists: the standard ones (by file name) then the player's
/// own (by `user/` and file name), each a drill or why its file was refused (shown in the
/// list, greyed out).
#[derive(Resource, Debug)]
pub struct DrillList {
    /// Where the standard drills were read from (`None`: the built-in set).
    pub folder: Option<PathBuf>,
    /// The player's drills folder (`drills` beside the settings file), where "Save as
    /// drill" writes; `None` without a settings file (`--no-config`).
    pub user_folder: Option<PathBuf>,
    /// Key (file name, `user/` before the player's own) and drill (or the error): the
    /// standard ones in file-name order, then the player's.
    pub drills: Vec<(String, Result<Drill, String>)>,
}

impl Default for DrillList {
    /// The standard drills; the player's folder is the settings file's (`crate::config`
    /// sets it when it reads the file; none with `--no-config`).
    fn default() -> Self {
        Self::load(drills_folder().as_deref(), None)
    }
}

/// The key a drill of the player's folder is listed and scored by.
pub const USER_PREFIX: &str = "user/";

impl DrillList {
    /// The drills of `folder`, or the built-in set without one (or if it cannot be read),
    /// then those of the player's `user` folder (none if it is missing).
    pub fn load(folder: Option<&Path>, user: Option<PathBuf>) -> Self {
        let refused = |(name, d): (String, Result<Drill, billiards_rules::DrillError>)| {
            (name, d.map_err(|e| e.to_string()))
        };
        let standard = folder.and_then(|dir| Drill::load_dir(dir).ok().map(|l| (dir, l)));
        let mut list = match standard {
            Some((dir, loaded)) => Self {
                folder: Some(dir.to_path_buf()),
                user_folder: None,
                drills: loaded.into_iter().map(refused).collect(),
            },
            None => Self {
                folder: None,
                user_folder: None,
                drills: BUILT_IN
                    .iter()
                    .map(|&(name, text)| {
                        (
                            name.to_owned(),
                            Drill::from_json(text).map_err(|e| e.to_string()),
                        )
                    })
                    .collect(),
            },
        };
        if let Some(dir) = &user
            && let Ok(loaded) = Drill::load_dir(dir)
        {
            list.drills.extend(
                loaded
                    .into_iter()
                    .map(refused)
                    .map(|(name, d)| (format!("{USER_PREFIX}{name}"), d)),
            );
        }
        list.user_folder = user;
        list
    }

    /// The list read again (a drill saved, a file added).
    pub fn reload(&mut self) {
        *self = Self::load(self.folder.as_deref(), self.user_folder.clone());
    }
}

/// A file name for a drill called `name`: its letters and digits, lower case, words joined by
/// '-', at most 40 characters ("drill" if none is left).
pub fn file_name(name: &str) -> String {
    let mut stem = String::new();
    for c in name.chars() {
        if c.is_ascii_alphanumeric() {
            stem.push(c.to_ascii_lowercase());
        } else if !stem.is_empty() && !stem.ends_with('-') {
            stem.push('-');
        }
    }
    let stem: String = stem.trim_end_matches('-').chars().take(40).collect();
    let stem = stem.trim_end_matches('-');
    format!("{}.json", if stem.is_empty() { "drill" } else { stem })
}

/// Writes `drill` into `folder` under [`file_name`] of its name (made if missing; a file of
/// that name is replaced, as saving again under the same name means); the path written.
pub fn save_drill(folder: &Path, drill: &Drill) -> Result<PathBuf, String> {
    drill.check().map_err(|e| format!("not a drill: {e}"))?;
    std::fs::create_dir_all(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    let path = folder.join(file_name(&drill.name));
    let text = serde_json::to_string_pretty(drill).map_err(|e| e.to_string())?;
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

/// The `assets/drills` folder: beside the game's manifest when run by cargo, beside the
/// binary, or in the current folder, whichever is there first.
pub fn drills_folder() -> Option<PathBuf> {
    let manifest = std::env::var_os("CARGO_MANIFEST_DIR").map(PathBuf::from);
    let exe = std::env::current_exe()
        .ok()
        .and_then(|p| p.parent().map(Path::to_path_buf));
    [manifest, exe, Some(PathBuf::from("."))]
        .into_iter()
        .flatten()
        .map(|dir| dir.join("assets").join("drills"))
        .find(|dir| dir.is_dir())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every standard drill is built in and loads; the folder's list is the same drills.
    #[test]
    fn the_standard_drills_load_from_the_folder_and_built_in() {
        let built_in = DrillList::load(None, None);
        assert_eq!(built_in.drills.len(), BUILT_IN.len());
        assert!(built_in.drills.iter().all(|(_, d)| d.is_ok()));
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/drills");
        let folder = DrillList::load(Some(&dir), None);
        let names = |l: &DrillList| l.drills.iter().map(|d| d.0.clone()).collect::<Vec<_>>();
        assert_eq!(
            names(&folder),
            names(&built_in),
            "a drill file not built in"
        );
        for ((_, a), (_, b)) in folder.drills.iter().zip(&built_in.drills) {
            assert_eq!(a.as_ref().unwrap(), b.as_ref().unwrap());
        }
    }

    /// A drill's file name keeps its name's letters and digits, words joined by '-'.
    #[test]
    fn a_saved_drill_is_named_after_it() {
        assert_eq!(file_name("My Cut, 30°!"), "my-cut-30.json");
        assert_eq!(file_name("  "), "drill.json");
        assert_eq!(
            file_name(&"x".repeat(60)),
            format!("{}.json", "x".repeat(40))
        );
    }
}
