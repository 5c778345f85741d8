//! 10-ball, WPA Rules of Play section 9 (the ten ball rules in force from 1 January 2009, in
//! the numbering of the edition the crate follows): 9-ball's rotation, the lowest ball first
//! (6.2), with every shot after the break called, one ball and one pocket (9.5).
//!
//! - 9.2 the rack ([`crate::racks::ten_ball`]); 9.3 the legal break: in hand behind the head
//!   string, the 1 first (6.2), a ball pocketed or four object balls to a rail; the 10 made
//!   on the break is spotted and the breaker continues (9, 9.9); a foul on the break gives
//!   ball in hand (9.10);
//! - 9.4 push out on the shot right after a break without a foul, the 10 made on it spotted;
//! - 9.5 called shots: the called ball in the called pocket keeps the shooter at the table,
//!   other balls made with it stay down (the 10 is spotted); the called 10 made on a legal
//!   shot wins, at any time (a combination: the lowest ball first, the 10 called);
//! - 9.6 a called safety: the turn passes;
//! - 9.7 a ball made on a called safety, or on a shot that did not pocket the called ball in
//!   the called pocket: no foul, the turn passes, the balls stay down but the 10, which is
//!   spotted, and the incoming player shoots or hands the table back;
//! - 9.10 fouls (6.1 to 6.3): ball in hand anywhere, balls made stay down, the 10 spotted;
//! - 9.11 with 6.14: the third foul in a row loses the rack.
//! - 6.5 (a ball driven off the table is a foul, "whether that ball is spotted depends on
//!   the rules of the game") with 9.9: as in 9-ball (2.6), only the 10 is spotted, the other
//!   object balls driven off the table stay off. The clause of 9.9 that names a ball driven
//!   off the table could not be confirmed from the text at hand; 10-ball follows 9-ball here.

use crate::foul::WinReason;
use crate::rotation;
use crate::shot::ShotSummary;
use crate::state::{Game, GameState, Pending, RuleError};
use crate::turn::{Call, CallRule, Choice, CueBall, NextShot, Outcome, Seat, Verdict};

/// The 10: the ball that wins when called and made.
const TEN: u8 = 10;

/// The next shot of an ordinary turn: hit the lowest ball first, call a ball and a pocket.
pub(crate) fn normal_next(state: &GameState, shooter: Seat, cue_ball: CueBall) -> NextShot {
    NextShot::plain(
        shooter,
        cue_ball,
        state.on_table.first().copied().into_iter().collect(),
        CallRule::BallAndPocket,
        state.fouls[shooter.index()],
    )
}

/// Whether the call is a push out; refuses a call the shot does not allow.
fn check_call(state: &GameState, call: Call) -> Result<bool, RuleError> {
    match call {
        Call::PushOut if state.next.push_out_allowed => Ok(true),
        Call::PushOut => Err(RuleError::PushOutNotAllowed),
        // WPA 9: "no ball may be called" on the break.
        Call::Safety | Call::Ball { .. } if state.next.break_shot => {
            Err(RuleError::CallNotUsed(Game::TenBall, "call on the break"))
        }
        Call::Ball { ball, .. } if !state.on_table.contains(&ball) => {
            Err(RuleError::BallNotOnTable(ball))
        }
        _ => Ok(false),
    }
}

/// Judges a 10-ball shot (see [`GameState::play`]).
pub(crate) fn play(
    state: &mut GameState,
    shot: &ShotSummary,
    call: Call,
) -> Result<Verdict, RuleError> {
    let shooter = state.next.shooter;
    let break_shot = state.next.break_shot;
    let push_out = check_call(state, call)?;
    // The 10 is on the table until the game ends, so there is a lowest ball.
    let lowest = state.on_table.first().copied().unwrap_or(TEN);
    // WPA 9.4: a push out suspends 6.2 and 6.3; WPA 9.3: the break's rail rule.
    let fouls = rotation::fouls(state, shot, lowest, push_out);
    let foul = !fouls.is_empty();
    // WPA 9.5: the called ball in the called pocket on a legal shot.
    let made = match call {
        Call::Ball { ball, pocket } if !foul => shot.pocket_of(ball) == Some(pocket),
        _ => false,
    };
    let ten_wins = made && matches!(call, Call::Ball { ball: TEN, .. });
    // WPA 9.9 with 6.5: the 10 driven off the table is spotted like the 10 pocketed illegally.
    let ten_down = shot.pocket_of(TEN).is_some() || shot.is_off_table(TEN);
    let any_down = shot.pocketed_object_balls().next().is_some();
    state.take_off(shot);
    let mut spot = Vec::new();
    // WPA 9.9: the 10 made in any other way (the break, a push out, a foul, uncalled, a
    // safety, beside another called ball) is spotted; no other ball is.
    if ten_down && !ten_wins {
        state.put_back(TEN);
        spot.push(TEN);
    }
    let me = shooter.index();
    let (outcome, next) = if foul {
        // WPA 9.10, 9.11: ball in hand anywhere, or the third foul loses.
        rotation::after_foul(state, shooter, spot, normal_next)
    } else {
        state.fouls[me] = 0;
        let (outcome, mut next) = legal(state, shooter, push_out, made, any_down);
        if ten_wins {
            // WPA 9.5: the called 10 legally pocketed wins the rack.
            let over = Outcome::GameOver {
                winner: shooter,
                reason: WinReason::TenPocketed,
            };
            (over, None)
        } else {
            // WPA 9.4: the shot after a legal break may be a push out.
            next.push_out_allowed = break_shot;
            next.spot = spot;
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

/// The turn after a legal shot that did not win: who shoots, and what they may choose.
fn legal(
    state: &mut GameState,
    shooter: Seat,
    push_out: bool,
    made: bool,
    any_down: bool,
) -> (Outcome, NextShot) {
    if push_out {
        // WPA 9.4: the opponent shoots from there or passes the shot back.
        return (
            Outcome::Passes,
            rotation::after_push_out(state, shooter, normal_next),
        );
    }
    // `state.next` is still the shot just played: the dispatcher replaces it afterwards.
    if state.next.break_shot {
        // WPA 9.3, 9: a ball made on a legal break (the 10 too, spotted) keeps the breaker
        // at the table.
        let who = if any_down { shooter } else { shooter.other() };
        let outcome = if any_down {
            Outcome::Continues
        } else {
            Outcome::Passes
        };
        return (outcome, normal_next(state, who, CueBall::AsItLies));
    }
    if made {
        // WPA 9.5, 9.8: the called ball made: the shooter continues.
        return (
            Outcome::Continues,
            normal_next(state, shooter, CueBall::AsItLies),
        );
    }
    let mut next = normal_next(state, shooter.other(), CueBall::AsItLies);
    if any_down {
        // WPA 9.7: a ball made on a safety or without the called ball in the called pocket:
        // the incoming player takes the table as it lies or hands it back.
        state.pending = Some(Pending::HandBack { shooter });
        next.choices = vec![Choice::ShootFromHere, Choice::PassBack];
    }
    (Outcome::Passes, next)
}
