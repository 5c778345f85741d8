//! The monitor proven: each test feeds it a history (or a state) built to break exactly one
//! invariant of the module docs, and asserts the exact violation it reports. The solver never
//! makes such histories, so they are forged into a real simulation's history after it is built
//! (`Simulation::forge`, test builds only).
//!
//! Each test also fails with its check disabled: `tools/monitor-mutations.py` disables each
//! check in turn and expects its test to fail.

use super::*;
use crate::ball::BallSetup;
use crate::ball::Motion;
use crate::math::Vec3;
use crate::params::Params;
use crate::table::{Cushion, Pocket, Table};

fn radius() -> f64 {
    Params::default().ball.radius
}

fn sim_on(table: Table, params: Params, balls: &[BallSetup]) -> Simulation {
    Simulation::new(table, params, balls).expect("a legal layout")
}

fn sim(balls: &[BallSetup]) -> Simulation {
    sim_on(Table::wpa_8ft(), Params::default(), balls)
}

/// A monitor started on `sim`, which is legal at the start.
fn monitor(sim: &Simulation) -> Monitor {
    Monitor::new(sim, Tolerances::default()).expect("the start breaks no invariant")
}

/// A ball at rest at `p`.
fn resting(p: Vec2) -> BallState {
    BallState {
        position: p,
        motion: Motion::Stationary,
        ..BallState::default()
    }
}

/// An event of one ball.
fn event(time: f64, kind: EventKind, after: BallState) -> Event {
    Event {
        time,
        kind,
        after: [after, BallState::default()],
    }
}

/// A stationary ball that "changes" to stationary: an event that names `ball` and changes
/// nothing, to make the monitor check the instants up to `time`.
fn nothing(time: f64, ball: BallId, at: Vec2) -> Event {
    let kind = EventKind::Transition {
        ball,
        from: Motion::Stationary,
        to: Motion::Stationary,
    };
    event(time, kind, resting(at))
}

/// Forges `events` into `sim`'s history and checks them.
fn check(sim: &mut Simulation, m: &mut Monitor, events: &[Event]) -> Result<(), Violation> {
    for e in events {
        sim.forge().0.push(*e);
    }
    m.catch_up(sim)
}

/// The unforged history of every scene here passes: what the tests forge is what fails.
#[test]
fn a_legal_history_passes() {
    let far = Vec2::new(0.5, 0.3);
    let mut s = sim(&[
        BallSetup::moving(0, Vec2::new(-0.3, 0.0), Vec2::new(1.0, 0.0)),
        BallSetup::at(1, Vec2::ZERO),
        BallSetup::at(2, far),
    ]);
    let mut m = monitor(&s);
    let st = m
        .run_to_rest(&mut s)
        .expect("the solver's history is legal");
    assert!(st.events >= 3, "{st:?}");
    assert_eq!(
        check(&mut s, &mut m, &[nothing(st.time + 1.0, 2, far)]),
        Ok(())
    );
}

#[test]
fn a_nan_in_a_state_is_non_finite() {
    let mut s = sim(&[BallSetup::at(0, Vec2::ZERO)]);
    let mut m = monitor(&s);
    let bad = BallState {
        velocity: Vec2::new(f64::NAN, 0.0),
        motion: Motion::Sliding,
        ..resting(Vec2::ZERO)
    };
    let got = check(
        &mut s,
        &mut m,
        &[event(0.5, EventKind::Placed { ball: 0 }, bad)],
    );
    assert!(
        matches!(got, Err(Violation::NonFinite { time: 0.5, ball: 0, state })
            if state.velocity.x.is_nan()),
        "{got:?}"
    );
}

#[test]
fn an_event_before_the_last_is_time_going_back() {
    let p = Vec2::new(0.2, 0.1);
    let mut s = sim(&[BallSetup::at(0, p)]);
    let mut m = monitor(&s);
    let got = check(&mut s, &mut m, &[nothing(0.5, 0, p), nothing(0.25, 0, p)]);
    assert_eq!(
        got,
        Err(Violation::TimeBack {
            before: 0.5,
            after: 0.25
        })
    );
}

/// Two balls rolling head on through each other with no contact event: at the midpoint sample
/// between the start and the next event (t = 0.1 s) they are a few millimetres apart, centre
/// to centre; at the event itself (0.2 s) they are clear again, so only the sample between
/// events catches them.
#[test]
fn balls_passing_through_each_other_between_events_overlap() {
    let far = Vec2::new(0.5, 0.3);
    let mut s = sim(&[
        BallSetup::moving(0, Vec2::new(-0.1, 0.0), Vec2::new(1.0, 0.0)),
        BallSetup::moving(1, Vec2::new(0.1, 0.0), Vec2::new(-1.0, 0.0)),
        BallSetup::at(2, far),
    ]);
    let mut m = monitor(&s);
    let got = check(&mut s, &mut m, &[nothing(0.2, 2, far)]);
    let at = |i: BallId| s.segment(i).state_at(0.1).position;
    let apart = (at(1) - at(0)).length();
    assert!(apart < radius(), "{apart}");
    let depth = 2.0 * radius() - apart;
    assert_eq!(
        got,
        Err(Violation::Overlap {
            time: 0.1,
            a: 0,
            b: 1,
            depth,
            when: "between"
        })
    );
}

/// A ball driven at the foot cushion with no cushion event: at the midpoint sample (0.1 s) it
/// is some 10 cm beyond the cushion line.
#[test]
fn a_ball_through_a_cushion_is_outside() {
    let t = Table::wpa_8ft();
    let line = t.centre_bounds(radius()).x;
    let far = Vec2::new(-0.5, 0.3);
    let mut s = sim(&[
        BallSetup::moving(0, Vec2::new(line - 0.05, 0.0), Vec2::new(2.0, 0.0)),
        BallSetup::at(1, far),
    ]);
    let mut m = monitor(&s);
    let got = check(&mut s, &mut m, &[nothing(0.2, 1, far)]);
    let at = s.segment(0).state_at(0.1).position;
    assert!(at.x - line > 0.1, "{at:?}");
    assert_eq!(
        got,
        Err(Violation::Outside {
            time: 0.1,
            ball: 0,
            position: at,
            by: at.x - line,
        })
    );
}

/// A ball set down in the side pocket's mouth, on the table side of its opening and inside
/// its cushion lines everywhere but across the mouth, yet 1.6 mm into the jaw of radius 1 cm
/// at the end of the left cushion (its centre 5 mm along the cushion from the jaw's, 2 mm
/// beyond the cushion line).
#[test]
fn a_ball_inside_a_pocket_jaw_is_outside() {
    let rho = 0.01;
    let t = Table::wpa_8ft().with_jaws(rho);
    let r = radius();
    let jaw = t
        .jaws()
        .into_iter()
        .find(|j| j.pocket == Pocket::SideLeft && j.centre.x > 0.0)
        .expect("a jaw of the left side pocket");
    let p = Vec2::new(jaw.centre.x - 0.005, t.centre_bounds(r).y + 0.002);
    let depth = r + rho - (p - jaw.centre).length();
    assert!((1.5e-3..1.7e-3).contains(&depth), "{depth}");
    let mut s = sim_on(t, Params::default(), &[BallSetup::at(0, Vec2::ZERO)]);
    let mut m = monitor(&s);
    let got = check(
        &mut s,
        &mut m,
        &[event(0.5, EventKind::Placed { ball: 0 }, resting(p))],
    );
    assert_eq!(
        got,
        Err(Violation::Outside {
            time: 0.5,
            ball: 0,
            position: p,
            by: depth,
        })
    );
}

/// A cushion event that moves a resting ball by a centimetre.
#[test]
fn an_event_that_moves_a_ball_is_a_jump() {
    let mut s = sim(&[BallSetup::at(0, Vec2::ZERO)]);
    let mut m = monitor(&s);
    let kind = EventKind::Cushion {
        ball: 0,
        cushion: Cushion::Foot,
    };
    let got = check(
        &mut s,
        &mut m,
        &[event(0.5, kind, resting(Vec2::new(0.01, 0.0)))],
    );
    assert_eq!(
        got,
        Err(Violation::Jump {
            time: 0.5,
            kind,
            ball: 0,
            by: 0.01
        })
    );
}

/// A cushion event that doubles a ball's speed where it is: four times the translational
/// energy.
#[test]
fn an_event_that_speeds_a_ball_up_gains_energy() {
    let mut s = sim(&[BallSetup::moving(0, Vec2::ZERO, Vec2::new(1.0, 0.0))]);
    let mut m = monitor(&s);
    let t = 0.1;
    let before = s.segment(0).state_at(t);
    let after = BallState {
        velocity: before.velocity * 2.0,
        ..before
    };
    let kind = EventKind::Cushion {
        ball: 0,
        cushion: Cushion::Foot,
    };
    let got = check(&mut s, &mut m, &[event(t, kind, after)]);
    let e = |st: BallState| kinetic_energy(&[st], s.params().ball.mass, radius());
    // What the monitor sees after the event: the state the history rebuilds.
    let rebuilt = s.history().state_at(0, t);
    assert!(e(rebuilt) > 3.9 * e(before));
    assert_eq!(
        got,
        Err(Violation::EnergyGain {
            time: t,
            before: e(before),
            after: e(rebuilt),
            what: format!("at {kind:?}"),
        })
    );
}

/// A ball given a segment that speeds up (at a change of parameters, where the monitor takes
/// every ball's new segment as it comes): by the next event it has more energy than the change
/// left it with.
#[test]
fn a_segment_that_speeds_a_ball_up_gains_energy_between_events() {
    let far = Vec2::new(0.5, 0.3);
    let mut s = sim(&[BallSetup::at(0, Vec2::ZERO), BallSetup::at(1, far)]);
    let mut m = monitor(&s);
    let start = BallState {
        velocity: Vec2::new(0.1, 0.0),
        motion: Motion::Sliding,
        ..resting(Vec2::ZERO)
    };
    let speeding = Segment::new(0.5, start, Vec2::new(1.0, 0.0), Vec3::ZERO, None);
    let segments = [speeding, *s.segment(1)];
    let change = Event {
        time: 0.5,
        kind: EventKind::ParamsChanged,
        after: [BallState::default(); 2],
    };
    let params = *s.params();
    s.forge().0.push_all(change, &segments, params);
    let got = check(&mut s, &mut m, &[nothing(0.6, 1, far)]);
    let e = |st: BallState| kinetic_energy(&[st], s.params().ball.mass, radius());
    assert_eq!(
        got,
        Err(Violation::EnergyGain {
            time: 0.6,
            before: e(start),
            after: e(speeding.state_at(0.6)),
            what: "between events".into(),
        })
    );
}

/// The solver's first contact of a cue ball with a resting ball, forged so that the cue ball
/// stops and the object ball leaves at half the speed it should: energy is lost (allowed),
/// and half the pair's momentum with it.
#[test]
fn a_ball_contact_that_loses_momentum_breaks_momentum() {
    let balls = [
        BallSetup::moving(0, Vec2::new(-0.3, 0.0), Vec2::new(1.0, 0.0)),
        BallSetup::at(1, Vec2::ZERO),
    ];
    let mut s = sim(&balls);
    let mut m = monitor(&s);
    // The solver's events up to the contact (the cue ball's slide to roll), then the contact.
    let mut real = s.clone();
    let mut events = Vec::new();
    while events.last().is_none_or(|e: &Event| !e.kind.is_collision()) {
        events.push(real.step_event().expect("the cue ball reaches ball 1"));
    }
    let hit = *events.last().unwrap();
    assert_eq!(hit.kind, EventKind::BallBall { a: 0, b: 1 });
    let mut forged = hit;
    forged.after[0].velocity = Vec2::ZERO;
    forged.after[0].motion = Motion::Stationary;
    forged.after[1].velocity = hit.after[1].velocity * 0.5;
    *events.last_mut().unwrap() = forged;
    let got = check(&mut s, &mut m, &events);
    // The cue ball just before the contact (ball 1 is at rest), as the monitor sees it.
    let track = s.history().track(0);
    let before = track[track.len() - 2].state_at(hit.time);
    let change = (forged.after[1].velocity - before.velocity).length()
        / before
            .velocity
            .length()
            .max(forged.after[1].velocity.length());
    assert!((0.4..0.6).contains(&change), "{change}");
    assert_eq!(
        got,
        Err(Violation::Momentum {
            time: hit.time,
            a: 0,
            b: 1,
            change,
        })
    );
}

/// A ball sent round the table with room for three events only.
#[test]
fn a_run_longer_than_the_cap_hits_the_event_cap() {
    let params = Params {
        max_events: 3,
        ..Params::default()
    };
    let mut s = sim_on(
        Table::wpa_8ft(),
        params,
        &[BallSetup::moving(0, Vec2::ZERO, Vec2::new(3.0, 1.0))],
    );
    let got = monitor(&s).run_to_rest(&mut s);
    assert_eq!(s.history().events().len(), 3);
    assert_eq!(
        got,
        Err(Violation::EventCap {
            events: 3,
            cap: 3,
            time: s.time(),
        })
    );
}

/// A resting ball (so no event pending) set moving behind the solver's back.
#[test]
fn a_ball_moving_with_nothing_pending_moves_forever() {
    let mut s = sim(&[BallSetup::at(0, Vec2::ZERO)]);
    let mut m = monitor(&s);
    let start = BallState {
        velocity: Vec2::new(0.1, 0.0),
        motion: Motion::Sliding,
        ..resting(Vec2::ZERO)
    };
    s.forge().1[0] = Segment::new(0.0, start, Vec2::new(-0.1, 0.0), Vec3::ZERO, Some(1.0));
    assert_eq!(
        m.step(&mut s),
        Err(Violation::MovingForever { time: 0.0, ball: 0 })
    );
}
