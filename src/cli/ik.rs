//! `gaitlab ik`: every IK solver on the walk's own targets, side by side.

use super::common::{in_range, stdout_written};
use crate::analysis::ik::{IkSummary, IkTarget, collect_targets, random_targets, run_solver_from};
use crate::config;
use crate::error::{Error, Result};
use crate::model::ik::{IkSettings, IkSolverKind};
use serde_json::json;
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
    let rows: Vec<(IkSolverKind, IkSummary)> = solvers
        .iter()
        .map(|&solver| {
            if tty {
                eprintln!("gaitlab ik: {} on {} targets", solver.name(), targets.len());
            }
            let run = run_solver_from(&targets, solver, &r.ik, (r.dims.thigh, r.dims.shank), cold);
            (solver, run.summary(&targets))
        })
        .collect();
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
    let written = if json { write_json(&mut out, &rows) } else { write_tables(&mut out, path, &header, &r.ik, &rows) };
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

fn write_json(out: &mut impl Write, rows: &[(IkSolverKind, IkSummary)]) -> io::Result<()> {
    for (solver, s) in rows {
        let line = json!({
            "solver": solver.name(),
            "solves": s.solves,
            "reached": s.reached,
            "position_error_max_mm": s.position_error_max_mm,
            "position_error_mean_mm": s.position_error_mean_mm,
            "knee_direction_error_max_deg": s.knee_direction_error_max_deg,
            "knee_direction_error_mean_deg": s.knee_direction_error_mean_deg,
            "iterations_mean": s.iterations_mean,
            "iterations_max": s.iterations_max,
            "time_per_solve_us": s.time_per_solve_us,
            "limit_violations": s.limit_violations,
            "knee_jump_max_mm": s.knee_jump_max_mm,
            "knee_jump_max_frame": s.knee_jump_max_frame,
            "knee_jump_mean_mm": s.knee_jump_mean_mm,
            "ankle_jump_max_mm": s.ankle_jump_max_mm,
            "ankle_jump_max_frame": s.ankle_jump_max_frame,
            "ankle_jump_mean_mm": s.ankle_jump_mean_mm,
        });
        writeln!(out, "{line}")?;
    }
    Ok(())
}
