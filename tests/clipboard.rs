//! The position code through a real X clipboard (issue 47): a code copied by one game's
//! Copy command is pasted by another game's Paste command, through an Xvfb server's
//! CLIPBOARD selection (arboard's X11 backend on both sides, no clipboard manager), and the
//! second game sets up every ball where the first had it.
//!
//! Needs `Xvfb` (`apt-get install xvfb`); without it the test says so and passes, except
//! when `CI` is set, where a missing server is a failure: CI installs it.

mod common;

use std::{
    path::Path,
    process::{Child, Command},
    time::Duration,
};

use billiards::{
    practice::{PositionCode, PositionCommand},
    sim::SimStatus,
};

/// An Xvfb server on the first free display from :91 (its number), ended when dropped.
struct Xvfb(Child, u32);

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
        // Killed, the server leaves its lock and socket behind; left there, they would
        // take the display from every later run until none of :91-:119 is free.
        let _ = std::fs::remove_file(format!("/tmp/.X{}-lock", self.1));
        let _ = std::fs::remove_file(format!("/tmp/.X11-unix/X{}", self.1));
    }
}

fn start_xvfb() -> Option<(Xvfb, String)> {
    for n in 91..120 {
        if Path::new(&format!("/tmp/.X{n}-lock")).exists() {
            continue;
        }
        let child = Command::new("Xvfb")
            .arg(format!(":{n}"))
            .args(["-screen", "0", "320x240x24", "-nolisten", "tcp"])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .ok()?;
        let mut server = Xvfb(child, n);
        // The socket appears once the server listens; a server that exits instead (the
        // display was taken) leaves the next number to try. However long a loaded machine
        // takes, the wait is for one or the other, not for a time.
        let socket = format!("/tmp/.X11-unix/X{n}");
        loop {
            if Path::new(&socket).exists() {
                return Some((server, format!(":{n}")));
            }
            if !matches!(server.0.try_wait(), Ok(None)) {
                break;
            }
            std::thread::sleep(Duration::from_millis(10));
        }
    }
    None
}

use common::{layout, practice_app as app, shoot_to_rest};

/// The test's own name, for the child run.
const NAME: &str = "a_code_copied_in_one_game_is_pasted_in_another_through_x";

/// Set in the child run: the display is the test's Xvfb.
const CHILD: &str = "BILLIARDS_CLIPBOARD_TEST_CHILD";

/// Copy in one game, Paste in another, through the X server's clipboard. The games run in a
/// child process of this test binary whose `DISPLAY` is a fresh Xvfb (the environment is
/// the child's own, so nothing here changes it while threads run).
#[test]
fn a_code_copied_in_one_game_is_pasted_in_another_through_x() {
    if std::env::var_os(CHILD).is_some() {
        copy_and_paste();
        return;
    }
    let Some((_server, display)) = start_xvfb() else {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set and Xvfb could not start: the clipboard is not tested"
        );
        eprintln!("clipboard test skipped: needs Xvfb (apt-get install xvfb)");
        return;
    };
    let out = Command::new(std::env::current_exe().expect("the test binary"))
        .args(["--exact", NAME, "--nocapture", "--test-threads=1"])
        .env(CHILD, "1")
        .env("DISPLAY", &display)
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("the child run starts");
    let text = format!(
        "{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "the child run failed:\n{text}");
    assert!(text.contains("1 passed"), "the child ran no test:\n{text}");
}

fn copy_and_paste() {
    let mut first = app();
    shoot_to_rest(&mut first, 0.03, 6.0);
    let broken = layout(&first);
    first.world_mut().write_message(PositionCommand::Copy {
        with_params: true,
        with_shot: true,
    });
    first.update();
    let note = first.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.starts_with("position copied: "), "{note}");
    let code = first.world().resource::<PositionCode>().0.clone();

    let mut second = app();
    assert_ne!(
        layout(&second),
        broken,
        "the second game starts from a rack"
    );
    second
        .world_mut()
        .write_message(PositionCommand::Paste { own_physics: true });
    for _ in 0..3 {
        second.update();
    }
    assert_eq!(second.world().resource::<PositionCode>().0, code);
    let note = second.world().resource::<SimStatus>().note.clone().unwrap();
    assert!(note.starts_with("position pasted: "), "{note}");
    assert_eq!(
        layout(&second),
        broken,
        "every ball where the first game had it"
    );
    drop(first);
}
