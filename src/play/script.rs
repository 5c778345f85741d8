//! `--script "STEP; STEP; …"`: the player's moves played at launch, each when the game is
//! ready for it, so that a screenshot or the layout check reaches any state of a match (a
//! scratch, a foul, a call, a nomination, the computer's turn: issue 48) the way a player
//! would. A step waits until the table rests and the game asks for what it does; the
//! screenshot waits until the last step is done and the balls rest again.
//!
//! Steps: `shoot DEG SPEED` (the cue ball struck at DEG degrees counter-clockwise from the
//! table's long axis, SPEED m/s, centre ball), `continue` (the verdict read), `call BALL
//! POCKET` (8-ball), `nominate BALL` (snooker), `choose K` (the K-th choice the verdict
//! offers), `move BALL X Y` (a ball put at (X, Y) m, the table's centre being (0, 0); the
//! rules are not told).

use std::collections::VecDeque;

use bevy::prelude::*;
use billiards_physics::{Pocket, Vec2};
use billiards_rules::Declaration;

use super::game::{Rules, Turn, TurnCommand};
use crate::{
    sim::{LayoutRequested, Referee, ShotRequested, SimStatus, SimSystems, Solver, layout_now},
    view::screenshot::CaptureHeld,
};

/// One move of a launch script.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    /// Strike the cue ball: direction (degrees counter-clockwise from +x) and speed (m/s).
    Shoot {
        /// Degrees counter-clockwise from the table's long axis (+x, towards the foot).
        degrees: f64,
        /// The cue ball's speed, m/s.
        speed: f64,
    },
    /// The verdict has been read: on to the next shot.
    Continue,
    /// Call this ball in this pocket (8-ball).
    Call {
        /// The ball.
        ball: u8,
        /// The pocket.
        pocket: Pocket,
    },
    /// Nominate this ball (snooker, after a red or for a free ball).
    Nominate(u8),
    /// Take the choice offered in this place of the verdict's list (1 the first).
    Choose(usize),
    /// Put a ball at a place of the cloth (metres from the table's centre).
    Move {
        /// The ball's number (0 the cue ball).
        ball: u8,
        /// Where, m.
        at: bevy::math::DVec2,
    },
}

/// The pocket named in a script: `head-left`, `head-right`, `side-left`, `side-right`,
/// `foot-left` or `foot-right`.
fn pocket(name: &str) -> Option<Pocket> {
    Some(match name {
        "head-left" => Pocket::HeadLeft,
        "head-right" => Pocket::HeadRight,
        "side-left" => Pocket::SideLeft,
        "side-right" => Pocket::SideRight,
        "foot-left" => Pocket::FootLeft,
        "foot-right" => Pocket::FootRight,
        _ => return None,
    })
}

/// Parses a script: steps separated by `;`. The error names the step it could not read.
pub fn parse(script: &str) -> Result<Vec<Step>, String> {
    script
        .split(';')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|text| {
            let words: Vec<&str> = text.split_whitespace().collect();
            let number = |k: usize| -> Option<f64> {
                words
                    .get(k)
                    .and_then(|w| w.parse::<f64>().ok())
                    .filter(|v| v.is_finite())
            };
            let ball = |k: usize| words.get(k).and_then(|w| w.parse::<u8>().ok());
            let step = match (words[0], words.len()) {
                ("shoot", 3) => match (number(1), number(2)) {
                    (Some(degrees), Some(speed)) if speed > 0.0 && speed <= 15.0 => {
                        Some(Step::Shoot { degrees, speed })
                    }
                    _ => None,
                },
                ("continue", 1) => Some(Step::Continue),
                ("call", 3) => ball(1)
                    .zip(pocket(words[2]))
                    .map(|(ball, pocket)| Step::Call { ball, pocket }),
                ("nominate", 2) => ball(1).map(Step::Nominate),
                ("choose", 2) => words[1]
                    .parse::<usize>()
                    .ok()
                    .filter(|&k| k >= 1)
                    .map(Step::Choose),
                ("move", 4) => match (ball(1), number(2), number(3)) {
                    (Some(ball), Some(x), Some(y)) => Some(Step::Move {
                        ball,
                        at: bevy::math::DVec2::new(x, y),
                    }),
                    _ => None,
                },
                _ => None,
            };
            step.ok_or_else(|| {
                format!(
                    "cannot read the step {text:?} (shoot DEG SPEED, continue, call BALL \
                     POCKET, nominate BALL, choose K, move BALL X Y; speed in (0, 15] m/s)"
                )
            })
        })
        .collect()
}

/// The steps of the launch script still to play.
#[derive(Resource, Debug, Clone, Default, PartialEq)]
pub struct LaunchScript(pub VecDeque<Step>);

/// Plays the script: its steps, then holds the screenshot until the balls rest.
pub fn plugin(app: &mut App) {
    app.add_systems(
        Update,
        play_script
            .run_if(resource_exists::<LaunchScript>)
            .after(SimSystems::Flow),
    );
}

/// Frames of rest, after a step, before the next one is tried: the rules judge a shot and
/// set the next turn over the frames after the balls stop.
const REST_FRAMES: u32 = 3;

#[allow(clippy::too_many_arguments)]
fn play_script(
    mut script: ResMut<LaunchScript>,
    (status, referee, rules): (Res<SimStatus>, Res<Referee>, Res<Rules>),
    turn: Option<Res<State<Turn>>>,
    solver: Option<Res<Solver>>,
    (mut rested, mut world): (Local<u32>, Commands),
    mut shots: MessageWriter<ShotRequested>,
    (mut commands, mut layouts): (MessageWriter<TurnCommand>, MessageWriter<LayoutRequested>),
    held: Option<ResMut<CaptureHeld>>,
) {
    let at_rest = status.at_rest && solver.as_ref().is_some_and(|s| s.simulation().is_at_rest());
    *rested = if at_rest { *rested + 1 } else { 0 };
    // Once the last step's balls rest, the script is done and the capture may go: what the
    // computer does next (its turn is a state to see) does not hold it.
    let finished = script.0.is_empty() && *rested >= REST_FRAMES;
    if let Some(mut held) = held {
        held.0 = !finished;
    }
    if finished {
        world.remove_resource::<LaunchScript>();
    }
    let Some(&step) = script.0.front().filter(|_| *rested >= REST_FRAMES) else {
        return;
    };
    let turn = turn.map(|t| *t.get());
    let human_to_play = rules.to_play().is_none_or(|(level, _)| level.is_none());
    let done = match step {
        Step::Shoot { degrees, speed } => {
            let ready = referee.refuse_shot.is_none()
                && human_to_play
                && matches!(turn, Some(Turn::Aiming | Turn::BallInHand));
            if ready {
                shots.write(ShotRequested::from(billiards_physics::Shot {
                    angle: degrees.to_radians(),
                    speed,
                    tip: Default::default(),
                    elevation: 0.0,
                }));
            }
            ready
        }
        Step::Continue => {
            let ready = turn == Some(Turn::Verdict);
            if ready {
                commands.write(TurnCommand::Continue);
            }
            ready
        }
        Step::Call { ball, pocket } => {
            let ready = human_to_play && matches!(turn, Some(Turn::Aiming | Turn::BallInHand));
            if ready {
                commands.write(TurnCommand::Declare(Declaration::Pocket { ball, pocket }));
            }
            ready
        }
        Step::Nominate(ball) => {
            let ready = human_to_play && rules.live.is_some() && turn != Some(Turn::Verdict);
            if ready {
                commands.write(TurnCommand::Declare(Declaration::Nominate { ball }));
            }
            ready
        }
        Step::Choose(k) => {
            let offered = rules.live.as_ref().map(|g| g.rules.turn().choices.len());
            let command = offered.and_then(|n| {
                (1..=n)
                    .contains(&k)
                    .then(|| TurnCommand::ChooseOption(k - 1))
            });
            let ready = human_to_play && turn == Some(Turn::Verdict) && command.is_some();
            if let Some(command) = command.filter(|_| ready) {
                commands.write(command);
            }
            ready
        }
        Step::Move { ball, at } => {
            let Some(solver) = solver else { return };
            let mut balls = layout_now(solver.simulation());
            match balls.iter_mut().find(|b| b.number == ball) {
                Some(b) => {
                    b.position = Vec2::new(at.x, at.y);
                    layouts.write(LayoutRequested {
                        balls,
                        rack: solver.rack(),
                        name: solver.name(),
                    });
                }
                None => warn!("script: no ball {ball} on the table to move"),
            }
            true
        }
    };
    if done {
        info!("script: {step:?}");
        script.0.pop_front();
        *rested = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_are_read_and_bad_ones_named() {
        let steps = parse(
            "shoot 90 0.6; continue ;call 3 foot-left; nominate 7; choose 2; move 1 0.5 -0.2",
        )
        .unwrap();
        assert_eq!(
            steps,
            vec![
                Step::Shoot {
                    degrees: 90.0,
                    speed: 0.6
                },
                Step::Continue,
                Step::Call {
                    ball: 3,
                    pocket: Pocket::FootLeft
                },
                Step::Nominate(7),
                Step::Choose(2),
                Step::Move {
                    ball: 1,
                    at: bevy::math::DVec2::new(0.5, -0.2)
                },
            ]
        );
        for bad in [
            "shoot 90",
            "shoot 90 NaN",
            "shoot 90 40",
            "call 3 corner",
            "choose 0",
            "jump",
        ] {
            let error = parse(bad).unwrap_err();
            assert!(error.contains(bad), "{bad}: {error}");
        }
    }
}
