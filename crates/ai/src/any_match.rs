//! A whole match of any game between two computer levels, through the one game interface
//! alone ([`GameRules`], issue 50): the same loop for every game of
//! [`billiards_rules::catalog`]. `billiards-cli match` prints it; tests play it to the end.

use crate::any_game::{Move, decide_any, layout_of};
use crate::level::Level;
use crate::noise::stream;
use billiards_physics::{BallSetup, Event, Params, Simulation, Vec2};
use billiards_rules::{CueBallPlace, GameRules, Seat, Setup, StrokeRecord};

/// How a match ended.
#[derive(Clone, Debug, PartialEq)]
pub struct MatchRun {
    /// The winner (`None`: stopped at the stroke limit).
    pub winner: Option<Seat>,
    /// Strokes played.
    pub strokes: usize,
    /// Fouls committed, by seat.
    pub fouls: [usize; 2],
    /// Games (racks, frames) finished.
    pub games: usize,
    /// The match's score in one line at the end.
    pub score_line: String,
}

fn solver(
    game: &dyn GameRules,
    params: &Params,
    balls: &[BallSetup],
) -> Result<Simulation, String> {
    let params = Params {
        ball: game.ball(),
        ..*params
    };
    let mut sim = Simulation::new(game.table(), params, balls).map_err(|e| e.to_string())?;
    sim.set_record_history(false);
    Ok(sim)
}

fn id_of(sim: &Simulation, n: u8) -> Result<usize, String> {
    crate::any_game::id_of(sim, n).ok_or_else(|| format!("no ball {n} on this table"))
}

fn put(sim: &mut Simulation, balls: &[(u8, Vec2)]) -> Result<(), String> {
    for &(n, p) in balls {
        let id = id_of(sim, n)?;
        sim.place(id, p, Vec2::ZERO, Default::default())
            .map_err(|e| format!("the {n} cannot go to ({:.3}, {:.3}): {e}", p.x, p.y))?;
    }
    Ok(())
}

/// Sets the table as a choice's [`Setup`] says.
fn apply(
    game: &dyn GameRules,
    params: &Params,
    sim: &mut Simulation,
    setup: Setup,
) -> Result<(), String> {
    match setup {
        Setup::Keep => Ok(()),
        Setup::Put { balls } => put(sim, &balls),
        Setup::Layout { balls } => {
            let balls: Vec<BallSetup> = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
            *sim = solver(game, params, &balls)?;
            Ok(())
        }
        Setup::Rack { balls } => {
            *sim = solver(game, params, &balls)?;
            Ok(())
        }
    }
}

/// Plays `game` to the end of its match between `levels` (seat A, seat B) under the
/// solver's `params` (the ball comes from the game), at most `max_strokes` strokes; each
/// stroke's verdict goes to `say`. Every draw comes from `seed`.
pub fn play_match(
    game: &mut dyn GameRules,
    params: &Params,
    levels: [Level; 2],
    seed: u64,
    max_strokes: usize,
    say: &mut dyn FnMut(String),
) -> Result<MatchRun, String> {
    let mut sim = solver(game, params, &game.layout().map_err(|e| e.0)?)?;
    let mut run = MatchRun {
        winner: None,
        strokes: 0,
        fouls: [0; 2],
        games: 0,
        score_line: String::new(),
    };
    while run.strokes < max_strokes {
        let turn = game.turn();
        let level = levels[turn.striker.index()];
        let decision_seed = seed ^ (run.strokes as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        let stroke = match decide_any(game, &sim, level, decision_seed)? {
            Move::Choose(index) => {
                let who = game.players()[turn.striker.index()].clone();
                say(format!("  {who} chooses: {}", turn.choices[index]));
                let setup = game.choose(index, &layout_of(&sim)).map_err(|e| e.0)?;
                apply(game, params, &mut sim, setup)?;
                continue;
            }
            Move::Strike(stroke) => stroke,
        };
        let cue = id_of(&sim, turn.cue_ball)?;
        if let (CueBallPlace::InHand { .. }, Some(at)) = (turn.place, stroke.place) {
            sim.place(cue, at, Vec2::ZERO, Default::default())
                .map_err(|e| e.to_string())?;
        }
        let before = layout_of(&sim);
        let mut rng = stream(seed, 1 << 40, run.strokes as u64);
        let shot = level
            .execution_noise()
            .apply(stroke.shot, sim.params(), &mut rng);
        // A history for this stroke only: its events start with the strike, as the rules
        // read them.
        sim.set_record_history(true);
        sim.strike(cue, shot).map_err(|e| e.to_string())?;
        sim.run_to_rest().map_err(|e| e.to_string())?;
        let events: Vec<Event> = sim.history().events().to_vec();
        sim.set_record_history(false);
        let after = layout_of(&sim);
        let judged = game
            .judge(&StrokeRecord {
                events: &events,
                numbers: sim.numbers(),
                before: &before,
                after: &after,
                declared: stroke.declared,
            })
            .map_err(|e| format!("stroke {}: {e}", run.strokes + 1))?;
        run.strokes += 1;
        if !judged.fair {
            run.fouls[judged.striker.index()] += 1;
        }
        let who = &game.players()[judged.striker.index()];
        let declared = stroke
            .declared
            .text(&|b| game.ball_name(b))
            .map_or(String::new(), |d| format!(" ({d})"));
        say(format!(
            "stroke {}: {who}{declared}: {}",
            run.strokes, judged.text
        ));
        put(&mut sim, &judged.put)?;
        if let Some(end) = &judged.end {
            run.games += 1;
            say(format!(
                "  {} wins the game: {}; {}",
                game.players()[end.winner.index()],
                end.reason,
                game.score_line()
            ));
            if end.match_over {
                // A one-player game (a drill session) names its player, not a try's winner.
                run.winner = game.match_winner().or(Some(end.winner));
                break;
            }
            let balls = game.next_game().map_err(|e| e.0)?;
            sim = solver(game, params, &balls)?;
        }
    }
    run.score_line = game.score_line();
    Ok(run)
}
