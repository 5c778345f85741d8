//! A game's log: the ruleset, the rack seed, the players, and per shot the choices made
//! before it, the call and the verdict. Saved beside a recording (`NAME.game.json` next to
//! `NAME.json`), so `billiards-physics` stays free of rules and every existing recording
//! still loads; [`GameLog::check`] re-judges the recording's shots and compares the verdicts.
//!
//! A snooker frame's log ([`FrameLog`]) has the same name beside its recording; [`RulesLog`]
//! reads either kind, telling them apart by content.

use crate::game::{Call, Choice, CueBall, Game, GameState, Outcome, RuleError, Seat, Verdict};
use crate::shot::summarise;
use crate::snooker::FrameLog;
use billiards_physics::{Event, EventKind};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The format version this build writes.
pub const LOG_VERSION: u32 = 1;

/// One shot of the log.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct LoggedShot {
    /// Choices taken before the shot ([`GameState::choose`]), in order.
    #[serde(default)]
    pub choices: Vec<Choice>,
    /// The shooter's call.
    #[serde(default)]
    pub call: Call,
    /// The verdict given.
    pub verdict: Verdict,
}

/// The rules side of a recorded game.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct GameLog {
    /// Format version ([`LOG_VERSION`]).
    pub version: u32,
    /// The game.
    pub game: Game,
    /// The seed the rack was built from ([`Game::rack`]).
    pub rack_seed: u64,
    /// The players' names, by [`Seat::index`].
    pub players: [String; 2],
    /// Who broke.
    pub breaker: Seat,
    /// The shots, in order (one per strike of the recording).
    pub shots: Vec<LoggedShot>,
}

/// Why a log does not match its recording.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LogError {
    /// Not as many shots as strikes.
    #[error("the log has {logged} shots, the recording {recorded} strikes")]
    ShotCount {
        /// Shots in the log.
        logged: usize,
        /// Strikes in the recording.
        recorded: usize,
    },
    /// A logged choice or call is refused by the rules.
    #[error("shot {shot}: {error}")]
    Refused {
        /// The shot, from 1.
        shot: usize,
        /// The rules' answer.
        error: RuleError,
    },
    /// The rules give another verdict than the one logged.
    #[error("shot {shot}: logged \"{logged}\", re-judged \"{rejudged}\"")]
    Differs {
        /// The shot, from 1.
        shot: usize,
        /// The logged verdict's reason and outcome.
        logged: String,
        /// The new verdict's reason and outcome.
        rejudged: String,
    },
}

impl GameLog {
    /// An empty log.
    pub fn new(game: Game, rack_seed: u64, players: [String; 2], breaker: Seat) -> Self {
        Self {
            version: LOG_VERSION,
            game,
            rack_seed,
            players,
            breaker,
            shots: Vec::new(),
        }
    }

    /// Where the log of the recording at `recording` is kept: `NAME.game.json` beside
    /// `NAME.json`.
    pub fn path_beside(recording: &Path) -> PathBuf {
        recording.with_extension("game.json")
    }

    /// Re-judges every shot of a recording's `events` (`numbers` as in the recording's
    /// setup) and checks that the verdicts are the logged ones. Returns the shots checked.
    pub fn check(&self, events: &[Event], numbers: &[u8]) -> Result<usize, LogError> {
        let strikes: Vec<usize> = events
            .iter()
            .enumerate()
            .filter(|(_, e)| matches!(e.kind, EventKind::Strike { .. }))
            .map(|(i, _)| i)
            .collect();
        if strikes.len() != self.shots.len() {
            return Err(LogError::ShotCount {
                logged: self.shots.len(),
                recorded: strikes.len(),
            });
        }
        let mut state = GameState::new(self.game, self.breaker);
        for (k, (logged, &at)) in (1..).zip(self.shots.iter().zip(&strikes)) {
            let refused = |error| LogError::Refused { shot: k, error };
            for &choice in &logged.choices {
                state.choose(choice).map_err(refused)?;
            }
            let summary = summarise(&events[at..], numbers);
            let verdict = state.play(&summary, logged.call).map_err(refused)?;
            if verdict != logged.verdict {
                let show = |v: &Verdict| format!("{}, {:?}", v.reason(), v.outcome);
                return Err(LogError::Differs {
                    shot: k,
                    logged: show(&logged.verdict),
                    rejudged: show(&verdict),
                });
            }
        }
        Ok(self.shots.len())
    }
}

impl GameLog {
    /// Shot `k` (from 1) in words for the replay timeline: who shot, the choices and the call
    /// before it, the verdict and what follows ("Bob: called the 5 in the left side pocket;
    /// foul: the cue ball was pocketed; Alice to shoot, ball in hand"). `None` past the end.
    pub fn shot_text(&self, k: usize) -> Option<String> {
        let shot = self.shots.get(k.checked_sub(1)?)?;
        let v = &shot.verdict;
        let name = |seat: Seat| self.players[seat.index()].as_str();
        let mut parts = Vec::new();
        for c in &shot.choices {
            parts.push(format!("chose to {}", c.label()));
        }
        if v.break_shot {
            parts.push("break".to_owned());
        }
        if let Some(call) = shot.call.text() {
            parts.push(format!("called {call}"));
        }
        parts.push(v.reason());
        if let Some(group) = v.assigned {
            parts.push(format!("takes the {}", group.name()));
        }
        let hand = match v.next.as_ref().map(|n| n.cue_ball) {
            Some(CueBall::InHandAnywhere) => ", ball in hand",
            Some(CueBall::InHandBehindHeadString) => ", ball in hand behind the head string",
            _ => "",
        };
        parts.push(match v.outcome {
            Outcome::Continues => format!("{} continues{hand}", name(v.shooter)),
            Outcome::Passes => match v.next.as_ref() {
                Some(next) if !next.choices.is_empty() => {
                    let options: Vec<&str> = next.choices.iter().map(|c| c.label()).collect();
                    format!("{} chooses: {}", name(next.shooter), options.join(" or "))
                }
                _ => format!("{} to shoot{hand}", name(v.shooter.other())),
            },
            Outcome::GameOver { winner, reason } => format!("{} wins: {reason}", name(winner)),
        });
        Some(format!("{}: {}", name(v.shooter), parts.join("; ")))
    }

    /// Reads a log from its JSON text, refusing other format versions.
    pub fn from_json(text: &str) -> Result<Self, String> {
        let log: GameLog =
            serde_json::from_str(text).map_err(|e| format!("not a game log: {e}"))?;
        if log.version != LOG_VERSION {
            return Err(format!(
                "game log version {} (this build reads {LOG_VERSION})",
                log.version
            ));
        }
        Ok(log)
    }
}

/// The rules' log of a recorded game, of either kind: both are saved as `NAME.game.json`
/// beside the recording `NAME.json`.
#[derive(Debug, Clone, PartialEq)]
pub enum RulesLog {
    /// A rack of 8-ball or 9-ball.
    Pool(GameLog),
    /// A frame of snooker.
    Snooker(FrameLog),
    /// Any game, through the one interface ([`crate::stroke_log::StrokeLog`]).
    Strokes(crate::stroke_log::StrokeLog),
}

impl RulesLog {
    /// Reads a log of either kind from its JSON text. The kinds are told apart by content: a
    /// pool log names its `game` (and rack seed), a frame log does not. Anything else (a
    /// recording, another JSON file) is refused with the reason.
    pub fn from_json(text: &str) -> Result<Self, String> {
        let value: serde_json::Value =
            serde_json::from_str(text).map_err(|e| format!("not a rules log: {e}"))?;
        let Some(object) = value.as_object() else {
            return Err("not a rules log: not a JSON object".into());
        };
        if object.contains_key("start") {
            crate::stroke_log::StrokeLog::from_json(text).map(RulesLog::Strokes)
        } else if object.contains_key("game") {
            GameLog::from_json(text).map(RulesLog::Pool)
        } else if object.contains_key("breaker") && object.contains_key("players") {
            FrameLog::from_json(text).map(RulesLog::Snooker)
        } else {
            Err("not a rules log (it has no players nor breaker)".into())
        }
    }

    /// The log beside the recording at `recording`, if there is one: `NAME.game.json`, or,
    /// for a snooker frame saved by an older build, `NAME.snooker.json` (still read so that
    /// those recordings keep their verdicts). `None` when neither file is there; the path
    /// read and the log (or why it cannot be read: path and reason) otherwise.
    pub fn beside(recording: &Path) -> Option<(PathBuf, Result<Self, String>)> {
        let path = [
            GameLog::path_beside(recording),
            FrameLog::old_path_beside(recording),
        ]
        .into_iter()
        .find(|path| path.exists())?;
        let log = std::fs::read_to_string(&path)
            .map_err(|e| e.to_string())
            .and_then(|text| Self::from_json(&text))
            .map_err(|e| format!("{}: {e}", path.display()));
        Some((path, log))
    }

    /// Re-judges `recording` with this log: the number of verdicts confirmed, or the first
    /// difference (or why the recording cannot be judged) in words.
    pub fn check(
        &self,
        recording: &billiards_physics::recording::Recording,
    ) -> Result<usize, String> {
        match self {
            RulesLog::Pool(log) => {
                let numbers: Vec<u8> = recording.balls.iter().map(|b| b.number).collect();
                log.check(&recording.events, &numbers)
                    .map_err(|e| e.to_string())
            }
            RulesLog::Snooker(log) => log.check(recording).map_err(|e| e.to_string()),
            RulesLog::Strokes(log) => log.check(recording),
        }
    }

    /// The timeline's line of every shot, in order: "shot 3, Bob: foul: ...", "stroke 3: ...".
    pub fn lines(&self) -> Vec<String> {
        match self {
            RulesLog::Pool(log) => (1..=log.shots.len())
                .filter_map(|k| Some(format!("shot {k}, {}", log.shot_text(k)?)))
                .collect(),
            RulesLog::Snooker(log) => (log.strokes.iter().enumerate())
                .map(|(i, s)| format!("stroke {}: {}", i + 1, s.verdict.text))
                .collect(),
            RulesLog::Strokes(log) => log.lines(),
        }
    }

    /// What its verdicts are, for "N ... re-judged identically": "verdicts of NineBall",
    /// "snooker verdicts", "three-cushion verdicts".
    pub fn verdicts(&self) -> String {
        match self {
            RulesLog::Pool(log) => format!("verdicts of {:?}", log.game),
            RulesLog::Snooker(_) => "snooker verdicts".to_owned(),
            RulesLog::Strokes(log) => format!("{} verdicts", log.game),
        }
    }

    /// Whether `text` is a rules log of either kind (a file given where a recording was
    /// expected is then named as such).
    pub fn is_log(text: &str) -> bool {
        Self::from_json(text).is_ok()
    }

    /// When the file at `path`, given where a recording was expected, is a rules log (by its
    /// content, or by its `.game.json` / `.snooker.json` name), what to tell the player:
    /// "X is a rules log, not a recording: `do_what` the recording beside it, Y". `None` when
    /// it is not a log (the loader's own error is then the answer).
    pub fn mistaken_for_recording(path: &Path, do_what: &str) -> Option<String> {
        let is_log = std::fs::read_to_string(path).is_ok_and(|text| Self::is_log(&text));
        let beside = Self::recording_beside(path);
        if !is_log && beside.is_none() {
            return None;
        }
        let what = format!("{} is a rules log, not a recording", path.display());
        Some(match beside {
            Some(recording) => format!(
                "{what}: {do_what} the recording beside it, {}",
                recording.display()
            ),
            None => format!("{what}: {do_what} the recording it was saved beside"),
        })
    }

    /// The recording a log at `log` belongs beside: `NAME.json` for `NAME.game.json` (or an
    /// old `NAME.snooker.json`); `None` when the name is neither.
    pub fn recording_beside(log: &Path) -> Option<PathBuf> {
        let name = log.file_name()?.to_str()?;
        let stem = name
            .strip_suffix(".game.json")
            .or_else(|| name.strip_suffix(".snooker.json"))?;
        Some(log.with_file_name(format!("{stem}.json")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::recording::Recorder;
    use billiards_physics::{Params, Shot, Table};

    /// A real 9-ball rack: the break, then a soft shot up the table; logged as played.
    fn played() -> (GameLog, Vec<Event>, Vec<u8>) {
        let table = Table::wpa_8ft().with_jaws(0.015);
        let params = Params::default();
        let balls = Game::NineBall.rack(&table, &params.ball, 4);
        let mut rec = Recorder::new(table, params, balls).unwrap();
        let mut state = GameState::new(Game::NineBall, Seat::A);
        let mut log = GameLog::new(Game::NineBall, 4, ["A".into(), "B".into()], Seat::A);
        for shot in [Shot::new(0.0, 9.0), Shot::new(0.3, 1.0)] {
            if !rec.sim().ball(0).motion.on_table() {
                let p = crate::cue_ball_spot(rec.sim(), 0).unwrap();
                rec.place(0, p, Default::default(), Default::default())
                    .unwrap();
            }
            let first = rec.sim().history().events().len();
            rec.strike(0, shot).unwrap();
            rec.run_to_rest().unwrap();
            let s = summarise(&rec.sim().history().events()[first..], rec.sim().numbers());
            let verdict = state.play(&s, Call::None).unwrap();
            log.shots.push(LoggedShot {
                choices: Vec::new(),
                call: Call::None,
                verdict,
            });
            if state.over.is_some() {
                break;
            }
        }
        let r = rec.recording();
        let numbers = r.balls.iter().map(|b| b.number).collect();
        (log, r.events, numbers)
    }

    #[test]
    fn a_pool_log_reads_as_pool_and_names_its_recording() {
        let (log, _, _) = played();
        let text = serde_json::to_string(&log).unwrap();
        assert_eq!(RulesLog::from_json(&text), Ok(RulesLog::Pool(log)));
        assert!(RulesLog::is_log(&text));
        assert_eq!(
            RulesLog::recording_beside(Path::new("/tmp/rack.game.json")),
            Some(PathBuf::from("/tmp/rack.json"))
        );
        assert_eq!(
            RulesLog::recording_beside(Path::new("/tmp/rack.json")),
            None
        );
    }

    #[test]
    fn a_log_rejudges_its_recording_and_an_edited_verdict_is_found() {
        let (log, events, numbers) = played();
        assert_eq!(log.check(&events, &numbers), Ok(log.shots.len()));
        // Round trip through JSON.
        let json = serde_json::to_string(&log).unwrap();
        assert_eq!(serde_json::from_str::<GameLog>(&json).unwrap(), log);
        let mut edited = log.clone();
        edited.shots[0].verdict.fouls.push(crate::Foul::NoRail);
        assert!(matches!(
            edited.check(&events, &numbers),
            Err(LogError::Differs { shot: 1, .. })
        ));
        let mut short = log.clone();
        short.shots.pop();
        assert!(matches!(
            short.check(&events, &numbers),
            Err(LogError::ShotCount { .. })
        ));
    }

    #[test]
    fn each_logged_shot_reads_as_a_sentence() {
        let (log, _, _) = played();
        let first = log.shot_text(1).unwrap();
        assert!(first.starts_with("A: break; "), "{first}");
        let v = &log.shots[0].verdict;
        assert!(first.contains(&v.reason()), "{first}");
        let follows = match v.outcome {
            Outcome::Continues => "A continues",
            Outcome::Passes => "B to shoot",
            Outcome::GameOver { .. } => "wins",
        };
        assert!(first.contains(follows), "{first}");
        assert_eq!(log.shot_text(0), None);
        assert_eq!(log.shot_text(log.shots.len() + 1), None);
        // A called foul with ball in hand, written by hand.
        let mut called = log.clone();
        called.shots[0].call = Call::Ball {
            ball: 5,
            pocket: billiards_physics::Pocket::SideLeft,
        };
        called.shots[0].verdict = Verdict {
            shooter: Seat::B,
            break_shot: false,
            push_out: false,
            fouls: vec![crate::Foul::Scratch],
            outcome: Outcome::Passes,
            assigned: None,
            next: Some(crate::NextShot::plain(
                Seat::A,
                CueBall::InHandAnywhere,
                vec![1],
                crate::CallRule::Optional,
                0,
            )),
        };
        let text = called.shot_text(1).unwrap();
        let scratch = crate::Foul::Scratch.to_string();
        assert_eq!(
            text,
            format!(
                "B: called the 5 in the left side pocket; foul: {scratch}; A to shoot, ball in hand"
            )
        );
    }

    #[test]
    fn a_log_of_another_version_is_refused() {
        let (log, _, _) = played();
        let json = serde_json::to_string(&log).unwrap();
        assert_eq!(GameLog::from_json(&json), Ok(log.clone()));
        let other = json.replacen("\"version\":1", "\"version\":2", 1);
        assert!(
            GameLog::from_json(&other)
                .unwrap_err()
                .contains("version 2")
        );
        assert!(
            GameLog::from_json("{")
                .unwrap_err()
                .starts_with("not a game log")
        );
    }

    #[test]
    fn the_log_lives_beside_the_recording() {
        assert_eq!(
            GameLog::path_beside(Path::new("/tmp/rack.json")),
            PathBuf::from("/tmp/rack.game.json")
        );
    }
}
