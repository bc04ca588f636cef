//! Median time of one step's pelvis choice (fixed-rule cost + search) by each method, with
//! the cost reached and evaluations used, over the steps of several configs. Figures for
//! benches/README.md: `cargo run --release --example opt_hot`.
use gaitlab::config::presets;
use gaitlab::model::params::SearchMethod;
use gaitlab::model::walk::Walker;
use std::time::Instant;

fn main() {
    println!("| config | method | evaluations (mean) | cost (mean over steps) | vs thesis | median µs |");
    println!("|---|---|---|---|---|---|");
    for name in ["default", "stairs_up", "stairs_down", "slope_up", "slope_down", "rough"] {
        let p = presets::params(name).unwrap().unwrap();
        let mut w = Walker::new(&p).unwrap();
        let mut problems = Vec::new();
        let mut seen = 0;
        while problems.len() < 16 {
            w.advance(1.0 / 60.0);
            if w.step_plans().len() > seen {
                seen = w.step_plans().len();
                if seen > 2 {
                    problems.push((w.clone(), w.last_step_problem().unwrap().clone()));
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
