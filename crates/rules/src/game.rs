//! One rack of a game: its state, the shot's verdict and what the next shot must respect.
//!
//! The rulesets are one closed enum, [`Game`], rather than a trait: there are three games,
//! each `match` over them is checked for exhaustiveness, and the whole state (a plain value)
//! can be saved with a recording and compared when it is verified, which trait objects make
//! awkward. The per-game logic lives in [`crate::nine_ball`] and [`crate::eight_ball`].
//!
//! Flow for a caller (the game, the command line): read [`GameState::next`]; if it offers
//! [`NextShot::choices`], the [`NextShot::shooter`] picks one with [`GameState::choose`];
//! prepare the table as it says (re-rack, spot balls, cue ball in hand); strike; run the
//! solver to rest; summarise the events ([`crate::summarise`]); [`GameState::play`] returns
//! the [`Verdict`] and moves the state on.
//!
//! Rules followed: the WPA World Standardized Rules, "Rules of Play", in the numbering of the
//! edition effective 1 January 2008 (section 2 nine ball, 3 eight ball, 6 fouls, 8
//! definitions); see the crate README for the rules covered and left out.

use crate::foul::{BallOn, Foul, Group, WinReason};
use crate::shot::ShotSummary;
use billiards_physics::{BallSetup, BallSpec, Pocket, Table};
use serde::{Deserialize, Serialize};

/// The game played.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Game {
    /// 8-ball, WPA section 3.
    EightBall,
    /// 9-ball, WPA section 2.
    NineBall,
    /// The sandbox: no fouls, no turns, a scratch respots the cue ball.
    FreePlay,
}

impl Game {
    /// The object balls of a full rack.
    pub fn object_balls(self) -> Vec<u8> {
        match self {
            Game::NineBall => (1..=9).collect(),
            Game::EightBall | Game::FreePlay => (1..=15).collect(),
        }
    }

    /// The rack of this game from `seed` ([`crate::racks`]); free play racks the 15 balls
    /// as 8-ball does. The cue ball comes first, on the head spot.
    pub fn rack(self, table: &Table, ball: &BallSpec, seed: u64) -> Vec<BallSetup> {
        self.rack_styled(table, ball, seed, crate::racks::RackStyle::Triangle)
    }

    /// [`Game::rack`] racked in `style`: a template (frozen) or a triangle (seeded gaps).
    pub fn rack_styled(
        self,
        table: &Table,
        ball: &BallSpec,
        seed: u64,
        style: crate::racks::RackStyle,
    ) -> Vec<BallSetup> {
        let gap = style.gap();
        match self {
            Game::NineBall => crate::racks::nine_ball_spaced(table, ball, seed, gap),
            Game::EightBall | Game::FreePlay => {
                crate::racks::eight_ball_spaced(table, ball, seed, gap)
            }
        }
    }
}

/// One of the two players.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Seat {
    /// The first player.
    A,
    /// The second player.
    B,
}

impl Seat {
    /// The opponent.
    pub fn other(self) -> Seat {
        match self {
            Seat::A => Seat::B,
            Seat::B => Seat::A,
        }
    }

    /// 0 for A, 1 for B.
    pub fn index(self) -> usize {
        match self {
            Seat::A => 0,
            Seat::B => 1,
        }
    }
}

/// What the shooter declared before the shot.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Call {
    /// No call: a break, a 9-ball shot, or an obvious 8-ball shot (WPA 1.6).
    #[default]
    None,
    /// 9-ball: a push out, only on the shot right after a legal break (WPA 2.4).
    PushOut,
    /// 8-ball: a called safety; the turn ends whatever drops (WPA 1.6).
    Safety,
    /// 8-ball: this ball in this pocket (WPA 1.6, 3.6). The 8 must always be called.
    Ball {
        /// The ball called.
        ball: u8,
        /// The pocket called.
        pocket: Pocket,
    },
}

/// Where the incoming shooter's cue ball is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CueBall {
    /// Where it came to rest.
    AsItLies,
    /// In hand, anywhere on the table (WPA 1.5, after a foul).
    InHandAnywhere,
    /// In hand behind the head string (the break, WPA 2.3 / 3.3; after a scratch on the
    /// 8-ball break, 3.3).
    InHandBehindHeadString,
    /// Free play: back on the head string by the respot rule ([`crate::respot`]).
    Respot,
}

/// Whether the next shot needs a call.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CallRule {
    /// No call is used (the break, 9-ball, free play).
    NotUsed,
    /// A call is accepted; an obvious shot needs none (WPA 1.6).
    Optional,
    /// The 8 is on: a pocket must be called for it, or pocketing it loses (WPA 3.8).
    EightPocket,
}

/// An option offered to a player before the next shot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Choice {
    /// Shoot the table as it lies (after an illegal 8-ball break, WPA 3.3; after a push
    /// out, WPA 2.4).
    ShootFromHere,
    /// After a push out: the player who pushed must shoot again (WPA 2.4).
    PassBack,
    /// Re-rack and break, the chooser breaking (WPA 3.3).
    RerackAndBreak,
    /// Re-rack and let the player who broke illegally break again (WPA 3.3).
    RerackOpponentBreaks,
    /// The 8 went in on the break: spot it and shoot (WPA 3.3).
    SpotEightAndShoot,
}

impl Choice {
    /// The player's words for the option ("re-rack and break").
    pub fn label(self) -> &'static str {
        match self {
            Choice::ShootFromHere => "shoot from here",
            Choice::PassBack => "pass it back",
            Choice::RerackAndBreak => "re-rack and break",
            Choice::RerackOpponentBreaks => "re-rack, the opponent breaks again",
            Choice::SpotEightAndShoot => "spot the 8 and shoot",
        }
    }
}

impl Call {
    /// The call in words ("the 5 in the left side pocket"), `None` when nothing was called.
    pub fn text(self) -> Option<String> {
        match self {
            Call::None => None,
            Call::PushOut => Some("push out".to_owned()),
            Call::Safety => Some("safety".to_owned()),
            Call::Ball { ball, pocket } => Some(format!(
                "the {ball} in the {}",
                crate::foul::pocket_name(pocket)
            )),
        }
    }
}

/// What the next shot must respect.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct NextShot {
    /// Who shoots next (or, with [`NextShot::choices`], who must choose first).
    pub shooter: Seat,
    /// Where the cue ball is.
    pub cue_ball: CueBall,
    /// The balls the cue ball may hit first (WPA 6.2); every ball on the table in free play.
    pub legal_first: Vec<u8>,
    /// Whether a call is needed.
    pub call: CallRule,
    /// The next shot is a break (cue ball behind the head string).
    pub break_shot: bool,
    /// A push out may be declared ([`Call::PushOut`], WPA 2.4).
    pub push_out_allowed: bool,
    /// Options the shooter must choose between before shooting ([`GameState::choose`]).
    pub choices: Vec<Choice>,
    /// Balls to spot on the long string before the shot (WPA 1.4, 2.6).
    pub spot: Vec<u8>,
    /// A new rack must be put up before the shot.
    pub rerack: bool,
    /// The shooter's fouls in a row (9-ball; two is the warning of WPA 6.14).
    pub fouls_in_a_row: u8,
}

impl NextShot {
    /// An ordinary shot: no break, no push out, no choice, nothing to spot, no re-rack.
    pub(crate) fn plain(
        shooter: Seat,
        cue_ball: CueBall,
        legal_first: Vec<u8>,
        call: CallRule,
        fouls_in_a_row: u8,
    ) -> Self {
        Self {
            shooter,
            cue_ball,
            legal_first,
            call,
            break_shot: false,
            push_out_allowed: false,
            choices: Vec::new(),
            spot: Vec::new(),
            rerack: false,
            fouls_in_a_row,
        }
    }
}

/// What happened to the turn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Outcome {
    /// The shooter stays at the table.
    Continues,
    /// The turn passes to the opponent.
    Passes,
    /// The game is over.
    GameOver {
        /// The winner.
        winner: Seat,
        /// Why.
        reason: WinReason,
    },
}

/// The verdict on one shot.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Verdict {
    /// Who shot.
    pub shooter: Seat,
    /// The shot was a break.
    pub break_shot: bool,
    /// The shot was a push out.
    pub push_out: bool,
    /// The fouls committed, most visible first; empty for a legal shot.
    pub fouls: Vec<Foul>,
    /// The turn, or the end of the game.
    pub outcome: Outcome,
    /// The group this shot assigned to the shooter (8-ball, WPA 3.5).
    pub assigned: Option<Group>,
    /// What the next shot must respect (`None` once the game is over).
    pub next: Option<NextShot>,
}

impl Verdict {
    /// The shot was legal.
    pub fn legal(&self) -> bool {
        self.fouls.is_empty()
    }

    /// "legal" or "foul: the 3 was hit first, the 2 was the lowest ball; ...".
    pub fn reason(&self) -> String {
        if self.fouls.is_empty() {
            return if self.push_out {
                "legal push out"
            } else {
                "legal"
            }
            .to_string();
        }
        let list: Vec<String> = self.fouls.iter().map(|f| f.to_string()).collect();
        format!("foul: {}", list.join("; "))
    }
}

/// What a pool shot did, in words, for its verdict (issue 48: a made call and a missed
/// call must not both read "legal"): the balls pocketed and where, in the order they
/// dropped ("the 7 in the right side pocket, the 3 in the foot-left corner"), or "nothing
/// pocketed"; and with a ball called (WPA 1.6), whether it went where called: "the 7 missed
/// the called right side pocket", "the 7 went in the foot-left corner, not the called right
/// side pocket".
pub fn what_happened(summary: &ShotSummary, call: Call) -> String {
    let name = |b: u8| {
        if b == crate::shot::CUE {
            "the cue ball".to_owned()
        } else {
            format!("the {b}")
        }
    };
    let mut parts: Vec<String> = Vec::new();
    if let Call::Ball { ball, pocket } = call {
        match summary.pocket_of(ball) {
            Some(p) if p == pocket => {}
            Some(p) => parts.push(format!(
                "the {ball} went in the {}, not the called {}",
                crate::foul::pocket_name(p),
                crate::foul::pocket_name(pocket)
            )),
            None => parts.push(format!(
                "the {ball} missed the called {}",
                crate::foul::pocket_name(pocket)
            )),
        }
    }
    let dropped: Vec<String> = summary
        .pocketed
        .iter()
        .map(|&(b, p)| format!("{} in the {}", name(b), crate::foul::pocket_name(p)))
        .collect();
    if dropped.is_empty() {
        if summary.first_contact.is_none() {
            parts.push("no ball hit".to_owned());
        }
        parts.push("nothing pocketed".to_owned());
    } else {
        parts.push(dropped.join(", "));
    }
    parts.join("; ")
}

/// A verdict's reason followed by what the shot did ([`what_happened`]), without saying
/// twice what the reason says: "foul: the cue ball hit no ball" needs no "no ball hit", and
/// "no ball pocketed and 0 balls to a rail" no "nothing pocketed" (issue 48, played: "foul:
/// the cue ball hit no ball: no ball hit; nothing pocketed").
pub fn verdict_words(reason: &str, what: &str) -> String {
    let no_hit = reason.contains("hit no ball") || reason.contains("no ball hit");
    // A cue ball that hit nothing pocketed nothing (a scratch would be named, not this).
    let no_hit_anywhere = no_hit || what.split("; ").any(|p| p == "no ball hit");
    let said = |part: &str| match part {
        "no ball hit" => no_hit,
        "nothing pocketed" => reason.contains("no ball pocketed") || no_hit_anywhere,
        _ => false,
    };
    let rest: Vec<&str> = what.split("; ").filter(|p| !said(p)).collect();
    if rest.is_empty() {
        reason.to_owned()
    } else {
        format!("{reason}: {}", rest.join("; "))
    }
}

/// Why a shot or a choice was refused (nothing changes).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RuleError {
    /// The game is over.
    #[error("the game is over")]
    GameOver,
    /// A choice must be made before the next shot.
    #[error("a choice must be made first: one of {0:?}")]
    ChoicePending(Vec<Choice>),
    /// The choice is not among those offered.
    #[error("{choice:?} is not offered (offered: {offered:?})")]
    ChoiceNotOffered {
        /// The choice made.
        choice: Choice,
        /// The choices offered.
        offered: Vec<Choice>,
    },
    /// The call names a ball that is not on the table.
    #[error("the {0} is not on the table")]
    BallNotOnTable(u8),
    /// The call is not one this shot allows.
    #[error("cannot call the {ball}: {why}")]
    IllegalCall {
        /// The ball called.
        ball: u8,
        /// Why not.
        why: &'static str,
    },
    /// A push out outside its window.
    #[error("a push out is allowed only on the shot right after a legal break (WPA 2.4)")]
    PushOutNotAllowed,
    /// A call this game does not use.
    #[error("{0:?} has no {1}")]
    CallNotUsed(Game, &'static str),
    /// The summary pockets a ball that is not on the table.
    #[error("the shot pocketed the {0}, which was not on the table")]
    UnknownBall(u8),
}

/// Choices pending, with what they depend on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub(crate) enum Pending {
    /// 8-ball illegal break: the incoming player decides (WPA 3.3).
    IllegalBreak {
        /// The player who broke.
        breaker: Seat,
        /// The cue ball was pocketed on that break.
        scratched: bool,
    },
    /// 8-ball: the 8 went in on the break (WPA 3.3).
    EightOnBreak {
        /// The player who broke.
        breaker: Seat,
        /// The break was a foul (the incoming player chooses).
        foul: bool,
    },
    /// 9-ball: after a push out (WPA 2.4).
    PushOut {
        /// The player who pushed.
        pusher: Seat,
    },
}

/// The state of one rack.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct GameState {
    /// The game.
    pub game: Game,
    /// The player who broke this rack (or breaks it next).
    pub breaker: Seat,
    /// 8-ball: the group of player A (`None`: the table is open; B has the other).
    pub group_a: Option<Group>,
    /// Fouls in a row of each player, by [`Seat::index`] (counted in every game; only
    /// 9-ball loses on the third, WPA 2.8 — 8-ball has no such rule, WPA 6.14).
    pub fouls: [u8; 2],
    /// Object balls on the table (after spotting), ascending.
    pub on_table: Vec<u8>,
    /// What the next shot must respect.
    pub next: NextShot,
    /// The winner and why, once the game is over.
    pub over: Option<(Seat, WinReason)>,
    pub(crate) pending: Option<Pending>,
}

impl GameState {
    /// A new rack of `game` broken by `breaker`.
    pub fn new(game: Game, breaker: Seat) -> Self {
        let on_table = game.object_balls();
        let cue_ball = match game {
            Game::FreePlay => CueBall::AsItLies,
            _ => CueBall::InHandBehindHeadString,
        };
        let legal_first = match game {
            // WPA 2.3 with 6.2: the 1 (the lowest) first.
            Game::NineBall => vec![1],
            _ => on_table.clone(),
        };
        let next = NextShot {
            break_shot: game != Game::FreePlay,
            ..NextShot::plain(breaker, cue_ball, legal_first, CallRule::NotUsed, 0)
        };
        Self {
            game,
            breaker,
            group_a: None,
            fouls: [0; 2],
            on_table,
            next,
            over: None,
            pending: None,
        }
    }

    /// A rack in progress (a drill, a shared position): `on_table` the object balls left,
    /// `shooter` at the table with the cue ball as it lies, no fouls, an open table in
    /// 8-ball, the lowest ball on in 9-ball (WPA 6.2).
    pub fn in_progress(game: Game, shooter: Seat, mut on_table: Vec<u8>) -> Self {
        on_table.sort_unstable();
        on_table.dedup();
        let mut state = Self::new(game, shooter);
        state.on_table = on_table;
        state.next = match game {
            Game::NineBall => crate::nine_ball::normal_next(&state, shooter, CueBall::AsItLies),
            Game::EightBall => crate::eight_ball::normal_next(&state, shooter, CueBall::AsItLies),
            Game::FreePlay => NextShot::plain(
                shooter,
                CueBall::AsItLies,
                state.on_table.clone(),
                CallRule::NotUsed,
                0,
            ),
        };
        state
    }

    /// The group of `seat` (8-ball; `None` while the table is open).
    pub fn group(&self, seat: Seat) -> Option<Group> {
        match seat {
            Seat::A => self.group_a,
            Seat::B => self.group_a.map(Group::other),
        }
    }

    /// Judges one shot played under [`GameState::next`] and moves the state on. Refused
    /// (state unchanged) while a choice is pending, once the game is over, or for a call the
    /// shot does not allow.
    pub fn play(&mut self, shot: &ShotSummary, call: Call) -> Result<Verdict, RuleError> {
        if self.over.is_some() {
            return Err(RuleError::GameOver);
        }
        if !self.next.choices.is_empty() {
            return Err(RuleError::ChoicePending(self.next.choices.clone()));
        }
        if let Some(b) = shot
            .pocketed_object_balls()
            .find(|b| !self.on_table.contains(b))
        {
            return Err(RuleError::UnknownBall(b));
        }
        let verdict = match self.game {
            Game::NineBall => crate::nine_ball::play(self, shot, call)?,
            Game::EightBall => crate::eight_ball::play(self, shot, call)?,
            Game::FreePlay => self.free_play(shot, call)?,
        };
        if let Outcome::GameOver { winner, reason } = verdict.outcome {
            self.over = Some((winner, reason));
        }
        if let Some(next) = &verdict.next {
            self.next = next.clone();
        }
        Ok(verdict)
    }

    /// Takes one of the [`NextShot::choices`] offered; returns the next shot it leads to.
    pub fn choose(&mut self, choice: Choice) -> Result<NextShot, RuleError> {
        if self.over.is_some() {
            return Err(RuleError::GameOver);
        }
        if !self.next.choices.contains(&choice) {
            return Err(RuleError::ChoiceNotOffered {
                choice,
                offered: self.next.choices.clone(),
            });
        }
        let chooser = self.next.shooter;
        let pending = self.pending.take();
        let next = match (pending, choice) {
            (_, Choice::RerackAndBreak) => self.rerack(chooser),
            (Some(Pending::IllegalBreak { breaker, .. }), Choice::RerackOpponentBreaks) => {
                self.rerack(breaker)
            }
            (Some(Pending::IllegalBreak { scratched, .. }), Choice::ShootFromHere) => {
                let cue_ball = if scratched {
                    CueBall::InHandBehindHeadString
                } else {
                    CueBall::AsItLies
                };
                crate::eight_ball::normal_next(self, chooser, cue_ball)
            }
            (Some(Pending::EightOnBreak { foul, .. }), Choice::SpotEightAndShoot) => {
                self.put_back(8);
                // WPA 3.3: after a foul, ball in hand behind the head string.
                let cue_ball = if foul {
                    CueBall::InHandBehindHeadString
                } else {
                    CueBall::AsItLies
                };
                let mut next = crate::eight_ball::normal_next(self, chooser, cue_ball);
                next.spot = vec![8];
                next
            }
            (Some(Pending::PushOut { .. }), Choice::ShootFromHere) => {
                crate::nine_ball::normal_next(self, chooser, CueBall::AsItLies)
            }
            (Some(Pending::PushOut { pusher }), Choice::PassBack) => {
                crate::nine_ball::normal_next(self, pusher, CueBall::AsItLies)
            }
            (pending, _) => {
                // Unreachable: the choices offered always match the pending decision.
                self.pending = pending;
                return Err(RuleError::ChoiceNotOffered {
                    choice,
                    offered: self.next.choices.clone(),
                });
            }
        };
        self.next = next.clone();
        Ok(next)
    }

    /// A fresh rack broken by `breaker`, with the fouls of the match kept.
    fn rerack(&mut self, breaker: Seat) -> NextShot {
        let fouls = self.fouls;
        *self = GameState::new(self.game, breaker);
        self.fouls = fouls;
        self.next.rerack = true;
        self.next.clone()
    }

    /// Puts a spotted ball back among the balls on the table.
    pub(crate) fn put_back(&mut self, ball: u8) {
        if let Err(at) = self.on_table.binary_search(&ball) {
            self.on_table.insert(at, ball);
        }
    }

    /// Takes the pocketed object balls off the table.
    pub(crate) fn take_off(&mut self, shot: &ShotSummary) {
        self.on_table
            .retain(|b| !shot.pocketed.iter().any(|&(p, _)| p == *b));
    }

    /// Free play: never a foul, the shooter stays, a scratch respots the cue ball.
    fn free_play(&mut self, shot: &ShotSummary, call: Call) -> Result<Verdict, RuleError> {
        if call != Call::None {
            return Err(RuleError::CallNotUsed(Game::FreePlay, "calls"));
        }
        self.take_off(shot);
        let shooter = self.next.shooter;
        let cue_ball = if shot.scratch() {
            CueBall::Respot
        } else {
            CueBall::AsItLies
        };
        let next = NextShot::plain(
            shooter,
            cue_ball,
            self.on_table.clone(),
            CallRule::NotUsed,
            0,
        );
        Ok(Verdict {
            shooter,
            break_shot: false,
            push_out: false,
            fouls: Vec::new(),
            outcome: Outcome::Continues,
            assigned: None,
            next: Some(next),
        })
    }
}

/// The common fouls of a shot (WPA 6.1, 6.2, 6.3), the scratch first; `on` is what the cue
/// ball had to hit first and `allowed` the balls that satisfy it. `rails` is false for a push
/// out, which needs no contact and no rail (WPA 2.4).
pub(crate) fn common_fouls(
    shot: &ShotSummary,
    on: BallOn,
    allowed: &[u8],
    contact_and_rail: bool,
) -> Vec<Foul> {
    let mut fouls = Vec::new();
    if shot.scratch() {
        fouls.push(Foul::Scratch);
    }
    if !contact_and_rail {
        return fouls;
    }
    match shot.first_contact {
        None => fouls.push(Foul::NoBallHit),
        Some(hit) => {
            if !allowed.contains(&hit) {
                fouls.push(Foul::WrongBallFirst { hit, on });
            }
            if shot.pocketed_object_balls().next().is_none() && !shot.rail_after_contact() {
                fouls.push(Foul::NoRail);
            }
        }
    }
    fouls
}
