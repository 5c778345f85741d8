//! The aiming aid's prediction against the solver and the closed forms.

use super::*;
use billiards_physics::{Params, Table, Vec2};

fn resting(number: u8, x: f64, y: f64) -> (u8, BallState) {
    let setup = BallSetup::at(number, Vec2::new(x, y));
    let sim = Simulation::new(Table::wpa_8ft(), Params::default(), &[setup]).unwrap();
    (number, sim.ball(0))
}

#[test]
fn ghost_ball_touches_the_object_ball_on_a_straight_shot() {
    let balls = [resting(0, -0.5, 0.0), resting(1, 0.3, 0.0)];
    let params = Params::default();
    let p = predict(Table::wpa_8ft(), params, &balls, 0, Shot::new(0.0, 2.0), 1);
    let (kind, ghost) = p.contact.unwrap();
    assert_eq!(kind, FirstContact::Ball { number: 1 });
    // Centre to centre 2R at contact, on the line of the shot.
    let two_r = 2.0 * params.ball.radius;
    assert!((ghost.x - (0.3 - two_r)).abs() < 1e-9, "{ghost:?}");
    assert!(ghost.y.abs() < 1e-12);
    // Head on with equal masses: the object ball goes straight on.
    let last = *p.after_of(1).unwrap().last().unwrap();
    assert!(last.x > 0.3 && last.y.abs() < 1e-9);
}

#[test]
fn a_cut_sends_the_object_ball_along_the_line_of_centres() {
    let balls = [resting(0, -0.5, 0.0), resting(1, 0.3, 0.03)];
    let params = Params::default();
    let p = predict(Table::wpa_8ft(), params, &balls, 0, Shot::new(0.0, 2.0), 1);
    let (_, ghost) = p.contact.unwrap();
    let centres = (DVec2::new(0.3, 0.03) - ghost).normalize();
    let moved = (p.after_of(1).unwrap()[SAMPLES_PER_PIECE / 2] - DVec2::new(0.3, 0.03)).normalize();
    // The paper's model has no ball friction: no throw, so exactly the line of centres.
    assert!(centres.angle_to(moved).abs() < 1e-9);
}

#[test]
fn a_miscue_is_reported_not_drawn() {
    let balls = [resting(0, -0.5, 0.0)];
    let params = Params {
        model: billiards_physics::Model::Spin(Default::default()),
        ..Params::default()
    };
    let shot = Shot {
        tip: billiards_physics::TipOffset {
            side: 0.6,
            height: 0.0,
        },
        ..Shot::new(0.0, 2.0)
    };
    let p = predict(Table::wpa_8ft(), params, &balls, 0, shot, 1);
    assert!(p.note.unwrap().contains("miscue"));
    assert!(p.path.is_empty());
}

#[test]
fn a_lone_cue_ball_hits_a_cushion() {
    let balls = [resting(0, 0.0, 0.0)];
    let p = predict(
        Table::wpa_8ft(),
        Params::default(),
        &balls,
        0,
        Shot::new(0.0, 3.0),
        1,
    );
    let (kind, ghost) = p.contact.unwrap();
    assert_eq!(kind, FirstContact::Cushion);
    let radius = Params::default().ball.radius;
    assert!((ghost.x - (Table::wpa_8ft().length / 2.0 - radius)).abs() < 1e-9);
}

/// A full-draw stop shot: the object ball goes on and the cue ball comes back by more
/// than a metre; the aid shows all of that, not a centimetre of it.
#[test]
fn a_draw_shot_shows_the_cue_ball_coming_back() {
    let balls = [resting(0, -0.6, 0.0), resting(1, 0.0, 0.0)];
    let params = Params {
        model: billiards_physics::Model::Spin(Default::default()),
        ..Params::default()
    };
    let shot = Shot {
        tip: billiards_physics::TipOffset {
            side: 0.0,
            height: -0.45,
        },
        ..Shot::new(0.0, 6.0)
    };
    let p = predict(Table::wpa_8ft(), params, &balls, 0, shot, 2);
    assert_eq!(p.contact.unwrap().0, FirstContact::Ball { number: 1 });
    let cue = p.after_of(0).expect("the cue ball moves after the contact");
    let ghost = p.contact.unwrap().1;
    let back = cue.iter().map(|q| ghost.x - q.x).fold(0.0, f64::max);
    assert!(back > 1.0, "the cue ball comes back {back} m");
    // The same shot run by the solver to rest: the cue ball's path reaches where it
    // really goes (its next two contacts or rest), so the drawn end is a real position.
    assert!(p.after_of(1).unwrap().len() > SAMPLES_PER_PIECE);
}

/// An elevated cue with right english: the drawn path curves right of the cue line
/// (swerve, the cue ball alone on the table), where a level cue's stays on it.
#[test]
fn an_elevated_cue_with_english_draws_a_curved_path() {
    let balls = [resting(0, -0.8, 0.0)];
    let params = Params {
        model: billiards_physics::Model::Spin(Default::default()),
        ..Params::default()
    };
    let shot = |elevation: f64| Shot {
        tip: billiards_physics::TipOffset {
            side: 0.3,
            height: 0.0,
        },
        elevation: elevation.to_radians(),
        ..Shot::new(0.0, 2.0)
    };
    let off_line = |p: &AimPrediction| p.path.iter().map(|q| q.y).fold(0.0, f64::min);
    let level = predict(Table::wpa_8ft(), params, &balls, 0, shot(0.0), 2);
    let raised = predict(Table::wpa_8ft(), params, &balls, 0, shot(20.0), 2);
    assert!(off_line(&level).abs() < 1e-9, "{}", off_line(&level));
    // Right english (+side) curves toward -y (right of a cue pointing +x).
    assert!(off_line(&raised) < -0.01, "{}", off_line(&raised));
}

/// Each ball's path ends at its N-th contact after the first: more contacts, longer paths.
#[test]
fn paths_end_after_the_chosen_number_of_contacts() {
    let balls = [resting(0, -0.5, 0.05), resting(1, 0.3, 0.0)];
    let params = Params::default();
    let length = |p: &AimPrediction, n| {
        p.after_of(n)
            .unwrap()
            .windows(2)
            .map(|w| w[0].distance(w[1]))
            .sum::<f64>()
    };
    let shot = Shot::new(0.0, 4.0);
    let one = predict(Table::wpa_8ft(), params, &balls, 0, shot, 1);
    let three = predict(Table::wpa_8ft(), params, &balls, 0, shot, 3);
    // The object ball takes three cushions; the cue ball drops in a corner pocket (its
    // path ends there however many contacts are asked for).
    let (a, b) = (length(&one, 1), length(&three, 1));
    assert!(b > a + 1.0, "{a} m after one contact, {b} m after three");
    assert_eq!(length(&one, 0), length(&three, 0));
}

/// A ball hit after a drawn path has ended (here: the object ball's path ends at its first
/// cushion, then it rolls on into the 2) is not drawn: the aid would show a ball set moving
/// by nothing it shows (issue 28, item 10).
#[test]
fn a_ball_hit_past_the_end_of_a_drawn_path_is_not_drawn() {
    let params = Params::default();
    let shot = Shot::new(0.0, 3.0);
    let two = [resting(0, -0.5, 0.05), resting(1, 0.3, 0.0)];
    let free = predict(Table::wpa_8ft(), params, &two, 0, shot, 3);
    let cushion = *predict(Table::wpa_8ft(), params, &two, 0, shot, 1)
        .after_of(1)
        .unwrap()
        .last()
        .unwrap();
    // A point of the object ball's free path 0.3 m past its first cushion.
    let path = free.after_of(1).unwrap();
    let at = path.iter().position(|p| *p == cushion).unwrap();
    let mut run = 0.0;
    let beyond = path[at..]
        .windows(2)
        .find(|w| {
            run += w[0].distance(w[1]);
            run > 0.3
        })
        .unwrap()[1];
    let three = [two[0], two[1], resting(2, beyond.x, beyond.y)];
    let open = predict(Table::wpa_8ft(), params, &three, 0, shot, 2);
    assert!(open.after_of(2).is_some(), "the 2 is hit on a drawn path");
    let ended = predict(Table::wpa_8ft(), params, &three, 0, shot, 1);
    assert!(ended.after_of(1).is_some());
    assert!(
        ended.after_of(2).is_none(),
        "the 2 is hit after the 1's drawn path ended"
    );
}

/// Issue 52: the aiming aid draws a jump's flight: the cue ball's path before any contact
/// rises off the cloth (its apex within 1 mm of the closed form `v_z^2 / 2g` of its sampled
/// take-off) and comes down, each landing found by `landings_in` where the sampled height is
/// back on the cloth, the first beyond the strike along the aim; a level shot has no heights.
#[test]
fn the_aim_draws_a_jumps_arc_and_its_landings() {
    use billiards_physics::{Model, SpinModel};
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    };
    let balls = [resting(0, -0.8, 0.0)];
    let level = predict(Table::wpa_8ft(), params, &balls, 0, Shot::new(0.0, 3.0), 1);
    assert!(
        level.path_heights.is_empty(),
        "a level shot stays on the cloth"
    );
    let jump = Shot {
        elevation: 50f64.to_radians(),
        ..Shot::new(0.0, 4.0)
    };
    let p = predict(Table::wpa_8ft(), params, &balls, 0, jump, 1);
    assert_eq!(p.path.len(), p.path_heights.len());
    let apex = p.path_heights.iter().copied().fold(0.0, f64::max);
    assert!(apex > 0.005, "the cue ball leaves the cloth: apex {apex}");
    // The closed form from the solver's own take-off speed.
    let mut sim = Simulation::new(
        Table::wpa_8ft(),
        params,
        &[BallSetup::at(0, Vec2::new(-0.8, 0.0))],
    )
    .unwrap();
    sim.strike(0, jump).unwrap();
    let vz = sim.ball(0).vertical;
    let g = params.gravity;
    assert!(
        (apex - vz * vz / (2.0 * g)).abs() < 1e-3,
        "apex {apex} against {}",
        vz * vz / (2.0 * g)
    );
    let landings: Vec<usize> = landings_in(&p.path_heights).collect();
    assert!(!landings.is_empty(), "{:?}", p.path_heights);
    let first = p.path[landings[0]];
    assert!(first.x > -0.8 && first.y.abs() < 1e-9, "{first:?}");
}
