//! Free play behind the one interface (issue 50): the sandbox whose table the player sets by
//! hand. Its strokes are judged on the table their strike finds (a ball placed back by hand
//! is in play, a ball taken off is not), a scratch puts the cue ball back on the head string
//! and says so, and no other game of the catalog lets its table be set by hand.

use billiards_physics::{BallSetup, Params, Shot, Simulation, Vec2};
use billiards_rules::catalog::{GAMES, MatchSettings, find};
use billiards_rules::{CueBallPlace, GameRules, Judgement, StrokeRecord};

mod interface_common;
use interface_common::{id_of, layout_of};

fn free_play() -> Box<dyn GameRules> {
    let settings = MatchSettings::new(["Ann".to_owned(), "Bob".to_owned()], 1, 0);
    find("free-play").unwrap().start(&settings).unwrap()
}

/// Strikes the cue ball of `balls` at `angle` (radians), `speed` m/s, runs to rest and judges
/// the stroke with `game`; returns the judgement and the table at rest.
fn stroke(
    game: &mut dyn GameRules,
    balls: &[BallSetup],
    angle: f64,
    speed: f64,
) -> (Judgement, Vec<(u8, Vec2)>) {
    let params = Params {
        ball: game.ball(),
        ..Params::default()
    };
    let mut sim = Simulation::new(game.table(), params, balls).unwrap();
    let before = layout_of(&sim);
    let cue = id_of(&sim, 0);
    sim.strike(cue, Shot::new(angle, speed)).unwrap();
    sim.run_to_rest().unwrap();
    let after = layout_of(&sim);
    let judgement = game
        .judge(&StrokeRecord {
            events: sim.history().events(),
            numbers: sim.numbers(),
            before: &before,
            after: &after,
            declared: Default::default(),
        })
        .unwrap();
    (judgement, after)
}

/// A point `d` metres in from the foot-right corner along its diagonal (the corner pocket's
/// line of entry at 45 degrees).
fn on_the_diagonal(game: &dyn GameRules, d: f64) -> Vec2 {
    let table = game.table();
    let corner = Vec2::new(table.length / 2.0, table.width / 2.0);
    corner - Vec2::new(d, d) / 2f64.sqrt()
}

/// Only free play's table is the player's: it takes stock of a table set by hand (a drill's
/// two balls left after leaving it: "balls left: 1", not the rack's 15), every other game
/// refuses, its state untouched.
#[test]
fn only_free_play_lets_its_table_be_set_by_hand() {
    let layout = [(0, Vec2::new(-0.5, 0.0)), (1, Vec2::new(0.4, 0.1))];
    for entry in GAMES {
        let settings = MatchSettings::new(["Ann".to_owned(), "Bob".to_owned()], 1, 0);
        let mut game = entry.start(&settings).unwrap();
        let free = entry.id == "free-play";
        assert_eq!(
            game.sandbox(),
            free,
            "{}: only free play's table is the player's",
            entry.id
        );
        let status = game.status();
        assert_eq!(game.set_by_hand(&layout).is_ok(), free, "{}", entry.id);
        if free {
            assert_eq!(game.status(), vec!["balls left: 1".to_owned()]);
            assert_eq!(game.turn().legal_first, vec![1]);
        } else {
            assert_eq!(game.status(), status, "{}: refused, untouched", entry.id);
        }
    }
}

#[test]
fn a_ball_placed_back_by_hand_is_in_play_at_the_next_stroke() {
    let mut game = free_play();
    let g = game.as_ref();
    // Stroke 1: the 3 alone with the cue ball, potted along the corner's diagonal.
    let balls = [
        BallSetup::at(0, on_the_diagonal(g, 0.60)),
        BallSetup::at(3, on_the_diagonal(g, 0.25)),
    ];
    let (judgement, after) = stroke(game.as_mut(), &balls, std::f64::consts::FRAC_PI_4, 2.0);
    assert!(
        !after.iter().any(|&(n, _)| n == 3),
        "the set-up pots the 3: {after:?}"
    );
    assert!(judgement.fair && judgement.continues, "{judgement:?}");
    assert!(
        judgement.text.contains("the 3 in the"),
        "the stroke says what it pocketed: {:?}",
        judgement.text
    );
    assert!(!judgement.text.starts_with("legal"), "{:?}", judgement.text);
    assert_eq!(game.status(), vec!["balls left: 0".to_owned()]);
    // Stroke 2: the player puts the 3 back by hand (and adds the 9): the rules take the
    // table as the strike finds it. Without that the 3 would be an unknown ball.
    let g = game.as_ref();
    let balls = [
        BallSetup::at(0, on_the_diagonal(g, 0.60)),
        BallSetup::at(3, on_the_diagonal(g, 0.25)),
        BallSetup::at(9, Vec2::new(-0.5, 0.0)),
    ];
    let (judgement, _) = stroke(game.as_mut(), &balls, std::f64::consts::FRAC_PI_4, 2.0);
    assert!(
        judgement.text.contains("the 3 in the"),
        "{:?}",
        judgement.text
    );
    assert_eq!(game.status(), vec!["balls left: 1".to_owned()]);
    assert_eq!(game.turn().ball_on, "any ball");
    assert!(
        game.score_line().starts_with("free play"),
        "no race in free play: {:?}",
        game.score_line()
    );
}

#[test]
fn a_scratch_in_free_play_puts_the_cue_ball_on_the_head_string_and_says_so() {
    let mut game = free_play();
    let g = game.as_ref();
    let balls = [
        BallSetup::at(0, on_the_diagonal(g, 0.40)),
        BallSetup::at(5, Vec2::new(-0.5, 0.2)),
    ];
    let (judgement, after) = stroke(game.as_mut(), &balls, std::f64::consts::FRAC_PI_4, 1.5);
    assert!(
        !after.iter().any(|&(n, _)| n == 0),
        "the set-up scratches: {after:?}"
    );
    // Free play has no fouls; the shooter stays.
    assert!(judgement.fair && judgement.continues, "{judgement:?}");
    let &(ball, at) = judgement.put.last().expect("the cue ball is put back");
    assert_eq!(ball, 0);
    // WPA 1.4's head spot side: the head string is a quarter of the length from the middle.
    let table = game.table();
    assert!(
        (at.x + table.length / 4.0).abs() < 1e-9,
        "on the head string: {at:?}"
    );
    assert!(
        judgement
            .text
            .contains("scratch: the cue ball is back on the head string"),
        "{:?}",
        judgement.text
    );
    assert_eq!(game.turn().place, CueBallPlace::Placed);
}
