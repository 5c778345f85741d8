//! Where the games are lost: plays 9-ball racks between two players exactly as
//! `billiards-cli tournament` does (the same racks, breakers and draws for the same seed)
//! and, for every game player A loses, says how A's last inning ended before the opponent
//! ran out: a missed pot (with the search's estimate of its success), a safety, a foul, a
//! dry break, or a push out; then totals how every inning of each player ended.
//!
//! ```sh
//! RAYON_NUM_THREADS=1 cargo run --release -p billiards-ai --example diagnose -- hard one-ply 40 1001
//! ```

use billiards_ai::noise::stream;
use billiards_ai::play::{execute, spot_balls, table_and_params_on};
use billiards_ai::{Decision, Plan, Player, ShotKind};
use billiards_physics::{Simulation, TableChoice};
use billiards_rules::{Game, GameState, Outcome, RackStyle, Seat};
use rand::Rng;
use std::collections::BTreeMap;

/// How an inning (a visit to the table) ended.
fn ending(kind: ShotKind, legal: bool, potted: bool, over: bool, won: bool) -> String {
    if over {
        return if won {
            "won".into()
        } else {
            "lost (foul on the 9 or the like)".into()
        };
    }
    if !legal {
        return "foul".into();
    }
    match kind {
        ShotKind::Break => "dry break".into(),
        ShotKind::Safety { .. } => "safety".into(),
        ShotKind::PushOut => "push out".into(),
        _ if potted => "potted, turn passed".into(),
        ShotKind::Pot { .. } => "missed pot".into(),
        ShotKind::Bank { .. } => "missed bank".into(),
        ShotKind::Kick { .. } => "missed kick".into(),
        ShotKind::Combo { .. } => "missed combo".into(),
    }
}

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: diagnose PLAYER PLAYER GAMES SEED";
    let [a, b, n, seed] = &args[..] else {
        return Err(usage.into());
    };
    let players: [Player; 2] = [
        a.parse().map_err(|e| format!("{e}"))?,
        b.parse().map_err(|e| format!("{e}"))?,
    ];
    let n: u64 = n.parse().map_err(|_| usage)?;
    let tseed: u64 = seed.parse().map_err(|_| usage)?;
    let game = Game::NineBall;
    let mut endings: [BTreeMap<String, usize>; 2] = Default::default();
    let mut lost_after: BTreeMap<String, usize> = BTreeMap::new();
    let mut missed_estimates: [Vec<f64>; 2] = Default::default();
    let mut wins = [0usize; 2];
    for g in 0..n {
        let seed: u64 = stream(tseed, 3, g).random();
        let breaker = (g % 2) as usize;
        let seat = |i: usize| if i == 0 { Seat::A } else { Seat::B };
        let (table, params) = table_and_params_on(TableChoice::default());
        let rack_seed: u64 = stream(seed, 0, 0).random();
        let balls = game.rack_styled(&table, &params.ball, rack_seed, RackStyle::default());
        let mut sim = Simulation::new(table, params, &balls).map_err(|e| e.to_string())?;
        sim.set_record_history(false);
        let mut state = GameState::new(game, seat(breaker));
        let mut shots = 0usize;
        // The last inning ending of each player in this game.
        let mut last_end: [Option<String>; 2] = [None, None];
        let mut line = String::new();
        while state.over.is_none() && shots < 400 {
            let next = state.next.clone();
            spot_balls(&mut sim, &next.spot)?;
            state.next.spot.clear();
            let who = next.shooter.index();
            let player = players[who];
            let decision = player
                .decide(&state, &sim, stream(seed, 1, shots as u64).random())
                .map_err(|e| e.to_string())?;
            let plan = match decision {
                Decision::Choose { choice, .. } => {
                    state.choose(choice).map_err(|e| e.to_string())?;
                    line.push_str(&format!(" {}:{choice:?}", "AB".as_bytes()[who] as char));
                    continue;
                }
                Decision::Shoot(plan) => plan,
            };
            let summary = execute(
                &mut sim,
                &plan,
                player.execution_noise(),
                stream(seed, 2, shots as u64).random(),
            )?;
            let verdict = state.play(&summary, plan.call).map_err(|e| e.to_string())?;
            shots += 1;
            let potted = summary.pocketed_object_balls().next().is_some();
            line.push_str(&shot_code(who, &plan, verdict.legal(), potted));
            if verdict.outcome != Outcome::Continues {
                let over = matches!(verdict.outcome, Outcome::GameOver { .. });
                let won = matches!(verdict.outcome, Outcome::GameOver { winner, .. } if winner == next.shooter);
                let e = ending(plan.kind, verdict.legal(), potted, over, won);
                if e == "missed pot" {
                    missed_estimates[who].push(plan.success);
                }
                *endings[who].entry(e.clone()).or_default() += 1;
                last_end[who] = Some(e);
            }
        }
        let winner = state.over.map(|(w, _)| w.index());
        if let Some(w) = winner {
            wins[w] += 1;
            if w == 1 {
                let e = last_end[0].clone().unwrap_or("never shot".into());
                *lost_after.entry(e).or_default() += 1;
            }
        }
        println!(
            "game {g}: breaker {} winner {:?}:{line}",
            "AB".as_bytes()[breaker] as char,
            winner.map(|w| "AB".as_bytes()[w] as char)
        );
    }
    print_totals(players, wins, n, &lost_after, &endings, &missed_estimates);
    Ok(())
}

/// One shot in a game's line, `a`/`b` (the shooter), the kind's letter, the estimated success
/// in percent and `F` (foul), `+` (potted) or `-`: compact enough to read a whole rack at once.
fn shot_code(who: usize, plan: &Plan, legal: bool, potted: bool) -> String {
    let kind = match plan.kind {
        ShotKind::Pot { .. } => "P",
        ShotKind::Bank { .. } => "B",
        ShotKind::Kick { .. } => "K",
        ShotKind::Combo { .. } => "C",
        ShotKind::Safety { .. } => "S",
        ShotKind::PushOut => "U",
        ShotKind::Break => "X",
    };
    format!(
        " {}{kind}{:.0}{}",
        "ab".as_bytes()[who] as char,
        plan.success * 100.0,
        if !legal {
            "F"
        } else if potted {
            "+"
        } else {
            "-"
        }
    )
}

/// The totals over all games: wins, how A's lost games began (its last inning), and how every
/// inning of each player ended, with the mean estimate of the pots it missed.
fn print_totals(
    players: [Player; 2],
    wins: [usize; 2],
    n: u64,
    lost_after: &BTreeMap<String, usize>,
    endings: &[BTreeMap<String, usize>; 2],
    missed_estimates: &[Vec<f64>; 2],
) {
    println!(
        "wins: {} {} {}, {} {}",
        players[0], wins[0], players[1], wins[1], n
    );
    println!(
        "{} lost after its last inning ended by: {lost_after:?}",
        players[0]
    );
    for p in 0..2 {
        let m = &missed_estimates[p];
        println!(
            "{}: innings ended by {:?}; missed pots' mean estimate {:.2}",
            players[p],
            endings[p],
            m.iter().sum::<f64>() / m.len().max(1) as f64
        );
    }
}
