//! Whether there is a display to open a window on, asked before Bevy starts: without one,
//! winit panics with a backtrace deep inside the event loop; the game says why instead.

use std::path::Path;

/// What the game says when no display can be reached.
pub const NO_DISPLAY: &str = "no display found (set DISPLAY or run under xvfb-run)";

/// `Err` with a message for the player when the X display named by `display` (the `DISPLAY`
/// variable; the game is built for X11 only) is missing, or is a local display whose socket
/// does not exist. Remote displays (`host:0`) are left to the window system to judge.
pub fn check(display: Option<&str>) -> Result<(), String> {
    let Some(display) = display.filter(|d| !d.trim().is_empty()) else {
        return Err(NO_DISPLAY.to_owned());
    };
    // ":N" or ":N.S" is the local server N, listening on /tmp/.X11-unix/XN.
    if let Some(rest) = display.strip_prefix(':') {
        let number = rest.split('.').next().unwrap_or_default();
        if number.is_empty() || !number.bytes().all(|b| b.is_ascii_digit()) {
            return Err(format!(
                "DISPLAY={display:?} is not a display name; {NO_DISPLAY}"
            ));
        }
        let socket = Path::new("/tmp/.X11-unix").join(format!("X{number}"));
        if !socket.exists() {
            return Err(format!("no X server on DISPLAY={display}; {NO_DISPLAY}"));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_or_empty_display_is_refused() {
        assert_eq!(check(None), Err(NO_DISPLAY.to_owned()));
        assert_eq!(check(Some("  ")), Err(NO_DISPLAY.to_owned()));
    }

    #[test]
    fn a_local_display_needs_its_socket() {
        // Display 65000 has no server here.
        let error = check(Some(":65000")).unwrap_err();
        assert!(
            error.contains("DISPLAY=:65000") && error.contains("xvfb-run"),
            "{error}"
        );
        assert!(check(Some(":x")).is_err());
        // A remote display is not judged here.
        assert_eq!(check(Some("otherhost:0")), Ok(()));
    }
}
