//! `simulate --game` and `tournament --game` for the games the one game interface alone
//! plays (issue 50: three-cushion came in through [`billiards_rules::GameRules`] and nothing
//! else): a scripted rack of shots judged stroke by stroke, and matches between two
//! computer levels ([`billiards_ai::any_match`]) with their win rates.

use crate::args::{SimulateArgs, TournamentArgs};
use crate::setup::setup;
use crate::stats::wilson;
use billiards_ai::any_game::layout_of;
use billiards_ai::any_match::play_match;
use billiards_ai::{Level, Player};
use billiards_physics::recording::Recorder;
use billiards_physics::{Model, Params, SpinModel};
use billiards_rules::catalog::{GameEntry, MatchSettings, find};
use billiards_rules::{CueBallPlace, Declaration, StrokeRecord};

fn entry(id: &str) -> Result<&'static GameEntry, String> {
    find(id).map_err(|e| e.0)
}

/// Plays `a.shots` in order as the strokes of a game of `id` (each by the striker of the
/// turn, with their own cue ball), every stroke judged and printed; the recording written
/// to `--out` after each stroke.
pub(crate) fn simulate(id: &str, a: &SimulateArgs) -> Result<(), String> {
    let entry = entry(id)?;
    let (_, params, _, _, shots) = setup(a)?;
    if shots.is_empty() {
        return Err("no shots: give --shot ANGLE_DEG:SPEED".into());
    }
    let players: [String; 2] = match a.players.split_once(',') {
        Some((x, y)) => [x.trim().to_string(), y.trim().to_string()],
        None => return Err(format!("--players {:?}: expected NAME,NAME", a.players)),
    };
    let settings = MatchSettings::new(players, entry.default_length, a.rack_seed.unwrap_or(0));
    let mut game = entry.start(&settings).map_err(|e| e.0)?;
    let params = Params {
        ball: game.ball(),
        ..params
    };
    let balls = game.layout().map_err(|e| e.0)?;
    let mut rec = Recorder::new(game.table(), params, balls).map_err(|e| e.to_string())?;
    println!("{}: {}", entry.label, game.score_line());
    for (k, shot) in (1..).zip(shots) {
        let at = |e: &dyn std::fmt::Display| format!("stroke {k}: {e}");
        let turn = game.turn();
        if game.end().is_some() {
            println!("stroke {k} and later not played: the game is over");
            break;
        }
        if !turn.choices.is_empty() {
            // A script has no hand to choose with: the first option (play on).
            println!("  {} (the first option taken)", turn.choices[0]);
            game.choose(0, &layout_of(rec.sim())).map_err(|e| at(&e))?;
        }
        if let CueBallPlace::InHand { .. } = turn.place {
            return Err(at(&"a cue ball in hand needs a player: not in a script"));
        }
        let cue = rec
            .sim()
            .numbers()
            .iter()
            .position(|&n| n == turn.cue_ball)
            .ok_or_else(|| at(&"no cue ball"))?;
        let before = layout_of(rec.sim());
        let first = rec.sim().history().events().len();
        rec.strike(cue, shot).map_err(|e| at(&e))?;
        rec.run_to_rest().map_err(|e| at(&e))?;
        let sim = rec.sim();
        let judged = game
            .judge(&StrokeRecord {
                events: &sim.history().events()[first..],
                numbers: sim.numbers(),
                before: &before,
                after: &layout_of(sim),
                declared: Declaration::None,
            })
            .map_err(|e| at(&e))?;
        let who = &game.players()[judged.striker.index()];
        println!("stroke {k}: {who}: {}", judged.text);
        if let Some(path) = &a.out {
            rec.recording().save(path).map_err(|e| e.to_string())?;
        }
    }
    println!("{}", game.score_line());
    Ok(())
}

/// The results of a tournament of a game played through the interface.
#[derive(Debug, Default, serde::Serialize)]
struct Tally {
    games: u64,
    wins: [u64; 2],
    strokes: usize,
    fouls: [usize; 2],
    undecided: u64,
}

fn levels(a: &TournamentArgs) -> Result<[Level; 2], String> {
    let (x, y) = a
        .players
        .split_once(',')
        .ok_or_else(|| format!("--players {:?}: expected A,B (e.g. hard,easy)", a.players))?;
    let level = |s: &str| match s.trim().parse::<Player>() {
        Ok(Player::Computer(level)) => Ok(level),
        Ok(other) => Err(format!(
            "{other:?} plays pool only: give computer levels (easy, medium, hard, expert, perfect)"
        )),
        Err(e) => Err(e.to_string()),
    };
    Ok([level(x)?, level(y)?])
}

/// `tournament --game ID`: `a.games` games of the game's length (`--length`, else its usual
/// one) between the two levels, the first player opening the even games, each game's draws
/// from the seed and its index. Errors: `(message, whether the input is at fault)`.
pub(crate) fn tournament(id: &str, a: &TournamentArgs) -> Result<(), (String, bool)> {
    let input = |e: String| (e, true);
    let entry = entry(id).map_err(input)?;
    if a.shard.is_some() || !a.merge.is_empty() {
        return Err(input(format!(
            "--shard and --merge are not supported for {} yet: run the games in one process",
            entry.label
        )));
    }
    let levels = levels(a).map_err(input)?;
    let length = a.length.unwrap_or(entry.default_length);
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let mut t = Tally::default();
    for g in 0..a.games {
        // Player k sits in seat A of the even games, in seat B of the odd ones.
        let swap = g % 2 == 1;
        let seats = if swap { [levels[1], levels[0]] } else { levels };
        let names = seats.map(|l| l.name().to_owned());
        let seed = a.seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ g;
        let mut game = entry
            .start(&MatchSettings::new(names, length, seed))
            .map_err(|e| input(e.0))?;
        let run = play_match(game.as_mut(), &params, seats, seed, 5000, &mut |_| {})
            .map_err(|e| (format!("game {g}: {e}"), false))?;
        let player = |seat: usize| if swap { 1 - seat } else { seat };
        t.games += 1;
        match run.winner {
            Some(w) => t.wins[player(w.index())] += 1,
            None => t.undecided += 1,
        }
        for seat in 0..2 {
            t.fouls[player(seat)] += run.fouls[seat];
        }
        t.strokes += run.strokes;
        println!("game {g}: {}", run.score_line);
    }
    print!("{}", report(entry, &levels, length, a.seed, &t));
    if let Some(path) = &a.out {
        let json = serde_json::to_string_pretty(&t).map_err(|e| (e.to_string(), false))?;
        std::fs::write(path, json).map_err(|e| (format!("{}: {e}", path.display()), false))?;
    }
    Ok(())
}

fn report(entry: &GameEntry, levels: &[Level; 2], length: u32, seed: u64, t: &Tally) -> String {
    let mut out = format!(
        "{}, {} {length}, {} vs {}: {} games (seed {seed}), {} strokes\n",
        entry.label,
        entry.length_unit,
        levels[0].name(),
        levels[1].name(),
        t.games,
        t.strokes
    );
    out += "player    wins   win % 95 % interval  fouls\n";
    for (k, level) in levels.iter().enumerate() {
        let n = t.games as usize;
        let (lo, hi) = wilson(t.wins[k] as usize, n);
        out += &format!(
            "{:<8} {:>5} {:>6.1}% {:>5.1}-{:>5.1}%  {:>5}\n",
            level.name(),
            t.wins[k],
            100.0 * t.wins[k] as f64 / n.max(1) as f64,
            100.0 * lo,
            100.0 * hi,
            t.fouls[k]
        );
    }
    if t.undecided > 0 {
        out += &format!("{} games without a winner\n", t.undecided);
    }
    out
}
