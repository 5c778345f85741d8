//! The value of a stroke at snooker, in points for the striker: what it scores or concedes
//! and the position it leaves (the next player's analytic chance at the balls on, weighted by
//! their worth), and where to put the cue ball in hand in the D.

use super::context::Snook;
use crate::candidates::{Layout, best_open, each_direct_aim};
use crate::noise::Noise;
use crate::placement::best_apart;
use crate::position::aim_probability;
use billiards_physics::{Simulation, SnookerMarks, Vec2};
use billiards_rules::snooker::balls::{WHITE, is_red, value};
use billiards_rules::snooker::geometry::snookered;
use billiards_rules::snooker::{Frame, Verdict};

/// What a red is worth to the player who pots it: its point and the colour that follows
/// (about the average of a blue and a pink, what a break-builder takes after a red).
const RED_WORTH: f64 = 1.0 + 4.0;
/// Points a player at the table is expected to add beyond the ball on, when he pots it
/// (the break goes on; a rough mean of a visit's continuation).
const CONTINUATION: f64 = 2.0;
/// The value of winning (or losing) the frame with this stroke, in points.
const FRAME: f64 = 40.0;
/// A snooker left: the opponent's expected foul (at least 4 points, 3.10, less his escapes).
const SNOOKER_BONUS: f64 = 2.0;
/// The same when snookers are needed to win: a snooker is the only way back.
const NEEDED_SNOOKER_BONUS: f64 = 6.0;
/// A ball potted while snookers are needed: one fewer ball to snooker behind.
const NEEDED_POT_COST: f64 = 4.0;

/// What potting ball `n` is worth to the player at the table.
pub(super) fn worth(n: u8) -> f64 {
    if is_red(n) {
        RED_WORTH
    } else {
        value(n).map_or(0.0, f64::from)
    }
}

/// The expected points of the player at the table with the cue ball at `layout.cue`: the
/// best straight or cut pot of a ball of `on`, its chance times the ball's worth and the
/// continuation (the pool search's one-ply position value, weighted by the balls' values).
pub fn chance(layout: &Layout, on: &[u8], noise: Noise) -> f64 {
    // The maximum over the open aims (0 without one), best first up to the first open one.
    let mut values = Vec::new();
    each_direct_aim(layout, on, false, |a, lines| {
        let v = aim_probability(&a, noise) * (worth(a.first) + CONTINUATION);
        values.push((v, lines));
    });
    best_open(layout, &mut values)
}

/// [`chance`] with the cue ball in hand: the best of three places in the D (behind the
/// brown, towards the yellow, towards the green) that are clear of every ball.
fn chance_in_hand(layout: &Layout, marks: &SnookerMarks, on: &[u8], noise: Noise) -> f64 {
    let r = layout.radius;
    let back = marks.brown - Vec2::new(0.1, 0.0);
    let probes = [
        back,
        back - Vec2::new(0.0, 0.18),
        back + Vec2::new(0.0, 0.18),
    ];
    let mut l = layout.clone();
    probes
        .iter()
        .filter(|&&p| {
            layout
                .balls
                .iter()
                .all(|&(_, q)| (p - q).length() > 2.0 * r)
        })
        .map(|&p| {
            l.cue = p;
            chance(&l, on, noise)
        })
        .fold(0.0, f64::max)
}

/// Up to `count` places in the D for the cue ball in hand (3.4), best first: a fan of
/// points behind the baulk-line clear of every ball, ranked by [`chance`] at the balls on
/// and kept apart as pool's places ([`best_apart`]); equal values keep the order proposed,
/// whose first two are the usual break-off places between the brown and the yellow or the
/// green.
pub fn d_places(frame: &Frame, sim: &Simulation, noise: Noise, count: usize) -> Vec<Vec2> {
    let Some(mut layout) = Layout::of(sim, Some(Vec2::ZERO)) else {
        return Vec::new();
    };
    let m = &frame.marks;
    let r = layout.radius;
    let mut proposed = vec![
        m.brown + Vec2::new(-0.02, -0.5 * m.d_radius),
        m.brown + Vec2::new(-0.02, 0.5 * m.d_radius),
    ];
    for radius in [0.06, 0.15, 0.24, 0.285] {
        for k in 0..=8 {
            // From the yellow's side round the back of the D to the green's.
            let a = std::f64::consts::PI * (f64::from(k) / 8.0 - 0.5);
            let dir = Vec2::new(-a.cos(), a.sin());
            proposed.push(m.brown + dir * radius);
        }
    }
    let bound = layout.table.centre_bounds(r);
    proposed.retain(|&p| {
        m.in_d(p)
            && p.x.abs() < bound.x
            && p.y.abs() < bound.y
            && layout
                .balls
                .iter()
                .all(|&(_, q)| (p - q).length() > 2.0 * r + 1e-4)
    });
    let on = frame.balls_on(frame.next.on);
    best_apart(proposed, count, |p| {
        layout.cue = p;
        chance(&layout, &on, noise)
    })
}

impl Snook<'_> {
    /// The value of `verdict` for the striker, in points, the balls at rest in `after` and
    /// `frame` the frame after the stroke: the stroke's own points and the position's.
    pub(super) fn score(&self, frame: &Frame, verdict: &Verdict, after: &[(u8, Vec2)]) -> f64 {
        let (now, position) = self.terms(frame, verdict, after);
        now + position
    }

    /// [`Snook::score`] in two terms: what the stroke itself earns (points, a penalty, the
    /// frame, a pot for nothing) and what the position is worth (the next player's chance,
    /// for or against the striker, and a snooker's bonus).
    pub(super) fn terms(
        &self,
        frame: &Frame,
        verdict: &Verdict,
        after: &[(u8, Vec2)],
    ) -> (f64, f64) {
        let me = self.me;
        if let Some((w, _)) = verdict.end {
            return (if w == me { FRAME } else { -FRAME }, 0.0);
        }
        let Some(next) = &verdict.next else {
            return (0.0, 0.0);
        };
        let mut balls: Vec<(u8, Vec2)> = after.to_vec();
        for &(c, p) in &verdict.spots {
            balls.retain(|&(n, _)| n != c);
            balls.push((c, p));
        }
        let cue = balls.iter().find(|b| b.0 == WHITE).map(|b| b.1);
        let objects: Vec<(u8, Vec2)> = balls.iter().copied().filter(|b| b.0 != WHITE).collect();
        let on_next = frame.balls_on(next.on);
        let layout = Layout {
            table: frame.table,
            radius: frame.radius,
            cue: cue.unwrap_or(Vec2::ZERO),
            balls: objects.clone(),
        };
        let next_chance = match cue {
            Some(_) if !next.in_hand => chance(&layout, &on_next, self.noise),
            _ => chance_in_hand(&layout, &frame.marks, &on_next, self.noise),
        };
        if !verdict.fair() {
            return (-f64::from(verdict.penalty), -next_chance);
        }
        if self.needs && verdict.points > 0 {
            // A pot for nothing: the points do not close the gap (3.3, 3.10), and each ball
            // gone is one fewer to lay a snooker behind; with one object ball left there is
            // none.
            let gone = self
                .frame
                .on_table
                .len()
                .saturating_sub(frame.on_table.len());
            let cost = if frame.on_table.len() <= 1 {
                0.5 * FRAME
            } else {
                NEEDED_POT_COST * gone.max(1) as f64
            };
            return (-cost, 0.0);
        }
        let gained = f64::from(verdict.points);
        if next.striker == me && next.choices.is_empty() {
            return (gained, next_chance);
        }
        let bonus = match cue {
            Some(c) if !next.in_hand && snookered(c, &on_next, &objects, frame.radius) => {
                if self.needs {
                    NEEDED_SNOOKER_BONUS
                } else {
                    SNOOKER_BONUS
                }
            }
            _ => 0.0,
        };
        (gained, bonus - next_chance)
    }
}
