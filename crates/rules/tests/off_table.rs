//! Balls driven off the table (issue 52, "Balls in the air, II"), pool: each test is named
//! after the rule it pins (WPA Rules of Play: 6.1 "Cue Ball Scratch or off the Table", 6.5
//! "Ball Driven off the Table" — "whether that ball is spotted depends on the rules of the
//! game" —, 2.6 nine-ball's spotting, 9.9 ten-ball's, 3.8 eight-ball's loss of rack, 8.3 "Ball
//! Pocketed"), from hand-made summaries and event lists, then from the real solver (spin
//! model) behind the game interface.

mod common;

use billiards_physics::Pocket::*;
use billiards_physics::{
    BallSetup, BallSpec, BallState, Cushion, Event, EventKind, Model, Motion, Params, Shot,
    Simulation, SpinModel, Table, Vec2,
};
use billiards_rules::pool::PoolMatch;
use billiards_rules::*;
use common::{after_break, shot};

/// `s` with `off` driven off the table, in that order.
fn off(mut s: ShotSummary, off: &[u8]) -> ShotSummary {
    s.off_table = off.to_vec();
    s
}

fn event(kind: EventKind) -> Event {
    Event {
        time: 0.0,
        kind,
        after: [BallState::default(); 2],
    }
}

/// Ball `ball` (solver id) flies off the table.
fn leaves(ball: usize) -> Event {
    event(EventKind::Transition {
        ball,
        from: Motion::Airborne,
        to: Motion::OffTable,
    })
}

#[test]
fn wpa_6_5_the_summary_lists_the_balls_driven_off_the_table_once_each_in_order() {
    // Solver ids 0..3 are the balls 0, 5, 9: the 9 leaves, then the cue ball; a repeated
    // transition (never made by the solver) is listed once; a stop is no departure.
    let numbers = [0, 5, 9];
    let events = [
        event(EventKind::Strike {
            ball: 0,
            shot: Shot::new(0.0, 3.0),
        }),
        event(EventKind::BallBall { a: 0, b: 1 }),
        leaves(2),
        event(EventKind::Transition {
            ball: 1,
            from: Motion::Rolling,
            to: Motion::Stationary,
        }),
        leaves(0),
        leaves(2),
    ];
    let mut s = summarise(&events, &numbers);
    assert_eq!(s.off_table, vec![9, 0]);
    assert!(s.cue_off_table() && s.is_off_table(9) && !s.is_off_table(5));
    assert_eq!(s.off_table_object_balls().collect::<Vec<_>>(), vec![9]);
    // WPA 8.3: a ball is pocketed only when it rests in a pocket.
    assert!(s.pocketed.is_empty() && !s.scratch());
    s.clear();
    assert_eq!(s, ShotSummary::default());
    // A log written before flight has no `off_table` key and still reads.
    let old = r#"{"first_contact":null,"rails_after_contact":[],"rails":[],"cue_rail":false,"pocketed":[],"jaws":[]}"#;
    let read: ShotSummary = serde_json::from_str(old).unwrap();
    assert!(read.off_table.is_empty());
}

#[test]
fn wpa_6_5_the_foul_names_the_ball_driven_off_the_table() {
    assert_eq!(
        Foul::OffTable { ball: 5 }.to_string(),
        "the 5 was driven off the table"
    );
    assert_eq!(
        Foul::OffTable { ball: 0 }.to_string(),
        "the cue ball was driven off the table"
    );
    assert_eq!(
        WinReason::EightOffTable.to_string(),
        "the 8 was driven off the table"
    );
}

#[test]
fn wpa_6_1_the_cue_ball_off_the_table_is_a_foul_with_ball_in_hand_anywhere() {
    // B hits the 1 first and drives it to a rail: legal but for the cue ball leaving.
    let mut g = after_break(Game::NineBall);
    let v = g
        .play(&off(shot(Some(1), &[1], &[]), &[0]), Call::None)
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::OffTable { ball: 0 }]);
    assert_eq!(v.outcome, Outcome::Passes);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::A);
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert!(next.spot.is_empty());
    assert_eq!(g.fouls, [0, 1], "it counts towards three fouls (WPA 2.8)");
}

#[test]
fn wpa_6_5_and_2_6_nine_ball_a_jumped_object_ball_stays_off_and_the_9_is_spotted() {
    // The 1 is pocketed legally, the 4 and the 9 fly off: the pot does not save the shot.
    let mut g = after_break(Game::NineBall);
    let s = off(shot(Some(1), &[1], &[(1, FootLeft)]), &[4, 9]);
    let v = g.play(&s, Call::None).unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::OffTable { ball: 4 }, Foul::OffTable { ball: 9 }]
    );
    let next = v.next.unwrap();
    assert_eq!(next.spot, vec![9], "only the 9 is ever spotted");
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert_eq!(g.on_table, vec![2, 3, 5, 6, 7, 8, 9]);
    assert!(g.over.is_none(), "a 9 off the table wins nothing");
}

#[test]
fn wpa_6_5_and_2_4_a_ball_off_the_table_on_a_push_out_is_a_foul() {
    // A push out needs no contact and no rail (2.4) but the 3 driven off is still a foul.
    let mut g = after_break(Game::NineBall);
    let v = g
        .play(&off(shot(None, &[], &[]), &[3]), Call::PushOut)
        .unwrap();
    assert_eq!(v.fouls, vec![Foul::OffTable { ball: 3 }]);
    assert!(!g.on_table.contains(&3));
}

#[test]
fn wpa_6_5_and_9_9_ten_ball_only_the_10_is_spotted() {
    let mut g = after_break(Game::TenBall);
    let s = off(shot(Some(1), &[1], &[]), &[10, 6]);
    let call = Call::Ball {
        ball: 1,
        pocket: FootLeft,
    };
    let v = g.play(&s, call).unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::OffTable { ball: 10 }, Foul::OffTable { ball: 6 }]
    );
    let next = v.next.unwrap();
    assert_eq!(next.spot, vec![10]);
    assert!(g.on_table.contains(&10) && !g.on_table.contains(&6));
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
}

#[test]
fn wpa_6_5_eight_ball_jumped_object_balls_are_spotted_and_the_shot_is_a_foul() {
    let mut g = after_break(Game::EightBall);
    let s = off(shot(Some(3), &[3], &[]), &[3, 12]);
    let v = g.play(&s, Call::None).unwrap();
    assert_eq!(
        v.fouls,
        vec![Foul::OffTable { ball: 3 }, Foul::OffTable { ball: 12 }]
    );
    let next = v.next.unwrap();
    assert_eq!(next.spot, vec![3, 12]);
    assert_eq!(next.cue_ball, CueBall::InHandAnywhere);
    assert_eq!(g.on_table, (1..=15).collect::<Vec<u8>>());
}

#[test]
fn wpa_3_8_eight_ball_the_8_driven_off_the_table_loses_the_rack() {
    // Even with a legal pot of the shooter's ball beside it, and on the break too.
    let mut g = after_break(Game::EightBall);
    let s = off(shot(Some(2), &[2], &[(2, SideLeft)]), &[8]);
    let v = g.play(&s, Call::None).unwrap();
    let lost = Outcome::GameOver {
        winner: Seat::A,
        reason: WinReason::EightOffTable,
    };
    assert_eq!(v.outcome, lost);
    assert_eq!(g.over, Some((Seat::A, WinReason::EightOffTable)));
    let mut b = GameState::new(Game::EightBall, Seat::A);
    let s = off(shot(Some(1), &[2, 3, 4, 5], &[]), &[8]);
    let v = b.play(&s, Call::None).unwrap();
    assert!(matches!(
        v.outcome,
        Outcome::GameOver {
            winner: Seat::B,
            reason: WinReason::EightOffTable
        }
    ));
}

#[test]
fn wpa_8_3_a_ball_off_the_table_is_not_pocketed_it_gives_no_group_and_no_turn() {
    // Open table: the 3, hit first, flies off; nothing drops. A pocketed 3 would give the
    // solids and keep the shooter at the table (3.5); off the table it gives neither.
    let mut g = after_break(Game::EightBall);
    let v = g
        .play(&off(shot(Some(3), &[0], &[]), &[3]), Call::None)
        .unwrap();
    assert_eq!(v.assigned, None);
    assert_eq!(g.group_a, None);
    assert_eq!(v.outcome, Outcome::Passes);
    assert_eq!(v.next.unwrap().shooter, Seat::A);
}

#[test]
fn wpa_3_3_with_6_5_a_ball_off_the_table_on_the_8_ball_break_is_a_foul_and_spotted() {
    // A legal break (four to a rail) that sends the 12 off: the opponent has the cue ball
    // in hand behind the head string, as after a scratch on the break (3.3), the 12 spotted.
    let mut g = GameState::new(Game::EightBall, Seat::A);
    let s = off(shot(Some(1), &[2, 3, 4, 5], &[]), &[12]);
    let v = g.play(&s, Call::None).unwrap();
    assert_eq!(v.fouls, vec![Foul::OffTable { ball: 12 }]);
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.cue_ball, CueBall::InHandBehindHeadString);
    assert_eq!(next.spot, vec![12]);
}

/// A 9-ball match (race to 2) whose rack stands after A's legal break: B is at the table.
fn nine_ball_match() -> PoolMatch {
    let mut m = PoolMatch::new(
        Game::NineBall,
        ["Ann".into(), "Bob".into()],
        2,
        Table::wpa_8ft(),
        BallSpec::default(),
        1,
        RackStyle::Template,
    );
    m.play.rack = after_break(Game::NineBall);
    m
}

#[test]
fn wpa_2_6_through_the_interface_the_jumped_9_is_put_on_the_foot_spot() {
    let mut m = nine_ball_match();
    // Solver ids are the numbers 0..=9; the cue ball hits the 1, which reaches a cushion
    // (6.3 met), the 9 flies off.
    let numbers: Vec<u8> = (0..=9).collect();
    let before: Vec<(u8, Vec2)> = numbers
        .iter()
        .map(|&n| (n, Vec2::new(-0.9 + 0.15 * f64::from(n), 0.3)))
        .collect();
    let after: Vec<(u8, Vec2)> = before.iter().copied().filter(|&(n, _)| n != 9).collect();
    let events = [
        event(EventKind::Strike {
            ball: 0,
            shot: Shot::new(0.0, 3.0),
        }),
        event(EventKind::BallBall { a: 0, b: 1 }),
        event(EventKind::Cushion {
            ball: 1,
            cushion: Cushion::Foot,
        }),
        leaves(9),
    ];
    let j = m
        .judge(&StrokeRecord {
            events: &events,
            numbers: &numbers,
            before: &before,
            after: &after,
            declared: Declaration::None,
        })
        .unwrap();
    assert!(!j.fair);
    assert_eq!(j.fouls, vec!["the 9 was driven off the table".to_owned()]);
    assert_eq!(j.put.len(), 1, "{:?}", j.put);
    let (n, at) = j.put[0];
    // WPA 1.4: on the long string (y = 0), at the foot spot (x = a quarter length).
    assert_eq!(n, 9);
    let foot = Table::wpa_8ft().length / 4.0;
    assert!(at.y.abs() < 1e-9 && (at.x - foot).abs() < 1e-9, "{at:?}");
    assert_eq!(m.rack().on_table, (1..=9).collect::<Vec<u8>>());
}

fn spin() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

/// Plays `shot` of the cue ball among `balls` with the spin model, judged by `m` behind
/// the interface; returns the judgement and the summary.
fn judge_real(m: &mut dyn GameRules, balls: &[BallSetup], shot: Shot) -> (Judgement, ShotSummary) {
    let mut sim = Simulation::new(Table::wpa_8ft(), spin(), balls).unwrap();
    let layout = |sim: &Simulation| -> Vec<(u8, Vec2)> {
        sim.balls()
            .zip(sim.numbers())
            .filter(|(b, _)| b.motion.on_table())
            .map(|(b, &n)| (n, b.position))
            .collect()
    };
    let before = layout(&sim);
    sim.strike(0, shot).unwrap();
    sim.run_to_rest().unwrap();
    let after = layout(&sim);
    let events = sim.history().events();
    let j = m
        .judge(&StrokeRecord {
            events,
            numbers: sim.numbers(),
            before: &before,
            after: &after,
            declared: Declaration::None,
        })
        .unwrap();
    (j, summarise(events, sim.numbers()))
}

#[test]
fn wpa_6_1_a_real_hard_elevated_shot_sends_the_cue_ball_off_the_table_a_foul() {
    // The physics' own flight test: 6 m/s at 60 degrees, 30 cm from the foot cushion,
    // leaves the table; the 1 and the 9 are far from its path.
    let mut m = nine_ball_match();
    let table = Table::wpa_8ft();
    let balls = [
        BallSetup::at(0, Vec2::new(0.5 * table.length - 0.3, 0.1)),
        BallSetup::at(1, Vec2::new(-0.6, -0.3)),
        BallSetup::at(9, Vec2::new(-0.3, -0.3)),
    ];
    let shot = Shot {
        elevation: 60f64.to_radians(),
        ..Shot::new(0.0, 6.0)
    };
    let (j, s) = judge_real(&mut m, &balls, shot);
    assert_eq!(s.off_table, vec![0], "{s:?}");
    assert!(!j.fair);
    assert!(
        j.fouls
            .contains(&"the cue ball was driven off the table".to_owned()),
        "{:?}",
        j.fouls
    );
    // WPA 6.1: ball in hand for A anywhere.
    let turn = m.turn();
    assert_eq!(turn.striker, Seat::A);
    assert!(matches!(turn.place, CueBallPlace::InHand { .. }));
}

#[test]
fn wpa_6_2_a_real_jump_over_a_blocking_ball_that_hits_the_1_first_is_legal() {
    // The replay's jump: 4 m/s at 50 degrees over a ball 15 cm ahead (here the 2, which
    // would be a wrong ball first), the 1 beyond it on the same line: the cue ball lands
    // past the 2 and hits the 1 first (WPA 6.2), a jump by the tip's stroke being legal
    // (games.md, "Balls off the table").
    let mut m = nine_ball_match();
    let balls = [
        BallSetup::at(0, Vec2::new(-0.5, 0.0)),
        BallSetup::at(2, Vec2::new(-0.35, 0.0)),
        BallSetup::at(1, Vec2::new(0.3, 0.0)),
        BallSetup::at(9, Vec2::new(0.9, -0.4)),
    ];
    let shot = Shot {
        elevation: 50f64.to_radians(),
        ..Shot::new(0.0, 4.0)
    };
    let (j, s) = judge_real(&mut m, &balls, shot);
    assert_eq!(s.first_contact, Some(1), "{s:?}");
    assert!(s.off_table.is_empty(), "{s:?}");
    assert!(j.fair, "{}: {:?}", j.text, j.fouls);
}
