//! The `gaitlab` command line: parsing (clap) and the headless commands.

use crate::config::{self, ConfigErrors, presets, render};
use crate::error::{Error, Result};
use crate::model::params::WalkParams;
use crate::model::walk::Walker;
use crate::output::{self, FileTarget, joint_table};

mod args;
mod common;
mod compare;
mod figures;
mod fit;
mod ik;
mod leading;
mod optimise;
mod snapshot;
pub use args::{Cli, Command, LabArgs};
use args::{LAB_FPS, LAB_MARKER};
use common::{Progress, in_range};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Prints a command's error the way the interface asks: config problems one located line
/// each, a walk's problem after its config's path, anything else after `gaitlab COMMAND:`.
fn print_error(command: &str, e: &Error) {
    match e {
        Error::Config(errors) => {
            for line in &errors.0 {
                eprintln!("{line}");
            }
        }
        Error::Walk { .. } => eprintln!("{e}"),
        _ if command.is_empty() => eprintln!("gaitlab: {e}"),
        _ => eprintln!("gaitlab {command}: {e}"),
    }
}

/// A walker for `params`, its problems blamed on the config at `path`.
fn walker_for(path: &Path, params: &WalkParams) -> Result<Walker> {
    Walker::new(params).map_err(|source| Error::Walk { config: path.to_path_buf(), source })
}

/// Runs the parsed command line; returns the exit code (0, 1 or 2), messages printed.
#[must_use]
pub fn run(mut cli: Cli) -> u8 {
    if let Err(e) = leading::hoist(&mut cli) {
        print_error("", &e);
        return e.exit_code();
    }
    let (command, result) = match cli.command {
        None => return lab(cli.config, &cli.lab),
        Some(Command::Tui { config, lab: args }) => return lab(config.or(cli.config), &args),
        Some(Command::Check { configs, sets }) => ("check", check(&configs, &sets)),
        Some(Command::Simulate { config, cycles, fps, out, sets }) => {
            ("simulate", simulate(&config, cycles, fps, out.as_deref(), &sets))
        }
        Some(Command::Optimise { config, steps, json, sets }) => {
            ("optimise", optimise::run(&config, steps, json, &sets))
        }
        Some(Command::Report { config, out, force, cycles, compare, ik_solvers, sets }) => (
            "report",
            report(&ReportArgs {
                path: &config,
                out: out.as_deref(),
                force,
                cycles,
                compare: &compare,
                ik_solvers: ik_solvers.as_deref(),
                sets: &sets,
            }),
        ),
        Some(Command::Ik { config, solvers, cycles, fps, json, targets, sets }) => {
            ("ik", ik::run(&config, solvers.as_deref(), cycles, fps, json, targets.as_deref(), &sets))
        }
        Some(Command::Snapshot { paths, update, json, junit, tolerance, plot, sets }) => (
            "snapshot",
            snapshot::run(&snapshot::Args {
                paths: &paths,
                update,
                json,
                junit: junit.as_deref(),
                tolerance: tolerance.as_deref(),
                plot: plot.as_deref(),
                sets: &sets,
            }),
        ),
        Some(Command::Fit { config, reference, out, evaluations, cycles, json, sets }) => {
            let options = fit::Args { reference: reference.as_deref(), out: out.as_deref(), evaluations, cycles, json };
            ("fit", fit::run(&config, &options, &sets))
        }
        Some(Command::Compare { config, reference, json, sets }) => {
            ("compare", compare::run(&config, reference.as_deref(), json, &sets))
        }
        Some(Command::Figures { config, out, force, sets }) => (
            "figures",
            figures::run(&figures::Args { config: config.as_deref(), out: out.as_deref(), force, sets: &sets }),
        ),
        Some(Command::Presets) => {
            for (name, text) in presets::PRESETS {
                println!("{name:<12} {}", presets::description(text));
            }
            ("presets", Ok(()))
        }
        Some(Command::Init { preset }) => ("init", init(preset.as_deref())),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            print_error(command, &e);
            e.exit_code()
        }
    }
}

fn lab(config: Option<PathBuf>, args: &LabArgs) -> u8 {
    let name = args.marker.as_deref().unwrap_or(LAB_MARKER);
    let Some(&(_, marker)) = crate::tui::MARKERS.iter().find(|(n, _)| *n == name) else {
        let names: Vec<&str> = crate::tui::MARKERS.iter().map(|(n, _)| *n).collect();
        eprintln!("gaitlab: --marker {name}: unknown; valid: {}", names.join(", "));
        return 2;
    };
    let code = crate::tui::run(&crate::tui::Options {
        config,
        sets: args.sets.clone(),
        fps: args.fps.unwrap_or(LAB_FPS),
        marker,
        mouse: !args.no_mouse,
    });
    u8::try_from(code).unwrap_or(1)
}

/// `gaitlab report`'s arguments.
struct ReportArgs<'a> {
    path: &'a Path,
    out: Option<&'a Path>,
    force: bool,
    cycles: Option<u32>,
    compare: &'a [PathBuf],
    ik_solvers: Option<&'a str>,
    sets: &'a [String],
}

fn report(args: &ReportArgs<'_>) -> Result<()> {
    use std::io::IsTerminal;
    let (source_text, params) = config::load_with_text(args.path, args.sets)?;
    let ik_solvers = match args.ik_solvers.map(ik::parse_solvers).transpose() {
        Ok(list) => list.unwrap_or_default(),
        Err(message) => return Err(Error::Usage(format!("--ik-solvers: {message}"))),
    };
    // A report records every frame with its full-body pose for its tables and plots, so the
    // bound keeps its memory and time in check (benches/README.md); simulate streams any length.
    // The first cycle is start-up and a steady cycle needs the two heel strikes after it; at
    // 3 cycles the third strike can fall just past the last frame (4 of the 11 shipped configs
    // failed there), so 4 is the least that always measures.
    let valid = "4 to 1000 (the first cycle is start-up; for longer walks use `gaitlab simulate`)";
    let cycles = in_range("--cycles", args.cycles.unwrap_or(params.sim.cycles), 4..=1000, valid)?;
    let mut others = Vec::new();
    for other in args.compare {
        let params = config::load(other, args.sets)?;
        others.push((other.file_stem().map_or("other".into(), |s| s.to_string_lossy().into_owned()), params));
    }
    let out = args.out.map_or_else(|| crate::report::default_out(args.path), Path::to_path_buf);
    let target = crate::report::resolve_out(&out, args.force)?;
    output::pending::remove_on_signal()
        .map_err(|e| Error::Output(output::OutputError::Failed(format!("cannot watch signals: {e}"))))?;
    let input = crate::report::ReportInput {
        name: args.path.file_stem().map_or("config".into(), |s| s.to_string_lossy().into_owned()),
        source_text: &source_text,
        params: &params,
        cycles,
        fps: params.sim.fps,
        compare: others,
        ik_solvers,
    };
    let tty = io::stderr().is_terminal();
    let mut progress = |stage: &str| {
        if tty {
            eprintln!("gaitlab report: {stage}");
        }
    };
    crate::report::write_report(&input, &target, &mut progress)?;
    println!("{}", out.display());
    Ok(())
}

fn check(configs: &[PathBuf], sets: &[String]) -> Result<()> {
    let mut problems = Vec::new();
    for path in configs {
        // `[keys]` is the lab's, and checked exactly as the lab checks it: a config `check`
        // calls ok must open in the lab.
        let keys = |text: &str| crate::tui::keys::KeyMap::from_config(text, &path.display().to_string()).map(|_| ());
        match config::load_with_text(path, sets).and_then(|(text, _)| keys(&text)) {
            Ok(()) => println!("ok: {}", path.display()),
            Err(e) => problems.extend(e.0),
        }
    }
    if problems.is_empty() { Ok(()) } else { Err(Error::Config(ConfigErrors(problems))) }
}

fn simulate(path: &Path, cycles: Option<u32>, fps: Option<f64>, out: Option<&Path>, sets: &[String]) -> Result<()> {
    let params = config::load(path, sets)?;
    let fps = in_range("--fps", fps.unwrap_or(params.sim.fps), 10.0..=1000.0, "10 to 1000 frames/s")?;
    let cycles = in_range("--cycles", cycles.unwrap_or(params.sim.cycles), 1..=100_000, "1 to 100000")?;
    let target = out.map_or(Ok(FileTarget::Stdout), FileTarget::resolve)?;
    let mut walker = walker_for(path, &params)?;
    let frames = (f64::from(cycles) * walker.resolved().cycle_s * fps).round() as u64;
    let mut progress = Progress::new("simulate", frames);
    let mut write = |out: &mut dyn Write| -> io::Result<()> {
        joint_table::write_header(out)?;
        let mut line = String::with_capacity(512);
        for i in 0..=frames {
            if i > 0 {
                walker.advance(1.0 / fps);
                // Rows are streamed out; the plans behind them need not stay, so a long
                // run's memory is flat (frames are the same with and without trimming).
                walker.keep_recent_history(crate::model::walk::RECENT_STEPS);
            }
            joint_table::format_row(&walker.frame(i), &mut line);
            line.push('\n');
            out.write_all(line.as_bytes())?;
            progress.at(i);
        }
        out.flush()
    };
    output::pending::remove_on_signal()
        .map_err(|e| Error::Output(output::OutputError::Failed(format!("cannot watch signals: {e}"))))?;
    let result = output::write_file(&target, &mut write);
    progress.done();
    Ok(result?)
}

fn init(preset: Option<&str>) -> Result<()> {
    let name = preset.unwrap_or("default");
    let Some(text) = presets::text(name) else {
        let names: Vec<&str> = presets::PRESETS.iter().map(|(n, _)| *n).collect();
        let hint = config::schema::did_you_mean(name, names.iter().copied())
            .map_or(String::new(), |n| format!("did you mean `{n}`? "));
        return Err(Error::Usage(format!("no preset `{name}`; {hint}presets: {}", names.join(", "))));
    };
    let params = presets::params(name).expect("listed")?;
    let description = if name == "default" { presets::DEFAULT_DESCRIPTION } else { presets::description(text) };
    print!("{}", render::render(&params, &format!("preset: {description}")));
    Ok(())
}
