//! 9-ball, WPA Rules of Play section 2: the lowest ball first (2.5, 6.2), then a pocket or a
//! rail (6.3); the 9 on a legal shot wins (2.5), on a foul or a push out it is spotted
//! (2.6); a push out right after a legal break (2.4); ball in hand anywhere after a foul
//! (2.7, 1.5); three fouls in a row lose the rack (2.8, 6.14).

use crate::foul::{BallOn, Foul, WinReason, common_fouls};
use crate::shot::ShotSummary;
use crate::state::{Game, GameState, Pending, RuleError};
use crate::turn::{Call, CallRule, Choice, CueBall, NextShot, Outcome, Seat, Verdict};

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
    // WPA 2.4: a push out needs no contact and no rail; a scratch is still a foul.
    let mut fouls = common_fouls(shot, BallOn::Lowest(lowest), &[lowest], !push_out);
    if break_shot {
        // WPA 2.3: the break's rail rule (four object balls) replaces 6.3's.
        fouls.retain(|f| *f != Foul::NoRail);
        let pocketed = shot.pocketed_object_balls().next().is_some();
        let to_rail = shot.object_balls_to_rail();
        if shot.first_contact.is_some() && !pocketed && to_rail < 4 {
            fouls.push(Foul::IllegalBreak { to_rail });
        }
    }
    let nine_down = shot.pocket_of(9).is_some();
    let any_down = shot.pocketed_object_balls().next().is_some();
    state.take_off(shot);
    let foul = !fouls.is_empty();
    let mut spot = Vec::new();
    // WPA 2.6: the 9 pocketed on a foul or a push out is spotted; no other ball is.
    if nine_down && (foul || push_out) {
        state.put_back(9);
        spot.push(9);
    }
    let me = shooter.index();
    let (outcome, next) = if foul {
        state.fouls[me] += 1;
        if state.fouls[me] >= 3 {
            // WPA 2.8 with 6.14: the third foul in a row loses the rack.
            let over = Outcome::GameOver {
                winner: shooter.other(),
                reason: WinReason::ThreeFouls,
            };
            (over, None)
        } else {
            // WPA 2.7, 1.5: ball in hand anywhere for the opponent.
            let mut next = normal_next(state, shooter.other(), CueBall::InHandAnywhere);
            next.spot = spot;
            (Outcome::Passes, Some(next))
        }
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
            state.pending = Some(Pending::PushOut { pusher: shooter });
            let mut next = normal_next(state, shooter.other(), CueBall::AsItLies);
            next.choices = vec![Choice::ShootFromHere, Choice::PassBack];
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
