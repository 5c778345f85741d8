//! What the rotation games (9-ball, WPA section 2; 10-ball, section 9) share: the lowest
//! ball first and a rail after contact, the break's four-ball rail rule in place of the
//! rail rule, the push out, and after a foul ball in hand anywhere or, on the third foul in
//! a row, the rack lost. Each game's own file keeps what differs (the called shot, which
//! ball wins and when it is spotted).

use crate::foul::{BallOn, Foul, WinReason, common_fouls};
use crate::shot::ShotSummary;
use crate::state::{GameState, Pending};
use crate::turn::{Choice, CueBall, NextShot, Outcome, Seat};

/// How a game builds its ordinary next shot.
pub(crate) type NormalNext = fn(&GameState, Seat, CueBall) -> NextShot;

/// The fouls of a shot on `lowest`: the lowest ball first and a rail after contact (6.2,
/// 6.3; a push out suspends both, WPA 2.4 and 9.4, a scratch is still a foul); on the
/// break, four object balls to a rail or a ball pocketed in place of 6.3 (WPA 2.3, 9.3).
pub(crate) fn fouls(
    state: &GameState,
    shot: &ShotSummary,
    lowest: u8,
    push_out: bool,
) -> Vec<Foul> {
    let mut fouls = common_fouls(shot, BallOn::Lowest(lowest), &[lowest], !push_out);
    if state.next.break_shot {
        fouls.retain(|f| *f != Foul::NoRail);
        let pocketed = shot.pocketed_object_balls().next().is_some();
        let to_rail = shot.object_balls_to_rail();
        if shot.first_contact.is_some() && !pocketed && to_rail < 4 {
            fouls.push(Foul::IllegalBreak { to_rail });
        }
    }
    fouls
}

/// After a foul by `shooter`: the third in a row loses the rack (WPA 2.8, 9.11 with
/// 6.14); else the opponent has ball in hand anywhere (2.7, 9.10, 1.5), the balls of
/// `spot` spotted first.
pub(crate) fn after_foul(
    state: &mut GameState,
    shooter: Seat,
    spot: Vec<u8>,
    normal_next: NormalNext,
) -> (Outcome, Option<NextShot>) {
    let me = shooter.index();
    state.fouls[me] += 1;
    if state.fouls[me] >= 3 {
        let over = Outcome::GameOver {
            winner: shooter.other(),
            reason: WinReason::ThreeFouls,
        };
        return (over, None);
    }
    let mut next = normal_next(state, shooter.other(), CueBall::InHandAnywhere);
    next.spot = spot;
    (Outcome::Passes, Some(next))
}

/// After a legal push out by `pusher`: the opponent shoots from there or passes the shot
/// back (WPA 2.4, 9.4).
pub(crate) fn after_push_out(
    state: &mut GameState,
    pusher: Seat,
    normal_next: NormalNext,
) -> NextShot {
    state.pending = Some(Pending::PushOut { pusher });
    let mut next = normal_next(state, pusher.other(), CueBall::AsItLies);
    next.choices = vec![Choice::ShootFromHere, Choice::PassBack];
    next
}
