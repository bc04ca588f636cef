//! The command line's shape: the commands and options clap parses (their help is the
//! `--help` text), apart from what runs them (`cli`), so that helpers reading the parsed
//! line (`leading`) import it without importing the runner.

use clap::{Parser, Subcommand};
use std::path::PathBuf;

/// The lab's redraws per second when `--fps` is not given.
pub(crate) const LAB_FPS: f64 = 30.0;

/// The lab's marker when `--marker` is not given.
pub(crate) const LAB_MARKER: &str = "braille";

/// gaitlab — a terminal lab for procedural human walking.
#[derive(Debug, Parser)]
#[command(name = "gaitlab", version, about, long_about = None)]
pub struct Cli {
    /// Config for the terminal lab (the embedded default without one).
    pub config: Option<PathBuf>,
    /// The lab's options, when started without a command.
    #[command(flatten)]
    pub lab: LabArgs,
    /// The command; without one, the terminal lab.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// Options of the terminal lab. The redraw rate and marker are `None` where not written (so a
/// value written before a command is told from none, even the default's own): the lab takes
/// 30 redraws a second and braille then.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct LabArgs {
    /// Redraws per second while walking (nothing is drawn when paused and idle) [default: 30]
    #[arg(long)]
    pub fps: Option<f64>,
    /// How curves and the figure are drawn: braille, halfblock or block (for fonts without braille) [default: braille]
    #[arg(long)]
    pub(crate) marker: Option<String>,
    /// Leave the mouse to the terminal (no clicking, dragging or wheel in the lab)
    #[arg(long)]
    pub no_mouse: bool,
    /// Override a key: --set walk.speed_mps=1.4 (repeatable)
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub sets: Vec<String>,
}

/// The commands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// The terminal lab (the same as no command)
    Tui {
        /// Config file [default: the embedded default]
        config: Option<PathBuf>,
        /// The lab's options.
        #[command(flatten)]
        lab: LabArgs,
    },
    /// Validate configs: prints `ok: PATH` or one line per problem, PATH:LINE:COL: key: message
    Check {
        /// Config files.
        #[arg(required = true)]
        configs: Vec<PathBuf>,
        /// Override a key: --set walk.speed_mps=1.4 (dotted TOML path, TOML value; repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// Run the walk headless and write the joint table as CSV
    Simulate {
        /// Config file.
        config: PathBuf,
        /// Gait cycles to simulate [default: the config's sim.cycles]
        #[arg(long)]
        cycles: Option<u32>,
        /// Frames per second [default: the config's sim.fps]
        #[arg(long)]
        fps: Option<f64>,
        /// Write the CSV here instead of to stdout: a regular file is replaced atomically
        /// (keeping its mode), a device or FIFO is written through, - is stdout
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a key: --set walk.speed_mps=1.4 (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// Run the walk and print each step's pelvis choice (the pelvis-acceleration optimisation)
    Optimise {
        /// Config file.
        config: PathBuf,
        /// Steps to run [default: two per cycle of the config's sim.cycles]
        #[arg(long)]
        steps: Option<u32>,
        /// One JSON object a line (each step with all its candidates, then a summary line)
        #[arg(long)]
        json: bool,
        /// Override a key: --set optimiser.method="brent" (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// Write a report folder: summary.md/json, config.toml, joints, footfalls and optimisation tables
    Report {
        /// Config file.
        config: PathBuf,
        /// Report folder, by default `reports/<config stem>`; a previous report there is
        /// replaced, any other folder is refused. (`help` is spelled out because rustdoc would
        /// read the help's `<config stem>` as an HTML tag.)
        #[arg(
            long,
            help = "Report folder [default: reports/<config stem>]; a previous report there is replaced, any other folder is refused"
        )]
        out: Option<PathBuf>,
        /// Replace a previous report even if it holds files a report does not write
        #[arg(long)]
        force: bool,
        /// Gait cycles to simulate [default: the config's sim.cycles]
        #[arg(long)]
        cycles: Option<u32>,
        /// Overlay another config's walk in the plots and put its figures beside (repeatable)
        #[arg(long)]
        compare: Vec<PathBuf>,
        /// IK solvers for ik.csv and the ik plot, comma-separated [default: the walk's ik.solver, with analytic beside it]
        #[arg(long, value_name = "LIST")]
        ik_solvers: Option<String>,
        /// Override a key: --set walk.speed_mps=1.4 (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// Solve the walk's IK targets with each solver; print error, iteration and timing tables
    Ik {
        /// Config file.
        config: PathBuf,
        /// Solvers to compare, comma-separated: analytic, ccd, fabrik, jacobian_dls, gradient [default: all]
        #[arg(long, value_name = "LIST")]
        solvers: Option<String>,
        /// Gait cycles whose targets are solved [default: the config's sim.cycles]
        #[arg(long)]
        cycles: Option<u32>,
        /// Frames per second [default: the config's sim.fps]
        #[arg(long)]
        fps: Option<f64>,
        /// One JSON object a line, one per solver
        #[arg(long)]
        json: bool,
        /// Target set: `walk` (the walk's own, warm-started in frame order) or `random:N[:SEED]` (N seeded targets for the right leg around a standing hip, reachable within the joint ranges, each solved from rest) [default: walk]
        #[arg(long, value_name = "SET")]
        targets: Option<String>,
        /// Override a key: --set ik.limits=false (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// Snapshot tests: compare each config's walk (summary figures, mean joint curves) with NAME.snap.json beside it
    Snapshot {
        /// Configs: files, or folders (every *.toml directly in them, sorted).
        #[arg(required = true, value_name = "PATH")]
        paths: Vec<PathBuf>,
        /// Write missing snapshots and rewrite drifted ones (then review the diff and commit them)
        #[arg(long)]
        update: bool,
        /// One JSON object a line, one per config: config, status, snapshot, moved
        #[arg(long)]
        json: bool,
        /// Also write the result as JUnit XML (one testcase per config) to FILE
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Tolerances: a TOML file with a `[tolerance]` table (kinds like angles_deg, or figure keys)
        #[arg(long, value_name = "FILE")]
        tolerance: Option<PathBuf>,
        /// For each config that moved, write DIR/STEM.png (its config's file stem): stored against new joint curves
        #[arg(long, value_name = "DIR")]
        plot: Option<PathBuf>,
        /// Override a key in every config: --set sim.cycles=6 (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// Calibrate a config to measured human gait: move the keys that shape the joint curves to bring hip, knee and ankle closest to the reference, skate, ground and reach kept
    Fit {
        /// Config file.
        config: PathBuf,
        /// A reference CSV in the built-in file's columns [default: Fukuchi et al. 2018, data/normative/]
        #[arg(long, value_name = "FILE")]
        reference: Option<PathBuf>,
        /// Write the fitted config (the input with the fitted keys set, comments kept) to FILE; `-` for stdout
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
        /// Walks the search may cost, 10 to 5000
        #[arg(long, default_value_t = 600)]
        evaluations: u32,
        /// Gait cycles of each walk, 4 to 50 (a reach failure in a later cycle is not seen)
        #[arg(long, default_value_t = 10)]
        cycles: u32,
        /// One JSON object: keys, costs and curves before and after
        #[arg(long)]
        json: bool,
        /// Override a key: --set walk.speed_mps=1.0 (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// The walk's joint curves against measured human gait (the reference's mean +- SD, read every 2 % of the cycle); above the table the walk's cadence, stride, stance and pelvis vertical range beside people's, and on level ground the pelvis range the joint curves alone give through this body's legs
    Compare {
        /// Config file.
        config: PathBuf,
        /// A reference CSV in the built-in file's columns [default: Fukuchi et al. 2018, data/normative/]
        #[arg(long, value_name = "FILE")]
        reference: Option<PathBuf>,
        /// One JSON object a line, one per curve
        #[arg(long)]
        json: bool,
        /// Override a key: --set walk.speed_mps=1.245 (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// Regenerate the seed thesis's figures 6.2, 6.6, 6.8, 6.15, 6.17 (PNG, SVG, CSV) and table 6.1 (each part of a frame, timed on this machine) into a folder
    Figures {
        /// Config file [default: the embedded default]
        config: Option<PathBuf>,
        /// The folder (`help` spelled out: rustdoc would read `<config stem>` as an HTML tag)
        #[arg(
            long,
            help = "Folder [default: reports/figures, or reports/<config stem>-figures with a CONFIG]; a previous figures folder there is replaced, any other folder is refused"
        )]
        out: Option<PathBuf>,
        /// Replace a previous figures folder even if it holds files `figures` does not write
        #[arg(long)]
        force: bool,
        /// Override a key: --set terrain.rise_m=0.2 (repeatable)
        #[arg(long = "set", value_name = "KEY=VALUE")]
        sets: Vec<String>,
    },
    /// List the presets: name, then a short description
    Presets,
    /// Print a complete, commented config
    Init {
        /// Start from this preset (see `gaitlab presets`)
        #[arg(long)]
        preset: Option<String>,
    },
}
