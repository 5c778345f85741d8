//! Closed-form motion between events for each model (paper 3.3–3.4).

use crate::ball::{BallState, Motion, Segment};
use crate::math::Vec2;
use crate::params::{Model, Params};

/// The segment a ball follows from `start`, given its position and velocity there, with its
/// motion state chosen from the speed (used after collisions and strikes, where the state
/// really is decided by the new speed).
pub fn segment_from(params: &Params, start: f64, position: Vec2, velocity: Vec2) -> Segment {
    let Model::Paper(m) = params.model;
    let speed = velocity.length();
    if speed == 0.0 {
        return Segment::at_rest(start, position, Motion::Stationary);
    }
    let motion = if speed > m.slide_roll_speed {
        Motion::Sliding
    } else {
        Motion::Rolling
    };
    paper_segment(params, start, position, velocity, motion)
}

/// The paper's decelerating segment in an explicit motion state: deceleration `mu g` against
/// the velocity, ending where the speed reaches the slide/roll threshold (sliding) or zero
/// (rolling).
fn paper_segment(
    params: &Params,
    start: f64,
    position: Vec2,
    velocity: Vec2,
    motion: Motion,
) -> Segment {
    let Model::Paper(m) = params.model;
    let speed = velocity.length();
    let (decel, end_speed) = match motion {
        Motion::Sliding => (m.mu_slide * params.gravity, m.slide_roll_speed),
        _ => (m.mu_roll * params.gravity, 0.0),
    };
    let dir = velocity / speed;
    let state = BallState {
        position,
        velocity,
        motion,
        ..BallState::default()
    };
    let end = (decel > 0.0).then(|| start + (speed - end_speed) / decel);
    Segment::new(start, state, dir * -decel, crate::Vec3::ZERO, end)
}

/// The segment after `seg` reaches its end by itself: sliding turns to rolling at exactly the
/// threshold speed, rolling stops. The new state is set explicitly, never re-derived from the
/// speed, so a transition cannot fire again at the same instant.
pub fn after_transition(params: &Params, seg: &Segment) -> Segment {
    let Model::Paper(m) = params.model;
    let end = seg
        .end
        .expect("a transition happens only at a segment's end");
    let position = seg.position_at(end);
    match seg.state.motion {
        Motion::Sliding if m.slide_roll_speed > 0.0 => {
            let dir = seg.state.velocity / seg.state.velocity.length();
            paper_segment(
                params,
                end,
                position,
                dir * m.slide_roll_speed,
                Motion::Rolling,
            )
        }
        _ => Segment::at_rest(end, position, Motion::Stationary),
    }
}
