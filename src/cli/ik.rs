//! `gaitlab ik`: every IK solver on the walk's own targets, side by side.

use super::common::{in_range, stdout_written};
use crate::analysis::ik::{IkSummary, IkTarget, collect_targets, random_targets, run_solver_from};
use crate::analysis::ik_tables::{MaxMean, SideTable, SolverSides, TextTable, seed_tables, side_tables};
use crate::config;
use crate::error::{Error, Result};
use crate::model::body::Side;
use crate::model::ik::{IkSettings, IkSolverKind};
use serde::Serialize;
use std::io::{self, IsTerminal, Write};
use std::path::Path;

/// The solvers named in `list` (comma-separated), or a message naming the valid ones.
pub(crate) fn parse_solvers(list: &str) -> Result<Vec<IkSolverKind>, String> {
    let mut solvers = Vec::new();
    for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
        let Some(kind) = IkSolverKind::from_name(name) else {
            let valid: Vec<&str> = IkSolverKind::ALL.iter().map(|k| k.name()).collect();
            return Err(format!("unknown solver `{name}`; valid: {}", valid.join(", ")));
        };
        if !solvers.contains(&kind) {
            solvers.push(kind);
        }
    }
    if solvers.is_empty() {
        return Err("--solvers names no solver".to_string());
    }
    Ok(solvers)
}

/// `--targets`: `walk`, or `random:N` with an optional `:SEED`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TargetSet {
    Walk,
    Random { n: usize, seed: u64 },
}

/// Seed of `random:N` without one: the issue that asked for the set.
const RANDOM_SEED: u64 = 19;

/// The target set named by `--targets`, or a message saying what is accepted.
pub(crate) fn parse_targets(spec: &str) -> Result<TargetSet, String> {
    let usage = || format!("--targets {spec}: expected `walk` or `random:N[:SEED]` with N from 1 to 1000000");
    if spec == "walk" {
        return Ok(TargetSet::Walk);
    }
    let mut parts = spec.strip_prefix("random:").ok_or_else(usage)?.split(':');
    let n: usize =
        parts.next().and_then(|n| n.parse().ok()).filter(|n| (1..=1_000_000).contains(n)).ok_or_else(usage)?;
    let seed = match parts.next() {
        Some(seed) => seed.parse().map_err(|_| usage())?,
        None => RANDOM_SEED,
    };
    if parts.next().is_some() {
        return Err(usage());
    }
    Ok(TargetSet::Random { n, seed })
}

pub(super) fn run(
    path: &Path,
    solvers: Option<&str>,
    cycles: Option<u32>,
    fps: Option<f64>,
    json: bool,
    target_set: Option<&str>,
    sets: &[String],
) -> Result<()> {
    let params = config::load(path, sets)?;
    let solvers = solvers.map_or_else(|| Ok(IkSolverKind::ALL.to_vec()), parse_solvers).map_err(Error::Usage)?;
    let target_set = target_set.map_or(Ok(TargetSet::Walk), parse_targets).map_err(Error::Usage)?;
    let cycles = in_range("--cycles", cycles.unwrap_or(params.sim.cycles), 1..=10_000, "1 to 10000")?;
    let fps = in_range("--fps", fps.unwrap_or(params.sim.fps), 10.0..=1000.0, "10 to 1000")?;
    let r = params.resolve();
    let (targets, cold, header): (Vec<IkTarget>, bool, String) = match target_set {
        TargetSet::Walk => {
            let targets = collect_targets(&params, f64::from(cycles), fps)
                .map_err(|source| Error::Walk { config: path.to_path_buf(), source })?;
            let header = format!("{} IK targets ({} cycles at {} fps, both legs)", targets.len(), cycles, fps);
            (targets, false, header)
        }
        TargetSet::Random { n, seed } => {
            let targets = random_targets(n, seed, r.dims.thigh, r.dims.shank, &r.ik.limits);
            let header = format!(
                "{n} random IK targets (right leg around a standing hip, reachable within the joint ranges, seed {seed}, each solved from rest)"
            );
            (targets, true, header)
        }
    };
    // The gradient solver takes seconds over a long walk: say what is running, on a terminal.
    let tty = io::stderr().is_terminal();
    let (rows, sides): (Vec<(IkSolverKind, IkSummary)>, Vec<SolverSides>) = solvers
        .iter()
        .map(|&solver| {
            if tty {
                eprintln!("gaitlab ik: {} on {} targets", solver.name(), targets.len());
            }
            let run = run_solver_from(&targets, solver, &r.ik, (r.dims.thigh, r.dims.shank), cold);
            ((solver, run.summary(&targets)), (solver, side_tables(&run, &targets)))
        })
        .unzip();
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
    let written = if json {
        write_json(&mut out, &rows, &sides)
    } else {
        write_tables(&mut out, path, &header, &r.ik, &rows)
            .and_then(|()| seed_tables(&sides).iter().try_for_each(|t| write_text_table(&mut out, t)))
    };
    stdout_written(written.and_then(|()| out.flush()))
}

/// What a solver's own settings are, in one line.
fn settings_line(solver: IkSolverKind, s: &IkSettings) -> String {
    let limits = if s.limits.enabled { "limits on" } else { "limits off" };
    let tol = format!("tolerance {:.3} mm, at most {} iterations, {limits}", s.tolerance * 1e3, s.max_iterations);
    match solver {
        IkSolverKind::Analytic => {
            format!(
                "exact; soften {:.2}, twist {:.1} deg; limits measured, not enforced",
                s.soften,
                s.twist.to_degrees()
            )
        }
        IkSolverKind::Ccd => {
            format!("stiffness hip {:.2} knee {:.2}; {tol}", s.ccd_stiffness_hip, s.ccd_stiffness_knee)
        }
        IkSolverKind::Fabrik => tol,
        IkSolverKind::JacobianDls => format!("{} (damping {} m); {tol}", s.jacobian_variant.name(), s.dls_damping),
        IkSolverKind::Gradient => {
            let g = &s.gradient;
            format!(
                "delta0 {} down to {}, {} restarts, {} perturbations of {:.0} deg a frame, seed {}; tolerance {:.3} mm, {limits}",
                g.delta0,
                g.epsilon,
                g.restarts,
                g.perturbations,
                g.perturbation.to_degrees(),
                g.seed,
                s.tolerance * 1e3
            )
        }
    }
}

fn write_tables(
    out: &mut impl Write,
    path: &Path,
    header: &str,
    settings: &IkSettings,
    rows: &[(IkSolverKind, IkSummary)],
) -> io::Result<()> {
    writeln!(out, "# {}: {header}; the walk uses {}", path.display(), settings.solver.name())?;
    for (solver, s) in rows {
        writeln!(out)?;
        writeln!(out, "{}: {}", solver.name(), settings_line(*solver, settings))?;
        writeln!(out, "  {:<28}{:>10}   (reached {}, missed {})", "solves", s.solves, s.reached, s.solves - s.reached)?;
        writeln!(
            out,
            "  {:<28}max {:>10.4}   mean {:>10.4}",
            "position error (mm)", s.position_error_max_mm, s.position_error_mean_mm
        )?;
        writeln!(
            out,
            "  {:<28}max {:>10.4}   mean {:>10.4}",
            "knee direction error (deg)", s.knee_direction_error_max_deg, s.knee_direction_error_mean_deg
        )?;
        writeln!(out, "  {:<28}max {:>10}   mean {:>10.2}", "iterations", s.iterations_max, s.iterations_mean)?;
        writeln!(out, "  {:<28}mean {:>9.2}", "time per solve (us)", s.time_per_solve_us)?;
        writeln!(out, "  {:<28}{:>10}", "joint-limit violations", s.limit_violations)?;
        writeln!(
            out,
            "  {:<28}max {:>10.2}   mean {:>10.2}   worst at frame {}",
            "knee jump (mm)", s.knee_jump_max_mm, s.knee_jump_mean_mm, s.knee_jump_max_frame
        )?;
        writeln!(
            out,
            "  {:<28}max {:>10.2}   mean {:>10.2}   worst at frame {}",
            "ankle jump (mm)", s.ankle_jump_max_mm, s.ankle_jump_mean_mm, s.ankle_jump_max_frame
        )?;
    }
    writeln!(out)?;
    writeln!(
        out,
        "{:<13} {:>11} {:>12} {:>12} {:>10} {:>10} {:>8}",
        "solver", "reached", "err max mm", "knee max deg", "iter mean", "us/solve", "limits"
    )?;
    for (solver, s) in rows {
        writeln!(
            out,
            "{:<13} {:>11} {:>12.4} {:>12.4} {:>10.2} {:>10.2} {:>8}",
            solver.name(),
            format!("{}/{}", s.reached, s.solves),
            s.position_error_max_mm,
            s.knee_direction_error_max_deg,
            s.iterations_mean,
            s.time_per_solve_us,
            s.limit_violations
        )?;
    }
    Ok(())
}

/// A table with its title, a blank line before it, its columns padded to their widest cell
/// (names to the left, figures to the right). Header and rows are indented: scripts pick the
/// side-by-side lines by the solver name at the start of a line.
fn write_text_table(out: &mut impl Write, table: &TextTable) -> io::Result<()> {
    let widths: Vec<usize> = (0..table.head.len())
        .map(|c| std::iter::once(&table.head).chain(&table.rows).map(|row| row[c].chars().count()).max().unwrap_or(0))
        .collect();
    let line = |row: &[String]| -> String {
        let cells: Vec<String> = row
            .iter()
            .zip(&widths)
            .enumerate()
            .map(|(c, (cell, &w))| if c < 2 { format!("{cell:<w$}") } else { format!("{cell:>w$}") })
            .collect();
        format!("  {}", cells.join("  ").trim_end())
    };
    writeln!(out)?;
    writeln!(out, "{}", table.title)?;
    writeln!(out, "{}", line(&table.head))?;
    for row in &table.rows {
        writeln!(out, "{}", line(row))?;
    }
    Ok(())
}

/// One `--json` line. The fields up to `time_per_solve_us` are in the alphabetical order the
/// line has always had (a `json!` map's), which scripts read; later fields go at the end.
#[derive(Serialize)]
struct JsonLine<'a> {
    ankle_jump_max_frame: u64,
    ankle_jump_max_mm: f64,
    ankle_jump_mean_mm: f64,
    iterations_max: u32,
    iterations_mean: f64,
    knee_direction_error_max_deg: f64,
    knee_direction_error_mean_deg: f64,
    knee_jump_max_frame: u64,
    knee_jump_max_mm: f64,
    knee_jump_mean_mm: f64,
    limit_violations: usize,
    position_error_max_mm: f64,
    position_error_mean_mm: f64,
    reached: usize,
    solver: &'a str,
    solves: usize,
    time_per_solve_us: f64,
    /// Seed 002's tables per leg (`src/analysis/ik_tables.rs`); a leg without targets is left out.
    seed002: SidesJson,
}

#[derive(Serialize)]
struct SidesJson {
    #[serde(skip_serializing_if = "Option::is_none")]
    right: Option<SideJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    left: Option<SideJson>,
}

#[derive(Serialize)]
struct AxesJson {
    hip_flexion: f64,
    hip_abduction: f64,
    hip_rotation: f64,
    knee_flexion: f64,
}

impl AxesJson {
    fn new(axes: [MaxMean; 4], pick: fn(MaxMean) -> f64) -> Self {
        let [hip_flexion, hip_abduction, hip_rotation, knee_flexion] = axes.map(pick);
        AxesJson { hip_flexion, hip_abduction, hip_rotation, knee_flexion }
    }
}

#[derive(Serialize)]
struct SideJson {
    solves: usize,
    position_error_max_mm: f64,
    position_error_mean_mm: f64,
    angle_error_max_deg: AxesJson,
    angle_error_mean_deg: AxesJson,
    knee_jump_max_mm: f64,
    knee_jump_mean_mm: f64,
    ankle_jump_max_mm: f64,
    ankle_jump_mean_mm: f64,
    knee_jitter_max_mm: f64,
    knee_jitter_mean_mm: f64,
    ankle_jitter_max_mm: f64,
    ankle_jitter_mean_mm: f64,
    angle_pass: bool,
    jump_pass: bool,
    position_pass: bool,
    pass: bool,
}

impl SideJson {
    fn new(s: &SideTable) -> Self {
        SideJson {
            solves: s.solves,
            position_error_max_mm: s.position_error_mm.max,
            position_error_mean_mm: s.position_error_mm.mean,
            angle_error_max_deg: AxesJson::new(s.angle_error_deg, |a| a.max),
            angle_error_mean_deg: AxesJson::new(s.angle_error_deg, |a| a.mean),
            knee_jump_max_mm: s.knee_jump_mm.max,
            knee_jump_mean_mm: s.knee_jump_mm.mean,
            ankle_jump_max_mm: s.ankle_jump_mm.max,
            ankle_jump_mean_mm: s.ankle_jump_mm.mean,
            knee_jitter_max_mm: s.knee_jitter_mm.max,
            knee_jitter_mean_mm: s.knee_jitter_mm.mean,
            ankle_jitter_max_mm: s.ankle_jitter_mm.max,
            ankle_jitter_mean_mm: s.ankle_jitter_mm.mean,
            angle_pass: s.angle_pass(),
            jump_pass: s.jump_pass(),
            position_pass: s.position_pass(),
            pass: s.pass(),
        }
    }
}

fn write_json(out: &mut impl Write, rows: &[(IkSolverKind, IkSummary)], sides: &[SolverSides]) -> io::Result<()> {
    for ((solver, s), (_, tables)) in rows.iter().zip(sides) {
        let side = |which: Side| tables.iter().find(|t| t.side == which).map(SideJson::new);
        let line = JsonLine {
            ankle_jump_max_frame: s.ankle_jump_max_frame,
            ankle_jump_max_mm: s.ankle_jump_max_mm,
            ankle_jump_mean_mm: s.ankle_jump_mean_mm,
            iterations_max: s.iterations_max,
            iterations_mean: s.iterations_mean,
            knee_direction_error_max_deg: s.knee_direction_error_max_deg,
            knee_direction_error_mean_deg: s.knee_direction_error_mean_deg,
            knee_jump_max_frame: s.knee_jump_max_frame,
            knee_jump_max_mm: s.knee_jump_max_mm,
            knee_jump_mean_mm: s.knee_jump_mean_mm,
            limit_violations: s.limit_violations,
            position_error_max_mm: s.position_error_max_mm,
            position_error_mean_mm: s.position_error_mean_mm,
            reached: s.reached,
            solver: solver.name(),
            solves: s.solves,
            time_per_solve_us: s.time_per_solve_us,
            seed002: SidesJson { right: side(Side::Right), left: side(Side::Left) },
        };
        writeln!(out, "{}", serde_json::to_string(&line).map_err(io::Error::other)?)?;
    }
    Ok(())
}
