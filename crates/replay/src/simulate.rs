//! `simulate`: shots from a rack, a scene file or a game under its rules, recorded, with a
//! summary. The dispatcher of `simulate`: a game's script goes through the one game interface
//! (`interface_game.rs`), a game between computers to `computer_game.rs`; what they share
//! with it lives in `args.rs` and `setup.rs`.

pub use crate::args::SimulateArgs;
pub use crate::setup::ShotSummary;

use crate::flight;
use crate::setup::{respot_cue_ball, setup};
use billiards_physics::recording::Recorder;
use billiards_physics::*;
use indicatif::{ProgressBar, ProgressStyle};
use rand::{Rng, SeedableRng};

fn play(rec: &mut Recorder, shot: Shot) -> Result<ShotSummary, String> {
    respot_cue_ball(rec)?;
    let start = rec.sim().time();
    let first = rec.sim().history().events().len();
    let in_air = flight::airborne(rec.sim());
    rec.strike(0, shot).map_err(|e| e.to_string())?;
    rec.run_to_rest().map_err(|e| e.to_string())?;
    Ok(ShotSummary::of(
        shot,
        rec.sim(),
        (first, start, in_air),
        None,
    ))
}

pub(crate) fn simulate(a: SimulateArgs) -> Result<(), String> {
    if let Some(game) = a.game {
        let entry = billiards_rules::catalog::find(game.id()).map_err(|e| e.0)?;
        // Without a script the computers play the game.
        if a.shots.is_empty() && a.scene.is_none() {
            return crate::computer_game::simulate(entry, &a);
        }
        if a.computer.is_some() {
            return Err(
                "--computer plays the game itself: give --shot or --computer, not both".into(),
            );
        }
        return crate::interface_game::simulate(game.id(), &a);
    }
    let (table, params, balls, flights, shots) = setup(&a)?;
    let mut rec = Recorder::new(table, params, balls).map_err(|e| e.to_string())?;
    for f in &flights {
        // A scene's balls in the air, recorded as inputs so `verify` replays them.
        rec.launch(f.ball, f.height, f.vertical)
            .map_err(|e| format!("flight of ball {}: {e}", f.ball))?;
    }
    if let Some(n) = a.batch {
        return batch(rec, n, &a);
    }
    if shots.is_empty() {
        return Err(
            "no shots: give --shot ANGLE_DEG:SPEED (or a scene with shots), or --batch N".into(),
        );
    }
    let mut out = Vec::new();
    // Shots count from 1, as in the game and `export --shot K` (billiards_rules::shots).
    for (k, shot) in (1..).zip(shots) {
        let s = play(&mut rec, shot).map_err(|e| format!("shot {k}: {e}"))?;
        out.push(s);
        if let Some(path) = &a.out {
            // After every shot: a crash loses at most the shot in flight.
            rec.recording().save(path).map_err(|e| e.to_string())?;
        }
    }
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&out).map_err(|e| e.to_string())?
        );
    } else {
        for (k, s) in (1..).zip(&out) {
            println!(
                "shot {k}: {} events, pocketed {:?}, rest after {:.3} s",
                s.events, s.pocketed, s.time_to_rest
            );
            for f in &s.flight {
                println!("  {f}");
            }
        }
    }
    Ok(())
}

fn batch(start: Recorder, n: usize, a: &SimulateArgs) -> Result<(), String> {
    let threads = a
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(a.seed.unwrap_or(0));
    let shots: Vec<Shot> = (0..n)
        .map(|_| Shot {
            elevation: a.elevation,
            ..Shot::new(rng.random_range(-0.3..0.3), rng.random_range(4.0..11.0))
        })
        .collect();
    let bar = ProgressBar::new(n as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} shots {eta}").expect("template"),
    );
    let chunk = n.div_ceil(threads).max(1);
    let results: Vec<Result<ShotSummary, String>> = std::thread::scope(|s| {
        let handles: Vec<_> = shots
            .chunks(chunk)
            .map(|part| {
                let (bar, start) = (&bar, &start);
                s.spawn(move || {
                    part.iter()
                        .map(|&shot| {
                            let r = play(&mut start.clone(), shot);
                            bar.inc(1);
                            r
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("worker"))
            .collect()
    });
    bar.finish_and_clear();
    let ok: Vec<ShotSummary> = results.into_iter().collect::<Result<_, _>>()?;
    let best = ok
        .iter()
        .max_by_key(|s| s.pocketed.len())
        .ok_or("no shots")?;
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&serde_json::json!({ "shots": ok, "best": best }))
                .map_err(|e| e.to_string())?
        );
    } else {
        let events: usize = ok.iter().map(|s| s.events).sum();
        println!(
            "{n} shots, {events} events; best: angle {:.4} rad, speed {:.2} m/s pocketed {:?}",
            best.shot.angle, best.shot.speed, best.pocketed
        );
    }
    Ok(())
}
