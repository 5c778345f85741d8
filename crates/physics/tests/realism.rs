//! The models set against measurements (issue 24): each choice loads from scene files (old
//! files keep today's model), rejects bad constants with a named error, and keeps every solver
//! invariant on soak scenes.

use billiards_physics::check::Tolerances;
use billiards_physics::scene::Scene;
use billiards_physics::soak::{run_scenario, scenario};
use billiards_physics::{BallFriction, CushionModel, Model, Params, SpinModel};

fn spin_of(scene: &Scene) -> SpinModel {
    match scene.params.model {
        Model::Spin(m) => m,
        other => panic!("expected the spin model, got {other:?}"),
    }
}

#[test]
fn an_old_scene_file_keeps_constant_ball_friction() {
    let old = r#"{ "rack": "nine_ball", "shots": [{ "ball": 0, "angle": 0.01, "speed": 3.0 }], "params": { "model": { "kind": "spin", "mu_ball": 0.06 } } }"#;
    let m = spin_of(&Scene::from_json(old).unwrap());
    assert_eq!(m.ball_friction, BallFriction::Constant);
    assert_eq!(m.mu_ball, 0.06);
}

#[test]
fn a_scene_file_chooses_speed_dependent_ball_friction() {
    let text = r#"{ "rack": "nine_ball", "shots": [{ "ball": 0, "angle": 0.01, "speed": 3.0 }], "params": { "model": { "kind": "spin", "ball_friction":
        { "kind": "speed_dependent", "a": 9.951e-3, "b": 0.108, "c": 1.088 } } } }"#;
    let scene = Scene::from_json(text).unwrap();
    assert_eq!(spin_of(&scene).ball_friction, BallFriction::ALCIATORE);
    // Round trip through the serialized parameters.
    let back: Params =
        serde_json::from_str(&serde_json::to_string(&scene.params).unwrap()).unwrap();
    assert_eq!(back, scene.params);
    scene.run().expect("runs");
}

#[test]
fn negative_friction_constants_are_named_errors() {
    let text = r#"{ "rack": "nine_ball", "shots": [{ "ball": 0, "angle": 0.01, "speed": 3.0 }], "params": { "model": { "kind": "spin", "ball_friction":
        { "kind": "speed_dependent", "a": 0.01, "b": -0.1, "c": 1.0 } } } }"#;
    let err = Scene::from_json(text)
        .unwrap()
        .run()
        .unwrap_err()
        .to_string();
    assert!(err.contains("ball_friction.b"), "{err}");
    let text = r#"{ "rack": "nine_ball", "shots": [{ "ball": 0, "angle": 0.01, "speed": 3.0 }], "params": { "model": { "kind": "spin", "ball_friction": { "kind": "fast" } } } }"#;
    let err = Scene::from_json(text).unwrap_err().to_string();
    assert!(err.contains("unknown variant"), "{err}");
}

/// The spin scenes among soak seeds `0..n` (`REALISM_SEEDS` overrides `n` for a long run),
/// with `change` applied to their model, all pass the monitor (no overlap, no energy gain,
/// rest within the cap).
fn soak_spin_scenes(n: u64, change: impl Fn(SpinModel) -> SpinModel) -> usize {
    let n = std::env::var("REALISM_SEEDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(n);
    let mut ran = 0;
    for seed in 0..n {
        let mut s = scenario(seed);
        let Model::Spin(m) = s.params.model else {
            continue;
        };
        s.params.model = Model::Spin(change(m));
        if let Err(v) = run_scenario(&s, Tolerances::default()) {
            panic!("seed {seed} ({}): {v}", s.kind);
        }
        ran += 1;
    }
    ran
}

#[test]
fn speed_dependent_ball_friction_keeps_every_invariant() {
    let ran = soak_spin_scenes(300, |m| SpinModel {
        ball_friction: BallFriction::ALCIATORE,
        ..m
    });
    assert!(ran > 50, "only {ran} spin scenes");
}

#[test]
fn a_scene_file_chooses_the_mathavan_cushion() {
    let text = r#"{ "rack": "nine_ball", "shots": [{ "ball": 0, "angle": 0.01, "speed": 3.0 }],
        "params": { "model": { "kind": "spin",
        "cushion": { "kind": "mathavan2010", "e": 0.98, "mu": 0.14 } } } }"#;
    let scene = Scene::from_json(text).unwrap();
    assert_eq!(spin_of(&scene).cushion, CushionModel::MATHAVAN_2010);
    let result = scene.run().expect("runs");
    assert!(result.error.is_none(), "{:?}", result.error);
    assert!(
        result
            .events
            .iter()
            .any(|e| matches!(e.kind, billiards_physics::EventKind::Cushion { .. }))
    );
    let bad = text.replace("0.98", "1.5");
    let err = Scene::from_json(&bad)
        .unwrap()
        .run()
        .unwrap_err()
        .to_string();
    assert!(err.contains("cushion.e"), "{err}");
}

#[test]
fn the_mathavan_cushion_keeps_every_invariant() {
    let ran = soak_spin_scenes(150, |m| SpinModel {
        cushion: match m.cushion {
            CushionModel::Han2005 { e, mu } | CushionModel::Mathavan2010 { e, mu } => {
                CushionModel::Mathavan2010 { e, mu }
            }
            CushionModel::Reflect { e } => CushionModel::Mathavan2010 { e, mu: 0.14 },
        },
        ..m
    });
    assert!(ran > 30, "only {ran} spin scenes");
}

#[test]
fn a_scene_file_sets_the_shafts_end_mass_and_old_files_have_no_squirt() {
    let old = r#"{ "rack": "nine_ball", "params": { "model": { "kind": "spin" } } }"#;
    assert_eq!(spin_of(&Scene::from_json(old).unwrap()).end_mass, None);
    let text = r#"{ "rack": "nine_ball",
        "shots": [{ "ball": 0, "angle": 0.0, "speed": 2.0, "tip": { "side": 0.4 } }],
        "params": { "model": { "kind": "spin", "end_mass": 0.008 } } }"#;
    let scene = Scene::from_json(text).unwrap();
    assert_eq!(spin_of(&scene).end_mass, Some(0.008));
    // The first event's cue ball heads left of the cue line (right english squirts left).
    let sim = scene.build().unwrap();
    assert!(sim.ball(0).velocity.y > 0.0, "{:?}", sim.ball(0).velocity);
    let bad = text.replace("0.008", "-0.008");
    let err = Scene::from_json(&bad)
        .unwrap()
        .run()
        .unwrap_err()
        .to_string();
    assert!(err.contains("end_mass"), "{err}");
}
