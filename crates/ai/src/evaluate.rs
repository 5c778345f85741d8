//! Evaluation under execution noise: each candidate simulated N times with Gaussian noise on
//! its aim, speed and tip ([`crate::noise`]), each run judged by the rules
//! ([`GameState::play`] on the shot's [`ShotSummary`]) and scored from the shooter's side.
//! A player at the table whose best next shot succeeds with probability `p` is worth
//! [`at_table`]`(p) = W p - M (1 - p)` to them (one ply: the next shot, then a miss hands
//! the opponent a chance), `W` = 1 when that shot is for the game ball and
//! [`RUN_WEIGHT`] otherwise, `M` the cost of a miss in that game ([`miss_cost`]):
//!
//! | what the verdict says                    | value                                        |
//! |------------------------------------------|----------------------------------------------|
//! | the shooter wins the game                | 1                                            |
//! | the shooter loses the game               | -1                                           |
//! | a foul (opponent has ball in hand)       | -at_table([`IN_HAND`]) for the opponent      |
//! | legal, the shooter continues             | at_table(p), p = own best next shot          |
//! | legal, the turn passes                   | -at_table(q), q = the opponent's best shot   |
//! | a legal push out                         | -at_table(max(q, 1 - q)): the opponent picks |
//!
//! `p` and `q` come from [`crate::position::best_success`] on the layout at rest. The mean
//! over the samples is the probability of a legal pot times the value of the position left,
//! minus the probability and cost of a foul or a loss.
//!
//! Lean mode ([`Mode::Lean`]): the solver keeps no history, each event is read as it comes
//! ([`Simulation::step_event`]) into the summary, and the run stops as soon as the verdict is
//! settled (see [`settled`]), where a position would not be looked at anyway.

use crate::candidates::{Candidate, Layout};
use crate::noise::{Noise, stream};
use crate::position::best_success;
use crate::quiet::final_layout;
use crate::rounds::Sampler;
pub use crate::rounds::{Stats, best_candidate};
use billiards_physics::{BallId, EventKind, Simulation, Vec2, Vec3};
use billiards_rules::{Call, Game, GameState, Outcome, Seat, ShotSummary, Verdict, summarise};

/// The value of a shot that runs on when it is not for the game ball: a share of the rest
/// of the run.
pub const RUN_WEIGHT: f64 = 0.85;
/// What a miss costs the player at the table: the opponent's chance it hands over, by game.
/// In 9-ball one ball can end the rack (the 9 on a combination, or a short run), so a miss
/// costs more than in 8-ball, where the opponent still has a group to clear first. Tuned by
/// tournaments (crates/ai/README.md): in 9-ball 0.4 wins 84.0 % of 600 games against the
/// greedy player where 0.3 won 83.5 % of 400 and 0.5 85.5 %, but 0.5 halved hard's break
/// and run (11 % at 0.4, 6 % at 0.5); in 8-ball 0.5 cost 3.5 points, so 0.3 stays.
pub fn miss_cost(game: Game) -> f64 {
    match game {
        Game::NineBall => 0.4,
        Game::EightBall | Game::FreePlay => 0.3,
    }
}
/// The success probability of a shot with the cue ball in hand.
pub const IN_HAND: f64 = 0.8;
/// The cost of a foul when nothing else is known (an illegal call, a refused placement).
pub const FOUL_COST: f64 = 0.6;

/// The value to a player at the table whose best shot succeeds with probability `p`, `game`
/// when that shot is for the game ball, a miss costing `miss` ([`miss_cost`]).
pub fn at_table(p: f64, game: bool, miss: f64) -> f64 {
    let w = if game { 1.0 } else { RUN_WEIGHT };
    w * p - miss * (1.0 - p)
}

/// Whether the next shot of `next` is for the game ball (the 9, or the 8 with the group down).
fn for_game_ball(state: &GameState, legal: &[u8]) -> bool {
    match state.game {
        Game::NineBall => legal == [9],
        Game::EightBall => legal == [8],
        Game::FreePlay => false,
    }
}

/// Most events one sample may take before it is cut short and scored on the layout of the
/// moment: a shot takes 10 to 50, but one into a cluster of frozen balls can run into
/// thousands of resting-contact hops whose end changes nothing the score reads.
const MAX_EVENTS: usize = 300;
/// The same for a break (a rack scattering takes a few hundred).
const MAX_BREAK_EVENTS: usize = 20_000;

/// How a sample runs the solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// No history, events read one at a time, stopped once the verdict is settled.
    Lean,
    /// The history on, run to rest, summarised from the history (for comparison).
    Full,
}

/// Draws `samples` of candidate `cand` from the random streams `(seed, stream, k)`.
#[derive(Clone, Debug)]
pub struct Run<'c> {
    /// The candidate.
    pub cand: &'c Candidate,
    /// The stream of its draws (its index in the search).
    pub stream: u64,
    /// The draws `k`.
    pub samples: std::ops::Range<u64>,
}

/// What one thread reuses from sample to sample: the simulation (reset from the search's
/// base) and the shot's summary (cleared), so a sample allocates neither anew.
#[derive(Clone, Debug)]
pub struct Scratch {
    /// The simulation a sample runs in.
    pub sim: Simulation,
    /// The summary of the sample's shot.
    pub summary: ShotSummary,
}

impl Scratch {
    /// A scratch for samples from `base`.
    pub fn new(base: &Simulation) -> Self {
        Self {
            sim: base.clone(),
            summary: ShotSummary::default(),
        }
    }
}

/// Everything a search shares: the rules' state, the resting table and the noise it plans
/// under.
#[derive(Clone, Debug)]
pub struct Search<'a> {
    /// The rack's state (the next shot as it asks).
    pub state: &'a GameState,
    /// The table at rest, in lean mode (no history).
    pub base: Simulation,
    /// The cue ball's index in the solver.
    pub cue: BallId,
    /// The noise the candidates are sampled under.
    pub noise: Noise,
    /// The decision's seed.
    pub seed: u64,
    /// How samples run the solver.
    pub mode: Mode,
}

/// Whether nothing later in the shot can change what the sample is scored on: a foul in
/// 9-ball (a scratch, or a wrong first ball unless the shot is a push out), whose cost does
/// not depend on where the balls stop; in 8-ball, the 8 down when it was not on, or down
/// with the cue ball (the game is lost either way, WPA 3.8).
pub fn settled(state: &GameState, call: Call, summary: &ShotSummary) -> bool {
    let legal = &state.next.legal_first;
    match state.game {
        Game::NineBall => {
            summary.scratch()
                || (call != Call::PushOut
                    && summary.first_contact.is_some_and(|b| !legal.contains(&b)))
        }
        Game::EightBall => {
            !state.next.break_shot
                && summary.pocket_of(8).is_some()
                && (!legal.contains(&8) || summary.scratch())
        }
        Game::FreePlay => false,
    }
}

impl Search<'_> {
    /// The simulation of `cand` before its strike: the cue ball in its place.
    fn start(&self, cand: &Candidate) -> Option<Simulation> {
        let mut sim = self.base.clone();
        self.place_cue(cand, &mut sim)?;
        Some(sim)
    }

    /// [`Search::start`] into `sim`, reusing its buffers (no allocation per sample).
    fn reset(&self, cand: &Candidate, sim: &mut Simulation) -> Option<()> {
        sim.clone_from(&self.base);
        self.place_cue(cand, sim)
    }

    /// The cue ball of `sim` where `cand` puts it (ball in hand); `None` when it cannot go.
    fn place_cue(&self, cand: &Candidate, sim: &mut Simulation) -> Option<()> {
        match cand.place {
            Some(p) => sim.place(self.cue, p, Vec2::ZERO, Vec3::ZERO).ok(),
            None => Some(()),
        }
    }

    /// Runs one noisy sample of candidate `index` (draw `k`) in the scratch simulation `sim`:
    /// its summary, the layout it leaves (`None` when it stopped early on a settled verdict)
    /// and the events it took.
    fn run(
        &self,
        cand: &Candidate,
        index: u64,
        k: u64,
        scratch: &mut Scratch,
    ) -> Option<(Option<Layout>, usize)> {
        let Scratch { sim, summary } = scratch;
        summary.clear();
        self.reset(cand, sim)?;
        let mut rng = stream(self.seed, index, k);
        let shot = self.noise.apply(cand.shot, sim.params(), &mut rng);
        let first = sim.event_count();
        if self.mode == Mode::Full {
            sim.set_record_history(true);
        }
        sim.strike(self.cue, shot).ok()?;
        let mut layout = None;
        let cap = if self.state.next.break_shot {
            MAX_BREAK_EVENTS
        } else {
            MAX_EVENTS
        };
        match self.mode {
            Mode::Lean => {
                while let Some(e) = sim.step_event() {
                    summary.record(&e.kind, sim.numbers());
                    // Only a first contact or a pocketing changes what `settled` reads.
                    let changes = matches!(
                        e.kind,
                        EventKind::BallBall { .. } | EventKind::Pocketed { .. }
                    );
                    if changes && settled(self.state, cand.call, summary) {
                        break;
                    }
                    if sim.event_count() - first > cap {
                        layout = Layout::of(sim, None);
                        break;
                    }
                    // Once only stops are left, the final layout is known (crate::quiet).
                    if matches!(e.kind, EventKind::Transition { .. }) {
                        layout = final_layout(sim);
                        if layout.is_some() {
                            break;
                        }
                    }
                }
                if layout.is_none() && sim.is_at_rest() {
                    layout = Layout::of(sim, None);
                }
            }
            Mode::Full => {
                let _ = sim.run_to_rest();
                *summary = summarise(sim.history().events(), sim.numbers());
                layout = Layout::of(sim, None);
            }
        }
        let events = sim.event_count() - first;
        Some((layout, events))
    }

    /// Draw `k` of candidate `index` run to rest (no early stop: the next shot is searched
    /// from where every ball stops): the table at rest, its summary and the events it took.
    /// `None` when the cue ball cannot be placed, the strike is refused or the run takes
    /// more than [`MAX_BREAK_EVENTS`].
    pub(crate) fn outcome(
        &self,
        cand: &Candidate,
        index: u64,
        k: u64,
    ) -> Option<(Simulation, ShotSummary, usize)> {
        let mut sim = self.start(cand)?;
        sim.set_record_history(false);
        let mut rng = stream(self.seed, index, k);
        let shot = self.noise.apply(cand.shot, sim.params(), &mut rng);
        let first = sim.event_count();
        sim.strike(self.cue, shot).ok()?;
        let mut summary = ShotSummary::default();
        while let Some(e) = sim.step_event() {
            summary.record(&e.kind, sim.numbers());
            if sim.event_count() - first > MAX_BREAK_EVENTS {
                return None;
            }
        }
        let events = sim.event_count() - first;
        Some((sim, summary, events))
    }

    /// One noisy sample of candidate `index` (draw `k`), scored, run in `scratch` (its
    /// simulation reset from the base first, its buffers reused).
    pub fn sample(&self, cand: &Candidate, index: u64, k: u64, scratch: &mut Scratch) -> Stats {
        let me = self.state.next.shooter;
        let foul = Stats {
            n: 1,
            value: -FOUL_COST,
            fouls: 1,
            ..Stats::default()
        };
        let Some((layout, events)) = self.run(cand, index, k, scratch) else {
            return foul;
        };
        let summary = &scratch.summary;
        let mut after = self.state.clone();
        let Ok(verdict) = after.play(summary, cand.call) else {
            return Stats { events, ..foul };
        };
        let potted = summary.pocketed_object_balls().next().is_some();
        let (value, pot) = self.score(&verdict, layout.as_ref(), me, potted);
        Stats {
            n: 1,
            value,
            pots: usize::from(pot),
            fouls: usize::from(!verdict.legal()),
            losses: usize::from(value == -1.0),
            events,
        }
    }

    /// The value of `verdict` for `me` with the balls left in `layout` (the cue ball off the
    /// table: `None`), and whether it was a legal pot (or a win).
    pub(crate) fn score(
        &self,
        verdict: &Verdict,
        layout: Option<&Layout>,
        me: Seat,
        potted: bool,
    ) -> (f64, bool) {
        if let Outcome::GameOver { winner, .. } = verdict.outcome {
            return if winner == me {
                (1.0, true)
            } else {
                (-1.0, false)
            };
        }
        let Some(next) = &verdict.next else {
            return (0.0, false);
        };
        let game_ball = for_game_ball(self.state, &next.legal_first);
        let miss = miss_cost(self.state.game);
        if !verdict.legal() {
            return (-at_table(IN_HAND, game_ball, miss), false);
        }
        let Some(layout) = layout else {
            return (-at_table(IN_HAND, game_ball, miss), false);
        };
        let p = best_success(layout, &next.legal_first, self.noise);
        if verdict.push_out {
            return (-at_table(p.max(1.0 - p), game_ball, miss), false);
        }
        if next.shooter == me && verdict.outcome == Outcome::Continues {
            (at_table(p, game_ball, miss), potted)
        } else {
            (-at_table(p, game_ball, miss), false)
        }
    }

    /// Samples `from..to` of every candidate of `cands`, on all cores. Candidate `i` draws
    /// from the streams `(seed, salt + i, k)`, so the result does not depend on the threads.
    pub fn evaluate(&self, cands: &[Candidate], salt: u64, from: u64, to: u64) -> Vec<Stats> {
        let runs: Vec<Run> = cands
            .iter()
            .enumerate()
            .map(|(i, cand)| Run {
                cand,
                stream: salt + i as u64,
                samples: from..to,
            })
            .collect();
        self.evaluate_runs(&runs)
    }

    /// The samples of every run, on all cores, each run's totals summed in the order of its
    /// draws (so the result does not depend on the threads). The work is split by sample,
    /// not by candidate: candidates differ in cost by ten times, and a refinement round
    /// gives a few candidates many samples each, which a split by candidate leaves to one
    /// core at the end.
    pub fn evaluate_runs(&self, runs: &[Run]) -> Vec<Stats> {
        let runs: Vec<(&Candidate, u64, std::ops::Range<u64>)> = runs
            .iter()
            .map(|r| (r.cand, r.stream, r.samples.clone()))
            .collect();
        crate::rounds::sample_runs(self, &runs)
    }

    /// `cand` with its aim corrected for throw and spin, noiselessly: a secant search on the
    /// aim angle until the ball hit first leaves in the direction the geometry wants (within
    /// 1e-5 rad), at most five runs to the first contact. Unchanged when the first contact is
    /// not that ball.
    pub fn correct_aim(&self, cand: Candidate) -> Candidate {
        let Some((ball, want)) = cand.object else {
            return cand;
        };
        let Some(start) = self.start(&cand) else {
            return cand;
        };
        let id = start.numbers().iter().position(|&n| n == ball);
        let error = |angle: f64| -> Option<f64> {
            let mut sim = start.clone();
            sim.strike(self.cue, billiards_physics::Shot { angle, ..cand.shot })
                .ok()?;
            for _ in 0..200 {
                let e = sim.step_event()?;
                if let EventKind::BallBall { a, b } = e.kind
                    && (a == self.cue || b == self.cue)
                {
                    let (other, slot) = if a == self.cue { (b, 1) } else { (a, 0) };
                    if Some(other) != id {
                        return None;
                    }
                    let v = e.after[slot].velocity;
                    return Some(want.perp_dot(v).atan2(want.dot(v)));
                }
            }
            None
        };
        let (mut a0, mut a1) = (cand.shot.angle, cand.shot.angle + 1e-4);
        let (Some(mut e0), Some(mut e1)) = (error(a0), error(a1)) else {
            return cand;
        };
        for _ in 0..3 {
            if e1.abs() < 1e-5 || e1 == e0 {
                break;
            }
            let a2 = a1 - e1 * (a1 - a0) / (e1 - e0);
            let Some(e2) = error(a2) else { break };
            (a0, e0, a1, e1) = (a1, e1, a2, e2);
        }
        let best = if e1.abs() <= e0.abs() { a1 } else { a0 };
        let mut out = cand;
        out.shot.angle = best;
        out
    }
}

impl Sampler for Search<'_> {
    type Cand = Candidate;
    type Scratch = Scratch;

    fn scratch(&self) -> Scratch {
        Scratch::new(&self.base)
    }

    fn sample(&self, cand: &Candidate, stream: u64, k: u64, scratch: &mut Scratch) -> Stats {
        Search::sample(self, cand, stream, k, scratch)
    }
}
