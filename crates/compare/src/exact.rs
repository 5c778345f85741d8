//! The exact event-driven solver and the paper's linear prediction, both through
//! `billiards-physics`.

use crate::scene::Scene;
use crate::trace::{CONTACT_TOLERANCE, Contact, ContactKey, OverlapWatch, Sample, Trace};
use billiards_physics::{BallState, EventKind, Motion, Prediction, Simulation};
use std::error::Error;

/// How the caller slices time when it advances the simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Slicing {
    /// One `advance_to(end)` call: the cheapest way to get the state at the end.
    Single,
    /// One `advance` per frame of this length, reading every ball after each frame, as the
    /// game does.
    Frames(f64),
}

/// Interval of the grid on which diagnostic runs look for overlaps between events, seconds.
const DIAGNOSTIC_GRID: f64 = 1e-3;

/// Converts a ball state of the library into a sample.
pub fn sample(s: &BallState) -> Sample {
    Sample {
        position: s.position,
        velocity: s.velocity,
        pocketed: match s.motion {
            Motion::Pocketed(p) => Some(p),
            _ => None,
        },
    }
}

/// Runs `scene` with the given prediction until `end` and returns the simulation (whose
/// history is the reference trajectory) and the trace sampled from that history. With
/// `diagnose`, the history is also scanned on a 1 ms grid for overlaps.
pub fn run(
    scene: &Scene,
    prediction: Prediction,
    slicing: Slicing,
    end: f64,
    diagnose: bool,
) -> Result<(Simulation, Trace), Box<dyn Error>> {
    let params = billiards_physics::Params {
        prediction,
        ..scene.params
    };
    let mut sim = Simulation::new(scene.table, params, &scene.balls)?;
    match slicing {
        Slicing::Single => {
            sim.advance_to(end)?;
        }
        Slicing::Frames(frame) => {
            let frames = (end / frame).round() as usize;
            for j in 1..=frames {
                // Absolute frame times, so no rounding accumulates in the clock.
                sim.advance_to((j as f64 * frame).min(end))?;
                for s in sim.balls() {
                    std::hint::black_box(s);
                }
            }
            sim.advance_to(end)?;
        }
    }
    let samples = (0..=sample_count(scene, end))
        .map(|k| {
            sim.history()
                .states_at(k as f64 * scene.sample_interval)
                .iter()
                .map(sample)
                .collect()
        })
        .collect();
    let contacts = contacts(&sim);
    let mut trace = Trace {
        samples,
        contacts,
        ..Trace::default()
    };
    if diagnose {
        trace.diagnostics = diagnose_history(scene, &sim, &trace.contacts, end);
    }
    Ok((sim, trace))
}

/// Index of the last sample time at or before `end`.
pub fn sample_count(scene: &Scene, end: f64) -> usize {
    (end / scene.sample_interval + 1e-9).floor() as usize
}

/// The collisions and pocketings of a simulation's history.
pub fn contacts(sim: &Simulation) -> Vec<Contact> {
    sim.history()
        .events()
        .iter()
        .filter_map(|e| {
            let key = match e.kind {
                EventKind::BallBall { a, b } => ContactKey::pair(a, b),
                EventKind::Cushion { ball, .. } => ContactKey::Cushion(ball),
                EventKind::Pocketed { ball, .. } => ContactKey::Pocket(ball),
                _ => return None,
            };
            Some(Contact { time: e.time, key })
        })
        .collect()
}

/// Scans the history on a fine grid for overlaps and escapes. An overlap episode with no
/// contact between the pair within two grid intervals of its start is a pass-through
/// (tunnelling): the linear prediction can miss a contact that the decelerating balls make.
fn diagnose_history(
    scene: &Scene,
    sim: &Simulation,
    contacts: &[Contact],
    end: f64,
) -> crate::trace::Diagnostics {
    let n = sim.ball_count();
    let mut watch = OverlapWatch::new(n);
    let steps = (end / DIAGNOSTIC_GRID).ceil() as usize;
    let mut tunnelled = 0;
    for k in 0..=steps {
        let t = (k as f64 * DIAGNOSTIC_GRID).min(end);
        let balls: Vec<Sample> = sim.history().states_at(t).iter().map(sample).collect();
        for (a, b) in watch.observe(&balls, scene.radius(), scene.bounds()) {
            let key = ContactKey::pair(a, b);
            let resolved = contacts
                .iter()
                .any(|c| c.key == key && (c.time - t).abs() <= 2.0 * DIAGNOSTIC_GRID);
            if !resolved {
                tunnelled += 1;
            }
        }
    }
    let mut d = watch.diagnostics;
    d.tunnelled = tunnelled;
    // Where each collision was resolved: an event-driven solver resolves a contact exactly
    // at touching; anything else is a wrong prediction (or, in linear prediction, the
    // paper's slip 4).
    for e in sim.history().events() {
        if let EventKind::BallBall { .. } = e.kind {
            let gap =
                ((e.after[1].position - e.after[0].position).length() - 2.0 * scene.radius()).abs();
            d.max_contact_gap = d.max_contact_gap.max(gap);
            if gap > CONTACT_TOLERANCE {
                d.gap_contacts += 1;
            }
        }
    }
    d
}
