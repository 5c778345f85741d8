//! Keys that change a value: a tap is one fixed step, a held key moves at a rate in real time.
//!
//! A frame's delta is no measure of a tap: after an idle spell the reactive window's first
//! frame can span seconds (a tap then turned the aim 45 degrees), and on a software renderer
//! a press and its release often fall in one frame (a `pressed` test then sees nothing), as do
//! several taps (`just_pressed` then sees one). So each press is one step, counted from the
//! keyboard's messages, and only the real time a key has been held past [`REPEAT_DELAY`]
//! adds a motion at the key's rate, however the frames fall.

use std::collections::HashMap;

use bevy::prelude::*;

/// How long a key must be held before it moves at its rate, seconds (a typical key-repeat
/// delay: a tap is shorter).
pub const REPEAT_DELAY: f64 = 0.35;

/// When each held key went down, on the real clock (seconds since start); the cue's keys keep
/// one as a system-local.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct HeldKeys {
    since: HashMap<KeyCode, f64>,
}

impl HeldKeys {
    /// How far `key` moves its value in the frame from `previous` to `now` (real seconds): one
    /// `step` for each of the frame's `presses` (not auto-repeats), then `rate` per second held
    /// past [`REPEAT_DELAY`].
    pub fn motion(
        &mut self,
        key: KeyCode,
        (presses, pressed): (u32, bool),
        (previous, now): (f64, f64),
        (step, rate): (f64, f64),
    ) -> f64 {
        if presses > 0 {
            // Presses this frame: their moments are not known closer than the frame; count
            // the last from now, so a long frame adds nothing to the taps.
            if pressed {
                self.since.insert(key, now);
            } else {
                self.since.remove(&key);
            }
            return step * f64::from(presses);
        }
        if !pressed {
            self.since.remove(&key);
            return 0.0;
        }
        let Some(&down) = self.since.get(&key) else {
            // Held since before this system ran (e.g. across a mode change): from now on.
            self.since.insert(key, now);
            return 0.0;
        };
        let from = previous.max(down + REPEAT_DELAY);
        rate * (now - from).max(0.0)
    }

    /// Whether a key is held long enough to be moving (frames must keep coming).
    pub fn any_held(&self) -> bool {
        !self.since.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs a key through frames of `frame` seconds: down for the first `held` seconds
    /// (at least one frame), and returns the total motion.
    fn press(frame: f64, held: f64, release_in_same_frame: bool) -> f64 {
        press_n(1, frame, held, release_in_same_frame)
    }

    /// [`press`] with `taps` presses in the first frame (the last one possibly held).
    fn press_n(taps: u32, frame: f64, held: f64, release_in_same_frame: bool) -> f64 {
        let mut keys = HeldKeys::default();
        let (step, rate) = (1.0, 30.0);
        let key = KeyCode::ArrowLeft;
        let mut total = 0.0;
        let mut t = 10.0;
        // The frame in which the key went down.
        total += keys.motion(
            key,
            (taps, !release_in_same_frame),
            (t - frame, t),
            (step, rate),
        );
        if release_in_same_frame {
            return total;
        }
        let up_at = t + held;
        loop {
            let previous = t;
            t += frame;
            let down = t <= up_at;
            total += keys.motion(key, (0, down), (previous, t), (step, rate));
            if !down {
                break;
            }
        }
        total
    }

    #[test]
    fn a_tap_is_one_step_at_16_ms_and_at_2_s_frames() {
        for frame in [0.016, 2.0] {
            // Released in the same frame as pressed, or in the next one.
            assert_eq!(press(frame, 0.0, true), 1.0, "frame {frame}");
            assert_eq!(press(frame, 0.1, false), 1.0, "frame {frame}");
            // Five taps within one slow frame are five steps (seen under Xvfb at 0.3 fps:
            // five taps of Up added 0.2 m/s, not 0.5).
            assert_eq!(press_n(5, frame, 0.0, true), 5.0, "frame {frame}");
        }
    }

    #[test]
    fn a_held_key_moves_at_its_rate_in_real_time_whatever_the_frame_rate() {
        // Held 2 s: one step, then 30 per second for 2 - 0.35 s, up to one frame's rounding
        // of the release.
        let want = 1.0 + 30.0 * (2.0 - REPEAT_DELAY);
        let fast = press(0.016, 2.0, false);
        assert!(
            (fast - want).abs() <= 30.0 * 0.016 + 1e-9,
            "{fast} vs {want}"
        );
        let slow = press(0.5, 2.0, false);
        assert!((slow - want).abs() <= 30.0 * 0.5 + 1e-9, "{slow} vs {want}");
    }
}
