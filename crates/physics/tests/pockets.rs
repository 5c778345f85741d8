//! Pockets with rounded jaws: pocketing through the opening, rattling off the jaws, and no
//! ball ever ending up inside a cushion or a jaw.

mod common;
use billiards_physics::*;
use common::*;

const JAW: f64 = 0.015;

fn spin_params() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

fn jaw_table() -> Table {
    Table::wpa_8ft().with_jaws(JAW)
}

/// Every sampled state of every ball in play is on the table: inside the cushion lines, or in
/// a mouth on the table side of its opening and clear of every jaw.
fn assert_inside(sim: &Simulation) {
    let t = *sim.table();
    let r = sim.params().ball.radius;
    let b = t.centre_bounds(r);
    let jaws = t.jaws();
    let openings = t.openings();
    let h = sim.history();
    let mut times: Vec<f64> = h.events().iter().map(|e| e.time).collect();
    let mids: Vec<f64> = times.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    times.extend(mids);
    for time in times {
        for (i, s) in h.states_at(time).iter().enumerate() {
            if !s.motion.on_table() {
                continue;
            }
            let p = s.position;
            for j in &jaws {
                let d = (p - j.centre).length() - (r + JAW);
                assert!(
                    d > -1e-9,
                    "ball {i} inside a jaw of {:?} by {d} at t = {time}",
                    j.pocket
                );
            }
            let inside = p.x.abs() <= b.x + 1e-9 && p.y.abs() <= b.y + 1e-9;
            if !inside {
                let o = openings
                    .iter()
                    .min_by(|a, c| {
                        (a.offset + a.normal.dot(p)).total_cmp(&(c.offset + c.normal.dot(p)))
                    })
                    .unwrap();
                assert!(
                    o.offset + o.normal.dot(p) > -1e-9,
                    "ball {i} beyond the opening of {:?} at t = {time}: {p:?}",
                    o.pocket
                );
                // Beyond a cushion line only inside a mouth.
                let in_mouth = (p.x.abs() > b.x && p.y.abs() > 0.5 * t.width - t.corner_leg())
                    || (p.y.abs() > b.y
                        && (p.x.abs() < 0.5 * t.side_mouth
                            || p.x.abs() > 0.5 * t.length - t.corner_leg()));
                assert!(in_mouth, "ball {i} through a cushion at t = {time}: {p:?}");
            }
        }
    }
}

fn shoot(from: Vec2, toward: Vec2, speed: f64) -> Simulation {
    let mut sim = Simulation::new(jaw_table(), spin_params(), &[BallSetup::at(0, from)]).unwrap();
    sim.strike(0, Shot::new((toward - from).angle(), speed))
        .unwrap();
    sim.run_to_rest().unwrap();
    sim
}

#[test]
fn ball_straight_into_a_corner_pocket_drops_without_touching_a_cushion() {
    let t = jaw_table();
    let sim = shoot(
        Vec2::new(0.5, 0.1),
        t.pocket_position(Pocket::FootLeft),
        2.0,
    );
    let kinds: Vec<EventKind> = sim.history().events().iter().map(|e| e.kind).collect();
    assert!(
        kinds.contains(&EventKind::Pocketed {
            ball: 0,
            pocket: Pocket::FootLeft
        }),
        "{kinds:?}"
    );
    assert!(
        !kinds
            .iter()
            .any(|k| matches!(k, EventKind::Cushion { .. } | EventKind::Jaw { .. })),
        "{kinds:?}"
    );
}

#[test]
fn ball_into_the_middle_of_a_side_pocket_drops() {
    let sim = shoot(Vec2::new(0.0, 0.0), Vec2::new(0.0, 1.0), 1.5);
    assert_eq!(sim.ball(0).motion, Motion::Pocketed(Pocket::SideLeft));
}

#[test]
fn ball_aimed_at_a_jaw_rebounds_off_it_and_stays_on_the_table() {
    let t = jaw_table();
    let jaw = t
        .jaws()
        .into_iter()
        .find(|j| j.pocket == Pocket::SideLeft)
        .unwrap();
    // Straight at the arc's centre: a head-on hit on the rounded cushion end.
    let sim = shoot(Vec2::new(jaw.centre.x, 0.0), jaw.centre, 1.0);
    let first = sim
        .history()
        .events()
        .iter()
        .find(|e| e.kind.is_collision())
        .unwrap();
    assert_eq!(
        first.kind,
        EventKind::Jaw {
            ball: 0,
            pocket: Pocket::SideLeft
        }
    );
    assert!(sim.ball(0).motion.on_table());
    assert!(sim.ball(0).position.y < 0.0 + 0.5 * t.width, "it came back");
    assert_inside(&sim);
}

#[test]
fn ball_rolling_along_the_rail_past_a_side_pocket_is_not_swallowed_by_the_cushion() {
    let t = jaw_table();
    let r = spin_params().ball.radius;
    let y = t.centre_bounds(r).y - 1e-6;
    let sim = shoot(Vec2::new(-0.6, y), Vec2::new(0.6, y), 2.0);
    assert_inside(&sim);
}

#[test]
fn pocket_jaws_hit_at_every_angle_never_let_a_ball_through_a_cushion() {
    let t = jaw_table();
    let mut pocketed = 0;
    let mut rattled = 0;
    for pocket in [Pocket::FootLeft, Pocket::SideLeft] {
        let target = t.pocket_position(pocket);
        for k in 0..=40 {
            // Approach directions spread over the half plane facing the pocket.
            let base = if pocket.is_corner() {
                std::f64::consts::FRAC_PI_4
            } else {
                std::f64::consts::FRAC_PI_2
            };
            let ang = base + (k as f64 / 40.0 - 0.5) * 2.6;
            let from = target - Vec2::from_angle(ang) * 0.45;
            let from = Vec2::new(from.x.clamp(-1.0, 1.0), from.y.clamp(-0.5, 0.5));
            for offset in [-0.03, 0.0, 0.02] {
                let aim = target + Vec2::from_angle(ang).perp() * offset;
                let sim = shoot(from, aim, 2.5);
                assert_inside(&sim);
                pocketed += usize::from(!sim.ball(0).motion.on_table());
                rattled += usize::from(
                    sim.history()
                        .events()
                        .iter()
                        .any(|e| matches!(e.kind, EventKind::Jaw { .. })),
                );
            }
        }
    }
    assert!(
        pocketed > 20 && rattled > 20,
        "pocketed {pocketed}, rattled {rattled}"
    );
}

#[test]
fn break_on_a_table_with_jaws_keeps_every_ball_on_the_table() {
    for speed in [8.0, 11.0] {
        let table = jaw_table();
        let p = spin_params();
        let balls = Rack::FifteenBall.layout(&table, &p.ball);
        let mut sim = Simulation::new(table, p, &balls).unwrap();
        sim.strike(0, Shot::new(0.003, speed)).unwrap();
        sim.run_to_rest().unwrap();
        assert_inside(&sim);
        assert_no_overlap_or_escape_allowing_mouths(&sim);
    }
}

/// Pairwise overlap check only (the cushion check is `assert_inside`).
fn assert_no_overlap_or_escape_allowing_mouths(sim: &Simulation) {
    let r = sim.params().ball.radius;
    let h = sim.history();
    for e in h.events() {
        let s = h.states_at(e.time);
        for i in 0..s.len() {
            for j in i + 1..s.len() {
                if s[i].motion.on_table() && s[j].motion.on_table() {
                    let overlap = 2.0 * r - (s[i].position - s[j].position).length();
                    assert!(overlap <= 1e-9, "balls {i},{j} overlap by {overlap}");
                }
            }
        }
    }
    let _ = rel(1.0, 1.0);
}
