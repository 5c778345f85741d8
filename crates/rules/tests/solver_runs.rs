//! Rule scenarios from real solver runs: lay out balls, strike, run to rest, summarise the
//! events and judge them.

use billiards_physics::{
    BallSetup, Model, Params, Pocket, Shot, Simulation, SpinModel, Table, Vec2,
};
use billiards_rules::*;

/// The game's default table and physics: 8-ft table with jaws, spin model.
fn setup() -> (Table, Params) {
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    (Table::wpa_8ft().with_jaws(0.015), params)
}

fn run(balls: &[BallSetup], shot: Shot) -> ShotSummary {
    let (table, params) = setup();
    let mut sim = Simulation::new(table, params, balls).unwrap();
    sim.strike(0, shot).unwrap();
    sim.run_to_rest().unwrap();
    summarise(sim.history().events(), sim.numbers())
}

/// The cue ball, `target` half a metre from the foot-left corner on its diagonal, aimed at
/// that corner; `other` balls elsewhere.
fn pot(target: u8, speed: f64, others: &[(u8, Vec2)]) -> (Vec<BallSetup>, Shot) {
    let t = Table::wpa_8ft();
    let corner = Vec2::new(t.length / 2.0, t.width / 2.0);
    let dir = corner.normalized().unwrap();
    let ball = corner - dir * 0.5;
    // Close enough that the cue ball still slides at the contact: a stun shot, it stops.
    let mut balls = vec![
        BallSetup::at(0, ball - dir * 0.15),
        BallSetup::at(target, ball),
    ];
    balls.extend(others.iter().map(|&(n, p)| BallSetup::at(n, p)));
    (balls, Shot::new(dir.angle(), speed))
}

fn nine_ball_with(on_table: &[u8]) -> GameState {
    let mut g = GameState::new(Game::NineBall, Seat::A);
    g.play(&common_break(), Call::None).unwrap();
    g.on_table = on_table.to_vec();
    g
}

/// A legal break by A pocketing nothing: B at the table.
fn common_break() -> ShotSummary {
    ShotSummary {
        first_contact: Some(1),
        rails: vec![2, 3, 4, 5],
        rails_after_contact: vec![2, 3, 4, 5],
        ..ShotSummary::default()
    }
}

#[test]
fn wpa_2_3_a_real_break_of_the_seeded_rack_is_judged_by_its_own_facts() {
    let (table, params) = setup();
    for seed in 0..4 {
        let mut balls = Game::NineBall.rack(&table, &params.ball, seed);
        // Cue ball on the head string, aimed at the 1.
        balls[0].position = table.head_spot() + Vec2::new(0.0, 0.1);
        let aim = (balls[1].position - balls[0].position).angle();
        let s = run(&balls, Shot::new(aim, 9.0));
        let mut g = GameState::new(Game::NineBall, Seat::A);
        let v = g.play(&s, Call::None).unwrap();
        assert_eq!(s.first_contact, Some(1));
        let pocketed = s.pocketed_object_balls().count();
        let legal = !s.scratch() && (pocketed > 0 || s.object_balls_to_rail() >= 4);
        assert_eq!(v.legal(), legal, "seed {seed}: {s:?} {v:?}");
        if s.pocket_of(9).is_some() && legal {
            assert_eq!(g.over, Some((Seat::A, WinReason::NinePocketed)));
        } else if legal && pocketed > 0 {
            assert_eq!(v.outcome, Outcome::Continues);
        } else {
            assert_eq!(v.outcome, Outcome::Passes);
        }
    }
}

#[test]
fn wpa_2_5_a_real_pot_of_the_lowest_ball_keeps_the_shooter() {
    let (balls, shot) = pot(
        2,
        2.0,
        &[(5, Vec2::new(-0.6, -0.3)), (9, Vec2::new(-0.8, 0.3))],
    );
    let s = run(&balls, shot);
    let mut g = nine_ball_with(&[2, 5, 9]);
    let v = g.play(&s, Call::None).unwrap();
    assert_eq!(s.pocketed, vec![(2, Pocket::FootLeft)]);
    assert!(v.legal(), "{}", v.reason());
    assert_eq!(v.outcome, Outcome::Continues);
    assert_eq!(v.next.unwrap().legal_first, vec![5]);
}

#[test]
fn wpa_6_2_a_real_shot_at_the_3_with_the_2_lowest_is_a_foul() {
    let (balls, shot) = pot(
        3,
        2.0,
        &[(2, Vec2::new(-0.6, -0.3)), (9, Vec2::new(-0.8, 0.3))],
    );
    let s = run(&balls, shot);
    let mut g = nine_ball_with(&[2, 3, 9]);
    let v = g.play(&s, Call::None).unwrap();
    assert_eq!(
        v.reason(),
        "foul: the 3 was hit first, the 2 was the lowest ball"
    );
    let next = v.next.unwrap();
    assert_eq!(
        (next.shooter, next.cue_ball),
        (Seat::A, CueBall::InHandAnywhere)
    );
}

#[test]
fn wpa_6_3_a_real_soft_touch_without_a_rail_is_a_foul() {
    let balls = [
        BallSetup::at(0, Vec2::new(-0.2, 0.0)),
        BallSetup::at(1, Vec2::new(0.0, 0.0)),
        BallSetup::at(9, Vec2::new(0.5, 0.4)),
    ];
    let s = run(&balls, Shot::new(0.0, 0.3));
    assert_eq!(s.first_contact, Some(1));
    assert!(s.rails.is_empty(), "{s:?}");
    let mut g = nine_ball_with(&[1, 9]);
    let v = g.play(&s, Call::None).unwrap();
    assert_eq!(v.fouls, vec![Foul::NoRail]);
}

#[test]
fn wpa_6_1_6_2_a_real_scratch_that_hits_no_ball_lists_both_fouls() {
    // The cue ball alone on the diagonal to the foot-left corner, then the 1 and 9 aside.
    let t = Table::wpa_8ft();
    let corner = Vec2::new(t.length / 2.0, t.width / 2.0);
    let dir = corner.normalized().unwrap();
    let balls = [
        BallSetup::at(0, corner - dir * 0.8),
        BallSetup::at(1, Vec2::new(-0.6, -0.3)),
        BallSetup::at(9, Vec2::new(-0.8, 0.3)),
    ];
    let s = run(&balls, Shot::new(dir.angle(), 2.0));
    assert!(s.scratch());
    let mut g = nine_ball_with(&[1, 9]);
    let v = g.play(&s, Call::None).unwrap();
    assert_eq!(v.fouls, vec![Foul::Scratch, Foul::NoBallHit]);
    assert_eq!(
        v.reason(),
        "foul: the cue ball was pocketed; the cue ball hit no ball"
    );
}

#[test]
fn wpa_3_5_a_real_called_pot_on_an_open_table_assigns_the_group() {
    let (balls, shot) = pot(
        13,
        2.0,
        &[(8, Vec2::new(-0.6, -0.3)), (2, Vec2::new(-0.8, 0.3))],
    );
    let s = run(&balls, shot);
    let mut g = GameState::new(Game::EightBall, Seat::A);
    g.play(&common_break(), Call::None).unwrap();
    let call = Call::Ball {
        ball: 13,
        pocket: Pocket::FootLeft,
    };
    let v = g.play(&s, call).unwrap();
    assert_eq!(v.assigned, Some(Group::Stripes));
    assert_eq!(g.group(Seat::B), Some(Group::Stripes));
    assert_eq!(v.outcome, Outcome::Continues);
}

#[test]
fn free_play_a_real_scratch_is_no_foul_and_respots_the_cue_ball() {
    let t = Table::wpa_8ft();
    let corner = Vec2::new(t.length / 2.0, t.width / 2.0);
    let dir = corner.normalized().unwrap();
    let balls = [
        BallSetup::at(0, corner - dir * 0.8),
        BallSetup::at(4, Vec2::new(-0.6, -0.3)),
    ];
    let s = run(&balls, Shot::new(dir.angle(), 2.0));
    let mut g = GameState::new(Game::FreePlay, Seat::A);
    let v = g.play(&s, Call::None).unwrap();
    assert!(v.legal());
    assert_eq!(v.outcome, Outcome::Continues);
    let next = v.next.unwrap();
    assert_eq!((next.shooter, next.cue_ball), (Seat::A, CueBall::Respot));
}

#[test]
fn a_match_race_to_two_scores_racks_and_alternates_the_break() {
    let mut m = Match::new(Game::NineBall, ["Ann".into(), "Bob".into()], 2, Seat::A);
    let nine = ShotSummary {
        first_contact: Some(1),
        pocketed: vec![(9, Pocket::FootLeft)],
        ..ShotSummary::default()
    };
    assert_eq!(
        m.next_rack().map(|_| ()),
        Err(RuleError::GameOver),
        "rack in play"
    );
    m.play(&nine, Call::None).unwrap();
    assert_eq!(m.score, [1, 0]);
    let next = m.next_rack().unwrap();
    assert_eq!((next.shooter, next.break_shot), (Seat::B, true));
    // B breaks and A wins again: A takes the match.
    m.play(&common_break(), Call::None).unwrap();
    m.play(&nine, Call::None).unwrap();
    assert_eq!(m.score, [2, 0]);
    assert_eq!(m.winner(), Some(Seat::A));
    assert_eq!(m.name(Seat::A), "Ann");
    assert!(m.next_rack().is_err(), "the match is over");
}

#[test]
fn wpa_9_3_9_9_a_real_break_of_the_seeded_ten_ball_rack_is_judged_by_its_own_facts() {
    let (table, params) = setup();
    for seed in 0..4 {
        let mut balls = Game::TenBall.rack(&table, &params.ball, seed);
        assert_eq!(
            balls.len(),
            11,
            "the cue ball and ten object balls (WPA 9.2)"
        );
        balls[0].position = table.head_spot() + Vec2::new(0.0, 0.1);
        let aim = (balls[1].position - balls[0].position).angle();
        let s = run(&balls, Shot::new(aim, 9.0));
        let mut g = GameState::new(Game::TenBall, Seat::A);
        let v = g.play(&s, Call::None).unwrap();
        assert_eq!(s.first_contact, Some(1));
        let pocketed = s.pocketed_object_balls().count();
        let legal = !s.scratch() && (pocketed > 0 || s.object_balls_to_rail() >= 4);
        assert_eq!(v.legal(), legal, "seed {seed}: {s:?} {v:?}");
        // WPA 9.9: never a win on the break; the 10 made is back on the table.
        assert_eq!(g.over, None);
        assert!(g.on_table.contains(&10));
        let next = v.next.unwrap();
        assert_eq!(next.spot.contains(&10), s.pocket_of(10).is_some());
        match (legal, pocketed > 0) {
            (true, true) => assert_eq!(v.outcome, Outcome::Continues),
            _ => assert_eq!(v.outcome, Outcome::Passes),
        }
        assert_eq!(next.push_out_allowed, legal, "WPA 9.4");
    }
}

#[test]
fn wpa_9_5_9_7_a_real_pot_of_the_10_wins_only_in_the_called_pocket() {
    let (balls, shot) = pot(10, 2.0, &[]);
    let s = run(&balls, shot);
    assert_eq!(s.pocketed, vec![(10, Pocket::FootLeft)]);
    let last_ball = || GameState::in_progress(Game::TenBall, Seat::A, vec![10]);
    let mut g = last_ball();
    let call = |pocket| Call::Ball { ball: 10, pocket };
    let v = g.play(&s, call(Pocket::FootLeft)).unwrap();
    assert_eq!(g.over, Some((Seat::A, WinReason::TenPocketed)), "{v:?}");
    let mut g = last_ball();
    let v = g.play(&s, call(Pocket::FootRight)).unwrap();
    assert_eq!(g.over, None);
    assert_eq!(g.on_table, vec![10], "WPA 9.9: the 10 spotted");
    let next = v.next.unwrap();
    assert_eq!(next.shooter, Seat::B);
    assert_eq!(next.choices, vec![Choice::ShootFromHere, Choice::PassBack]);
}
