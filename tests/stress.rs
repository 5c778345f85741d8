//! Headless tests of the stress table: built through the panel's request, run by the same
//! solver step, checked live; refused with the reason; left again for a standard rack.

mod common;

use bevy::prelude::*;
use billiards::{
    settings::{PhysicsSettings, TableSetup, table_label},
    sim::{RackRequested, ShotRequested, SimStatus, Solver},
    stress::{self, StressMonitor, StressRequested, StressSettings},
    table::balls::Ball,
    table::geometry::TableSpec,
    ui::settings::table_in_play,
};
use billiards_physics::{Rack, Table, racks::stress_scale};

fn app() -> App {
    let mut app = common::headless(stress::plugin);
    app.update();
    app.world_mut()
        .write_message(RackRequested::standard(Rack::FifteenBall));
    app.update();
    app
}

fn request(app: &mut App, settings: StressSettings) {
    *app.world_mut().resource_mut::<StressSettings>() = settings;
    app.world_mut().write_message(StressRequested);
    app.update();
}

fn ball_entities(app: &mut App) -> usize {
    let world = app.world_mut();
    world.query::<&Ball>().iter(world).count()
}

#[test]
fn a_thousand_balls_run_live_with_their_energy_and_overlap_checked() {
    let mut app = app();
    request(
        &mut app,
        StressSettings {
            balls: 1000,
            ..default()
        },
    );
    let solver = app.world().resource::<Solver>();
    assert!(solver.is_scene());
    assert_eq!(solver.name(), stress::STRESS_NAME);
    assert_eq!(solver.simulation().ball_count(), 1000);
    let length = Table::wpa_8ft().length * stress_scale(1000);
    assert!((app.world().resource::<TableSpec>().length - length).abs() < 1e-9);
    assert_eq!(ball_entities(&mut app), 1000);
    for _ in 0..120 {
        app.update();
    }
    let m = app.world().resource::<StressMonitor>().clone();
    assert!(m.active);
    assert_eq!(m.on_table, 1000);
    assert!(m.events_per_second > 100.0, "{m:?}");
    // Frictionless and elastic: the energy stays, to rounding; no pair ever overlaps.
    assert!(m.energy > 1.0 && (m.energy - m.energy_start).abs() < 1e-9 * m.energy_start);
    assert!(m.worst_energy_rise < stress::ENERGY_RISE_WARNING, "{m:?}");
    assert_eq!(m.worst_overlap, 0.0);
    assert!(app.world().resource::<Solver>().simulation().event_count() > 500);
}

#[test]
fn the_scene_keeps_its_physics_and_a_standard_rack_brings_the_table_back() {
    let mut app = app();
    request(
        &mut app,
        StressSettings {
            balls: 100,
            ..default()
        },
    );
    // The Play section names the stress table, not the pool table chosen before it (issue 48).
    app.update();
    let label = |app: &App| {
        let setup = *app.world().resource::<TableSetup>();
        table_in_play(
            setup.table,
            app.world().resource::<TableSpec>(),
            app.world().resource::<StressMonitor>(),
        )
    };
    let named = label(&app);
    assert!(
        named.starts_with("stress table: ") && named.ends_with(" m, 100 balls"),
        "{named}"
    );
    let params = *app.world().resource::<Solver>().simulation().params();
    app.world_mut().resource_mut::<PhysicsSettings>().mu_roll = 0.013;
    app.update();
    assert_eq!(
        *app.world().resource::<Solver>().simulation().params(),
        params
    );
    let note = app.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.contains("keeps its own physics"), "{note}");

    app.world_mut()
        .write_message(RackRequested::standard(Rack::NineBall));
    app.update();
    let setup = *app.world().resource::<TableSetup>();
    assert_eq!(
        *app.world().resource::<TableSpec>(),
        TableSpec::of(setup.table)
    );
    let solver = app.world().resource::<Solver>();
    assert!(!solver.is_scene());
    assert_eq!(solver.simulation().ball_count(), 10);
    // The checks stop with the stress table; the panel names the pool table again.
    app.update();
    assert!(!app.world().resource::<StressMonitor>().active);
    assert_eq!(label(&app), table_label(setup.table));
}

#[test]
fn a_count_the_table_cannot_hold_is_refused_with_the_reason_and_the_table_stays() {
    let mut app = app();
    for (settings, reason) in [
        (
            StressSettings {
                balls: 2000,
                scale: Some(1.0),
                ..default()
            },
            "2000 balls do not fit on a 2.34 x 1.17 m table",
        ),
        (
            StressSettings {
                balls: 0,
                ..default()
            },
            "needs at least 1 ball",
        ),
        (
            StressSettings {
                balls: 20_000,
                ..default()
            },
            "more than the stress scene's maximum of 10000",
        ),
    ] {
        request(&mut app, settings);
        let refused = app.world().resource::<StressMonitor>().refused.clone();
        assert!(
            refused.as_deref().is_some_and(|r| r.contains(reason)),
            "{refused:?}"
        );
        let note = app.world().resource::<SimStatus>().note.clone();
        assert!(note.is_some_and(|n| n.contains(reason)));
        // The 15-ball rack is still on its table.
        assert_eq!(
            app.world().resource::<Solver>().simulation().ball_count(),
            16
        );
        assert_eq!(*app.world().resource::<TableSpec>(), TableSpec::default());
    }
}

#[test]
fn with_friction_the_balls_come_to_rest_and_the_cue_ball_can_be_struck() {
    let mut app = app();
    request(
        &mut app,
        StressSettings {
            balls: 50,
            friction: true,
            ..default()
        },
    );
    // 16 ms frames: a ball from 2 m/s rolls to rest within 25 s.
    for _ in 0..2000 {
        app.update();
        if app.world().resource::<SimStatus>().at_rest {
            break;
        }
    }
    assert!(app.world().resource::<SimStatus>().at_rest);
    let before = app.world().resource::<StressMonitor>().energy;
    assert_eq!(before, 0.0);
    app.world_mut()
        .write_message(ShotRequested::from(billiards_physics::Shot::new(0.3, 2.0)));
    app.update();
    app.update();
    let m = app.world().resource::<StressMonitor>().clone();
    // The strike's energy is an input: the baseline moves with it, no rise is reported.
    assert!(m.energy > 0.0 && m.energy_start > 0.0, "{m:?}");
    assert!(m.worst_energy_rise < stress::ENERGY_RISE_WARNING, "{m:?}");
}
