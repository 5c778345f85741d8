//! 8-ball, WPA Rules of Play section 3: the break and its options (3.3), the open table and
//! the groups (3.5), called shots (1.6, 3.6), ball in hand after a foul (3.7, 1.5) and the
//! ways to lose the rack with the 8 (3.8). A ball driven off the table is a foul (6.1 the cue
//! ball, 6.5 an object ball: "whether that ball is spotted depends on the rules of the
//! game"); in 8-ball the jumped object balls are spotted (WPA 1.4 spotting on the long
//! string) and the 8 driven off the table loses the rack (3.8) — as games.md ("Balls off
//! the table") says; the number of 8-ball's own jumped-ball clause could not be confirmed
//! from the text at hand, so none is cited. There is no three-foul rule (6.14: "some games
//! such as eight ball do not include this rule").

use crate::foul::{BallOn, Foul, Group, WinReason, common_fouls};
use crate::shot::ShotSummary;
use crate::state::{Game, GameState, Pending, RuleError};
use crate::turn::{Call, CallRule, Choice, CueBall, NextShot, Outcome, Seat, Verdict};

/// What `shooter` must hit first: open table, own group, or the 8 (WPA 3.5, 3.6).
fn ball_on(state: &GameState, shooter: Seat) -> (BallOn, Vec<u8>) {
    match state.group(shooter) {
        None => {
            let balls = state.on_table.iter().copied().filter(|&b| b != 8).collect();
            (BallOn::AnyButEight, balls)
        }
        Some(g) => {
            let balls: Vec<u8> = state
                .on_table
                .iter()
                .copied()
                .filter(|&b| g.contains(b))
                .collect();
            if balls.is_empty() {
                (BallOn::Eight, vec![8])
            } else {
                (BallOn::Group(g), balls)
            }
        }
    }
}

/// The next shot of an ordinary turn of `shooter`.
pub(crate) fn normal_next(state: &GameState, shooter: Seat, cue_ball: CueBall) -> NextShot {
    let (on, legal_first) = ball_on(state, shooter);
    // WPA 1.6: obvious shots need no call; the 8 is always called (3.8).
    let call = if on == BallOn::Eight {
        CallRule::EightPocket
    } else {
        CallRule::Optional
    };
    NextShot::plain(
        shooter,
        cue_ball,
        legal_first,
        call,
        state.fouls[shooter.index()],
    )
}

/// Judges an 8-ball shot (see [`GameState::play`]).
pub(crate) fn play(
    state: &mut GameState,
    shot: &ShotSummary,
    call: Call,
) -> Result<Verdict, RuleError> {
    if state.next.break_shot {
        return break_shot(state, shot, call);
    }
    let shooter = state.next.shooter;
    let (on, allowed) = ball_on(state, shooter);
    match call {
        Call::PushOut => return Err(RuleError::CallNotUsed(Game::EightBall, "push out")),
        Call::Ball { ball, .. } if !state.on_table.contains(&ball) => {
            return Err(RuleError::BallNotOnTable(ball));
        }
        Call::Ball { ball, .. } if !allowed.contains(&ball) => {
            let why = match on {
                BallOn::Eight => "the shooter is on the 8 (WPA 3.6)",
                _ if ball == 8 => "the 8 is on only once the group is cleared (WPA 3.6)",
                _ => "it is not in the shooter's group (WPA 3.6)",
            };
            return Err(RuleError::IllegalCall { ball, why });
        }
        _ => {}
    }
    let fouls = common_fouls(shot, on, &allowed, true);
    let foul = !fouls.is_empty();
    let eight = shot.pocket_of(8);
    state.take_off(shot);
    let spot = spot_jumped(state, shot);
    let me = shooter.index();
    state.fouls[me] = if foul { state.fouls[me] + 1 } else { 0 };
    let verdict = |fouls, outcome, assigned, next| Verdict {
        shooter,
        break_shot: false,
        push_out: false,
        fouls,
        outcome,
        assigned,
        next,
    };
    if shot.is_off_table(8) {
        // WPA 3.8: the 8 driven off the table loses the rack, whatever else happened.
        let outcome = Outcome::GameOver {
            winner: shooter.other(),
            reason: WinReason::EightOffTable,
        };
        return Ok(verdict(fouls, outcome, None, None));
    }
    if let Some(went) = eight {
        // WPA 3.6 wins; 3.8 loses: early, on a foul, in another pocket than the called one.
        let lost = match call {
            _ if on != BallOn::Eight => Some(WinReason::EightEarly),
            _ if foul => Some(WinReason::EightOnFoul),
            Call::Ball { pocket, .. } if pocket == went => None,
            Call::Ball { pocket, .. } => Some(WinReason::EightWrongPocket {
                called: Some(pocket),
                went,
            }),
            _ => Some(WinReason::EightWrongPocket { called: None, went }),
        };
        let outcome = match lost {
            None => Outcome::GameOver {
                winner: shooter,
                reason: WinReason::EightPocketed,
            },
            Some(reason) => Outcome::GameOver {
                winner: shooter.other(),
                reason,
            },
        };
        return Ok(verdict(fouls, outcome, None, None));
    }
    if foul {
        // WPA 3.7, 1.5: ball in hand anywhere; balls pocketed stay down, jumped ones are
        // spotted (6.5).
        let mut next = normal_next(state, shooter.other(), CueBall::InHandAnywhere);
        next.spot = spot;
        return Ok(verdict(fouls, Outcome::Passes, None, Some(next)));
    }
    // The ball that counts: the called ball in the called pocket; without a call, any ball
    // the shooter could call (an obvious shot, WPA 1.6); none on a called safety.
    let scored = match call {
        Call::Safety | Call::PushOut => None,
        Call::Ball { ball, pocket } => (shot.pocket_of(ball) == Some(pocket)).then_some(ball),
        Call::None => shot.pocketed_object_balls().find(|b| allowed.contains(b)),
    };
    let mut assigned = None;
    if state.group_a.is_none()
        && let Some(g) = scored.and_then(Group::of)
    {
        // WPA 3.5: the first legally pocketed called ball gives its group.
        state.group_a = Some(if shooter == Seat::A { g } else { g.other() });
        assigned = Some(g);
    }
    let (outcome, who) = match scored {
        Some(_) => (Outcome::Continues, shooter),
        None => (Outcome::Passes, shooter.other()),
    };
    let next = normal_next(state, who, CueBall::AsItLies);
    Ok(verdict(fouls, outcome, assigned, Some(next)))
}

/// The break (WPA 3.3): legal when a ball is pocketed or four object balls reach a rail.
fn break_shot(state: &mut GameState, shot: &ShotSummary, call: Call) -> Result<Verdict, RuleError> {
    if call != Call::None {
        return Err(RuleError::CallNotUsed(Game::EightBall, "call on the break"));
    }
    let breaker = state.next.shooter;
    let pocketed = shot.pocketed_object_balls().next().is_some();
    let to_rail = shot.object_balls_to_rail();
    let legal = pocketed || to_rail >= 4;
    // A ball driven off the table on the break (WPA 6.1, 6.5) is a foul the break's rule
    // treats as the scratch: the opponent's options are those after a scratch (3.3). The
    // 2008 BCA text gives the same option for a jumped object ball on the break.
    let scratched = shot.scratch() || !shot.off_table.is_empty();
    let mut fouls = Vec::new();
    if shot.scratch() {
        fouls.push(Foul::Scratch);
    }
    fouls.extend(shot.off_table.iter().map(|&ball| Foul::OffTable { ball }));
    if !legal {
        fouls.push(Foul::IllegalBreak { to_rail });
    }
    let eight = shot.pocket_of(8).is_some();
    state.take_off(shot);
    let spot = spot_jumped(state, shot);
    let me = breaker.index();
    state.fouls[me] = if fouls.is_empty() {
        0
    } else {
        state.fouls[me] + 1
    };
    let verdict = |fouls, outcome, next| Verdict {
        shooter: breaker,
        break_shot: true,
        push_out: false,
        fouls,
        outcome,
        assigned: None,
        next,
    };
    if shot.is_off_table(8) {
        // WPA 3.8: the 8 driven off the table loses the rack, on the break too.
        let outcome = Outcome::GameOver {
            winner: breaker.other(),
            reason: WinReason::EightOffTable,
        };
        return Ok(verdict(fouls, outcome, None));
    }
    // The table stays open after the break, whatever dropped (WPA 3.5).
    let (outcome, mut next) = if eight {
        // WPA 3.3: spot the 8 or re-rack; the breaker chooses, or after a foul the opponent.
        state.pending = Some(Pending::EightOnBreak {
            breaker,
            foul: scratched,
        });
        let (outcome, chooser) = if scratched {
            (Outcome::Passes, breaker.other())
        } else {
            (Outcome::Continues, breaker)
        };
        let mut next = normal_next(state, chooser, CueBall::AsItLies);
        next.choices = vec![Choice::SpotEightAndShoot, Choice::RerackAndBreak];
        (outcome, next)
    } else if !legal {
        // WPA 3.3: the opponent accepts the table or has it re-racked and breaks or lets
        // the offender break again.
        state.pending = Some(Pending::IllegalBreak { breaker, scratched });
        let mut next = normal_next(state, breaker.other(), CueBall::AsItLies);
        next.choices = vec![
            Choice::ShootFromHere,
            Choice::RerackAndBreak,
            Choice::RerackOpponentBreaks,
        ];
        (Outcome::Passes, next)
    } else if scratched {
        // WPA 3.3 (the 2008 edition's rule): ball in hand behind the head string.
        let next = normal_next(state, breaker.other(), CueBall::InHandBehindHeadString);
        (Outcome::Passes, next)
    } else if pocketed {
        (
            Outcome::Continues,
            normal_next(state, breaker, CueBall::AsItLies),
        )
    } else {
        let next = normal_next(state, breaker.other(), CueBall::AsItLies);
        (Outcome::Passes, next)
    };
    next.spot.extend(spot);
    Ok(verdict(fouls, outcome, Some(next)))
}

/// Puts the object balls driven off the table (the 8 apart: it loses the rack, 3.8) back
/// among the balls on the table and lists them for the spot (WPA 6.5, 1.4).
fn spot_jumped(state: &mut GameState, shot: &ShotSummary) -> Vec<u8> {
    let jumped: Vec<u8> = shot.off_table_object_balls().filter(|&b| b != 8).collect();
    for &b in &jumped {
        state.put_back(b);
    }
    jumped
}
