//! `simulate --game ID` without `--shot`: one game of any game of the catalog (a rack, a
//! frame, a carom game: [`GameEntry::one_game`]) between two computer players (`--computer
//! A,B`), played by the one match loop through the one game interface
//! ([`billiards_ai::any_match`]), each stroke printed; with `--out` the recording and its
//! [`StrokeLog`] beside it, which `verify` re-judges. Pool's games are played on `--table`
//! with `--rack-style`, the others on their own tables, under the solver's parameters the
//! tournaments use ([`GameEntry::params`]); every draw and the rack come from `--rack-seed`
//! (else `--seed`, else 0).

use crate::args::SimulateArgs;
use crate::setup::setup;
use billiards_ai::Player;
use billiards_ai::any_match::{Seating, play_match};
use billiards_ai::play::MAX_SHOTS;
use billiards_rules::StrokeLog;
use billiards_rules::catalog::{GameEntry, MatchSettings};

/// Parses `A,B` as two players (computer levels; greedy and one-ply at pool's games).
fn players(s: &str) -> Result<[Player; 2], String> {
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| format!("--computer {s:?}: expected A,B (e.g. hard,easy)"))?;
    let p = |x: &str| {
        x.trim()
            .parse::<Player>()
            .map_err(|e| format!("--computer: {e}"))
    };
    Ok([p(a)?, p(b)?])
}

/// Plays the game; an error for bad players or names, or a refused stroke.
pub(crate) fn simulate(entry: &GameEntry, a: &SimulateArgs) -> Result<(), String> {
    if !a.calls.is_empty() || !a.choices.is_empty() {
        return Err(format!(
            "a game of {} between computers takes no --call or --choice (they decide; give \
             --shot for a scripted game)",
            entry.label
        ));
    }
    let names: [String; 2] = match a.players.split_once(',') {
        Some((x, y)) => [x.trim().to_string(), y.trim().to_string()],
        None => return Err(format!("--players {:?}: expected NAME,NAME", a.players)),
    };
    let computers = players(a.computer.as_deref().unwrap_or("hard,hard"))?;
    let seed = a.rack_seed.or(a.seed).unwrap_or(0);
    let (table, params, ..) = setup(a)?;
    let settings = MatchSettings {
        style: a.rack_style,
        equipment: entry.pool_table.then_some((table, params.ball)),
        ..MatchSettings::new(names.clone(), entry.one_game, seed)
    };
    let mut game = entry.start(&settings).map_err(|e| e.0)?;
    for player in computers {
        player.plays(game.as_ref())?;
    }
    println!(
        "{}, seed {seed}: {} ({}) opens against {} ({})",
        entry.label, names[0], computers[0], names[1], computers[1]
    );
    let seating = Seating {
        record: a.out.is_some(),
        ..Seating::new(
            computers,
            (entry.params)(),
            seed,
            MAX_SHOTS * entry.one_game as usize,
        )
    };
    let run = play_match(game.as_mut(), &seating, &mut |line| println!("{line}"))?;
    let how = run
        .played
        .last()
        .map_or(String::new(), |p| p.reason.clone());
    println!("{} in {} strokes ({how})", run.score_line, run.strokes);
    if let (Some(path), Some((rec, log))) = (&a.out, run.recorded.first()) {
        rec.save(path).map_err(|e| e.to_string())?;
        let beside = StrokeLog::path_beside(path);
        crate::interface_game::save_json(&beside, log)?;
        println!("{} and {}", path.display(), beside.display());
    }
    Ok(())
}
