//! One walk's mean joint curves against a stored version of them (`gaitlab snapshot
//! --plot`): each curve in its panel, the stored one dark, this walk's red, and the figures
//! that moved listed beside the panels.

use super::common::{DESIGN, FONT, RIGHT, Res, draw_legend, err, titled, y_range};
use plotters::coord::Shift;
use plotters::prelude::*;

/// A curve over % of the cycle: its name, the stored values and this walk's, evenly spaced
/// from 0 to 100 %.
pub(crate) type Overlay<'a> = (&'a str, &'a [f64], &'a [f64]);

/// Points spread evenly over 0..100 %.
fn over_cycle(values: &[f64]) -> Vec<(f64, f64)> {
    let last = values.len().saturating_sub(1).max(1) as f64;
    values.iter().enumerate().map(|(i, &y)| (100.0 * i as f64 / last, y)).collect()
}

/// One panel: the stored curve and this walk's.
fn panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, (name, old, new): Overlay<'_>) -> Res {
    let (old, new) = (over_cycle(old), over_cycle(new));
    let y = y_range(&[&old, &new]);
    let mut chart = ChartBuilder::on(area)
        .caption(name, (FONT, 24))
        .margin(8)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0f64..100f64, y)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("% of right gait cycle")
        .x_labels(6)
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_desc("deg")
        .label_style((FONT, 16))
        .axis_desc_style((FONT, 17))
        .draw()
        .map_err(err)?;
    let stored = DESIGN.mix(0.7);
    chart
        .draw_series(LineSeries::new(old, stored.stroke_width(4)))
        .map_err(err)?
        .label("snapshot")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], stored.stroke_width(4)));
    chart
        .draw_series(LineSeries::new(new, RIGHT.stroke_width(2)))
        .map_err(err)?
        .label("this walk")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RIGHT.stroke_width(2)));
    draw_legend(&mut chart, 15, Some(SeriesLabelPosition::UpperRight))
}

/// Draws `title`, the curves in a grid of three columns, and `notes` (the moved figures, one
/// a line; as many as fit) in a column at the right.
pub(super) fn overlay<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    curves: &[Overlay<'_>],
    notes: &[String],
) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = titled(&root, title, 30)?;
    let (width, height) = root.dim_in_pixel();
    let (grid, side) = root.split_horizontally(width * 7 / 10);
    let rows = curves.len().div_ceil(3).max(1);
    for (area, curve) in grid.split_evenly((rows, 3)).iter().zip(curves) {
        panel(area, *curve)?;
    }
    side.draw(&Text::new("Moved (snapshot -> this walk):", (8, 20), (FONT, 20))).map_err(err)?;
    let fit = (height.saturating_sub(60) / 22) as usize;
    for (i, note) in notes.iter().take(fit).enumerate() {
        let y = 50 + 22 * i as i32;
        side.draw(&Text::new(note.clone(), (8, y), (FONT, 15))).map_err(err)?;
    }
    if notes.len() > fit {
        let more = format!("... and {} more", notes.len() - fit);
        side.draw(&Text::new(more, (8, 50 + 22 * fit as i32), (FONT, 15))).map_err(err)?;
    }
    root.present().map_err(err)
}
