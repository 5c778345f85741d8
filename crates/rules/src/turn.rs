//! One turn at the table: who shoots ([`Seat`]), what they call ([`Call`]), what the next shot
//! must respect ([`NextShot`]) and the [`Verdict`] on the shot. Each game's rules
//! ([`crate::nine_ball`], [`crate::ten_ball`], [`crate::eight_ball`]) and the dispatcher over them
//! ([`crate::game`]) speak these words, so they live here, below both (issue 50).

use crate::foul::{Foul, Group, WinReason};
use crate::shot::ShotSummary;
use billiards_physics::Pocket;
use serde::{Deserialize, Serialize};

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
    /// No call: a break, a 9-ball shot, or an obvious 8-ball shot (WPA 1.6); in 10-ball a
    /// shot that calls nothing, so pocketing nothing legally (WPA 9.5, 9.7).
    #[default]
    None,
    /// 9-ball and 10-ball: a push out, only on the shot right after a legal break (WPA 2.4,
    /// 9.4).
    PushOut,
    /// 8-ball and 10-ball: a called safety; the turn ends whatever drops (WPA 1.6, 9.6; in
    /// 10-ball a ball made on it gives the incoming player the option of 9.7).
    Safety,
    /// 8-ball and 10-ball: this ball in this pocket (WPA 1.6, 3.6, 9.5). The 8 must always be
    /// called; in 10-ball every ball, the 10 only winning when called.
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
    /// 10-ball: every shot but the break calls one ball (any on the table: the lowest is hit
    /// first, the called ball may be another, as in a combination) and one pocket; only the
    /// called ball in the called pocket keeps the shooter at the table (WPA 9.5).
    BallAndPocket,
}

/// An option offered to a player before the next shot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Choice {
    /// Shoot the table as it lies (after an illegal 8-ball break, WPA 3.3; after a push
    /// out, WPA 2.4, 9.4; after a 10-ball shot that pocketed a ball it did not call, 9.7).
    ShootFromHere,
    /// After a push out (WPA 2.4, 9.4), or a 10-ball shot that pocketed a ball it did not
    /// call (WPA 9.7): the player who shot must shoot again.
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
    /// Options the shooter must choose between before shooting ([`GameState::choose`](crate::GameState::choose)).
    pub choices: Vec<Choice>,
    /// Balls to spot on the long string before the shot (WPA 1.4, 2.6).
    pub spot: Vec<u8>,
    /// A new rack must be put up before the shot.
    pub rerack: bool,
    /// The shooter's fouls in a row (9-ball and 10-ball; two is the warning of WPA 6.14).
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
/// side pocket". What the verdict's `fouls` already say is left out (issue 48, played:
/// "foul: the cue ball hit no ball: no ball hit; nothing pocketed"): a cue ball that hit no
/// ball ([`Foul::NoBallHit`]) pocketed nothing, and [`Foul::NoRail`] and
/// [`Foul::IllegalBreak`] say that no ball was pocketed; the words may then be empty.
pub fn what_happened(summary: &ShotSummary, call: Call, fouls: &[Foul]) -> String {
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
    let said = |f: fn(&Foul) -> bool| fouls.iter().any(f);
    let no_hit = summary.first_contact.is_none();
    if !dropped.is_empty() {
        parts.push(dropped.join(", "));
    } else if !said(|f| matches!(f, Foul::NoBallHit)) {
        if no_hit {
            parts.push("no ball hit".to_owned());
        }
        // A cue ball that hit nothing pocketed nothing: saying both is saying it twice.
        if !no_hit && !said(|f| matches!(f, Foul::NoRail | Foul::IllegalBreak { .. })) {
            parts.push("nothing pocketed".to_owned());
        }
    }
    parts.join("; ")
}
