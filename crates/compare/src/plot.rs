//! The log-log plot of run time against error, one panel per scene, one curve per solver.

use crate::bench::{Report, Solver};
use plotters::prelude::*;
use std::error::Error;
use std::path::Path;

/// Errors below this are drawn at it (the exact solver's can be exactly zero), metres.
pub const ERROR_FLOOR: f64 = 1e-17;

/// Errors above this are drawn at it (a solver that lost a ball entirely), metres.
const ERROR_CEILING: f64 = 10.0;

/// How to read the plot, drawn in the spare panel.
const NOTES: [&str; 9] = [
    "Each point: one solver configuration; run time is the median of repeated runs.",
    "Error: largest distance of any ball from the exact solution at any sample",
    "time (every 0.1 s) up to the horizon. The exact solver is measured against",
    "the closed form (stop, cut) or by its own rounding uncertainty (chaotic scenes).",
    "Errors of exactly zero are drawn at 1e-17 m (paper-linear = exact without friction).",
    "Chaotic scenes (billiard, breaks): horizon = last time the exact solution is",
    "known to 1e-10 m; an early millimetre grows to metres there, so errors saturate.",
    "euler-swept moves balls in straight lines between contacts inside a step: without",
    "friction that is exact, which is why it matches the exact solver there.",
];

/// Colours per solver, in [`Solver::ALL`] order: distinguishable in print and for the common
/// forms of colour blindness (Okabe–Ito).
const COLOURS: [RGBColor; 5] = [
    RGBColor(0, 0, 0),
    RGBColor(230, 159, 0),
    RGBColor(0, 114, 178),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
];

/// Draws the plot as an SVG file (no system font or image library is needed).
pub fn draw(report: &Report, path: &Path) -> Result<(), Box<dyn Error>> {
    let rows = report.scenes.len().div_ceil(2);
    let root = SVGBackend::new(path, (1400, 500 * rows as u32)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((rows, 2));
    for (area, scene) in panels.iter().zip(&report.scenes) {
        let rows: Vec<_> = report
            .rows
            .iter()
            .filter(|r| r.scene == scene.name)
            .collect();
        let times = rows.iter().map(|r| r.runtime.max(1e-9));
        let lo = times.clone().fold(f64::INFINITY, f64::min) / 3.0;
        let hi = times.fold(0.0, f64::max) * 3.0;
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!(
                    "{}: {:.1} s simulated, {} ball{}",
                    scene.name,
                    scene.horizon,
                    scene.balls,
                    if scene.balls == 1 { "" } else { "s" }
                ),
                ("sans-serif", 20),
            )
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(
                (ERROR_FLOOR..ERROR_CEILING).log_scale(),
                (lo..hi).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc("largest position error (m)")
            .y_desc("run time (s, median)")
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()?;
        for (solver, colour) in Solver::ALL.iter().zip(COLOURS) {
            let mut points: Vec<(f64, f64, String)> = rows
                .iter()
                .filter(|r| r.solver == *solver)
                .map(|r| {
                    let e = r.errors.position;
                    let e = if e.is_finite() { e } else { ERROR_CEILING };
                    (
                        e.clamp(ERROR_FLOOR, ERROR_CEILING),
                        r.runtime,
                        r.parameter.clone(),
                    )
                })
                .collect();
            if points.is_empty() {
                continue;
            }
            // Along the curve from the cheapest configuration to the dearest.
            points.sort_by(|a, b| a.1.total_cmp(&b.1));
            let style = ShapeStyle::from(colour).stroke_width(2);
            chart
                .draw_series(LineSeries::new(points.iter().map(|p| (p.0, p.1)), style))?
                .label(solver.name())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
            chart.draw_series(
                points
                    .iter()
                    .map(|p| Circle::new((p.0, p.1), 4, colour.filled())),
            )?;
            // Label the time steps on the discrete curve, so the sweep can be read off.
            if *solver == Solver::EulerDiscrete {
                chart.draw_series(points.iter().map(|p| {
                    // Offset right of the marker so the marker does not hide the label.
                    EmptyElement::at((p.0, p.1))
                        + Text::new(
                            p.2.trim_start_matches("dt ").to_string(),
                            (7, -4),
                            ("sans-serif", 12).into_font().color(&colour),
                        )
                }))?;
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperLeft)
            .draw()?;
    }
    // A spare panel (odd number of scenes) holds the notes needed to read the others.
    if let Some(area) = panels.get(report.scenes.len()) {
        let style = ("sans-serif", 16).into_font();
        for (k, line) in NOTES.iter().enumerate() {
            area.draw(&Text::new(*line, (30, 40 + 26 * k as i32), style.clone()))?;
        }
    }
    root.present()?;
    Ok(())
}
