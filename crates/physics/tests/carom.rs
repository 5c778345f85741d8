//! The carom table ([`Table::carom_match`]): no pocket anywhere, every ball kept on the cloth.

use billiards_physics::check::Tolerances;
use billiards_physics::soak::{carom_scenario, run_scenario_traced};
use billiards_physics::{
    BallSetup, Cushion, EventKind, Motion, Params, Shot, Simulation, Table, Vec2,
};

/// Invariant: over 300 random carom scenes (every model, random friction and restitution,
/// 1 to 16 balls, follow-up shots), with every event checked by the monitor, no ball is ever
/// pocketed or meets a jaw, and every ball's centre stays within the cushion lines.
#[test]
fn a_carom_soak_never_pockets_a_ball_and_keeps_every_ball_on_the_table() {
    let (mut cushions, mut events) = (0u64, 0u64);
    for seed in 0..300 {
        let s = carom_scenario(seed);
        assert_eq!(s.table, Table::carom_match());
        let bounds = s.table.centre_bounds(s.params.ball.radius);
        let mut trace = |e: &billiards_physics::Event| {
            events += 1;
            match e.kind {
                EventKind::Pocketed { .. } | EventKind::Jaw { .. } => {
                    panic!("seed {seed}: {:?} on a table without pockets", e.kind)
                }
                EventKind::Cushion { .. } => cushions += 1,
                _ => {}
            }
            for (id, st) in e.states_after() {
                let p = st.position;
                assert!(
                    p.x.abs() <= bounds.x + 1e-6 && p.y.abs() <= bounds.y + 1e-6,
                    "seed {seed}: ball {id} at {p:?} is off the table"
                );
                assert!(st.motion.on_table(), "seed {seed}: ball {id} left play");
            }
        };
        if let Err(v) = run_scenario_traced(&s, Tolerances::default(), &mut trace) {
            panic!("carom seed {seed} ({}, {}): {v}", s.model, s.kind);
        }
    }
    // The soak did exercise the cushions (a soak of balls that never moved would pass).
    assert!(
        cushions > 1_000 && events > 10_000,
        "{cushions} cushions, {events} events"
    );
}

/// The first two cushion events of a centre-ball shot from the middle of `table` along the
/// diagonal into the foot-left corner, the ball's motion at rest, and the pocket events.
fn diagonal(table: Table) -> (Vec<(Cushion, Vec2)>, Motion, usize) {
    let params = Params::carom();
    let balls = [BallSetup::at(0, Vec2::ZERO)];
    let mut sim = Simulation::new(table, params, &balls).unwrap();
    let angle = table.width.atan2(table.length);
    sim.strike(0, Shot::new(angle, 3.0)).unwrap();
    sim.run_to_rest().unwrap();
    let events = sim.history().events();
    let cushions = events
        .iter()
        .filter_map(|e| match e.kind {
            EventKind::Cushion { cushion, .. } => Some((cushion, e.after[0].velocity)),
            _ => None,
        })
        .take(2)
        .collect();
    let pocketed = events
        .iter()
        .filter(|e| matches!(e.kind, EventKind::Pocketed { .. }))
        .count();
    (cushions, sim.ball(0).motion, pocketed)
}

/// A ball sent along the diagonal into a corner rebounds off both cushions there (the foot
/// cushion and the left one) and comes back towards the table's middle; the same shot on a
/// pool table drops into the corner pocket, so the test tells the two apart.
#[test]
fn a_ball_sent_along_the_diagonal_into_a_corner_rebounds() {
    let (cushions, motion, pocketed) = diagonal(Table::carom_match());
    assert_eq!(pocketed, 0);
    assert_eq!(motion, Motion::Stationary);
    let hit: Vec<Cushion> = cushions.iter().map(|c| c.0).collect();
    assert!(
        hit.contains(&Cushion::Foot) && hit.contains(&Cushion::Left),
        "{hit:?}"
    );
    // After both: moving back to the head and to the right (away from the corner).
    let v = cushions[1].1;
    assert!(v.x < 0.0 && v.y < 0.0, "{v:?}");
    let pool = Table {
        length: 2.84,
        width: 1.42,
        ..Table::wpa_9ft()
    };
    let (_, motion, pocketed) = diagonal(pool);
    assert_eq!(pocketed, 1);
    assert!(matches!(motion, Motion::Pocketed(_)), "{motion:?}");
}
