//! `gaitlab snapshot` over the 11 shipped configs (issue 20: ≤ 0.5 s on 2 cores): each walked
//! for its `sim.cycles`, measured and compared with its `NAME.snap.json`, configs in parallel.
//! Beside it the normative comparison and the fit, which measure walks the same way (issue 12:
//! `compare` on a 10-cycle walk ≤ 50 ms, `fit` at one speed ≤ 10 s).

use criterion::{Criterion, criterion_group, criterion_main};
use std::path::PathBuf;

fn snapshot_corpus(c: &mut Criterion) {
    let configs = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("configs");
    let options = gaitlab::snapshot::Options::default();
    let mut group = c.benchmark_group("snapshot");
    group.sample_size(10);
    group.bench_function("shipped_configs", |b| {
        b.iter(|| gaitlab::snapshot::run(std::slice::from_ref(&configs), &options).unwrap());
    });
    group.finish();
}

fn normative(c: &mut Criterion) {
    use gaitlab::normative::{self, References};
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
    let params = gaitlab::config::load(&path, &[]).unwrap();
    let reference = References::built_in();
    let mut group = c.benchmark_group("normative");
    group.sample_size(10);
    group.bench_function("compare_default_10_cycles", |b| {
        b.iter(|| normative::compare(&path, &params, reference).unwrap());
    });
    group.bench_function("fit_default_600_walks", |b| {
        let options = gaitlab::fit::FitOptions::default();
        b.iter(|| gaitlab::fit::fit(&path, &params, reference, options).unwrap());
    });
    group.finish();
}

criterion_group!(benches, snapshot_corpus, normative);
criterion_main!(benches);
