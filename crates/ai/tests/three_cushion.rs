//! The computer at three-cushion (`billiards_ai::three_cushion`).

use billiards_ai::noise::Noise;
use billiards_ai::three_cushion::{
    CaromBudget, CaromError, CaromStroke, decide_three_cushion, scores,
};
use billiards_physics::{Model, PaperModel, Params, Shot, Table, Vec2};
use billiards_rules::three_cushion::Ball;

/// The paper's model with the carom ball: straight paths between mirror rebounds, so a
/// three-cushion point drawn with mirror images is a point in the solver.
fn paper_carom() -> Params {
    Params {
        model: Model::Paper(PaperModel::default()),
        ..Params::carom()
    }
}

/// A layout with a point known to exist, by construction: the yellow at (-0.9, -0.3) sent
/// off the foot, left and head cushions (mirror images) to a ghost point where it cuts the
/// white thinly (80 degrees) and runs on 0.4 m into the red. The layout and that shot.
fn known_point() -> (CaromStroke, Shot) {
    let t = Table::carom_match();
    let r = paper_carom().ball.radius;
    let (bx, by) = (0.5 * t.length - r, 0.5 * t.width - r);
    let (from, ghost) = (Vec2::new(-0.9, -0.3), Vec2::new(-0.6, 0.2));
    // Images of the ghost across the head, then the left, then the foot cushion line.
    let image = Vec2::new(2.0 * bx - (-2.0 * bx - ghost.x), 2.0 * by - ghost.y);
    let d = (image - from).normalized().unwrap();
    let arrive = Vec2::new(d.x, -d.y); // reversed in x twice (foot, head), in y once (left)
    let n = Vec2::from_angle(arrive.angle() + 80f64.to_radians());
    let on = (arrive - n * arrive.dot(n)).normalized().unwrap();
    let stroke = CaromStroke {
        positions: [ghost + n * (2.0 * r), from, ghost + on * 0.4],
        cue: Ball::Yellow,
        opening: false,
    };
    (stroke, Shot::new(d.angle(), 6.0))
}

#[test]
fn the_computer_scores_from_a_position_where_a_point_is_known_to_exist() {
    let (stroke, planned) = known_point();
    let (table, params) = (Table::carom_match(), paper_carom());
    // The constructed shot is a point (the judge of the rules agrees with the geometry).
    assert_eq!(scores(stroke, &table, &params, planned), Some(true));
    let budget = CaromBudget::default();
    let plan = decide_three_cushion(stroke, &table, &params, Noise::NONE, &budget, 7).unwrap();
    assert!(plan.scoring > 0 && plan.success == 1.0, "{plan:?}");
    assert_eq!(scores(stroke, &table, &params, plan.shot), Some(true));
    // Under the reference execution noise it still picks a shot that scores more often than
    // not, and the same seed gives the same plan.
    let noisy = decide_three_cushion(stroke, &table, &params, Noise::REFERENCE, &budget, 7);
    let noisy = noisy.unwrap();
    assert!(noisy.success > 0.5, "{noisy:?}");
    let again = decide_three_cushion(stroke, &table, &params, Noise::REFERENCE, &budget, 7);
    assert_eq!(again.unwrap(), noisy);
}

#[test]
fn on_the_opening_the_computer_plays_at_the_red_first() {
    // UMB 3.3: every shot tried on the opening meets the red first; a few directions, so
    // the test is quick.
    let budget = CaromBudget {
        directions: 24,
        ..CaromBudget::default()
    };
    let (table, params) = (Table::carom_match(), Params::carom());
    let head = -0.25 * table.length;
    let stroke = CaromStroke {
        positions: [
            Vec2::new(head, -0.1825),
            Vec2::new(head, 0.0),
            Vec2::new(0.25 * table.length, 0.0),
        ],
        cue: Ball::White,
        opening: true,
    };
    let plan = decide_three_cushion(stroke, &table, &params, Noise::NONE, &budget, 1).unwrap();
    let to_red = stroke.positions[2] - stroke.positions[0];
    let off = (plan.shot.angle - to_red.angle()).abs();
    assert!(
        off < (2.0 * params.ball.radius / to_red.length()).asin(),
        "{plan:?}"
    );
}

#[test]
fn a_layout_the_solver_refuses_is_an_error() {
    let stroke = CaromStroke {
        positions: [Vec2::ZERO, Vec2::new(0.01, 0.0), Vec2::new(0.5, 0.0)],
        cue: Ball::White,
        opening: false,
    };
    let r = decide_three_cushion(
        stroke,
        &Table::carom_match(),
        &Params::carom(),
        Noise::NONE,
        &CaromBudget::default(),
        0,
    );
    assert_eq!(r, Err(CaromError::Layout));
}
