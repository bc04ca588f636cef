use gaitlab::config::presets;
use gaitlab::model::walk::Walker;
use std::time::Instant;
fn main() {
    let params = presets::params("default").unwrap().unwrap();
    let mut w = Walker::new(&params).unwrap();
    for _ in 0..1000 {
        w.advance(1.0 / 60.0);
    }
    let mut times = Vec::with_capacity(200_000);
    let mut s = 0.0;
    for _ in 0..200_000 {
        let t = Instant::now();
        w.advance(1.0 / 60.0);
        times.push(t.elapsed().as_nanos() as u64);
        s += w.pose().position[0].x;
    }
    times.sort();
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
