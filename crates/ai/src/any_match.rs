//! A whole match of any game between two players, through the one game interface alone
//! ([`GameRules`], issue 50): the one loop that `billiards-cli match`, every tournament
//! (pool's racks, snooker's frames, carom's games) and `simulate --computer` run. Each
//! decision is the game's own search ([`Player::decide_game`]), each stroke struck with the
//! player's execution noise, run to rest and judged by the game; what the tournaments count
//! (visits, balls pocketed, points in a visit, run-outs from the opening stroke) is read
//! from the interface's judgements and points, so no game has a loop of its own.
//!
//! Every draw comes from the match's seed: decision `k` (strokes and options counted
//! together) from `stream(seed, 1, k)`, stroke `k`'s execution from `stream(seed, 2, k)`
//! ([`crate::Plan::executed`]'s stream); the layouts are the game's.

use crate::Player;
use crate::any_game::{Move, layout_of};
use crate::noise::stream;
use billiards_physics::recording::{Recorder, Recording};
use billiards_physics::{BallId, BallSetup, Event, Params, Shot, Simulation, Vec2, Vec3};
use billiards_rules::interface::layout_moves;
use billiards_rules::{
    CueBallPlace, GameEnd, GameRules, Judgement, Seat, Setup, StrokeEntry, StrokeLog, StrokeRecord,
};
use rand::Rng;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// How a match is played: the players by seat, the solver, the seed, the limits.
#[derive(Clone, Copy, Debug)]
pub struct Seating {
    /// The players, by [`Seat::index`].
    pub players: [Player; 2],
    /// The solver's parameters (the ball is the game's, [`GameRules::ball`]).
    pub params: Params,
    /// The seed of every draw.
    pub seed: u64,
    /// Strokes after which the match is stopped without a winner.
    pub max_strokes: usize,
    /// Record every input: each game's [`Recording`] and [`StrokeLog`] in
    /// [`MatchRun::recorded`].
    pub record: bool,
}

impl Seating {
    /// Two players under `params`, seed `seed`, at most `max_strokes` strokes, no
    /// recording.
    pub fn new(players: [Player; 2], params: Params, seed: u64, max_strokes: usize) -> Self {
        Self {
            players,
            params,
            seed,
            max_strokes,
            record: false,
        }
    }
}

/// One seat's figures over a match.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SeatTally {
    /// Visits to the table (from taking it to leaving it: a stroke that does not continue
    /// ends one).
    pub visits: usize,
    /// Strokes played.
    pub strokes: usize,
    /// Fouls.
    pub fouls: usize,
    /// Object balls pocketed on the seat's strokes.
    pub pocketed: usize,
    /// The game's points ([`GameRules::points`]) the seat's own strokes gained.
    pub points: u32,
    /// Those points by visit: every visit that gained any (snooker's breaks, carom's runs).
    pub runs: Vec<u32>,
    /// Decisions taken (strokes and options).
    pub decisions: usize,
    /// Seconds spent deciding, in all.
    pub decision_secs: f64,
    /// The longest decision, seconds.
    pub max_decision_secs: f64,
    /// Noisy simulations the decisions ran, where the search counts them.
    pub simulations: usize,
}

/// One game (rack, frame, carom game) of a match, as it ended.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GamePlayed {
    /// The winner; `None`: the match was stopped in it.
    pub winner: Option<Seat>,
    /// Who struck its last opening stroke (a break, a break-off; a re-rack's break).
    pub opener: Seat,
    /// Won by the opener without the other seat striking after that opening.
    pub run_out: bool,
    /// Why it ended, in the game's words.
    pub reason: String,
}

/// A match played.
#[derive(Clone, Debug, PartialEq)]
pub struct MatchRun {
    /// The winner (`None`: stopped at the stroke limit).
    pub winner: Option<Seat>,
    /// Strokes played.
    pub strokes: usize,
    /// Every game begun, in order (the last unfinished when the match was stopped).
    pub played: Vec<GamePlayed>,
    /// Each seat's figures.
    pub tally: [SeatTally; 2],
    /// The game's points at the end ([`GameRules::points`]).
    pub points: [u32; 2],
    /// The match's score in one line at the end.
    pub score_line: String,
    /// With [`Seating::record`]: each game's recording and rules log.
    pub recorded: Vec<(Recording, StrokeLog)>,
}

impl MatchRun {
    /// Games (racks, frames, tries) finished.
    pub fn games(&self) -> usize {
        self.played.iter().filter(|g| g.winner.is_some()).count()
    }

    /// Fouls committed, by seat.
    pub fn fouls(&self) -> [usize; 2] {
        [self.tally[0].fouls, self.tally[1].fouls]
    }
}

/// The table in play: a lean solver, or one recorded input by input.
enum Table {
    Lean(Box<Simulation>),
    Recorded(Box<Recorder>, StrokeLog),
}

impl Table {
    fn new(
        game: &dyn GameRules,
        params: &Params,
        balls: Vec<BallSetup>,
        record: bool,
    ) -> Result<Self, String> {
        let params = Params {
            ball: game.ball(),
            ..*params
        };
        if record {
            let recorder = Recorder::new(game.table(), params, balls).map_err(|e| e.to_string())?;
            let log = StrokeLog::new(game).map_err(|e| e.0)?;
            return Ok(Table::Recorded(Box::new(recorder), log));
        }
        let mut sim = Simulation::new(game.table(), params, &balls).map_err(|e| e.to_string())?;
        sim.set_record_history(false);
        Ok(Table::Lean(Box::new(sim)))
    }

    fn sim(&self) -> &Simulation {
        match self {
            Table::Lean(s) => s,
            Table::Recorded(r, _) => r.sim(),
        }
    }

    fn id(&self, n: u8) -> Result<BallId, String> {
        self.sim()
            .numbers()
            .iter()
            .position(|&m| m == n)
            .ok_or_else(|| format!("no ball {n} on this table"))
    }

    fn place(&mut self, n: u8, p: Vec2) -> Result<(), String> {
        let id = self.id(n)?;
        match self {
            Table::Lean(s) => s.place(id, p, Vec2::ZERO, Vec3::ZERO),
            Table::Recorded(r, _) => r.place(id, p, Vec2::ZERO, Vec3::ZERO),
        }
        .map_err(|e| format!("the {n} cannot go to ({:.4}, {:.4}): {e}", p.x, p.y))
    }

    /// Strikes ball `n` and runs to rest; the stroke's events from the strike on.
    fn strike(&mut self, n: u8, shot: Shot) -> Result<Vec<Event>, String> {
        let id = self.id(n)?;
        match self {
            Table::Lean(s) => {
                // A history for this stroke only: its events start with the strike, as the
                // rules read them.
                s.set_record_history(true);
                s.strike(id, shot).map_err(|e| e.to_string())?;
                s.run_to_rest().map_err(|e| e.to_string())?;
                let events = s.history().events().to_vec();
                s.set_record_history(false);
                Ok(events)
            }
            Table::Recorded(r, _) => {
                let first = r.sim().history().events().len();
                r.strike(id, shot).map_err(|e| e.to_string())?;
                r.run_to_rest().map_err(|e| e.to_string())?;
                Ok(r.sim().history().events()[first..].to_vec())
            }
        }
    }

    fn log(&mut self, entry: StrokeEntry) {
        if let Table::Recorded(_, log) = self {
            log.strokes.push(entry);
        }
    }

    fn finish(self) -> Option<(Recording, StrokeLog)> {
        match self {
            Table::Lean(_) => None,
            Table::Recorded(r, log) => Some((r.recording(), log)),
        }
    }
}

/// Where a match stands between strokes: the table, the figures, the game's opener.
struct Play<'a> {
    seating: &'a Seating,
    table: Table,
    run: MatchRun,
    decisions: u64,
    /// The options taken since the last stroke, by index.
    choices: Vec<usize>,
    /// The seat whose visit is on, until a stroke ends it.
    visit: Option<Seat>,
    /// The points gained in the visit so far.
    run_points: u32,
    opener: Seat,
    other_struck: bool,
}

impl Play<'_> {
    /// Starts a new table for `balls`, keeping the finished one's recording.
    fn new_table(&mut self, game: &dyn GameRules, balls: Vec<BallSetup>) -> Result<(), String> {
        let table = Table::new(game, &self.seating.params, balls, self.seating.record)?;
        if let Some(done) = std::mem::replace(&mut self.table, table).finish() {
            self.run.recorded.push(done);
        }
        Ok(())
    }

    /// Sets the table as an option's [`Setup`] says.
    fn apply(&mut self, game: &dyn GameRules, setup: Setup) -> Result<(), String> {
        match setup {
            Setup::Keep => Ok(()),
            Setup::Put { balls } => balls.iter().try_for_each(|&(n, p)| self.table.place(n, p)),
            Setup::Layout { balls } => {
                let now = layout_of(self.table.sim());
                let sim = self.table.sim();
                let moves = layout_moves(&now, &balls, sim.params().ball.radius, sim.table());
                match moves {
                    // Every ball now on the table is in the layout: moved in place, in the
                    // same recording.
                    Some(moves) if now.iter().all(|(n, _)| balls.iter().any(|(m, _)| m == n)) => {
                        moves.iter().try_for_each(|&(n, p)| self.table.place(n, p))
                    }
                    _ => {
                        let setups = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
                        self.new_table(game, setups)
                    }
                }
            }
            Setup::Rack { balls } => self.new_table(game, balls),
        }
    }

    /// Times one decision of the striker into its tally.
    fn decide(
        &mut self,
        game: &dyn GameRules,
        striker: Seat,
    ) -> Result<crate::game::Decided, String> {
        let player = self.seating.players[striker.index()];
        let seed = stream(self.seating.seed, 1, self.decisions).random();
        let started = Instant::now();
        let decided = player.decide_game(game, self.table.sim(), seed)?;
        let secs = started.elapsed().as_secs_f64();
        self.decisions += 1;
        let t = &mut self.run.tally[striker.index()];
        t.decisions += 1;
        t.decision_secs += secs;
        t.max_decision_secs = t.max_decision_secs.max(secs);
        Ok(decided)
    }

    /// Counts one judged stroke of `striker` that gained `gained` points and pocketed
    /// `pocketed` object balls.
    fn count(&mut self, striker: Seat, judged: &Judgement, gained: u32, pocketed: usize) {
        let run = &mut self.run;
        run.strokes += 1;
        if self.visit != Some(striker) {
            run.tally[striker.index()].visits += 1;
            self.visit = Some(striker);
        }
        if striker != self.opener {
            self.other_struck = true;
        }
        let t = &mut run.tally[striker.index()];
        t.strokes += 1;
        t.pocketed += pocketed;
        t.points += gained;
        if !judged.fair {
            t.fouls += 1;
        }
        // A visit's run goes on while its strokes score (snooker's break, 2.8): a stroke that
        // gains nothing, or the end of the visit or of the game, closes it.
        self.run_points += gained;
        if gained == 0 || !judged.continues || judged.end.is_some() {
            self.close_run(striker);
        }
        if !judged.continues || judged.end.is_some() {
            self.visit = None;
        }
    }

    fn close_run(&mut self, striker: Seat) {
        if self.run_points > 0 {
            self.run.tally[striker.index()].runs.push(self.run_points);
        }
        self.run_points = 0;
    }
}

/// Plays `game` to the end of its match (or `seating.max_strokes` strokes) between
/// `seating`'s players; each stroke's verdict and each option taken go to `say`.
pub fn play_match(
    game: &mut dyn GameRules,
    seating: &Seating,
    say: &mut dyn FnMut(String),
) -> Result<MatchRun, String> {
    for player in seating.players {
        player.plays(game)?;
    }
    let layout = game.layout().map_err(|e| e.0)?;
    let mut play = Play {
        seating,
        table: Table::new(game, &seating.params, layout, seating.record)?,
        run: MatchRun {
            winner: None,
            strokes: 0,
            played: Vec::new(),
            tally: Default::default(),
            points: [0; 2],
            score_line: String::new(),
            recorded: Vec::new(),
        },
        decisions: 0,
        choices: Vec::new(),
        visit: None,
        run_points: 0,
        opener: game.turn().striker,
        other_struck: false,
    };
    while play.run.strokes < seating.max_strokes {
        if strike_once(game, &mut play, say)? {
            break;
        }
    }
    if let Some(seat) = play.visit {
        // Stopped in a visit: its run so far counts.
        play.close_run(seat);
    }
    if play.run.winner.is_none() {
        // Stopped in a game: it is counted as begun, without a winner.
        play.run.played.push(GamePlayed {
            winner: None,
            opener: play.opener,
            run_out: false,
            reason: format!("stopped after {} strokes", seating.max_strokes),
        });
    }
    let Play { table, mut run, .. } = play;
    if let Some(done) = table.finish() {
        run.recorded.push(done);
    }
    run.score_line = game.score_line();
    run.points = game.points();
    Ok(run)
}

/// One decision of the striker carried out: an option taken, or a stroke played, judged,
/// counted and logged, the balls put back and a finished game closed; `true` once the match
/// is over.
fn strike_once(
    game: &mut dyn GameRules,
    play: &mut Play<'_>,
    say: &mut dyn FnMut(String),
) -> Result<bool, String> {
    let turn = game.turn();
    let decided = play.decide(game, turn.striker)?;
    let stroke = match decided.as_move(game) {
        Some(Move::Choose(index)) => {
            let who = &game.players()[turn.striker.index()];
            say(format!("  {who} chooses: {}", turn.choices[index]));
            let setup = game
                .choose(index, &layout_of(play.table.sim()))
                .map_err(|e| e.0)?;
            play.choices.push(index);
            play.apply(game, setup)?;
            return Ok(false);
        }
        Some(Move::Strike(stroke)) => stroke,
        None => return Err(format!("{decided:?}: not an option of this turn")),
    };
    if turn.opening {
        play.opener = turn.striker;
        play.other_struck = false;
    }
    if let Some(sims) = decided.simulations() {
        play.run.tally[turn.striker.index()].simulations += sims;
    }
    let judged = play_stroke(game, play, &turn, &stroke)?;
    let declared = stroke
        .declared
        .text(&|b| game.ball_name(b))
        .map_or(String::new(), |d| format!(" ({d})"));
    say(format!(
        "stroke {}{declared}: {}",
        play.run.strokes,
        judged.text_by(&game.players()[judged.striker.index()])
    ));
    for &(n, p) in &judged.put {
        play.table.place(n, p)?;
    }
    play.table.log(StrokeEntry {
        choices: std::mem::take(&mut play.choices),
        declared: stroke.declared,
        judgement: judged.clone(),
    });
    match &judged.end {
        Some(end) => close_game(game, play, end, say),
        None => Ok(false),
    }
}

/// Plays `stroke` under `turn`: the cue ball placed if in hand, struck with the striker's
/// execution noise, run to rest, judged and counted.
fn play_stroke(
    game: &mut dyn GameRules,
    play: &mut Play<'_>,
    turn: &billiards_rules::Turn,
    stroke: &crate::any_game::Stroke,
) -> Result<Judgement, String> {
    match (turn.place, stroke.place) {
        (CueBallPlace::InHand { .. }, Some(at)) => play.table.place(turn.cue_ball, at)?,
        (_, Some(at)) => {
            return Err(format!(
                "the cue ball is not in hand, yet the decision places it at ({:.3}, {:.3})",
                at.x, at.y
            ));
        }
        (_, None) => {}
    }
    let before = layout_of(play.table.sim());
    let noise = play.seating.players[turn.striker.index()].execution_noise();
    let draw = stream(play.seating.seed, 2, play.run.strokes as u64).random();
    let shot = noise.apply(
        stroke.shot,
        play.table.sim().params(),
        &mut stream(draw, u64::MAX, 0),
    );
    let events = play.table.strike(turn.cue_ball, shot)?;
    let sim = play.table.sim();
    let after = layout_of(sim);
    let record = StrokeRecord {
        events: &events,
        numbers: sim.numbers(),
        before: &before,
        after: &after,
        declared: stroke.declared,
    };
    let pocketed = record
        .summary()
        .map_err(|e| e.0)?
        .pocketed_object_balls()
        .count();
    let points_before = game.points()[turn.striker.index()];
    let judged = game
        .judge(&record)
        .map_err(|e| format!("stroke {}: {e}", play.run.strokes + 1))?;
    let gained = game.points()[turn.striker.index()].saturating_sub(points_before);
    play.count(judged.striker, &judged, gained, pocketed);
    Ok(judged)
}

/// A game that ended with `end`: recorded, said, and the next one set up unless the match
/// is over too (`true` then).
fn close_game(
    game: &mut dyn GameRules,
    play: &mut Play<'_>,
    end: &GameEnd,
    say: &mut dyn FnMut(String),
) -> Result<bool, String> {
    play.run.played.push(GamePlayed {
        winner: Some(end.winner),
        opener: play.opener,
        run_out: end.winner == play.opener && !play.other_struck,
        reason: end.reason.clone(),
    });
    say(format!(
        "  {} wins the game: {}; {}",
        game.players()[end.winner.index()],
        end.reason,
        game.score_line()
    ));
    if end.match_over {
        // A one-player game (a drill session) names its player, not a try's winner.
        play.run.winner = game.match_winner().or(Some(end.winner));
        return Ok(true);
    }
    let balls = game.next_game().map_err(|e| e.0)?;
    play.new_table(game, balls)?;
    Ok(false)
}
