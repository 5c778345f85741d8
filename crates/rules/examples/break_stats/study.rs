//! The break study (`--study`): 9-ball, one change at a time from the options, and its plot.

use crate::options::Options;
use crate::rows::{Setup, default_table, run};
use billiards_rules::Game;
use billiards_rules::breaks::{BreakStats, cushion_by_name, wilson};

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
pub struct StudyRow {
    group: &'static str,
    label: String,
    stats: BreakStats,
}

/// Runs the study: 9-ball on the options' table, each change alone.
pub fn study(o: &Options) -> Vec<StudyRow> {
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
pub fn study_svg(rows: &[StudyRow], title: &str) -> String {
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
