//! Plays racks between two players one after the other and prints each one (a quick look;
//! `billiards-cli tournament` is the full tool).
//!
//! ```sh
//! cargo run --release -p billiards-ai --example duel -- nine-ball hard easy 4 0
//! ```

use billiards_ai::Player;
use billiards_ai::play::play_rack;
use billiards_rules::Game;

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: duel nine-ball|ten-ball|eight-ball PLAYER PLAYER GAMES SEED";
    let [game, a, b, n, seed] = &args[..] else {
        return Err(usage.into());
    };
    let game = match game.as_str() {
        "nine-ball" => Game::NineBall,
        "ten-ball" => Game::TenBall,
        "eight-ball" => Game::EightBall,
        _ => return Err(usage.into()),
    };
    let players: [Player; 2] = [
        a.parse().map_err(|e| format!("{e}"))?,
        b.parse().map_err(|e| format!("{e}"))?,
    ];
    let n: u64 = n.parse().map_err(|_| usage)?;
    let seed: u64 = seed.parse().map_err(|_| usage)?;
    for k in 0..n {
        let r = play_rack(game, players, k, seed + k, (k % 2) as usize)?;
        let t = &r.players;
        println!(
            "game {k}: breaker {} winner {:?} ({}), {} shots, run-out {}; decisions {:.3}/{:.3} s mean, {:.3}/{:.3} max; potted {}/{}, fouls {}/{}",
            players[r.breaker],
            r.winner.map(|w| players[w].to_string()),
            r.reason,
            r.shots,
            r.break_and_run,
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
