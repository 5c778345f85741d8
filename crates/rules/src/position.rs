//! A position as a short text code (issue 39): the game, the table, every ball's place, and
//! optionally the physics and the shot, in a versioned binary form with a checksum, written
//! in base64url (RFC 4648 section 5, no padding) so it survives a chat message or a URL.
//!
//! Layout of version 1 (little-endian):
//!
//! | bytes | what |
//! |---|---|
//! | 1 | version (1) |
//! | 1 | flags: bit 0 the physics follow, bit 1 a shot follows |
//! | 1 | game: 0 8-ball, 1 9-ball, 2 free play |
//! | 4 x 8 + 1 (+ 8) | table: length, width, corner and side mouth (f64), pockets (0 the paper's mouths, 1 jaws, then their radius, 2 none) |
//! | 1 + 17 n | the balls: their count, then each one's number (u8) and centre x, y (f64) |
//! | 2 + k | with flag 0: the parameters as JSON (`Params`, the scene files' form), k bytes |
//! | 5 x 8 | with flag 1: the shot's angle, speed, tip side, tip height, elevation (f64) |
//! | 4 | CRC-32 (IEEE) of every byte before it |
//!
//! Values are kept bit for bit (no rounding), so a code opens exactly the position it was
//! made from; balls are at rest (a position is set up, not caught in motion). Decoding checks
//! the checksum, the version, every field, and that the balls lie on the table apart from each
//! other (as [`Simulation::new`] does), and says what is wrong.

use crate::game::Game;
use billiards_physics::recording::{Action, Recording};
use billiards_physics::{
    BallSetup, History, Params, PocketShape, Shot, Simulation, Table, TipOffset, Vec2,
};
use serde::{Deserialize, Serialize};

/// The version this build writes and reads.
pub const VERSION: u8 = 1;

/// Most balls a position holds (a snooker frame has 22).
pub const MAX_BALLS: usize = 64;

const PARAMS: u8 = 1;
const SHOT: u8 = 2;

/// A ball of a position: its number and its centre (at rest).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlacedBall {
    /// Number painted on the ball (0 for the cue ball).
    pub number: u8,
    /// Centre, metres.
    pub position: Vec2,
}

/// A position: what a code holds, and its JSON form (`billiards-cli position`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Position {
    /// The game played from it.
    pub game: Game,
    /// The table.
    pub table: Table,
    /// Every ball on the table.
    pub balls: Vec<PlacedBall>,
    /// The physics, if the position carries its own (else the player's are kept).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub params: Option<Params>,
    /// The shot to try from it, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shot: Option<Shot>,
}

/// Why a code (or a position to encode) was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PositionError {
    /// Nothing was given.
    #[error("the position code is empty")]
    Empty,
    /// A character outside base64url.
    #[error("not a position code: {0:?} at character {1} is not base64url (A-Z a-z 0-9 - _)")]
    NotBase64(char, usize),
    /// The code ends too soon.
    #[error("the position code is cut short (truncated while reading {0}); copy all of it")]
    Truncated(&'static str),
    /// The checksum does not match: a character was changed or lost.
    #[error("the position code is damaged (its checksum does not match); copy it again")]
    Checksum,
    /// Made by a newer version of the game.
    #[error(
        "the position code is version {0}; this build reads version {VERSION}: update the game"
    )]
    FutureVersion(u8),
    /// A version that never existed.
    #[error("the position code has an unknown version {0}")]
    BadVersion(u8),
    /// A field holds a value no position may have (two balls of one number, a ball off the
    /// table, a shot that is not a number): in a code or a JSON file alike.
    #[error("the position is not valid: {0}")]
    Invalid(String),
    /// Bytes after the checksum's place.
    #[error("the position code has {0} bytes too many")]
    Trailing(usize),
}

impl Position {
    /// The position's code.
    pub fn encode(&self) -> Result<String, PositionError> {
        self.check()?;
        let mut b = vec![VERSION];
        let flags = if self.params.is_some() { PARAMS } else { 0 }
            | if self.shot.is_some() { SHOT } else { 0 };
        b.push(flags);
        b.push(match self.game {
            Game::EightBall => 0,
            Game::NineBall => 1,
            Game::FreePlay => 2,
        });
        let t = &self.table;
        for x in [t.length, t.width, t.corner_mouth, t.side_mouth] {
            b.extend(x.to_le_bytes());
        }
        match t.pockets {
            PocketShape::Mouth => b.push(0),
            PocketShape::Jaws { radius } => {
                b.push(1);
                b.extend(radius.to_le_bytes());
            }
            PocketShape::Pocketless => b.push(2),
        }
        b.push(self.balls.len() as u8);
        for ball in &self.balls {
            b.push(ball.number);
            b.extend(ball.position.x.to_le_bytes());
            b.extend(ball.position.y.to_le_bytes());
        }
        if let Some(p) = &self.params {
            let json = serde_json::to_vec(p).map_err(|e| PositionError::Invalid(e.to_string()))?;
            let len = u16::try_from(json.len())
                .map_err(|_| PositionError::Invalid("the parameters are too long".into()))?;
            b.extend(len.to_le_bytes());
            b.extend(json);
        }
        if let Some(s) = &self.shot {
            for x in [s.angle, s.speed, s.tip.side, s.tip.height, s.elevation] {
                b.extend(x.to_le_bytes());
            }
        }
        let crc = crc32(&b);
        b.extend(crc.to_le_bytes());
        Ok(base64url(&b))
    }

    /// The position of `code` (spaces and line breaks around or inside it are ignored).
    pub fn decode(code: &str) -> Result<Self, PositionError> {
        let text: String = code.chars().filter(|c| !c.is_whitespace()).collect();
        if text.is_empty() {
            return Err(PositionError::Empty);
        }
        let bytes = unbase64url(&text)?;
        let mut r = Reader { b: &bytes, at: 0 };
        let version = r.u8("the version")?;
        if version > VERSION {
            return Err(PositionError::FutureVersion(version));
        }
        if version == 0 {
            return Err(PositionError::BadVersion(version));
        }
        if bytes.len() < 4 {
            return Err(PositionError::Truncated("the checksum"));
        }
        let (body, crc) = bytes.split_at(bytes.len() - 4);
        let crc = u32::from_le_bytes(crc.try_into().expect("four bytes"));
        // A code cut short reads as one whose last bytes are its checksum: say it is short
        // if its fields run out, else that it is damaged (never what a damaged field says).
        if crc32(body) != crc {
            return Err(match Self::parse(body) {
                Err(e @ PositionError::Truncated(_)) => e,
                _ => PositionError::Checksum,
            });
        }
        Self::parse(body)
    }

    /// The fields of a code's body (without its checksum).
    fn parse(body: &[u8]) -> Result<Self, PositionError> {
        let mut r = Reader { b: body, at: 1 };
        let invalid = |s: String| PositionError::Invalid(s);
        let flags = r.u8("the flags")?;
        if flags & !(PARAMS | SHOT) != 0 {
            return Err(invalid(format!("unknown flags {flags:#04x}")));
        }
        let game = match r.u8("the game")? {
            0 => Game::EightBall,
            1 => Game::NineBall,
            2 => Game::FreePlay,
            g => return Err(invalid(format!("unknown game {g}"))),
        };
        let (length, width) = (r.f64("the table")?, r.f64("the table")?);
        let (corner_mouth, side_mouth) = (r.f64("the table")?, r.f64("the table")?);
        let pockets = match r.u8("the table")? {
            0 => PocketShape::Mouth,
            1 => PocketShape::Jaws {
                radius: r.f64("the table")?,
            },
            2 => PocketShape::Pocketless,
            k => return Err(invalid(format!("unknown pocket shape {k}"))),
        };
        let table = Table {
            length,
            width,
            corner_mouth,
            side_mouth,
            pockets,
        };
        let n = usize::from(r.u8("the ball count")?);
        let mut balls = Vec::with_capacity(n);
        for _ in 0..n {
            let number = r.u8("a ball")?;
            let position = Vec2::new(r.f64("a ball")?, r.f64("a ball")?);
            balls.push(PlacedBall { number, position });
        }
        let params = if flags & PARAMS != 0 {
            let len = usize::from(u16::from_le_bytes([
                r.u8("the physics")?,
                r.u8("the physics")?,
            ]));
            let json = r.take(len, "the physics")?;
            Some(
                serde_json::from_slice::<Params>(json)
                    .map_err(|e| invalid(format!("the physics: {e}")))?,
            )
        } else {
            None
        };
        let shot = if flags & SHOT != 0 {
            let mut x = [0.0; 5];
            for v in &mut x {
                *v = r.f64("the shot")?;
            }
            Some(Shot {
                angle: x[0],
                speed: x[1],
                tip: TipOffset {
                    side: x[2],
                    height: x[3],
                },
                elevation: x[4],
            })
        } else {
            None
        };
        if r.at != body.len() {
            return Err(PositionError::Trailing(body.len() - r.at));
        }
        let p = Self {
            game,
            table,
            balls,
            params,
            shot,
        };
        p.check()?;
        Ok(p)
    }

    /// The balls of `sim` on the table now, by number and centre (pocketed balls left out),
    /// with `sim`'s table and, if `with_params`, its physics.
    pub fn of_simulation(sim: &Simulation, game: Game, with_params: bool) -> Self {
        let balls = sim
            .balls()
            .zip(sim.numbers())
            .filter(|(b, _)| b.motion.on_table())
            .map(|(b, &number)| PlacedBall {
                number,
                position: b.position,
            })
            .collect();
        Self {
            game,
            table: *sim.table(),
            balls,
            params: with_params.then(|| *sim.params()),
            shot: None,
        }
    }

    /// Shot `k` (from 1, as [`crate::Shots`] counts) of `recording` as a position: every
    /// ball where it rested when the shot was struck (from `history`, the recording's
    /// rebuilt events), the recording's table, the physics in force then (its last
    /// parameter change before the strike) and the shot itself. A shot struck while balls
    /// still rolled is refused: a position is set up at rest.
    pub fn from_recording(
        recording: &Recording,
        history: &History,
        k: usize,
        game: Game,
    ) -> Result<Self, PositionError> {
        let invalid = |s: String| PositionError::Invalid(s);
        let strikes: Vec<(f64, Shot)> = recording
            .inputs
            .iter()
            .filter_map(|i| match i.action {
                Action::Strike { shot, .. } => Some((i.time, shot)),
                _ => None,
            })
            .collect();
        let &(time, shot) = k
            .checked_sub(1)
            .and_then(|i| strikes.get(i))
            .ok_or_else(|| {
                invalid(format!(
                    "the recording has no shot {k} (it has {})",
                    strikes.len()
                ))
            })?;
        let params = recording
            .inputs
            .iter()
            .take_while(|i| i.time <= time)
            .filter_map(|i| match i.action {
                Action::SetParams { params } => Some(params),
                _ => None,
            })
            .last()
            .unwrap_or(recording.params);
        let mut balls = Vec::new();
        for (id, setup) in recording.balls.iter().enumerate() {
            // The state just before the strike: the segment before `time` for the struck
            // ball; a ball still moving then makes no position.
            let before = history.state_at(id, time.next_down());
            if !before.motion.on_table() {
                continue;
            }
            // A ball that came to rest at the strike's own instant (the game strikes at the
            // rest time) still has, one ulp before, a speed of about g mu ulp ~ 1e-16 m/s:
            // moving means faster than a micrometre a second.
            if before.velocity.length() > 1e-6 && time > 0.0 {
                return Err(invalid(format!(
                    "shot {k} was struck while the {} still moved",
                    setup.number
                )));
            }
            let at = history.state_at(id, time);
            balls.push(PlacedBall {
                number: setup.number,
                position: at.position,
            });
        }
        let p = Self {
            game,
            table: recording.table,
            balls,
            params: Some(params),
            shot: Some(shot),
        };
        p.check()?;
        Ok(p)
    }

    /// The balls as a simulation's setups, at rest.
    pub fn setups(&self) -> Vec<BallSetup> {
        self.balls
            .iter()
            .map(|b| BallSetup::at(b.number, b.position))
            .collect()
    }

    /// A position a simulation can start from: a valid table and physics, at most
    /// [`MAX_BALLS`] balls, each on the table and clear of the others, and a finite shot.
    pub fn check(&self) -> Result<(), PositionError> {
        let invalid = |s: String| PositionError::Invalid(s);
        if self.balls.len() > MAX_BALLS {
            return Err(invalid(format!(
                "{} balls, at most {MAX_BALLS}",
                self.balls.len()
            )));
        }
        // One ball of each number: a rack has one 5 (WPA 1.2, the balls), and the rules, the
        // drills and the Place tool name balls by number.
        let mut numbers: Vec<u8> = self.balls.iter().map(|b| b.number).collect();
        numbers.sort_unstable();
        if let Some(pair) = numbers.windows(2).find(|w| w[0] == w[1]) {
            return Err(invalid(format!(
                "two balls are numbered {} (each number once)",
                pair[0]
            )));
        }
        let params = self.params.unwrap_or_default();
        Simulation::new(self.table, params, &self.setups()).map_err(|e| invalid(e.to_string()))?;
        if let Some(s) = self.shot {
            let finite = [s.angle, s.speed, s.tip.side, s.tip.height, s.elevation]
                .iter()
                .all(|x| x.is_finite());
            if !finite {
                return Err(invalid("the shot has a value that is not a number".into()));
            }
        }
        Ok(())
    }
}

/// Reads a code's bytes in order, naming what it was reading when they ran out.
struct Reader<'a> {
    b: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take(&mut self, n: usize, what: &'static str) -> Result<&[u8], PositionError> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.b.len());
        let end = end.ok_or(PositionError::Truncated(what))?;
        let s = &self.b[self.at..end];
        self.at = end;
        Ok(s)
    }

    fn u8(&mut self, what: &'static str) -> Result<u8, PositionError> {
        Ok(self.take(1, what)?[0])
    }

    fn f64(&mut self, what: &'static str) -> Result<f64, PositionError> {
        let b = self.take(8, what)?;
        Ok(f64::from_le_bytes(b.try_into().expect("eight bytes")))
    }
}

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), as zlib computes it.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = (crc >> 1) ^ (0xEDB8_8320 & (crc & 1).wrapping_neg());
        }
    }
    !crc
}

const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

/// Base64url without padding (RFC 4648 section 5).
fn base64url(bytes: &[u8]) -> String {
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let v = chunk
            .iter()
            .enumerate()
            .fold(0u32, |v, (i, &b)| v | u32::from(b) << (16 - 8 * i));
        for k in 0..=chunk.len() {
            out.push(char::from(ALPHABET[(v >> (18 - 6 * k) & 63) as usize]));
        }
    }
    out
}

/// The bytes of base64url text without padding.
fn unbase64url(text: &str) -> Result<Vec<u8>, PositionError> {
    let mut vals = Vec::with_capacity(text.len());
    for (i, c) in text.chars().enumerate() {
        let v = ALPHABET.iter().position(|&a| char::from(a) == c);
        vals.push(v.ok_or(PositionError::NotBase64(c, i + 1))? as u32);
    }
    if vals.len() % 4 == 1 {
        return Err(PositionError::Truncated("the last character"));
    }
    let mut out = Vec::with_capacity(vals.len() * 3 / 4);
    for chunk in vals.chunks(4) {
        let v = chunk
            .iter()
            .enumerate()
            .fold(0u32, |v, (i, &x)| v | x << (18 - 6 * i));
        for k in 0..chunk.len() - 1 {
            out.push((v >> (16 - 8 * k)) as u8);
        }
        // The bits of a last partial group beyond its bytes must be zero (RFC 4648 3.5), so
        // that one position has one code.
        let used = 8 * (chunk.len() - 1);
        if chunk.len() < 4 && v & ((1 << (24 - used)) - 1) != 0 {
            return Err(PositionError::Checksum);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_and_base64url_match_their_standards() {
        // zlib's CRC-32 of "123456789" (the check value of the IEEE polynomial).
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        // RFC 4648 section 10's test vectors, without padding.
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg"),
            ("fo", "Zm8"),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg"),
            ("fooba", "Zm9vYmE"),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64url(plain.as_bytes()), coded);
            assert_eq!(unbase64url(coded).unwrap(), plain.as_bytes());
        }
        // The two characters that differ from plain base64.
        assert_eq!(base64url(&[0xfb, 0xff]), "-_8");
    }
}
