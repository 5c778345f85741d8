//! Command-line options of the game binary.

use std::{fmt, path::PathBuf, time::Duration};

/// What the binary was asked to do on the command line.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LaunchOptions {
    /// Capture the first fully drawn frame to this PNG file, then exit.
    pub screenshot: Option<PathBuf>,
    /// How long the scene must have been fully drawn before the capture (wall time).
    pub screenshot_settle: Duration,
    /// Start with the camera straight above the table.
    pub top_view: bool,
    /// Print the usage text and exit.
    pub show_help: bool,
    /// Where recordings are saved and listed (default: `recordings` in the current folder).
    pub recordings: Option<PathBuf>,
    /// Do not save recordings.
    pub no_record: bool,
    /// Neither read nor write the settings file (start from the defaults).
    pub no_config: bool,
    /// The window's size in logical pixels (default 1280x720).
    pub size: Option<(u32, u32)>,
    /// Write a check of the UI's text (cut, elided, off screen) to this file every frame.
    pub check_layout: Option<PathBuf>,
    /// Open every section of the panel (for screenshots and the layout check).
    pub open_sections: bool,
    /// Count the frames drawn in this long at idle, print them and exit.
    pub count_idle_frames: Option<Duration>,
    /// Open this recording in the replay viewer at start (`billiards replay FILE`).
    pub replay: Option<PathBuf>,
    /// Start a match of this game (two players, the game's usual length) instead of free
    /// play.
    pub game: Option<crate::play::game::GameChoice>,
    /// Start on the stress table with this many balls (frictionless, seed 1).
    pub stress: Option<usize>,
    /// Start from this position (`--position CODE`), decoded and checked.
    pub position: Option<billiards_rules::Position>,
    /// Start a session of this drill (`--drill NAME`: its file name in the drills list,
    /// with or without `.json`).
    pub drill: Option<String>,
    /// The player's moves to play at launch (`--script`), parsed.
    pub script: Vec<crate::play::script::Step>,
    /// The second seat is the computer's, at this level (`--computer`, with `--game`).
    pub computer: Option<billiards_ai::Level>,
    /// The first rack's seed (`--seed`, with `--game`).
    pub seed: Option<u64>,
}

/// Why the command line could not be understood.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ArgsError {
    /// A flag that needs a value came last.
    MissingValue(&'static str),
    /// A value that could not be parsed.
    InvalidValue {
        /// The flag the value belongs to.
        flag: &'static str,
        /// The text that was given.
        value: String,
    },
    /// A flag this binary does not know.
    UnknownArgument(String),
    /// Two flags that exclude each other were both given.
    Conflict(&'static str, &'static str),
    /// `--position`'s code was refused: why.
    Position(String),
    /// `--script` could not be read: why.
    Script(String),
    /// A flag that needs another one was given without it.
    Needs(&'static str, &'static str),
}

impl fmt::Display for ArgsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::MissingValue(flag) => write!(f, "{flag} needs a value"),
            Self::InvalidValue { flag, value } => write!(f, "invalid value {value:?} for {flag}"),
            Self::UnknownArgument(arg) => write!(f, "unknown argument {arg:?}"),
            Self::Conflict(a, b) => write!(f, "{a} and {b} cannot be used together"),
            Self::Position(why) => write!(f, "--position: {why}"),
            Self::Script(why) => write!(f, "--script: {why}"),
            Self::Needs(a, b) => write!(f, "{a} needs {b}"),
        }
    }
}

impl std::error::Error for ArgsError {}

impl LaunchOptions {
    /// The usage text printed by `--help` and after a command-line error.
    pub const USAGE: &'static str = "\
usage: billiards [replay FILE] [--recordings DIR | --no-record] [--top-view]
                 [--game nine-ball|ten-ball|eight-ball|snooker|free-play] [--no-config]
                 [--size WxH] [--screenshot PATH [--settle SECONDS]]
                 [--check-layout PATH] [--open-sections] [--count-idle-frames SECONDS]
                 [--stress BALLS] [--position CODE] [--drill NAME]
                 [--computer] [--seed N] [--script STEPS]

  replay FILE         open a recording in the replay viewer
  --recordings DIR    save every game there, one file per rack (default: ./recordings)
  --no-record         do not save recordings
  --no-config         start from the default settings and keep none (the settings file
                      is otherwise in the config directory: $XDG_CONFIG_HOME/billiards)
  --game GAME         start a match between two players: nine-ball, ten-ball or
                      eight-ball (race to 3), snooker (best of 3 frames), three-cushion
                      (40 points); free-play (the default) is the sandbox
  --stress BALLS      start on the stress table (free play): BALLS balls on a table grown
                      to hold them, frictionless; the panel's Stress table section changes it
  --position CODE     start from a position code (the panel's Copy position makes one;
                      billiards-cli position encode too): its balls, table, physics, shot
  --drill NAME        start a session of a drill of the New game dialog's list, by its file
                      name (04-cut-30, or user/NAME for one of your own)
  --computer          with --game: the computer plays the second seat (medium)
  --seed N            with --game: the first rack's seed (racks repeat; default: the clock)
  --script STEPS      play these moves at launch, each when the game asks for it, ';'
                      between them: shoot DEG SPEED (degrees from the long axis, m/s),
                      continue, call BALL POCKET (head-left ... foot-right), nominate
                      BALL, choose K (the K-th choice offered), move BALL X Y (metres
                      from the centre); a screenshot waits
                      until they are played and the balls rest

  --screenshot PATH   wait until the scene has been drawn, save it as PNG to PATH, exit
  --settle SECONDS    how long every render pipeline must have been ready before the
                      capture (default 2; 4 frames at least, however long they take)
  --top-view          start with the camera straight above the table (T toggles it)
  --size WxH          window size in logical pixels (default 1280x720)
  --check-layout PATH write every text of the UI that is cut, elided or off screen to
                      PATH after each frame (the render test reads it)
  --open-sections     open every section of the panel
  --count-idle-frames SECONDS
                      once drawn, count the frames the idle window draws in SECONDS,
                      print \"idle frames: N in S s\" and exit
  -h, --help          print this text";

    /// Wall time the scene must have been fully drawn before a screenshot, unless overridden.
    pub const DEFAULT_SETTLE: Duration = Duration::from_secs(2);

    /// Parses the arguments that follow the program name.
    pub fn from_args(args: impl IntoIterator<Item = String>) -> Result<Self, ArgsError> {
        let mut options = Self {
            screenshot_settle: Self::DEFAULT_SETTLE,
            ..Self::default()
        };
        let mut args = args.into_iter();
        while let Some(arg) = args.next() {
            match arg.as_str() {
                "--screenshot" => {
                    let path = args.next().ok_or(ArgsError::MissingValue("--screenshot"))?;
                    options.screenshot = Some(PathBuf::from(path));
                }
                "--settle" => {
                    let value = args.next().ok_or(ArgsError::MissingValue("--settle"))?;
                    options.screenshot_settle = seconds("--settle", value)?;
                }
                "--top-view" => options.top_view = true,
                "--open-sections" => options.open_sections = true,
                "--size" => {
                    let value = args.next().ok_or(ArgsError::MissingValue("--size"))?;
                    let parsed = value
                        .split_once('x')
                        .and_then(|(w, h)| Some((w.parse().ok()?, h.parse().ok()?)))
                        .filter(|&(w, h): &(u32, u32)| {
                            (200..=8192).contains(&w) && (200..=8192).contains(&h)
                        });
                    options.size = Some(parsed.ok_or(ArgsError::InvalidValue {
                        flag: "--size",
                        value,
                    })?);
                }
                "--check-layout" => {
                    let path = args
                        .next()
                        .ok_or(ArgsError::MissingValue("--check-layout"))?;
                    options.check_layout = Some(PathBuf::from(path));
                }
                "--count-idle-frames" => {
                    let value = args
                        .next()
                        .ok_or(ArgsError::MissingValue("--count-idle-frames"))?;
                    options.count_idle_frames = Some(seconds("--count-idle-frames", value)?);
                }
                "--recordings" => {
                    let dir = args.next().ok_or(ArgsError::MissingValue("--recordings"))?;
                    options.recordings = Some(PathBuf::from(dir));
                }
                "--no-record" => options.no_record = true,
                "--no-config" => options.no_config = true,
                "--game" => {
                    let value = args.next().ok_or(ArgsError::MissingValue("--game"))?;
                    options.game = Some(game_choice(value)?);
                }
                "--stress" => {
                    let value = args.next().ok_or(ArgsError::MissingValue("--stress"))?;
                    // The count's own limits are the physics crate's, refused in the game.
                    options.stress = Some(value.parse().map_err(|_| ArgsError::InvalidValue {
                        flag: "--stress",
                        value,
                    })?);
                }
                "--position" => {
                    let code = args.next().ok_or(ArgsError::MissingValue("--position"))?;
                    let position = billiards_rules::Position::decode(&code)
                        .map_err(|e| ArgsError::Position(e.to_string()))?;
                    options.position = Some(position);
                }
                "--drill" => {
                    let name = args.next().ok_or(ArgsError::MissingValue("--drill"))?;
                    options.drill = Some(name);
                }
                "replay" if options.replay.is_none() => {
                    let file = args.next().ok_or(ArgsError::MissingValue("replay"))?;
                    options.replay = Some(PathBuf::from(file));
                }
                "--script" => {
                    let steps = args.next().ok_or(ArgsError::MissingValue("--script"))?;
                    options.script =
                        crate::play::script::parse(&steps).map_err(ArgsError::Script)?;
                }
                "--computer" => options.computer = Some(billiards_ai::Level::Medium),
                "--seed" => {
                    let value = args.next().ok_or(ArgsError::MissingValue("--seed"))?;
                    options.seed = Some(value.parse().map_err(|_| ArgsError::InvalidValue {
                        flag: "--seed",
                        value,
                    })?);
                }
                "-h" | "--help" => options.show_help = true,
                _ => return Err(ArgsError::UnknownArgument(arg)),
            }
        }
        options.check()?;
        Ok(options)
    }

    /// The options the usage marks exclusive, or that need another, refused.
    fn check(&self) -> Result<(), ArgsError> {
        // The usage marks them exclusive: saving nowhere and saving to DIR.
        if self.no_record && self.recordings.is_some() {
            return Err(ArgsError::Conflict("--no-record", "--recordings"));
        }
        if self.stress.is_some() && self.game.is_some() {
            return Err(ArgsError::Conflict("--stress", "--game"));
        }
        for (flag, given) in [
            ("--stress", self.stress.is_some()),
            ("--game", self.game.is_some()),
        ] {
            if given && self.position.is_some() {
                return Err(ArgsError::Conflict("--position", flag));
            }
            if given && self.drill.is_some() {
                return Err(ArgsError::Conflict("--drill", flag));
            }
        }
        if self.position.is_some() && self.drill.is_some() {
            return Err(ArgsError::Conflict("--drill", "--position"));
        }
        for (flag, given) in [
            ("--computer", self.computer.is_some()),
            ("--seed", self.seed.is_some()),
        ] {
            if given && self.game.is_none() {
                return Err(ArgsError::Needs(flag, "--game"));
            }
        }
        if self.screenshot.is_some() && self.count_idle_frames.is_some() {
            return Err(ArgsError::Conflict("--screenshot", "--count-idle-frames"));
        }
        Ok(())
    }
}

/// `value` of `flag` as seconds (`--settle 2.5`), refused when not a duration.
fn seconds(flag: &'static str, value: String) -> Result<Duration, ArgsError> {
    value
        .parse::<f64>()
        .ok()
        .and_then(|s| Duration::try_from_secs_f64(s).ok())
        .ok_or(ArgsError::InvalidValue { flag, value })
}

/// `--game`'s value: any game of the catalog by its id (`nine-ball`, `three-cushion`).
fn game_choice(value: String) -> Result<crate::play::game::GameChoice, ArgsError> {
    use crate::play::game::GameChoice;
    match billiards_rules::catalog::find(&value) {
        Ok(entry) => Ok(GameChoice::Catalog(entry.id)),
        Err(_) => Err(ArgsError::InvalidValue {
            flag: "--game",
            value,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<LaunchOptions, ArgsError> {
        LaunchOptions::from_args(args.iter().map(|s| s.to_string()))
    }

    #[test]
    fn a_script_a_computer_and_a_seed() {
        let options = parse(&[
            "--game",
            "nine-ball",
            "--computer",
            "--seed",
            "7",
            "--script",
            "shoot 90 0.6; continue",
        ])
        .unwrap();
        assert_eq!(options.script.len(), 2);
        assert_eq!(options.computer, Some(billiards_ai::Level::Medium));
        assert_eq!(options.seed, Some(7));
        assert_eq!(
            parse(&["--computer"]),
            Err(ArgsError::Needs("--computer", "--game"))
        );
        assert!(matches!(
            parse(&["--script", "shoot fast"]),
            Err(ArgsError::Script(_))
        ));
        assert!(matches!(
            parse(&["--game", "snooker", "--seed", "x"]),
            Err(ArgsError::InvalidValue { flag: "--seed", .. })
        ));
    }

    #[test]
    fn no_arguments_means_play() {
        let options = parse(&[]).unwrap();
        assert_eq!(options.screenshot, None);
        assert_eq!(options.screenshot_settle, LaunchOptions::DEFAULT_SETTLE);
        assert!(!options.show_help);
    }

    #[test]
    fn screenshot_and_settle_are_read() {
        let options = parse(&["--screenshot", "out.png", "--settle", "0.5", "--top-view"]).unwrap();
        assert!(options.top_view);
        assert_eq!(options.screenshot, Some(PathBuf::from("out.png")));
        assert_eq!(options.screenshot_settle, Duration::from_millis(500));
    }

    #[test]
    fn replay_and_recordings_are_read() {
        assert_eq!(parse(&["--stress", "1000"]).unwrap().stress, Some(1000));
        assert!(matches!(
            parse(&["--stress", "many"]),
            Err(ArgsError::InvalidValue {
                flag: "--stress",
                ..
            })
        ));
        assert!(parse(&["--stress", "16", "--game", "snooker"]).is_err());
        let options = parse(&["replay", "game.json", "--recordings", "out"]).unwrap();
        assert_eq!(options.replay, Some(PathBuf::from("game.json")));
        assert_eq!(options.recordings, Some(PathBuf::from("out")));
        assert!(!options.no_record);
        assert!(parse(&["--no-record"]).unwrap().no_record);
        assert_eq!(
            parse(&["--game", "nine-ball"]).unwrap().game,
            Some(crate::play::game::GameChoice::Catalog("nine-ball"))
        );
        assert_eq!(
            parse(&["--game", "ten-ball"]).unwrap().game,
            Some(crate::play::game::GameChoice::Catalog("ten-ball"))
        );
        assert_eq!(
            parse(&["--game", "snooker"]).unwrap().game,
            Some(crate::play::game::GameChoice::Catalog("snooker"))
        );
        assert_eq!(
            parse(&["--game", "three-cushion"]).unwrap().game,
            Some(crate::play::game::GameChoice::Catalog("three-cushion"))
        );
        assert!(matches!(
            parse(&["--game", "pyramid"]),
            Err(ArgsError::InvalidValue { flag: "--game", .. })
        ));
        assert_eq!(parse(&["replay"]), Err(ArgsError::MissingValue("replay")));
        assert_eq!(
            parse(&["--size", "1920x1080"]).unwrap().size,
            Some((1920, 1080))
        );
        assert!(matches!(
            parse(&["--size", "big"]),
            Err(ArgsError::InvalidValue { flag: "--size", .. })
        ));
        assert_eq!(
            parse(&["--count-idle-frames", "10"])
                .unwrap()
                .count_idle_frames,
            Some(Duration::from_secs(10))
        );
    }

    /// Issue 39: `--position` opens a code's position; a damaged or cut code is refused at
    /// the command line with the code's own reason, before a window opens.
    #[test]
    fn a_position_code_is_read_or_refused_with_its_reason() {
        use billiards_physics::{BallSpec, Rack, Table};
        use billiards_rules::{Game, PlacedBall, Position};
        let table = Table::wpa_9ft().with_jaws(0.015);
        let balls = Rack::NineBall
            .layout(&table, &BallSpec::default())
            .into_iter()
            .map(|b| PlacedBall {
                number: b.number,
                position: b.position,
            })
            .collect();
        let p = Position {
            game: Game::NineBall,
            table,
            balls,
            params: None,
            shot: None,
        };
        let code = p.encode().unwrap();
        assert_eq!(parse(&["--position", &code]).unwrap().position, Some(p));
        let cut = &code[..code.len() - 5];
        match parse(&["--position", cut]) {
            // The command line says the code's own reason.
            Err(ArgsError::Position(why)) => {
                assert_eq!(why, Position::decode(cut).unwrap_err().to_string())
            }
            other => panic!("a cut code was not refused: {other:?}"),
        }
        assert!(matches!(
            parse(&["--position", &code, "--game", "snooker"]),
            Err(ArgsError::Conflict("--position", "--game"))
        ));
        assert_eq!(
            parse(&["--position"]),
            Err(ArgsError::MissingValue("--position"))
        );
    }

    #[test]
    fn bad_arguments_are_errors() {
        assert_eq!(
            parse(&["--screenshot"]),
            Err(ArgsError::MissingValue("--screenshot"))
        );
        assert!(matches!(
            parse(&["--settle", "-1"]),
            Err(ArgsError::InvalidValue { .. })
        ));
        assert_eq!(
            parse(&["--fast"]),
            Err(ArgsError::UnknownArgument("--fast".into()))
        );
        assert_eq!(
            parse(&["--no-record", "--recordings", "out"]),
            Err(ArgsError::Conflict("--no-record", "--recordings"))
        );
    }
}
