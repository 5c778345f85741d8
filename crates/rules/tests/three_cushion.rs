//! Three-cushion under the UMB rules (`billiards_rules::three_cushion`): each test is named
//! after the article it checks (UMB "World rules of carom billiard", 1989: Art. 23/3.3 the
//! opening, Art. 24 the inning, Art. 27 balls in contact, Art. 29 the end, Art. 41 fouls,
//! Art. 83 three cushions), driven by hand-built event lists and by the solver on the carom
//! table.

use billiards_physics::{
    BallId, BallState, Cushion, Event, EventKind, Shot, Simulation, Table, Vec2,
};
use billiards_rules::three_cushion::{
    Ball, Foul, Outcome, Rules, STARTING_SPOT_OFFSET, ThreeCushionError, ThreeCushionGame,
};
use billiards_rules::turn::Seat;

const R: f64 = 0.5 * 0.0615;
const WHITE: BallId = 0;
const YELLOW: BallId = 1;
const RED: BallId = 2;

fn game(rules: Rules) -> ThreeCushionGame {
    ThreeCushionGame::new(rules, &Table::carom_match(), R).unwrap()
}

/// One step of a hand-built stroke of the striker's cue ball.
#[derive(Clone, Copy)]
enum Step {
    /// The cue ball touches a cushion.
    C(Cushion),
    /// The cue ball touches this ball.
    B(BallId),
}
use Step::{B, C};

fn state(p: Vec2) -> BallState {
    BallState {
        position: p,
        ..Default::default()
    }
}

fn event(t: f64, kind: EventKind, a: Vec2, b: Vec2) -> Event {
    Event {
        time: t,
        kind,
        after: [state(a), state(b)],
    }
}

/// A ball placed at `p` by hand (before a stroke).
fn placed(ball: BallId, p: Vec2) -> Event {
    event(0.0, EventKind::Placed { ball }, p, Vec2::ZERO)
}

/// The events of a stroke of ball `cue` doing `steps`, every ball keeping the place the game
/// has it at (the judge reads the order of contacts; where balls rest is not the point here).
fn stroke(g: &ThreeCushionGame, cue: BallId, steps: &[Step]) -> Vec<Event> {
    let at = |id: BallId| g.position(Ball::ALL[id]);
    let mut out = vec![event(
        0.0,
        EventKind::Strike {
            ball: cue,
            shot: Shot::new(0.0, 2.0),
        },
        at(cue),
        Vec2::ZERO,
    )];
    for (k, s) in steps.iter().enumerate() {
        let t = 0.1 * (k + 1) as f64;
        out.push(match *s {
            C(cushion) => event(
                t,
                EventKind::Cushion { ball: cue, cushion },
                at(cue),
                at(cue),
            ),
            B(o) => {
                let (a, b) = (cue.min(o), cue.max(o));
                event(t, EventKind::BallBall { a, b }, at(a), at(b))
            }
        });
    }
    out
}

const FOUR: [Step; 4] = [
    C(Cushion::Foot),
    C(Cushion::Left),
    C(Cushion::Head),
    C(Cushion::Right),
];

/// A's opening played legally without a point (the red directly, then nothing): B to play.
fn after_an_opening_miss(rules: Rules) -> ThreeCushionGame {
    let mut g = game(rules);
    let v = g
        .play(&stroke(&g, WHITE, &[B(RED), C(Cushion::Foot)]))
        .unwrap();
    assert!(!v.point && v.fouls.is_empty(), "{v:?}");
    g
}

#[test]
fn umb_3_3_opening_position_red_on_top_spot_opponent_on_bottom_spot_striker_beside() {
    let g = game(Rules::default());
    let t = Table::carom_match();
    assert_eq!(g.position(Ball::Red), Vec2::new(0.25 * t.length, 0.0));
    assert_eq!(g.position(Ball::Yellow), Vec2::new(-0.25 * t.length, 0.0));
    assert_eq!(
        g.position(Ball::White),
        Vec2::new(-0.25 * t.length, -STARTING_SPOT_OFFSET)
    );
    let n = g.next().unwrap();
    assert_eq!(
        (n.striker, n.cue_ball, n.opening),
        (Seat::A, Ball::White, true)
    );
    assert!(n.frozen_to.is_empty() && !n.equalising);
    assert_eq!((g.scores(), g.innings()), ([0, 0], [1, 0]));
    // The simulation's balls, by id: white, yellow, red.
    let s = g.setups();
    assert_eq!(s.len(), 3);
    assert_eq!(s[2].position, g.position(Ball::Red));
}

#[test]
fn umb_3_3_the_opening_stroke_must_hit_the_red_first_and_directly() {
    // The yellow first: a foul even with three cushions before the red.
    let mut g = game(Rules::default());
    let mut steps = vec![B(YELLOW)];
    steps.extend(FOUR);
    steps.push(B(RED));
    let v = g.play(&stroke(&g, WHITE, &steps)).unwrap();
    assert!(!v.point);
    assert_eq!(
        v.fouls,
        vec![Foul::OpeningNotOnTheRed {
            first: Some(Ball::Yellow),
            cushions_before: 0
        }]
    );
    assert!(v.reason.contains("red first"), "{}", v.reason);
    assert_eq!(v.next.as_ref().unwrap().striker, Seat::B);
    // The red after a cushion: not a direct attack.
    let mut g = game(Rules::default());
    let v = g
        .play(&stroke(&g, WHITE, &[C(Cushion::Foot), B(RED)]))
        .unwrap();
    assert!(matches!(
        v.fouls[..],
        [Foul::OpeningNotOnTheRed {
            first: Some(Ball::Red),
            cushions_before: 1
        }]
    ));
    // The red directly, three cushions, the yellow: a point, A plays on, no longer an opening.
    let mut g = game(Rules::default());
    let v = g
        .play(&stroke(
            &g,
            WHITE,
            &[
                B(RED),
                C(Cushion::Foot),
                C(Cushion::Left),
                C(Cushion::Head),
                B(YELLOW),
            ],
        ))
        .unwrap();
    assert!(v.point && v.fouls.is_empty(), "{v:?}");
    let n = v.next.unwrap();
    assert_eq!((n.striker, n.opening), (Seat::A, false));
}

#[test]
fn umb_article_83_point_needs_three_cushions_before_the_second_ball() {
    let mut g = after_an_opening_miss(Rules::default());
    // B: the white, three cushions, the red.
    let v = g
        .play(&stroke(
            &g,
            YELLOW,
            &[
                B(WHITE),
                C(Cushion::Left),
                C(Cushion::Foot),
                C(Cushion::Right),
                B(RED),
            ],
        ))
        .unwrap();
    assert!(v.point, "{}", v.reason);
    assert_eq!((v.cushions, v.scores), (3, [0, 1]));
    assert!(v.reason.starts_with("Point"), "{}", v.reason);
    // Two cushions before the second ball: no point, though more follow after it.
    let v = g
        .play(&stroke(
            &g,
            YELLOW,
            &[
                B(RED),
                C(Cushion::Left),
                C(Cushion::Foot),
                B(WHITE),
                C(Cushion::Right),
            ],
        ))
        .unwrap();
    assert!(!v.point && v.fouls.is_empty());
    assert_eq!(v.cushions, 2);
    assert!(v.reason.contains("only 2 cushions"), "{}", v.reason);
    assert_eq!(v.scores, [0, 1]);
}

#[test]
fn umb_article_83_cushions_before_the_first_ball_count() {
    for steps in [
        vec![
            C(Cushion::Foot),
            C(Cushion::Left),
            C(Cushion::Head),
            B(RED),
            B(WHITE),
        ],
        vec![
            C(Cushion::Foot),
            B(RED),
            C(Cushion::Left),
            C(Cushion::Head),
            B(WHITE),
        ],
        vec![
            C(Cushion::Foot),
            C(Cushion::Left),
            B(WHITE),
            C(Cushion::Head),
            B(RED),
        ],
    ] {
        let mut g = after_an_opening_miss(Rules::default());
        let v = g.play(&stroke(&g, YELLOW, &steps)).unwrap();
        assert!(v.point && v.cushions == 3, "{}", v.reason);
    }
}

#[test]
fn umb_article_83_the_same_cushion_counts_each_time() {
    let mut g = after_an_opening_miss(Rules::default());
    let steps = [
        B(RED),
        C(Cushion::Left),
        C(Cushion::Left),
        C(Cushion::Left),
        B(WHITE),
    ];
    let v = g.play(&stroke(&g, YELLOW, &steps)).unwrap();
    assert!(v.point && v.cushions == 3, "{}", v.reason);
}

#[test]
fn umb_article_83_touching_the_first_ball_again_is_not_the_second() {
    let mut g = after_an_opening_miss(Rules::default());
    // The red twice with three cushions between, then nothing: only one object ball.
    let mut steps = vec![B(RED)];
    steps.extend(FOUR);
    steps.push(B(RED));
    let v = g.play(&stroke(&g, YELLOW, &steps)).unwrap();
    assert!(!v.point);
    assert!(v.reason.contains("touched only the red"), "{}", v.reason);
    // Neither ball.
    let v = g.play(&stroke(&g, WHITE, &FOUR)).unwrap();
    assert!(!v.point && v.cushions == 4);
    assert!(v.reason.contains("neither"), "{}", v.reason);
}

#[test]
fn umb_article_24_a_point_continues_the_inning_a_miss_passes_it() {
    let mut g = game(Rules::default());
    let point = [
        B(RED),
        C(Cushion::Foot),
        C(Cushion::Left),
        C(Cushion::Head),
        B(YELLOW),
    ];
    for k in 1..=3 {
        let v = g.play(&stroke(&g, WHITE, &point)).unwrap();
        assert_eq!((v.scores, v.innings), ([k, 0], [1, 0]));
        assert_eq!(v.next.unwrap().striker, Seat::A);
    }
    let v = g.play(&stroke(&g, WHITE, &[B(RED)])).unwrap();
    assert_eq!((v.scores, v.innings), ([3, 0], [1, 1]));
    let n = v.next.unwrap();
    assert_eq!((n.striker, n.cue_ball), (Seat::B, Ball::Yellow));
    let v = g.play(&stroke(&g, YELLOW, &[])).unwrap();
    assert_eq!((v.innings, v.next.unwrap().striker), ([2, 1], Seat::A));
}

#[test]
fn umb_article_41_playing_the_opponents_ball_is_a_foul() {
    let mut g = after_an_opening_miss(Rules::default());
    // B strikes the white: a foul, whatever the white then does.
    let steps = [
        B(RED),
        C(Cushion::Foot),
        C(Cushion::Left),
        C(Cushion::Head),
        B(YELLOW),
    ];
    let v = g.play(&stroke(&g, WHITE, &steps)).unwrap();
    assert!(!v.point);
    assert_eq!(
        v.fouls,
        vec![Foul::WrongBall {
            played: Ball::White,
            own: Ball::Yellow
        }]
    );
    assert!(v.reason.starts_with("Foul"), "{}", v.reason);
    assert_eq!((v.scores, v.next.unwrap().striker), ([0, 0], Seat::A));
}

/// Points for the striker: red, three cushions, the other white.
fn point(g: &mut ThreeCushionGame) -> billiards_rules::three_cushion::Verdict {
    let cue = match g.next().unwrap().striker {
        Seat::A => (WHITE, YELLOW),
        Seat::B => (YELLOW, WHITE),
    };
    let steps = [
        B(RED),
        C(Cushion::Foot),
        C(Cushion::Left),
        C(Cushion::Head),
        B(cue.1),
    ];
    g.play(&stroke(g, cue.0, &steps)).unwrap()
}

fn miss(g: &mut ThreeCushionGame) -> billiards_rules::three_cushion::Verdict {
    let cue = match g.next().unwrap().striker {
        Seat::A => WHITE,
        Seat::B => YELLOW,
    };
    g.play(&stroke(g, cue, &[B(RED)])).unwrap()
}

#[test]
fn umb_article_29_the_equalising_inning_gives_the_second_player_the_same_innings() {
    let rules = Rules {
        target: 2,
        ..Rules::default()
    };
    // A reaches the distance in the first inning: B plays one inning; a miss ends it, A wins.
    let mut g = game(rules);
    point(&mut g);
    let v = point(&mut g);
    assert_eq!((v.scores, v.end), ([2, 0], None));
    let n = v.next.unwrap();
    assert!(n.equalising && n.striker == Seat::B);
    let v = miss(&mut g);
    assert_eq!(
        (v.end, v.next, v.innings),
        (Some(Outcome::Won(Seat::A)), None, [1, 1])
    );
    assert_eq!(g.play(&[]), Err(ThreeCushionError::GameOver));
    // B reaches the distance in the equalising inning: a draw.
    let mut g = game(rules);
    point(&mut g);
    point(&mut g);
    point(&mut g);
    let v = point(&mut g);
    assert_eq!((v.scores, v.end), ([2, 2], Some(Outcome::Draw)));
    // Without the rule, A's second point wins at once.
    let mut g = game(Rules {
        equal_innings: false,
        ..rules
    });
    point(&mut g);
    assert_eq!(point(&mut g).end, Some(Outcome::Won(Seat::A)));
    // B reaching the distance first has had as many innings as A: B wins at once.
    let mut g = game(rules);
    miss(&mut g);
    point(&mut g);
    assert_eq!(point(&mut g).end, Some(Outcome::Won(Seat::B)));
}

#[test]
fn umb_article_27_a_frozen_cue_ball_may_have_the_balls_set_up_on_their_spots() {
    let mut g = after_an_opening_miss(Rules::default());
    let spots = *g.spots();
    // B's yellow frozen to the red mid-table: B plays away from it (a cushion first) and
    // misses: no foul.
    let (y, r) = (Vec2::new(0.3, 0.2), Vec2::new(0.3 + 2.0 * R, 0.2));
    let shot = Shot::new(std::f64::consts::PI, 1.0);
    let away = [
        placed(YELLOW, y),
        placed(RED, r),
        event(0.0, EventKind::Strike { ball: YELLOW, shot }, y, Vec2::ZERO),
        event(
            0.5,
            EventKind::Cushion {
                ball: YELLOW,
                cushion: Cushion::Head,
            },
            Vec2::new(-1.0, 0.2),
            Vec2::ZERO,
        ),
    ];
    let v = g.play(&away).unwrap();
    assert!(v.fouls.is_empty() && !v.point, "{v:?}");
    assert!(v.next.unwrap().frozen_to.is_empty());
    // A's white frozen to the red: the balls may be set up again.
    let mut g = after_an_opening_miss(Rules::default());
    let w = Vec2::new(0.3, 0.2);
    let pre = [placed(WHITE, w), placed(RED, w + Vec2::new(0.0, 2.0 * R))];
    let strike_yellow = |g: &ThreeCushionGame| {
        let mut e = pre.to_vec();
        e.extend(stroke(g, YELLOW, &[]));
        e
    };
    let v = g.play(&strike_yellow(&g)).unwrap();
    assert_eq!(v.next.unwrap().frozen_to, vec![Ball::Red]);
    let p = g.respot_frozen().unwrap();
    // The red on the top spot, the white (the cue ball) on the bottom spot: but the yellow
    // stands there, so the white takes the yellow's spot, the centre.
    assert_eq!(p[Ball::Red.index()], spots.top);
    assert_eq!(p[Ball::Yellow.index()], spots.bottom);
    assert_eq!(p[Ball::White.index()], spots.centre);
    assert!(g.next().unwrap().frozen_to.is_empty());
    assert_eq!(
        g.respot_frozen(),
        Err(ThreeCushionError::NotFrozen("white"))
    );
}

#[test]
fn umb_article_27_playing_straight_into_the_frozen_ball_is_a_foul() {
    let mut g = after_an_opening_miss(Rules::default());
    let y = Vec2::new(0.3, 0.2);
    let mut events = vec![placed(YELLOW, y), placed(RED, y + Vec2::new(2.0 * R, 0.0))];
    let mut s = stroke(&g, YELLOW, &[B(RED), C(Cushion::Foot), C(Cushion::Left)]);
    s.extend(
        stroke(&g, YELLOW, &[C(Cushion::Head), B(WHITE)])
            .into_iter()
            .skip(1),
    );
    s[0].after[0].position = y;
    events.extend(s);
    let v = g.play(&events).unwrap();
    assert_eq!(v.fouls, vec![Foul::IntoTheFrozenBall { ball: Ball::Red }]);
    assert!(!v.point, "three cushions, both balls, but a foul");
}

#[test]
fn strokes_the_rules_cannot_judge_are_refused_with_a_reason() {
    let mut g = game(Rules::default());
    assert_eq!(g.play(&[]), Err(ThreeCushionError::NoStrike));
    let mut two = stroke(&g, WHITE, &[]);
    two.extend(stroke(&g, WHITE, &[]));
    assert_eq!(g.play(&two), Err(ThreeCushionError::SeveralStrikes(2)));
    let mut s = stroke(&g, WHITE, &[]);
    s.push(event(
        1.0,
        EventKind::Pocketed {
            ball: RED,
            pocket: billiards_physics::Pocket::FootLeft,
        },
        Vec2::ZERO,
        Vec2::ZERO,
    ));
    assert_eq!(g.play(&s), Err(ThreeCushionError::Pocketed(RED)));
    let mut s = stroke(&g, WHITE, &[]);
    s.push(placed(7, Vec2::ZERO));
    assert_eq!(g.play(&s), Err(ThreeCushionError::UnknownBall(7)));
    let mut s = stroke(&g, WHITE, &[]);
    s[0].after[0].position = Vec2::new(1.0, 0.5);
    let e = g.play(&s).unwrap_err();
    assert!(e.to_string().contains("the game has it"), "{e}");
    // Nothing was judged: still A's opening.
    assert_eq!(g.innings(), [1, 0]);
    assert!(g.next().unwrap().opening);
    let bad = Rules {
        target: 0,
        ..Rules::default()
    };
    assert!(ThreeCushionGame::new(bad, &Table::carom_match(), R).is_err());
    assert!(ThreeCushionGame::new(Rules::default(), &Table::carom_match(), 0.2).is_err());
}

// ---- The solver on the carom table -------------------------------------------------------

/// The paper's model with the carom ball: no spin, so a path is straight between mirror
/// rebounds (e = 1) and a plan drawn with reflections is the path the solver takes.
fn paper_carom() -> billiards_physics::Params {
    billiards_physics::Params {
        model: billiards_physics::Model::Paper(billiards_physics::PaperModel::default()),
        ..billiards_physics::Params::carom()
    }
}

/// The balls at `at` (by id) placed by hand, then `cue` struck with `shot` and run to rest:
/// the stroke's events as the game receives them.
fn solver_stroke(at: [Vec2; 3], cue: BallId, shot: Shot) -> Vec<Event> {
    let setups: Vec<_> = (0..3)
        .map(|i| billiards_physics::BallSetup::at(i as u8, at[i]))
        .collect();
    let mut sim = Simulation::new(Table::carom_match(), paper_carom(), &setups).unwrap();
    sim.strike(cue, shot).unwrap();
    sim.run_to_rest().unwrap();
    let mut events: Vec<Event> = (0..3).map(|i| placed(i, at[i])).collect();
    events.extend_from_slice(sim.history().events());
    events
}

/// The aim from `from` that reaches `to` after rebounding off `cushions` in that order
/// (mirror images of `to` across the cushion lines the centre meets, last cushion first),
/// and the direction the ball arrives in.
fn bank(from: Vec2, to: Vec2, cushions: &[Cushion]) -> (f64, Vec2) {
    let t = Table::carom_match();
    let (bx, by) = (0.5 * t.length - R, 0.5 * t.width - R);
    let mirror = |p: Vec2, c: Cushion| match c {
        Cushion::Head => Vec2::new(-2.0 * bx - p.x, p.y),
        Cushion::Foot => Vec2::new(2.0 * bx - p.x, p.y),
        Cushion::Left => Vec2::new(p.x, 2.0 * by - p.y),
        Cushion::Right => Vec2::new(p.x, -2.0 * by - p.y),
    };
    let image = cushions.iter().rev().fold(to, |p, &c| mirror(p, c));
    let d = (image - from).normalized().unwrap();
    let arrive = cushions.iter().fold(d, |d, c| match c {
        Cushion::Head | Cushion::Foot => Vec2::new(-d.x, d.y),
        Cushion::Left | Cushion::Right => Vec2::new(d.x, -d.y),
    });
    (d.angle(), arrive)
}

/// B's planned stroke: the yellow from `from` off `cushions` to `ghost`, where it cuts the
/// white thinly (its centre 80 degrees off the path) and runs on (the paper model keeps the
/// tangential part) 0.4 m into the red. The layout by id, and the shot.
fn planned(from: Vec2, ghost: Vec2, cushions: &[Cushion]) -> ([Vec2; 3], Shot) {
    let (angle, d) = bank(from, ghost, cushions);
    let cut = 80f64.to_radians();
    let n = Vec2::from_angle(d.angle() + cut);
    let white = ghost + n * (2.0 * R);
    let on = (d - n * d.dot(n)).normalized().unwrap();
    let red = ghost + on * 0.4;
    ([white, from, red], Shot::new(angle, 6.0))
}

/// A's opening in the solver: the white from its starting spot full at the red, hard enough
/// to reach it: the red first and directly, then the white stops dead (equal masses): no
/// point, no foul, B to play.
fn solver_opening() -> ThreeCushionGame {
    let mut g = game(Rules::default());
    let at = [Ball::White, Ball::Yellow, Ball::Red].map(|b| g.position(b));
    let aim = (at[2] - at[0]).angle();
    let v = g
        .play(&solver_stroke(at, WHITE, Shot::new(aim, 2.5)))
        .unwrap();
    assert!(v.fouls.is_empty() && !v.point, "{v:?}");
    assert_eq!(v.next.unwrap().striker, Seat::B);
    g
}

#[test]
fn umb_article_83_a_planned_three_cushion_point_scores_in_the_solver() {
    let mut g = solver_opening();
    let cushions = [Cushion::Foot, Cushion::Left, Cushion::Head];
    let (at, shot) = planned(Vec2::new(-0.9, -0.3), Vec2::new(-0.6, 0.2), &cushions);
    let v = g.play(&solver_stroke(at, YELLOW, shot)).unwrap();
    assert!(v.point, "{}", v.reason);
    assert_eq!((v.cushions, v.scores), (3, [0, 1]));
    assert!(v.reason.contains("the white and the red"), "{}", v.reason);
    assert_eq!(v.next.unwrap().striker, Seat::B);
}

#[test]
fn umb_article_83_a_planned_two_cushion_carom_does_not_score_in_the_solver() {
    let mut g = solver_opening();
    let cushions = [Cushion::Foot, Cushion::Left];
    let (at, shot) = planned(Vec2::new(-0.9, -0.3), Vec2::new(-0.6, 0.2), &cushions);
    let v = g.play(&solver_stroke(at, YELLOW, shot)).unwrap();
    assert!(!v.point, "{}", v.reason);
    assert_eq!(v.cushions, 2);
    assert!(v.reason.contains("only 2 cushions"), "{}", v.reason);
    assert_eq!((v.scores, v.next.unwrap().striker), ([0, 0], Seat::A));
}
