//! The input contract at every entry point of the library: the largest and smallest values
//! accepted, and the first ones beyond them rejected with an error naming them.

use billiards_physics::limits::{MAX_SPEED, MAX_SURFACE_SPEED, MAX_TIME, MIN_SPEED};
use billiards_physics::recording::{Recorder, Recording};
use billiards_physics::scene::{Scene, SceneError};
use billiards_physics::*;
use std::path::Path;

fn up(x: f64) -> f64 {
    f64::from_bits(x.to_bits() + 1)
}

fn down(x: f64) -> f64 {
    f64::from_bits(x.to_bits() - 1)
}

fn spin_params() -> Params {
    Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    }
}

fn nine_ball(params: Params) -> Simulation {
    let table = Table::wpa_8ft();
    Simulation::new(table, params, &Rack::NineBall.layout(&table, &params.ball)).unwrap()
}

fn limit_of(e: SetupError) -> LimitError {
    match e {
        SetupError::Limit(l) => l,
        e => panic!("not a limit error: {e}"),
    }
}

#[test]
fn strike_accepts_the_limits_and_runs_them_to_rest() {
    for params in [Params::default(), spin_params()] {
        for speed in [0.0, MIN_SPEED, MAX_SPEED] {
            let mut sim = nine_ball(params);
            sim.strike(0, Shot::new(0.0, speed))
                .unwrap_or_else(|e| panic!("speed {speed} refused: {e}"));
            let run = check::run_to_rest_checked(&mut sim);
            assert!(run.is_ok(), "speed {speed}: {run:?}");
            assert!(sim.is_at_rest(), "speed {speed}");
        }
    }
}

#[test]
fn strike_rejects_speeds_beyond_the_limits_naming_ball_and_limit() {
    let mut sim = nine_ball(spin_params());
    for speed in [
        up(MAX_SPEED),
        down(MIN_SPEED),
        1e308,
        1e-308,
        -1.0,
        f64::NAN,
    ] {
        let e = limit_of(sim.strike(0, Shot::new(0.0, speed)).unwrap_err());
        assert_eq!((e.ball, e.what), (Some((0, 0)), "shot speed"));
    }
    let text = sim
        .strike(0, Shot::new(0.0, 1e308))
        .unwrap_err()
        .to_string();
    assert!(text.contains("ball 0") && text.contains("1e308") && text.contains("100 m/s"));
    // Nothing was recorded and the balls still rest.
    assert_eq!(sim.history().events().len(), 0);
    assert!(sim.is_at_rest());
}

#[test]
fn strike_takes_any_finite_angle() {
    let mut sim = nine_ball(Params::default());
    sim.strike(0, Shot::new(1e300, 1.0)).unwrap();
    sim.run_to_rest().unwrap();
    assert!(sim.strike(0, Shot::new(f64::INFINITY, 1.0)).is_err());
}

#[test]
fn new_and_place_check_speeds_and_spins() {
    let params = spin_params();
    let table = Table::wpa_8ft();
    let r = params.ball.radius;
    // The surface speed is `|w| R` rounded: stay a hair inside (limits.rs tests it exactly).
    let top = 0.999_999 * MAX_SURFACE_SPEED / r;
    let ok = [
        (Vec2::new(0.0, MAX_SPEED), Vec3::new(0.0, 0.0, top)),
        (Vec2::new(MIN_SPEED, 0.0), Vec3::ZERO),
    ];
    let bad = [
        (Vec2::new(0.0, up(MAX_SPEED)), Vec3::ZERO, "velocity"),
        (Vec2::new(down(MIN_SPEED), 0.0), Vec3::ZERO, "velocity"),
        (
            Vec2::ZERO,
            Vec3::new(1e3 / r, 0.0, 0.0),
            "spin surface speed |w| R",
        ),
    ];
    let ball = |v, w| BallSetup {
        spin: w,
        ..BallSetup::moving(7, Vec2::ZERO, v)
    };
    for (v, w) in ok {
        let mut sim = Simulation::new(table, params, &[ball(v, w)]).unwrap();
        sim.place(0, Vec2::new(0.5, 0.0), v, w).unwrap();
    }
    for (v, w, what) in bad {
        let e = limit_of(Simulation::new(table, params, &[ball(v, w)]).unwrap_err());
        assert_eq!((e.ball, e.what), (Some((0, 7)), what));
        let mut sim = Simulation::new(table, params, &[ball(Vec2::ZERO, Vec3::ZERO)]).unwrap();
        let e = limit_of(sim.place(0, Vec2::ZERO, v, w).unwrap_err());
        assert_eq!((e.ball, e.what), (Some((0, 7)), what));
    }
    // `new` used to take a NaN spin; the shared setup check names it as `place` does.
    let nan = Vec3::new(f64::NAN, 0.0, 0.0);
    let e = Simulation::new(table, params, &[ball(Vec2::ZERO, nan)]).unwrap_err();
    assert_eq!(
        e,
        SetupError::NonFinite {
            ball: 0,
            number: 7,
            what: "spin"
        }
    );
}

#[test]
fn advance_stops_at_the_clock_limit() {
    let mut sim = nine_ball(Params::default());
    assert!(matches!(sim.advance(up(MAX_TIME)), Err(SimError::Limit(_))));
    assert!(matches!(sim.advance(1e300), Err(SimError::Limit(_))));
    assert_eq!(sim.time(), 0.0);
    sim.advance(MAX_TIME).unwrap();
    assert!(matches!(sim.advance(1e-3), Err(SimError::Limit(_))));
    // The clock is at the limit: an input there is still honoured, none after it.
    sim.strike(0, Shot::new(0.0, 1.0)).unwrap();
    sim.run_to_rest().unwrap();
    assert!(sim.time() > MAX_TIME);
    let e = limit_of(sim.strike(0, Shot::new(0.0, 1.0)).unwrap_err());
    assert_eq!(e.what, "simulation time");
}

#[test]
fn set_params_rejects_every_non_finite_field() {
    let mut sim = nine_ball(spin_params());
    let base = spin_params();
    let Model::Spin(m) = base.model else {
        unreachable!()
    };
    let spin = |f: fn(&mut SpinModel)| {
        let mut m = m;
        f(&mut m);
        Params {
            model: Model::Spin(m),
            ..base
        }
    };
    let paper = |f: fn(&mut PaperModel)| {
        let mut m = PaperModel::default();
        f(&mut m);
        Params {
            model: Model::Paper(m),
            ..base
        }
    };
    let nan = f64::NAN;
    let bad = [
        Params {
            gravity: nan,
            ..base
        },
        spin(|m| m.mu_slide = f64::NAN),
        spin(|m| m.mu_roll = f64::NAN),
        spin(|m| m.mu_spin = f64::NAN),
        spin(|m| m.e_ball = f64::NAN),
        spin(|m| m.mu_ball = f64::NAN),
        spin(|m| m.cushion_height = f64::NAN),
        spin(|m| m.cue_mass = f64::NAN),
        spin(|m| m.miscue_limit = f64::NAN),
        spin(|m| {
            m.cushion = CushionModel::Han2005 {
                e: f64::NAN,
                mu: 0.2,
            }
        }),
        spin(|m| {
            m.cushion = CushionModel::Han2005 {
                e: 0.8,
                mu: f64::NAN,
            }
        }),
        spin(|m| m.cushion = CushionModel::Reflect { e: f64::NAN }),
        paper(|m| m.mu_slide = f64::NAN),
        paper(|m| m.mu_roll = f64::NAN),
        paper(|m| m.slide_roll_speed = f64::NAN),
        paper(|m| m.e_ball = f64::NAN),
        paper(|m| m.e_cushion = f64::NAN),
        Params {
            randomization: Some(Randomization {
                spread: nan,
                seed: 1,
            }),
            ..base
        },
        Params {
            max_events: 0,
            ..base
        },
    ];
    for p in bad {
        assert!(
            matches!(sim.set_params(p), Err(SetupError::Param(_))),
            "{p:?}"
        );
    }
    // The ball size is checked by `new` (and may not change in `set_params`).
    for ball in [
        BallSpec {
            radius: nan,
            ..base.ball
        },
        BallSpec {
            mass: nan,
            ..base.ball
        },
    ] {
        let p = Params { ball, ..base };
        let table = Table::wpa_8ft();
        let balls = [BallSetup::at(0, Vec2::ZERO)];
        assert!(matches!(
            Simulation::new(table, p, &balls),
            Err(SetupError::Param(_))
        ));
    }
}

#[test]
fn scenes_reject_out_of_contract_shots_speeds_and_durations() {
    let shot = r#"{"rack": "nine_ball", "shots": [{"angle": 0, "speed": 1e308}]}"#;
    let e = Scene::from_json(shot).unwrap().run().unwrap_err();
    assert!(matches!(e, SceneError::Setup(SetupError::Limit(_))), "{e}");
    assert!(e.to_string().contains("shot speed 1e308"), "{e}");
    let ball = r#"{"balls": [{"number": 3, "position": {"x": 0, "y": 0},
        "velocity": {"x": 0, "y": 1e-300}}]}"#;
    let e = Scene::from_json(ball).unwrap().run().unwrap_err();
    assert!(e.to_string().contains("ball 3"), "{e}");
    let at = |s: f64| {
        let text = format!(r#"{{"rack": "nine_ball", "duration": {{"seconds": {s:e}}}}}"#);
        Scene::from_json(&text).unwrap().run()
    };
    assert!(at(MAX_TIME).is_ok());
    assert!(matches!(at(up(MAX_TIME)), Err(SceneError::BadDuration(_))));
}

fn recording() -> Recording {
    let params = spin_params();
    let table = Table::wpa_8ft();
    let mut rec =
        Recorder::new(table, params, Rack::NineBall.layout(&table, &params.ball)).unwrap();
    rec.strike(0, Shot::new(0.0, 5.0)).unwrap();
    rec.run_to_rest().unwrap();
    rec.recording()
}

#[test]
fn recordings_with_out_of_contract_inputs_fail_to_load_naming_them() {
    let good = recording();
    let load = |rec: &Recording| {
        let text = serde_json::to_string(rec).unwrap();
        Recording::from_json(&text, Path::new("r.json"))
    };
    load(&good).unwrap();
    let mut fast = good.clone();
    let recording::Action::Strike { shot, .. } = &mut fast.inputs[0].action else {
        panic!("the first input is the strike")
    };
    shot.speed = 1e308;
    let e = load(&fast).unwrap_err().to_string();
    assert!(
        e.contains("input 0") && e.contains("shot speed 1e308"),
        "{e}"
    );
    // Replaying it (without loading) fails the same way instead of a wrong history.
    let e = fast.verify().unwrap_err();
    assert!(e.contains("shot speed 1e308"), "{e}");

    let mut late = good.clone();
    late.end_time = 1e300;
    let e = load(&late).unwrap_err().to_string();
    assert!(e.contains("end_time") && e.contains("1e300"), "{e}");

    let mut placed = good.clone();
    placed.inputs.push(recording::Input {
        time: placed.end_time,
        action: recording::Action::Place {
            ball: 0,
            position: Vec2::ZERO,
            velocity: Vec2::new(1e200, 0.0),
            spin: Vec3::ZERO,
        },
    });
    let e = load(&placed).unwrap_err().to_string();
    assert!(e.contains("ball 0") && e.contains("velocity 1e200"), "{e}");
}
