//! The computer at three-cushion: the search every game shares
//! ([`billiards_ai::any_game`]) through the game interface (`ThreeCushionMatch`).

use billiards_ai::Level;
use billiards_ai::any_game::{Move, decide_any, layout_of};
use billiards_physics::{Model, PaperModel, Params, Shot, Simulation, Table, Vec2};
use billiards_rules::three_cushion::rules::ThreeCushionMatch;
use billiards_rules::{Declaration, GameRules, Seat, StrokeRecord};

/// The paper's model with the carom ball: straight paths between mirror rebounds, so a
/// three-cushion point drawn with mirror images is a point in the solver.
fn paper_carom() -> Params {
    Params {
        model: Model::Paper(PaperModel::default()),
        ..Params::carom()
    }
}

fn players() -> [String; 2] {
    ["A".to_owned(), "B".to_owned()]
}

/// A layout with a point known to exist, by construction: the yellow (B's cue ball) at
/// (-0.9, -0.3) sent off the foot, left and head cushions (mirror images) to a ghost point
/// where it cuts the white thinly (80 degrees) and runs on 0.4 m into the red. The game
/// (B to play) and that shot.
fn known_point() -> (ThreeCushionMatch, Shot) {
    let t = Table::carom_match();
    let params = paper_carom();
    let r = params.ball.radius;
    let (bx, by) = (0.5 * t.length - r, 0.5 * t.width - r);
    let (from, ghost) = (Vec2::new(-0.9, -0.3), Vec2::new(-0.6, 0.2));
    // Images of the ghost across the head, then the left, then the foot cushion line.
    let image = Vec2::new(2.0 * bx - (-2.0 * bx - ghost.x), 2.0 * by - ghost.y);
    let d = (image - from).normalized().unwrap();
    let arrive = Vec2::new(d.x, -d.y); // reversed in x twice (foot, head), in y once (left)
    let n = Vec2::from_angle(arrive.angle() + 80f64.to_radians());
    let on = (arrive - n * arrive.dot(n)).normalized().unwrap();
    let at = [ghost + n * (2.0 * r), from, ghost + on * 0.4];
    let game = ThreeCushionMatch::in_progress(players(), 40, (t, params.ball), at, Seat::B);
    (game.unwrap(), Shot::new(d.angle(), 6.0))
}

/// Plays `shot` by the striker and judges it on a copy: did the striker score?
fn scores(game: &ThreeCushionMatch, sim: &Simulation, shot: Shot) -> bool {
    let (mut sim, mut game) = (sim.clone(), game.clone());
    let striker = game.turn().striker.index();
    let before = layout_of(&sim);
    sim.set_record_history(true);
    sim.strike(usize::from(game.turn().cue_ball), shot).unwrap();
    sim.run_to_rest().unwrap();
    let events = sim.history().events().to_vec();
    let was = game.points()[striker];
    game.judge(&StrokeRecord {
        events: &events,
        numbers: sim.numbers(),
        before: &before,
        after: &layout_of(&sim),
        declared: Declaration::None,
    })
    .unwrap();
    game.points()[striker] > was
}

fn table_of(game: &ThreeCushionMatch, params: Params) -> Simulation {
    Simulation::new(game.table, params, &game.layout().unwrap()).unwrap()
}

#[test]
fn the_computer_scores_from_a_position_where_a_point_is_known_to_exist() {
    let (game, planned) = known_point();
    let sim = table_of(&game, paper_carom());
    // The constructed shot is a point (UMB Art. 83: the judge agrees with the geometry).
    assert!(scores(&game, &sim, planned));
    // The perfect level (no execution noise) finds a point, and the same seed gives the
    // same decision.
    let Move::Strike(plan) = decide_any(&game, &sim, Level::Perfect, 7).unwrap() else {
        panic!("no option is offered here");
    };
    assert!(scores(&game, &sim, plan.shot), "{plan:?}");
    assert!(
        plan.value > 0.5,
        "a point is valued as the turn kept: {plan:?}"
    );
    let again = decide_any(&game, &sim, Level::Perfect, 7).unwrap();
    assert_eq!(again, Move::Strike(plan));
}

#[test]
fn on_the_opening_the_computer_plays_at_the_red_first() {
    // UMB 3.3 / Art. 23: the opening stroke goes at the red with no cushion first; the
    // computer's choice is judged without a foul.
    let game =
        ThreeCushionMatch::new(players(), 40, Table::carom_match(), Params::carom().ball).unwrap();
    assert!(game.turn().opening);
    let sim = table_of(&game, Params::carom());
    let Move::Strike(plan) = decide_any(&game, &sim, Level::Easy, 1).unwrap() else {
        panic!("no option on the opening");
    };
    let mut s = sim.clone();
    s.set_record_history(true);
    s.strike(0, plan.shot).unwrap();
    s.run_to_rest().unwrap();
    let events = s.history().events().to_vec();
    let mut copy = game.clone();
    let judged = copy
        .judge(&StrokeRecord {
            events: &events,
            numbers: s.numbers(),
            before: &layout_of(&sim),
            after: &layout_of(&s),
            declared: Declaration::None,
        })
        .unwrap();
    assert!(judged.fair, "{}", judged.text);
}

#[test]
fn a_layout_with_overlapping_balls_is_refused() {
    let t = Table::carom_match();
    let at = [Vec2::ZERO, Vec2::new(0.01, 0.0), Vec2::new(0.5, 0.0)];
    let r = ThreeCushionMatch::in_progress(players(), 40, (t, Params::carom().ball), at, Seat::A);
    assert!(r.unwrap_err().to_string().contains("overlaps"));
}
