//! Where the player's pointer and keyboard input goes. The game's input systems (aiming, the
//! camera, the timeline's keys) sit in these sets; the UI plugin ([`crate::ui`]) turns a set
//! off while the UI has claimed that input, so a click or key meant for a widget never also
//! reaches the table. No plugin has to know about the UI to be kept out of its way.

use bevy::prelude::*;

/// The input systems of every plugin, by the device they read.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InputSystems {
    /// Systems that read the mouse (buttons, motion, wheel) to act on the table or camera.
    Pointer,
    /// Systems that read the keyboard.
    Keyboard,
}

/// While set, a click or drag on the table does not aim the cue: it means something else (a
/// pocket being called) or the shot is not the player's (the computer's turn). Set by the game
/// flow ([`crate::play::game`]), read by the cue's pointer input.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct AimLocked(pub bool);

/// Run condition: the pointer may aim the cue.
pub fn aim_unlocked(lock: Option<Res<AimLocked>>) -> bool {
    !lock.is_some_and(|l| l.0)
}

/// While set, the pointer on the table belongs to a tool (the Place tool moves balls with it)
/// and does not aim. Set by [`crate::practice`] on entering and leaving the tool.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct PointerTool(pub bool);

/// Run condition: no tool has the pointer (it may aim).
pub fn no_pointer_tool(tool: Option<Res<PointerTool>>) -> bool {
    !tool.is_some_and(|t| t.0)
}

/// Whether `button` is down this frame, counting a click whose press and release both fell
/// in this frame: `ButtonInput::pressed` is already false then. A frame takes a second on a
/// software renderer, so most quick clicks end within one; a click on the table must still
/// aim at the point clicked.
pub fn held_or_clicked(buttons: &ButtonInput<MouseButton>, button: MouseButton) -> bool {
    buttons.pressed(button) || buttons.just_pressed(button)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_click_within_one_frame_counts_as_down() {
        let mut buttons = ButtonInput::<MouseButton>::default();
        assert!(!held_or_clicked(&buttons, MouseButton::Left));
        buttons.press(MouseButton::Left);
        buttons.release(MouseButton::Left);
        assert!(!buttons.pressed(MouseButton::Left));
        assert!(held_or_clicked(&buttons, MouseButton::Left));
        // The next frame it is up.
        buttons.clear();
        assert!(!held_or_clicked(&buttons, MouseButton::Left));
        // Held over frames.
        buttons.press(MouseButton::Left);
        buttons.clear();
        assert!(held_or_clicked(&buttons, MouseButton::Left));
    }
}
