//! The computer plays whole matches of every game with a winner through the one game
//! interface alone (issue 50): one search, one match loop, no game named.

use billiards_ai::any_match::{MatchRun, Seating, play_match};
use billiards_ai::{Level, Player};
use billiards_physics::{Model, Params, SpinModel};
use billiards_rules::catalog::{GAMES, MatchSettings};

fn run(id: &str, seed: u64) -> MatchRun {
    let entry = GAMES.iter().find(|g| g.id == id).unwrap();
    let players = ["A".to_owned(), "B".to_owned()];
    let mut game = entry.start(&MatchSettings::new(players, 1, seed)).unwrap();
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let players = [Player::Computer(Level::Medium); 2];
    let mut run = play_match(
        game.as_mut(),
        &Seating::new(players, params, seed, 600),
        &mut |_| {},
    )
    .unwrap();
    // Decision times are the machine's, not the match's.
    for t in &mut run.tally {
        (t.decision_secs, t.max_decision_secs) = (0.0, 0.0);
    }
    run
}

#[test]
fn every_game_with_a_winner_is_played_to_the_end_between_computers() {
    for entry in GAMES.iter().filter(|g| g.id != "free-play") {
        let r = run(entry.id, 5);
        assert!(
            r.winner.is_some() && r.games() == 1,
            "{}: no winner in {} strokes: {}",
            entry.label,
            r.strokes,
            r.score_line
        );
    }
}

#[test]
fn the_same_seed_plays_the_same_match() {
    let (a, b) = (run("nine-ball", 9), run("nine-ball", 9));
    assert_eq!(a, b);
}

/// A drill is a one-player game behind the same interface: the computer plays a session of
/// every standard drill to its end, each try judged by the drill's goals.
#[test]
fn every_standard_drill_is_a_session_played_through_the_interface() {
    use billiards_rules::Drill;
    use billiards_rules::drill_game::DrillGame;
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/drills");
    let drills = Drill::load_dir(&dir).unwrap();
    assert!(drills.len() >= 10, "{} drills", drills.len());
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    for loaded in drills {
        let mut drill = loaded.1.unwrap();
        drill.tries = 3;
        let name = drill.name.clone();
        let mut game = DrillGame::new(drill, "A".to_owned(), params.ball).unwrap();
        let players = [Player::Computer(Level::Medium); 2];
        let r = play_match(
            &mut game,
            &Seating::new(players, params, 1, 100),
            &mut |_| {},
        )
        .unwrap();
        assert_eq!(r.games(), 3, "{name}: three tries judged: {}", r.score_line);
        assert_eq!(r.winner, Some(billiards_rules::Seat::A), "{name}");
        assert_eq!(game.score.tries, 3, "{name}");
        assert!(r.score_line.contains("of 3 tries made"), "{}", r.score_line);
    }
}
