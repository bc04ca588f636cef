//! Probe: one step's pelvis choice by each search method (`thesis`, `golden`, `brent`,
//! `joint`) on the same step problems — 16 consecutive steps after start-up of each of six
//! configs, every method given the same walker state. Each choice is the fixed rule's cost
//! (which sets the allowances) plus the search, timed 25 times a step; the table gives the
//! mean evaluations (the fixed rule's included), the mean cost reached, the cost against the
//! thesis method's and the median time. It prints the markdown table of benches/README.md,
//! "Pelvis optimisation".
//!
//! ```text
//! cargo bench --bench opt_hot
//! ```
//!
//! Not run by a plain `cargo bench` (`bench = false` in Cargo.toml).

mod common;

use gaitlab::model::params::SearchMethod;
use gaitlab::model::walk::Walker;
use std::time::Instant;

const USAGE: &str = "cargo bench --bench opt_hot";

fn main() {
    common::args(USAGE, 0);
    println!("| config | method | evaluations (mean) | cost (mean over steps) | vs thesis | median µs |");
    println!("|---|---|---|---|---|---|");
    for name in ["default", "stairs_up", "stairs_down", "slope_up", "slope_down", "rough"] {
        let p = common::preset(USAGE, name);
        let mut w = Walker::new(&p).expect("a preset walks");
        let mut problems = Vec::new();
        let mut seen = 0;
        while problems.len() < 16 {
            w.advance(1.0 / 60.0);
            if w.step_plans().len() > seen {
                seen = w.step_plans().len();
                // The first two steps are start-up.
                if seen > 2 {
                    problems.push((w.clone(), w.last_step_problem().expect("a step was just planned").clone()));
                }
            }
        }
        let mut thesis_cost = 0.0;
        for method in SearchMethod::ALL {
            let mut times = Vec::new();
            let (mut evals, mut cost) = (0usize, 0.0);
            for (walker, problem) in &problems {
                let mut q = problem.clone();
                q.settings.method = method;
                for rep in 0..25 {
                    let t = Instant::now();
                    let q2 = q.clone().with_allowance(walker);
                    let found = q2.search(walker);
                    times.push(t.elapsed().as_secs_f64() * 1e6);
                    if rep == 0 {
                        evals += found.len();
                        cost += found.iter().filter_map(|c| c.cost).fold(f64::INFINITY, f64::min);
                    }
                }
            }
            times.sort_by(f64::total_cmp);
            let n = problems.len() as f64;
            if method == SearchMethod::Thesis {
                thesis_cost = cost;
            }
            println!(
                "| {name} | {} | {:.1} | {:.1} | {:+.1}% | {:.0} |",
                method.name(),
                evals as f64 / n,
                cost / n,
                100.0 * (cost - thesis_cost) / thesis_cost,
                times[times.len() / 2]
            );
        }
    }
}
