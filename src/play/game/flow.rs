//! The turn's phase and what the simulation is told from the rules (the judging of a
//! stroke and the player's commands are in `live_flow.rs` and `commands.rs`).

use bevy::prelude::*;
use billiards_rules::{Declaration, Need};

use super::state::*;
use crate::sim::{HandRule, Referee, SimStatus, Solver};

/// The phase the game is in, from the rules, the flags and the table.
fn phase(rules: &Rules, status: &SimStatus, dialog: bool) -> Turn {
    if dialog {
        return Turn::NewGame;
    }
    if !status.at_rest {
        return Turn::ShotInPlay;
    }
    rules.live.as_ref().map_or(Turn::Aiming, LiveGame::phase)
}

/// Derives the turn, the cue ball in hand and the referee's word from the rules.
pub(super) fn follow_rules(
    rules: Res<Rules>,
    dialog: Res<DialogOpen>,
    solver: Option<ResMut<Solver>>,
    mut status: ResMut<SimStatus>,
    mut referee: ResMut<Referee>,
    turn: Option<Res<State<Turn>>>,
    mut next_turn: ResMut<NextState<Turn>>,
) {
    let wanted = phase(&rules, &status, dialog.0);
    // A game behind the interface: its turn, asked once a frame.
    let live = rules.live.as_ref().map(|g| (g, g.rules.turn()));
    if turn.is_some_and(|turn| *turn.get() != wanted) {
        next_turn.set(wanted);
    }
    let refuse_shot = match wanted {
        Turn::NewGame => Some("finish the new-game dialog first"),
        Turn::Verdict => Some("the verdict first: continue or choose"),
        Turn::GameOver => Some("the game is over"),
        Turn::Calling => Some("click a pocket to call it first"),
        // WPA 3.8: the 8 must be called; every 10-ball shot too (9.5), though a shot
        // without one is the rules' to judge, so only the 8 is refused here.
        Turn::Aiming | Turn::BallInHand if let Some((game, turn)) = &live => (turn.declare.pocket
            == Need::Required
            && turn.declare.callable == [8]
            && !matches!(game.declared, Declaration::Pocket { ball: 8, .. }))
        .then_some("call a pocket for the 8 first"),
        Turn::Aiming | Turn::BallInHand => None,
        Turn::ShotInPlay => None,
    }
    .map(|why| match (wanted, &live) {
        // "the rack is over", "the frame is over", "the try is over: Next try".
        (Turn::GameOver, Some((game, _))) => format!(
            "the {} is over{}",
            game.game_noun(),
            if game.rules.solo() { ": Next try" } else { "" }
        ),
        _ => why.to_owned(),
    });
    let wanted_referee = Referee {
        edits: !rules.in_match(),
        refuse_shot,
        rack_over: wanted == Turn::GameOver,
    };
    referee.set_if_neq(wanted_referee);
    // The striker's own cue ball (three-cushion: the white or the yellow), 0 otherwise.
    let cue = live.as_ref().map_or(0, |(_, turn)| turn.cue_ball);
    if let Some(mut solver) = solver
        && solver.cue_number() != cue
    {
        solver.set_cue_number(cue);
    }
    if let Some((game, turn)) = &live
        && status.at_rest
    {
        let hand = HandRule::of_place(turn.place).filter(|_| game.rules.end().is_none());
        if status.ball_in_hand != hand {
            status.ball_in_hand = hand;
        }
    }
}
