//! Measuring a run against the reference: position and energy errors, matched contacts,
//! outcomes, and run time.

use crate::trace::{Contact, Sample, kinetic_energy};
use std::time::Instant;

/// How a run differs from the reference.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Errors {
    /// Largest distance between a ball and its reference position at any sample time up to
    /// the horizon, metres.
    pub position: f64,
    /// Largest kinetic energy difference at any sample time up to the energy horizon,
    /// relative to the reference's starting energy.
    pub energy: f64,
    /// Largest distance between a ball and its reference position at the end of the run,
    /// metres (after the horizon of a chaotic scene this says little about the solver).
    pub final_position: f64,
    /// Balls pocketed in a different pocket, or pocketed in one run only, at the end.
    pub pocket_differences: usize,
}

/// Compares the samples of `run` with those of `reference`: positions up to sample index
/// `horizon`, energies up to `energy_horizon`, outcomes at their last common sample.
pub fn errors(
    reference: &[Vec<Sample>],
    run: &[Vec<Sample>],
    horizon: usize,
    energy_horizon: usize,
    mass: f64,
) -> Errors {
    let e0 = kinetic_energy(&reference[0], mass).max(f64::MIN_POSITIVE);
    let distance = |a: &[Sample], b: &[Sample]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x.position - y.position).length())
            .fold(0.0, f64::max)
    };
    let mut e = Errors::default();
    for (k, (r, s)) in reference.iter().zip(run).enumerate() {
        if k <= horizon {
            e.position = e.position.max(distance(r, s));
        }
        if k <= energy_horizon {
            let de = (kinetic_energy(r, mass) - kinetic_energy(s, mass)).abs() / e0;
            e.energy = e.energy.max(de);
        }
    }
    if e.energy.is_nan() {
        e.energy = f64::INFINITY;
    }
    let last = reference.len().min(run.len()) - 1;
    e.final_position = distance(&reference[last], &run[last]);
    e.pocket_differences = reference[last]
        .iter()
        .zip(&run[last])
        .filter(|(a, b)| a.pocketed != b.pocketed)
        .count();
    // NaN (a solver that blew up) must not read as zero error.
    if !e.position.is_finite() {
        e.position = f64::INFINITY;
    }
    e
}

/// How many contacts of the reference a run reproduced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ContactMatch {
    /// Reference contacts up to the horizon.
    pub reference: usize,
    /// The run's contacts up to the horizon (consecutive reports of one contact merged).
    pub run: usize,
    /// Reference contacts with no contact of the same bodies in the run within the window.
    pub missed: usize,
    /// Run contacts with no reference contact of the same bodies within the window.
    pub extra: usize,
}

/// Matches contacts of `run` to those of `reference` with the same bodies and times within
/// `window` seconds, up to time `horizon`. A fixed-step solver with soft contacts (Rapier) may
/// report one contact in several consecutive steps; reports of the same bodies within
/// `repeat` seconds of the previous one count once (pass 1.5 time steps, or 0).
pub fn match_contacts(
    reference: &[Contact],
    run: &[Contact],
    window: f64,
    repeat: f64,
    horizon: f64,
) -> ContactMatch {
    let within = |c: &&Contact| c.time <= horizon;
    let reference: Vec<Contact> = reference.iter().filter(within).copied().collect();
    let mut merged: Vec<Contact> = Vec::new();
    for c in run.iter().filter(within) {
        let repeat = merged
            .iter()
            .rev()
            .take_while(|m| c.time - m.time <= repeat)
            .any(|m| m.key == c.key);
        if !repeat {
            merged.push(*c);
        }
    }
    let mut used = vec![false; merged.len()];
    let mut missed = 0;
    for r in &reference {
        let found = merged
            .iter()
            .enumerate()
            .find(|(k, m)| !used[*k] && m.key == r.key && (m.time - r.time).abs() <= window);
        match found {
            Some((k, _)) => used[k] = true,
            None => missed += 1,
        }
    }
    ContactMatch {
        reference: reference.len(),
        run: merged.len(),
        missed,
        extra: used.iter().filter(|u| !**u).count(),
    }
}

/// Most timed runs per configuration.
pub const MAX_REPS: usize = 1000;

/// Run time above which the warm-up run counts as a timed run, seconds: caches and the
/// allocator are warm long before it ends.
const LONG_RUN: f64 = 1.0;

/// Median wall-clock time of repeated runs of `f`, how many timed runs it took, and the last
/// run's output.
///
/// A first run decides the repetitions: enough to fill about `budget` seconds, at least
/// `min_reps` and at most [`MAX_REPS`] (many runs of a fast configuration make its median
/// robust against colleagues' builds on a shared machine). It is a warm-up, untimed, unless it
/// took over a second.
pub fn median_time<T>(budget: f64, min_reps: usize, mut f: impl FnMut() -> T) -> (f64, usize, T) {
    let t0 = Instant::now();
    let mut out = f();
    let first = t0.elapsed().as_secs_f64();
    let reps = ((budget / first.max(1e-9)) as usize).clamp(min_reps.max(1), MAX_REPS);
    let mut times = Vec::with_capacity(reps);
    if first > LONG_RUN {
        times.push(first);
    }
    while times.len() < reps {
        let t = Instant::now();
        out = std::hint::black_box(f());
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let mid = times.len() / 2;
    let median = if times.len() % 2 == 1 {
        times[mid]
    } else {
        0.5 * (times[mid - 1] + times[mid])
    };
    (median, reps, out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::ContactKey;

    fn c(time: f64, key: ContactKey) -> Contact {
        Contact { time, key }
    }

    #[test]
    fn contacts_match_by_bodies_within_the_window() {
        let reference = [
            c(0.10, ContactKey::pair(0, 1)),
            c(0.50, ContactKey::Cushion(1)),
        ];
        let run = [
            c(0.12, ContactKey::pair(1, 0)),
            c(0.13, ContactKey::pair(0, 1)), // a soft contact reported again next step
            c(0.90, ContactKey::Cushion(1)), // too late: the reference's is missed
        ];
        let m = match_contacts(&reference, &run, 0.05, 0.015, 1.0);
        assert_eq!(
            m,
            ContactMatch {
                reference: 2,
                run: 2,
                missed: 1,
                extra: 1
            }
        );
        // Without merging repeats, the second report is an extra contact.
        assert_eq!(match_contacts(&reference, &run, 0.05, 0.0, 1.0).extra, 2);
    }

    #[test]
    fn errors_take_the_worst_ball_and_sample_up_to_the_horizon() {
        let s = |x: f64, v: f64| Sample {
            position: billiards_physics::Vec2::new(x, 0.0),
            velocity: billiards_physics::Vec2::new(v, 0.0),
            pocketed: None,
        };
        let reference = vec![vec![s(0.0, 1.0)], vec![s(1.0, 1.0)], vec![s(2.0, 1.0)]];
        let run = vec![vec![s(0.0, 1.0)], vec![s(1.1, 1.0)], vec![s(5.0, 0.0)]];
        let e = errors(&reference, &run, 1, 1, 2.0);
        assert!((e.position - 0.1).abs() < 1e-12);
        assert_eq!(e.energy, 0.0);
        assert_eq!(e.final_position, 3.0);
    }
}
