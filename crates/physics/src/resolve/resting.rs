//! Resting contacts: touching bodies pressed together or approaching too slowly to bounce
//! (see [`crate::detect::RESTING_DEPTH`]). They hop apart by [`RESTING_HOP`] instead of
//! touching again in a Zeno cascade of ever smaller bounces; a slow spinning ball settles
//! against a cushion or jaw instead ([`super::settle`]).

use super::ball_ball::{resting_contact, unpress};
use super::ball_cushion::resting_reflect;
use crate::ball::{BallId, BallState, Motion};
use crate::detect::{RESTING_DEPTH, RESTING_HOP};
use crate::math::{Vec2, Vec3};
use crate::params::BallSpec;
use crate::table::Cushion;

/// Is a contact a resting one (resolved by [`resting_contact`]): sunk past half the resting
/// depth, or pressed together and approaching too slowly to hop apart by the resting depth on
/// its own? Such contacts bounce elastically with a minimum hop, so that neither a pressed
/// pair (a Zeno cascade of ever smaller bounces) nor an inelastic collapse can make
/// unboundedly many events per second.
#[inline]
pub fn is_resting(depth: f64, approach: f64, pressing: f64) -> bool {
    depth > 0.5 * RESTING_DEPTH
        || (pressing > 0.0 && approach * approach < 8.0 * pressing * RESTING_DEPTH)
}

/// Spin of a ball in state `s` whose velocity a resting contact changed to `v`: a rolling ball
/// keeps rolling (its spin follows the small change of velocity), so a micro-impulse does not
/// leave a tiny slip whose sliding friction, large against it, would press the pair together
/// again within femtoseconds (the spin model); any other ball keeps its spin.
pub fn keep_rolling(s: &BallState, v: Vec2, radius: f64) -> Vec3 {
    if s.motion != Motion::Rolling {
        return s.angular_velocity;
    }
    let dv = v - s.velocity;
    s.angular_velocity + Vec3::new(-dv.y / radius, dv.x / radius, 0.0)
}

/// Velocity and spin after a resting contact of a ball in state `s` with a fixed body of unit
/// normal `n` (towards the ball), approaching it at `approach` and pressed into it at
/// `pressing` (m/s^2). `repeat`: the same contact was already resolved at this instant.
pub fn resting_on_fixed_body(
    s: &BallState,
    n: Vec2,
    approach: f64,
    pressing: f64,
    repeat: bool,
    radius: f64,
) -> (Vec2, Vec3) {
    let v = if repeat {
        // A second resting contact with the same body in one instant: a ball wedged
        // between a jaw and a ball held by the other jaw bounced elastically between
        // them forever at that instant (soak seed 349173). Plastic: the approach
        // goes, no hop, and the wedge's contacts converge.
        s.velocity + n * approach.max(0.0)
    } else {
        resting_reflect(s.velocity, n, pressing, RESTING_HOP)
    };
    (v, keep_rolling(s, v, radius))
}

/// States after a resting contact of balls `sa` and `sb` along unit normal `n` (from `a` to
/// `b`), pressed together at `pressing` (m/s^2): [`resting_contact`]'s hop, paid for by the
/// spin of a sliding ball when the pair has no tangential speed to turn into it.
pub fn resting_pair(
    sa: BallState,
    sb: BallState,
    n: Vec2,
    pressing: f64,
    ball: &BallSpec,
) -> (BallState, BallState) {
    let (va, vb) = resting_contact(sa.velocity, sb.velocity, n, pressing, RESTING_HOP);
    let r = ball.radius;
    // Pressed head-on with no tangential speed to turn into the hop (a sliding
    // ball driven into another by its own spin, as after a follow shot): its
    // spin pays for the hop, as its cloth friction would by pushing.
    let (mut va, mut vb, mut wa, mut wb) = (va, vb, sa.angular_velocity, sb.angular_velocity);
    let want = (2.0 * pressing.max(0.0) * RESTING_HOP).sqrt();
    let got = (vb - va).dot(n);
    if got < want {
        let half = n * (0.5 * (want - got));
        let (va2, vb2) = (va - half, vb + half);
        let m = ball.mass;
        let cost = 0.5
            * m
            * (va2.length_squared() + vb2.length_squared()
                - va.length_squared()
                - vb.length_squared());
        let inertia = 0.4 * m * r * r;
        let spin_energy = |w: Vec3| 0.5 * inertia * (w.x * w.x + w.y * w.y);
        let payer = [(&sa, &mut wa), (&sb, &mut wb)]
            .into_iter()
            .filter(|(s, w)| s.motion == Motion::Sliding && spin_energy(**w) > 2.0 * cost)
            .max_by(|x, y| spin_energy(*x.1).total_cmp(&spin_energy(*y.1)));
        if cost <= 0.0 {
            (va, vb) = (va2, vb2);
        } else if let Some((_, w)) = payer {
            let k = (1.0 - cost * (1.0 + 1e-9) / spin_energy(*w)).sqrt();
            *w = Vec3::new(w.x * k, w.y * k, w.z);
            (va, vb) = (va2, vb2);
        } else {
            // Nothing to pay a hop with (soak seed 16706: a ball with next to
            // no roll spin driven by its slip into a ball held by a rail): the
            // contact holds, and its slip into the other ball goes, as cloth
            // friction would remove it within microseconds.
            if sa.motion == Motion::Sliding {
                wa = unpress(va, wa, n, r).unwrap_or(wa);
            }
            if sb.motion == Motion::Sliding {
                wb = unpress(vb, wb, -n, r).unwrap_or(wb);
            }
        }
    }
    let sa = BallState {
        angular_velocity: wa,
        ..sa
    };
    let sb = BallState {
        angular_velocity: wb,
        ..sb
    };
    // Both rolling: the pair's energy is 7/10 m (|va|^2 + |vb|^2), which the
    // resting contact never raises. Otherwise only a ball that slows may keep
    // rolling (its spin energy then falls too).
    let both = sa.motion == Motion::Rolling && sb.motion == Motion::Rolling;
    let roll = |s: &BallState, v: Vec2| {
        if both || v.length_squared() <= s.velocity.length_squared() {
            keep_rolling(s, v, r)
        } else {
            s.angular_velocity
        }
    };
    (
        BallState {
            velocity: va,
            angular_velocity: roll(&sa, va),
            ..sa
        },
        BallState {
            velocity: vb,
            angular_velocity: roll(&sb, vb),
            ..sb
        },
    )
}

/// A fixed body a ball can touch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FixedBody {
    /// A cushion.
    Cushion(Cushion),
    /// Jaw `k` of the table's jaws.
    Jaw(usize),
}

/// The contacts of balls with fixed bodies resolved at the current instant: a resting
/// contact that repeats within one instant is plastic ([`resting_on_fixed_body`]).
#[derive(Debug)]
pub struct InstantContacts {
    time: f64,
    contacts: Vec<(BallId, FixedBody)>,
}

clone_reusing!(InstantContacts { time, contacts });

impl Default for InstantContacts {
    fn default() -> Self {
        Self {
            time: f64::NAN,
            contacts: Vec::new(),
        }
    }
}

impl InstantContacts {
    /// Has ball `ball` already touched `body` at `time`? Records the contact if not.
    pub fn repeats(&mut self, time: f64, ball: BallId, body: FixedBody) -> bool {
        if self.time != time {
            self.contacts.clear();
            self.time = time;
        }
        let seen = self.contacts.contains(&(ball, body));
        if !seen {
            self.contacts.push((ball, body));
        }
        seen
    }
}
