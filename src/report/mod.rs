//! `gaitlab report`: a folder with the walk's figures and tables for a write-up.
//!
//! The folder is built under a temporary name beside the target and renamed into place at
//! the end, so an interrupted run never leaves a folder that looks complete.

mod against;
pub mod figures;
pub mod metrics;
mod pace;
pub mod plots;

use crate::analysis::ik::{self, IkSummary, IkTarget, SolverRun};
use crate::analysis::ik_tables::{SolverSides, TextTable, seed_tables, side_tables};
use crate::analysis::{self, Keep, Recording, Run};
use crate::config::{self, render::toml_number, schema::PARAMS};
use crate::model::body::Side;
use crate::model::ik::IkSolverKind;
use crate::model::params::WalkParams;
use crate::model::terrain::Terrain;
use crate::model::walk::ModelError;
use crate::output::{self, FolderTarget, OutputError, joint_table};
use metrics::{LABELS, Summary, TooShort};
use std::fmt::Write as _;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// What a report is made from.
pub struct ReportInput<'a> {
    /// Name shown in the summary (the config's file stem).
    pub name: String,
    /// The config text the parameters were read from (written back with `--set` applied).
    pub source_text: &'a str,
    /// The parameters, `--set` included.
    pub params: &'a WalkParams,
    /// Gait cycles to simulate.
    pub cycles: u32,
    /// Frames per second.
    pub fps: f64,
    /// Other walks to compare with (`--compare`): name and parameters.
    pub compare: Vec<(String, WalkParams)>,
    /// IK solvers measured on the walk's targets for `ik.csv` and the `ik` plot; empty means
    /// the walk's own solver, with the analytic reference beside it when that is another.
    pub ik_solvers: Vec<IkSolverKind>,
}

impl ReportInput<'_> {
    /// The IK solvers the report measures.
    #[must_use]
    pub fn ik_solvers(&self) -> Vec<IkSolverKind> {
        if !self.ik_solvers.is_empty() {
            return self.ik_solvers.clone();
        }
        let own = self.params.ik.solver;
        if own == IkSolverKind::Analytic { vec![own] } else { vec![IkSolverKind::Analytic, own] }
    }
}

/// Files of the report folder, relative to it.
pub const FILES: &[&str] = &[
    "summary.md",
    "summary.json",
    "config.toml",
    "joints.csv",
    "footfalls.csv",
    "optimisation.csv",
    "ik.csv",
    "walk.bvh",
    "walk.glb",
    "walk.gif",
    "walk.svg",
];

/// Decides where a report may go (see [`output::folder`]), before any walking is done.
pub fn resolve_out(out: &Path, force: bool) -> Result<FolderTarget, OutputError> {
    FolderTarget::resolve(out, FILES, force)
}

/// Writes the report into `target` (replacing a previous report only once the new one is
/// whole). `progress` receives a line per stage.
pub fn write_report(
    input: &ReportInput<'_>,
    target: &FolderTarget,
    progress: &mut dyn FnMut(&str),
) -> crate::Result<Summary> {
    progress(&format!("simulating {} cycles at {} fps", input.cycles, input.fps));
    // The walk is recorded once with everything the report reads: the IK section measures
    // the solvers on the questions this very walk asked, the BVH, the glTF and the stick
    // figure take its poses, the optimisation plot its middle step's problem.
    let run = analysis::record(input.params, f64::from(input.cycles), input.fps, Keep::ALL)?;
    let ik_targets = &run.ik_targets;
    let window = metrics::steady_window(&run)?;
    let (steady, terrain_line) = measured_part(&window);
    let summary = metrics::summarise_window(&run, &window);
    let normative = against::compare(&input.name, input.cycles, &run, &summary)?;
    let mut others = Vec::new();
    for (name, params) in &input.compare {
        progress(&format!("simulating {name} for comparison"));
        let run = analysis::run(params, f64::from(input.cycles), input.fps)
            .map_err(|e| crate::Error::Model(ModelError(format!("{name}: {e}"))))?;
        let summary = metrics::summarise(&run).map_err(|e| TooShort(format!("{name}: {e}")))?;
        others.push((name.clone(), params, run, summary));
    }
    let solvers = input.ik_solvers();
    progress(&format!(
        "solving the walk's IK targets with {}",
        solvers.iter().map(|s| s.name()).collect::<Vec<_>>().join(", ")
    ));
    let resolved = input.params.resolve();
    let ik_runs: Vec<SolverRun> = solvers
        .iter()
        .map(|&solver| ik::run_solver(ik_targets, solver, &resolved.ik, resolved.dims.thigh, resolved.dims.shank))
        .collect();
    let terrain = &run.terrain;
    output::write_folder(target, FILES, |temp| {
        let file = |rel: &str| temp.join(rel);
        let write = |rel: &str, text: &str| {
            fs::write(file(rel), text).map_err(|e| format!("cannot write {}: {e}", target.path.join(rel).display()))
        };
        progress("writing tables");
        write_joints(&file("joints.csv"), &run).map_err(|e| format!("cannot write joints.csv: {e}"))?;
        write("footfalls.csv", &footfalls_csv(&run, terrain))?;
        write("optimisation.csv", &optimisation_csv(&run))?;
        write("ik.csv", &ik_csv(ik_targets, &ik_runs))?;
        progress("writing walk.bvh");
        write_bvh(&file("walk.bvh"), &run).map_err(|e| format!("cannot write walk.bvh: {e}"))?;
        progress("writing walk.glb");
        write_glb(&file("walk.glb"), &run).map_err(|e| format!("cannot write walk.glb: {e}"))?;
        progress("drawing walk.gif and walk.svg");
        let animation = plots::animation::animate(&input.name, &run)?;
        fs::write(file("walk.gif"), &animation.gif).map_err(|e| format!("cannot write walk.gif: {e}"))?;
        write("walk.svg", &animation.svg)?;
        progress("drawing plots");
        let plots = temp.join("plots");
        fs::create_dir_all(&plots).map_err(|e| format!("cannot create {}: {e}", plots.display()))?;
        let mut walks = vec![plots::Walk { name: input.name.clone(), run: &run }];
        walks.extend(others.iter().map(|(name, _, run, _)| plots::Walk { name: name.clone(), run }));
        plots::write_plots(&plots, &walks)?;
        plots::write_ik_plot(&plots, ik_targets, &ik_runs)?;
        pace::write_speed_plot(&plots, &input.name, &run, steady.as_ref())?;
        progress("writing summary");
        let json = serde_json::to_string_pretty(&against::SummaryJson::new(&summary, &normative))
            .map_err(|e| e.to_string())?;
        write("summary.json", &format!("{json}\n"))?;
        write("config.toml", &config_text(input)?)?;
        let compared: Vec<(&str, &Summary)> = others.iter().map(|(n, _, _, s)| (n.as_str(), s)).collect();
        let ik_summaries: Vec<(IkSolverKind, IkSummary)> =
            ik_runs.iter().map(|run| (run.solver, run.summary(ik_targets))).collect();
        let ik_sides: Vec<SolverSides> = ik_runs.iter().map(|run| (run.solver, side_tables(run, ik_targets))).collect();
        let ik = IkRows { summaries: &ik_summaries, sides: &ik_sides };
        let parts = (steady.as_ref(), terrain_line.as_deref());
        let mut md = summary_md(input, &summary, &compared, &normative, &ik, &animation.clip, parts);
        pace::section(&mut md, &run);
        write("summary.md", &md)?;
        Ok(())
    })?;
    Ok(summary)
}

fn write_joints(path: &Path, run: &Run) -> io::Result<()> {
    let mut out = io::BufWriter::new(fs::File::create(path)?);
    joint_table::write_header(&mut out)?;
    let mut line = String::with_capacity(512);
    for f in &run.frames {
        joint_table::format_row(f, &mut line);
        line.push('\n');
        out.write_all(line.as_bytes())?;
    }
    out.flush()
}

/// Writes every recorded frame's full pose.
fn write_bvh(path: &Path, run: &Recording) -> io::Result<()> {
    let mut out = io::BufWriter::new(fs::File::create(path)?);
    let dims = &run.gait.resolved().dims;
    crate::output::bvh::write_header(&mut out, dims, run.poses.len(), run.fps)?;
    let mut line = String::with_capacity(1024);
    for pose in &run.poses {
        crate::output::bvh::write_frame(&mut out, pose, &mut line)?;
    }
    out.flush()
}

/// Writes the walk as glTF: the same poses as the BVH, in metres.
fn write_glb(path: &Path, run: &Recording) -> io::Result<()> {
    let mut out = io::BufWriter::new(fs::File::create(path)?);
    output::gltf::write_glb(&mut out, &run.gait.resolved().dims, &run.poses, run.fps)?;
    out.flush()
}

fn footfalls_csv(run: &Run, terrain: &Terrain) -> String {
    let mut s = String::from("step,side,x,y,z,terrain_y,stride_m\n");
    let mut last_x = [None::<f64>; 2];
    for f in &run.footfalls {
        let stride = last_x[f.side.index()].map_or(String::new(), |x| format!("{:.6}", f.heel.x - x));
        last_x[f.side.index()] = Some(f.heel.x);
        let side = if f.side == Side::Right { "r" } else { "l" };
        let _ = writeln!(
            s,
            "{},{side},{:.6},{:.6},{:.6},{:.6},{stride}",
            f.step,
            f.heel.x,
            f.heel.y,
            f.heel.z,
            terrain.height(f.heel.x)
        );
    }
    s
}

/// `ik.csv`: one row per solver, frame and leg. Times per solve are left out: they differ
/// between runs, and the table must not.
fn ik_csv(targets: &[IkTarget], runs: &[SolverRun]) -> String {
    let mut out = String::from(
        "frame,time_s,side,solver,position_error_mm,knee_direction_error_deg,iterations,reached,limit_excess_deg,knee_jump_mm,ankle_jump_mm\n",
    );
    for run in runs {
        for (t, x) in targets.iter().zip(&run.samples) {
            let direction = x.knee_direction_error_deg.map_or(String::new(), |d| format!("{d:.4}"));
            let _ = writeln!(
                out,
                "{},{:.4},{},{},{:.6},{},{},{},{:.4},{:.3},{:.3}",
                t.frame,
                t.time_s,
                if t.side == Side::Right { "right" } else { "left" },
                run.solver.name(),
                x.answer.position_error * 1e3,
                direction,
                x.answer.iterations,
                x.answer.reached,
                x.limit_excess_deg,
                x.knee_jump_mm,
                x.ankle_jump_mm
            );
        }
    }
    out
}

fn optimisation_csv(run: &Run) -> String {
    let mut s = String::from("step,candidate,pelvis_x,cost,feasible,chosen\n");
    for plan in &run.step_plans {
        let r = &plan.optimisation;
        for (i, c) in r.candidates.iter().enumerate() {
            let chosen = c.x == r.chosen.x && c.y == r.chosen.y;
            let _ = writeln!(
                s,
                "{},{i},{:.6},{},{},{}",
                r.step,
                c.x,
                c.cost.map_or(String::new(), |k| format!("{k:.6}")),
                c.cost.is_some(),
                chosen
            );
        }
    }
    s
}

/// The config with `--set` values written in (comments and layout kept).
fn config_text(input: &ReportInput<'_>) -> Result<String, String> {
    let read = config::load_text(input.source_text, "config", &[]).map_err(|e| e.to_string())?;
    let changed: Vec<&str> = PARAMS.iter().filter(|p| (p.get)(&read) != (p.get)(input.params)).map(|p| p.key).collect();
    config::edit::edited_text(input.source_text, input.params, &changed)
}

/// `summary.md`: the walk's figures (beside any compared walk's), the walk against measured
/// gait, the IK solvers on its targets, and links to the plots and tables.
/// What `summary.md` and the speed plot say was measured: the plateau (its span narrowed to
/// the cycles on stairs or a slope when it has some: the speed plot and the headline show that
/// span, not the whole plateau's), and the sentence on the terrain's part, if any.
fn measured_part(window: &metrics::SteadyWindow) -> (Option<metrics::SteadyPlateau>, Option<String>) {
    let steady = window.plateau.map(|p| match window.terrain {
        Some(t) => metrics::SteadyPlateau { from_s: t.from_s, to_s: t.to_s, cycles: t.cycles, ..p },
        None => p,
    });
    let terrain_line = match (window.terrain, window.terrain_missed) {
        (Some(t), _) => Some(format!(
            "Measured on the terrain: {}. The figures below (and *Against measured gait*) are measured on the \
             whole gait cycles walked there only; the health checks (foot skate, penetration, reach failures, \
             non-finite values) cover every frame.\n",
            t.describe()
        )),
        (None, Some(on)) => Some(format!(
            "None of the walk's whole gait cycles lies {on} (a short flight or walk): the figures below average \
             the level cycles in with the others.\n"
        )),
        (None, None) => None,
    };
    (steady, terrain_line)
}

fn summary_md(
    input: &ReportInput<'_>,
    s: &Summary,
    others: &[(&str, &Summary)],
    normative: &crate::normative::Comparison,
    ik: &IkRows<'_>,
    clip: &plots::animation::Clip,
    (steady, terrain): (Option<&metrics::SteadyPlateau>, Option<&str>),
) -> String {
    let mut md = summary_intro(input, others, steady.is_some() || terrain.is_some());
    if let Some(plateau) = steady {
        pace::headline(&mut md, plateau);
    }
    if let Some(line) = terrain {
        let _ = writeln!(md, "{line}");
    }
    figures_table(&mut md, input, s, others);
    against::section(&mut md, &input.name, !others.is_empty(), normative);
    ik_table(&mut md, input, ik.summaries);
    seed_ik_tables(&mut md, input, ik.sides);
    md.push_str("\n## Plots\n\n");
    for plot in plots::PLOTS {
        let _ = writeln!(md, "- [{plot}](plots/{plot}.png) ([svg](plots/{plot}.svg))");
    }
    let _ = writeln!(
        md,
        "- [walk.gif](walk.gif) ([svg](walk.svg)): the walk for slides, side and from ahead, {} looping at \
         the walk's pace ({} frames at {} fps, {}x{})",
        clip.describe(),
        clip.frames,
        plots::animation::FPS,
        plots::animation::WIDTH,
        plots::animation::HEIGHT
    );
    md.push_str(
        "\nTables: [joints.csv](joints.csv) (one row a frame), [footfalls.csv](footfalls.csv), \
         [optimisation.csv](optimisation.csv) (every candidate of every step), [ik.csv](ik.csv) (every IK \
         solve of every solver above). Definitions of the \
         figures: `src/report/metrics.rs`.\n",
    );
    md
}

/// The title and the paragraph that says what was walked: the preset's description, the
/// terrain, the speed, how long, and which walks it is compared with.
fn summary_intro(input: &ReportInput<'_>, others: &[(&str, &Summary)], part_named: bool) -> String {
    let p = input.params;
    // The preset's description is its author's words and may name another speed than the one
    // walked (`--set walk.speed_mps=0.8` on stroll's "at 0.9 m/s"): quoted as the preset's, and
    // the walked speed stated on its own.
    let description = input
        .source_text
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("# preset: "))
        .map_or_else(|| "A custom config".to_string(), |d| format!("Preset: \"{d}\""));
    let terrain = crate::config::schema::spec("terrain.kind").map_or(String::new(), |k| match (k.get)(p) {
        crate::config::schema::Value::Word(w) => w.to_string(),
        _ => String::new(),
    });
    format!(
        "# gaitlab report: {}\n\n{description}, walked at {} m/s (`walk.speed_mps`) on {terrain} terrain; {} cycles at {} fps \
         (the first cycle is start-up and not measured{}). Config: [config.toml](config.toml).\n\n\
         {}",
        input.name,
        toml_number(p.walk.speed_mps),
        input.cycles,
        input.fps,
        if part_named { "; the part measured is named below" } else { "" },
        if others.is_empty() {
            String::new()
        } else {
            format!(
                "Compared with {} (same cycles and frame rate); the plots overlay their pelvis curves, swing heel heights and joint angles.\n\n",
                others.iter().map(|(n, _)| format!("`{n}`")).collect::<Vec<_>>().join(", ")
            )
        }
    )
}

/// The figures of `summary.json` as a table, one column per walk, in [`LABELS`] order;
/// counts as integers, everything else to two decimals.
fn figures_table(md: &mut String, input: &ReportInput<'_>, s: &Summary, others: &[(&str, &Summary)]) {
    let values: Vec<serde_json::Value> = std::iter::once(s)
        .chain(others.iter().map(|(_, o)| *o))
        .map(|x| serde_json::to_value(x).expect("plain numbers"))
        .collect();
    let names: Vec<&str> = std::iter::once(input.name.as_str()).chain(others.iter().map(|(n, _)| *n)).collect();
    let _ = writeln!(md, "| figure | {} | unit |", names.join(" | "));
    let _ = writeln!(md, "|---|{}---|", "---:|".repeat(names.len()));
    for (key, unit, label) in LABELS {
        let cells: Vec<String> = values
            .iter()
            .map(|value| {
                let v = &value[*key];
                match v.as_u64() {
                    Some(n) if !key.ends_with("cost") => n.to_string(),
                    _ => format!("{:.2}", v.as_f64().unwrap_or(f64::NAN)),
                }
            })
            .collect();
        let _ = writeln!(md, "| {label} (`{key}`) | {} | {unit} |", cells.join(" | "));
    }
}

/// The Leg IK section: the solver the walk uses, and each solver's row on the walk's targets.
fn ik_table(md: &mut String, input: &ReportInput<'_>, ik_rows: &[(IkSolverKind, IkSummary)]) {
    let _ = write!(
        md,
        "\n## Leg IK\n\nThe walk places its legs with `{}`. Solvers on the walk's {} IK targets \
         (both legs, every frame; definitions in `src/analysis/ik.rs`; timings: `gaitlab ik`):\n\n\
         | solver | reached | position error max (mm) | knee direction error max (deg) | iterations mean | iterations max | joint-limit violations |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
        input.params.ik.solver.name(),
        ik_rows.first().map_or(0, |(_, r)| r.solves)
    );
    for (solver, r) in ik_rows {
        let _ = writeln!(
            md,
            "| {} | {}/{} | {:.4} | {:.4} | {:.2} | {} | {} |",
            solver.name(),
            r.reached,
            r.solves,
            r.position_error_max_mm,
            r.knee_direction_error_max_deg,
            r.iterations_mean,
            r.iterations_max,
            r.limit_violations
        );
    }
}

/// The IK solvers' figures on the report's walk: overall, and per leg in seed 002's form.
struct IkRows<'a> {
    summaries: &'a [(IkSolverKind, IkSummary)],
    sides: &'a [SolverSides],
}

/// Seed 002's tables 5.1–5.3 for the report's own walk (the IK section measures no compared
/// walk), as `gaitlab ik` prints them.
fn seed_ik_tables(md: &mut String, input: &ReportInput<'_>, sides: &[SolverSides]) {
    let _ = write!(
        md,
        "\nPer leg, in seed 002's form, on `{}`'s targets (definitions and thresholds in \
         `src/analysis/ik_tables.rs`):\n",
        input.name
    );
    for table in seed_tables(sides) {
        markdown_table(md, &table);
    }
}

/// A table under its title in bold, names left-aligned and figures right-aligned.
fn markdown_table(md: &mut String, table: &TextTable) {
    let _ = writeln!(md, "\n**{}**\n", table.title);
    let _ = writeln!(md, "| {} |", table.head.join(" | "));
    let align: Vec<&str> = (0..table.head.len()).map(|c| if c < 2 { "---" } else { "---:" }).collect();
    let _ = writeln!(md, "|{}|", align.join("|"));
    for row in &table.rows {
        let _ = writeln!(md, "| {} |", row.join(" | "));
    }
}

/// The default report folder for a config: `reports/<stem>`.
#[must_use]
pub fn default_out(config: &Path) -> PathBuf {
    Path::new("reports").join(config.file_stem().unwrap_or_default())
}
