//! The 22 balls by number (as racked by [`billiards_physics::snooker::layout`]): the cue ball
//! 0, the reds 1 to 15, the colours 16 (yellow) to 21 (black); their values (WPBSA 3.1).

pub use billiards_physics::snooker::{
    BLACK, BLUE, BROWN, COLOURS, GREEN, PINK, REDS, WHITE, YELLOW,
};

/// Is `n` a red?
pub fn is_red(n: u8) -> bool {
    REDS.contains(&n)
}

/// Is `n` one of the six colours?
pub fn is_colour(n: u8) -> bool {
    COLOURS.contains(&n)
}

/// The value of object ball `n` (3.1: red 1, yellow 2 ... black 7); `None` for the cue ball
/// and numbers beyond the black.
pub fn value(n: u8) -> Option<u32> {
    match n {
        1..=15 => Some(1),
        YELLOW..=BLACK => Some(u32::from(n - YELLOW) + 2),
        _ => None,
    }
}

/// The ball's name in a sentence: "red", "yellow", ..., "cue ball".
pub fn name(n: u8) -> &'static str {
    match n {
        WHITE => "cue ball",
        1..=15 => "red",
        YELLOW => "yellow",
        GREEN => "green",
        BROWN => "brown",
        BLUE => "blue",
        PINK => "pink",
        BLACK => "black",
        _ => "unknown ball",
    }
}

/// The colour after `c` in the order of 3.3(c) (`None` after the black).
pub fn next_colour(c: u8) -> Option<u8> {
    COLOURS
        .iter()
        .position(|&k| k == c)
        .and_then(|i| COLOURS.get(i + 1).copied())
}

/// Balls pocketed, named: the reds counted, the colours named ("2 reds", "the pink", "the
/// cue ball").
pub fn list_names(numbers: &[u8]) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    match numbers.iter().filter(|&&n| is_red(n)).count() {
        0 => {}
        1 => names.push("a red".to_owned()),
        k => names.push(format!("{k} reds")),
    }
    names.extend(
        numbers
            .iter()
            .filter(|&&n| !is_red(n) && n != WHITE)
            .map(|&n| format!("the {}", name(n))),
    );
    if numbers.contains(&WHITE) {
        names.push("the cue ball".to_owned());
    }
    names
}

/// A ball in a replay's words: its [`name`].
pub fn word(n: u8) -> String {
    name(n).to_owned()
}
