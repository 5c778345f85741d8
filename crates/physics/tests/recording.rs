//! Recordings: round trips, exact verification, sampling without re-simulating, bad files.

use billiards_physics::recording::{Recorder, Recording, RecordingError, Verdict};
use billiards_physics::*;
use std::path::Path;

/// A game of several shots with a respot and a parameter change, in the spin model with
/// randomization on.
fn game() -> Recorder {
    let table = Table::wpa_8ft().with_jaws(0.015);
    let params = Params {
        model: Model::Spin(SpinModel::default()),
        randomization: Some(Randomization {
            spread: 0.01,
            seed: 9,
        }),
        ..Params::default()
    };
    let balls = Rack::NineBall.layout(&table, &params.ball);
    let mut rec = Recorder::new(table, params, balls).unwrap();
    rec.strike(0, Shot::new(0.0, 8.0)).unwrap();
    rec.run_to_rest().unwrap();
    rec.advance(0.5).unwrap();
    let free = Vec2::new(-0.8, 0.3);
    rec.place(0, free, Vec2::ZERO, Vec3::ZERO).unwrap();
    let mut p = params;
    if let Model::Spin(m) = &mut p.model {
        m.mu_roll = 0.015;
    }
    rec.set_params(p).unwrap();
    rec.strike(
        0,
        Shot {
            tip: TipOffset {
                side: 0.2,
                height: -0.3,
            },
            ..Shot::new(0.3, 3.0)
        },
    )
    .unwrap();
    for _ in 0..90 {
        rec.advance(1.0 / 60.0).unwrap();
    }
    rec.strike(0, Shot::new(2.0, 2.0)).unwrap_or(()); // may be in a pocket by now: not recorded then
    rec.run_to_rest().unwrap();
    rec
}

#[test]
fn saved_recording_loads_back_equal_and_verifies_bit_for_bit() {
    let rec = game().recording();
    assert!(rec.inputs.len() >= 4 && rec.events.len() > 50);
    let dir = std::env::temp_dir().join(format!("billiards-rec-{}", std::process::id()));
    let path = dir.join("game.json");
    rec.save(&path).unwrap();
    let back = Recording::load(&path).unwrap();
    assert_eq!(back, rec);
    assert_eq!(
        back.verify().unwrap(),
        Verdict::Reproduced {
            events: rec.events.len()
        }
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn history_rebuilt_from_the_file_samples_exactly_what_the_game_showed() {
    let live = game();
    let rec = live.recording();
    let rebuilt = rec.history().unwrap();
    let h = live.sim().history();
    for id in 0..h.ball_count() {
        assert_eq!(rebuilt.track(id), h.track(id), "ball {id}");
    }
    for k in 0..200 {
        let t = rec.end_time * k as f64 / 199.0;
        assert_eq!(rebuilt.states_at(t), h.states_at(t));
    }
}

#[test]
fn a_recording_edited_by_one_value_fails_verify_and_says_where() {
    let mut rec = game().recording();
    // Nudge the speed of the second strike by one part in a million.
    let k = rec
        .inputs
        .iter()
        .enumerate()
        .filter(|(_, i)| matches!(i.action, recording::Action::Strike { .. }))
        .nth(1)
        .unwrap()
        .0;
    if let recording::Action::Strike { shot, .. } = &mut rec.inputs[k].action {
        shot.speed *= 1.000001;
    }
    match rec.verify().unwrap() {
        Verdict::Differs {
            index,
            recorded,
            replayed,
        } => {
            assert!(
                index > 0 && recorded.is_some() && replayed.is_some(),
                "{index}"
            );
        }
        v => panic!("edited recording verified: {v:?}"),
    }
}

fn load_text(text: &str) -> Result<Recording, RecordingError> {
    Recording::from_json(text, Path::new("corpus.json"))
}

#[test]
fn broken_files_give_errors_that_name_the_file_and_never_panic() {
    let good = serde_json::to_string(&game().recording()).unwrap();
    // Empty, truncated at every byte of a small recording, and the whole file.
    let small = {
        let table = Table::wpa_8ft();
        let params = Params::default();
        let mut rec = Recorder::new(
            table,
            params,
            Rack::PaperDefault.layout(&table, &params.ball),
        )
        .unwrap();
        rec.strike(0, Shot::new(0.5, 1.0)).unwrap();
        rec.run_to_rest().unwrap();
        serde_json::to_string(&rec.recording()).unwrap()
    };
    assert!(load_text(&small).is_ok());
    for cut in 0..small.len() {
        let err = load_text(&small[..cut]).expect_err("a truncated file must not load");
        assert!(err.to_string().starts_with("corpus.json"), "{err}");
    }
    let v: serde_json::Value = serde_json::from_str(&good).unwrap();
    let edit = |f: &dyn Fn(&mut serde_json::Value)| {
        let mut v = v.clone();
        f(&mut v);
        load_text(&v.to_string())
    };
    assert!(matches!(
        edit(&|v| v["version"] = 99.into()),
        Err(RecordingError::FutureVersion { found: 99, .. })
    ));
    assert!(matches!(
        edit(&|v| v["table"]["length"] = "long".into()),
        Err(RecordingError::Parse { .. })
    ));
    assert!(matches!(
        edit(&|v| v["balls"][0]["position"]["x"] = serde_json::Value::Null),
        Err(RecordingError::Parse { .. })
    ));
    // NaN is not JSON; a huge number overflows to infinity and is refused as not finite.
    let mut huge = v.clone();
    huge["balls"][0]["position"]["x"] = 12345.678.into();
    assert!(load_text(&huge.to_string().replace("12345.678", "1e400")).is_err());
    assert!(matches!(
        edit(&|v| v["balls"][1]["position"]["x"] = v["balls"][2]["position"]["x"].clone()),
        Err(RecordingError::Invalid { .. })
    ));
    assert!(matches!(
        edit(&|v| v["end_time"] = (-1.0).into()),
        Err(RecordingError::Invalid { .. })
    ));
    assert!(matches!(
        edit(&|v| v["events"][3]["time"] = 1e9.into()),
        Err(RecordingError::Invalid { .. })
    ));
    assert!(matches!(load_text(""), Err(RecordingError::Parse { .. })));
    assert!(matches!(
        Recording::load(Path::new("/nonexistent/x.json")),
        Err(RecordingError::Io { .. })
    ));
}

#[test]
fn saving_over_an_existing_recording_replaces_it_whole() {
    let dir = std::env::temp_dir().join(format!("billiards-atomic-{}", std::process::id()));
    let path = dir.join("g.json");
    let rec = game().recording();
    rec.save(&path).unwrap();
    let mut shorter = rec.clone();
    shorter.events.truncate(10);
    shorter.end_time = shorter.events[9].time;
    shorter.inputs.retain(|i| i.time <= shorter.end_time);
    shorter.save(&path).unwrap();
    assert_eq!(Recording::load(&path).unwrap(), shorter);
    // No temporary files are left behind.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 1, "{names:?}");
    std::fs::remove_dir_all(dir).ok();
}

/// A frozen 9-ball break on a 9-ft table, in the spin model with cluster impacts or without.
fn frozen_break(cluster: bool) -> Recording {
    let table = Table::wpa_9ft().with_jaws(0.015);
    let m = SpinModel::default();
    let params = Params {
        model: Model::Spin(SpinModel {
            cluster: if cluster { m.cluster } else { None },
            ..m
        }),
        ..Params::default()
    };
    let balls = Rack::NineBall.layout(&table, &params.ball);
    let mut rec = Recorder::new(table, params, balls).unwrap();
    rec.strike(0, Shot::new(0.0, 11.0)).unwrap();
    rec.run_to_rest().unwrap();
    rec.recording()
}

#[test]
fn a_recording_from_before_cluster_impacts_loads_and_verifies_pair_by_pair() {
    // A file written before `cluster` existed has no such key: it must load as pairwise
    // (the solver it was made with) and reproduce every event.
    let old = frozen_break(false);
    let json = serde_json::to_string(&old).unwrap();
    assert!(json.contains("\"cluster\":null"), "the key is written");
    let stripped = json.replace(",\"cluster\":null", "");
    assert!(!stripped.contains("cluster"));
    let loaded = Recording::from_json(&stripped, Path::new("old.json")).unwrap();
    assert!(matches!(loaded.verify(), Ok(Verdict::Reproduced { .. })));
    // The same break with cluster impacts is another history, which also verifies, and its
    // table (9 ft) is kept.
    let new = frozen_break(true);
    assert_ne!(new.events, old.events);
    let text = serde_json::to_string(&new).unwrap();
    let back = Recording::from_json(&text, Path::new("new.json")).unwrap();
    assert_eq!(back.table.length, 100.0 * table::INCH);
    assert!(matches!(back.verify(), Ok(Verdict::Reproduced { .. })));
}
