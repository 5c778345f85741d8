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
//! Options: `--breaks N` (default 1000), `--seed S` (default 1), `--game nine|ten|eight|both`,
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
//! game's defaults (spin model, Mathavan 2010 cushion with e 0.98 and mu 0.14 as the game's
//! settings have it, 15 mm jaws, cluster impacts); `--cushion han|reflect|mathavan` changes it
//! (Han 2005 with e 0.85, mu 0.2 is the solver's own `Params::default()`).
//!
//! More options: `--elevation-deg D` (cue elevation, 0–30°), `--nine-on-spot` (9-ball: the
//! rack two rows nearer the head, the 9 on the foot spot), `--seeds K` (K streams of
//! `--breaks` each, seeds S to S + K - 1), `--study` (the break study: 9-ball, one change at a
//! time from the other options, one row each; docs/realism.md, "The break"), `--svg PATH`
//! (with `--study`: its plot).

mod options;
mod rows;
mod study;

use options::{Options, options};
use rows::{Setup, default_table, gap_label, header, row};
use study::{study, study_svg};

use billiards_physics::{Table, TableChoice, table::INCH};
use billiards_rules::breaks::Cue;
use billiards_rules::{Game, RackStyle};

fn main() {
    let o = match options() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    banner(&o);
    if o.study {
        let rows = study(&o);
        if let Some(path) = &o.svg {
            let title = format!(
                "9-ball break from the {}, {} rack, {}–{} m/s, aim sd {}°, {} breaks a row: \
                 one change at a time",
                o.cue,
                o.rack.name(),
                o.speed.0,
                o.speed.1,
                o.aim_sd.to_degrees(),
                o.breaks * o.seeds.max(1) as usize
            );
            std::fs::write(path, study_svg(&rows, &title)).expect("the SVG is written");
        }
        return;
    }
    header();
    let setups = if o.suite {
        suite_setups(&o)
    } else {
        given_setups(&o)
    };
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

/// The first line: what every row shares.
fn banner(o: &Options) {
    println!(
        "{} breaks a row, seed {}{}, {}–{} m/s, cue ball {:?}, tip {} R, elevation {:.1}°, \
         aim sd {:.3}°, {:?}, spin model with 15 mm jaws, {}",
        o.breaks,
        o.seed,
        if o.seeds > 1 {
            format!(" to {}", o.seed + o.seeds - 1)
        } else {
            String::new()
        },
        o.speed.0,
        o.speed.1,
        o.cue,
        o.tip_height,
        o.elevation.to_degrees(),
        o.aim_sd.to_degrees(),
        o.cushion,
        if o.pairwise {
            "contacts pair by pair"
        } else {
            "cluster impacts"
        }
    );
}

/// `--suite`: both games on their tables with both racks, the continuity sweep of rack
/// gaps, then 9-ball's side break with aim noise.
fn suite_setups(o: &Options) -> Vec<Setup> {
    let mut setups = Vec::new();
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
    setups
}

/// The rows the options ask for: each game on its table, one row per rack gap.
fn given_setups(o: &Options) -> Vec<Setup> {
    let mut setups = Vec::new();
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
    setups
}
