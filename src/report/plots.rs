//! The report's plots, each as a 1600x1000 PNG and an SVG, drawn with plotters and a font
//! embedded in the binary (DejaVu Sans, `assets/fonts`), so no system font is needed.
//!
//! Curves over the gait cycle are the mean of the steady cycles with their min–max band;
//! the right leg's cycle runs from its heel strike, the left leg's from its own. Vertical
//! lines mark the gait events (mean over the cycles): right toe-off (RTO), left heel strike
//! (LHS), left toe-off (LTO).
//!
//! Each plot is drawn in its own file under `plots/`; `common` holds what they share,
//! `data` the run prepared once for all of them, and `chrono` the stick figure's layout
//! (which instants, which slot each figure takes). `animation` draws the walk for slides
//! (`walk.gif`, `walk.svg`) from the same geometry.

pub mod animation;
mod chrono;
mod common;
mod cycle;
pub(crate) mod data;
mod ik;
mod optimisation;
mod overlay;
mod stick_figure;
mod swing;
mod thesis;

pub use common::SIZE;
pub(crate) use overlay::Overlay;
pub(crate) use thesis::{Band, Figure, Line, Panel, write_figure};

use crate::analysis::Run;
use crate::analysis::ik::{IkTarget, SolverRun};
use common::{FONT, Res};
use cycle::{joints, pelvis};
use data::Data;
use ik::ik;
use optimisation::optimisation;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;
use stick_figure::stick_figure;
use swing::{ankle, swing_foot};

/// Plot names, each written as `plots/<name>.png` and `plots/<name>.svg`.
pub const PLOTS: &[&str] = &["pelvis", "swing_foot", "ankle", "joints", "stick_figure", "optimisation", "ik"];

static REGISTER_FONT: Once = Once::new();

fn register_font() {
    REGISTER_FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
        // The font is compiled in and known to parse; failure would be a build problem.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, bytes);
    });
}

macro_rules! both {
    ($dir:expr, $name:expr, $f:ident $(, $arg:expr)*) => {{
        let png = $dir.join(format!("{}.png", $name));
        let svg = $dir.join(format!("{}.svg", $name));
        $f(BitMapBackend::new(&png, SIZE).into_drawing_area() $(, $arg)*)?;
        $f(SVGBackend::new(&svg, SIZE).into_drawing_area() $(, $arg)*)?;
    }};
}

/// A walk to plot: its name (legend), run and parameters.
pub struct Walk<'a> {
    /// Legend name (the config's file stem).
    pub name: String,
    /// The simulated walk.
    pub run: &'a Run,
}

/// Writes every plot of [`PLOTS`] into `dir` (which must exist). The first walk is the
/// report's; others (from `--compare`) are overlaid on the pelvis, swing-foot and joint-angle
/// plots.
pub fn write_plots(dir: &Path, walks: &[Walk<'_>]) -> Res {
    register_font();
    let all: Vec<(String, Data<'_>)> = walks.iter().map(|w| (w.name.clone(), Data::new(w.run))).collect();
    let d = &all[0].1;
    both!(dir, "pelvis", pelvis, &all);
    both!(dir, "swing_foot", swing_foot, &all);
    both!(dir, "ankle", ankle, d);
    both!(dir, "joints", joints, &all);
    both!(dir, "stick_figure", stick_figure, d);
    both!(dir, "optimisation", optimisation, d);
    Ok(())
}

/// Writes `ik.png` and `ik.svg` into `dir`: each solver's error and iterations per frame.
pub fn write_ik_plot(dir: &Path, targets: &[IkTarget], runs: &[SolverRun]) -> Res {
    register_font();
    both!(dir, "ik", ik, targets, runs);
    Ok(())
}

/// PNG bytes ([`SIZE`]) of `curves` against their stored versions, under `title`, with
/// `notes` listed beside them (`gaitlab snapshot --plot`): drawn in memory, so that the
/// caller writes the file through the output module.
pub(crate) fn overlay_png(title: &str, curves: &[Overlay<'_>], notes: &[String]) -> Result<Vec<u8>, String> {
    use image::ImageEncoder as _;
    register_font();
    let (w, h) = SIZE;
    let mut rgb = vec![0u8; w as usize * h as usize * 3];
    overlay::overlay(BitMapBackend::with_buffer(&mut rgb, SIZE).into_drawing_area(), title, curves, notes)?;
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(&rgb, w, h, image::ColorType::Rgb8)
        .map_err(|e| format!("plot: {e}"))?;
    Ok(png)
}
