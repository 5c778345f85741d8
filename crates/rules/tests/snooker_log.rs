//! The rules log of a snooker frame: a frame played on the solver by a crude player (straight
//! at a ball on, seeded speeds), recorded with every placement (the cue ball in hand in the
//! D, the colours spotted), logged, and re-judged from the recording by [`FrameLog::check`];
//! an edited verdict, an edited nomination, a missing stroke or a colour left unspotted is
//! found and named.

use billiards_physics::recording::{Action, Recorder, Recording};
use billiards_physics::snooker::{default_cue_position, layout};
use billiards_physics::{Params, Shot, SnookerMarks, Table, Vec2, Vec3};
use billiards_rules::snooker::balls::{WHITE, is_colour};
use billiards_rules::snooker::{
    BallOn, Choice, Frame, FrameLog, FrameLogError, LoggedStroke, Stroke,
};
use billiards_rules::{GameLog, RulesLog, Seat, summarise};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::{Path, PathBuf};

fn on_table(rec: &Recorder) -> Vec<(u8, Vec2)> {
    let sim = rec.sim();
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}

fn place_in_d(marks: &SnookerMarks, balls: &[(u8, Vec2)], r: f64) -> Vec2 {
    let base = default_cue_position(marks);
    (0..40)
        .map(|k| base + Vec2::new(-0.02 * f64::from(k % 5), 0.1 * (f64::from(k) * 0.7).sin()))
        .find(|&p| {
            marks.in_d(p)
                && balls
                    .iter()
                    .filter(|b| b.0 != WHITE)
                    .all(|&(_, q)| (p - q).length() > 2.0 * r + 1e-4)
        })
        .expect("a free place in the D")
}

/// Up to `strokes` strokes of a frame, recorded and logged. The incoming player plays on or
/// puts the offender back (a replace would need its balls set one by one; the computer's
/// frames in crates/ai/tests/snooker.rs check those).
fn played(seed: u64, strokes: usize) -> (FrameLog, Recording) {
    let table = Table::snooker_12ft();
    let params = Params::snooker();
    let r = params.ball.radius;
    let marks = SnookerMarks::of(&table).unwrap();
    let balls = layout(&table, &params.ball, default_cue_position(&marks)).unwrap();
    let mut rec = Recorder::new(table, params, balls).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let names = ["Ann".to_owned(), "Bob".to_owned()];
    let mut frame = Frame::new(names.clone(), table, &params.ball, Seat::A).unwrap();
    let mut log = FrameLog::new(names, Seat::A);
    let id = |rec: &Recorder, n: u8| rec.sim().numbers().iter().position(|&m| m == n).unwrap();
    while frame.end.is_none() && log.strokes.len() < strokes {
        let mut choices = Vec::new();
        while !frame.next.choices.is_empty() {
            let c = if let Some(&c) = frame
                .next
                .choices
                .iter()
                .find(|c| matches!(c, Choice::BlackFirst(_)))
            {
                c
            } else if rng.random_bool(0.3) {
                Choice::PutBack
            } else {
                Choice::PlayOn
            };
            frame.choose(c).unwrap();
            choices.push(c);
        }
        if frame.next.in_hand {
            let p = place_in_d(&marks, &on_table(&rec), r);
            rec.place(0, p, Vec2::ZERO, Vec3::ZERO).unwrap();
        }
        let balls = on_table(&rec);
        let on = frame.balls_on(frame.next.on);
        let targets: Vec<(u8, Vec2)> = balls
            .iter()
            .copied()
            .filter(|b| on.contains(&b.0))
            .collect();
        let (target, tp) = targets[rng.random_range(0..targets.len())];
        let cue = balls.iter().find(|b| b.0 == WHITE).unwrap().1;
        let nominated = matches!(frame.next.on, BallOn::Colour { .. }).then_some(target);
        assert!(nominated.is_none_or(is_colour));
        let first = rec.sim().history().events().len();
        let speed = rng.random_range(1.0..4.0);
        rec.strike(0, Shot::new((tp - cue).angle(), speed)).unwrap();
        rec.run_to_rest().unwrap();
        let summary = summarise(&rec.sim().history().events()[first..], rec.sim().numbers());
        let after = on_table(&rec);
        let verdict = frame
            .play(Stroke {
                summary: &summary,
                nominated,
                before: &balls,
                after: &after,
            })
            .unwrap();
        for &(c, p) in &verdict.spots {
            let b = id(&rec, c);
            rec.place(b, p, Vec2::ZERO, Vec3::ZERO).unwrap();
        }
        log.strokes.push(LoggedStroke {
            choices,
            nominated,
            verdict,
        });
    }
    (log, rec.recording())
}

/// A frame long enough to have fouls, a nominated colour and a spotted colour.
fn rich_frame() -> (FrameLog, Recording) {
    for seed in 0..20 {
        let (log, rec) = played(seed, 100);
        let fouls = log.strokes.iter().any(|s| !s.verdict.fair());
        let nominated = log.strokes.iter().any(|s| s.nominated.is_some());
        let spotted = log.strokes.iter().any(|s| !s.verdict.spots.is_empty());
        if fouls && nominated && spotted {
            return (log, rec);
        }
    }
    panic!("no seed of 20 gave a frame with a foul, a nomination and a spot");
}

#[test]
fn a_logged_frame_rejudges_from_its_recording_and_edits_are_found() {
    let (log, rec) = rich_frame();
    assert_eq!(log.check(&rec), Ok(log.strokes.len()));
    // Through JSON and back.
    let json = serde_json::to_string(&log).unwrap();
    assert_eq!(FrameLog::from_json(&json).unwrap(), log);

    // An edited verdict: a point more for the striker of a scoring stroke.
    let k = log
        .strokes
        .iter()
        .position(|s| s.verdict.points > 0)
        .unwrap();
    let mut edited = log.clone();
    edited.strokes[k].verdict.points += 1;
    assert!(
        matches!(edited.check(&rec), Err(FrameLogError::Differs { stroke, .. }) if stroke == k + 1)
    );

    // An edited nomination: another colour than the one played after a red (2.12).
    let k = log
        .strokes
        .iter()
        .position(|s| s.nominated.is_some())
        .unwrap();
    let mut edited = log.clone();
    let c = edited.strokes[k].nominated.unwrap();
    edited.strokes[k].nominated = Some(if c == 21 { 20 } else { c + 1 });
    let err = edited.check(&rec).unwrap_err();
    assert!(
        matches!(err, FrameLogError::Differs { stroke, .. } | FrameLogError::Refused { stroke, .. } if stroke == k + 1),
        "{err}"
    );

    // A stroke missing from the log.
    let mut short = log.clone();
    short.strokes.pop();
    assert!(matches!(
        short.check(&rec),
        Err(FrameLogError::StrokeCount { .. })
    ));

    // Another breaker: the first verdict names another striker.
    let mut other = log.clone();
    other.breaker = Seat::B;
    assert!(matches!(
        other.check(&rec),
        Err(FrameLogError::Differs { stroke: 1, .. })
    ));
}

#[test]
fn a_colour_left_unspotted_in_the_recording_is_found() {
    let (log, rec) = rich_frame();
    // Drop the placement of the first colour spotted: the next strike's table is wrong.
    let k = log
        .strokes
        .iter()
        .position(|s| !s.verdict.spots.is_empty())
        .unwrap();
    let (colour, _) = log.strokes[k].verdict.spots[0];
    let colour_id = rec.balls.iter().position(|b| b.number == colour).unwrap();
    let strike_k = rec
        .inputs
        .iter()
        .enumerate()
        .filter(|(_, i)| matches!(i.action, Action::Strike { .. }))
        .nth(k)
        .unwrap()
        .0;
    let mut cut = rec.clone();
    let spot = (strike_k + 1..cut.inputs.len())
        .find(|&i| matches!(cut.inputs[i].action, Action::Place { ball, .. } if ball == colour_id))
        .unwrap();
    cut.inputs.remove(spot);
    cut.events.clear();
    match log.check(&cut) {
        // The colour stayed in the pocket (the strike after finds it missing), or the
        // strokes after it went otherwise (their verdicts differ).
        Err(FrameLogError::Table { stroke, .. }) => assert_eq!(stroke, k + 2),
        Err(FrameLogError::Differs { stroke, .. }) => assert!(stroke > k + 1),
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_log_lives_beside_the_recording() {
    // One name for every game's log: a frame's is a pool game's `NAME.game.json`.
    assert_eq!(
        FrameLog::path_beside(Path::new("/tmp/frame.json")),
        PathBuf::from("/tmp/frame.game.json")
    );
    assert_eq!(
        FrameLog::path_beside(Path::new("/tmp/frame.json")),
        GameLog::path_beside(Path::new("/tmp/frame.json"))
    );
    assert_eq!(
        FrameLog::old_path_beside(Path::new("/tmp/frame.json")),
        PathBuf::from("/tmp/frame.snooker.json")
    );
    let other = r#"{"version":2,"players":["A","B"],"breaker":"a","strokes":[]}"#;
    assert!(
        FrameLog::from_json(other)
            .unwrap_err()
            .contains("version 2")
    );
}

#[test]
fn a_replace_swapping_two_balls_is_placed_without_an_overlap() {
    use billiards_rules::interface::layout_moves;
    let table = Table::snooker_12ft();
    let r = Params::snooker().ball.radius;
    let (a, b, c) = (
        Vec2::new(0.3, 0.1),
        Vec2::new(0.3 + 2.0 * r + 1e-3, 0.1),
        Vec2::new(-0.5, 0.4),
    );
    // The red and the cue ball swap places, the blue comes back from the pocket.
    let now = [(WHITE, a), (1, b)];
    let layout = [(WHITE, b), (1, a), (19, c)];
    let moves = layout_moves(&now, &layout, r, &table).unwrap();
    let mut at: Vec<(u8, Vec2)> = now.to_vec();
    for &(n, p) in &moves {
        at.retain(|q| q.0 != n);
        for &(m, q) in &at {
            assert!(
                (p - q).length() >= 2.0 * r,
                "ball {n} placed on ball {m}: {moves:?}"
            );
        }
        at.push((n, p));
    }
    for (n, p) in layout {
        assert_eq!(
            at.iter().find(|q| q.0 == n).map(|q| q.1),
            Some(p),
            "ball {n}"
        );
    }
    assert!(
        moves.len() > layout.len(),
        "one ball parked first: {moves:?}"
    );
}

/// A fresh empty folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "billiards-snooker-log-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_frame_log_saved_as_game_json_is_found_and_read_as_a_frame() {
    let (log, rec) = played(7, 4);
    let dir = scratch("new");
    let recording = dir.join("frame.json");
    let path = FrameLog::path_beside(&recording);
    assert!(path.to_string_lossy().ends_with("frame.game.json"));
    std::fs::write(&path, serde_json::to_string_pretty(&log).unwrap()).unwrap();
    let (found, read) = RulesLog::beside(&recording).expect("the log beside is found");
    assert_eq!(found, path);
    // Told apart from a pool log by content: read as the frame it is, and it re-judges.
    match read.unwrap() {
        RulesLog::Snooker(read) => {
            assert_eq!(read, log);
            assert_eq!(read.check(&rec).unwrap(), log.strokes.len());
        }
        other => panic!("read as {other:?}"),
    }
    assert_eq!(RulesLog::recording_beside(&path), Some(recording));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_old_snooker_json_log_is_still_read() {
    let (log, _) = played(8, 3);
    let dir = scratch("old");
    let recording = dir.join("frame.json");
    // As builds before the one-name change saved it.
    let old = dir.join("frame.snooker.json");
    std::fs::write(&old, serde_json::to_string(&log).unwrap()).unwrap();
    let (found, read) = RulesLog::beside(&recording).expect("the old log is found");
    assert_eq!(found, old);
    assert_eq!(read.unwrap(), RulesLog::Snooker(log));
    assert_eq!(RulesLog::recording_beside(&old), Some(recording.clone()));
    // No log at all: nothing found.
    std::fs::remove_file(&old).unwrap();
    assert!(RulesLog::beside(&recording).is_none());
    // Neither kind: refused with a reason, not taken for a log.
    let err = RulesLog::from_json(r#"{"version":1,"balls":[]}"#).unwrap_err();
    assert!(err.contains("not a rules log"), "{err}");
    assert!(!RulesLog::is_log("[1, 2]"));
    std::fs::remove_dir_all(&dir).unwrap();
}
