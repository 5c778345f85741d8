//! A recording loaded for replay: its history rebuilt for exact sampling, and navigation by
//! event and by shot (shots as [`billiards_rules::Shots`] numbers them, from 1).

use std::{
    path::{Path, PathBuf},
    sync::Arc,
};

use billiards_physics::{Event, History, recording::Recording};
pub use billiards_rules::RulesLog;
use billiards_rules::Shots;

use super::jobs::{ExportFormat, ExportScope};

/// A recording loaded for replay, with its history rebuilt for exact sampling.
#[derive(Debug)]
pub struct OpenRecording {
    /// The file it was loaded from.
    pub path: PathBuf,
    /// The recording (shared with export and verification threads).
    pub recording: Arc<Recording>,
    /// Every ball's closed-form trajectory, rebuilt from the recorded events.
    pub history: History,
    /// The shots: strike times and where the replay ends.
    pub shots: Shots,
    /// The rules' log beside the file (`NAME.game.json` for every game; a snooker frame saved
    /// by an older build has `NAME.snooker.json`, still read so those recordings keep their
    /// verdicts): `None` for free play, an error text when it is there but cannot be read (the
    /// recording still replays).
    pub game: Option<Result<RulesLog, String>>,
    /// The log's line of each shot ([`RulesLog::lines`]), made once when opened.
    lines: Vec<String>,
}

impl OpenRecording {
    /// Rebuilds the history of a loaded recording.
    pub fn new(path: &Path, recording: Recording) -> Result<Self, String> {
        let history = recording
            .history()
            .map_err(|error| format!("{}: {error}", path.display()))?;
        let game = read_log(path);
        let lines = match &game {
            Some(Ok(log)) => log.lines(),
            _ => Vec::new(),
        };
        Ok(Self {
            path: path.to_path_buf(),
            game,
            lines,
            shots: Shots::of(&recording),
            recording: Arc::new(recording),
            history,
        })
    }

    /// Where the replay ends: the recording's end time (or its last event, if later).
    pub fn end_time(&self) -> f64 {
        self.shots.end()
    }

    /// The events, in time order.
    pub fn events(&self) -> &[Event] {
        self.history.events()
    }

    /// The number printed on recorded ball `id`.
    pub fn number(&self, id: usize) -> u8 {
        self.recording.balls.get(id).map_or(0, |ball| ball.number)
    }

    /// The file name, for titles.
    pub fn file_name(&self) -> String {
        self.path
            .file_name()
            .unwrap_or(self.path.as_os_str())
            .to_string_lossy()
            .into_owned()
    }

    /// The last event at or before `t`, with its index.
    pub fn event_at(&self, t: f64) -> Option<(usize, &Event)> {
        let events = self.events();
        let after = events.partition_point(|event| event.time <= t);
        after.checked_sub(1).map(|i| (i, &events[i]))
    }

    /// The rules' line for the shot under `t` ("shot 3, Bob: foul: ..."), if the recording is
    /// a rules game (or its log cannot be read).
    pub fn game_line(&self, t: f64) -> Option<String> {
        match self.game.as_ref()? {
            Err(error) => Some(format!("game log: {error}")),
            Ok(_) => self.lines.get(self.shot_at(t).checked_sub(1)?).cloned(),
        }
    }

    /// Re-judges the recorded shots with the rules and compares the logged verdicts
    /// ([`RulesLog::check`]): the number of verdicts confirmed, `None` for free play.
    pub fn check_verdicts(&self) -> Option<Result<usize, String>> {
        let log = match self.game.as_ref()? {
            Ok(log) => log,
            Err(error) => return Some(Err(error.clone())),
        };
        Some(log.check(&self.recording))
    }

    /// The time of the first event after `t`.
    pub fn next_event_time(&self, t: f64) -> Option<f64> {
        let events = self.events();
        events
            .get(events.partition_point(|event| event.time <= t))
            .map(|event| event.time)
    }

    /// The time of the last event before `t`.
    pub fn previous_event_time(&self, t: f64) -> Option<f64> {
        let events = self.events();
        let before = events.partition_point(|event| event.time < t);
        before.checked_sub(1).map(|i| events[i].time)
    }

    /// The shot under `t`, counted from 1 (0 before the first strike).
    pub fn shot_at(&self, t: f64) -> usize {
        self.shots.at(t)
    }

    /// The shot an export of `scope` at replay time `t` covers (`None`: the whole game), and
    /// its time span.
    pub fn export_span(&self, scope: ExportScope, t: f64) -> (Option<usize>, (f64, f64)) {
        let whole = (None, self.shots.whole());
        match scope {
            ExportScope::WholeGame => whole,
            ExportScope::CurrentShot => {
                let k = self.shot_at(t).max(1);
                self.shots.span(k).map_or(whole, |span| (Some(k), span))
            }
        }
    }

    /// Where an export goes unless told otherwise: next to the recording, named after it
    /// (`<name>.gif`, `<name>_shot3.gif`, `<name>_frames/`, `<name>_shot3_frames/`).
    pub fn default_export_path(&self, format: ExportFormat, shot: Option<usize>) -> PathBuf {
        let stem = self
            .path
            .file_stem()
            .map_or_else(|| "replay".into(), |stem| stem.to_string_lossy());
        let name = match shot {
            Some(k) => format!("{stem}_shot{k}"),
            None => stem.into_owned(),
        };
        let dir = self.path.parent().unwrap_or(Path::new(""));
        match format {
            ExportFormat::Gif => dir.join(format!("{name}.gif")),
            ExportFormat::PngSequence => dir.join(format!("{name}_frames")),
            ExportFormat::Video => dir.join(format!("{name}.mp4")),
        }
    }
}

/// The rules' log beside the recording at `path`, if there is one: `NAME.game.json` (either
/// kind, told apart by content), or an old snooker `NAME.snooker.json`.
fn read_log(path: &Path) -> Option<Result<RulesLog, String>> {
    RulesLog::beside(path).map(|(_, log)| log)
}
