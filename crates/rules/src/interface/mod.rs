//! One interface for every game (issue 50): [`GameRules`], which pool's games
//! ([`crate::pool`]), snooker ([`crate::snooker::rules`]) and every game added
//! later implement, and the words it speaks. The game, the command line and the computer
//! hold a `Box<dyn GameRules>` and never ask which game it is.
//!
//! The flow of one stroke, for any game:
//!
//! 1. read [`GameRules::turn`]: who strikes, with which cue ball, from where
//!    ([`CueBallPlace`]), what may be hit first, what may or must be declared
//!    ([`Declarations`]) and the options to choose between first ([`Turn::choices`]);
//! 2. while options are offered, the striker takes one by index with
//!    [`GameRules::choose`] and sets the table as the returned [`Setup`] says;
//! 3. place the cue ball if it is in hand, strike, run the solver to rest;
//! 4. [`GameRules::judge`] the [`StrokeRecord`] (the solver's events of the stroke, the
//!    layouts before and after, the declaration): the [`Judgement`] says whether the
//!    stroke was fair, in words, which balls the rules put back on the table and where,
//!    and whether the game (a rack, a frame, a carom game) and the match are over;
//! 5. when the game is over and the match is not, [`GameRules::next_game`] gives the next
//!    game's layout.
//!
//! The words are plain data (numbers of balls, positions, sentences), so a caller that
//! knows no game (the HUD, a log, the computer's search) can use them.
//!
//! Arrows: this module imports only the shared words ([`crate::turn`], [`crate::shot`]) and
//! the solver's types; each game's adapter imports this module, and the list of games
//! ([`crate::catalog`]) imports the adapters, never the other way.

use crate::shot::{ShotSummary, summarise};
use crate::turn::Seat;
use billiards_physics::{BallSetup, BallSpec, Event, EventKind, Pocket, Table, Vec2};
use serde::{Deserialize, Serialize};

/// What the striker may declare before a stroke: a ball and a pocket (pool's call shot),
/// a safety, a push out (9-ball, 10-ball), a nominated ball (snooker's colour or free
/// ball), or nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Declaration {
    /// Nothing declared.
    #[default]
    None,
    /// This ball in this pocket (WPA 1.6).
    Pocket {
        /// The ball called.
        ball: u8,
        /// The pocket called.
        pocket: Pocket,
    },
    /// A called safety (WPA 1.6, 8-ball).
    Safety,
    /// A push out (WPA 2.4).
    PushOut,
    /// A nominated ball (WPBSA 2.12 a colour after a red, 3.12 a free ball).
    Nominate {
        /// The ball nominated.
        ball: u8,
    },
}

impl Declaration {
    /// The declaration in words ("the 5 in the left side pocket", "push out"), `None` when
    /// nothing was declared. `name` names a ball in the game's words.
    pub fn text(self, name: &dyn Fn(u8) -> String) -> Option<String> {
        match self {
            Declaration::None => None,
            Declaration::Pocket { ball, pocket } => Some(format!(
                "{} in the {}",
                name(ball),
                crate::foul::pocket_name(pocket)
            )),
            Declaration::Safety => Some("safety".to_owned()),
            Declaration::PushOut => Some("push out".to_owned()),
            Declaration::Nominate { ball } => Some(format!("{} nominated", name(ball))),
        }
    }
}

/// Whether a kind of declaration is used on the next stroke.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Need {
    /// Not used: declaring it is refused.
    #[default]
    NotUsed,
    /// Accepted; an obvious stroke needs none (WPA 1.6, WPBSA 2.12).
    Optional,
    /// Required: a stroke without it is judged as the game's rules say (8-ball's 8, 10-ball
    /// every shot).
    Required,
}

/// What the striker may declare before the next stroke.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Declarations {
    /// A ball and a pocket ([`Declaration::Pocket`]).
    pub pocket: Need,
    /// The balls that may be called with a pocket: the 8 when it is on (WPA 3.8), the
    /// striker's group or any legal ball (1.6), any ball on the table in 10-ball (9.5, a
    /// combination too); empty when no pocket is called.
    pub callable: Vec<u8>,
    /// A safety may be called ([`Declaration::Safety`]).
    pub safety: bool,
    /// A push out may be declared ([`Declaration::PushOut`]).
    pub push_out: bool,
    /// The balls that may be nominated ([`Declaration::Nominate`]); empty: none.
    pub nominate: Vec<u8>,
}

/// Where the cue ball may be put by hand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HandRegion {
    /// Anywhere on the table (WPA 1.5).
    Anywhere,
    /// Behind the head string (pool's break, WPA 2.3, 3.3).
    BehindHeadString,
    /// In the D (WPBSA 3.4).
    D,
}

impl HandRegion {
    /// Where, in words: "anywhere on the table", "behind the head string", "in the D".
    pub fn words(self) -> &'static str {
        match self {
            HandRegion::Anywhere => "anywhere on the table",
            HandRegion::BehindHeadString => "behind the head string",
            HandRegion::D => "in the D",
        }
    }
}

/// Where the striker's cue ball is before the next stroke.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum CueBallPlace {
    /// Where it came to rest.
    AsItLies,
    /// In hand: the striker places it in this region (the caller checks the place with
    /// [`GameRules::check_hand`]).
    InHand {
        /// The region.
        region: HandRegion,
    },
    /// Put back by the rules before the stroke (free play's respot): the caller places it
    /// where [`Judgement::put`] said.
    Placed,
}

/// The next stroke as any game describes it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Turn {
    /// Who strikes (or, with [`Turn::choices`], who chooses first).
    pub striker: Seat,
    /// The number of the striker's cue ball (0, or carom's yellow for the second player).
    pub cue_ball: u8,
    /// Where the cue ball is.
    pub place: CueBallPlace,
    /// The balls the cue ball may hit first; every object ball when any may be.
    pub legal_first: Vec<u8>,
    /// What is on, in words ("the 3", "a red", "the red first").
    pub ball_on: String,
    /// What may or must be declared.
    pub declare: Declarations,
    /// The stroke opens a game (a break, a break-off, carom's opening stroke).
    pub opening: bool,
    /// Options the striker must choose one of before striking (by index, with
    /// [`GameRules::choose`]), in the player's words; empty: strike.
    pub choices: Vec<String>,
}

/// How the table must be set before the next stroke, after a choice or a new game.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Setup {
    /// Nothing changes.
    #[default]
    Keep,
    /// Put these balls here (spotted balls), the others left as they lie.
    Put {
        /// Each ball and where.
        balls: Vec<(u8, Vec2)>,
    },
    /// Every ball exactly as listed, the others off the table (WPBSA 3.14's replace).
    Layout {
        /// Each ball and where.
        balls: Vec<(u8, Vec2)>,
    },
    /// A new rack: a fresh start of the table.
    Rack {
        /// The balls of the rack.
        balls: Vec<BallSetup>,
    },
}

/// One stroke as played, for [`GameRules::judge`].
#[derive(Clone, Copy, Debug)]
pub struct StrokeRecord<'a> {
    /// The solver's events of the stroke, from its strike event to rest (a history's
    /// slice: a lean solver's steps hold no strike event and are refused,
    /// [`StrokeRecord::check_strike`]).
    pub events: &'a [Event],
    /// The number painted on each ball, by the solver's ball id.
    pub numbers: &'a [u8],
    /// Every ball on the table at the strike (the cue ball included).
    pub before: &'a [(u8, Vec2)],
    /// Every ball on the table at rest (pocketed balls absent).
    pub after: &'a [(u8, Vec2)],
    /// What the striker declared.
    pub declared: Declaration,
}

impl StrokeRecord<'_> {
    /// Refuses events without a strike: judged, they would read as a stroke that did
    /// nothing (a silent "no ball hit").
    pub fn check_strike(&self) -> Result<(), RulesError> {
        if self
            .events
            .iter()
            .any(|e| matches!(e.kind, EventKind::Strike { .. }))
        {
            Ok(())
        } else {
            Err(RulesError(
                "the stroke's events hold no strike: record them from the strike on".to_owned(),
            ))
        }
    }

    /// The stroke's facts in the rules' terms ([`ShotSummary`], read after the strike).
    pub fn summary(&self) -> Result<ShotSummary, RulesError> {
        self.check_strike()?;
        Ok(summarise(self.events, self.numbers))
    }
}

/// How a game (a rack, a frame, a carom game) ended.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct GameEnd {
    /// The winner.
    pub winner: Seat,
    /// Why, in words ("the 9 was pocketed on a legal shot").
    pub reason: String,
    /// The match is over too.
    pub match_over: bool,
}

/// The judgement of one stroke, in any game's words.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Judgement {
    /// Who struck.
    pub striker: Seat,
    /// No foul.
    pub fair: bool,
    /// The fouls, each in words; empty on a fair stroke.
    pub fouls: Vec<String>,
    /// The verdict in words: fair or the fouls, and what the stroke did ("legal: the 7 in
    /// the right side pocket", "foul: the cue ball went in-off: 4 points to Ann").
    pub text: String,
    /// Balls the rules put back on the table before the next stroke, and where (spotted
    /// balls, a respotted cue ball), in the order to place them.
    pub put: Vec<(u8, Vec2)>,
    /// The striker stays at the table.
    pub continues: bool,
    /// The game's end, if this stroke ended it.
    pub end: Option<GameEnd>,
}

impl Judgement {
    /// The verdict with the striker named once: "Ann: no point ..."; a text that opens with
    /// the striker's name already ("Ann pots a red", snooker's) is given as it is (a name
    /// elsewhere in it may be the opponent's: "4 points to Ann"). `name`: the striker's.
    pub fn text_by(&self, name: &str) -> String {
        if self.text.starts_with(name) {
            self.text.clone()
        } else {
            format!("{name}: {}", self.text)
        }
    }
}

/// Why a call on a game was refused (nothing changed).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct RulesError(pub String);

impl RulesError {
    /// An error from any displayable reason.
    pub fn from_display(e: impl std::fmt::Display) -> Self {
        Self(e.to_string())
    }
}

/// One game's rules: the equipment, the rack, whose turn and what they may do, the
/// judgement of a stroke, the score and the end. Implemented by every game; used alone by
/// the game, the command line and the computer.
pub trait GameRules: std::fmt::Debug + Send + Sync {
    /// The game's name for a player ("9-ball", "snooker").
    fn name(&self) -> &'static str;
    /// The players' names, by [`Seat::index`].
    fn players(&self) -> &[String; 2];
    /// The table the game is played on.
    fn table(&self) -> Table;
    /// The balls' size and mass.
    fn ball(&self) -> BallSpec;
    /// The layout of the game in play at its start (the rack, the opening position).
    fn layout(&self) -> Result<Vec<BallSetup>, RulesError>;
    /// The next stroke.
    fn turn(&self) -> Turn;
    /// The name of a ball in the game's words ("the 7", "the pink", "the yellow").
    fn ball_name(&self, ball: u8) -> String;
    /// Takes option `index` of [`Turn::choices`], with the balls on the table at `layout`
    /// (a spotted ball must miss them); returns how the table must be set.
    fn choose(&mut self, index: usize, layout: &[(u8, Vec2)]) -> Result<Setup, RulesError>;
    /// Whether the cue ball may be put at `at` by hand now, with the other balls at
    /// `others` (number and centre): `Err` says why not.
    fn check_hand(&self, at: Vec2, others: &[(u8, Vec2)]) -> Result<(), RulesError>;
    /// Judges one stroke played under [`GameRules::turn`] and moves the game on.
    fn judge(&mut self, stroke: &StrokeRecord<'_>) -> Result<Judgement, RulesError>;
    /// The match's score in one line ("9-ball, race to 3: Ann 1 - 0 Bob").
    fn score_line(&self) -> String;
    /// The game's points (a frame's score, carom's points; pool's racks won).
    fn points(&self) -> [u32; 2];
    /// The state in a few lines for the HUD: the ball on, groups, balls left, fouls in a
    /// row, the break, innings.
    fn status(&self) -> Vec<String>;
    /// The status lines while a stroke is in play, with the balls `off` (those it has
    /// pocketed or driven off so far) already counted off "balls left" and the like, which
    /// [`GameRules::status`] changes only with the judgement. Games that count no balls
    /// give [`GameRules::status`].
    fn status_while(&self, off: &[u8]) -> Vec<String> {
        let _ = off;
        self.status()
    }
    /// The game's end, once it is over.
    fn end(&self) -> Option<GameEnd>;
    /// The match's winner, once it is over.
    fn match_winner(&self) -> Option<Seat>;
    /// Starts the next game of the match (after [`GameRules::end`]); returns its layout.
    fn next_game(&mut self) -> Result<Vec<BallSetup>, RulesError>;
    /// The striker concedes the game (WPBSA 2.1(a)); refused where the game has no such
    /// rule.
    fn concede(&mut self) -> Result<GameEnd, RulesError> {
        Err(RulesError(format!("{} has no concession", self.name())))
    }
    /// Whether the striker may concede now ([`GameRules::concede`] would be taken).
    fn concedes(&self) -> bool {
        false
    }
    /// Free play's sandbox: the table may be set by hand between strokes (balls placed or
    /// taken off, a new rack, a stroke taken back), so each stroke is judged on the table
    /// its strike finds ([`StrokeRecord::before`]), and a judgement needs no reading before
    /// the next stroke. Every game with rules of its own keeps its table: `false`.
    fn sandbox(&self) -> bool {
        false
    }
    /// The sandbox's table set by hand (balls placed, taken off, a new rack): its game takes
    /// stock of the balls now on it (`layout`: number and centre), as its next judgement
    /// would, so that what it says between strokes ("balls left") is the table's. Refused by
    /// every game whose table is its own.
    fn set_by_hand(&mut self, layout: &[(u8, Vec2)]) -> Result<(), RulesError> {
        let _ = layout;
        Err(not_by_hand(self.name()))
    }
    /// A one-player game (a drill session): the second seat is no player but the game
    /// itself, a judgement needs no reading (the game's own window and the HUD say it), and a
    /// game's end is the end of one try, whose reason says all ([`GameEnd::reason`]). Every
    /// game between two players: `false`.
    fn solo(&self) -> bool {
        false
    }
    /// A copy behind a new box (the computer searches on copies).
    fn boxed_clone(&self) -> Box<dyn GameRules>;
    /// The whole state as JSON tagged with its kind ([`saved`]), for a rules log that
    /// re-judges a recording from where its first stroke found the game
    /// ([`crate::catalog::restore`] reads it back).
    fn save(&self) -> Result<serde_json::Value, RulesError>;
    /// The game as [`std::any::Any`]: a caller with a game's own tools (the computer's
    /// dedicated pool and snooker searches) finds its type; every other caller needs none.
    fn as_any(&self) -> &dyn std::any::Any;
}

/// A place the rules of `game` accept for its cue ball in hand, with the other balls at
/// `others` (number and centre): `first` if given and accepted (a script's rule, the head
/// spot), else the first of a 40 x 20 sweep of the table nearest the middle of its head
/// half. `None` when nothing is accepted. Where a player has no hand to place it with (a
/// script, a ball the rules put back), this is the hand.
pub fn hand_place(
    game: &dyn GameRules,
    others: &[(u8, Vec2)],
    first: Option<Vec2>,
) -> Option<Vec2> {
    let table = game.table();
    let from = Vec2::new(-table.length / 4.0, 0.0);
    let mut places: Vec<Vec2> = (0..40 * 20)
        .map(|k| {
            Vec2::new(
                (f64::from(k % 40) + 0.5) / 40.0 * table.length - table.length / 2.0,
                (f64::from(k / 40) + 0.5) / 20.0 * table.width - table.width / 2.0,
            )
        })
        .collect();
    places.sort_by(|a, b| (*a - from).length().total_cmp(&(*b - from).length()));
    first
        .into_iter()
        .chain(places)
        .find(|&at| game.check_hand(at, others).is_ok())
}

/// A [`Setup::Layout`] as placements that never overlap (snooker's replace, WPBSA 3.14;
/// carom's respot of frozen balls): from the balls on the table `now` to `layout`, the
/// moves `(number, centre)` to make one after another (`Simulation::place`). A ball whose
/// place is clear goes first; when every place left is taken by a ball still to move, that
/// ball is first parked on a free point along the bottom cushion. `None` when no point
/// there is free (never on a real table). `radius` is the balls' radius, `table` the table
/// (for its cushions).
pub fn layout_moves(
    now: &[(u8, Vec2)],
    layout: &[(u8, Vec2)],
    radius: f64,
    table: &Table,
) -> Option<Vec<(u8, Vec2)>> {
    const CLEAR: f64 = 1e-9;
    let mut at: Vec<(u8, Vec2)> = now.to_vec();
    let mut todo: Vec<(u8, Vec2)> = layout.to_vec();
    let mut moves = Vec::new();
    let bound = table.centre_bounds(radius);
    let clear = |at: &[(u8, Vec2)], n: u8, p: Vec2| {
        at.iter()
            .all(|&(m, q)| m == n || (p - q).length() >= 2.0 * radius + CLEAR)
    };
    let set = |at: &mut Vec<(u8, Vec2)>, moves: &mut Vec<(u8, Vec2)>, n: u8, p: Vec2| {
        at.retain(|b| b.0 != n);
        at.push((n, p));
        moves.push((n, p));
    };
    // Each pass places a ball or parks one; a parked ball is placed in a later pass.
    for _ in 0..4 * (layout.len() + 1) {
        if todo.is_empty() {
            return Some(moves);
        }
        if let Some(i) = todo.iter().position(|&(n, p)| clear(&at, n, p)) {
            let (n, p) = todo.remove(i);
            set(&mut at, &mut moves, n, p);
            continue;
        }
        let (n, p) = todo[0];
        let &(blocker, _) = at
            .iter()
            .find(|&&(m, q)| m != n && (p - q).length() < 2.0 * radius + CLEAR)?;
        // Along the bottom cushion, 20 cm clear of the corner pockets.
        let (from, pitch) = (-bound.y + 0.2, 2.0 * radius + 1e-3);
        let steps = ((2.0 * bound.y - 0.4) / pitch) as usize;
        let park = (0..=steps)
            .map(|j| Vec2::new(-bound.x + 1e-4, from + j as f64 * pitch))
            .find(|&q| {
                clear(&at, blocker, q)
                    && todo
                        .iter()
                        .all(|&(_, t)| (t - q).length() >= 2.0 * radius + CLEAR)
            })?;
        set(&mut at, &mut moves, blocker, park);
    }
    None
}

/// Why game `name`'s table may not be set by hand ([`GameRules::set_by_hand`]).
pub fn not_by_hand(name: &str) -> RulesError {
    RulesError(format!("{name}: the table is the rules', not set by hand"))
}

/// `state` as `{"kind": kind, "state": ...}`, the form [`crate::catalog::restore`] reads.
pub fn saved<T: Serialize>(kind: &str, state: &T) -> Result<serde_json::Value, RulesError> {
    let state = serde_json::to_value(state).map_err(RulesError::from_display)?;
    Ok(serde_json::json!({ "kind": kind, "state": state }))
}

impl Clone for Box<dyn GameRules> {
    fn clone(&self) -> Self {
        self.boxed_clone()
    }
}
