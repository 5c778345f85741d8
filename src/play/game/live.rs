//! A game in play behind the one game interface ([`GameRules`], issue 50): any game of the
//! catalog ([`billiards_rules::catalog::GAMES`]) the game knows nothing special about. The
//! turn, the verdict, the options, the score and the end all come from the interface; the
//! log ([`StrokeLog`]) is written beside the recording as every game's is.
//!
//! Every match is played through it: pool's games, snooker, three-cushion.

use billiards_ai::Level;
use billiards_rules::catalog::{GameEntry, MatchSettings};
use billiards_rules::{CueBallPlace, Declaration, GameRules, Judgement, Seat, StrokeLog};

use super::turn::Turn;

/// A match of any game in play and what the players did since the last stroke.
#[derive(Debug)]
pub struct LiveGame {
    /// The game's rules and state.
    pub rules: Box<dyn GameRules>,
    /// Its catalog entry (id, label, what its length counts); `None` for a game not of the
    /// catalog (a drill session, [`GameRules::solo`]).
    pub entry: Option<&'static GameEntry>,
    /// Each seat's computer level; `None`: a human.
    pub seats: [Option<Level>; 2],
    /// The seed of the match; each game of it takes the next.
    pub seed: u64,
    /// Games started in the match (the first is 0).
    pub games: u64,
    /// What the striker declared for the next stroke.
    pub declared: Declaration,
    /// The last judgement.
    pub last: Option<Judgement>,
    /// The last judgement waits for the player.
    pub verdict_shown: bool,
    /// The last foul in words, with the offender, kept until a later foul.
    pub last_foul: Option<String>,
    /// Options taken since the last stroke (logged with the next one).
    pub choices: Vec<usize>,
    /// The log of the recording in play.
    pub log: StrokeLog,
    /// Balls an option puts back, set on the table after the command.
    pub pending: Vec<(u8, billiards_physics::Vec2)>,
    /// A ball and pocket are being called (the call window is up, a click on a pocket
    /// calls it).
    pub calling: bool,
    /// The ball being called ([`billiards_rules::Declarations::callable`]).
    pub call_ball: Option<u8>,
    /// The call the aim proposed when calling began, for the player to confirm.
    pub proposed: Option<Declaration>,
    /// The recording (by its start) the log belongs to; `None` until free play's first
    /// stroke binds it ([`LiveGame::bind_sandbox`]).
    pub recording: Option<std::time::SystemTime>,
    /// Free play: the table at rest its game last took stock of
    /// ([`GameRules::set_by_hand`]).
    pub seen: Vec<(u8, billiards_physics::Vec2)>,
}

impl LiveGame {
    /// `rules` as started from `entry` (`None`: a game not of the catalog, a drill), with
    /// each seat's computer level and the match's seed; its log empty from the game as it
    /// stands.
    pub fn new(
        rules: Box<dyn GameRules>,
        entry: Option<&'static GameEntry>,
        seats: [Option<Level>; 2],
        seed: u64,
    ) -> Result<Self, billiards_rules::RulesError> {
        let log = StrokeLog::new(rules.as_ref())?;
        Ok(Self {
            rules,
            entry,
            seats,
            seed,
            games: 0,
            declared: Declaration::None,
            last: None,
            verdict_shown: false,
            last_foul: None,
            choices: Vec::new(),
            log,
            pending: Vec::new(),
            calling: false,
            call_ball: None,
            proposed: None,
            recording: None,
            seen: Vec::new(),
        })
    }

    /// Free play between `players` on the table as it is: the sandbox, bound to the table
    /// and the recording at its first stroke ([`LiveGame::bind_sandbox`]). `None` if the
    /// catalog cannot start it (never for its own equipment).
    pub fn sandbox(players: [String; 2], seats: [Option<Level>; 2]) -> Option<Self> {
        let entry = billiards_rules::catalog::find("free-play").ok()?;
        let settings = MatchSettings::new(players, 1, 0);
        let rules = entry.start(&settings).ok()?;
        Self::new(rules, Some(entry), seats, 0).ok()
    }

    /// Free play's game follows the table: when the recording in play is not the one its log
    /// belongs to (a rack, a position, a scene or a new table since), it starts again on
    /// `table` and `ball`, its log empty, bound to `recording`. Other games keep theirs
    /// (their layouts are the rules' own). Returns why it could not, if it could not.
    pub fn bind_sandbox(
        &mut self,
        recording: std::time::SystemTime,
        table: billiards_physics::Table,
        ball: billiards_physics::BallSpec,
    ) -> Result<(), billiards_rules::RulesError> {
        let Some(entry) = self.entry.filter(|_| self.rules.sandbox()) else {
            return Ok(());
        };
        if self.recording == Some(recording) {
            return Ok(());
        }
        let settings = MatchSettings {
            equipment: Some((table, ball)),
            ..MatchSettings::new(self.rules.players().clone(), 1, self.seed)
        };
        let rules = entry.start(&settings)?;
        *self = Self {
            recording: Some(recording),
            last: self.last.take(),
            ..Self::new(rules, self.entry, self.seats, self.seed)?
        };
        Ok(())
    }
    /// The name of `seat`.
    pub fn name(&self, seat: Seat) -> &str {
        &self.rules.players()[seat.index()]
    }

    /// The name of `seat`, "(computer)" after it for the computer's seat.
    pub fn seat_name(&self, seat: Seat) -> String {
        match self.computer(seat) {
            Some(_) => format!("{} (computer)", self.name(seat)),
            None => self.name(seat).to_owned(),
        }
    }

    /// The computer's level at `seat`, `None` for a human.
    pub fn computer(&self, seat: Seat) -> Option<Level> {
        self.seats[seat.index()]
    }

    /// Whether a human plays in this match.
    pub fn has_human(&self) -> bool {
        self.seats.iter().any(Option::is_none)
    }

    /// Which turn this is: the game, the strokes and the options so far.
    pub fn turn_key(&self) -> (u64, usize, usize) {
        (
            self.seed.wrapping_add(self.games),
            self.log.strokes.len(),
            self.choices.len(),
        )
    }

    /// The turn's phase (with the balls at rest and no dialog open).
    pub fn phase(&self) -> Turn {
        let turn = self.rules.turn();
        if self.rules.end().is_some() {
            Turn::GameOver
        } else if self.verdict_shown || !turn.choices.is_empty() {
            Turn::Verdict
        } else if self.calling {
            Turn::Calling
        } else if matches!(turn.place, CueBallPlace::InHand { .. }) {
            Turn::BallInHand
        } else {
            Turn::Aiming
        }
    }

    /// The last judgement in words, with the striker: "Ann: no point ...". A text that names
    /// the striker already ("Ann pots a red") is given as it is.
    pub fn verdict_text(&self, judgement: &Judgement) -> String {
        judgement.text_by(self.name(judgement.striker))
    }

    /// What one game of the match is called: a rack (pool), a frame (snooker), a try (a
    /// drill), a game.
    pub fn game_noun(&self) -> &'static str {
        if self.rules.solo() {
            return "try";
        }
        self.entry.map_or("game", |e| e.unit.game())
    }

    /// The next game of the match started ([`GameRules::next_game`], a drill's next try):
    /// the last stroke and foul forgotten. Returns the layout to set, a new recording
    /// (whose log [`LiveGame::restart_log`] starts).
    pub fn begin_next(
        &mut self,
    ) -> Result<Vec<billiards_physics::BallSetup>, billiards_rules::RulesError> {
        let balls = self.rules.next_game()?;
        self.games += 1;
        self.last = None;
        self.last_foul = None;
        self.verdict_shown = false;
        Ok(balls)
    }

    /// A new recording of the game as it stands: a new log, the options taken forgotten.
    pub fn restart_log(&mut self) -> Result<(), billiards_rules::RulesError> {
        self.choices.clear();
        self.log = StrokeLog::new(self.rules.as_ref())?;
        Ok(())
    }

    /// The end of the game in words: "Ann wins the rack and the match: the 9 was pocketed
    /// legally", "Ann wins the game and the match: 40 points".
    pub fn end_text(&self) -> Option<String> {
        let end = self.rules.end()?;
        if self.rules.solo() {
            // One player: the reason says who made what ("try 2 made (score 100): ...").
            return Some(end.reason);
        }
        Some(format!(
            "{} wins the {}{}: {}",
            self.name(end.winner),
            self.game_noun(),
            if end.match_over { " and the match" } else { "" },
            end.reason,
        ))
    }

    /// Who plays next and how: "Bob (computer) plays the cue ball next, with ball in hand
    /// anywhere on the table".
    pub fn next_text(&self) -> String {
        let turn = self.rules.turn();
        let hand = match turn.place {
            CueBallPlace::InHand { region } => format!(", with ball in hand {}", region.words()),
            CueBallPlace::AsItLies | CueBallPlace::Placed => String::new(),
        };
        format!(
            "{} plays {} next{hand}",
            self.seat_name(turn.striker),
            self.rules.ball_name(turn.cue_ball)
        )
    }

    /// The HUD's lines: the score (computer seats marked), what to do now, the ball on, the
    /// game's own status lines, the declaration, the last stroke and the last foul. `off`:
    /// the balls the stroke in play has pocketed so far, counted off the balls left at once
    /// ([`GameRules::status_while`]).
    pub fn hud_lines(&self, phase: Turn, off: &[u8]) -> Vec<String> {
        let turn = self.rules.turn();
        let striker = self.name(turn.striker);
        let mut score = self.rules.score_line();
        for seat in [Seat::A, Seat::B] {
            if self.computer(seat).is_some() && !self.name(seat).is_empty() {
                score = score.replacen(self.name(seat), &self.seat_name(seat), 1);
            }
        }
        // The opening stroke on a table with pockets is a break (pool's, snooker's
        // break-off); carom's opening stroke is a stroke like the others.
        let pockets = self.rules.table().pockets != billiards_physics::PocketShape::Pocketless;
        let to = if turn.opening && pockets {
            "to break".to_owned()
        } else {
            format!("to play {}", self.rules.ball_name(turn.cue_ball))
        };
        let doing = match phase {
            Turn::NewGame => "new game: choose the game and the players".to_owned(),
            Turn::ShotInPlay => format!("{striker} plays: balls moving"),
            Turn::GameOver => self
                .end_text()
                .unwrap_or_else(|| "the game is over".to_owned()),
            Turn::Verdict if !turn.choices.is_empty() => {
                format!("{striker} to choose: {}", turn.choices.join(" or "))
            }
            Turn::Verdict => format!("{striker} to play next: continue"),
            Turn::BallInHand | Turn::Aiming if let Some(level) = self.computer(turn.striker) => {
                format!("{striker} (computer, {level}) {to}")
            }
            Turn::BallInHand => format!(
                "{striker} {to}: ball in hand {}, drag it, aim and shoot",
                match turn.place {
                    CueBallPlace::InHand { region } => region.words(),
                    _ => "anywhere",
                }
            ),
            Turn::Calling if turn.declare.callable == [8] => {
                format!("{striker} calls the 8: click a pocket")
            }
            Turn::Calling => format!("{striker} calls a ball and a pocket: click the pocket"),
            Turn::Aiming => format!("{striker} {to}: aim and shoot"),
        };
        let mut lines = vec![score, doing];
        let status = self.rules.status_while(off);
        // The ball on, unless the game's own lines say it.
        let said = status.iter().any(|l| l.starts_with("ball on"));
        if self.rules.end().is_none() && !turn.ball_on.is_empty() && !said {
            lines.push(format!("ball on: {}", turn.ball_on));
        }
        lines.extend(status);
        if let Some(text) = self.declared.text(&|b| self.rules.ball_name(b)) {
            // Pool's words for its declarations (WPA 1.6, 2.4): a call.
            let word = match self.declared {
                Declaration::Nominate { .. } => "declared",
                _ => "call",
            };
            lines.push(format!("{word}: {text}"));
        }
        if let Some(last) = &self.last {
            lines.push(format!("last stroke: {}", self.verdict_text(last)));
        }
        if let Some(foul) = &self.last_foul {
            lines.push(format!("last foul: {foul}"));
        }
        lines
    }
}
