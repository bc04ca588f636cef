//! The seed thesis's figures as `gaitlab figures` draws them: a figure is a title over panels
//! of lines (with an optional grey band and a shaded span), described as plain data by
//! `report::figures` and drawn here the report's way (size, font, legend placement).

use super::common::{FONT, LEGEND_FONT_PX, Res, draw_legend, err, legend_corner, titled, y_range};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::ops::Range;

/// A line of a panel.
#[derive(Clone, Debug)]
pub(crate) struct Line {
    /// Legend entry.
    pub(crate) name: String,
    /// Colour (r, g, b).
    pub(crate) rgb: (u8, u8, u8),
    /// Stroke width (px).
    pub(crate) width: u32,
    /// Points, x then y.
    pub(crate) points: Vec<(f64, f64)>,
}

/// A band drawn behind the lines: a closed polygon (lower edge, then upper edge back).
#[derive(Clone, Debug)]
pub(crate) struct Band {
    /// Legend entry.
    pub(crate) name: String,
    /// The polygon.
    pub(crate) polygon: Vec<(f64, f64)>,
}

/// One chart.
#[derive(Clone, Debug)]
pub(crate) struct Panel {
    /// Caption over the chart.
    pub(crate) title: String,
    /// x axis label, with its unit.
    pub(crate) x_desc: String,
    /// y axis label, with its unit.
    pub(crate) y_desc: String,
    /// x range.
    pub(crate) x: Range<f64>,
    /// Lines, drawn in order.
    pub(crate) lines: Vec<Line>,
    /// Grey band behind them.
    pub(crate) band: Option<Band>,
    /// A shaded x span (from, to) with its label at the top.
    pub(crate) span: Option<(f64, f64, String)>,
    /// Events: a thin vertical line at each x with its label beside it, the labels stepped
    /// down in four rows so that close events do not print over each other.
    pub(crate) marks: Vec<(f64, String)>,
}

/// A figure: title (naming the thesis figure) and panels, stacked in `rows` rows.
#[derive(Clone, Debug)]
pub(crate) struct Figure {
    /// Title over the panels.
    pub(crate) title: String,
    /// Rows of panels (columns follow from the count).
    pub(crate) rows: usize,
    /// The panels.
    pub(crate) panels: Vec<Panel>,
}

/// The share of a chart's height, at its top, that the marks' four label rows take.
const MARK_ROWS_SHARE: f64 = 0.24;

/// The band's colour: grey, as the report draws measured adults.
const BAND: RGBColor = RGBColor(120, 120, 120);

fn panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, p: &Panel) -> Res {
    let mut all: Vec<&[(f64, f64)]> = p.lines.iter().map(|l| l.points.as_slice()).collect();
    if let Some(b) = &p.band {
        all.push(&b.polygon);
    }
    // At least one unit tall: a flat line (terrain of no amplitude) would otherwise get
    // a thousandth of a unit and tick labels too long for the axis.
    let y = match y_range(&all) {
        y if y.end - y.start < 1.0 => (0.5 * (y.start + y.end) - 0.5)..(0.5 * (y.start + y.end) + 0.5),
        y => y,
    };
    // The marks' labels step down over the top quarter of the chart: that quarter is kept
    // free of data, or a label printed over a line where an event fell mid-ramp.
    let y = if p.marks.is_empty() { y } else { y.start..y.start + (y.end - y.start) / (1.0 - MARK_ROWS_SHARE) };
    let span = p.x.end - p.x.start;
    let mut chart = ChartBuilder::on(area)
        .caption(&p.title, (FONT, 28))
        .margin(12)
        .margin_right(28)
        .x_label_area_size(55)
        .y_label_area_size(80)
        .build_cartesian_2d(p.x.clone(), y.clone())
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc(p.x_desc.as_str())
        .y_desc(p.y_desc.as_str())
        .x_labels(11)
        .x_label_formatter(&|x| if span >= 10.0 { format!("{x:.0}") } else { format!("{x:.1}") })
        .label_style((FONT, 20))
        .axis_desc_style((FONT, 22))
        .draw()
        .map_err(err)?;
    if let Some((from, to, label)) = &p.span {
        let shade = RGBColor(250, 225, 150).mix(0.35);
        chart
            .draw_series(std::iter::once(Rectangle::new([(*from, y.start), (*to, y.end)], shade.filled())))
            .map_err(err)?;
        let at = (*from + 0.01 * (p.x.end - p.x.start), y.start + 0.04 * (y.end - y.start));
        chart.draw_series(std::iter::once(Text::new(label.clone(), at, (FONT, 20)))).map_err(err)?;
    }
    let mark_ink = marks(&mut chart, &p.marks, &y, span)?;
    if let Some(b) = &p.band {
        chart
            .draw_series(std::iter::once(Polygon::new(b.polygon.clone(), BAND.mix(0.25))))
            .map_err(err)?
            .label(b.name.as_str())
            .legend(|(x, y)| Rectangle::new([(x, y - 6), (x + 24, y + 6)], BAND.mix(0.4).filled()));
    }
    for l in &p.lines {
        let color = RGBColor(l.rgb.0, l.rgb.1, l.rgb.2);
        let width = l.width;
        chart
            .draw_series(LineSeries::new(l.points.clone(), color.stroke_width(width)))
            .map_err(err)?
            .label(l.name.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(width)));
    }
    let mut labels: Vec<&str> = p.lines.iter().map(|l| l.name.as_str()).collect();
    if let Some(b) = &p.band {
        labels.push(&b.name);
    }
    // The marks' labels count as ink the legend must leave free.
    all.extend(mark_ink.iter().map(<[(f64, f64); 2]>::as_slice));
    let corner = legend_corner(chart.plotting_area().dim_in_pixel(), p.x.clone(), y, &labels, &all);
    draw_legend(&mut chart, LEGEND_FONT_PX, Some(corner))
}

/// Draws each mark (a thin vertical line, its label beside its top, stepped down in four
/// rows) and returns where the labels are, as two-point series for the legend to avoid.
fn marks<DB: DrawingBackend>(
    chart: &mut ChartContext<
        '_,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    marks: &[(f64, String)],
    y: &Range<f64>,
    span: f64,
) -> Result<Vec<[(f64, f64); 2]>, String> {
    let grey = RGBColor(90, 90, 90);
    let mut ink = Vec::new();
    for (i, (x, label)) in marks.iter().enumerate() {
        chart.draw_series(LineSeries::new([(*x, y.start), (*x, y.end)], grey.stroke_width(1))).map_err(err)?;
        let at = (*x + 0.004 * span, y.end - (0.02 + 0.05 * (i % 4) as f64) * (y.end - y.start));
        chart.draw_series(std::iter::once(Text::new(label.clone(), at, (FONT, 18)))).map_err(err)?;
        ink.push([at, (at.0 + 0.12 * span, at.1)]);
    }
    Ok(ink)
}

fn figure<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, f: &Figure) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = titled(&root, &f.title, 32)?;
    let rows = f.rows.max(1);
    let columns = f.panels.len().div_ceil(rows).max(1);
    for (area, p) in root.split_evenly((rows, columns)).iter().zip(&f.panels) {
        panel(area, p)?;
    }
    root.present().map_err(err)
}

/// Writes `figure` as `dir/stem.png` and `dir/stem.svg` ([`super::SIZE`]).
pub(crate) fn write_figure(dir: &std::path::Path, stem: &str, f: &Figure) -> Res {
    super::register_font();
    let png = dir.join(format!("{stem}.png"));
    let svg = dir.join(format!("{stem}.svg"));
    figure(BitMapBackend::new(&png, super::SIZE).into_drawing_area(), f)?;
    figure(SVGBackend::new(&svg, super::SIZE).into_drawing_area(), f)
}
