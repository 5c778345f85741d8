//! A decision in words, for the hint and the status line: the balls and the options in the
//! game's own words, asked of the one interface ([`GameRules::ball_name`], the labels of
//! [`billiards_rules::Turn::choices`]), the cushions as the caller's view names them. The
//! game asks no question of which game it plays (issue 50).

use crate::any_game::Move;
use crate::candidates::ShotKind;
use crate::game::Decided;
use crate::plan::Decision;
use billiards_physics::Cushion;
use billiards_rules::{Call, GameRules, pocket_name};

/// The least cue elevation, degrees, named a jump shot in words (below the 30 degrees of the
/// computer's lowest jump, above any swerve or masse it plans).
const JUMP_DEGREES: f64 = 20.0;

impl Decided {
    /// The decision in words, with its odds: "the 3 in the foot-right corner, 72 % to
    /// succeed, 4 % foul". `game` is the game it was decided for; `cushion` names a cushion
    /// as the player's view shows it.
    pub fn words(&self, game: &dyn GameRules, cushion: &dyn Fn(Cushion) -> &'static str) -> String {
        // An option in the rules' own label (snooker's "put Bob back in").
        let label = || match self.as_move(game) {
            Some(Move::Choose(i)) => game.turn().choices.get(i).cloned(),
            _ => None,
        };
        let shot = |kind: ShotKind| kind_text(kind, game, cushion);
        match self {
            Decided::Pool(Decision::Choose { choice, estimate }) => {
                format!("{} ({:.0} %)", choice.label(), 100.0 * estimate)
            }
            Decided::Pool(Decision::Shoot(plan)) => {
                let call = match plan.call {
                    Call::Ball { .. } | Call::None => String::new(),
                    other => other.text().map_or(String::new(), |c| format!(", {c}")),
                };
                format!(
                    "{}{call}{}, {:.0} % to succeed, {:.0} % foul",
                    shot(plan.kind),
                    jump_text(plan.shot.elevation),
                    100.0 * plan.success,
                    100.0 * plan.foul
                )
            }
            Decided::Snooker(Decision::Choose { choice, estimate }) => format!(
                "{} (worth {estimate:+.1} points)",
                label().unwrap_or_else(|| format!("{choice:?}"))
            ),
            Decided::Snooker(Decision::Shoot(plan)) => {
                let what = match plan.kind {
                    ShotKind::Break => "the break-off".to_owned(),
                    kind => shot(kind),
                };
                let nominated = plan.nominated.map_or(String::new(), |n| {
                    format!(", nominating {}", game.ball_name(n))
                });
                format!(
                    "{what}{nominated}{}, {:.0} % to pot, {:.0} % foul",
                    jump_text(plan.shot.elevation),
                    100.0 * plan.success,
                    100.0 * plan.foul
                )
            }
            Decided::Any(Move::Choose(index)) => {
                label().unwrap_or_else(|| format!("option {}", index + 1))
            }
            Decided::Any(Move::Strike(stroke)) => {
                let aim = format!(
                    "{:.1} degrees, {:.1} m/s",
                    stroke.shot.angle.to_degrees().rem_euclid(360.0),
                    stroke.shot.speed
                );
                let what = match stroke.kind {
                    Some(kind) => format!("{} ({aim})", shot(kind)),
                    None => format!("a stroke at {aim}"),
                };
                // The search's own scale (`stroke_value`): a game won +10, lost -10, a foul
                // -1, a point or a pot +1.
                format!(
                    "{what}{}, expected value {:+.2}",
                    jump_text(stroke.shot.elevation),
                    stroke.value
                )
            }
        }
    }
}

/// A jump shot said as one: the computer raises the cue 30 to 60 degrees to fly the cue
/// ball over a blocker ([`crate::jump`]); a level shot (or the few degrees of a swerve) says
/// nothing.
pub fn jump_text(elevation: f64) -> String {
    let degrees = elevation.to_degrees();
    if degrees >= JUMP_DEGREES {
        format!(", a jump shot (cue raised {degrees:.0} degrees)")
    } else {
        String::new()
    }
}

/// A shot in words, the balls named by `game` (pool's numbers, snooker's colours).
fn kind_text(
    kind: ShotKind,
    game: &dyn GameRules,
    cushion: &dyn Fn(Cushion) -> &'static str,
) -> String {
    let name = |n: u8| game.ball_name(n);
    match kind {
        ShotKind::Break => "the break".to_owned(),
        ShotKind::Pot { ball, pocket } => {
            format!("{} in the {}", name(ball), pocket_name(pocket))
        }
        ShotKind::Bank {
            ball,
            pocket,
            cushion: c,
        } => format!(
            "{} off the {} cushion in the {}",
            name(ball),
            cushion(c),
            pocket_name(pocket)
        ),
        ShotKind::Kick {
            ball,
            pocket,
            cushion: c,
        } => format!(
            "a kick off the {} cushion, {} in the {}",
            cushion(c),
            name(ball),
            pocket_name(pocket)
        ),
        ShotKind::Combo {
            first,
            ball,
            pocket,
        } => format!(
            "{} into {}, in the {}",
            name(first),
            name(ball),
            pocket_name(pocket)
        ),
        ShotKind::Safety { ball } => format!("a safety on {}", name(ball)),
        ShotKind::PushOut => "a push out".to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::{Called, Plan};
    use billiards_physics::{Pocket, Shot};
    use billiards_rules::catalog::{self, MatchSettings};

    /// Issue 52: a jump (the computer's 30 to 60 degrees) is said as one, and a level shot or
    /// a swerve's few degrees is not called one.
    #[test]
    fn a_jump_shot_is_said_as_one() {
        assert_eq!(
            jump_text(45f64.to_radians()),
            ", a jump shot (cue raised 45 degrees)"
        );
        assert!(jump_text(30f64.to_radians()).contains("jump shot"));
        assert_eq!(jump_text(0.0), "");
        assert_eq!(jump_text(8f64.to_radians()), "");
    }

    /// The balls are named by the game through the interface: pool's by number, snooker's
    /// by colour, the same plan in each game's words.
    #[test]
    fn balls_are_named_in_the_games_own_words() {
        let plan = |kind| Plan {
            shot: Shot::new(0.0, 2.0),
            place: None,
            part: Called { call: Call::None },
            kind,
            success: 0.72,
            foul: 0.04,
            value: 0.5,
            samples: 1,
            simulations: 1,
            events: 1,
        };
        let start = |id: &str| {
            let settings = MatchSettings::new(["A".to_owned(), "B".to_owned()], 1, 0);
            catalog::find(id).unwrap().start(&settings).unwrap()
        };
        let right = |_: Cushion| "right";
        let pot = ShotKind::Pot {
            ball: 3,
            pocket: Pocket::FootRight,
        };
        let nine = start("nine-ball");
        let said = Decided::Pool(Decision::Shoot(plan(pot))).words(nine.as_ref(), &right);
        assert_eq!(
            said,
            format!(
                "the 3 in the {}, 72 % to succeed, 4 % foul",
                pocket_name(Pocket::FootRight)
            )
        );
        let kick = ShotKind::Kick {
            ball: 20,
            pocket: Pocket::FootRight,
            cushion: Cushion::Right,
        };
        let snooker = start("snooker");
        let said = kind_text(kick, snooker.as_ref(), &right);
        assert!(
            said.starts_with("a kick off the right cushion, the pink in"),
            "{said}"
        );
        // The shared search's stroke says what its aim tries, else where it goes.
        let stroke = |kind| {
            Decided::Any(Move::Strike(crate::any_game::Stroke {
                place: None,
                shot: Shot::new(0.0, 2.0),
                declared: billiards_rules::Declaration::None,
                kind,
                value: 1.0,
            }))
        };
        let ten = start("ten-ball");
        let said = stroke(Some(pot)).words(ten.as_ref(), &right);
        assert!(
            said.starts_with("the 3 in the ") && said.ends_with("m/s), expected value +1.00"),
            "{said}"
        );
        let said = stroke(None).words(ten.as_ref(), &right);
        assert_eq!(
            said,
            "a stroke at 0.0 degrees, 2.0 m/s, expected value +1.00"
        );
    }
}
