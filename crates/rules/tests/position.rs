//! Position codes (issue 39): every position comes back bit for bit from its code, and every
//! wrong, truncated, damaged or future-version code is refused with its reason.

use billiards_physics::{
    BallSpec, Model, Params, PocketShape, Shot, SpinModel, Table, TipOffset, Vec2,
};
use billiards_rules::{Game, PlacedBall, Position, PositionError};
use proptest::prelude::*;

fn rack() -> Position {
    let table = Table::wpa_9ft().with_jaws(0.015);
    let balls = billiards_physics::Rack::NineBall
        .layout(&table, &BallSpec::default())
        .into_iter()
        .map(|b| PlacedBall {
            number: b.number,
            position: b.position,
        })
        .collect();
    Position {
        game: Game::NineBall,
        table,
        balls,
        params: None,
        shot: None,
    }
}

/// A position's bytes: the code decoded by hand (for the tests that forge codes).
fn bytes(code: &str) -> Vec<u8> {
    let alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    let vals: Vec<u32> = code
        .chars()
        .map(|c| alphabet.find(c).unwrap() as u32)
        .collect();
    let mut out = Vec::new();
    for chunk in vals.chunks(4) {
        let v = chunk
            .iter()
            .enumerate()
            .fold(0, |v, (i, &x)| v | x << (18 - 6 * i));
        for k in 0..chunk.len() - 1 {
            out.push((v >> (16 - 8 * k)) as u8);
        }
    }
    out
}

fn code(bytes: &[u8]) -> String {
    let alphabet = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    let mut s = String::new();
    for chunk in bytes.chunks(3) {
        let v = chunk
            .iter()
            .enumerate()
            .fold(0u32, |v, (i, &b)| v | u32::from(b) << (16 - 8 * i));
        for k in 0..=chunk.len() {
            s.push(char::from(alphabet[(v >> (18 - 6 * k) & 63) as usize]));
        }
    }
    s
}

/// `body` with a valid CRC-32 appended (zlib's), so a test can forge a well-formed code.
fn sealed(body: &[u8]) -> String {
    let mut crc = !0u32;
    for &b in body {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = (crc >> 1) ^ (0xEDB8_8320 & (crc & 1).wrapping_neg());
        }
    }
    let mut b = body.to_vec();
    b.extend((!crc).to_le_bytes());
    code(&b)
}

#[test]
fn a_rack_with_its_physics_and_shot_comes_back_bit_for_bit() {
    let mut p = rack();
    p.params = Some(Params {
        model: Model::Spin(SpinModel::default()),
        ..Params::default()
    });
    p.shot = Some(Shot {
        angle: 0.013,
        speed: 11.5,
        tip: TipOffset {
            side: 0.1,
            height: -0.2,
        },
        elevation: 0.05,
    });
    let c = p.encode().unwrap();
    assert!(
        c.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
    );
    assert_eq!(Position::decode(&c).unwrap(), p);
    // Without physics the 9-ball rack is 10 balls of 17 bytes, 45 bytes of header (the
    // table with its jaws) and 4 of checksum: 219 bytes, 292 characters.
    let short = rack().encode().unwrap();
    assert_eq!(
        short.len(),
        ((3 + 33 + 8 + 1 + 10 * 17 + 4usize) * 8).div_ceil(6)
    );
    // Spaces and line breaks of a pasted code are ignored.
    let spaced: String = short.chars().flat_map(|c| [c, ' ']).collect();
    assert_eq!(Position::decode(&format!("\n {spaced}\n")).unwrap(), rack());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn any_position_comes_back_from_its_code(
        n in 0usize..16,
        seed in any::<u64>(),
        game in 0u8..3,
        jaws in any::<bool>(),
        shot in proptest::option::of((-4.0f64..4.0, 0.0f64..12.0, -0.3f64..0.3, -0.3f64..0.3, 0.0f64..0.5)),
        mu in proptest::option::of(0.05f64..0.4),
    ) {
        let table = if jaws { Table::wpa_8ft().with_jaws(0.012) } else { Table::wpa_7ft() };
        let balls = billiards_physics::racks::scattered(&table, &BallSpec::default(), n, 0.0, seed)
            .into_iter()
            .map(|b| PlacedBall { number: b.number, position: b.position })
            .collect();
        let params = mu.map(|mu| Params {
            model: Model::Spin(SpinModel { mu_slide: mu, ..SpinModel::default() }),
            ..Params::default()
        });
        let p = Position {
            game: [Game::EightBall, Game::NineBall, Game::FreePlay][game as usize],
            table,
            balls,
            params,
            shot: shot.map(|(angle, speed, side, height, elevation)| Shot {
                angle, speed, tip: TipOffset { side, height }, elevation,
            }),
        };
        let c = p.encode().unwrap();
        prop_assert_eq!(Position::decode(&c).unwrap(), p);
    }
}

#[test]
fn every_bad_code_is_refused_with_its_reason() {
    let good = rack().encode().unwrap();
    let b = bytes(&good);
    assert_eq!(Position::decode(""), Err(PositionError::Empty));
    assert_eq!(Position::decode("  \n"), Err(PositionError::Empty));
    assert_eq!(
        Position::decode(&format!("{good}=")),
        Err(PositionError::NotBase64('=', good.len() + 1))
    );
    assert!(matches!(
        Position::decode("ab+c"),
        Err(PositionError::NotBase64('+', 3))
    ));
    // Cut short anywhere: refused (as cut short, or as damaged where the cut leaves a
    // whole number of fields).
    for len in 1..good.len() {
        let e = Position::decode(&good[..len]).unwrap_err();
        assert!(
            matches!(e, PositionError::Truncated(_) | PositionError::Checksum),
            "cut at {len}: {e:?}"
        );
    }
    // One character changed anywhere: refused.
    for i in 0..good.len() {
        let mut c: Vec<char> = good.chars().collect();
        c[i] = if c[i] == 'A' { 'B' } else { 'A' };
        let c: String = c.into_iter().collect();
        assert!(Position::decode(&c).is_err(), "changed at {i}");
    }
    // A newer version, with a valid checksum: refused by its version, the message says update.
    let mut future = b[..b.len() - 4].to_vec();
    future[0] = 2;
    let e = Position::decode(&sealed(&future)).unwrap_err();
    assert_eq!(e, PositionError::FutureVersion(2));
    assert!(e.to_string().contains("update"));
    let mut zero = b[..b.len() - 4].to_vec();
    zero[0] = 0;
    assert_eq!(
        Position::decode(&sealed(&zero)),
        Err(PositionError::BadVersion(0))
    );
    // Well-formed but wrong: unknown flags, game, pocket shape; extra bytes.
    for (at, value, says) in [(1, 0x80, "flags"), (2, 7, "game"), (35, 9, "pocket")] {
        let mut bad = b[..b.len() - 4].to_vec();
        bad[at] = value;
        let e = Position::decode(&sealed(&bad)).unwrap_err();
        assert!(e.to_string().contains(says), "{e}");
    }
    // A last partial group with bits beyond its bytes: not the canonical code, refused.
    let mut mouth = rack();
    mouth.table = Table::wpa_9ft();
    let c = mouth.encode().unwrap();
    assert_ne!(c.len() % 4, 0, "this code ends in a partial group");
    let last = c.chars().last().unwrap();
    let alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    let flipped = alphabet.as_bytes()[alphabet.find(last).unwrap() ^ 1] as char;
    let bad = format!("{}{flipped}", &c[..c.len() - 1]);
    assert_eq!(Position::decode(&bad), Err(PositionError::Checksum));
    assert_eq!(Position::decode(&c).unwrap(), mouth);
    let mut long = b[..b.len() - 4].to_vec();
    long.push(0);
    assert_eq!(
        Position::decode(&sealed(&long)),
        Err(PositionError::Trailing(1))
    );
}

#[test]
fn a_position_the_table_cannot_hold_is_refused_both_ways() {
    // Two balls on one spot.
    let mut p = rack();
    p.balls[1].position = p.balls[2].position;
    let e = p.encode().unwrap_err();
    assert!(matches!(e, PositionError::Invalid(_)), "{e:?}");
    // Off the table, forged into a code with a valid checksum.
    let mut q = rack();
    let good = bytes(&q.encode().unwrap());
    q.balls[0].position = Vec2::new(5.0, 0.0);
    let mut body = good[..good.len() - 4].to_vec();
    let x_at = 3 + 33 + 8 + 1 + 1;
    body[x_at..x_at + 8].copy_from_slice(&5.0f64.to_le_bytes());
    let e = Position::decode(&sealed(&body)).unwrap_err();
    assert!(matches!(e, PositionError::Invalid(_)), "{e:?}");
    // A NaN in the shot.
    let mut s = rack();
    s.shot = Some(Shot::new(f64::NAN, 3.0));
    assert!(s.encode().is_err());
    assert!(matches!(rack().table.pockets, PocketShape::Jaws { .. }));
}

/// Issue 48: two balls of one number are refused, by the number, whether the position comes
/// as JSON (`position encode`) or as a code forged with a valid checksum.
#[test]
fn two_balls_of_one_number_are_refused_both_ways() {
    let mut p = rack();
    let good = bytes(&p.encode().unwrap());
    p.balls[2].number = p.balls[1].number;
    let n = p.balls[1].number;
    let e = p.encode().unwrap_err();
    assert_eq!(
        e.to_string(),
        format!("the position is not valid: two balls are numbered {n} (each number once)")
    );
    // The same in a code: the third ball's number byte set to the second's.
    let mut body = good[..good.len() - 4].to_vec();
    let (second, third) = (3 + 33 + 8 + 1 + 17, 3 + 33 + 8 + 1 + 2 * 17);
    assert_eq!(body[second], n, "the code's layout: a number then x, y");
    body[third] = n;
    let e = Position::decode(&sealed(&body)).unwrap_err();
    assert!(
        e.to_string()
            .contains(&format!("two balls are numbered {n}")),
        "{e}"
    );
}

/// Issue 39: a replay's shot opened as a position holds every ball where it rested when
/// that shot was struck, the physics then in force and the shot itself; a shot that is not
/// there is refused.
#[test]
fn a_recorded_shot_opens_as_the_position_it_was_struck_from() {
    use billiards_physics::recording::Recorder;
    let p = rack();
    let mut rec = Recorder::new(p.table, Params::default(), p.setups()).unwrap();
    let first = Shot {
        angle: 0.1,
        speed: 3.0,
        tip: TipOffset::default(),
        elevation: 0.0,
    };
    rec.strike(0, first).unwrap();
    rec.run_to_rest().unwrap();
    let resting: Vec<(u8, Vec2)> = rec
        .sim()
        .balls()
        .zip(rec.sim().numbers())
        .filter(|(b, _)| b.motion.on_table())
        .map(|(b, &n)| (n, b.position))
        .collect();
    let second = Shot {
        angle: -2.0,
        speed: 1.5,
        ..first
    };
    rec.strike(0, second).unwrap();
    rec.run_to_rest().unwrap();
    let recording = rec.recording();
    let history = recording.history().unwrap();

    let one = Position::from_recording(&recording, &history, 1, Game::FreePlay).unwrap();
    assert_eq!(one.balls, p.balls, "shot 1 starts from the rack");
    assert_eq!(one.shot, Some(first));
    let two = Position::from_recording(&recording, &history, 2, Game::FreePlay).unwrap();
    let got: Vec<(u8, Vec2)> = two.balls.iter().map(|b| (b.number, b.position)).collect();
    assert_eq!(got, resting, "shot 2 starts where shot 1 left the balls");
    assert_eq!(two.shot, Some(second));
    assert_eq!(two.params, Some(Params::default()));
    // And the code of it opens the same position.
    assert_eq!(Position::decode(&two.encode().unwrap()).unwrap(), two);
    for k in [0, 3] {
        let e = Position::from_recording(&recording, &history, k, Game::FreePlay).unwrap_err();
        assert!(e.to_string().contains(&format!("no shot {k}")), "{e}");
    }
}
