//! Users' own blocks on the loop's signal bus (`simulation::Block`): each is one type and
//! one line (`Simulation::builder(..).block(position, block)`), flown here.

use std::sync::Arc;

mod common;

use deckland::recording::TimeSeriesRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{
    Block, BlockPosition, SetupError, SignalId, Signals, Simulation, SIGNALS,
};

/// Reads every signal available at its position and writes the same values back: the
/// loop with it must fly exactly as without.
#[derive(Debug)]
struct PassThrough(&'static [SignalId]);

impl Block for PassThrough {
    fn name(&self) -> &'static str {
        "pass_through"
    }
    fn reads(&self) -> &'static [SignalId] {
        self.0
    }
    fn writes(&self) -> &'static [SignalId] {
        self.0
    }
    fn outputs(&self, _: f64, _: &[f64], bus: &mut Signals) {
        for &id in self.0 {
            if let Some(value) = bus.get(id) {
                bus.set(id, value);
            }
        }
    }
}

/// A steady downdraft of `mps` (positive down) within the last `range_m` before the
/// ship's pitch centre.
#[derive(Debug)]
struct Downdraft {
    mps: f64,
    range_m: f64,
}

impl Block for Downdraft {
    fn name(&self) -> &'static str {
        "downdraft"
    }
    fn reads(&self) -> &'static [SignalId] {
        &[SignalId::DistanceAft]
    }
    fn writes(&self) -> &'static [SignalId] {
        &[SignalId::WindZ]
    }
    fn outputs(&self, _: f64, _: &[f64], bus: &mut Signals) {
        if bus.distance_aft_m < self.range_m {
            bus.wind.z_mps += self.mps;
        }
    }
}

/// A first-order low-pass filter on the measured pitch attitude, with its own state.
#[derive(Debug)]
struct AttitudeFilter {
    time_constant_s: f64,
    initial_rad: f64,
}

impl Block for AttitudeFilter {
    fn name(&self) -> &'static str {
        "attitude_filter"
    }
    fn state_names(&self) -> &'static [&'static str] {
        &["filtered_theta_rad"]
    }
    fn initial_state(&self, state: &mut [f64]) {
        state[0] = self.initial_rad;
    }
    fn reads(&self) -> &'static [SignalId] {
        &[SignalId::ThetaMeasured]
    }
    fn writes(&self) -> &'static [SignalId] {
        &[SignalId::ThetaMeasured]
    }
    fn outputs(&self, _: f64, state: &[f64], bus: &mut Signals) {
        bus.theta_measured_rad = state[0];
    }
    fn derivative(&self, _: f64, state: &[f64], bus: &Signals, rate: &mut [f64]) {
        // The bus holds this block's output; the filter's input is the attitude the
        // sensor read, θ + its noise: recompute it from the true attitude (noise-free
        // scenario below).
        rate[0] = (bus.theta_rad - state[0]) / self.time_constant_s;
    }
}

use common::fly_recorded as fly;

#[test]
fn a_block_that_changes_nothing_flies_bit_for_bit_as_the_loop_without_it() {
    let scenario = Scenario::default();
    let plain = fly(Simulation::new(&scenario).expect("valid"));
    // At each position, every signal available there, read and written back.
    let mut with_blocks = Simulation::builder(&scenario);
    for position in [
        BlockPosition::AirMass,
        BlockPosition::Sensors,
        BlockPosition::Commands,
    ] {
        let available: Vec<SignalId> = position.available();
        let ids: &'static [SignalId] = Box::leak(available.into_boxed_slice());
        with_blocks = with_blocks.block(position, Arc::new(PassThrough(ids)));
    }
    let passed = fly(with_blocks
        .build()
        .expect("each reads what is written before it"));
    assert_eq!(passed.summary, plain.summary);
    assert_eq!(passed.samples, plain.samples);
    assert_eq!(passed.events, plain.events);
}

#[test]
fn a_downdraft_block_reaches_the_recorded_wind_and_pushes_the_hook_below_the_path() {
    let scenario = Scenario::default();
    let plain = fly(Simulation::new(&scenario).expect("valid"));
    let block = Downdraft {
        mps: 2.0,
        range_m: 900.0,
    };
    let gusted = fly(Simulation::builder(&scenario)
        .block(BlockPosition::AirMass, Arc::new(block))
        .build()
        .expect("valid"));
    // Before the downdraft the two runs are one; inside it the recorded wind is 2 m/s
    // further down (at the first sample inside, the aircraft has flown a few steps in
    // the downdraft and is a few µm elsewhere: the rest of the wind differs by less than
    // 1e-3 m/s).
    let first_inside = plain
        .samples
        .iter()
        .position(|s| s.distance_aft_m < 900.0)
        .expect("the approach passes 900 m");
    assert_eq!(
        plain.samples[..first_inside],
        gusted.samples[..first_inside]
    );
    let (p, g) = (&plain.samples[first_inside], &gusted.samples[first_inside]);
    assert!(
        (g.wind.z_mps - p.wind.z_mps - 2.0).abs() < 1e-3,
        "{} {} at {} {}",
        g.wind.z_mps,
        p.wind.z_mps,
        g.distance_aft_m,
        p.distance_aft_m
    );
    // Air sinking at 2 m/s carries the aircraft down before the loops respond: within the
    // next second the hook falls below its undisturbed height.
    let later = first_inside + 100;
    assert!(gusted.samples[later].hook_h_m < plain.samples[later].hook_h_m - 0.2);
}

#[test]
fn a_block_with_its_own_state_is_integrated_with_the_loop() {
    let mut scenario = Scenario::default();
    scenario.environment.pitch_noise.enabled = false;
    let theta0 = Simulation::new(&scenario)
        .expect("valid")
        .signals()
        .theta_rad;
    let filter = AttitudeFilter {
        time_constant_s: 0.05,
        initial_rad: theta0,
    };
    let simulation = Simulation::builder(&scenario)
        .block(BlockPosition::Sensors, Arc::new(filter))
        .build()
        .expect("valid");
    let layout = simulation.system().layout().states.clone();
    let index = (0..layout.dimension())
        .find(|&i| layout.state_name(i).as_deref() == Some("attitude_filter.filtered_theta_rad"))
        .expect("the block's state is laid out under its name");
    let mut recorder = TimeSeriesRecorder::every(0.01);
    let mut simulation = simulation;
    for _ in 0..5000 {
        simulation.step(&mut recorder);
    }
    // The recorded measurement is the filter's state, which lags the attitude.
    let state = simulation.state()[index];
    assert_eq!(simulation.signals().theta_measured_rad, state);
    let last = recorder.samples.last().expect("sampled");
    assert!((last.theta_measured_rad - last.theta_rad).abs() < 0.01);
    assert!(recorder
        .samples
        .iter()
        .any(|s| s.theta_measured_rad != s.theta_rad));
}

#[test]
fn a_block_that_reads_a_signal_before_it_is_written_is_refused_naming_it() {
    #[derive(Debug)]
    struct ReadsAirspeed;
    impl Block for ReadsAirspeed {
        fn name(&self) -> &'static str {
            "reads_airspeed"
        }
        fn reads(&self) -> &'static [SignalId] {
            &[SignalId::Airspeed]
        }
        fn writes(&self) -> &'static [SignalId] {
            &[]
        }
        fn outputs(&self, _: f64, _: &[f64], _: &mut Signals) {}
    }
    let error = Simulation::builder(&Scenario::default())
        .block(BlockPosition::AirMass, Arc::new(ReadsAirspeed))
        .build()
        .expect_err("air data come after the air mass");
    let SetupError::Block(error) = &error else {
        panic!("expected a placement error, got {error}");
    };
    assert_eq!(error.signal, "airspeed_mps");
    assert!(error.to_string().contains("reads_airspeed"));
    assert!(SIGNALS.iter().any(|s| s.name == error.signal));
}
