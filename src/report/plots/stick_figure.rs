//! The stick figure as a chronophotograph: one steady gait cycle at evenly spaced
//! instants, each figure in its own slot on the ground under it, with the % of the cycle
//! and the gait events beneath; the side view above, the frontal view below, both at the
//! same metres per pixel on either axis so that the figures keep their proportions.

use super::chrono::{self, FIGURES, Figure, HEAD_M, Part, Row, View};
use super::common::{DESIGN, FONT, LEFT, RIGHT, Res, SIZE, err, titled};
use super::data::Data;
use crate::model::body::Side;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Chart margin, y label area and x label area (px): fixed, so that the plotting area's
/// size is known before the chart is built and both axes can be given one scale.
const MARGIN: u32 = 12;
const Y_LABELS: u32 = 70;
const X_LABELS: u32 = 50;
/// Room (px) above the highest head.
const TOP_PX: f64 = 12.0;
/// Label text size (px) and the line spacing of the labels under a figure.
const LABEL_FONT: u32 = 18;
const LINE_PX: f64 = 22.0;
/// The ground's colour.
const GROUND: RGBColor = RGBColor(60, 140, 60);

/// Both views over the middle steady cycle (on stairs or a slope, on the climb rather than
/// before it).
pub(super) fn stick_figure<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let Some(instants) = chrono::instants(d) else { return root.present().map_err(err) };
    let (top, bottom) = root.split_vertically(SIZE.1 / 2);
    let captions = [
        format!("Side view: one gait cycle in {FIGURES} figures (right limbs red, left blue)"),
        "Frontal view, seen from in front (the right side on the page's left)".to_string(),
    ];
    let panels = [titled(&top, &captions[0], 26)?, titled(&bottom, &captions[1], 26)?];
    let views = [View::Side, View::Front];
    let mut rows = views.map(|v| chrono::row(d, &instants, v));
    let lines = 1 + instants.iter().map(|i| i.events.len()).max().unwrap_or(0);
    let label_px = 8.0 + LINE_PX * lines as f64;
    // One scale for both views, the largest at which each row fits its panel across and up.
    let scale = rows
        .iter()
        .zip(&panels)
        .map(|(row, panel)| {
            let (w, h) = plot_px(panel);
            (w / row.width).min((h - label_px - TOP_PX) / (row.high - row.low))
        })
        .fold(f64::INFINITY, f64::min);
    for ((row, panel), view) in rows.iter_mut().zip(&panels).zip(views) {
        let (w, h) = plot_px(panel);
        // The row centred across its panel, the panel's x starting at 0.
        row.shift(0.5 * (w / scale - row.width));
        let y0 = row.low - label_px / scale;
        draw_row(panel, row, view, &instants, (0.0..w / scale, y0..y0 + h / scale), scale)?;
    }
    root.present().map_err(err)
}

/// The plotting area (px) a chart on `panel` gets: the panel less the margins and the
/// label areas.
fn plot_px<DB: DrawingBackend>(panel: &DrawingArea<DB, Shift>) -> (f64, f64) {
    let (w, h) = panel.dim_in_pixel();
    (f64::from(w - 2 * MARGIN - Y_LABELS), f64::from(h - 2 * MARGIN - X_LABELS))
}

/// One view's chart: axes, then per figure its ground, body, head and labels.
fn draw_row<DB: DrawingBackend>(
    panel: &DrawingArea<DB, Shift>,
    row: &Row,
    view: View,
    instants: &[chrono::Instant],
    (x, y): (std::ops::Range<f64>, std::ops::Range<f64>),
    scale: f64,
) -> Res {
    let mut chart = ChartBuilder::on(panel)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .build_cartesian_2d(x, y)
        .map_err(err)?;
    let across = match view {
        View::Side => "forward x (m), each figure moved into its own slot",
        View::Front => "lateral -z (m), each figure moved into its own slot",
    };
    chart
        .configure_mesh()
        .disable_x_mesh()
        .x_desc(across)
        .y_desc("height y (m)")
        .label_style((FONT, 18))
        .axis_desc_style((FONT, 20))
        .draw()
        .map_err(err)?;
    for (f, i) in row.figures.iter().zip(instants) {
        chart.draw_series(std::iter::once(PathElement::new(f.ground.clone(), GROUND.stroke_width(3)))).map_err(err)?;
        chart.draw_series(body(f)).map_err(err)?;
        let radius = (HEAD_M * scale).round() as i32;
        chart.draw_series(std::iter::once(Circle::new(f.head, radius, DESIGN.stroke_width(2)))).map_err(err)?;
        chart.draw_series(labels(f, i, scale)).map_err(err)?;
    }
    Ok(())
}

/// A figure's segments in their colours: the trunk black, limbs red (right) and blue
/// (left), the arms fainter than the legs.
fn body(f: &Figure) -> Vec<PathElement<(f64, f64)>> {
    let colour = |side: Side| if side == Side::Right { RIGHT } else { LEFT };
    f.segments
        .iter()
        .map(|&(a, b, part)| {
            let c = match part {
                Part::Trunk => DESIGN.mix(1.0),
                Part::Leg(side) => colour(side).mix(1.0),
                Part::Arm(side) => colour(side).mix(0.6),
            };
            PathElement::new(vec![a, b], c.stroke_width(2))
        })
        .collect()
}

/// The labels under a figure, hung from the lowest ground of its slot: its % of the cycle,
/// then each event it is the nearest instant to, in the colour of the event's leg.
fn labels(f: &Figure, i: &chrono::Instant, scale: f64) -> Vec<Text<'static, (f64, f64), String>> {
    let below = |line: usize| (f.centre, f.lowest_ground() - (8.0 + LINE_PX * line as f64) / scale);
    let style =
        |c: &'static RGBColor| TextStyle::from((FONT, LABEL_FONT)).color(c).pos(Pos::new(HPos::Center, VPos::Top));
    let mut out = vec![Text::new(format!("{:.0} %", i.pct), below(0), style(&DESIGN))];
    for (k, name) in i.events.iter().enumerate() {
        let c = if name.starts_with('R') { &RIGHT } else { &LEFT };
        out.push(Text::new((*name).to_string(), below(k + 1), style(c)));
    }
    out
}
