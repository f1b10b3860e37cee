//! Campaign throughput: adverse approaches (the default scenario, summary only) flown by
//! `monte_carlo::run_campaign` on 1 and 2 threads, for the parallel speed-up.

#![allow(missing_docs)] // criterion_group! generates undocumented items

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use deckland::monte_carlo::{run_campaign, CampaignSpec, RunRecord};
use deckland::scenario::Scenario;
use std::hint::black_box;
use std::sync::atomic::AtomicBool;

/// Approaches per iteration: large enough that the pool's start-up and the unequal
/// lengths of the last runs matter little, small enough for ten samples in a minute.
const RUNS: u64 = 100;

fn campaign(c: &mut Criterion) {
    let spec = CampaignSpec::new(Scenario::default(), RUNS, 1);
    let never = AtomicBool::new(false);
    let no_progress = |_: &RunRecord| {};
    let mut group = c.benchmark_group("campaign");
    group.sample_size(10);
    group.throughput(Throughput::Elements(RUNS));
    for threads in [1, 2] {
        group.bench_function(
            format!("{RUNS} adverse approaches, {threads} threads"),
            |b| {
                b.iter(|| {
                    run_campaign(black_box(&spec), threads, &no_progress, &never)
                        .expect("valid campaign")
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, campaign);
criterion_main!(benches);
