//! The baseline player: FooBillard++'s method (`aiplayer.c`), geometry without simulation.
//! Among the straight and cut shots of the legal balls whose paths are clear, the smallest
//! cut angle (then the shortest shot) is played, centre ball, at the speed the distances call
//! for; with nothing open, a full hit on the first legal ball it can see. Ball in hand: the
//! cue ball straight behind the easiest ball and pocket; the break from the head spot. No
//! noisy search, no position play, no safeties.

use crate::candidates::{Aim, Layout, ShotKind, call_for, direct_aims};
use crate::placement::places;
use crate::{AiError, Called, Decision, Plan};
use billiards_physics::{Shot, Simulation, Vec2};
use billiards_rules::{CUE, Call, Choice, CueBall, Game, GameState, NextShot, check_placement};

/// The greedy player's decision for the shot `state` asks for.
pub fn decide(state: &GameState, sim: &Simulation) -> Result<Decision, AiError> {
    let next = crate::ready(state, sim)?;
    if let Some(&first) = next.choices.first() {
        // No judgement: shoot when it may, otherwise the first option offered.
        let choice = [Choice::ShootFromHere, Choice::SpotEightAndShoot]
            .into_iter()
            .find(|c| next.choices.contains(c))
            .unwrap_or(first);
        return Ok(Decision::Choose {
            choice,
            estimate: 0.5,
        });
    }
    let cue = sim
        .numbers()
        .iter()
        .position(|&n| n == CUE)
        .ok_or(AiError::NoCueBall)?;
    let place = cue_ball_place(sim, cue, next)?;
    let layout = Layout::of(sim, place).ok_or(AiError::CueBallOff)?;
    let eight = state.game == Game::EightBall;
    // 8-ball and 10-ball call every pot (WPA 3.6, 9.5).
    let called = eight || state.game == Game::TenBall;
    let aims = if next.break_shot {
        Vec::new()
    } else {
        direct_aims(&layout, &next.legal_first)
    };
    let (shot, kind, call) = match smallest_cut(&aims) {
        Some(a) => (
            Shot::new(a.angle, (1.3 * a.speed).min(8.0)),
            a.kind,
            call_for(a.kind, called),
        ),
        None => nearest_ball_shot(state, next, &layout)?,
    };
    Ok(Decision::Shoot(Plan {
        shot,
        place,
        part: Called { call },
        kind,
        success: 0.0,
        foul: 0.0,
        value: 0.0,
        samples: 0,
        simulations: 0,
        events: 0,
    }))
}

/// Where the cue ball goes with ball in hand (`None` when it is not in hand): the head spot for
/// the break, as a player racks up to break, else the single best place the placement search
/// finds, which is all a player without search can use.
fn cue_ball_place(sim: &Simulation, cue: usize, next: &NextShot) -> Result<Option<Vec2>, AiError> {
    let in_hand = matches!(
        next.cue_ball,
        CueBall::InHandAnywhere | CueBall::InHandBehindHeadString
    );
    let head = sim.table().head_spot();
    let at_head = check_placement(sim, cue, head, next.cue_ball).is_ok();
    Ok(if in_hand && next.break_shot && at_head {
        Some(head)
    } else if in_hand {
        let best = places(
            sim,
            cue,
            next.cue_ball,
            &next.legal_first,
            crate::Noise::REFERENCE,
            1,
        );
        Some(*best.first().ok_or(AiError::NoPlace)?)
    } else {
        None
    })
}

/// FooBillard++'s pick among the open pots: the smallest cut, the largest cosine between the
/// cue ball's and the object's paths; ties go to the shorter (slower) shot, then the first aim.
fn smallest_cut(aims: &[Aim]) -> Option<&Aim> {
    let cut_cos = |a: &Aim| Vec2::from_angle(a.angle).dot(a.object_dir);
    aims.iter()
        .enumerate()
        .max_by(|(i, a), (j, b)| {
            cut_cos(a)
                .total_cmp(&cut_cos(b))
                .then(b.speed.total_cmp(&a.speed))
                .then(j.cmp(i))
        })
        .map(|(_, a)| a)
}

/// Nothing open (or the break): straight at the nearest legal ball, firmly, so at least the
/// first contact is legal; on the 8 and in 10-ball it is called a safety (WPA 3.8, 9.5).
fn nearest_ball_shot(
    state: &GameState,
    next: &NextShot,
    layout: &Layout,
) -> Result<(Shot, ShotKind, Call), AiError> {
    let eight = state.game == Game::EightBall;
    let target = next
        .legal_first
        .iter()
        .filter_map(|&n| layout.ball(n).map(|p| (n, p)))
        .min_by(|a, b| {
            (a.1 - layout.cue)
                .length()
                .total_cmp(&(b.1 - layout.cue).length())
        });
    let (n, p) = target.ok_or(AiError::NoBall)?;
    let speed = if next.break_shot { 10.0 } else { 2.5 };
    let kind = if next.break_shot {
        ShotKind::Break
    } else {
        ShotKind::Safety { ball: n }
    };
    let ten_safety = state.game == Game::TenBall && !next.break_shot;
    let call = if (eight && next.legal_first == [8]) || ten_safety {
        Call::Safety
    } else {
        Call::None
    };
    Ok((Shot::new((p - layout.cue).angle(), speed), kind, call))
}
