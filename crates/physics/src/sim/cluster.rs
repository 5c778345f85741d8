//! Impacts that reach a cluster: a ball–ball contact whose balls have neighbours closer than
//! the distance one contact closes is resolved over the whole connected cluster at once, with
//! Hertz forces over the impact's finite duration and the contacts' friction integrated with
//! them ([`crate::resolve::hertz`], [`crate::resolve::hertz::Tangential`]).

use super::Simulation;
use super::reach::MAX_CLUSTER;
use crate::ball::{BallId, BallState};
use crate::event::EventKind;
use crate::math::{Vec2, Vec3};
use crate::motion;
use crate::params::Model;
use crate::resolve;
use crate::resolve::hertz::{self, Edge, Hertz};

/// The balls and pairs of one cluster.
#[derive(Clone, Debug, Default)]
pub(super) struct Cluster {
    /// Ball ids; `members[0]` and `members[1]` are the pair whose contact started it.
    pub members: Vec<BallId>,
    /// Pairs closer than the reach, as local indices, with their normals and gaps.
    pub edges: Vec<Edge>,
}

impl Simulation {
    /// The cluster a contact of `a` and `b` reaches: every ball in play connected to them by
    /// gaps under `reach` (m). `None` if it is only the pair, or larger than [`MAX_CLUSTER`].
    pub(super) fn cluster_of(&self, a: BallId, b: BallId, reach: f64) -> Option<Cluster> {
        let t = self.time;
        let r2 = 2.0 * self.params.ball.radius;
        let near = r2 + reach;
        // Most contacts have no third ball within reach: the search below would find the
        // pair alone. The same test, before anything is allocated.
        // Only balls level with the cloth: one higher up touches in space, not in the plane
        // the impact integrates in (its contacts are pairs in the air).
        let position = |id: BallId| {
            let s = &self.segments[id];
            (s.state.motion.on_table() && self.level_at(id, t)).then(|| s.position_at(t))
        };
        let (pa, pb) = (position(a)?, position(b)?);
        let within = |d: Vec2| d.x.abs() < near && d.y.abs() < near && d.length() < near;
        let third = (0..self.segments.len()).any(|j| {
            j != a && j != b && position(j).is_some_and(|q| within(q - pa) || within(q - pb))
        });
        if !third {
            return None;
        }
        let positions: Vec<Option<Vec2>> = (0..self.segments.len()).map(position).collect();
        let mut local = vec![usize::MAX; positions.len()];
        let mut cluster = Cluster::default();
        for id in [a, b] {
            local[id] = cluster.members.len();
            cluster.members.push(id);
        }
        // The starting pair is edge 0.
        let (pa, pb) = (positions[a]?, positions[b]?);
        cluster.edges.push(Edge {
            a: 0,
            b: 1,
            n: (pb - pa).normalized().unwrap_or(Vec2::new(1.0, 0.0)),
            gap: (pb - pa).length() - r2,
        });
        let mut next = 0;
        while next < cluster.members.len() {
            let id = cluster.members[next];
            let p = positions[id].expect("members are in play");
            for (j, q) in positions.iter().enumerate() {
                let Some(q) = *q else { continue };
                if j == id || (local[j] != usize::MAX && local[j] <= next) || (next == 0 && j == b)
                {
                    continue;
                }
                let d = q - p;
                if d.x.abs() >= near || d.y.abs() >= near {
                    continue;
                }
                let dist = d.length();
                if dist >= near {
                    continue;
                }
                if local[j] == usize::MAX {
                    if cluster.members.len() == MAX_CLUSTER {
                        return None;
                    }
                    local[j] = cluster.members.len();
                    cluster.members.push(j);
                }
                cluster.edges.push(Edge {
                    a: next,
                    b: local[j],
                    n: d.normalized().unwrap_or(Vec2::new(1.0, 0.0)),
                    gap: dist - r2,
                });
            }
            next += 1;
        }
        (cluster.members.len() > 2).then_some(cluster)
    }

    /// Resolves `cluster` as one impact now: Hertz forces and each contact's friction
    /// integrated together over its duration, every force of a stage from one state, so the
    /// order the balls are listed in does not matter (no normal is randomized: the
    /// perturbation draws nothing here). Records one
    /// [`EventKind::BallBall`] per pair that carried an impulse (the starting pair first),
    /// each with its balls' states after the whole impact, and marks them as one impact.
    pub(super) fn cluster_impact(&mut self, cluster: &Cluster) {
        let Model::Spin(m) = self.params.model else {
            unreachable!("only the spin model has cluster contacts")
        };
        let material = m.cluster.expect("a cluster model");
        let t = self.time;
        let r = self.params.ball.radius;
        let hertz = Hertz::new(&material, &self.params.ball, m.e_ball);
        let friction = resolve::PairFriction::of(&m);
        let mut states: Vec<BallState> = cluster
            .members
            .iter()
            .map(|&id| self.segments[id].state_at(t))
            .collect();
        let mut velocities: Vec<Vec2> = states.iter().map(|s| s.velocity).collect();
        let mut spins: Vec<Vec3> = states.iter().map(|s| s.angular_velocity).collect();
        // The edges in an order the balls' labels do not decide (by their contact points),
        // so each ball's forces are summed in the same order however the balls are listed:
        // a relabelled cluster gives the same impact to rounding of a few sums, not of
        // thousands of steps.
        let mut by_place: Vec<usize> = (0..cluster.edges.len()).collect();
        let place = |k: usize| {
            let e = &cluster.edges[k];
            states[e.a].position + states[e.b].position
        };
        by_place.sort_by(|&x, &y| {
            let (p, q) = (place(x), place(y));
            p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y))
        });
        let edges: Vec<Edge> = by_place.iter().map(|&k| cluster.edges[k]).collect();
        let sorted = hertz::impact_with_friction(
            &hertz,
            Some((friction, r)),
            &mut velocities,
            &mut spins,
            &edges,
        );
        let mut impact = sorted.clone();
        for (i, &k) in by_place.iter().enumerate() {
            impact.impulse[k] = sorted.impulse[i];
            impact.onset[k] = sorted.onset[i];
        }
        for ((s, v), w) in states.iter_mut().zip(&velocities).zip(&spins) {
            s.velocity = *v;
            s.angular_velocity = *w;
        }
        // The events are recorded in this order (it decides nothing in the physics).
        let mut order: Vec<usize> = (0..cluster.edges.len())
            .filter(|&k| impact.impulse[k] > 0.0)
            .collect();
        // The starting pair first, then by onset (ties by index: deterministic).
        order.sort_by(|&x, &y| {
            let key = |k: usize| (k != 0, impact.onset[k]);
            key(x)
                .partial_cmp(&key(y))
                .expect("onsets are not NaN")
                .then(x.cmp(&y))
        });
        let mut changed = vec![false; cluster.members.len()];
        for &k in &order {
            let e = cluster.edges[k];
            changed[e.a] = true;
            changed[e.b] = true;
        }
        for (i, &id) in cluster.members.iter().enumerate() {
            if changed[i] {
                let s = &states[i];
                // A ball in the air keeps flying (its height and upward speed are in `s`).
                self.segments[id] =
                    motion::segment_after(&self.params, t, s, s.velocity, s.angular_velocity);
            }
        }
        for &k in &order {
            let e = cluster.edges[k];
            let (x, y) = (cluster.members[e.a], cluster.members[e.b]);
            self.record(EventKind::BallBall {
                a: x.min(y),
                b: x.max(y),
            });
        }
        self.impacts += 1;
        if self.record_history {
            let start = self.history.events().len() - order.len();
            self.history.mark_impact(start..self.history.events().len());
        }
        for (i, &id) in cluster.members.iter().enumerate() {
            if changed[i] {
                self.repredict([id]);
            }
        }
    }
}
