//! The rounds of a search, shared by every game's search (issue 50: one skeleton, not a
//! copy per game): candidates evaluated by noisy samples ([`Sampler`]) on all cores, the
//! best refined with more samples, the best chosen from the finalists or from a second ply.
//! A game's search brings its candidates, its sampler (what one noisy sample of a
//! candidate is worth) and, if any, its second ply ([`Searched`]); [`find`] runs them, the
//! same for pool, snooker and any game ([`crate::any_game`]), and [`search`] gives pool's and
//! snooker's best as the one [`Plan`] type ([`Planned`]).

use crate::AiError;
use crate::candidates::ShotKind;
use crate::plan::Plan;
use billiards_physics::{BallId, Shot, Simulation, Vec2};
use rayon::prelude::*;
use std::ops::Range;

/// The running totals of one candidate's samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Samples.
    pub n: usize,
    /// Sum of the values.
    pub value: f64,
    /// Samples with a legal pot (or a win).
    pub pots: usize,
    /// Samples with a foul.
    pub fouls: usize,
    /// Samples that lost the game.
    pub losses: usize,
    /// Solver events processed.
    pub events: usize,
}

impl Stats {
    /// Mean value (minus infinity without samples).
    pub fn mean(&self) -> f64 {
        if self.n == 0 {
            f64::NEG_INFINITY
        } else {
            self.value / self.n as f64
        }
    }

    /// Fraction of samples with a legal pot or a win.
    pub fn pot_rate(&self) -> f64 {
        self.pots as f64 / self.n.max(1) as f64
    }

    /// Both sets of samples together.
    pub fn merged(self, o: Stats) -> Stats {
        Stats {
            n: self.n + o.n,
            value: self.value + o.value,
            pots: self.pots + o.pots,
            fouls: self.fouls + o.fouls,
            losses: self.losses + o.losses,
            events: self.events + o.events,
        }
    }
}

/// What one noisy sample of a candidate is worth, for one game's search.
pub trait Sampler: Sync {
    /// A candidate stroke.
    type Cand: Sync;
    /// What one thread reuses from sample to sample (a simulation to reset).
    type Scratch: Send;
    /// A fresh scratch.
    fn scratch(&self) -> Self::Scratch;
    /// Draw `k` of random stream `stream` of `cand`, played in `scratch`.
    fn sample(&self, cand: &Self::Cand, stream: u64, k: u64, scratch: &mut Self::Scratch) -> Stats;
}

/// The samples of every run (a candidate, its stream and its draws), on all cores, each
/// run's totals summed in the order of its draws (so the result does not depend on the
/// threads). The work is split by sample, not by candidate: candidates differ in cost by
/// ten times, and a refinement round gives a few candidates many samples each, which a
/// split by candidate leaves to one core at the end.
pub fn sample_runs<S: Sampler>(s: &S, runs: &[(&S::Cand, u64, Range<u64>)]) -> Vec<Stats> {
    let mut starts = Vec::with_capacity(runs.len() + 1);
    let mut total = 0usize;
    for r in runs {
        starts.push(total);
        total += r.2.end.saturating_sub(r.2.start) as usize;
    }
    starts.push(total);
    let samples: Vec<Stats> = (0..total)
        .into_par_iter()
        .map_init(
            || s.scratch(),
            |scratch, n| {
                let r = starts.partition_point(|&x| x <= n) - 1;
                let (cand, stream, ref draws) = runs[r];
                let k = draws.start + (n - starts[r]) as u64;
                s.sample(cand, stream, k, scratch)
            },
        )
        .collect();
    starts
        .windows(2)
        .map(|w| {
            samples[w[0]..w[1]]
                .iter()
                .fold(Stats::default(), |s, x| s.merged(*x))
        })
        .collect()
}

/// The best candidate of a search: after a second ply the best two-ply value (`two`: the
/// candidate and its value); else the best mean among the finalists of the last round (all
/// `stats` when there was none; ties: the first).
pub fn best_candidate(two: &[(usize, f64)], finalists: &[usize], stats: &[Stats]) -> Option<usize> {
    if !two.is_empty() {
        return two
            .iter()
            .copied()
            .reduce(|a, b| if b.1 > a.1 { b } else { a })
            .map(|v| v.0);
    }
    let all: Vec<usize> = (0..stats.len()).collect();
    let pool = if finalists.is_empty() {
        &all
    } else {
        finalists
    };
    pool.iter().copied().reduce(|a, b| {
        let (ma, mb) = (stats[a].mean(), stats[b].mean());
        if mb > ma || (mb == ma && b < a) { b } else { a }
    })
}

/// Below this chance of success for the best first candidate, a search adds its safeties
/// (the pool and snooker searches alike).
pub const SAFETY_BELOW: f64 = 0.6;

/// What a search found: the best candidate, its samples and value, and the work done.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Found {
    /// The candidate's index in [`Rounds::cands`].
    pub index: usize,
    /// Its samples.
    pub stats: Stats,
    /// Its value ([`Rounds::value`]).
    pub value: f64,
    /// Simulations the search ran.
    pub simulations: usize,
    /// Solver events it processed.
    pub events: usize,
}

impl Found {
    /// The share of its samples that fouled.
    pub fn foul_rate(&self) -> f64 {
        self.stats.fouls as f64 / self.stats.n.max(1) as f64
    }
}

/// Every candidate of a search evaluated so far, with its samples.
#[derive(Debug)]
pub struct Rounds<C> {
    /// The candidates, in the order they were added.
    pub cands: Vec<C>,
    /// Their samples.
    pub stats: Vec<Stats>,
    /// Simulations run.
    pub simulations: usize,
    /// Solver events processed.
    pub events: usize,
    /// The candidates of the last refinement round (empty: none yet).
    pub finalists: Vec<usize>,
    /// The candidates valued two plies deep and their values (empty: one ply).
    pub two: Vec<(usize, f64)>,
}

impl<C> Default for Rounds<C> {
    fn default() -> Self {
        Self {
            cands: Vec::new(),
            stats: Vec::new(),
            simulations: 0,
            events: 0,
            finalists: Vec::new(),
            two: Vec::new(),
        }
    }
}

impl<C: Sync> Rounds<C> {
    /// Evaluates `cands` with `samples` each and keeps them. A candidate's random streams are
    /// named by its index in the search, so the order of the rounds fixes them.
    pub fn add<S: Sampler<Cand = C>>(&mut self, s: &S, cands: Vec<C>, samples: usize) {
        let salt = self.cands.len() as u64;
        let runs: Vec<(&C, u64, Range<u64>)> = cands
            .iter()
            .enumerate()
            .map(|(i, c)| (c, salt + i as u64, 0..samples as u64))
            .collect();
        let stats = sample_runs(s, &runs);
        self.count(&stats);
        self.cands.extend(cands);
        self.stats.extend(stats);
    }

    /// A search's rounds: `first` sampled `samples` times each; then what `more` gives
    /// (the safeties) sampled as much, `more` being told whether the best first candidate
    /// succeeds at least [`SAFETY_BELOW`] of the time; then each refinement round `(k, m)`.
    pub fn play_rounds<S: Sampler<Cand = C>>(
        &mut self,
        s: &S,
        first: Vec<C>,
        more: impl FnOnce(bool) -> Vec<C>,
        (samples, rounds): (usize, &[(usize, usize)]),
    ) {
        self.add(s, first, samples);
        let scoring = self
            .best()
            .is_some_and(|i| self.stats[i].pot_rate() >= SAFETY_BELOW);
        let extra = more(scoring);
        if !extra.is_empty() {
            self.add(s, extra, samples);
        }
        for &(k, m) in rounds {
            self.refine(s, k, m);
        }
    }

    /// The best candidate so far with its samples, value and the search's work.
    pub fn found(&self) -> Option<Found> {
        let index = self.best()?;
        Some(Found {
            index,
            stats: self.stats[index],
            value: self.value(index),
            simulations: self.simulations,
            events: self.events,
        })
    }

    /// Gives the best `k` candidates `m` more samples each; they become the finalists.
    pub fn refine<S: Sampler<Cand = C>>(&mut self, s: &S, k: usize, m: usize) {
        let order = self.best_by_mean(&(0..self.cands.len()).collect::<Vec<_>>(), k);
        let runs: Vec<(&C, u64, Range<u64>)> = order
            .iter()
            .map(|&i| {
                let n = self.stats[i].n as u64;
                (&self.cands[i], i as u64, n..n + m as u64)
            })
            .collect();
        let more = sample_runs(s, &runs);
        self.count(&more);
        for (&i, st) in order.iter().zip(more) {
            self.stats[i] = self.stats[i].merged(st);
        }
        self.finalists = order;
    }

    /// The best `k` of `among` by mean (ties: the first).
    fn best_by_mean(&self, among: &[usize], k: usize) -> Vec<usize> {
        let mut order = among.to_vec();
        let mean = |i: usize| self.stats[i].mean();
        order.sort_by(|&a, &b| mean(b).total_cmp(&mean(a)).then(a.cmp(&b)));
        order.truncate(k);
        order
    }

    /// The candidates a second ply values: the best `k` finalists (of all candidates when
    /// no round refined any).
    pub fn second_ply_order(&self, k: usize) -> Vec<usize> {
        let pool: Vec<usize> = if self.finalists.is_empty() {
            (0..self.cands.len()).collect()
        } else {
            self.finalists.clone()
        };
        self.best_by_mean(&pool, k)
    }

    /// Counts the simulations and events of `stats`.
    pub fn count(&mut self, stats: &[Stats]) {
        self.simulations += stats.iter().map(|s| s.n).sum::<usize>();
        self.events += stats.iter().map(|s| s.events).sum::<usize>();
    }

    /// The value of candidate `i`: two plies deep when it was so valued, else its mean.
    pub fn value(&self, i: usize) -> f64 {
        self.two
            .iter()
            .find(|v| v.0 == i)
            .map_or(self.stats[i].mean(), |v| v.1)
    }

    /// The best candidate so far ([`best_candidate`]).
    pub fn best(&self) -> Option<usize> {
        best_candidate(&self.two, &self.finalists, &self.stats)
    }

    /// Values the best `finalists` (by [`Rounds::second_ply_order`]) two plies deep; they
    /// become the only candidates [`Rounds::best`] chooses from. Each is struck `outcomes`
    /// times, `correction(candidate, k)` giving outcome `k`'s (second-ply value - one-ply
    /// value, simulations, events); its value is its one-ply mean plus the mean correction
    /// (a control variate: [`crate::twoply`]). The outcomes run on all cores, each a
    /// function of its candidate and `k` only, so the values do not depend on the threads.
    pub fn second_ply(
        &mut self,
        finalists: usize,
        outcomes: usize,
        correction: impl Fn(&C, u64) -> Correction + Sync,
    ) {
        let order = self.second_ply_order(finalists);
        let jobs: Vec<(usize, u64)> = order
            .iter()
            .flat_map(|&i| (0..outcomes as u64).map(move |k| (i, k)))
            .collect();
        let corrections: Vec<Correction> = jobs
            .par_iter()
            .map(|&(i, k)| correction(&self.cands[i], k))
            .collect();
        for (n, &i) in order.iter().enumerate() {
            let mine = &corrections[n * outcomes..(n + 1) * outcomes];
            let shift = mine.iter().map(|c| c.0).sum::<f64>() / outcomes.max(1) as f64;
            self.two.push((i, self.stats[i].mean() + shift));
            self.simulations += mine.iter().map(|c| c.1).sum::<usize>();
            self.events += mine.iter().map(|c| c.2).sum::<usize>();
        }
    }
}

/// One outcome of a second ply: (second-ply value - one-ply value), simulations, events.
pub type Correction = (f64, usize, usize);

/// What a game's search brings to the skeleton ([`find`]): where the cue ball may start,
/// its candidates and safeties from there, its rounds and its second ply. Sampling is the
/// [`Sampler`]'s; what goes with the chosen candidate to the rules is [`Planned`]'s.
pub trait Searched: Sampler {
    /// How much it searches (a level's budget).
    type Budget;
    /// The cue ball's places to search from: `None` alone when it is not in hand.
    fn places(&self, budget: &Self::Budget) -> Result<Vec<Option<Vec2>>, AiError>;
    /// The first candidates (pots, or the break), from every place.
    fn offence(&self, places: &[Option<Vec2>], budget: &Self::Budget) -> Vec<Self::Cand>;
    /// The safeties from every place, `scoring` when the best first candidate succeeds at
    /// least [`SAFETY_BELOW`] of the time (none when the game's search does not want them).
    fn safeties(
        &self,
        places: &[Option<Vec2>],
        budget: &Self::Budget,
        scoring: bool,
    ) -> Vec<Self::Cand>;
    /// The first round's samples and the refinement rounds `(k, m)`.
    fn rounds<'b>(&self, budget: &'b Self::Budget) -> (usize, &'b [(usize, usize)]);
    /// The second ply, if the budget has one ([`Rounds::second_ply`]).
    fn second_ply(&self, pool: &mut Rounds<Self::Cand>, budget: &Self::Budget);
}

/// A search whose best candidate becomes a [`Plan`] (pool's and snooker's): the shot, its
/// place, what it tries and the per-game part that goes with it to the rules.
pub trait Planned: Searched {
    /// The per-game part of its plan (pool's call, snooker's nomination).
    type Part;
    /// The shot of candidate `cand`, its place, what it tries and its per-game part.
    fn stroke(&self, cand: &Self::Cand) -> (Shot, Option<Vec2>, ShotKind, Self::Part);
}

/// The one search skeleton (issue 50): the places, the first candidates sampled, the
/// safeties when the best does not score, the refinement rounds, the second ply; the best
/// candidate and what its samples gave ([`Rounds::found`]; no candidate: [`AiError::NoBall`]).
pub fn find<S: Searched>(s: &S, budget: &S::Budget) -> Result<(S::Cand, Found), AiError> {
    let places = s.places(budget)?;
    let mut pool = Rounds::default();
    let first = s.offence(&places, budget);
    let safeties = |scoring: bool| s.safeties(&places, budget, scoring);
    pool.play_rounds(s, first, safeties, s.rounds(budget));
    s.second_ply(&mut pool, budget);
    let found = pool.found().ok_or(AiError::NoBall)?;
    Ok((pool.cands.swap_remove(found.index), found))
}

/// The skeleton's best candidate ([`find`]) as a plan, with the figures its samples gave.
pub fn search<S: Planned>(s: &S, budget: &S::Budget) -> Result<Plan<S::Part>, AiError> {
    let (cand, found) = find(s, budget)?;
    let (shot, place, kind, part) = s.stroke(&cand);
    Ok(Plan {
        shot,
        place,
        part,
        kind,
        success: found.stats.pot_rate(),
        foul: found.foul_rate(),
        value: found.value,
        samples: found.stats.n,
        simulations: found.simulations,
        events: found.events,
    })
}

/// The option of `choices` the search values best (ties: the first), with its value and
/// what else `value` gave. Option `k` is valued by `value(choice, salt)` for the chooser
/// (`None`: it cannot be weighed); `salt` seeds the search behind it, a function of `seed`
/// and `k` only, so the choice does not depend on the threads. Pool's, snooker's and any
/// game's choices alike (issue 50).
pub fn best_choice<C: Copy, E>(
    choices: &[C],
    seed: u64,
    mut value: impl FnMut(C, u64) -> Option<(f64, E)>,
) -> Option<(C, f64, E)> {
    let mut best: Option<(C, f64, E)> = None;
    for (k, &choice) in choices.iter().enumerate() {
        let salt = seed.wrapping_add(0x9e37_79b9 * (k as u64 + 1));
        let Some((v, extra)) = value(choice, salt) else {
            continue;
        };
        if best.as_ref().is_none_or(|b| v > b.1) {
            best = Some((choice, v, extra));
        }
    }
    best
}

/// Every game's first step: the game must be on (`over` false) and the balls at rest.
pub fn at_rest(over: bool, sim: &Simulation) -> Result<(), AiError> {
    if over {
        return Err(AiError::GameOver);
    }
    if !sim.is_at_rest() {
        return Err(AiError::NotAtRest);
    }
    Ok(())
}

/// The cue ball's index in `sim` (ball number `cue`) and the table a search samples from (a
/// copy without history). The cue ball must be on the table unless it is `in_hand`.
pub fn cue_and_base(
    sim: &Simulation,
    cue: u8,
    in_hand: bool,
) -> Result<(BallId, Simulation), AiError> {
    let id = sim
        .numbers()
        .iter()
        .position(|&n| n == cue)
        .ok_or(AiError::NoCueBall)?;
    if !in_hand && !sim.ball(id).motion.on_table() {
        return Err(AiError::CueBallOff);
    }
    let mut base = sim.clone();
    base.set_record_history(false);
    Ok((id, base))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A game whose every sample of candidate `(v, pot)` is worth `v` and pots when `pot`;
    /// its first candidates are `first`, its one safety is worth 0.6.
    struct Toy {
        first: Vec<(f64, bool)>,
    }

    impl Sampler for Toy {
        type Cand = (f64, bool);
        type Scratch = ();
        fn scratch(&self) {}
        fn sample(&self, c: &(f64, bool), _: u64, _: u64, _: &mut ()) -> Stats {
            Stats {
                n: 1,
                value: c.0,
                pots: usize::from(c.1),
                events: 3,
                ..Stats::default()
            }
        }
    }

    impl Searched for Toy {
        type Budget = (usize, Vec<(usize, usize)>);
        fn places(&self, _: &Self::Budget) -> Result<Vec<Option<Vec2>>, AiError> {
            Ok(vec![None])
        }
        fn offence(&self, _: &[Option<Vec2>], _: &Self::Budget) -> Vec<(f64, bool)> {
            self.first.clone()
        }
        fn safeties(
            &self,
            _: &[Option<Vec2>],
            _: &Self::Budget,
            scoring: bool,
        ) -> Vec<(f64, bool)> {
            if scoring {
                Vec::new()
            } else {
                vec![(0.6, false)]
            }
        }
        fn rounds<'b>(&self, b: &'b Self::Budget) -> (usize, &'b [(usize, usize)]) {
            (b.0, &b.1)
        }
        fn second_ply(&self, _: &mut Rounds<(f64, bool)>, _: &Self::Budget) {}
    }

    impl Planned for Toy {
        type Part = bool;
        fn stroke(&self, c: &(f64, bool)) -> (Shot, Option<Vec2>, ShotKind, bool) {
            (Shot::new(c.0, 1.0), None, ShotKind::Break, c.1)
        }
    }

    #[test]
    fn the_skeleton_adds_safeties_only_when_nothing_scores_and_plans_the_best() {
        // Two candidates x 2 samples; nothing pots (rate 0 < SAFETY_BELOW), so the safety
        // comes in with 2 samples; one round gives the best 2 three more: 12 samples, 3
        // events each. The safety (0.6) wins with 5 samples.
        let budget = (2, vec![(2, 3)]);
        let toy = Toy {
            first: vec![(0.2, false), (0.4, false)],
        };
        let plan = search(&toy, &budget).unwrap();
        assert_eq!((plan.shot.angle, plan.value, plan.samples), (0.6, 0.6, 5));
        assert_eq!((plan.simulations, plan.events), (12, 36));
        assert_eq!((plan.success, plan.part), (0.0, false));
        // Every first candidate pots: no safety, the better pot is played.
        let toy = Toy {
            first: vec![(0.2, true), (0.4, true)],
        };
        let plan = search(&toy, &budget).unwrap();
        assert_eq!((plan.shot.angle, plan.success, plan.part), (0.4, 1.0, true));
        assert_eq!(plan.simulations, 10);
    }

    #[test]
    fn best_choice_skips_the_unweighed_keeps_the_first_of_equals_and_salts_by_index() {
        // Options 'a' (cannot be weighed), 'b' 0.5, 'c' 0.5, 'd' 0.2: 'b' wins the tie with
        // 'c'; option k's salt is the seed plus 0x9e3779b9 (k + 1), whatever else is valued.
        let values = [None, Some(0.5), Some(0.5), Some(0.2)];
        let mut salts = Vec::new();
        let best = best_choice(&['a', 'b', 'c', 'd'], 7, |c, salt| {
            salts.push(salt);
            values[(c as u8 - b'a') as usize].map(|v| (v, c))
        });
        assert_eq!(best, Some(('b', 0.5, 'b')));
        let expected: Vec<u64> = (1..=4).map(|k| 7 + 0x9e37_79b9 * k).collect();
        assert_eq!(salts, expected);
        assert_eq!(best_choice(&[1, 2], 0, |_, _| None::<(f64, ())>), None);
    }

    #[test]
    fn a_second_ply_adds_the_mean_correction_to_the_finalists_mean() {
        // Means 0.1, 0.5, 0.3: the best two finalists are 1 and 2. Correction k of
        // candidate (v, _) is k v over 4 outcomes: a mean of 1.5 v, so 1 is worth
        // 0.5 + 0.75 and 2 is worth 0.3 + 0.45; each outcome counts 2 runs and 10 events.
        let toy = Toy { first: Vec::new() };
        let mut pool = Rounds::default();
        pool.add(&toy, vec![(0.1, false), (0.5, false), (0.3, false)], 2);
        pool.second_ply(2, 4, |c: &(f64, bool), k| (k as f64 * c.0, 2, 10));
        assert_eq!(pool.two, vec![(1, 0.5 + 0.75), (2, 0.3 + 1.5 * 0.3)]);
        assert_eq!((pool.simulations, pool.events), (6 + 16, 18 + 80));
        assert_eq!(pool.best(), Some(1));
    }
}
