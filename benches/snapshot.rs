//! `gaitlab snapshot` over the 11 shipped configs (issue 20: ≤ 0.5 s on 2 cores): each walked
//! for its `sim.cycles`, measured and compared with its `NAME.snap.json`, configs in parallel.

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

criterion_group!(benches, snapshot_corpus);
criterion_main!(benches);
