//! The IK plot: each solver's ankle error and iterations on the walk's own targets.

use super::common::{FONT, PALETTE, Res, SIZE, draw_legend, err, titled};
use crate::analysis::ik::{IkSample, IkTarget, SolverRun};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Per frame, the worse of the two legs' values.
fn per_frame(targets: &[IkTarget], run: &SolverRun, value: impl Fn(&IkSample) -> f64) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for (t, x) in targets.iter().zip(&run.samples) {
        let v = value(x);
        match out.last_mut() {
            Some(last) if last.0 == t.time_s => last.1 = last.1.max(v),
            _ => out.push((t.time_s, v)),
        }
    }
    out
}

/// Each solver's error (top) and iterations (bottom, log scale) per frame.
pub(super) fn ik<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, targets: &[IkTarget], runs: &[SolverRun]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = titled(&root, "Leg IK on the walk's targets (worse leg per frame)", 34)?;
    let (top, bottom) = root.split_vertically((SIZE.1 - 50) / 2);
    let t_end = targets.last().map_or(1.0, |t| t.time_s).max(1e-3);
    let errors: Vec<Vec<(f64, f64)>> =
        runs.iter().map(|r| per_frame(targets, r, |x| x.answer.position_error * 1e3)).collect();
    let iterations: Vec<Vec<(f64, f64)>> =
        runs.iter().map(|r| per_frame(targets, r, |x| f64::from(x.answer.iterations.max(1)))).collect();
    // Headroom above the data for the legend.
    let worst_error = errors.iter().flatten().map(|p| p.1).fold(0.0, f64::max);
    let error_max = worst_error.max(1e-3) * 1.5;
    // As many decimals as make the ticks (about five over the axis) distinct.
    let decimals = (-(error_max / 5.0).log10()).ceil().max(0.0) as usize;
    // An exact solver draws a flat line at zero: say so in words, where a reader looks.
    let error_caption = if worst_error < 1e-6 {
        "ankle position error: exact (every solve within 1 nm)".to_string()
    } else {
        "ankle position error".to_string()
    };
    let iteration_max = iterations.iter().flatten().map(|p| p.1).fold(1.0, f64::max) * 8.0;
    for (area, caption, y_desc, series, log) in [
        (&top, error_caption.as_str(), "error (mm)", &errors, false),
        (&bottom, "iterations per solve", "iterations (log scale)", &iterations, true),
    ] {
        let mut builder = ChartBuilder::on(area);
        builder.caption(caption, (FONT, 28)).margin(12).x_label_area_size(50).y_label_area_size(90);
        macro_rules! draw {
            ($chart:expr) => {{
                let mut chart = $chart;
                chart
                    .configure_mesh()
                    .x_desc("time (s)")
                    .y_desc(y_desc)
                    .y_label_formatter(&|v| if log { format!("{v:.0}") } else { format!("{v:.decimals$}") })
                    .label_style((FONT, 18))
                    .axis_desc_style((FONT, 20))
                    .draw()
                    .map_err(err)?;
                for (i, (run, points)) in runs.iter().zip(series.iter()).enumerate() {
                    let colour = PALETTE[i % PALETTE.len()];
                    chart
                        .draw_series(LineSeries::new(points.iter().copied(), colour.stroke_width(2)))
                        .map_err(err)?
                        .label(run.solver.name())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(3)));
                }
                draw_legend(&mut chart, 18, Some(SeriesLabelPosition::UpperRight))?;
            }};
        }
        if log {
            draw!(builder.build_cartesian_2d(0f64..t_end, (1f64..iteration_max).log_scale()).map_err(err)?);
        } else {
            draw!(builder.build_cartesian_2d(0f64..t_end, 0f64..error_max).map_err(err)?);
        }
    }
    root.present().map_err(err)
}
