//! Observer-bandwidth study and pitch-step comparison (GitHub issue 4; paper §5,
//! Fig. 10–12): prints markdown tables.
//!
//! Run with `cargo run --release -p deckland --example epsilon_study`.
//!
//! 1. For the O-PD with ε ∈ {0.01, 0.02, 0.03, 0.05, 0.08, 0.1, 0.15}: the 2 % settling
//!    time of a 2° pitch step and the elevator activity, in ideal conditions and in
//!    adverse conditions (median over seeds 1–5).
//! 2. O-PD (library default ε) against the PID for steps of 1°, 2° and 5°, ideal and
//!    adverse (median over seeds 1–5).
//! 3. Which disturbance keeps the 2° step from settling: adverse with the sensor noise
//!    off, or only its sinusoidal or its white part off; and the O-PD feeding back the
//!    observer's θ estimate instead of the measurement.
//!
//! Every run is `Mission::pitch_step(step, 6 s)`: the step at t = 1 s from level trim at
//! 69.1 m/s, recorded every 1 ms. Settling time: from the step to the last entry into
//! the ±2 % band around θ* + step, staying there at least 0.5 s to the end of the record
//! (`deckland::metrics`). A median over seeds counts an unsettled run as slower than
//! any settled one; if the median run did not settle, the table says "—".

use deckland::control::pitch::{
    ObserverPdParameters, PidParameters, PitchControllerParameters, PitchFeedback,
};
use deckland::experiments::{fly_pitch_step, PitchStep};
use deckland::scenario::Scenario;

/// Observer bandwidth parameters studied.
const EPSILONS: [f64; 7] = [0.01, 0.02, 0.03, 0.05, 0.08, 0.1, 0.15];
/// Seeds of the adverse runs.
const SEEDS: std::ops::RangeInclusive<u64> = 1..=5;
/// Length of each run (s).
const DURATION_S: f64 = 6.0;

/// What one run measured.
#[derive(Debug, Clone, Copy)]
struct RunMetrics {
    /// Settling time from the step (s); `None` when not settled.
    settling_time_s: Option<f64>,
    /// Overshoot (% of the step).
    overshoot_pct: f64,
    /// Largest |δe − δe*| (deg).
    peak_elevator_change_deg: f64,
    /// RMS of the elevator rate over the whole run (deg/s).
    elevator_rate_rms_degps: f64,
    /// Total travel of the elevator over the run (deg).
    elevator_total_variation_deg: f64,
    /// Time on either elevator stop (s).
    saturated_s: f64,
    /// RMS of θ − (θ* + step) over the last 2 s (deg): how far noise and wind keep θ
    /// from the target once the transient is over.
    residual_rms_deg: f64,
}

/// Which disturbances act.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Disturbances {
    /// None (`Scenario::ideal`).
    Ideal,
    /// Every disturbance at its default (`Scenario::default`).
    Adverse,
    /// Adverse without the pitch-measurement noise (both terms).
    AdverseWithoutSensorNoise,
    /// Adverse without the sinusoidal pitch-measurement error.
    AdverseWithoutSinusoid,
    /// Adverse without the white pitch-measurement noise.
    AdverseWithoutWhiteNoise,
}

impl Disturbances {
    fn scenario(self, seed: u64) -> Scenario {
        let mut scenario = Scenario {
            seed,
            ..Scenario::default()
        };
        let noise = &mut scenario.environment.pitch_noise;
        match self {
            Self::Ideal => return scenario.ideal(),
            Self::Adverse => {}
            Self::AdverseWithoutSensorNoise => noise.enabled = false,
            Self::AdverseWithoutSinusoid => noise.sinusoid_amplitude_rad = 0.0,
            Self::AdverseWithoutWhiteNoise => noise.white_noise_sigma_rad = 0.0,
        }
        scenario
    }
}

fn fly(
    pitch: PitchControllerParameters,
    disturbances: Disturbances,
    seed: u64,
    step_deg: f64,
) -> Result<RunMetrics, Box<dyn std::error::Error>> {
    let mut scenario = disturbances.scenario(seed);
    scenario.control.pitch = pitch;
    let step = PitchStep {
        record_interval_s: 0.001,
        ..PitchStep::new(step_deg, DURATION_S)
    };
    let run = fly_pitch_step(&scenario, &step)?;
    let response = &run.response;
    let samples = &run.samples;
    let first = samples.first().ok_or("no samples recorded")?;
    let target_deg = first.theta_ref_rad.to_degrees() + step_deg;
    let rates: Vec<f64> = samples
        .windows(2)
        .map(|w| {
            (w[1].elevator_rad.to_degrees() - w[0].elevator_rad.to_degrees())
                / (w[1].time_s - w[0].time_s)
        })
        .collect();
    let rms = |values: &[f64]| {
        (values.iter().map(|v| v * v).sum::<f64>() / values.len().max(1) as f64).sqrt()
    };
    let end_s = samples.last().map_or(0.0, |s| s.time_s);
    let residual: Vec<f64> = samples
        .iter()
        .filter(|s| s.time_s >= end_s - 2.0)
        .map(|s| s.theta_rad.to_degrees() - target_deg)
        .collect();
    Ok(RunMetrics {
        settling_time_s: response.settling_time_s,
        overshoot_pct: response.overshoot_pct,
        peak_elevator_change_deg: response.max_elevator_change_deg,
        elevator_rate_rms_degps: rms(&rates),
        elevator_total_variation_deg: response.elevator_total_variation_deg,
        saturated_s: response.elevator_saturation_s,
        residual_rms_deg: rms(&residual),
    })
}

/// Median of the runs, field by field (settling: unsettled counts as +∞), and the
/// number of runs that settled.
fn median(runs: &[RunMetrics]) -> (RunMetrics, usize) {
    let middle = |mut values: Vec<f64>| {
        values.sort_by(f64::total_cmp);
        values[values.len() / 2]
    };
    let field = |f: fn(&RunMetrics) -> f64| middle(runs.iter().map(f).collect());
    let settling = field(|r| r.settling_time_s.unwrap_or(f64::INFINITY));
    (
        RunMetrics {
            settling_time_s: settling.is_finite().then_some(settling),
            overshoot_pct: field(|r| r.overshoot_pct),
            peak_elevator_change_deg: field(|r| r.peak_elevator_change_deg),
            elevator_rate_rms_degps: field(|r| r.elevator_rate_rms_degps),
            elevator_total_variation_deg: field(|r| r.elevator_total_variation_deg),
            saturated_s: field(|r| r.saturated_s),
            residual_rms_deg: field(|r| r.residual_rms_deg),
        },
        runs.iter().filter(|r| r.settling_time_s.is_some()).count(),
    )
}

fn runs(
    pitch: PitchControllerParameters,
    disturbances: Disturbances,
    step_deg: f64,
) -> Result<(RunMetrics, usize, usize), Box<dyn std::error::Error>> {
    let seeds: Vec<u64> = if disturbances == Disturbances::Ideal {
        vec![1]
    } else {
        SEEDS.collect()
    };
    let metrics = seeds
        .iter()
        .map(|&seed| fly(pitch, disturbances, seed, step_deg))
        .collect::<Result<Vec<_>, _>>()?;
    let (median, settled) = median(&metrics);
    Ok((median, settled, seeds.len()))
}

fn settling_cell(m: &RunMetrics, settled: usize, of: usize) -> String {
    let time = m
        .settling_time_s
        .map_or_else(|| "—".to_string(), |t| format!("{t:.2}"));
    if of > 1 {
        format!("{time} ({settled}/{of})")
    } else {
        time
    }
}

fn row(label: &str, m: &RunMetrics, settled: usize, of: usize) -> String {
    format!(
        "| {label} | {} | {:.1} | {:.1} | {:.0} | {:.0} | {:.3} | {:.3} |",
        settling_cell(m, settled, of),
        m.overshoot_pct,
        m.peak_elevator_change_deg,
        m.elevator_rate_rms_degps,
        m.elevator_total_variation_deg,
        m.saturated_s,
        m.residual_rms_deg,
    )
}

const HEADER: &str = "| settling time (s) | overshoot (%) | peak \\|δe − δe*\\| (deg) | \
                      RMS δe rate (deg/s) | δe total travel (deg) | time on stops (s) | \
                      θ residual RMS, last 2 s (deg) |";
const RULE: &str = "|---|---|---|---|---|---|---|---|";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("## O-PD observer bandwidth ε, 2° pitch step, {DURATION_S} s runs\n");
    let conditions = [
        ("ideal", Disturbances::Ideal),
        ("adverse (median of seeds 1–5)", Disturbances::Adverse),
    ];
    for (conditions, disturbances) in conditions {
        println!("### {conditions}\n");
        println!("| ε {HEADER}");
        println!("{RULE}");
        for epsilon in EPSILONS {
            let mut opd = ObserverPdParameters::default();
            opd.observer.epsilon = epsilon;
            let (m, settled, of) = runs(
                PitchControllerParameters::ObserverPd(opd),
                disturbances,
                2.0,
            )?;
            println!("{}", row(&format!("{epsilon}"), &m, settled, of));
        }
        println!();
    }

    let default_epsilon = ObserverPdParameters::default().observer.epsilon;
    println!("## O-PD (ε = {default_epsilon}) against the PID, steps of 1°, 2°, 5°\n");
    for (conditions, disturbances) in conditions {
        println!("### {conditions}\n");
        println!("| controller, step {HEADER}");
        println!("{RULE}");
        for step_deg in [1.0, 2.0, 5.0] {
            for (name, pitch) in [
                ("O-PD", PitchControllerParameters::default()),
                (
                    "PID",
                    PitchControllerParameters::Pid(PidParameters::default()),
                ),
            ] {
                let (m, settled, of) = runs(pitch, disturbances, step_deg)?;
                println!("{}", row(&format!("{name}, {step_deg}°"), &m, settled, of));
            }
        }
        println!();
    }

    println!("## Which disturbance stops the 2° step settling (median of seeds 1–5)\n");
    println!("| controller, disturbances {HEADER}");
    println!("{RULE}");
    let estimate_feedback = ObserverPdParameters {
        pitch_feedback: PitchFeedback::ObserverEstimate,
        ..ObserverPdParameters::default()
    };
    for (case, disturbances) in [
        ("adverse", Disturbances::Adverse),
        ("no sensor noise", Disturbances::AdverseWithoutSensorNoise),
        (
            "no sinusoidal sensor error",
            Disturbances::AdverseWithoutSinusoid,
        ),
        (
            "no white sensor noise",
            Disturbances::AdverseWithoutWhiteNoise,
        ),
    ] {
        for (name, pitch) in [
            ("O-PD", PitchControllerParameters::default()),
            (
                "PID",
                PitchControllerParameters::Pid(PidParameters::default()),
            ),
        ] {
            let (m, settled, of) = runs(pitch, disturbances, 2.0)?;
            println!("{}", row(&format!("{name}, {case}"), &m, settled, of));
        }
    }
    let (m, settled, of) = runs(
        PitchControllerParameters::ObserverPd(estimate_feedback),
        Disturbances::Adverse,
        2.0,
    )?;
    println!(
        "{}",
        row("O-PD, θ estimate fed back, adverse", &m, settled, of)
    );
    Ok(())
}
