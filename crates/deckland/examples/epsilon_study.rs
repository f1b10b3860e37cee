//! Observer-bandwidth study and pitch-step comparison (GitHub issues 4 and 11; paper
//! §5, Fig. 10–12): prints markdown tables.
//!
//! Run with `cargo run --release -p deckland --example epsilon_study -- [paper|realistic]
//! [SEEDS]` (default: `paper 5`, the tables of docs/pitch-step.md; `realistic 20` gives
//! the realistic hardware's tables, issue 11).
//!
//! 1. For the O-PD over a range of ε: the 2 % settling time of a 2° pitch step and the
//!    elevator activity, in ideal conditions and in adverse conditions (median over the
//!    seeds).
//! 2. The set's O-PD against its PID for steps of 1°, 2° and 5°, ideal and adverse
//!    (median over the seeds).
//! 3. Which disturbance keeps the 2° step from settling: adverse with the sensor noise
//!    off, or only its sinusoidal or its white part off, or the wind off; and the O-PD
//!    feeding back the other pitch signal (measured θ or the observer's estimate).
//! 4. How many seeds settle the 2° and 5° steps within a time, in bands of ±2, ±5 and
//!    ±10 % of the step: the tightest band the sensor allows.
//!
//! Every run is `Mission::pitch_step(step, 6 s)` of the set (a step in the paper's set,
//! jerk-limited and fed forward on the realistic hardware): the step at t = 1 s from
//! level trim at 69.1 m/s, recorded every 1 ms. Settling time: from the step to the last
//! entry into the band around θ* + step, staying there at least 0.5 s to the end of the
//! record (`deckland::metrics`). A median over seeds counts an unsettled run as slower
//! than any settled one; if the median run did not settle, the table says "—".

use deckland::control::pitch::{
    ObserverPdParameters, PidParameters, PitchControllerParameters, PitchFeedback,
};
use deckland::experiments::{fly_pitch_step, PitchStep};
use deckland::metrics::{step_response_metrics, StepResponseSpec};
use deckland::scenario::{HardwareSet, Scenario};

/// Length of each run (s).
const DURATION_S: f64 = 6.0;
/// Settling bands of table 4, as fractions of the step.
const BANDS: [f64; 3] = [0.02, 0.05, 0.10];
/// The settling time table 4 counts against (s): issue 11's target for the adverse step.
const TARGET_SETTLING_S: f64 = 1.6;

/// What is studied: the hardware set and the seeds of the adverse runs.
#[derive(Debug, Clone)]
struct Study {
    set: HardwareSet,
    seeds: Vec<u64>,
}

impl Study {
    /// From the command line: `[paper|realistic] [SEEDS]`.
    fn from_args() -> Result<Self, String> {
        let mut args = std::env::args().skip(1);
        let set = match args.next().as_deref() {
            None | Some("paper") => HardwareSet::Paper,
            Some("realistic") => HardwareSet::Realistic,
            Some(other) => {
                return Err(format!(
                    "unknown hardware set `{other}`: paper or realistic"
                ))
            }
        };
        let seeds = match args.next() {
            None => 5,
            Some(text) => text
                .parse::<u64>()
                .ok()
                .filter(|n| (1..=1000).contains(n))
                .ok_or(format!("SEEDS = {text}: a whole number from 1 to 1000"))?,
        };
        Ok(Self {
            set,
            seeds: (1..=seeds).collect(),
        })
    }

    /// Observer bandwidth parameters studied with this set's O-PD.
    fn epsilons(&self) -> &'static [f64] {
        match self.set {
            HardwareSet::Paper => &[0.01, 0.02, 0.03, 0.05, 0.08, 0.1, 0.15],
            HardwareSet::Realistic => &[0.05, 0.1, 0.15, 0.2, 0.3, 0.5],
        }
    }

    /// The set's O-PD and PID.
    fn laws(&self) -> [(&'static str, PitchControllerParameters); 2] {
        let opd = self.set.scenario().control.pitch;
        let pid = match self.set {
            HardwareSet::Paper => PidParameters::paper(),
            HardwareSet::Realistic => PidParameters::default(),
        };
        [("O-PD", opd), ("PID", PitchControllerParameters::Pid(pid))]
    }

    fn opd(&self) -> ObserverPdParameters {
        match self.set.scenario().control.pitch {
            PitchControllerParameters::ObserverPd(opd) => opd,
            PitchControllerParameters::Pid(_) => ObserverPdParameters::default(),
        }
    }
}

/// What one run measured.
#[derive(Debug, Clone, Copy)]
struct RunMetrics {
    /// Settling time from the step (s); `None` when not settled.
    settling_time_s: Option<f64>,
    /// Settling time into each of [`BANDS`] (s); `None` when not settled.
    band_settling_s: [Option<f64>; 3],
    /// Overshoot (% of the step).
    overshoot_pct: f64,
    /// Largest |δe − δe*| (deg).
    peak_elevator_change_deg: f64,
    /// RMS of the elevator rate over the whole run (deg/s).
    elevator_rate_rms_degps: f64,
    /// Time on the elevator's rate limit (% of the run).
    rate_limit_pct: f64,
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
    /// Every disturbance at its default.
    Adverse,
    /// Adverse without the pitch-measurement noise (both terms).
    AdverseWithoutSensorNoise,
    /// Adverse without the sinusoidal pitch-measurement error.
    AdverseWithoutSinusoid,
    /// Adverse without the white pitch-measurement noise.
    AdverseWithoutWhiteNoise,
    /// Adverse without wind, turbulence and air wake (sensor noise only).
    AdverseWithoutWind,
}

impl Disturbances {
    fn scenario(self, set: HardwareSet, seed: u64) -> Scenario {
        let mut scenario = Scenario {
            seed,
            ..set.scenario()
        };
        let noise = &mut scenario.environment.pitch_noise;
        match self {
            Self::Ideal => return scenario.ideal(),
            Self::Adverse => {}
            Self::AdverseWithoutSensorNoise => noise.enabled = false,
            Self::AdverseWithoutSinusoid => noise.sinusoid_amplitude_rad = 0.0,
            Self::AdverseWithoutWhiteNoise => noise.white_noise_sigma_rad = 0.0,
            Self::AdverseWithoutWind => {
                let wind = &mut scenario.environment.wind;
                wind.mean_wind = false;
                wind.turbulence = false;
                wind.steady_wake = false;
                wind.periodic_wake = false;
            }
        }
        scenario
    }
}

fn fly(
    set: HardwareSet,
    pitch: PitchControllerParameters,
    disturbances: Disturbances,
    seed: u64,
    step_deg: f64,
) -> Result<RunMetrics, Box<dyn std::error::Error>> {
    let mut scenario = disturbances.scenario(set, seed);
    scenario.control.pitch = pitch;
    let step = PitchStep {
        record_interval_s: 0.001,
        ..PitchStep::new(step_deg, DURATION_S)
    };
    let run = fly_pitch_step(&scenario, &step)?;
    let response = &run.response;
    let samples = &run.samples;
    let first = samples.first().ok_or("no samples recorded")?;
    let trim_deg = first.theta_ref_rad.to_degrees();
    let target_deg = trim_deg + step_deg;
    let time: Vec<f64> = samples.iter().map(|s| s.time_s).collect();
    let theta_deg: Vec<f64> = samples.iter().map(|s| s.theta_rad.to_degrees()).collect();
    let mut band_settling_s = [None; 3];
    for (settling, band) in band_settling_s.iter_mut().zip(BANDS) {
        let mut spec = StepResponseSpec::new(1.0, trim_deg, target_deg);
        spec.settling_band_fraction = band;
        *settling = step_response_metrics(&time, &theta_deg, &spec)
            .ok()
            .filter(|m| m.not_settled_reason.is_none())
            .and_then(|m| m.settling_time_s);
    }
    let rms = |values: &[f64]| {
        (values.iter().map(|v| v * v).sum::<f64>() / values.len().max(1) as f64).sqrt()
    };
    let end_s = time.last().copied().unwrap_or(0.0);
    let residual: Vec<f64> = samples
        .iter()
        .filter(|s| s.time_s >= end_s - 2.0)
        .map(|s| s.theta_rad.to_degrees() - target_deg)
        .collect();
    Ok(RunMetrics {
        settling_time_s: response.settling_time_s,
        band_settling_s,
        overshoot_pct: response.overshoot_pct,
        peak_elevator_change_deg: response.max_elevator_change_deg,
        elevator_rate_rms_degps: response.actuator.elevator_rate_rms_degps,
        rate_limit_pct: response.actuator.time_on_rate_limit_pct,
        elevator_total_variation_deg: response.elevator_total_variation_deg,
        saturated_s: response.elevator_saturation_s,
        residual_rms_deg: rms(&residual),
    })
}

/// The middle value (the upper one of an even count); unsettled runs are +∞.
fn middle(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Median of the runs, field by field (settling: unsettled counts as +∞), and the
/// number of runs that settled.
fn median(runs: &[RunMetrics]) -> (RunMetrics, usize) {
    let field = |f: fn(&RunMetrics) -> f64| middle(runs.iter().map(f).collect());
    let settling = field(|r| r.settling_time_s.unwrap_or(f64::INFINITY));
    let finite = |t: f64| t.is_finite().then_some(t);
    let band = |k: usize| {
        finite(middle(
            runs.iter()
                .map(|r| r.band_settling_s[k].unwrap_or(f64::INFINITY))
                .collect(),
        ))
    };
    (
        RunMetrics {
            settling_time_s: finite(settling),
            band_settling_s: [band(0), band(1), band(2)],
            overshoot_pct: field(|r| r.overshoot_pct),
            peak_elevator_change_deg: field(|r| r.peak_elevator_change_deg),
            elevator_rate_rms_degps: field(|r| r.elevator_rate_rms_degps),
            rate_limit_pct: field(|r| r.rate_limit_pct),
            elevator_total_variation_deg: field(|r| r.elevator_total_variation_deg),
            saturated_s: field(|r| r.saturated_s),
            residual_rms_deg: field(|r| r.residual_rms_deg),
        },
        runs.iter().filter(|r| r.settling_time_s.is_some()).count(),
    )
}

/// Every seed's run (one run in ideal conditions).
fn all_runs(
    study: &Study,
    pitch: PitchControllerParameters,
    disturbances: Disturbances,
    step_deg: f64,
) -> Result<Vec<RunMetrics>, Box<dyn std::error::Error>> {
    let seeds: &[u64] = if disturbances == Disturbances::Ideal {
        &[1]
    } else {
        &study.seeds
    };
    seeds
        .iter()
        .map(|&seed| fly(study.set, pitch, disturbances, seed, step_deg))
        .collect()
}

/// One table row: the median of the runs, or why they could not be flown (a tuning the
/// hardware refuses).
fn row(
    study: &Study,
    label: &str,
    pitch: PitchControllerParameters,
    disturbances: Disturbances,
    step_deg: f64,
) -> String {
    let runs = match all_runs(study, pitch, disturbances, step_deg) {
        Ok(runs) => runs,
        // The whole message is what `deckland step --epsilon …` prints.
        Err(error) => {
            let reason = error.to_string();
            let first_clause = reason.split(';').next().unwrap_or_default();
            return format!("| {label} | refused at setup: {first_clause} |||||||");
        }
    };
    let (m, settled) = median(&runs);
    let time = m
        .settling_time_s
        .map_or_else(|| "—".to_string(), |t| format!("{t:.2}"));
    let settling = if runs.len() > 1 {
        format!("{time} ({settled}/{})", runs.len())
    } else {
        time
    };
    format!(
        "| {label} | {settling} | {:.1} | {:.1} | {:.0} | {:.1} | {:.0} | {:.3} | {:.3} |",
        m.overshoot_pct,
        m.peak_elevator_change_deg,
        m.elevator_rate_rms_degps,
        m.rate_limit_pct,
        m.elevator_total_variation_deg,
        m.saturated_s,
        m.residual_rms_deg,
    )
}

const HEADER: &str = "| settling time (s) | overshoot (%) | peak \\|δe − δe*\\| (deg) | \
                      RMS δe rate (deg/s) | on rate limit (%) | δe total travel (deg) | \
                      time on stops (s) | θ residual RMS, last 2 s (deg) |";
const RULE: &str = "|---|---|---|---|---|---|---|---|---|";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let study = Study::from_args()?;
    let seeds = study.seeds.len();
    let set = study.set.name();
    let conditions = [
        ("ideal".to_string(), Disturbances::Ideal),
        (
            format!("adverse (median of seeds 1–{seeds})"),
            Disturbances::Adverse,
        ),
    ];
    let [opd_law, pid_law] = study.laws();

    println!("# Pitch steps on the `{set}` hardware\n");
    println!("## O-PD observer bandwidth ε, 2° pitch step, {DURATION_S} s runs\n");
    for (conditions, disturbances) in &conditions {
        println!("### {conditions}\n");
        println!("| ε {HEADER}");
        println!("{RULE}");
        for &epsilon in study.epsilons() {
            let mut opd = study.opd();
            opd.observer.epsilon = epsilon;
            let pitch = PitchControllerParameters::ObserverPd(opd);
            println!(
                "{}",
                row(&study, &format!("{epsilon}"), pitch, *disturbances, 2.0)
            );
        }
        println!();
    }

    let epsilon = study.opd().observer.epsilon;
    println!("## O-PD (ε = {epsilon}) against the PID, steps of 1°, 2°, 5°\n");
    for (conditions, disturbances) in &conditions {
        println!("### {conditions}\n");
        println!("| controller, step {HEADER}");
        println!("{RULE}");
        for step_deg in [1.0, 2.0, 5.0] {
            for (name, pitch) in [opd_law, pid_law] {
                let label = format!("{name}, {step_deg}°");
                println!("{}", row(&study, &label, pitch, *disturbances, step_deg));
            }
        }
        println!();
    }

    println!("## Which disturbance stops the 2° step settling (median of seeds 1–{seeds})\n");
    println!("| controller, disturbances {HEADER}");
    println!("{RULE}");
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
        ("no wind", Disturbances::AdverseWithoutWind),
    ] {
        for (name, pitch) in [opd_law, pid_law] {
            let label = format!("{name}, {case}");
            println!("{}", row(&study, &label, pitch, disturbances, 2.0));
        }
    }
    let mut other_feedback = study.opd();
    other_feedback.pitch_feedback = match other_feedback.pitch_feedback {
        PitchFeedback::Measured => PitchFeedback::ObserverEstimate,
        PitchFeedback::ObserverEstimate => PitchFeedback::Measured,
    };
    let label = format!(
        "O-PD, {:?} θ fed back, adverse",
        other_feedback.pitch_feedback
    );
    let pitch = PitchControllerParameters::ObserverPd(other_feedback);
    println!("{}", row(&study, &label, pitch, Disturbances::Adverse, 2.0));
    println!();

    println!(
        "## Settling by band: seeds settled within {TARGET_SETTLING_S} s, and the median \
         settling time, of {seeds} seeds\n"
    );
    println!("| controller, step, conditions | ±2 % | ±5 % | ±10 % |");
    println!("|---|---|---|---|");
    for (conditions, disturbances) in &conditions {
        for step_deg in [2.0, 5.0] {
            for (name, pitch) in [opd_law, pid_law] {
                let runs = all_runs(&study, pitch, *disturbances, step_deg)?;
                let cells: Vec<String> = (0..BANDS.len())
                    .map(|k| {
                        let times: Vec<f64> = runs
                            .iter()
                            .map(|r| r.band_settling_s[k].unwrap_or(f64::INFINITY))
                            .collect();
                        let within = times.iter().filter(|t| **t <= TARGET_SETTLING_S).count();
                        let median = middle(times);
                        let median = if median.is_finite() {
                            format!("{median:.2} s")
                        } else {
                            "—".to_string()
                        };
                        format!(
                            "{within}/{} ≤ {TARGET_SETTLING_S} s, median {median}",
                            runs.len()
                        )
                    })
                    .collect();
                println!(
                    "| {name}, {step_deg}°, {conditions} | {} |",
                    cells.join(" | ")
                );
            }
        }
    }
    Ok(())
}
