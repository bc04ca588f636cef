//! `gaitlab figures`: the seed thesis's figures 6.2, 6.6, 6.8, 6.15 and 6.17 and its table
//! 6.1 regenerated from this build, in a folder of their own.
//!
//! Each figure is written as PNG and SVG (1600x1000, the report's plot machinery) with its
//! numbers as CSV beside it; `figures.md` lists them, a sentence each; `table_6_1.md` is the
//! cost of each part of a frame, measured on this machine ([`crate::analysis::frame_cost`]),
//! beside the thesis's figures. Every file but `table_6_1.md` is the same for the same
//! config; the table is a measurement. The folder is written like a report's: built whole
//! and swapped into place, replacing only an empty folder or a previous figures folder.
//!
//! The walks: the config as given (figs 6.8, 6.17); on level ground (6.6, 6.15); over a
//! single step of `terrain.rise_m` up and down (6.6); down a slope of `terrain.grade_pct`
//! (6.15, 10 % when the config's grade is under 1 %). Fig 6.2 draws the config's random
//! terrain settings at H 0.3 and 0.1.

mod series;

use crate::analysis::frame_cost::FrameCosts;
use crate::analysis::{Keep, Recording, record};
use crate::model::params::{TerrainChoice, WalkParams};
use crate::model::walk::ModelError;
use crate::model::walk::timing::FramePart;
use crate::output::{self, FolderTarget, OutputError};
use series::Made;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

/// The figures, by file stem, in the thesis's order.
pub const FIGURES: [&str; 5] =
    ["fig_6_2_terrain", "fig_6_6_swing_foot", "fig_6_8_ankle", "fig_6_15_pelvis_progress", "fig_6_17_arms"];

/// Every file of the folder: the index first (it marks the folder as gaitlab's).
pub const FILES: &[&str] = &[
    "figures.md",
    "table_6_1.md",
    "fig_6_2_terrain.png",
    "fig_6_2_terrain.svg",
    "fig_6_2_terrain.csv",
    "fig_6_6_swing_foot.png",
    "fig_6_6_swing_foot.svg",
    "fig_6_6_swing_foot.csv",
    "fig_6_8_ankle.png",
    "fig_6_8_ankle.svg",
    "fig_6_8_ankle.csv",
    "fig_6_15_pelvis_progress.png",
    "fig_6_15_pelvis_progress.svg",
    "fig_6_15_pelvis_progress.csv",
    "fig_6_17_arms.png",
    "fig_6_17_arms.svg",
    "fig_6_17_arms.csv",
];

/// Frame rate of the figures' walks: fine enough for smooth swing curves.
const FPS: f64 = 120.0;

/// The lab's draw, measured by the caller (the library draws no terminal).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LabDraw {
    /// Median time to draw every panel once (µs).
    pub us: f64,
    /// The screen drawn (columns, rows).
    pub size: (u16, u16),
}

/// What the figures are made from.
pub struct FiguresInput<'a> {
    /// The config's name (its file stem, or `default` for the embedded default).
    pub name: String,
    /// The parameters, `--set` included.
    pub params: &'a WalkParams,
    /// The frame's parts, measured.
    pub costs: &'a FrameCosts,
    /// The lab's draw, if measured.
    pub lab_draw: Option<LabDraw>,
}

/// The default folder: `reports/figures` for the embedded default, else
/// `reports/<config stem>-figures` (beside the config's report, never in it).
#[must_use]
pub fn default_out(config: Option<&Path>) -> PathBuf {
    match config.and_then(Path::file_stem) {
        Some(stem) => Path::new("reports").join(format!("{}-figures", stem.to_string_lossy())),
        None => Path::new("reports").join("figures"),
    }
}

/// Decides where the figures may go (see [`output::folder`]), before anything is walked.
pub fn resolve_out(out: &Path, force: bool) -> Result<FolderTarget, OutputError> {
    FolderTarget::resolve(out, FILES, force)
}

/// Cycles that carry a walk `beyond_m` past where it starts, with two steady cycles more.
fn cycles_past(params: &WalkParams, beyond_m: f64) -> f64 {
    let stride = params.resolve().stride_m.max(0.1);
    ((beyond_m / stride).ceil() + 3.0).clamp(4.0, 200.0)
}

/// The config with its terrain set by `set`.
fn with_terrain(params: &WalkParams, set: impl Fn(&mut WalkParams)) -> WalkParams {
    let mut p = params.clone();
    set(&mut p);
    p
}

/// The slope fig 6.15 walks down (%, negative).
fn downhill_grade(params: &WalkParams) -> f64 {
    if params.terrain.grade_pct.abs() >= 1.0 { -params.terrain.grade_pct.abs() } else { -10.0 }
}

/// The walks the figures are drawn from: own, flat, step up, step down, downhill.
fn walks(params: &WalkParams, progress: &mut dyn FnMut(&str)) -> Result<[Recording; 5], ModelError> {
    let start = params.terrain.start_x_m;
    let flat = with_terrain(params, |p| p.terrain.kind = TerrainChoice::Flat);
    let step = |up: bool| {
        with_terrain(params, |p| {
            p.terrain.kind = TerrainChoice::Stairs;
            p.terrain.count = 1;
            p.terrain.up = up;
        })
    };
    let downhill = with_terrain(params, |p| {
        p.terrain.kind = TerrainChoice::Slope;
        p.terrain.grade_pct = downhill_grade(params);
    });
    let named = [
        ("the config as given", params.clone(), 6.0),
        ("on level ground", flat, cycles_past(params, start + 2.0)),
        ("over a step up", step(true), cycles_past(params, start + 1.0)),
        ("over a step down", step(false), cycles_past(params, start + 1.0)),
        ("downhill", downhill, cycles_past(params, start + 2.0)),
    ];
    let mut out = Vec::with_capacity(5);
    for (what, p, cycles) in named {
        progress(&format!("walking {what}"));
        out.push(record(&p, cycles, FPS, Keep::default()).map_err(|e| ModelError(format!("walking {what}: {e}")))?);
    }
    Ok(out.try_into().unwrap_or_else(|_| unreachable!("five walks")))
}

/// Makes every figure's data, in [`FIGURES`] order.
fn make(params: &WalkParams, w: &[Recording; 5]) -> Result<Vec<Made>, String> {
    let [own, flat, up, down, downhill] = w;
    Ok(vec![
        series::terrain(params),
        series::swing_foot(flat, up, down, params.terrain.rise_m)?,
        series::ankle(own)?,
        series::pelvis_progress(flat, downhill, downhill_grade(params))?,
        series::arms(own),
    ])
}

/// Writes the figures folder into `target`; `progress` receives a line per stage.
pub fn write_figures(
    input: &FiguresInput<'_>,
    target: &FolderTarget,
    progress: &mut dyn FnMut(&str),
) -> crate::Result<()> {
    let recorded = walks(input.params, progress)?;
    let made = make(input.params, &recorded).map_err(|e| ModelError(format!("{}: {e}", input.name)))?;
    output::write_folder(target, FILES, |temp| {
        let write = |rel: &str, text: &str| {
            fs::write(temp.join(rel), text)
                .map_err(|e| format!("cannot write {}: {e}", target.path.join(rel).display()))
        };
        for (stem, m) in FIGURES.iter().zip(&made) {
            progress(&format!("drawing {stem}"));
            crate::report::plots::write_figure(temp, stem, &m.figure)?;
            write(&format!("{stem}.csv"), &m.csv)?;
        }
        write("table_6_1.md", &table_6_1(input))?;
        write("figures.md", &index(input, &made))?;
        Ok(())
    })?;
    Ok(())
}

/// `figures.md`: each figure with its sentence and files.
fn index(input: &FiguresInput<'_>, made: &[Made]) -> String {
    let mut md = format!(
        "# The seed thesis's figures, regenerated\n\nP. Mohelník, *Procedural animation of human walk* (2016), \
         chapter 6, redrawn by gaitlab from `{}` (walks at {FPS} frames/s; the numbers of each figure in its CSV).\n\n",
        input.name
    );
    for (stem, m) in FIGURES.iter().zip(made) {
        let _ = writeln!(md, "- [{stem}.png]({stem}.png) ([svg]({stem}.svg), [csv]({stem}.csv)): {}", m.note);
    }
    md.push_str(
        "- [table_6_1.md](table_6_1.md): thesis table 6.1, the cost of each part of a frame, measured on this \
         build and machine beside the thesis's ~5 ms a frame and Chung & Hahn's 3.75 steps/s (a measurement: \
         it differs from run to run, unlike every other file here).\n",
    );
    md
}

/// The thesis's row of table 6.1 that each part answers to, and its share (%).
fn thesis_row(part: FramePart) -> (&'static str, &'static str, &'static str) {
    match part {
        FramePart::Curves => {
            ("curves (pelvis trajectory, arm curves)", "Vyhodnocování křivek (evaluating curves)", "3")
        }
        FramePart::LegTargets => ("legs: targets (phase rules, swing curves)", "Řešení nohou (legs)", "5"),
        FramePart::LegIk => ("legs: IK", "Řešení inverzní kinematiky (IK)", "5"),
        FramePart::PelvisChoice => {
            ("pelvis choice (the optimiser, each toe-off)", "Určení pozice pánve (pelvis position)", "10")
        }
        FramePart::SwingPlanning => ("swing planning (footfall, keys, reach guards; each toe-off)", "in legs", "-"),
        FramePart::Spine => ("spine (frontal compensation)", "Řešení páteře (spine)", "0.08"),
        FramePart::Arms => ("arms and trunk rotations", "Řešení rukou (arms)", "0.6"),
        FramePart::Pose => ("pose (forward kinematics)", "-", "-"),
        FramePart::Frame => ("the frame's numbers (joint-table row)", "-", "-"),
        FramePart::Bookkeeping => ("clock (phase boundaries, live curves)", "-", "-"),
    }
}

/// `table_6_1.md`: each part's cost, the sum against the whole frame, the lab's draw, and
/// the comparisons the thesis makes.
fn table_6_1(input: &FiguresInput<'_>) -> String {
    let c = input.costs;
    let draw = input.lab_draw.map_or(0.0, |d| d.us);
    let lab = c.whole_us + draw;
    let mut md = format!(
        "# Thesis table 6.1: the cost of each part of a frame, on this build\n\n\
         `{}` walked {} frames at {} frames/s ({} steps), part by part with a lap timer and whole without it, \
         in {} paired runs; each frame at its median over the runs (definitions: `src/analysis/frame_cost.rs`). \
         The parts happen once a frame except the pelvis choice and the swing planning, which happen at each toe-off \
         and are spread over the frames. A measurement: it varies with the machine and its load.\n\n\
         | part | thesis's row | thesis % | µs per frame | % of the walk's frame | % of the lab's frame |\n\
         |---|---|---:|---:|---:|---:|\n",
        input.name, c.frames, c.fps, c.steps, c.repeats
    );
    for (part, us) in &c.parts_us {
        let (name, row, pct) = thesis_row(*part);
        let _ = writeln!(
            md,
            "| {name} | {row} | {pct} | {us:.3} | {:.1} | {:.1} |",
            100.0 * us / c.whole_us,
            100.0 * us / lab
        );
    }
    let sum = c.parts_sum_us();
    let _ = writeln!(md, "| **sum of the parts** | | | **{sum:.3}** | **{:.1}** | |", 100.0 * sum / c.whole_us);
    let _ = writeln!(
        md,
        "| **the walk's frame, timed whole** | | | **{:.3}** | 100 | {:.1} |",
        c.whole_us,
        100.0 * c.whole_us / lab
    );
    if let Some(d) = input.lab_draw {
        let _ = writeln!(
            md,
            "| the lab's draw (every panel at {}x{}, into ratatui's TestBackend) | Vykreslování scény + GUI (drawing scene + GUI) | 25 + 35 | {:.1} | | {:.1} |",
            d.size.0,
            d.size.1,
            d.us,
            100.0 * d.us / lab
        );
        let _ = writeln!(md, "| **the lab's frame (walk + draw)** | | | **{lab:.1}** | | 100 |");
    }
    comparisons(&mut md, c, lab, input.lab_draw.is_some());
    md
}

/// The thesis's ~5 ms a frame and Chung & Hahn's 3.75 steps/s against this build.
fn comparisons(md: &mut String, c: &FrameCosts, lab_us: f64, drawn: bool) {
    let per_step: f64 = c
        .parts_us
        .iter()
        .filter(|(p, _)| matches!(p, FramePart::PelvisChoice | FramePart::SwingPlanning))
        .map(|(_, us)| us * c.frames_per_step())
        .sum();
    let ordinary = c.parts_sum_us() - per_step / c.frames_per_step();
    let steps_per_s = 1e6 / (10.0 * ordinary + per_step);
    let _ = write!(
        md,
        "\nThe thesis (Asus K53SV, Intel Core i5, GeForce GT 540M) spends ~5 ms a frame, 3D scene and GUI drawn. \
         Here the {}: {:.3} ms, {:.0}x less.\n\n\
         Chung & Hahn (1999; lower body only, no drawing) computed 3.75 steps a second at 10 frames a step on a \
         Pentium II 300 MHz. This build's walk at 10 frames a step (an ordinary frame {ordinary:.2} µs, each step's \
         planning and pelvis choice {per_step:.0} µs): {steps_per_s:.0} steps a second, {:.0}x theirs.\n",
        if drawn { "lab's frame (walk and draw)" } else { "walk's frame (no draw measured)" },
        lab_us / 1000.0,
        5000.0 / lab_us,
        steps_per_s / 3.75
    );
}
