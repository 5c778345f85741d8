//! Break statistics: many breaks of seeded 9-ball and 8-ball racks, judged by the rules, per
//! game, table and rack, with 95 % intervals.
//!
//! ```text
//! cargo run --release -p billiards-rules --example break_stats -- --suite
//! cargo run --release -p billiards-rules --example break_stats -- --game nine --table 9ft \
//!     --rack template --breaks 1000 --seed 1
//! cargo run --release -p billiards-rules --example break_stats -- --game nine --table 8ft \
//!     --gaps-mm 0,0.000001,0.01,0.05          # continuity: one row per rack gap
//! ```
//!
//! Options: `--breaks N` (default 1000), `--seed S` (default 1), `--game nine|eight|both`,
//! `--table T` (`7ft`, `8ft`, `9ft`, optionally `-wide` or `-tight` pockets; default: 9-ft for
//! 9-ball, 7-ft for 8-ball), `--rack template|triangle` (default triangle), `--gaps-mm G,..`
//! (rack lattice slack instead of the rack style's), `--speed MIN:MAX` (default 10:12 m/s),
//! `--gaps-mm` is the lattice slack (neighbours end 0 to twice it apart), as `racks::RACK_GAP`.
//! `--set NAME=VALUE` (repeatable: one of the game's physical constants changed, for
//! sensitivity: mu_slide, mu_roll, e_ball, mu_ball (a constant), e_cushion, mu_cushion,
//! young, mu_ball_slip (a factor on Alciatore's slip-dependent fit; 0: the constant mu_ball)),
//! `--aim-sd-deg D` (Gaussian aim error of standard deviation D degrees; FastFiz's noise at
//! magnitude 1 is 0.125), `--tip-height H` (tip offset as a fraction of the radius, negative for draw; default 0),
//! `--cue box|kitchen|string|side|y:F` (default box; side: on the head string within half a
//! diamond of a long cushion; y:F on the head string at F in [0, 1] of the way from the head
//! spot to a long cushion, either side), `--pairwise` (every contact pair by pair: the
//! solver without cluster impacts), `--suite` (the standard comparison: both games, their
//! tables, both racks, then the continuity sweep, then 9-ball's side break with aim noise).
//!
//! The default break: the cue ball in the break box (behind the head string, within one
//! diamond of it and of the long axis: `x` in `[head string - L/8, head string]`, `|y| <= W/4`),
//! aimed at the centre of the head ball, centre ball, speed uniform in 10–12 m/s. Physics: the
//! game's defaults (spin model, Han 2005 cushion, 15 mm jaws, cluster impacts).

use billiards_physics::{Table, TableChoice, table::INCH};
use billiards_rules::breaks::{BreakSpec, BreakStats, Cue, SETTABLE, one_break, params, wilson};
use billiards_rules::{Game, RackStyle};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

#[derive(Clone, Debug)]
struct Options {
    breaks: usize,
    seed: u64,
    games: Vec<Game>,
    table: Option<TableChoice>,
    rack: RackStyle,
    gaps: Option<Vec<f64>>,
    speed: (f64, f64),
    cue: Cue,
    pairwise: bool,
    suite: bool,
    /// Changes to the game's physics, for sensitivity: (name, value).
    set: Vec<(String, f64)>,
    /// Tip height as a fraction of the radius (0: centre ball, negative: draw).
    tip_height: f64,
    /// Standard deviation of a Gaussian error of the aim, radians (0: exactly at the ball).
    aim_sd: f64,
}

fn options() -> Result<Options, String> {
    let mut o = Options {
        breaks: 1000,
        seed: 1,
        games: vec![Game::NineBall, Game::EightBall],
        table: None,
        rack: RackStyle::Triangle,
        gaps: None,
        speed: (10.0, 12.0),
        cue: Cue::Box,
        pairwise: false,
        suite: false,
        set: Vec::new(),
        tip_height: 0.0,
        aim_sd: 0.0,
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        match flag.as_str() {
            "--pairwise" => {
                o.pairwise = true;
                continue;
            }
            "--suite" => {
                o.suite = true;
                continue;
            }
            _ => {}
        }
        let value = it.next().ok_or(format!("{flag} needs a value"))?;
        let bad = |e: &dyn std::fmt::Display| format!("{flag} {value}: {e}");
        match flag.as_str() {
            "--breaks" => o.breaks = value.parse().map_err(|e| bad(&e))?,
            "--seed" => o.seed = value.parse().map_err(|e| bad(&e))?,
            "--game" => {
                o.games = match value.as_str() {
                    "nine" | "nine-ball" => vec![Game::NineBall],
                    "eight" | "eight-ball" => vec![Game::EightBall],
                    "both" => vec![Game::NineBall, Game::EightBall],
                    _ => return Err(bad(&"expected nine, eight or both")),
                }
            }
            "--table" => o.table = Some(value.parse().map_err(|e: String| bad(&e))?),
            "--rack" => o.rack = value.parse().map_err(|e: String| bad(&e))?,
            "--gaps-mm" => {
                let gaps: Result<Vec<f64>, _> =
                    value.split(',').map(|g| g.trim().parse::<f64>()).collect();
                let gaps = gaps.map_err(|e| bad(&e))?;
                if gaps.iter().any(|g| !(0.0..=10.0).contains(g)) {
                    return Err(bad(&"gaps in [0, 10] mm"));
                }
                o.gaps = Some(gaps.into_iter().map(|g| g * 1e-3).collect());
            }
            "--speed" => {
                let (a, b) = value.split_once(':').ok_or(bad(&"expected MIN:MAX"))?;
                let (a, b): (f64, f64) = (
                    a.parse().map_err(|e| bad(&e))?,
                    b.parse().map_err(|e| bad(&e))?,
                );
                if !(0.0 < a && a <= b && b <= 100.0) {
                    return Err(bad(&"expected 0 < MIN <= MAX <= 100 m/s"));
                }
                o.speed = (a, b);
            }
            "--cue" => o.cue = value.parse().map_err(|e: String| bad(&e))?,
            "--set" => {
                let (k, v) = value.split_once('=').ok_or(bad(&"expected NAME=VALUE"))?;
                if !SETTABLE.contains(&k) {
                    return Err(bad(&format!("NAME is one of {SETTABLE:?}")));
                }
                o.set.push((k.into(), v.parse().map_err(|e| bad(&e))?));
            }
            "--tip-height" => o.tip_height = value.parse().map_err(|e| bad(&e))?,
            "--aim-sd-deg" => {
                let d: f64 = value.parse().map_err(|e| bad(&e))?;
                if !(0.0..=10.0).contains(&d) {
                    return Err(bad(&"expected 0 to 10 degrees"));
                }
                o.aim_sd = d.to_radians();
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(o)
}

/// One set of breaks: a game on a table with a rack slack, the cue ball's place and the
/// aim's error (radians).
struct Setup {
    game: Game,
    table: TableChoice,
    gap: f64,
    label: String,
    cue: Cue,
    aim_sd: f64,
}

fn run(o: &Options, s: &Setup) -> BreakStats {
    let params = params(o.pairwise, &o.set).expect("--set values in the physical ranges");
    let spec = BreakSpec {
        game: s.game,
        table: s.table,
        gap: s.gap,
        cue: s.cue,
        speed: o.speed,
        aim_sd: s.aim_sd,
        tip_height: o.tip_height,
    };
    // One stream for the whole row, as the published tables were made.
    let mut rng = ChaCha8Rng::seed_from_u64(o.seed);
    let mut st = BreakStats::default();
    for _ in 0..o.breaks {
        st.add(&one_break(&spec, &params, &mut rng).expect("a break is played"));
    }
    st
}

fn header() {
    println!(
        "| game | table | rack | >= 1 ball (95 %) | balls/break | scratch | legal | success | \
         9/8 on the break | events/break | s |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
}

fn row(o: &Options, s: &Setup) {
    let start = Instant::now();
    let st = run(o, s);
    let n = st.breaks.max(1) as f64;
    let pct = |k: usize| 100.0 * k as f64 / n;
    let (lo, hi) = wilson(st.with_ball, st.breaks);
    let (mean, half) = st.balls_per_break();
    println!(
        "| {} | {} | {} | {:.1} % ({lo:.1}–{hi:.1}) | {mean:.2} ± {:.2} | {:.1} % | {:.1} % | \
         {:.1} % | {:.1} % | {:.0} | {:.1} |",
        match s.game {
            Game::NineBall => "9-ball",
            Game::EightBall => "8-ball",
            Game::FreePlay => "free play",
        },
        s.table,
        s.label,
        pct(st.with_ball),
        half,
        pct(st.scratches),
        pct(st.legal),
        pct(st.success),
        pct(st.money_ball),
        st.events as f64 / n,
        start.elapsed().as_secs_f64()
    );
}

fn gap_label(gap: f64) -> String {
    if gap == 0.0 {
        "frozen".into()
    } else {
        format!("slack {gap:e} m (gaps 0–{:e} m)", 2.0 * gap)
    }
}

fn default_table(game: Game) -> TableChoice {
    let name = if game == Game::NineBall { "9ft" } else { "7ft" };
    name.parse().expect("a table name")
}

fn main() {
    let o = match options() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    println!(
        "{} breaks a row, seed {}, {}–{} m/s, cue ball {:?}, spin model with 15 mm jaws, {}",
        o.breaks,
        o.seed,
        o.speed.0,
        o.speed.1,
        o.cue,
        if o.pairwise {
            "contacts pair by pair"
        } else {
            "cluster impacts"
        }
    );
    header();
    let mut setups = Vec::new();
    if o.suite {
        let nine = |t: &str| t.parse::<TableChoice>().expect("a table name");
        for (game, tables) in [
            (Game::NineBall, vec![nine("9ft"), nine("9ft-tight")]),
            (Game::EightBall, vec![nine("7ft")]),
        ] {
            for table in tables {
                for rack in RackStyle::ALL {
                    setups.push(Setup {
                        game,
                        table,
                        gap: rack.gap(),
                        label: rack.name().into(),
                        cue: o.cue,
                        aim_sd: o.aim_sd,
                    });
                }
            }
        }
        for gap in [0.0, 1e-9, 0.01e-3, 0.05e-3] {
            setups.push(Setup {
                game: Game::NineBall,
                table: nine("9ft"),
                gap,
                label: gap_label(gap),
                cue: o.cue,
                aim_sd: o.aim_sd,
            });
        }
        // The pros' 9-ball break: from near a long cushion, square on the 1, with FastFiz's
        // aim noise at magnitude 1 (crates/rules/README.md, "Why the target is missed").
        for rack in RackStyle::ALL {
            setups.push(Setup {
                game: Game::NineBall,
                table: nine("9ft"),
                gap: rack.gap(),
                label: format!("{}, side break, aim ± 0.125°", rack.name()),
                cue: Cue::Side,
                aim_sd: 0.125f64.to_radians(),
            });
        }
    } else {
        for &game in &o.games {
            let table = o.table.unwrap_or(default_table(game));
            let gaps = o.gaps.clone().unwrap_or(vec![o.rack.gap()]);
            for gap in gaps {
                let label = if o.gaps.is_some() {
                    gap_label(gap)
                } else {
                    o.rack.name().into()
                };
                setups.push(Setup {
                    game,
                    table,
                    gap,
                    label,
                    cue: o.cue,
                    aim_sd: o.aim_sd,
                });
            }
        }
    }
    for s in &setups {
        row(&o, s);
    }
    let t = o.table.map(|t| t.table()).unwrap_or(Table::wpa_9ft());
    println!(
        "(a table's pockets: {:.3} in corner, {:.3} in side; `-tight`: 4 in corner)",
        t.corner_mouth / INCH,
        t.side_mouth / INCH
    );
}
