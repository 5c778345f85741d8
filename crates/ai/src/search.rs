//! The decision: which candidates to build for the shot the rules ask for, the rounds of
//! noisy evaluation, and the choices (push out, 8-ball break options).

use crate::candidates::{
    Candidate, Layout, ShotKind, combo_aims, direct_aims, expand, rail_aims, safeties,
};
use crate::evaluate::{Mode, Search};
use crate::jump::{hidden, jump_hits, jump_pots};
use crate::level::{Budget, Level};
use crate::noise::Noise;
use crate::placement::places;
use crate::plan::{Called, Decision, Plan};
use crate::position::{aim_probability, best_success};
use crate::rounds::{Planned, Rounds, Searched, best_choice, cue_and_base, search};
use crate::{AiError, ready};
use billiards_physics::{Shot, Simulation, TipOffset, Vec2};
use billiards_rules::{CUE, Call, Choice, CueBall, Game, GameState, NextShot, check_placement};
use rayon::prelude::*;

/// The computer's decision at `level` for what `state` asks next, on the resting table
/// `sim`: the balls `state.next.spot` names already spotted, a respotted cue ball (free
/// play) already back; a cue ball in hand may be anywhere or off the table. The same `seed`
/// gives the same decision, on any number of threads.
pub fn decide(
    state: &GameState,
    sim: &Simulation,
    level: Level,
    seed: u64,
) -> Result<Decision, AiError> {
    decide_with(state, sim, level, seed, Mode::Lean)
}

/// [`decide`] with the solver run in `mode` (the lean mode is [`decide`]'s; the full one is
/// there to measure what it saves).
pub fn decide_with(
    state: &GameState,
    sim: &Simulation,
    level: Level,
    seed: u64,
    mode: Mode,
) -> Result<Decision, AiError> {
    decide_planned(
        state,
        sim,
        level.planning_noise(),
        &level.budget(),
        seed,
        mode,
    )
}

/// [`decide_with`] planned under `noise` with `budget` instead of a level's (the one-ply
/// baseline, [`crate::Player::OnePly`], and the second ply's searches of the next shot).
pub fn decide_planned(
    state: &GameState,
    sim: &Simulation,
    noise: Noise,
    budget: &Budget,
    seed: u64,
    mode: Mode,
) -> Result<Decision, AiError> {
    let next = ready(state, sim)?;
    if !next.choices.is_empty() {
        let shot = |after: &GameState, table: &Simulation, salt| match decide_planned(
            after, table, noise, budget, salt, mode,
        ) {
            Ok(Decision::Shoot(plan)) => Some(plan),
            _ => None,
        };
        let (choice, estimate) = choose(state, sim, noise, seed, shot);
        return Ok(Decision::Choose { choice, estimate });
    }
    let (cue, base) = cue_and_base(sim, CUE, in_hand(next))?;
    let pool_search = Search {
        state,
        base,
        cue,
        noise,
        seed,
        mode,
    };
    search(&pool_search, budget).map(Decision::Shoot)
}

/// Pool's parts of the one search skeleton ([`search`]): the break or the pots, the
/// safeties and push outs and the second ply ([`crate::twoply`]); the call is [`Planned`]'s.
impl Searched for Search<'_> {
    type Budget = Budget;

    fn places(&self, budget: &Budget) -> Result<Vec<Option<Vec2>>, AiError> {
        cue_places(&self.base, self.cue, &self.state.next, self.noise, budget)
    }

    fn offence(&self, places: &[Option<Vec2>], budget: &Budget) -> Vec<Candidate> {
        if self.state.next.break_shot {
            breaks(self, places, budget)
        } else {
            places
                .iter()
                .flat_map(|&p| offence(self, p, budget))
                .collect()
        }
    }

    fn safeties(&self, places: &[Option<Vec2>], budget: &Budget, scoring: bool) -> Vec<Candidate> {
        let next = &self.state.next;
        if next.break_shot || scoring {
            return Vec::new();
        }
        safety_candidates(self.state, &self.base, next, places, budget)
    }

    /// A break is sampled on the break's budget.
    fn rounds<'b>(&self, budget: &'b Budget) -> (usize, &'b [(usize, usize)]) {
        if self.state.next.break_shot {
            (budget.breaks.samples, budget.breaks.rounds)
        } else {
            (budget.samples, budget.rounds)
        }
    }

    fn second_ply(&self, pool: &mut Pool, budget: &Budget) {
        if let Some(two) = budget.second.filter(|_| !self.state.next.break_shot) {
            let correct = |c: &Candidate, k| crate::twoply::correction(self, c, k, two);
            pool.second_ply(two.finalists, two.outcomes, correct);
        }
    }
}

/// Pool's plan: the call goes with the shot.
impl Planned for Search<'_> {
    type Part = Called;

    fn stroke(&self, c: &Candidate) -> (Shot, Option<Vec2>, ShotKind, Called) {
        (c.shot, c.place, c.kind, Called { call: c.call })
    }
}

/// Whether the cue ball is in hand: then it may be off the table and must be placed first.
fn in_hand(next: &NextShot) -> bool {
    matches!(
        next.cue_ball,
        CueBall::InHandAnywhere | CueBall::InHandBehindHeadString
    )
}

/// The cue ball's places to search from: `None` alone when it is not in hand, else the break
/// places or the placement search's best, so every later step loops over places the same way.
fn cue_places(
    sim: &Simulation,
    cue: usize,
    next: &NextShot,
    noise: Noise,
    budget: &Budget,
) -> Result<Vec<Option<Vec2>>, AiError> {
    if !in_hand(next) {
        return Ok(vec![None]);
    }
    let found = if next.break_shot {
        break_places(sim, cue, next.cue_ball, budget.breaks.places)
    } else {
        let (rule, legal) = (next.cue_ball, &next.legal_first);
        places(sim, cue, rule, legal, noise, budget.placements)
    };
    if found.is_empty() {
        return Err(AiError::NoPlace);
    }
    Ok(found.into_iter().map(Some).collect())
}

/// The safeties (and push outs) from every place, added only when no pot scores well enough,
/// with the budget's jump safeties when no legal ball is in view: their calls follow the
/// game's rule for a safety on the last ball.
fn safety_candidates(
    state: &GameState,
    sim: &Simulation,
    next: &NextShot,
    place_list: &[Option<Vec2>],
    budget: &Budget,
) -> Vec<Candidate> {
    let mut more = Vec::new();
    let legal = &next.legal_first;
    for &p in place_list {
        let Some(layout) = Layout::of(sim, p) else {
            continue;
        };
        let mut s = safeties(&layout, legal, budget.safeties, p);
        if let Some(jumps) = &budget.jumps
            && hidden(&layout, legal)
        {
            s.extend(jump_hits(&layout, legal, sim.params(), jumps, p));
        }
        if (state.game == Game::EightBall && next.legal_first == [8]) || state.game == Game::TenBall
        {
            // On the 8, only a called safety is safe from a lucky loss (WPA 3.8); in
            // 10-ball every shot is called, a safety declared as one (WPA 9.5, 9.6).
            s.iter_mut().for_each(|c| c.call = Call::Safety);
        }
        more.extend(s);
        if next.push_out_allowed {
            more.extend(push_outs(p));
        }
    }
    more
}

/// Every candidate evaluated so far, with its samples ([`Rounds`]).
type Pool = Rounds<Candidate>;

/// Pots, banks, kicks and combinations from the cue ball at `place` (or where it is): the
/// `budget.aims` best aims by analytic success, each in the budget's speeds and tips, aims
/// corrected for throw when the budget says so.
fn offence(search: &Search, place: Option<Vec2>, budget: &Budget) -> Vec<Candidate> {
    let state = search.state;
    let Some(layout) = Layout::of(&search.base, place) else {
        return Vec::new();
    };
    let legal = &state.next.legal_first;
    let eight = state.game == Game::EightBall;
    let mut aims = direct_aims(&layout, legal);
    // 8-ball and 10-ball call every pot (WPA 3.6, 9.5); 9-ball none.
    let called = eight || state.game == Game::TenBall;
    if budget.banks_kicks_combos {
        aims.extend(rail_aims(&layout, legal));
        // 8-ball: the ball called must be the shooter's (WPA 3.6); 9-ball, 10-ball: any
        // ball (in 10-ball a combination called on the 10 wins, WPA 9.5).
        let second: Vec<u8> = if eight {
            legal.clone()
        } else {
            layout.balls.iter().map(|b| b.0).collect()
        };
        aims.extend(combo_aims(&layout, legal, &second));
    }
    let mut ranked: Vec<(f64, usize)> = aims
        .iter()
        .enumerate()
        .map(|(i, a)| (aim_probability(a, search.noise), i))
        .collect();
    ranked.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    // In hand, each of the places gets half the aims: the places were chosen for their aims.
    let aims_kept = if place.is_some() {
        budget.aims.div_ceil(2)
    } else {
        budget.aims
    };
    let kept: Vec<_> = ranked
        .iter()
        .take(aims_kept)
        .map(|&(_, i)| aims[i])
        .collect();
    let mut cands = expand(&kept, budget.speeds, budget.tips, called, place);
    // Issue 52: no legal ball in view, the cue ball may jump the blocker (hard and up).
    if let Some(jumps) = &budget.jumps
        && hidden(&layout, legal)
    {
        let params = search.base.params();
        let how = (called, place);
        cands.extend(jump_pots(&layout, legal, params, search.noise, jumps, how));
    }
    if budget.correct_aim {
        cands
            .into_par_iter()
            .map(|c| search.correct_aim(c))
            .collect()
    } else {
        cands
    }
}

/// Break candidates: from each place (or where the cue ball is), full on the ball nearest
/// the foot spot (the 1 in 9-ball, WPA 2.3), at three speeds, stun and a little draw.
fn breaks(search: &Search, place_list: &[Option<Vec2>], budget: &Budget) -> Vec<Candidate> {
    let sim = &search.base;
    let spot = sim.table().foot_spot();
    let legal = &search.state.next.legal_first;
    let mut out = Vec::new();
    for &p in place_list {
        let Some(layout) = Layout::of(sim, p) else {
            continue;
        };
        let apex = layout
            .balls
            .iter()
            .filter(|b| legal.contains(&b.0))
            .min_by(|a, b| (a.1 - spot).length().total_cmp(&(b.1 - spot).length()));
        let Some(&(_, at)) = apex else { continue };
        let angle = (at - layout.cue).angle();
        for &speed in budget.breaks.speeds {
            for &height in budget.breaks.heights {
                out.push(Candidate {
                    kind: ShotKind::Break,
                    shot: Shot {
                        angle,
                        speed,
                        tip: TipOffset { side: 0.0, height },
                        elevation: 0.0,
                    },
                    call: Call::None,
                    place: p,
                    object: None,
                });
            }
        }
    }
    out
}

/// Where the breaker may put the cue ball: on the head string at each fraction of the way to
/// either long cushion, those legal. Three quarters of the way, near the rail, is where pros
/// break 9-ball from: the wing ball then reaches the corner pocket (crates/rules/README.md,
/// the break study).
fn break_places(sim: &Simulation, cue: usize, rule: CueBall, fractions: &[f64]) -> Vec<Vec2> {
    let spot = sim.table().head_spot();
    let half = sim.table().centre_bounds(sim.params().ball.radius).y;
    fractions
        .iter()
        .flat_map(|&f| if f == 0.0 { vec![f] } else { vec![f, -f] })
        .map(|f| spot + Vec2::new(0.0, f * half))
        .filter(|&p| check_placement(sim, cue, p, rule).is_ok())
        .collect()
}

/// Push-out candidates (WPA 2.4): soft rolls in sixteen directions; no contact is needed.
fn push_outs(place: Option<Vec2>) -> Vec<Candidate> {
    (0..16)
        .flat_map(|k| {
            let angle = k as f64 * std::f64::consts::TAU / 16.0;
            [0.8, 1.5].map(|speed| Candidate {
                kind: ShotKind::PushOut,
                shot: Shot::new(angle, speed),
                call: Call::PushOut,
                place,
                object: None,
            })
        })
        .collect()
}

/// What having the break is worth to the breaker, on the search's scale (-1 a lost rack,
/// 1 a won one): the breaker wins a little over half the racks between equal players
/// (hard against hard at 9-ball: 11 % break and run, and the table after the break).
const BREAK_VALUE: f64 = 0.1;

/// The choice the rules offer (`state.next.choices`), by the same search as a shot: each
/// option is taken on a copy of the rack, and the shot it leads to is searched in full from
/// the side of whoever shoots it (the balls it spots put back first); its value counts for
/// the chooser, or against them when the opponent shoots. A re-rack is worth
/// [`BREAK_VALUE`] to whoever breaks. The estimate is the success of the shot the chosen
/// option leads to (an even 0.5 for a break, which is not searched here). Options the search
/// cannot weigh (no place to spot a ball, no legal shot) fall back to the analytic chance of
/// the table as it lies ([`analytic_choice`]). `shot(state, table, salt)` is the search
/// of the shot an option leads to (this decision's, seeded by `salt`).
fn choose(
    state: &GameState,
    sim: &Simulation,
    noise: Noise,
    seed: u64,
    shot: impl Fn(&GameState, &Simulation, u64) -> Option<Plan>,
) -> (Choice, f64) {
    let me = state.next.shooter;
    let best = best_choice(&state.next.choices, seed, |choice, salt| {
        let mut after = state.clone();
        let next = after.choose(choice).ok()?;
        let sign = if next.shooter == me { 1.0 } else { -1.0 };
        if next.rerack {
            return Some((sign * BREAK_VALUE, 0.5));
        }
        let mut table = sim.clone();
        crate::play::spot_balls(&mut table, &next.spot).ok()?;
        after.next.spot.clear();
        let plan = shot(&after, &table, salt)?;
        Some((sign * plan.value, plan.success))
    });
    match best {
        Some((choice, _, estimate)) => (choice, estimate),
        None => analytic_choice(state, sim, noise),
    }
}

/// A choice the rules offer: the analytic best chance from the table as it lies decides
/// whether to shoot it (after a push out or an illegal 8-ball break; spot the 8 after it
/// dropped on the break) or to hand it back / re-rack.
fn analytic_choice(state: &GameState, sim: &Simulation, noise: Noise) -> (Choice, f64) {
    let next = &state.next;
    let p = match Layout::of(sim, None) {
        Some(layout) => best_success(&layout, &next.legal_first, noise),
        // The cue ball went down (a scratch on the break): ball in hand behind the line.
        None => 0.6,
    };
    let offered = |c: Choice| next.choices.contains(&c);
    let choice = if offered(Choice::PassBack) {
        // After a push out the other side shoots what is left: take it only if it is good.
        if p >= 0.5 {
            Choice::ShootFromHere
        } else {
            Choice::PassBack
        }
    } else if offered(Choice::SpotEightAndShoot) {
        if p >= 0.3 || !offered(Choice::RerackAndBreak) {
            Choice::SpotEightAndShoot
        } else {
            Choice::RerackAndBreak
        }
    } else if offered(Choice::ShootFromHere) && p >= 0.5 {
        Choice::ShootFromHere
    } else if offered(Choice::RerackAndBreak) {
        Choice::RerackAndBreak
    } else {
        next.choices[0]
    };
    (choice, p)
}
