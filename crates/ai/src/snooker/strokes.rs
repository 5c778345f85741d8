//! The candidate strokes at snooker: pots (banks, kicks, red-on-red plants) of the balls on,
//! with the nomination that goes with them, and safeties.

use super::budget::SnookerBudget;
use super::context::Snook;
use super::value::worth;
use crate::candidates::{Candidate, Layout, ShotKind, combo_aims, direct_aims, expand, rail_aims};
use crate::evaluate::{Mode, Search};
use crate::position::aim_probability;
use billiards_physics::{Shot, Vec2};
use billiards_rules::snooker::BallOn;
use billiards_rules::snooker::balls::{is_colour, is_red};
use billiards_rules::{Call, Game, GameState, Seat};
use rayon::prelude::*;

/// The first ball the cue ball meets sent straight along unit `dir` (no cushion).
fn first_hit(layout: &Layout, dir: Vec2) -> Option<u8> {
    let d = 2.0 * layout.radius;
    layout
        .balls
        .iter()
        .filter_map(|&(n, q)| {
            let w = q - layout.cue;
            let along = w.dot(dir);
            let off2 = w.length_squared() - along * along;
            (along > 0.0 && off2 < d * d).then(|| (along - (d * d - off2).sqrt(), n))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)))
        .map(|(_, n)| n)
}

/// A candidate stroke and the ball it nominates.
#[derive(Clone, Copy, Debug)]
pub(super) struct Cand {
    pub(super) cand: Candidate,
    pub(super) nominated: Option<u8>,
}

impl Snook<'_> {
    /// The balls the striker may pot: the balls on and, with a free ball (3.12), any other
    /// object ball (nominated).
    pub(super) fn targets(&self) -> (Vec<u8>, Vec<u8>) {
        let on = self.frame.balls_on(self.frame.next.on);
        let free: Vec<u8> = if self.frame.next.free_ball {
            self.frame
                .on_table
                .iter()
                .copied()
                .filter(|n| !on.contains(n))
                .collect()
        } else {
            Vec::new()
        };
        (on, free)
    }

    /// The nomination that goes with a stroke at `ball` first: the colour after a red
    /// (2.12), a free ball (3.12), else none.
    pub(super) fn nomination(&self, ball: u8, free: &[u8]) -> Option<u8> {
        match self.frame.next.on {
            BallOn::Colour { .. } if is_colour(ball) => Some(ball),
            _ if free.contains(&ball) => Some(ball),
            _ => None,
        }
    }

    /// Pots (and banks, kicks, plants) from `place`: the best `budget.aims` aims by chance
    /// times worth, in the budget's speeds and tips.
    pub(super) fn offence(&self, place: Option<Vec2>, budget: &SnookerBudget) -> Vec<Cand> {
        let Some(layout) = Layout::of(&self.base, place) else {
            return Vec::new();
        };
        let (on, free) = self.targets();
        let mut legal = on.clone();
        legal.extend(&free);
        let mut aims = direct_aims(&layout, &legal);
        if budget.banks {
            aims.extend(rail_aims(&layout, &legal));
            if self.frame.next.on == BallOn::Red {
                // A red into a red: both are on (3.3(a)).
                aims.extend(combo_aims(&layout, &on, &on));
            }
        }
        let mut ranked: Vec<(f64, usize)> = aims
            .iter()
            .enumerate()
            .map(|(i, a)| {
                let ball = match a.kind {
                    ShotKind::Combo { ball, .. } => ball,
                    _ => a.first,
                };
                (aim_probability(a, self.noise) * (worth(ball) + 1.0), i)
            })
            .collect();
        ranked.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        let kept: Vec<_> = ranked
            .iter()
            .take(budget.aims)
            .map(|&(_, i)| aims[i])
            .collect();
        let cands = expand(&kept, &budget.speeds, &budget.tips, false, place);
        let cands: Vec<Candidate> = if budget.correct_aim {
            let dummy = GameState::new(Game::FreePlay, Seat::A);
            let pool = Search {
                state: &dummy,
                base: self.base.clone(),
                cue: self.cue,
                noise: self.noise,
                seed: self.seed,
                mode: Mode::Lean,
            };
            cands.into_par_iter().map(|c| pool.correct_aim(c)).collect()
        } else {
            cands
        };
        cands
            .into_iter()
            .map(|c| {
                let first = match c.kind {
                    ShotKind::Pot { ball, .. }
                    | ShotKind::Bank { ball, .. }
                    | ShotKind::Kick { ball, .. } => ball,
                    ShotKind::Combo { first, .. } => first,
                    _ => 0,
                };
                Cand {
                    cand: c,
                    nominated: self.nomination(first, &free),
                }
            })
            .collect()
    }

    /// Safeties from `place`: at the nearest balls on in view, contacts from full to thin on
    /// either side at three weights (back to baulk, to a cushion and back, a touch); a ball
    /// on hidden is kicked at off each cushion ([`crate::candidates::safeties`]).
    pub(super) fn safeties(&self, place: Option<Vec2>, budget: &SnookerBudget) -> Vec<Cand> {
        let Some(layout) = Layout::of(&self.base, place) else {
            return Vec::new();
        };
        let (on, _) = self.targets();
        let r = layout.radius;
        let mut balls: Vec<(f64, u8, Vec2)> = on
            .iter()
            .filter_map(|&n| layout.ball(n).map(|b| ((b - layout.cue).length(), n, b)))
            .collect();
        balls.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut out = Vec::new();
        let push = |out: &mut Vec<Cand>, ball: u8, angle: f64, speed: f64| {
            out.push(Cand {
                cand: Candidate {
                    kind: ShotKind::Safety { ball },
                    shot: Shot::new(angle, speed.clamp(0.3, 7.0)),
                    call: Call::None,
                    place,
                    object: None,
                },
                nominated: matches!(self.frame.next.on, BallOn::Colour { .. }).then_some(ball),
            })
        };
        let k = budget.safety_hits.max(1);
        let mut seen = 0;
        for &(d, n, b) in &balls {
            if seen == budget.safety_balls {
                break;
            }
            let to = (b - layout.cue).normalized().unwrap_or(Vec2::new(1.0, 0.0));
            // A red may meet another red first (any red is on, 3.3(a)); a colour must be met
            // itself.
            let fair = |m: u8| if is_red(n) { on.contains(&m) } else { m == n };
            let angles: Vec<f64> = (0..k)
                .map(|j| {
                    let f = if k == 1 {
                        0.0
                    } else {
                        -0.95 + 1.9 * j as f64 / (k - 1) as f64
                    };
                    to.angle() + (2.0 * r * f / d).clamp(-1.0, 1.0).asin()
                })
                .filter(|&a| first_hit(&layout, Vec2::from_angle(a)).is_some_and(fair))
                .collect();
            if angles.is_empty() {
                continue;
            }
            seen += 1;
            for a in angles {
                // Rolling distances of about d + 0.3, d + 3 and d + 7 m (0.1 m/s^2 with
                // the losses of the contact and the cushions).
                for extra in [0.3, 3.0, 7.0] {
                    let speed = 1.4 * (0.2 * (d + extra)).sqrt() + 0.3;
                    push(&mut out, n, a, speed);
                }
            }
        }
        if seen == 0 {
            // Snookered: the kicks of the pool safeties (a cushion first, then the ball on).
            for c in crate::candidates::safeties(&layout, &on, 1, place) {
                let ball = match c.kind {
                    ShotKind::Safety { ball } => ball,
                    _ => continue,
                };
                for k in [0.8, 1.0, 1.4] {
                    push(&mut out, ball, c.shot.angle, c.shot.speed * k);
                }
            }
        }
        out
    }
}
