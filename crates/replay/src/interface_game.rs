//! `simulate --game ID --shot ...` for every game through the one game interface (issue 50):
//! a scripted rack of shots judged stroke by stroke by [`billiards_rules::GameRules`], logged
//! as any game's ([`StrokeLog`]). A game between computers is `computer_game.rs`'s, a
//! tournament `tournament.rs`'s.

use crate::args::SimulateArgs;
use crate::setup::{ShotSummary, setup};
use billiards_ai::any_game::layout_of;
use billiards_ai::game::declaration_of;
use billiards_physics::recording::Recorder;
use billiards_physics::{Params, Vec2, Vec3};
use billiards_rules::catalog::{GameEntry, MatchSettings, find};
use billiards_rules::{
    CueBallPlace, Declaration, GameRules, Setup, StrokeEntry, StrokeLog, StrokeRecord, Turn,
};

fn entry(id: &str) -> Result<&'static GameEntry, String> {
    find(id).map_err(|e| e.0)
}

/// Plays `a.shots` in order as the strokes of a game of `id` through the one game interface
/// (pool's games on `--table` with `--rack-style`, the others on their own tables): each
/// stroke by the striker of the turn with their own cue ball, `--call K:...` declared for
/// stroke K, the options the rules offer taken from `--choice` in order (else the first),
/// a cue ball in hand put where the rules accept it (the head spot first, a script has no
/// hand), the balls a judgement puts back set; every judgement printed, and with `--out`
/// the recording and its log ([`StrokeLog`]) written after each stroke (`verify` re-judges
/// it). Rack seed: `--rack-seed`, else `--seed`, else 0.
pub(crate) fn simulate(id: &str, a: &SimulateArgs) -> Result<(), String> {
    let entry = entry(id)?;
    let (table, params, _, _, shots) = setup(a)?;
    if shots.is_empty() {
        return Err("no shots: give --shot ANGLE_DEG:SPEED".into());
    }
    let players: [String; 2] = match a.players.split_once(',') {
        Some((x, y)) => [x.trim().to_string(), y.trim().to_string()],
        None => return Err(format!("--players {:?}: expected NAME,NAME", a.players)),
    };
    let seed = a.rack_seed.or(a.seed).unwrap_or(0);
    let settings = MatchSettings {
        style: a.rack_style,
        equipment: entry.pool_table.then_some((table, params.ball)),
        ..MatchSettings::new(players, entry.default_length, seed)
    };
    let mut game = entry.start(&settings).map_err(|e| e.0)?;
    let params = Params {
        ball: game.ball(),
        ..params
    };
    let balls = game.layout().map_err(|e| e.0)?;
    let mut rec = Recorder::new(game.table(), params, balls).map_err(|e| e.to_string())?;
    let mut log = StrokeLog::new(game.as_ref()).map_err(|e| e.0)?;
    let mut choices = a.choices.iter().copied();
    let mut out = Vec::new();
    println!("{}, rack seed {seed}: {}", entry.label, game.score_line());
    for (k, shot) in (1..).zip(shots) {
        let at = |e: &dyn std::fmt::Display| format!("stroke {k}: {e}");
        if game.end().is_some() {
            println!("stroke {k} and later not played: the game is over");
            break;
        }
        let made = take_options(game.as_mut(), &mut rec, &mut choices).map_err(|e| at(&e))?;
        let turn = game.turn();
        put_in_hand(game.as_ref(), &mut rec, &turn).map_err(|e| at(&e))?;
        let declared = a
            .calls
            .iter()
            .find(|(s, _)| *s == k)
            .map_or(Declaration::None, |&(_, call)| declaration_of(call));
        let cue = id_of(&rec, turn.cue_ball).ok_or_else(|| at(&"no cue ball"))?;
        let before = layout_of(rec.sim());
        let (start, first) = (rec.sim().time(), rec.sim().history().events().len());
        let in_air = crate::flight::airborne(rec.sim());
        rec.strike(cue, shot).map_err(|e| at(&e))?;
        rec.run_to_rest().map_err(|e| at(&e))?;
        let sim = rec.sim();
        let events = &sim.history().events()[first..];
        let judged = game
            .judge(&StrokeRecord {
                events,
                numbers: sim.numbers(),
                before: &before,
                after: &layout_of(sim),
                declared,
            })
            .map_err(|e| at(&e))?;
        let said = judged.text_by(&game.players()[judged.striker.index()]);
        let spotted: String = judged
            .put
            .iter()
            .map(|&(n, _)| format!("; {} is spotted", game.ball_name(n)))
            .collect();
        println!("stroke {k}: {said}{spotted}{}", what_next(game.as_ref()));
        out.push(ShotSummary::of(
            shot,
            sim,
            (first, start, in_air),
            Some(judged.clone()),
        ));
        put(&mut rec, &judged.put).map_err(|e| at(&e))?;
        log.strokes.push(StrokeEntry {
            choices: made,
            declared,
            judgement: judged,
        });
        if let Some(path) = &a.out {
            rec.recording().save(path).map_err(|e| e.to_string())?;
            save_json(&StrokeLog::path_beside(path), &log)?;
        }
    }
    println!("{}", game.score_line());
    if a.json {
        let json = serde_json::to_string_pretty(&out).map_err(|e| e.to_string())?;
        println!("{json}");
    }
    Ok(())
}

/// What the judgement left, in words: "; game over: B wins (the 9 was pocketed)", or who
/// plays next, with the cue ball in hand and where, or the options offered.
fn what_next(game: &dyn GameRules) -> String {
    let name = |seat: billiards_rules::Seat| game.players()[seat.index()].clone();
    if let Some(end) = game.end() {
        let over = if end.match_over { "match" } else { "game" };
        return format!("; {over} over: {} wins ({})", name(end.winner), end.reason);
    }
    let turn = game.turn();
    if !turn.choices.is_empty() {
        return format!(
            "; {} chooses: {}",
            name(turn.striker),
            turn.choices.join(" or ")
        );
    }
    let hand = match turn.place {
        CueBallPlace::InHand { region } => format!(" with ball in hand {}", region.words()),
        CueBallPlace::AsItLies | CueBallPlace::Placed => String::new(),
    };
    let push_out = if turn.declare.push_out {
        " (push out allowed)"
    } else {
        ""
    };
    format!("; {} to shoot{hand}{push_out}", name(turn.striker))
}

/// The simulation's index of ball number `number`.
fn id_of(rec: &Recorder, number: u8) -> Option<usize> {
    rec.sim().numbers().iter().position(|&n| n == number)
}

/// The options the rules offer before the stroke, taken from the script's `--choice` in
/// order (else the first offered), each printed; returns their indices for the log. A
/// re-rack is refused (one rack a recording); balls an option puts back are set.
fn take_options(
    game: &mut dyn GameRules,
    rec: &mut Recorder,
    choices: &mut impl Iterator<Item = billiards_rules::Choice>,
) -> Result<Vec<usize>, String> {
    let mut made = Vec::new();
    loop {
        let turn = game.turn();
        if turn.choices.is_empty() {
            return Ok(made);
        }
        let index = match choices.next() {
            Some(choice) => turn
                .choices
                .iter()
                .position(|c| c == choice.label())
                .ok_or_else(|| {
                    format!(
                        "{:?} is not offered (offered: {})",
                        choice.label(),
                        turn.choices.join(", ")
                    )
                })?,
            None => 0,
        };
        let chooser = &game.players()[turn.striker.index()];
        println!(
            "  {chooser} chooses {:?} (offered: {})",
            turn.choices[index],
            turn.choices.join(", ")
        );
        match game.choose(index, &layout_of(rec.sim())).map_err(|e| e.0)? {
            Setup::Keep => {}
            Setup::Put { balls } => put(rec, &balls)?,
            Setup::Layout { .. } | Setup::Rack { .. } => {
                return Err("re-racks are not supported here (one rack a recording)".into());
            }
        }
        made.push(index);
    }
}

/// With the cue ball in hand and off the table, puts it where the rules accept it: the head
/// spot's respot first (pool's rule for a cue ball nobody places), else the first clear place
/// of [`billiards_rules::hand_place`]. A cue ball on the table is played where it lies.
fn put_in_hand(game: &dyn GameRules, rec: &mut Recorder, turn: &Turn) -> Result<(), String> {
    if !matches!(turn.place, CueBallPlace::InHand { .. }) {
        return Ok(());
    }
    let cue = id_of(rec, turn.cue_ball).ok_or("no cue ball")?;
    if rec.sim().ball(cue).motion.on_table() {
        return Ok(());
    }
    let others: Vec<(u8, Vec2)> = layout_of(rec.sim())
        .into_iter()
        .filter(|&(n, _)| n != turn.cue_ball)
        .collect();
    let spot = billiards_rules::cue_ball_spot(rec.sim(), cue);
    let at = billiards_rules::hand_place(game, &others, spot)
        .ok_or("no place the rules accept for the cue ball in hand")?;
    put(rec, &[(turn.cue_ball, at)])
}

/// Sets balls `balls` (number and place) on the table, as the rules put them back.
fn put(rec: &mut Recorder, balls: &[(u8, Vec2)]) -> Result<(), String> {
    for &(number, at) in balls {
        let id = id_of(rec, number).ok_or_else(|| format!("no ball {number}"))?;
        rec.place(id, at, Vec2::ZERO, Vec3::ZERO)
            .map_err(|e| format!("the {number} put back: {e}"))?;
    }
    Ok(())
}

/// Writes `value` as JSON to `path` through a temporary file and a rename, as recordings
/// are: never half-written.
pub(crate) fn save_json(
    path: &std::path::Path,
    value: &impl serde::Serialize,
) -> Result<(), String> {
    let json = serde_json::to_string_pretty(value).map_err(|e| e.to_string())?;
    let tmp = path.with_extension("json.tmp");
    std::fs::write(&tmp, json).map_err(|e| format!("{}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| format!("{}: {e}", path.display()))
}
