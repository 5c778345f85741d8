//! The wing ball of a 9-ball break (issue 23's missed target, crates/rules/README.md): with a
//! tight rack a square hit on the 1 from near the long cushion sends a wing ball (an outer
//! ball of the third row) into the foot corner on the breaker's side, at any break speed;
//! from the middle of the head string the wing balls leave towards the side cushions, short
//! of the corners (Alciatore, "How to Rack and Break 9-Ball Like a Pro", and "Breaking Bad",
//! Billiards Digest, March 2018). Frozen rack, 9-ft table, 15 mm jaws, the game's physics.

use billiards_physics::{
    BallId, EventKind, Model, Params, Pocket, Shot, Simulation, SpinModel, Table, Vec2,
};
use billiards_rules::racks::nine_ball_spaced;

/// The pockets the left (+y) and right wing balls fell in (`None`: stayed on the table) for a
/// square hit on the 1 at `speed` from the head string at `across` of the way from the head
/// spot to the left cushion (negative: to the right one).
fn wing_balls(across: f64, speed: f64) -> [Option<Pocket>; 2] {
    let table = Table::wpa_9ft().with_jaws(0.015);
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let mut balls = nine_ball_spaced(&table, &params.ball, 7, 0.0);
    let cue = Vec2::new(
        table.head_spot().x,
        across * table.centre_bounds(params.ball.radius).y,
    );
    balls[0].position = cue;
    assert!(balls[4].position.y > 0.0 && balls[6].position.y < 0.0);
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    sim.strike(0, Shot::new((balls[1].position - cue).angle(), speed))
        .unwrap();
    sim.run_to_rest().unwrap();
    // Lattice order after the cue ball: apex, row 2, row 3 (indices 4, 5, 6), rows 4, 5.
    let pocket = |id: BallId| {
        sim.history().events().iter().find_map(|e| match e.kind {
            EventKind::Pocketed { ball, pocket } if ball == id => Some(pocket),
            _ => None,
        })
    };
    [pocket(4), pocket(6)]
}

#[test]
fn a_side_break_pockets_the_wing_ball_on_the_breakers_side_at_any_speed() {
    for speed in [10.0, 11.0, 12.0] {
        let [left, _] = wing_balls(0.75, speed);
        assert_eq!(left, Some(Pocket::FootLeft), "from the left at {speed} m/s");
        let [_, right] = wing_balls(-0.75, speed);
        assert_eq!(
            right,
            Some(Pocket::FootRight),
            "from the right at {speed} m/s"
        );
    }
}

#[test]
fn a_break_from_the_head_spot_leaves_both_wing_balls_on_the_table() {
    for speed in [10.0, 11.0, 12.0] {
        assert_eq!(wing_balls(0.0, speed), [None, None], "at {speed} m/s");
    }
}
