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

use billiards_physics::{CushionModel, Table, TableChoice, table::INCH};
use billiards_rules::breaks::{
    BreakSpec, BreakStats, Cue, GAME_CUSHION, SETTABLE, cushion_by_name, one_break, params_with,
    wilson,
};
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
    /// The cushion model (default: the game's, Mathavan 2010).
    cushion: CushionModel,
    /// Cue elevation, radians.
    elevation: f64,
    /// 9-ball: the 9 on the foot spot instead of the 1.
    nine_on_spot: bool,
    /// Random streams a row (seeds `seed`, `seed + 1`, ...), `breaks` each.
    seeds: u64,
    /// Print the sensitivity study (one change at a time from these options).
    study: bool,
    /// Write the study's plot here (SVG).
    svg: Option<String>,
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
        cushion: GAME_CUSHION,
        elevation: 0.0,
        nine_on_spot: false,
        seeds: 1,
        study: false,
        svg: None,
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
            "--study" => {
                o.study = true;
                continue;
            }
            "--nine-on-spot" => {
                o.nine_on_spot = true;
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
                    "ten" | "ten-ball" => vec![Game::TenBall],
                    "eight" | "eight-ball" => vec![Game::EightBall],
                    "both" => vec![Game::NineBall, Game::EightBall],
                    _ => return Err(bad(&"expected nine, ten, eight or both")),
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
            "--cushion" => o.cushion = cushion_by_name(value).map_err(|e| bad(&e))?,
            "--elevation-deg" => {
                let d: f64 = value.parse().map_err(|e| bad(&e))?;
                if !(0.0..=30.0).contains(&d) {
                    return Err(bad(&"expected 0 to 30 degrees"));
                }
                o.elevation = d.to_radians();
            }
            "--seeds" => o.seeds = value.parse().map_err(|e| bad(&e))?,
            "--svg" => o.svg = Some(value.clone()),
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
    let params =
        params_with(o.cushion, o.pairwise, &o.set).expect("--set values in the physical ranges");
    let spec = BreakSpec {
        game: s.game,
        table: s.table,
        gap: s.gap,
        cue: s.cue,
        speed: o.speed,
        aim_sd: s.aim_sd,
        tip_height: o.tip_height,
        elevation: o.elevation,
        nine_on_spot: o.nine_on_spot,
    };
    // One stream a seed for the whole row, as the published tables were made.
    let mut st = BreakStats::default();
    for seed in o.seed..o.seed + o.seeds.max(1) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for _ in 0..o.breaks {
            st.add(&one_break(&spec, &params, &mut rng).expect("a break is played"));
        }
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
            Game::TenBall => "10-ball",
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
    let name = match game {
        Game::NineBall | Game::TenBall => "9ft",
        Game::EightBall | Game::FreePlay => "7ft",
    };
    name.parse().expect("a table name")
}

/// What a change of the study does to the options and the setup.
type Apply = Box<dyn Fn(&mut Options, &mut Setup)>;

/// One change of the study: its group, its label and what it changes.
type Change = (&'static str, String, Apply);

/// The study's changes, each alone from the options given.
fn changes() -> Vec<Change> {
    let mut c: Vec<Change> = vec![("base", "as given".into(), Box::new(|_, _| {}))];
    let set =
        |k: &'static str, v: f64| -> Apply { Box::new(move |o, _| o.set.push((k.into(), v))) };
    for v in [8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0] {
        c.push((
            "cue ball speed",
            format!("{v} ± 0.5 m/s"),
            Box::new(move |o, _| o.speed = (v - 0.5, v + 0.5)),
        ));
    }
    for h in [0.1, -0.1, -0.2, -0.3] {
        c.push((
            "tip height",
            format!("{h:+} R"),
            Box::new(move |o, _| o.tip_height = h),
        ));
    }
    for d in [3.0, 6.0, 10.0] {
        c.push((
            "cue elevation",
            format!("{d}°"),
            Box::new(move |o, _| o.elevation = f64::to_radians(d)),
        ));
    }
    for (k, label, vals) in [
        ("young", "Young's modulus", &[3e9, 9e9][..]),
        ("poisson", "Poisson's ratio", &[0.30, 0.40]),
        (
            "e_ball",
            "ball restitution (and Hertz damping)",
            &[0.92, 0.98],
        ),
        ("mu_ball", "ball–ball friction", &[0.0, 0.03, 0.08]),
        (
            "mu_ball_slip",
            "ball–ball friction, Alciatore's mu(v) x",
            &[1.0],
        ),
        ("mu_slide", "cloth sliding friction", &[0.15, 0.25, 0.3]),
        ("mu_roll", "cloth rolling resistance", &[0.005, 0.015]),
        ("e_cushion", "cushion restitution", &[0.85, 0.9, 0.95]),
        ("mu_cushion", "cushion friction", &[0.1, 0.2]),
        (
            "cushion_height",
            "cushion nose height (of the diameter)",
            &[0.6, 0.65],
        ),
    ] {
        for &v in vals {
            let value = if k == "young" {
                format!("{k} = {} GPa", v / 1e9)
            } else {
                format!("{k} = {v}")
            };
            c.push((label, value, set(k, v)));
        }
    }
    for (name, label) in [
        ("han", "Han 2005, e 0.85, mu 0.2"),
        ("reflect", "reflection, e 0.85"),
    ] {
        c.push((
            "cushion model",
            label.into(),
            Box::new(move |o, _| o.cushion = cushion_by_name(name).expect("a cushion")),
        ));
    }
    for (g, label) in [
        (0.0, "frozen (template)"),
        (0.05e-3, "0.05 mm slack (triangle)"),
        (0.1e-3, "0.1 mm slack"),
    ] {
        c.push(("rack gaps", label.into(), Box::new(move |_, s| s.gap = g)));
    }
    c.push((
        "rack",
        "9 on the spot".into(),
        Box::new(|o, _| o.nine_on_spot = true),
    ));
    for d in [0.125, 0.25] {
        c.push((
            "aim error",
            format!("sd {d}°"),
            Box::new(move |_, s| s.aim_sd = f64::to_radians(d)),
        ));
    }
    c.push((
        "pockets",
        "WPA wide (4.625 in corners)".into(),
        Box::new(|_, s| s.table = "9ft-wide".parse().expect("a table")),
    ));
    c
}

/// A row of the study: group, label, the counts.
struct StudyRow {
    group: &'static str,
    label: String,
    stats: BreakStats,
}

/// Runs the study: 9-ball on the options' table, each change alone.
fn study(o: &Options) -> Vec<StudyRow> {
    println!(
        "| change | value | >= 1 ball (95 %) | balls/break | scratch (95 %) | 9 on the break (95 %) | \
         success |"
    );
    println!("|---|---|---|---|---|---|---|");
    let mut rows = Vec::new();
    for (group, label, f) in changes() {
        let mut oo = o.clone();
        let mut s = Setup {
            game: Game::NineBall,
            table: o.table.unwrap_or(default_table(Game::NineBall)),
            gap: o.gaps.as_ref().map_or(o.rack.gap(), |g| g[0]),
            label: String::new(),
            cue: o.cue,
            aim_sd: o.aim_sd,
        };
        f(&mut oo, &mut s);
        let st = run(&oo, &s);
        let n = st.breaks.max(1) as f64;
        let pct = |k: usize| 100.0 * k as f64 / n;
        let ci = |k: usize| {
            let (lo, hi) = wilson(k, st.breaks);
            format!("{:.1} % ({lo:.1}–{hi:.1})", pct(k))
        };
        let (mean, half) = st.balls_per_break();
        println!(
            "| {group} | {label} | {} | {mean:.2} ± {half:.2} | {} | {} | {:.1} % |",
            ci(st.with_ball),
            ci(st.scratches),
            ci(st.money_ball),
            pct(st.success)
        );
        rows.push(StudyRow {
            group,
            label,
            stats: st,
        });
    }
    rows
}

/// The study as an SVG: each row's rate with its 95 % interval, the base's as a band, the
/// target 66–85 % shaded.
fn study_svg(rows: &[StudyRow], title: &str) -> String {
    let (w, row_h, left, right, top) = (900.0, 16.0, 430.0, 40.0, 50.0);
    let h = top + row_h * rows.len() as f64 + 40.0;
    let (x0, x1) = (20.0, 100.0);
    let x = |p: f64| left + (p - x0) / (x1 - x0) * (w - left - right);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
         font-family=\"sans-serif\" font-size=\"11\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
         <text x=\"{}\" y=\"18\" font-size=\"13\" text-anchor=\"middle\">{title}</text>\n",
        w / 2.0
    );
    let y_end = top + row_h * rows.len() as f64;
    out += &format!(
        "<rect x=\"{:.1}\" y=\"{top}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"#dfd\"/>\n",
        x(66.0),
        x(85.0) - x(66.0),
        y_end - top
    );
    if let Some(base) = rows.first() {
        let (lo, hi) = wilson(base.stats.with_ball, base.stats.breaks);
        out += &format!(
            "<rect x=\"{:.1}\" y=\"{top}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"#ddd\" \
             opacity=\"0.7\"/>\n",
            x(lo),
            x(hi) - x(lo),
            y_end - top
        );
    }
    for p in (20..=100).step_by(10) {
        let px = x(p as f64);
        out += &format!(
            "<line x1=\"{px:.1}\" y1=\"{top}\" x2=\"{px:.1}\" y2=\"{y_end}\" stroke=\"#bbb\" \
             stroke-width=\"0.5\"/>\n<text x=\"{px:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{p} %</text>\n",
            y_end + 14.0
        );
    }
    out += &format!(
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">breaks with a ball (95 % Wilson \
         interval); green: the target 66–85 %; grey: the base's interval</text>\n",
        x(60.0),
        y_end + 30.0
    );
    for (i, r) in rows.iter().enumerate() {
        let y = top + row_h * (i as f64 + 0.5);
        let n = r.stats.breaks.max(1) as f64;
        let p = 100.0 * r.stats.with_ball as f64 / n;
        let (lo, hi) = wilson(r.stats.with_ball, r.stats.breaks);
        out += &format!(
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{}: {}</text>\n\
             <line x1=\"{:.1}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"black\"/>\n\
             <circle cx=\"{:.1}\" cy=\"{y:.1}\" r=\"3\" fill=\"#c00\"/>\n",
            left - 8.0,
            y + 4.0,
            r.group,
            r.label.replace('&', "and"),
            x(lo),
            x(hi),
            x(p)
        );
    }
    out + "</svg>\n"
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
