//! The plot of the solver's cost per event against the number of balls (issue 37), from the
//! table `billiards-physics`'s `scaling` example writes with `--csv`: this build and, where
//! measured, another build (`--against`), beside the bar of three times the 16-ball cost.

use plotters::prelude::*;
use std::error::Error;
use std::path::Path;

/// One line of the table: balls, ns per event, and the other build's ns per event if measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// Number of balls.
    pub balls: usize,
    /// Nanoseconds per event, this build.
    pub ns: f64,
    /// Nanoseconds per event, the other build.
    pub other: Option<f64>,
}

/// Reads the table (`balls,ns_per_event,other_ns_per_event` and a header); an error names the
/// line that is wrong.
pub fn parse(text: &str) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    for (k, line) in text.lines().enumerate().skip(1) {
        if line.trim().is_empty() {
            continue;
        }
        let bad = || format!("line {}: expected balls,ns,[other ns], got {line:?}", k + 1);
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let (Some(b), Some(ns)) = (f.first(), f.get(1)) else {
            return Err(bad());
        };
        let balls: usize = b.parse().map_err(|_| bad())?;
        let ns: f64 = ns.parse().map_err(|_| bad())?;
        let other = match f.get(2) {
            None | Some(&"") => None,
            Some(s) => Some(s.parse::<f64>().map_err(|_| bad())?),
        };
        let positive = |x: f64| x.is_finite() && x > 0.0;
        if balls == 0 || !positive(ns) || other.is_some_and(|o| !positive(o)) {
            return Err(bad());
        }
        rows.push(Row { balls, ns, other });
    }
    if rows.is_empty() {
        return Err("no rows".to_owned());
    }
    Ok(rows)
}

/// Draws the plot as an SVG file; `other` names the other build in the legend.
pub fn draw(rows: &[Row], other: &str, path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let xs = rows.iter().map(|r| r.balls as f64);
    let (x0, x1) = (
        xs.clone().fold(f64::INFINITY, f64::min) / 1.5,
        xs.fold(0.0, f64::max) * 1.5,
    );
    let ys = rows
        .iter()
        .flat_map(|r| std::iter::once(r.ns).chain(r.other))
        .collect::<Vec<_>>();
    let y0 = ys.iter().copied().fold(f64::INFINITY, f64::min) / 2.0;
    let y1 = ys.iter().copied().fold(0.0, f64::max) * 2.0;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Solver cost per event, frictionless gas at constant density",
            ("sans-serif", 22),
        )
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("balls")
        .y_desc("ns per event")
        .draw()?;
    let blue = RGBColor(0, 114, 178);
    let orange = RGBColor(230, 159, 0);
    let mine: Vec<(f64, f64)> = rows.iter().map(|r| (r.balls as f64, r.ns)).collect();
    chart
        .draw_series(LineSeries::new(mine.clone(), blue.stroke_width(2)))?
        .label("this build")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], blue.stroke_width(2)));
    chart.draw_series(mine.iter().map(|&p| Circle::new(p, 4, blue.filled())))?;
    let theirs: Vec<(f64, f64)> = rows
        .iter()
        .filter_map(|r| r.other.map(|o| (r.balls as f64, o)))
        .collect();
    if !theirs.is_empty() {
        chart
            .draw_series(LineSeries::new(theirs.clone(), orange.stroke_width(2)))?
            .label(other.to_owned())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], orange.stroke_width(2)));
        chart.draw_series(theirs.iter().map(|&p| Circle::new(p, 4, orange.filled())))?;
    }
    let bar = 3.0 * rows[0].ns;
    chart
        .draw_series(LineSeries::new(
            [(x0, bar), (x1, bar)],
            BLACK.mix(0.5).stroke_width(1),
        ))?
        .label(format!("3x this build's {}-ball cost", rows[0].balls))
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK.mix(0.5)));
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperLeft)
        .draw()?;
    root.present()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_reads_back_and_bad_lines_are_named() {
        let rows = parse("balls,ns,other\n16,400.5,600\n100,1500,\n").unwrap();
        assert_eq!(
            rows,
            vec![
                Row {
                    balls: 16,
                    ns: 400.5,
                    other: Some(600.0)
                },
                Row {
                    balls: 100,
                    ns: 1500.0,
                    other: None
                }
            ]
        );
        for bad in [
            "h\n16,abc\n",
            "h\n0,10\n",
            "h\n16,-1\n",
            "h\n16,NaN\n",
            "h\n16\n",
            "h\n",
        ] {
            let e = parse(bad).unwrap_err();
            assert!(e.contains("line 2") || e == "no rows", "{bad:?}: {e}");
        }
    }

    #[test]
    fn the_plot_is_written() {
        let rows = parse("balls,ns,other\n16,400,600\n1000,2000,5000\n").unwrap();
        let path = std::env::temp_dir().join(format!("scaling-{}.svg", std::process::id()));
        draw(&rows, "c339665", &path).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        std::fs::remove_file(&path).ok();
        assert!(svg.contains("this build") && svg.contains("c339665"));
    }
}
