//! Plays games (racks, frames, carom games) of any game between two players one after the
//! other and prints each one (a quick look; `billiards-cli tournament` is the full tool).
//!
//! ```sh
//! cargo run --release -p billiards-ai --example duel -- nine-ball hard easy 4 0
//! ```

use billiards_ai::Player;
use billiards_ai::match_record::{Between, play_between};
use billiards_ai::play::{MAX_SHOTS, table_and_params};
use billiards_rules::catalog::{MatchSettings, find};

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: duel GAME PLAYER PLAYER GAMES SEED (GAME: nine-ball, snooker, ...)";
    let [game, a, b, n, seed] = &args[..] else {
        return Err(usage.into());
    };
    let entry = find(game).map_err(|e| format!("{e}; {usage}"))?;
    let players: [Player; 2] = [
        a.parse().map_err(|e| format!("{e}"))?,
        b.parse().map_err(|e| format!("{e}"))?,
    ];
    let n: u64 = n.parse().map_err(|_| usage)?;
    let seed: u64 = seed.parse().map_err(|_| usage)?;
    for k in 0..n {
        let between = Between {
            players,
            params: (entry.params)(),
            seed: seed + k,
            max_strokes: MAX_SHOTS * entry.one_game as usize,
        };
        let start = |names| {
            let mut settings = MatchSettings::new(names, entry.one_game, seed + k);
            if entry.pool_table {
                settings.equipment = Some((table_and_params().0, between.params.ball));
            }
            entry.start(&settings).map_err(|e| e.0)
        };
        let (r, game) = play_between(k, (k % 2) as usize, &between, &start)?;
        let t = &r.players;
        println!(
            "game {k}: opener {} winner {:?} ({}; {}), {} strokes, run-out {}; decisions {:.3}/{:.3} s mean, {:.3}/{:.3} max; potted {}/{}, fouls {}/{}",
            players[r.opener],
            r.winner.map(|w| players[w].to_string()),
            r.reason,
            game.score_line(),
            r.strokes,
            r.run_outs.iter().sum::<usize>() > 0,
            t[0].decision_secs / t[0].decisions.max(1) as f64,
            t[1].decision_secs / t[1].decisions.max(1) as f64,
            t[0].max_decision_secs,
            t[1].max_decision_secs,
            t[0].pocketed,
            t[1].pocketed,
            t[0].fouls,
            t[1].fouls,
        );
    }
    Ok(())
}
