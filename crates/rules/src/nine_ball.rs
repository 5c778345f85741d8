//! 9-ball, WPA Rules of Play section 2: the lowest ball first (2.5, 6.2), then a pocket or a
//! rail (6.3); the 9 on a legal shot wins (2.5), on a foul or a push out it is spotted
//! (2.6), and so is the 9 driven off the table while the other object balls driven off it
//! stay off (2.6 with 6.5: "only the 9 is ever spotted"); a push out right after a legal break (2.4); ball in hand anywhere after a foul
//! (2.7, 1.5); three fouls in a row lose the rack (2.8, 6.14).

use crate::foul::WinReason;
use crate::rotation;
use crate::shot::ShotSummary;
use crate::state::{Game, GameState, RuleError};
use crate::turn::{Call, CallRule, CueBall, NextShot, Outcome, Seat, Verdict};

/// The next shot of an ordinary turn: hit the lowest ball first, no call.
pub(crate) fn normal_next(state: &GameState, shooter: Seat, cue_ball: CueBall) -> NextShot {
    NextShot::plain(
        shooter,
        cue_ball,
        state.on_table.first().copied().into_iter().collect(),
        CallRule::NotUsed,
        state.fouls[shooter.index()],
    )
}

/// Judges a 9-ball shot (see [`GameState::play`]).
pub(crate) fn play(
    state: &mut GameState,
    shot: &ShotSummary,
    call: Call,
) -> Result<Verdict, RuleError> {
    let shooter = state.next.shooter;
    let break_shot = state.next.break_shot;
    let push_out = match call {
        Call::None => false,
        Call::PushOut if state.next.push_out_allowed => true,
        Call::PushOut => return Err(RuleError::PushOutNotAllowed),
        // WPA 2: "players are not required to call any shot".
        Call::Safety | Call::Ball { .. } => {
            return Err(RuleError::CallNotUsed(Game::NineBall, "called shots"));
        }
    };
    // The 9 is on the table until the game ends, so there is a lowest ball.
    let lowest = state.on_table.first().copied().unwrap_or(9);
    // WPA 2.4: a push out needs no contact and no rail; WPA 2.3: the break's rail rule.
    let fouls = rotation::fouls(state, shot, lowest, push_out);
    let nine_down = shot.pocket_of(9).is_some();
    // WPA 6.5 with 2.6: the 9 driven off the table is spotted (always on a foul, 6.5).
    let nine_off = shot.is_off_table(9);
    let any_down = shot.pocketed_object_balls().next().is_some();
    state.take_off(shot);
    let foul = !fouls.is_empty();
    let mut spot = Vec::new();
    // WPA 2.6: the 9 pocketed on a foul or a push out is spotted; no other ball is.
    if (nine_down && (foul || push_out)) || nine_off {
        state.put_back(9);
        spot.push(9);
    }
    let me = shooter.index();
    let (outcome, next) = if foul {
        // WPA 2.7, 2.8: ball in hand anywhere, or the third foul loses.
        rotation::after_foul(state, shooter, spot, normal_next)
    } else {
        state.fouls[me] = 0;
        if nine_down && !push_out {
            // WPA 2.5: the 9 on any legal shot wins (a combination, the break).
            let over = Outcome::GameOver {
                winner: shooter,
                reason: WinReason::NinePocketed,
            };
            (over, None)
        } else if push_out {
            // WPA 2.4: the opponent shoots from there or passes the shot back.
            let mut next = rotation::after_push_out(state, shooter, normal_next);
            next.spot = spot;
            (Outcome::Passes, Some(next))
        } else {
            // WPA 2.5: a ball pocketed on a legal shot keeps the shooter at the table.
            let (outcome, who) = if any_down {
                (Outcome::Continues, shooter)
            } else {
                (Outcome::Passes, shooter.other())
            };
            let mut next = normal_next(state, who, CueBall::AsItLies);
            // WPA 2.4: the shot after a legal break may be a push out.
            next.push_out_allowed = break_shot;
            (outcome, Some(next))
        }
    };
    Ok(Verdict {
        shooter,
        break_shot,
        push_out,
        fouls,
        outcome,
        assigned: None,
        next,
    })
}
