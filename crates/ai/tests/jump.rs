//! Jump shots (issue 52): with the 1 hidden behind a blocker, hard jumps it, and medium,
//! whose budget has no jumps, keeps the cue level.

mod common;

use billiards_ai::jump::hidden;
use billiards_ai::play::table_and_params;
use billiards_ai::{Decision, Layout, Level, Plan, decide};
use billiards_physics::{Pocket, Vec2};
use billiards_rules::CueBall;
use common::*;

/// A 25-degree cut of the 1 into the foot-right corner, the ghost ball 1 m ahead of the cue
/// ball, with the 2 on that line 25 cm from the cue ball (hiding the 1: every straight path
/// to it is blocked), and the 9 out of the way near the head-left corner.
fn blocked_one() -> Vec<(u8, Vec2)> {
    let (table, params) = table_and_params();
    let r = params.ball.radius;
    let (pocket, _) = billiards_ai::candidates::pocket_target(&table, r, Pocket::FootRight);
    let out = pocket.normalized().unwrap();
    let one = pocket - out * 0.45;
    // A 25-degree cut: straight in, the jumped cue ball (rolling by then) follows the 1 in.
    let dir = out.rotated(25f64.to_radians());
    let cue = one - out * (2.0 * r) - dir * 1.0;
    vec![
        (0, cue),
        (1, one),
        (2, cue + dir * 0.25),
        (9, Vec2::new(-0.9, 0.4)),
    ]
}

fn shoot(d: Decision) -> Plan {
    match d {
        Decision::Shoot(p) => p,
        other => panic!("expected a shot, got {other:?}"),
    }
}

/// The position is hidden (billiards_ai::jump::hidden: the full hit and every ghost-ball
/// path blocked); hard's shot is raised more than 20 degrees, and played on the solver
/// without noise the cue ball's first contact is the 1 (over the 2: a level shot along
/// that line would meet the 2 first, a foul, WPA 6.1 in 9-ball); medium's is level.
#[test]
fn hard_jumps_a_blocker_onto_the_hidden_one_and_medium_stays_level() {
    let balls = blocked_one();
    let (cloth, params) = table_and_params();
    let layout = Layout {
        table: cloth,
        radius: params.ball.radius,
        cue: balls[0].1,
        balls: balls[1..].to_vec(),
    };
    assert!(hidden(&layout, &[1]), "the 1 is hidden");
    let state = nine_ball(&[1, 2, 9], CueBall::AsItLies);
    let sim = table(&balls);
    let plan = shoot(decide(&state, &sim, Level::Hard, 7).unwrap());
    let degrees = plan.shot.elevation.to_degrees();
    assert!(degrees > 20.0, "a jump: {degrees} degrees, {plan:?}");
    let mut played = sim.clone();
    let summary = run(&mut played, &plan);
    assert_eq!(summary.first_contact, Some(1), "{plan:?} {summary:?}");
    let medium = shoot(decide(&state, &sim, Level::Medium, 7).unwrap());
    assert_eq!(medium.shot.elevation, 0.0, "{medium:?}");
}
