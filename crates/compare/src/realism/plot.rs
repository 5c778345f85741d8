//! The realism plots, SVG only: `throw.svg`, `cushion.svg`, `squirt.svg` and `swerve.svg`.

use super::cushion::CushionCurve;
use super::data;
use super::swerve::{END_MASSES, HALF_TIP, SWERVE_ELEVATIONS, SWERVE_SPEED, swerve_path};
use super::throw::{Spin, solver_throw, tp_a14_throw};
use billiards_physics::{BallFriction, SpinModel};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::error::Error;
use std::path::Path;

/// Okabe–Ito colours, distinguishable in print and for the common colour blindnesses.
const COLOURS: [RGBColor; 6] = [
    RGBColor(0, 114, 178),
    RGBColor(230, 159, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(213, 94, 0),
    RGBColor(0, 0, 0),
];

/// `c` halfway to white: the thin published curve beside the solver's thick one.
fn lighter(c: RGBColor) -> RGBColor {
    let half = |x: u8| ((u16::from(x) + 255) / 2) as u8;
    RGBColor(half(c.0), half(c.1), half(c.2))
}

/// One curve: its legend, colour, stroke width and points.
struct Curve {
    label: String,
    colour: RGBColor,
    width: u32,
    points: Vec<(f64, f64)>,
}

/// Measured markers: legend, colour, points.
struct Marks {
    label: String,
    colour: RGBColor,
    points: Vec<(f64, f64)>,
}

struct Panel<'a> {
    title: &'a str,
    x: (&'a str, f64, f64),
    y: (&'a str, f64, f64),
    curves: Vec<Curve>,
    marks: Vec<Marks>,
}

fn draw_panel(area: &DrawingArea<SVGBackend, Shift>, p: Panel) -> Result<(), Box<dyn Error>> {
    draw_panel_at(area, p, SeriesLabelPosition::UpperRight)
}

/// [`draw_panel`] with the legend at `legend`.
fn draw_panel_at(
    area: &DrawingArea<SVGBackend, Shift>,
    p: Panel,
    legend: SeriesLabelPosition,
) -> Result<(), Box<dyn Error>> {
    let mut chart = ChartBuilder::on(area)
        .caption(p.title, ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(55)
        .build_cartesian_2d(p.x.1..p.x.2, p.y.1..p.y.2)?;
    chart
        .configure_mesh()
        .x_desc(p.x.0)
        .y_desc(p.y.0)
        .light_line_style(WHITE.mix(0.0))
        .draw()?;
    for c in p.curves {
        let style = ShapeStyle::from(c.colour).stroke_width(c.width);
        chart
            .draw_series(LineSeries::new(c.points, style))?
            .label(c.label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
    }
    for m in p.marks {
        let colour = m.colour;
        chart
            .draw_series(
                m.points
                    .iter()
                    .map(|&(x, y)| Cross::new((x, y), 5, colour.stroke_width(2))),
            )?
            .label(m.label)
            .legend(move |(x, y)| Cross::new((x + 10, y), 5, colour.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 12))
        .position(legend)
        .draw()?;
    Ok(())
}

fn range(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..=n).map(move |k| lo + (hi - lo) * k as f64 / n as f64)
}

fn throw_curve(
    label: String,
    colour: RGBColor,
    width: u32,
    f: impl Fn(f64) -> Result<f64, String>,
) -> Result<Curve, String> {
    let points = range(1.0, 89.0, 88)
        .map(|cut| f(cut).map(|t| (cut, t)))
        .collect::<Result<_, _>>()?;
    Ok(Curve {
        label,
        colour,
        width,
        points,
    })
}

/// Draws `throw.svg`, `cushion.svg`, `squirt.svg` and `swerve.svg` into `out`.
pub fn draw(out: &Path) -> Result<(), Box<dyn Error>> {
    std::fs::create_dir_all(out)?;
    draw_throw(&out.join("throw.svg"))?;
    draw_cushion(&out.join("cushion.svg"))?;
    draw_squirt(&out.join("squirt.svg"))?;
    draw_swerve(&out.join("swerve.svg"))?;
    Ok(())
}

/// The cue ball's path (lateral offset in cm, exaggerated against the distance in m) for
/// each elevation, without squirt and with a standard shaft's; a cross where it starts to
/// roll (the curve ends there: the rest is straight).
fn draw_swerve(path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1400, 550)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((1, 2));
    let shafts = [
        ("no squirt (end_mass None, the default)", None),
        ("standard shaft, 8 g (squirt)", Some(END_MASSES[0].1)),
    ];
    for (area, (name, end_mass)) in panels.iter().zip(shafts) {
        let model = SpinModel {
            end_mass,
            ..SpinModel::default()
        };
        let mut curves = Vec::new();
        let mut marks = Vec::new();
        for (k, &deg) in SWERVE_ELEVATIONS.iter().enumerate() {
            let p = swerve_path(model, deg, HALF_TIP, SWERVE_SPEED)?;
            curves.push(Curve {
                label: format!("elevation {deg:.0} deg"),
                colour: COLOURS[k],
                width: 2,
                points: p
                    .points
                    .iter()
                    .filter(|&&(x, _)| x <= 2.6)
                    .map(|&(x, y)| (x, -y * 100.0))
                    .collect(),
            });
            marks.push(Marks {
                label: format!("starts rolling ({deg:.0} deg)"),
                colour: COLOURS[k],
                points: vec![(p.rolls_at.x, -p.rolls_at.y * 100.0)],
            });
        }
        let title = format!(
            "Swerve: half-tip right english, {} m/s, {name}",
            SWERVE_SPEED
        );
        draw_panel_at(
            area,
            Panel {
                title: &title,
                x: ("distance along the cue line (m)", 0.0, 2.5),
                y: ("to the right of the cue line (cm)", -8.0, 36.0),
                curves,
                marks,
            },
            SeriesLabelPosition::UpperLeft,
        )?;
    }
    root.present()?;
    Ok(())
}

fn draw_squirt(path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (800, 550)).into_drawing_area();
    root.fill(&WHITE)?;
    let ball = billiards_physics::BallSpec::default().mass;
    let curves = END_MASSES
        .iter()
        .enumerate()
        .map(|(k, &(name, m))| Curve {
            label: format!("TP A-31, {name}"),
            colour: COLOURS[k],
            width: 3,
            points: range(0.0, 0.6, 60)
                .map(|b| {
                    (
                        b,
                        billiards_physics::resolve::cue::squirt_angle(b, ball / m).to_degrees(),
                    )
                })
                .collect(),
        })
        .chain([1.0, 3.0].map(|deg| Curve {
            label: format!("issue 24: about 1-3 deg at full english ({deg} deg)"),
            colour: COLOURS[5],
            width: 1,
            points: vec![(0.45, deg), (0.6, deg)],
        }))
        .collect();
    draw_panel(
        &root,
        Panel {
            title: "Squirt against side offset (level cue)",
            x: ("tip offset from centre (ball radii)", 0.0, 0.6),
            y: ("squirt angle (deg)", 0.0, 4.0),
            curves,
            marks: vec![],
        },
    )?;
    root.present()?;
    Ok(())
}

/// The throw figure: throw against cut by speed (stun, rolling), with english, and the friction
/// law beneath them all, so the throw curves can be traced back to the friction that makes them.
fn draw_throw(path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1400, 1000)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((2, 2));
    let constant = SpinModel::default();
    let speed_dep = SpinModel {
        ball_friction: BallFriction::ALCIATORE,
        ..constant
    };
    throw_by_speed_panels(&panels[..2], speed_dep, constant)?;
    throw_english_panel(&panels[2], speed_dep)?;
    friction_panel(&panels[3])?;
    root.present()?;
    Ok(())
}

/// Stun and rolling throw against cut, one curve per measured speed: the speed dependence is
/// what the speed-dependent friction adds over the constant 0.05.
fn throw_by_speed_panels(
    panels: &[DrawingArea<SVGBackend, Shift>],
    speed_dep: SpinModel,
    constant: SpinModel,
) -> Result<(), Box<dyn Error>> {
    for (area, (title, roll)) in panels.iter().zip([
        ("Throw, stun cue ball (TP A-14 Fig. 'stun shot')", 0.0),
        ("Throw, rolling cue ball (TP A-14 Fig. 'natural roll')", 1.0),
    ]) {
        let spin = Spin { roll, english: 0.0 };
        let mut curves = Vec::new();
        for (k, &(name, speed)) in data::ALCIATORE_SPEEDS.iter().enumerate() {
            let colour = COLOURS[k];
            curves.push(throw_curve(
                format!("solver, mu(v) {name}"),
                colour,
                3,
                |cut| solver_throw(speed_dep, speed, cut, spin),
            )?);
            curves.push(throw_curve(
                format!("TP A-14 formula (e 1) {name}"),
                lighter(colour),
                1,
                |cut| Ok(tp_a14_throw(speed, cut, spin)),
            )?);
        }
        curves.push(throw_curve(
            "solver, constant mu 0.05 (today), any speed".into(),
            COLOURS[5],
            2,
            |cut| solver_throw(constant, 1.341, cut, spin),
        )?);
        draw_panel(
            area,
            Panel {
                title,
                x: ("cut angle (deg)", 0.0, 90.0),
                y: ("throw (deg)", 0.0, 7.0),
                curves,
                marks: vec![Marks {
                    label: "Dr. Dave: typical max, ~1 in per ft (Throw XI)".into(),
                    colour: COLOURS[4],
                    points: vec![data::ALCIATORE_MAX_THROW],
                }],
            },
        )?;
    }
    Ok(())
}

/// Throw with inside and outside english at medium speed, rolling, against TP A-14's plots.
fn throw_english_panel(
    area: &DrawingArea<SVGBackend, Shift>,
    speed_dep: SpinModel,
) -> Result<(), Box<dyn Error>> {
    // English: medium speed, rolling and stun, outside/inside 25 and 50 %.
    let mut curves = Vec::new();
    for (k, english) in [-0.5, -0.25, 0.0, 0.25, 0.5].into_iter().enumerate() {
        let spin = Spin { roll: 1.0, english };
        let label = match english {
            e if e < 0.0 => format!("inside {:.0} %", -e * 100.0),
            e if e > 0.0 => format!("outside {:.0} %", e * 100.0),
            _ => "no english".into(),
        };
        curves.push(throw_curve(
            format!("solver, mu(v), {label}"),
            COLOURS[k],
            3,
            |cut| solver_throw(speed_dep, 1.341, cut, spin),
        )?);
        curves.push(throw_curve(
            format!("TP A-14 formula, {label}"),
            lighter(COLOURS[k]),
            1,
            |cut| Ok(tp_a14_throw(1.341, cut, spin)),
        )?);
    }
    draw_panel(
        area,
        Panel {
            title: "Throw with english, rolling, 1.34 m/s (TP A-14 english plots)",
            x: ("cut angle (deg)", 0.0, 90.0),
            y: ("throw (deg)", -6.0, 8.0),
            curves,
            marks: vec![],
        },
    )?;
    Ok(())
}

/// The friction law itself against Marlow's measurements: the cause of the throw curves' shape.
fn friction_panel(area: &DrawingArea<SVGBackend, Shift>) -> Result<(), Box<dyn Error>> {
    let mu = |f: BallFriction| {
        range(0.0, 7.5, 150)
            .map(|v| (v, f.mu(0.05, v)))
            .collect::<Vec<_>>()
    };
    draw_panel(
        area,
        Panel {
            title: "Ball-ball friction against sliding speed",
            x: ("sliding speed at the contact (m/s)", 0.0, 7.5),
            y: ("friction coefficient", 0.0, 0.13),
            curves: vec![
                Curve {
                    label: "a + b exp(-c v), TP A-28 fit".into(),
                    colour: COLOURS[0],
                    width: 3,
                    points: mu(BallFriction::ALCIATORE),
                },
                Curve {
                    label: "constant 0.05 (today's default)".into(),
                    colour: COLOURS[5],
                    width: 2,
                    points: mu(BallFriction::Constant),
                },
            ],
            marks: vec![Marks {
                label: "Marlow 1995, Table 10 (via TP A-28)".into(),
                colour: COLOURS[4],
                points: data::MARLOW_FRICTION.to_vec(),
            }],
        },
    )?;
    Ok(())
}

/// The cushion figure: Fig. 7(a), rebound against incidence, the spin panels and the notes on
/// what was measured, one panel function each.
fn draw_cushion(path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1400, 1500)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((3, 2));
    fig7a_panel(&panels[0])?;
    incidence_panels(&panels[1..3])?;
    cushion_spin_panels(&panels[3..5])?;
    cushion_notes(&panels[5])?;
    root.present()?;
    Ok(())
}

/// Mathavan's Fig. 7(a), the only cushion panel with measured points to judge the models by.
fn fig7a_panel(area: &DrawingArea<SVGBackend, Shift>) -> Result<(), Box<dyn Error>> {
    // (a) Mathavan's Fig. 7(a): rolling, square, rebound against incident speed.
    let curves = CushionCurve::ALL
        .iter()
        .enumerate()
        .map(|(k, &m)| Curve {
            label: m.name().into(),
            colour: COLOURS[k],
            width: 2,
            points: range(0.0, 3.5, 35)
                .map(|v| (v, m.rebound(v.max(1e-6), 90.0, 1.0, 0.0).0))
                .collect(),
        })
        .collect();
    draw_panel(
        area,
        Panel {
            title: "Rolling ball, square: Mathavan 2010 Fig. 7(a)",
            x: ("incident speed (m/s)", 0.0, 3.5),
            y: ("rebound speed (m/s)", 0.0, 3.5),
            curves,
            marks: vec![Marks {
                label: "measured (high-speed camera), Fig. 7(a)".into(),
                colour: COLOURS[4],
                points: data::MATHAVAN_FIG7A.to_vec(),
            }],
        },
    )?;
    Ok(())
}

/// Rebound angle and speed against incidence, rolling at 1 m/s: where the models part.
fn incidence_panels(panels: &[DrawingArea<SVGBackend, Shift>]) -> Result<(), Box<dyn Error>> {
    // (b, c) Angle and speed against incidence, rolling at 1 m/s.
    for (area, (title, ylabel, pick, ymax)) in panels.iter().zip([
        (
            "Rebound angle, rolling at 1 m/s",
            "rebound angle from the cushion (deg)",
            1,
            100.0,
        ),
        (
            "Rebound speed, rolling at 1 m/s",
            "rebound speed (m/s)",
            0,
            1.1,
        ),
    ]) {
        let curves = CushionCurve::ALL
            .iter()
            .enumerate()
            .map(|(k, &m)| Curve {
                label: m.name().into(),
                colour: COLOURS[k],
                width: 2,
                points: range(2.0, 90.0, 88)
                    .map(|a| {
                        let r = m.rebound(1.0, a, 1.0, 0.0);
                        (a, if pick == 1 { r.1 } else { r.0 })
                    })
                    .collect(),
            })
            .collect();
        draw_panel(
            area,
            Panel {
                title,
                x: ("incidence angle from the cushion (deg)", 0.0, 90.0),
                y: (ylabel, 0.0, ymax),
                curves,
                marks: vec![],
            },
        )?;
    }
    Ok(())
}

/// Rebound angle with topspin and with side spin, Han (thin) against Mathavan (thick).
fn cushion_spin_panels(panels: &[DrawingArea<SVGBackend, Shift>]) -> Result<(), Box<dyn Error>> {
    // (d) Topspin and (e) side spin: Han (thin) and Mathavan (thick), 1 m/s.
    let spins: [(&str, &[(f64, f64)]); 2] = [
        (
            "Rebound angle vs topspin (k x roll), 1 m/s",
            &[(-1.0, 0.0), (0.0, 0.0), (1.0, 0.0), (2.0, 0.0)],
        ),
        (
            "Rebound angle vs side spin (k v/R; k > 0 running), rolling, 1 m/s",
            &[(1.0, -1.0), (1.0, 0.0), (1.0, 1.0)],
        ),
    ];
    for (area, (title, cases)) in panels.iter().zip(spins) {
        let mut curves = Vec::new();
        for (k, &(top, side)) in cases.iter().enumerate() {
            let tag = if title.contains("topspin") {
                format!("k = {top}")
            } else {
                format!("k = {side}")
            };
            for (m, width) in [(CushionCurve::Han2005, 1), (CushionCurve::Mathavan2010, 3)] {
                curves.push(Curve {
                    label: format!("{} {tag}", if width == 1 { "Han" } else { "Mathavan" }),
                    colour: COLOURS[k],
                    width,
                    points: range(2.0, 90.0, 88)
                        .map(|a| (a, m.rebound(1.0, a, top, side).1))
                        .collect(),
                });
            }
        }
        draw_panel(
            area,
            Panel {
                title,
                x: ("incidence angle from the cushion (deg)", 0.0, 90.0),
                y: ("rebound angle from the cushion (deg)", 0.0, 180.0),
                curves,
                marks: vec![],
            },
        )?;
    }
    Ok(())
}

/// What the cushion panels rest on (ball, cushion, validity), written on the figure itself so it
/// travels with the SVG.
fn cushion_notes(area: &DrawingArea<SVGBackend, Shift>) -> Result<(), Box<dyn Error>> {
    let notes = [
        "All panels: the paper's snooker ball (R 26.25 mm) and cushion (nose at 7R/5).",
        "Measured data exist for panel 1 only (Mathavan 2010 Fig. 7(a), p. 1870);",
        "the rigid-cushion model is valid below 2.5 m/s (the paper's abstract).",
        "Han and reflection use the solver's e = 0.85; Mathavan its fitted 0.98 / 0.14.",
        "Angles from the cushion line: 90 deg is square; > 90 deg: back along the rail.",
        "Regenerate: cargo run --release -p billiards-compare -- realism --out docs/realism",
    ];
    let style = ("sans-serif", 16).into_font();
    for (k, line) in notes.iter().enumerate() {
        area.draw(&Text::new(*line, (20, 40 + 28 * k as i32), style.clone()))?;
    }
    Ok(())
}
