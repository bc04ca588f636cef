//! What every plot shares: its size, the font, the colours, the error type, and the y range
//! that fits a set of series.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Pixel size of every PNG (and the SVG's nominal size).
pub const SIZE: (u32, u32) = (1600, 1000);

/// The embedded font's family name (registered by [`super::write_plots`]).
pub(super) const FONT: &str = "sans-serif";

/// `area` less a band across its bottom with `caption` drawn in it, `size` px, centred.
pub(super) fn captioned<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    size: u32,
) -> Result<DrawingArea<DB, plotters::coord::Shift>, String> {
    let (_, height) = area.dim_in_pixel();
    let (rest, band) = area.split_vertically(height.saturating_sub(size * 2));
    let (width, band_height) = band.dim_in_pixel();
    let style = TextStyle::from((FONT, size).into_font()).pos(Pos::new(HPos::Center, VPos::Center));
    band.draw_text(caption, &style, (width as i32 / 2, band_height as i32 / 2)).map_err(err)?;
    Ok(rest)
}

/// What the cycle plots' event lines are: named by three letters, explained nowhere.
pub(super) const EVENTS_CAPTION: &str = "Event lines, the right leg's cycle (0 and 100 %: right heel strike): \
     LTO left toe-off, LHS left heel strike, RTO right toe-off";

/// `area` with `title` drawn across its top in `size` px, and the rest of the area. plotters'
/// own `titled` hangs the text from the area's top pixel row by the font's estimated ascent,
/// which is short: every title lost its ascenders (the dots of its i's, the tops of l, t, J).
/// Centred in a band half as tall again as the text, the ink stays inside.
pub(super) fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    title: &str,
    size: u32,
) -> Result<DrawingArea<DB, plotters::coord::Shift>, String> {
    let (band, rest) = area.split_vertically(size * 3 / 2 + 6);
    let (width, height) = band.dim_in_pixel();
    let style = TextStyle::from((FONT, size).into_font()).pos(Pos::new(HPos::Center, VPos::Center));
    band.draw_text(title, &style, (width as i32 / 2, height as i32 / 2)).map_err(err)?;
    Ok(rest)
}

/// What drawing a plot returns: the error as text.
pub(super) type Res = Result<(), String>;

/// A plotters error as the report's text.
pub(super) fn err<E: std::fmt::Debug>(e: E) -> String {
    format!("plot: {e:?}")
}

/// Padded y range over the finite points of `series` (0..1 when there are none).
pub(super) fn y_range(series: &[&[(f64, f64)]]) -> std::ops::Range<f64> {
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.iter().map(|p| p.1))
        .filter(|y| y.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(y), b.max(y)));
    if !lo.is_finite() {
        return 0.0..1.0;
    }
    // A flat series (one feasible candidate, or every step at the same cost) still gets an
    // axis of readable ticks, padded by 0.5 % of its value: padded by a tenth of its own
    // range, only the labels' last digits differed (2111.71, 2111.72, ... crowding the axis
    // title).
    let flat = (hi - lo) < 1e-3 * lo.abs().max(hi.abs());
    let pad = if flat { 5e-3 * lo.abs().max(hi.abs()) } else { ((hi - lo) * 0.1).max(1e-3) };
    (lo - pad)..(hi + pad)
}

/// Legend label text size (px), shared so the legend's footprint can be estimated.
pub(super) const LEGEND_FONT_PX: u32 = 20;

/// Draws a chart's legend the one way every plot does (framed, on a nearly opaque white
/// ground) at `font_px`, at `position` (plotters' own default place when `None`).
pub(super) fn draw_legend<'a, DB: DrawingBackend + 'a, CT: plotters::coord::CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    font_px: u32,
    position: Option<SeriesLabelPosition>,
) -> Res {
    let mut legend = chart.configure_series_labels();
    legend.label_font((FONT, font_px)).background_style(WHITE.mix(0.85)).border_style(BLACK);
    if let Some(position) = position {
        legend.position(position);
    }
    legend.draw().map_err(err)
}

/// A chart over 0–100 % (of the gait cycle, or of a curve's own span) on `area`, with the
/// report's caption, margins and label areas: the cycle and swing charts share its layout,
/// so their axes line up and neither cuts its last label.
pub(super) fn percent_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, plotters::coord::Shift>,
    title: &str,
    y: std::ops::Range<f64>,
) -> Result<
    ChartContext<'a, DB, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>,
    String,
> {
    ChartBuilder::on(area)
        .caption(title, (FONT, 30))
        .margin(12)
        // The last x label ("100") is centred on the axis's end: room for its right half
        // (in the rightmost chart it ran off the image).
        .margin_right(28)
        .x_label_area_size(55)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..100f64, y)
        .map_err(err)
}

/// Pixel height of a legend of `rows` labels (measured on the embedded font: 3 rows, 84 px).
pub(super) fn legend_height_px(rows: usize) -> f64 {
    28.0 * rows as f64 + 6.0
}

/// The legend corner of a plot `plot_px` (width, height) in pixels over `x` by `y` that
/// covers the fewest of `series`' points, so a legend never hides the curve it names where
/// a free corner exists. Ties keep the order upper right, upper left, lower right, lower left.
pub(super) fn legend_corner(
    plot_px: (u32, u32),
    x: std::ops::Range<f64>,
    y: std::ops::Range<f64>,
    labels: &[&str],
    series: &[&[(f64, f64)]],
) -> SeriesLabelPosition {
    // The legend's footprint as shares of the plot: a 24 px swatch, the text (the font's
    // average advance is about 0.55 of its size) and the box's padding and offset.
    let widest = labels.iter().map(|l| l.chars().count()).max().unwrap_or(0) as f64;
    let width_px = 24.0 + 0.55 * f64::from(LEGEND_FONT_PX) * widest + 40.0;
    let w = (width_px / f64::from(plot_px.0.max(1))).min(1.0);
    let h = ((legend_height_px(labels.len()) + 10.0) / f64::from(plot_px.1.max(1))).min(1.0);
    let covered = |right: bool, upper: bool| {
        series
            .iter()
            .flat_map(|s| s.iter())
            .filter(|(px, py)| {
                let fx = (px - x.start) / (x.end - x.start);
                let fy = (py - y.start) / (y.end - y.start);
                let in_x = if right { fx >= 1.0 - w } else { fx <= w };
                let in_y = if upper { fy >= 1.0 - h } else { fy <= h };
                in_x && in_y
            })
            .count()
    };
    [
        (covered(true, true), SeriesLabelPosition::UpperRight),
        (covered(false, true), SeriesLabelPosition::UpperLeft),
        (covered(true, false), SeriesLabelPosition::LowerRight),
        (covered(false, false), SeriesLabelPosition::LowerLeft),
    ]
    .into_iter()
    .min_by_key(|(count, _)| *count)
    .map_or(SeriesLabelPosition::UpperRight, |(_, corner)| corner)
}

/// The right leg's colour.
pub(super) const RIGHT: RGBColor = RGBColor(200, 40, 40);
/// The left leg's colour.
pub(super) const LEFT: RGBColor = RGBColor(30, 80, 200);
/// Design curves, the body's outline.
pub(super) const DESIGN: RGBColor = RGBColor(20, 20, 20);

/// Colours of compared walks, the report's own first.
pub(super) const PALETTE: [RGBColor; 5] = [
    RGBColor(200, 40, 40),
    RGBColor(30, 80, 200),
    RGBColor(30, 150, 60),
    RGBColor(230, 130, 0),
    RGBColor(130, 40, 170),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// A plot of 500 x 400 px over 0..100 by 0..1.
    fn corner(series: &[(f64, f64)]) -> SeriesLabelPosition {
        legend_corner((500, 400), 0.0..100.0, 0.0..1.0, &["design"], &[series])
    }

    #[test]
    fn the_legend_goes_to_the_corner_its_curves_leave_free() {
        assert_eq!(corner(&[]), SeriesLabelPosition::UpperRight, "nothing drawn: the usual corner");
        // A rising curve fills the upper right and the lower left.
        let rising: Vec<(f64, f64)> = (0..=100).map(|p| (f64::from(p), f64::from(p) / 100.0)).collect();
        assert_eq!(corner(&rising), SeriesLabelPosition::UpperLeft);
        // A hump (the swing's lateral curve) peaks mid-plot and leaves the upper corners free.
        let hump: Vec<(f64, f64)> =
            (0..=100).map(|p| (f64::from(p), (std::f64::consts::PI * f64::from(p) / 100.0).sin())).collect();
        assert_eq!(corner(&hump), SeriesLabelPosition::UpperRight);
        // Points in every corner but the lower left.
        let three = [(99.0, 0.99), (1.0, 0.99), (99.0, 0.01)];
        assert_eq!(corner(&three), SeriesLabelPosition::LowerLeft);
    }

    #[test]
    fn a_flat_series_gets_an_axis_of_distinct_ticks_and_others_keep_their_zoom() {
        // Every step at one cost: 1 % of the value around it, not a few hundredths.
        let flat = [(1.0, 2111.719), (2.0, 2111.72), (3.0, 2111.721)];
        let r = y_range(&[&flat]);
        assert!(r.end - r.start > 20.0 && r.contains(&2111.72), "{r:?}");
        // A 13-unit valley in a cost near 1950 keeps its 10 % padding.
        let valley = [(0.0, 1955.0), (1.0, 1942.0)];
        let r = y_range(&[&valley]);
        assert!((r.start - 1940.7).abs() < 1e-9 && (r.end - 1956.3).abs() < 1e-9, "{r:?}");
        assert_eq!(y_range(&[&[]]), 0.0..1.0);
    }
}
