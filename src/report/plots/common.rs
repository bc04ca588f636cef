//! What every plot shares: its size, the font, the colours, the error type, and the y range
//! that fits a set of series.

use plotters::prelude::*;

/// Pixel size of every PNG (and the SVG's nominal size).
pub const SIZE: (u32, u32) = (1600, 1000);

/// The embedded font's family name (registered by [`super::write_plots`]).
pub(super) const FONT: &str = "sans-serif";

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
    let pad = ((hi - lo) * 0.1).max(1e-3);
    (lo - pad)..(hi + pad)
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
