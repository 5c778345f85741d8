//! Cluster impacts in a break: one impact for a frozen rack, the balls leaving it with no
//! pair closer than touching and no touching pair approaching, every invariant of the
//! monitor kept, and a ball with no neighbour within reach left to the exact pair law.

use billiards_physics::*;

fn spin() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

/// Index of the first ball–ball event in `sim`'s history.
fn first_contact(sim: &Simulation) -> usize {
    let events = sim.history().events();
    events
        .iter()
        .position(|e| matches!(e.kind, EventKind::BallBall { .. }))
        .expect("a contact")
}

/// The states just after the first ball–ball event's instant (the whole impact), the number
/// of events at that instant, and the simulation run on to rest under the monitor.
fn after_first_impact(balls: &[BallSetup], speed: f64) -> (Simulation, Vec<BallState>, usize) {
    let table = Table::wpa_9ft().with_jaws(0.015);
    let mut sim = Simulation::new(table, spin(), balls).unwrap();
    let aim = (balls[1].position - balls[0].position).angle();
    sim.strike(0, Shot::new(aim, speed)).unwrap();
    let mut monitor = check::Monitor::new(&sim, check::Tolerances::default()).unwrap();
    let t0 = loop {
        let e = monitor.step(&mut sim).unwrap().expect("an event");
        if matches!(e.kind, EventKind::BallBall { .. }) {
            break e.time;
        }
    };
    // A cluster impact's events are all recorded at once (step_event hands them out one a
    // call); anything else at that instant would come from a new prediction.
    while sim.next_event_time() == Some(t0) {
        monitor.step(&mut sim).unwrap();
    }
    let at_t0 = sim
        .history()
        .events()
        .iter()
        .filter(|e| e.time == t0)
        .count();
    let states = (0..sim.ball_count()).map(|i| sim.ball(i)).collect();
    monitor.run_to_rest(&mut sim).unwrap();
    (sim, states, at_t0)
}

#[test]
fn a_frozen_rack_breaks_in_one_impact_leaving_no_touching_pair_approaching() {
    let table = Table::wpa_9ft();
    let r = spin().ball.radius;
    for speed in [2.0, 11.0] {
        let mut balls = Rack::Tight.layout(&table, &spin().ball);
        balls[0].position = Vec2::new(-0.6, 0.05);
        let (sim, states, at_t0) = after_first_impact(&balls, speed);
        assert!(sim.cluster_impacts() >= 1);
        let impact = sim
            .history()
            .impact_of(first_contact(&sim))
            .expect("the first contact is an impact");
        assert_eq!(at_t0, impact.len(), "nothing else at that instant");
        for (i, a) in states.iter().enumerate() {
            for b in &states[i + 1..] {
                let d = b.position - a.position;
                let gap = d.length() - 2.0 * r;
                assert!(gap > -1e-9, "overlap {gap}");
                if gap < 1e-9 {
                    let closing = (a.velocity - b.velocity).dot(d * (1.0 / d.length()));
                    assert!(
                        closing <= 1e-12 * speed,
                        "touching pair closing at {closing}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_pair_with_no_neighbour_within_reach_keeps_the_exact_law() {
    // Cue ball into a ball whose neighbour is 5 mm away: more than the 2.4 mm one contact
    // closes at 10 m/s, so the first contact is the plain pair law (no impact), as an
    // isolated pair.
    let r = spin().ball.radius;
    let balls = [
        BallSetup::at(0, Vec2::new(-0.5, 0.0)),
        BallSetup::at(1, Vec2::new(0.0, 0.0)),
        BallSetup::at(2, Vec2::new(2.0 * r + 5e-3, 0.0)),
    ];
    let (sim, states, at_t0) = after_first_impact(&balls, 10.0);
    assert_eq!(at_t0, 1);
    assert!(sim.history().impact_of(first_contact(&sim)).is_none());
    // Head on, no spin: 1 leaves at (1 + e)/2 of the cue ball's speed at contact.
    let e = 0.95;
    let v1 = states[1].velocity.x;
    let v0 = states[0].velocity.x + v1;
    assert!((v1 / v0 - 0.5 * (1.0 + e)).abs() < 1e-12, "{}", v1 / v0);
    // The same with the neighbour at 1 mm: one impact of three balls.
    let mut near = balls;
    near[2].position.x = 2.0 * r + 1e-3;
    let (sim, _, at_t0) = after_first_impact(&near, 10.0);
    assert!(sim.history().impact_of(first_contact(&sim)).is_some() && at_t0 == 2);
}

/// A frozen diamond (rows of `widths` balls) with its apex at `(0.6, 0)`, every pair of
/// neighbours 1 nm apart, and the cue ball on the long axis at `(-0.6, 0)`: a scene exactly
/// symmetric under `y -> -y` (each ball's `y` is an exact negation of its partner's).
fn frozen_rack(widths: &[usize]) -> Vec<BallSetup> {
    let r = spin().ball.radius;
    let d = 2.0 * r + 1e-9;
    let mut balls = vec![BallSetup::at(0, Vec2::new(-0.6, 0.0))];
    for (k, &w) in widths.iter().enumerate() {
        let x = 0.6 + k as f64 * d * 0.75f64.sqrt();
        for j in 0..w {
            let y = (2.0 * j as f64 - (w as f64 - 1.0)) * 0.5 * d;
            balls.push(BallSetup::at(balls.len() as u8, Vec2::new(x, y)));
        }
    }
    balls
}

const NINE: [usize; 5] = [1, 2, 3, 2, 1];
const FIFTEEN: [usize; 5] = [1, 2, 3, 4, 5];

/// Every ball's state just after the first impact when ball `cue` of `balls` is struck
/// along +x at `speed`, and the number of cluster impacts so far (one: the rack's).
fn first_impact(balls: &[BallSetup], cue: usize, speed: f64) -> (Vec<BallState>, usize) {
    let mut sim = Simulation::new(Table::wpa_9ft(), spin(), balls).unwrap();
    sim.strike(cue, Shot::new(0.0, speed)).unwrap();
    let t0 = loop {
        let e = sim.step_event().expect("an event");
        if matches!(e.kind, EventKind::BallBall { .. }) {
            break e.time;
        }
    };
    while sim.next_event_time() == Some(t0) {
        sim.step_event();
    }
    let states = (0..sim.ball_count()).map(|i| sim.ball(i)).collect();
    (states, sim.cluster_impacts())
}

/// Largest difference of velocity or surface speed of spin (`R w`) between `a` and `b`.
fn difference(a: &BallState, b: &BallState) -> f64 {
    let r = spin().ball.radius;
    let dw = a.angular_velocity - b.angular_velocity;
    (a.velocity - b.velocity)
        .length()
        .max(r * dw.dot(dw).sqrt())
}

/// Relabelling: the balls of a frozen 9-ball and 15-ball rack listed in five shuffled orders
/// (the cue ball's index moved too) leave the rack's impact with the same velocities and
/// spins, ball by ball, to 1e-10 of the cue ball's speed at 3, 8 and 13 m/s. With each pair's
/// friction applied in turn after the normal impulses (the order decided by the indices)
/// they differed by about 2.6e-2.
#[test]
fn a_cluster_impact_does_not_depend_on_the_order_the_balls_are_listed_in() {
    for widths in [&NINE[..], &FIFTEEN[..]] {
        let balls = frozen_rack(widths);
        let n = balls.len();
        for speed in [3.0, 8.0, 13.0] {
            let (base, impacts) = first_impact(&balls, 0, speed);
            assert_eq!(impacts, 1, "the rack is one cluster impact");
            let moved = base.iter().filter(|s| s.velocity.length() > 0.0).count();
            assert!(moved > n / 2, "the impact reaches the rack: {moved} of {n}");
            let mut seed = 0x2545_f491_4f6c_dd1du64 ^ (n as u64);
            for _ in 0..5 {
                // A Fisher-Yates shuffle: ball i of `balls` is ball perm[i] of `shuffled`.
                let mut order: Vec<usize> = (0..n).collect();
                for i in (1..n).rev() {
                    seed ^= seed << 13;
                    seed ^= seed >> 7;
                    seed ^= seed << 17;
                    order.swap(i, (seed % (i as u64 + 1)) as usize);
                }
                let shuffled: Vec<BallSetup> = order.iter().map(|&i| balls[i]).collect();
                let mut perm = vec![0; n];
                for (new, &old) in order.iter().enumerate() {
                    perm[old] = new;
                }
                let (states, _) = first_impact(&shuffled, perm[0], speed);
                let worst = (0..n)
                    .map(|i| difference(&base[i], &states[perm[i]]))
                    .fold(0.0f64, f64::max);
                eprintln!("relabelled, {n} balls, {speed} m/s: {:.2e}", worst / speed);
                assert!(
                    worst <= 1e-10 * speed,
                    "{n} balls at {speed} m/s, order {order:?}: {:.2e} of the cue speed",
                    worst / speed
                );
            }
        }
    }
}

/// Mirror: on a frozen 9-ball and 15-ball rack struck on the long axis at 3, 8 and 13 m/s
/// (a scene its own mirror image under `y -> -y`), every ball leaves the impact as the mirror
/// image of its partner across the axis (velocity `(v_x, -v_y)`, spin `(-w_x, w_y, -w_z)`),
/// to 1e-10 of the cue ball's speed; balls on the axis are their own partners.
#[test]
fn a_mirror_symmetric_cluster_impact_leaves_mirror_image_states() {
    for widths in [&NINE[..], &FIFTEEN[..]] {
        let balls = frozen_rack(widths);
        let partner: Vec<usize> = balls
            .iter()
            .map(|b| {
                let m = Vec2::new(b.position.x, -b.position.y);
                balls
                    .iter()
                    .position(|c| c.position == m)
                    .expect("a partner")
            })
            .collect();
        for speed in [3.0, 8.0, 13.0] {
            let (s, _) = first_impact(&balls, 0, speed);
            let mut worst = 0.0f64;
            let mut sideways = 0.0f64;
            for (i, &p) in partner.iter().enumerate() {
                let q = &s[p];
                let mirrored = BallState {
                    velocity: Vec2::new(q.velocity.x, -q.velocity.y),
                    angular_velocity: Vec3::new(
                        -q.angular_velocity.x,
                        q.angular_velocity.y,
                        -q.angular_velocity.z,
                    ),
                    ..s[i]
                };
                worst = worst.max(difference(&s[i], &mirrored));
                sideways = sideways.max(s[i].velocity.y.abs());
            }
            // Not trivially symmetric: balls leave sideways at a good part of the speed.
            eprintln!(
                "mirror, {} balls, {speed} m/s: {:.2e}",
                balls.len(),
                worst / speed
            );
            assert!(sideways > 0.05 * speed, "{sideways}");
            assert!(
                worst <= 1e-10 * speed,
                "{} balls at {speed} m/s: {:.2e} of the cue speed",
                balls.len(),
                worst / speed
            );
        }
    }
}

/// The worst case for friction inside an impact, kept as a regression (summing every
/// pair's friction impulse from one state, tried and reverted, took one scene from 203 k
/// to 917 k events and multiplied its near-zero energy by 7e274): a frozen 15-ball rack
/// whose balls spin in place at up to 40 rad/s about every axis, hit at 2 mm/s, so the
/// impacts carry almost no linear energy against much more in spin, and the cloth drives
/// the spinning balls into each other in clusters at near-zero speeds. Under the invariant
/// monitor (no energy gained at any event, no overlap) it comes to rest in a bounded
/// number of events.
#[test]
fn a_creeping_cue_ball_into_a_spinning_frozen_rack_gains_nothing() {
    let mut balls = frozen_rack(&FIFTEEN);
    for (i, b) in balls.iter_mut().enumerate().skip(1) {
        let k = i as f64;
        b.spin = Vec3::new(
            40.0 * (1.7 * k).sin(),
            40.0 * (2.3 * k).cos(),
            40.0 * (0.9 * k).sin(),
        );
    }
    balls[0].position.x = 0.6 - 2.0 * spin().ball.radius - 1e-4;
    let mut sim = Simulation::new(Table::wpa_9ft(), spin(), &balls).unwrap();
    sim.strike(0, Shot::new(0.0, 2e-3)).unwrap();
    let mut monitor = check::Monitor::new(&sim, check::Tolerances::default()).unwrap();
    let stats = monitor.run_to_rest(&mut sim).unwrap();
    eprintln!("{stats:?}, {} cluster impacts", sim.cluster_impacts());
    assert!(sim.cluster_impacts() >= 1, "clusters met");
    assert!(sim.history().events().len() < 20_000, "{stats:?}");
}
