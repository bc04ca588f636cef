//! Probe: the default walk's plain frame update timed one frame at a time — median, p90,
//! p99, max and mean of 200 000 frames at 60 fps after 1 000 frames of start-up. Criterion
//! (`cargo bench --bench walk`) gives the mean; this gives the spread it hides. Figures in
//! benches/README.md, "Walk model".
//!
//! ```text
//! cargo bench --bench hot
//! ```
//!
//! Not run by a plain `cargo bench` (`bench = false` in Cargo.toml).

mod common;

use gaitlab::model::walk::Walker;
use std::time::Instant;

const USAGE: &str = "cargo bench --bench hot";

fn main() {
    common::args(USAGE, 0);
    let params = common::preset(USAGE, "default");
    let mut w = Walker::new(&params).expect("the default preset walks");
    for _ in 0..1000 {
        w.advance(1.0 / 60.0);
    }
    let mut times = Vec::with_capacity(200_000);
    // Summed and printed so the optimiser cannot drop the updates.
    let mut s = 0.0;
    for _ in 0..200_000 {
        let t = Instant::now();
        w.advance(1.0 / 60.0);
        times.push(t.elapsed().as_nanos() as u64);
        s += w.pose().position[0].x;
    }
    times.sort_unstable();
    let mean = times.iter().sum::<u64>() as f64 / times.len() as f64;
    println!(
        "median {} ns, p90 {} ns, p99 {} ns, max {} ns, mean {:.0} ns ({s:.0})",
        times[times.len() / 2],
        times[times.len() * 9 / 10],
        times[times.len() * 99 / 100],
        times[times.len() - 1],
        mean
    );
}
