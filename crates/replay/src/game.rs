//! `simulate --game`: a rack played under the rules with scripted shots, each verdict
//! printed, and the rules' log ([`GameLog`]) written beside the recording; `verify` checks it.

use crate::args::SimulateArgs;
use crate::setup::{ShotSummary, respot_cue_ball, setup};
use billiards_physics::recording::Recorder;
use billiards_physics::{Vec2, Vec3};
use billiards_rules::{
    Call, Choice, CueBall, Game, GameLog, GameState, LoggedShot, NextShot, Outcome, Seat, Verdict,
    cue_ball_spot, object_ball_spot, pocket_name, summarise,
};
use std::path::Path;

/// Plays `a.shots` as a rack of `game`; see [`SimulateArgs::game`].
pub(crate) fn play_game(a: &SimulateArgs, game: Game) -> Result<(), String> {
    let (table, params, _, _, shots) = setup(a)?;
    if shots.is_empty() {
        return Err("no shots: give --shot ANGLE_DEG:SPEED".into());
    }
    let rack_seed = a.rack_seed.or(a.seed).unwrap_or(0);
    let balls = game.rack_styled(&table, &params.ball, rack_seed, a.rack_style);
    let players: [String; 2] = match a.players.split_once(',') {
        Some((x, y)) => [x.trim().to_string(), y.trim().to_string()],
        None => return Err(format!("--players {:?}: expected NAME,NAME", a.players)),
    };
    let name = |s: Seat| players[s.index()].clone();
    let mut rec = Recorder::new(table, params, balls).map_err(|e| e.to_string())?;
    let mut state = GameState::new(game, Seat::A);
    let mut log = GameLog::new(game, rack_seed, players.clone(), Seat::A);
    let mut choices = a.choices.iter().copied();
    let mut out = Vec::new();
    println!("{game:?}, rack seed {rack_seed}: {} breaks", name(Seat::A));
    for (k, shot) in (1..).zip(shots) {
        if state.over.is_some() {
            println!("shot {k} and later not played: the game is over");
            break;
        }
        let at = |e: &dyn std::fmt::Display| format!("shot {k}: {e}");
        let mut made = Vec::new();
        while !state.next.choices.is_empty() {
            let offered = state.next.choices.clone();
            let choice = choices.next().unwrap_or(offered[0]);
            if matches!(
                choice,
                Choice::RerackAndBreak | Choice::RerackOpponentBreaks
            ) {
                return Err(at(
                    &"re-racks are not supported here (one rack a recording)",
                ));
            }
            let chooser = state.next.shooter;
            state.choose(choice).map_err(|e| at(&e))?;
            println!(
                "  {} chooses {choice:?} (offered {offered:?})",
                name(chooser)
            );
            made.push(choice);
        }
        prepare(&mut rec, &state.next).map_err(|e| at(&e))?;
        let call = a
            .calls
            .iter()
            .find(|(s, _)| *s == k)
            .map_or(Call::None, |&(_, c)| c);
        let (start, first) = (rec.sim().time(), rec.sim().history().events().len());
        let in_air = crate::flight::airborne(rec.sim());
        rec.strike(0, shot).map_err(|e| at(&e))?;
        rec.run_to_rest().map_err(|e| at(&e))?;
        let sim = rec.sim();
        let events = &sim.history().events()[first..];
        let summary = summarise(events, sim.numbers());
        let verdict = state.play(&summary, call).map_err(|e| at(&e))?;
        println!("shot {k}: {}", describe(&verdict, &summary, &name));
        out.push(ShotSummary {
            shot,
            events: events.len(),
            pocketed: summary.pocketed_object_balls().collect(),
            time_to_rest: sim.time() - start,
            flight: crate::flight::flight_events(events, sim.numbers(), start, in_air),
            verdict: Some(verdict.clone()),
        });
        log.shots.push(LoggedShot {
            choices: made,
            call,
            verdict,
        });
        if let Some(path) = &a.out {
            rec.recording().save(path).map_err(|e| e.to_string())?;
            save_log(path, &log)?;
        }
    }
    if a.json {
        let json = serde_json::to_string_pretty(&out).map_err(|e| e.to_string())?;
        println!("{json}");
    }
    Ok(())
}

/// Puts the table as `next` says: spotted balls on the foot string (WPA 1.4); the cue ball
/// in hand on the head string by the respot rule (a script has no hand to place it with);
/// the break's cue ball stays where the rack put it (the head spot).
fn prepare(rec: &mut Recorder, next: &NextShot) -> Result<(), String> {
    for &n in &next.spot {
        let id = rec
            .sim()
            .numbers()
            .iter()
            .position(|&m| m == n)
            .ok_or(format!("no ball {n}"))?;
        let p = object_ball_spot(rec.sim(), id).ok_or("no free place on the long string")?;
        rec.place(id, p, Vec2::ZERO, Vec3::ZERO)
            .map_err(|e| e.to_string())?;
    }
    let cue_on_table = rec.sim().ball(0).motion.on_table();
    match next.cue_ball {
        CueBall::AsItLies => Ok(()),
        CueBall::Respot => respot_cue_ball(rec),
        CueBall::InHandAnywhere | CueBall::InHandBehindHeadString
            if next.break_shot && cue_on_table =>
        {
            Ok(())
        }
        CueBall::InHandAnywhere | CueBall::InHandBehindHeadString => {
            let spot = cue_ball_spot(rec.sim(), 0).ok_or("no free place on the head string")?;
            rec.place(0, spot, Vec2::ZERO, Vec3::ZERO)
                .map_err(|e| e.to_string())
        }
    }
}

/// One line: who shot, legal or the fouls, what dropped, who is next or who won.
fn describe(
    v: &Verdict,
    s: &billiards_rules::ShotSummary,
    name: &dyn Fn(Seat) -> String,
) -> String {
    let kind = if v.break_shot {
        " (break)"
    } else if v.push_out {
        " (push out)"
    } else {
        ""
    };
    let mut line = format!("{}{kind}: {}", name(v.shooter), v.reason());
    let down: Vec<String> = s
        .pocketed
        .iter()
        .map(|&(b, p)| match b {
            0 => format!("cue ball ({})", pocket_name(p)),
            _ => format!("{b} ({})", pocket_name(p)),
        })
        .collect();
    if !down.is_empty() {
        line += &format!("; pocketed {}", down.join(", "));
    }
    if let Some(g) = v.assigned {
        line += &format!("; {} takes {}", name(v.shooter), g.name());
    }
    match (v.outcome, &v.next) {
        (Outcome::GameOver { winner, reason }, _) => {
            line += &format!("; game over: {} wins ({reason})", name(winner));
        }
        (_, Some(next)) => {
            let who = name(next.shooter);
            if !next.choices.is_empty() {
                line += &format!("; {who} chooses: {:?}", next.choices);
            } else if v.outcome == Outcome::Continues {
                line += &format!("; {who} continues");
            } else {
                line += &format!("; {who} to shoot");
            }
            line += match next.cue_ball {
                CueBall::InHandAnywhere => " with ball in hand anywhere",
                CueBall::InHandBehindHeadString => " with ball in hand behind the head string",
                CueBall::Respot => ", the cue ball respotted",
                CueBall::AsItLies => "",
            };
            for b in &next.spot {
                line += &format!("; the {b} is spotted");
            }
            if next.push_out_allowed {
                line += " (push out allowed)";
            }
        }
        (_, None) => {}
    }
    line
}

fn save_log(recording: &Path, log: &GameLog) -> Result<(), String> {
    let path = GameLog::path_beside(recording);
    let json = serde_json::to_string_pretty(log).map_err(|e| e.to_string())?;
    // Through a temporary file and a rename, as recordings are: never half-written.
    let tmp = path.with_extension("json.tmp");
    std::fs::write(&tmp, json).map_err(|e| format!("{}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, &path).map_err(|e| format!("{}: {e}", path.display()))
}
