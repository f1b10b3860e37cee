//! Cost of one plant derivative evaluation and one RK4 step of the open-loop plant.

#![allow(missing_docs)] // criterion_group! generates undocumented items

use criterion::{criterion_group, criterion_main, Criterion};
use deckland::aircraft::{Aircraft, AircraftCommands, OpenLoopAircraft, Wind};
use deckland::analysis::{trim, TrimRequest};
use deckland::integration::{rk4_step, OdeSystem};
use std::hint::black_box;

fn plant(c: &mut Criterion) {
    let aircraft = Aircraft::default();
    let point = trim(&aircraft, &TrimRequest::default()).expect("default trim exists");
    let wind = Wind {
        x_mps: -10.0,
        z_mps: 0.3,
        ..Default::default()
    };
    let state = point.state(0.0, 100.0, &wind);
    let commands = AircraftCommands {
        elevator_rad: point.elevator_rad + 0.01,
        thrust_n: point.thrust_n,
    };
    c.bench_function("plant derivative", |b| {
        b.iter(|| aircraft.derivative(black_box(&state), black_box(&commands), black_box(&wind)))
    });
    let system = OpenLoopAircraft {
        aircraft,
        commands,
        wind,
    };
    let x = state.to_array();
    c.bench_function("plant rk4 step (1 ms)", |b| {
        b.iter(|| rk4_step(black_box(&system), 0.0, black_box(&x), 1e-3))
    });
    c.bench_function("trim (Newton)", |b| {
        b.iter(|| trim(black_box(&aircraft), black_box(&TrimRequest::default())))
    });
    let _ = system.derivative(0.0, &x);
}

criterion_group!(benches, plant);
criterion_main!(benches);
