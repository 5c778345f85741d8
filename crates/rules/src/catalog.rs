//! Every game there is, each started behind the one interface ([`GameRules`], issue 50):
//! the New game dialog lists [`GAMES`], the command line finds one by [`find`]'s id
//! (`--game nine-ball`), and both start it with [`GameEntry::start`]. Adding a game is one
//! entry here and an implementation of [`GameRules`] in the game's own module.

use crate::interface::{GameRules, RulesError};
use crate::pool::PoolMatch;
use crate::racks::RackStyle;
use crate::snooker::rules::SnookerGame;
use crate::state::Game;
use crate::three_cushion::rules::ThreeCushionMatch;
use billiards_physics::{BallSpec, Model, Params, SpinModel, Table};

/// How a match is set up, for any game.
#[derive(Clone, Debug, PartialEq)]
pub struct MatchSettings {
    /// The players' names; A opens.
    pub players: [String; 2],
    /// The match's length in the game's unit: racks to win (pool), frames best of (snooker,
    /// odd), points to reach (carom).
    pub length: u32,
    /// The seed of the first rack's random gaps.
    pub seed: u64,
    /// How pool's racks are set.
    pub style: RackStyle,
    /// The table and balls; `None`: the game's own ([`GameEntry::equipment`]).
    pub equipment: Option<(Table, BallSpec)>,
}

impl MatchSettings {
    /// Two players, a match of `length`, seed `seed`, the game's own equipment.
    pub fn new(players: [String; 2], length: u32, seed: u64) -> Self {
        Self {
            players,
            length,
            seed,
            style: RackStyle::Triangle,
            equipment: None,
        }
    }
}

/// What a game's match is counted in, and with it what a tournament counts of the game
/// besides wins, fouls and decision times (each read from the interface: the judgements and
/// [`GameRules::points`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// Racks (pool): object balls pocketed an inning, racks won from the break without the
    /// other player striking (break and run).
    Racks,
    /// Frames (snooker): points a frame, breaks (points in a visit, WPBSA 2.8), the highest,
    /// centuries.
    Frames,
    /// Points (carom): the general average (points an inning) and the high run (the most
    /// points in one inning).
    Points,
}

impl Unit {
    /// What a match's length is in: "racks", "frames", "points".
    pub fn noun(self) -> &'static str {
        match self {
            Unit::Racks => "racks",
            Unit::Frames => "frames",
            Unit::Points => "points",
        }
    }

    /// What one game of a match is called: a rack, a frame, a game.
    pub fn game(self) -> &'static str {
        match self {
            Unit::Racks => "rack",
            Unit::Frames => "frame",
            Unit::Points => "game",
        }
    }
}

/// How an entry starts a match on the given table and balls.
pub type Start = fn(&MatchSettings, Table, BallSpec) -> Result<Box<dyn GameRules>, RulesError>;

/// One game of the catalog.
#[derive(Clone, Copy, Debug)]
pub struct GameEntry {
    /// The id on the command line (`nine-ball`).
    pub id: &'static str,
    /// The player's name for it (`9-ball`).
    pub label: &'static str,
    /// What the match's length counts ("race to", "best of", "points to").
    pub length_unit: &'static str,
    /// What the length is in ([`Unit::noun`]) and what a tournament counts of the game.
    pub unit: Unit,
    /// The usual length of a match.
    pub default_length: u32,
    /// The length of a match of one game: one rack (race to 1), one frame (best of 1), one
    /// carom game to its usual points; what a tournament plays by default.
    pub one_game: u32,
    /// The solver's parameters the command line's tournaments play it under (their figures in
    /// the READMEs were measured so): pool's and carom's the spin model (Han 2005's cushion),
    /// snooker's the paper model of issue 26's frames; the ball is always the game's.
    pub params: fn() -> Params,
    /// The game's own table and balls.
    pub equipment: fn() -> (Table, BallSpec),
    /// Played on any pool table of the player's choosing (its size, pockets, jaws and
    /// rack style: pool's games); otherwise only on its own ([`GameEntry::equipment`]).
    pub pool_table: bool,
    /// A ball in the words of a view of the table without the game in hand (a replay):
    /// "cue ball", "ball 3"; "pink"; "white".
    pub ball_word: fn(u8) -> String,
    /// Balls pocketed or off the table, named for [`GameEntry::list_words`]: "the 3", "2
    /// reds", "the pink", "the cue ball".
    pub list_names: fn(&[u8]) -> Vec<String>,
    start: Start,
}

impl GameEntry {
    /// Balls pocketed or off the table, in a sentence in this game's words ("the 3, the 12,
    /// the cue ball", "2 reds, the pink"; "none").
    pub fn list_words(&self, numbers: &[u8]) -> String {
        let names = (self.list_names)(numbers);
        if names.is_empty() {
            "none".to_owned()
        } else {
            names.join(", ")
        }
    }

    /// Starts a match of this game.
    pub fn start(&self, settings: &MatchSettings) -> Result<Box<dyn GameRules>, RulesError> {
        if settings.length == 0 {
            return Err(RulesError(format!(
                "a match of {} needs a length of at least 1 ({} 0 given)",
                self.label, self.length_unit
            )));
        }
        let (table, ball) = settings.equipment.unwrap_or_else(self.equipment);
        (self.start)(settings, table, ball)
    }
}

/// The spin model with its default cushion (Han 2005): pool's and carom's studies.
fn spin_params() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

/// Pool's table: the WPA 8-ft table with 15 mm jaws (the game's default venue) and the
/// WPA ball (2.25 in).
fn pool_equipment() -> (Table, BallSpec) {
    (Table::wpa_8ft().with_jaws(0.015), BallSpec::default())
}

fn snooker_equipment() -> (Table, BallSpec) {
    (Table::snooker_12ft(), BallSpec::snooker())
}

/// The UMB match table (2.84 x 1.42 m, Art. 11) and ball (61.5 mm, Art. 12).
fn carom_equipment() -> (Table, BallSpec) {
    (Table::carom_match(), BallSpec::carom())
}

fn pool(game: Game, s: &MatchSettings, table: Table, ball: BallSpec) -> Box<dyn GameRules> {
    Box::new(PoolMatch::new(
        game,
        s.players.clone(),
        s.length,
        table,
        ball,
        s.seed,
        s.style,
    ))
}

/// Pool's ball by number: "cue ball", "ball 3".
fn pool_word(n: u8) -> String {
    if n == 0 {
        "cue ball".to_owned()
    } else {
        format!("ball {n}")
    }
}

/// Pool's balls by number, the cue ball last: "the 3", "the 12", "the cue ball" (issue 48:
/// "pocketed: 12" read as a count).
fn pool_list(numbers: &[u8]) -> Vec<String> {
    let mut names: Vec<String> = numbers
        .iter()
        .filter(|&&n| n != 0)
        .map(|n| format!("the {n}"))
        .collect();
    if numbers.contains(&0) {
        names.push("the cue ball".to_owned());
    }
    names
}

/// The game whose own table `table` is (snooker's, three-cushion's: by its length and
/// width), else 9-ball's (any pool table): what names its balls where no game is in hand.
pub fn of_table(table: &Table) -> &'static GameEntry {
    let own = |g: &&GameEntry| {
        let (t, _) = (g.equipment)();
        !g.pool_table && t.length == table.length && t.width == table.width
    };
    GAMES.iter().find(own).unwrap_or(&GAMES[0])
}

/// Every game, in the dialog's order.
pub const GAMES: &[GameEntry] = &[
    GameEntry {
        id: "nine-ball",
        label: "9-ball",
        length_unit: "race to",
        unit: Unit::Racks,
        default_length: 3,
        one_game: 1,
        params: spin_params,
        equipment: pool_equipment,
        pool_table: true,
        ball_word: pool_word,
        list_names: pool_list,
        start: |s, t, b| Ok(pool(Game::NineBall, s, t, b)),
    },
    GameEntry {
        id: "eight-ball",
        label: "8-ball",
        length_unit: "race to",
        unit: Unit::Racks,
        default_length: 3,
        one_game: 1,
        params: spin_params,
        equipment: pool_equipment,
        pool_table: true,
        ball_word: pool_word,
        list_names: pool_list,
        start: |s, t, b| Ok(pool(Game::EightBall, s, t, b)),
    },
    GameEntry {
        id: "ten-ball",
        label: "10-ball",
        length_unit: "race to",
        unit: Unit::Racks,
        default_length: 3,
        one_game: 1,
        params: spin_params,
        equipment: pool_equipment,
        pool_table: true,
        ball_word: pool_word,
        list_names: pool_list,
        start: |s, t, b| Ok(pool(Game::TenBall, s, t, b)),
    },
    GameEntry {
        id: "snooker",
        label: "snooker",
        length_unit: "best of",
        unit: Unit::Frames,
        default_length: 3,
        one_game: 1,
        params: Params::snooker,
        equipment: snooker_equipment,
        pool_table: false,
        ball_word: crate::snooker::balls::word,
        list_names: crate::snooker::balls::list_names,
        start: |s, t, b| {
            Ok(Box::new(SnookerGame::new(
                s.players.clone(),
                s.length,
                t,
                b,
            )?))
        },
    },
    GameEntry {
        id: "three-cushion",
        label: "three-cushion",
        length_unit: "points to",
        unit: Unit::Points,
        // UMB world cup and championship distance (Art. 29 leaves it to the event).
        default_length: 40,
        one_game: 40,
        params: spin_params,
        equipment: carom_equipment,
        pool_table: false,
        ball_word: crate::three_cushion::balls::word,
        list_names: crate::three_cushion::balls::list_names,
        start: |s, t, b| {
            Ok(Box::new(ThreeCushionMatch::new(
                s.players.clone(),
                s.length,
                t,
                b,
            )?))
        },
    },
    GameEntry {
        id: "free-play",
        label: "free play",
        length_unit: "race to",
        unit: Unit::Racks,
        default_length: 1,
        one_game: 1,
        params: spin_params,
        equipment: pool_equipment,
        pool_table: true,
        ball_word: pool_word,
        list_names: pool_list,
        start: |s, t, b| Ok(pool(Game::FreePlay, s, t, b)),
    },
];

/// The game of command-line id `id` (`nine-ball`; `9-ball` and `9ball` too).
pub fn find(id: &str) -> Result<&'static GameEntry, RulesError> {
    let wanted = id.trim().to_ascii_lowercase();
    GAMES
        .iter()
        .find(|g| {
            g.id == wanted
                || g.label.replace(' ', "-") == wanted
                || g.label.replace('-', "") == wanted
        })
        .ok_or_else(|| {
            let ids: Vec<&str> = GAMES.iter().map(|g| g.id).collect();
            RulesError(format!("unknown game {id:?}: one of {}", ids.join(", ")))
        })
}

/// A game saved by [`GameRules::save`], by its kind.
#[derive(serde::Deserialize)]
#[serde(tag = "kind", content = "state", rename_all = "snake_case")]
enum Saved {
    Pool(Box<PoolMatch>),
    Snooker(Box<SnookerGame>),
    ThreeCushion(Box<ThreeCushionMatch>),
    Drill(Box<crate::drill_game::DrillGame>),
}

/// The game [`GameRules::save`] saved, back behind the interface; a clear error for JSON
/// that is not a saved game.
pub fn restore(saved: &serde_json::Value) -> Result<Box<dyn GameRules>, RulesError> {
    let game: Saved = serde_json::from_value(saved.clone())
        .map_err(|e| RulesError(format!("not a saved game: {e}")))?;
    Ok(match game {
        Saved::Pool(g) => g,
        Saved::Snooker(g) => g,
        Saved::ThreeCushion(g) => g,
        Saved::Drill(g) => g,
    })
}
