//! One full adverse approach: 1 ms RK4, every disturbance, O-PD, summary recording only;
//! with the 3-DOF aircraft (the default), with the 6-DOF (`[aircraft] model = "6dof"`),
//! and the 3-D approach of `scenarios/crosswind.toml` (6-DOF, angled deck, moving ship,
//! moderate sea, 5 m/s crosswind), with its 80 Hz flight computer and without one.

#![allow(missing_docs)] // criterion_group! generates undocumented items

use criterion::measurement::WallTime;
use criterion::{criterion_group, criterion_main, BenchmarkGroup, Criterion};
use deckland::aircraft::PlantModel;
use deckland::recording::SummaryRecorder;
use deckland::scenario::{load_scenario, Scenario};
use deckland::simulation::Simulation;
use std::hint::black_box;

/// Benchmarks, as `name`, one flight of `scenario` recording its summary only.
fn bench_summary_run(group: &mut BenchmarkGroup<'_, WallTime>, name: &str, scenario: &Scenario) {
    group.bench_function(name, |b| {
        b.iter(|| {
            Simulation::new(black_box(scenario))
                .expect("valid")
                .run(&mut SummaryRecorder)
        })
    });
}

fn approach(c: &mut Criterion) {
    let scenario = Scenario::default();
    let simulated_s = Simulation::new(&scenario)
        .expect("default scenario is valid")
        .run(&mut SummaryRecorder)
        .end_time_s;
    println!("simulated approach length: {simulated_s:.2} s");
    let mut group = c.benchmark_group("approach");
    group.sample_size(30);
    bench_summary_run(&mut group, "adverse O-PD, summary only", &scenario);
    let mut six_dof = scenario;
    six_dof.aircraft.model = PlantModel::SixDof;
    bench_summary_run(
        &mut group,
        "adverse O-PD, summary only, 6-DOF aircraft",
        &six_dof,
    );
    let crosswind = load_scenario(
        include_str!("../../../scenarios/crosswind.toml"),
        "crosswind.toml",
    )
    .expect("scenarios/crosswind.toml is valid");
    let simulated_3d_s = Simulation::new(&crosswind)
        .expect("valid")
        .run(&mut SummaryRecorder)
        .end_time_s;
    println!("simulated 3-D approach length: {simulated_3d_s:.2} s");
    bench_summary_run(
        &mut group,
        "3-D approach (crosswind.toml), summary only",
        &crosswind,
    );
    // The same approach without a flight computer: the lateral guidance and the ship's
    // view at every step rather than at the 80 Hz frames (issue 27's speed).
    let mut every_step = crosswind;
    every_step.control.flight_computer_rate_hz = None;
    bench_summary_run(
        &mut group,
        "3-D approach (crosswind.toml), no flight computer, summary only",
        &every_step,
    );
    group.bench_function("setup only (trim, linearise, build)", |b| {
        b.iter(|| Simulation::new(black_box(&scenario)).expect("valid"))
    });
    group.finish();
}

criterion_group!(benches, approach);
criterion_main!(benches);
