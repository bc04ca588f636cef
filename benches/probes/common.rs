//! What every probe shares: its command line and the embedded presets.
//!
//! `cargo bench --bench NAME -- ARGS` runs a probe with ARGS followed by a `--bench` of
//! cargo's own, so that flag is dropped here. A wrong command line prints the probe's usage
//! and exits 2, like the gaitlab binary.

use gaitlab::config::presets;
use gaitlab::model::params::WalkParams;
use std::process::exit;

/// The probe's arguments without cargo's `--bench`. `-h` / `--help` prints `usage` and exits
/// 0; more than `max` arguments print it and exit 2.
pub fn args(usage: &str, max: usize) -> Vec<String> {
    let args: Vec<String> = std::env::args().skip(1).filter(|a| a != "--bench").collect();
    if args.iter().any(|a| a == "-h" || a == "--help") {
        println!("usage: {usage}");
        exit(0);
    }
    if args.len() > max {
        usage_exit(usage, &format!("expected at most {max} argument(s), got {}: {}", args.len(), args.join(" ")));
    }
    args
}

/// Prints `problem` and the usage line on stderr and exits 2.
pub fn usage_exit(usage: &str, problem: &str) -> ! {
    eprintln!("{problem}\nusage: {usage}");
    exit(2)
}

/// The parameters of the embedded preset `name`; an unknown name is a usage error.
#[allow(dead_code, reason = "the terminal probes walk the lab's own default and never call it")]
pub fn preset(usage: &str, name: &str) -> WalkParams {
    match presets::params(name) {
        Some(Ok(params)) => params,
        Some(Err(e)) => {
            // The presets are the repository's own files: a broken one is a bug, not input.
            eprintln!("preset {name} does not load:\n{e}");
            exit(1)
        }
        None => {
            let names: Vec<&str> = presets::PRESETS.iter().map(|(n, _)| *n).collect();
            usage_exit(usage, &format!("no preset {name:?}; presets: {}", names.join(", ")))
        }
    }
}
