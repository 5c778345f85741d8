//! Noisy samples of the candidates at snooker, each judged by `Frame::play` on a clone and
//! scored, and the second ply's outcomes searched for the next stroke.

use super::budget::SnookerBudget;
use super::context::Snook;
use super::decision::SnookerDecision;
use super::search::decide_snooker_with;
use super::strokes::Cand;
use crate::evaluate::Stats;
use crate::noise::stream;
use crate::quiet::final_layout;
use billiards_physics::{EventKind, Simulation, Vec2, Vec3};
use billiards_rules::ShotSummary;
use billiards_rules::snooker::balls::WHITE;
use billiards_rules::snooker::{Frame, Stroke, Verdict};
use rand::Rng;

/// The stream of the second ply's outcomes: common to every finalist (close strokes meet the
/// same errors), far from the candidates' own streams and [`crate::Plan::executed`]'s.
const OUTCOMES: u64 = 1 << 62;
/// The stream of the seeds of the second ply's searches.
const STREAMS: u64 = (1 << 62) + 1;
/// Most events one sample may take before it is scored on the layout of the moment.
const MAX_EVENTS: usize = 600;
/// A refused stroke (a place the solver rejects, a stroke the rules refuse) costs this.
const REFUSED: f64 = 10.0;

/// The balls of `sim` on the table, by number.
pub(super) fn on_table(sim: &Simulation) -> Vec<(u8, Vec2)> {
    sim.balls()
        .zip(sim.numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect()
}

impl Snook<'_> {
    /// `c` placed and struck in `sim` (a copy of the base) with draw `k` of stream `id`: the
    /// balls before the stroke and the solver's event count at the strike; `None` when the
    /// solver refuses the place or the strike.
    fn strike(
        &self,
        c: &Cand,
        sim: &mut Simulation,
        id: u64,
        k: u64,
    ) -> Option<(Vec<(u8, Vec2)>, usize)> {
        if let Some(p) = c.cand.place {
            sim.place(self.cue, p, Vec2::ZERO, Vec3::ZERO).ok()?;
        }
        let before = on_table(sim);
        let shot = self
            .noise
            .apply(c.cand.shot, sim.params(), &mut stream(self.seed, id, k));
        let first = sim.event_count();
        sim.strike(self.cue, shot).ok()?;
        Some((before, first))
    }

    /// The frame after `c` as the rules judge it (`summary`, the balls `before` and `after`)
    /// and their verdict; `None` when the rules refuse the stroke.
    fn judge(
        &self,
        c: &Cand,
        summary: &ShotSummary,
        before: &[(u8, Vec2)],
        after: &[(u8, Vec2)],
    ) -> Option<(Frame, Verdict)> {
        let mut frame = self.frame.clone();
        let verdict = frame
            .play(Stroke {
                summary,
                nominated: c.nominated,
                before,
                after,
            })
            .ok()?;
        Some((frame, verdict))
    }

    /// One noisy sample of `c` (draw `k` of stream `id`) in the scratch simulation `sim`.
    pub(super) fn sample(&self, c: &Cand, id: u64, k: u64, sim: &mut Simulation) -> Stats {
        let refused = Stats {
            n: 1,
            value: -REFUSED,
            fouls: 1,
            ..Stats::default()
        };
        sim.clone_from(&self.base);
        let Some((before, first)) = self.strike(c, sim, id, k) else {
            return refused;
        };
        let mut summary = ShotSummary::default();
        let mut layout = None;
        while let Some(e) = sim.step_event() {
            summary.record(&e.kind, sim.numbers());
            if sim.event_count() - first > MAX_EVENTS {
                break;
            }
            if matches!(e.kind, EventKind::Transition { .. }) {
                layout = final_layout(sim);
                if layout.is_some() {
                    break;
                }
            }
        }
        let events = sim.event_count() - first;
        let after: Vec<(u8, Vec2)> = match layout {
            Some(l) => std::iter::once((WHITE, l.cue)).chain(l.balls).collect(),
            None => on_table(sim),
        };
        let Some((frame, verdict)) = self.judge(c, &summary, &before, &after) else {
            return Stats { events, ..refused };
        };
        let value = self.score(&frame, &verdict, &after);
        let pot = verdict.fair() && verdict.points > 0;
        Stats {
            n: 1,
            value,
            pots: usize::from(pot),
            fouls: usize::from(!verdict.fair()),
            losses: usize::from(verdict.end.is_some_and(|(w, _)| w != self.me)),
            events,
        }
    }

    /// Draw `k` of the outcomes' stream struck as `c`, run to rest and judged: its
    /// second-ply value (the stroke's own points and the next stroke's searched value, for
    /// or against the striker) minus its one-ply value, the simulations and the events. The
    /// end of the frame or a choice to make is not searched (a difference of 0).
    pub(super) fn correction(
        &self,
        c: &Cand,
        k: u64,
        reply: &SnookerBudget,
    ) -> (f64, usize, usize) {
        let mut sim = self.base.clone();
        let Some((before, first)) = self.strike(c, &mut sim, OUTCOMES, k) else {
            return (0.0, 1, 0);
        };
        let mut summary = ShotSummary::default();
        while let Some(e) = sim.step_event() {
            summary.record(&e.kind, sim.numbers());
            if sim.event_count() - first > 20 * MAX_EVENTS {
                return (0.0, 1, sim.event_count() - first);
            }
        }
        let events = sim.event_count() - first;
        let after = on_table(&sim);
        let Some((frame, verdict)) = self.judge(c, &summary, &before, &after) else {
            return (0.0, 1, events);
        };
        let Some(next) = verdict.next.clone() else {
            return (0.0, 1, events);
        };
        if !next.choices.is_empty() {
            return (0.0, 1, events);
        }
        let (_, position) = self.terms(&frame, &verdict, &after);
        for &(n, p) in &verdict.spots {
            let Some(id) = sim.numbers().iter().position(|&m| m == n) else {
                return (0.0, 1, events);
            };
            if sim.place(id, p, Vec2::ZERO, Vec3::ZERO).is_err() {
                return (0.0, 1, events);
            }
        }
        let sign = if next.striker == self.me { 1.0 } else { -1.0 };
        let seed = stream(self.seed, STREAMS, k).random();
        match decide_snooker_with(&frame, &sim, self.noise, reply, seed) {
            Ok(SnookerDecision::Shoot(plan)) => (
                sign * plan.value - position,
                1 + plan.simulations,
                events + plan.events,
            ),
            _ => (0.0, 1, events),
        }
    }
}

impl crate::rounds::Sampler for Snook<'_> {
    type Cand = Cand;
    type Scratch = Simulation;

    fn scratch(&self) -> Simulation {
        self.base.clone()
    }

    fn sample(&self, cand: &Cand, stream: u64, k: u64, sim: &mut Simulation) -> Stats {
        Snook::sample(self, cand, stream, k, sim)
    }
}
