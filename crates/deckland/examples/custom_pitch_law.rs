//! Your own pitch law, flown beside the O-PD: one approach, then a small campaign.
//!
//! `cargo run --release -p deckland --example custom_pitch_law [RUNS]` (default 40).
//!
//! Everything a pitch law needs is in this one file; a law outside the library needs no
//! registration. It implements [`deckland::control::AxisLaw`] for the pitch axis
//! (`type Inputs = PitchLawInputs`, which makes it a [`PitchLaw`]): it names its states,
//! gives the elevator command from them and the signals of the instant
//! ([`PitchLawInputs`]: the pitch command, the measured attitude and rate, the trim), and
//! the states' derivatives, which the simulation integrates with the aircraft (RK4,
//! 1 ms). It also describes itself in its linear limit ([`LinearLaw`]), the form in which
//! the design code (`control::design::assess_loop`: margins, noise, the rate
//! limit's limit cycle) assesses any law. A factory builds it for each run from the plant
//! derivatives at that run's trim ([`PitchDesignContext`]).
//!
//! The law here is a filtered PID designed like the O-PD, from the plant: the measured
//! attitude goes through a first-order filter (time constant `filter_s`) that keeps the
//! sensor's white noise off the elevator; the error dynamics are placed at ω_n, ζ with
//! K_P = ω_n², K_D = 2ζω_n + ∂q̇/∂q (docs/model.md §5.2's rule), and a slow integral
//! K_I = 0.016·ω_n³ trims out steady disturbances. ω_n = 2.5 rad/s, ζ = 1 are the error
//! dynamics of the realistic O-PD design (T_2% = 1.6 s), which the stabilator's 40 °/s
//! rate limit can follow; K_I is then the realistic PID's 0.25 s⁻³. Faster gains
//! (ω_n = 4 rad/s, ζ = 0.9, K_I = 0.1·ω_n³) diverged in all 4 approaches of
//! `cargo run -p deckland --example custom_pitch_law 4`; these board as often as the
//! O-PD there (3 of 4).

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use deckland::control::pitch::{AxisLaw, LinearLaw, PitchDesignContext, PitchLaw, PitchLawInputs};
use deckland::experiments::{fly_approach, fly_approach_with_law};
use deckland::monte_carlo::{run_campaign, CampaignSpec, ControllerVariant};
use deckland::parameters::ParameterError;
use deckland::scenario::Scenario;
use deckland::simulation::PitchLawFactory;

/// A filtered PID pitch law: states x0 = filtered θ_m (rad), x1 = ∫(θ_ref − x0) dt (rad·s).
#[derive(Debug, Clone)]
struct FilteredPid {
    proportional_per_s2: f64,
    integral_per_s3: f64,
    derivative_per_s: f64,
    filter_s: f64,
    control_power_per_s2: f64,
}

impl FilteredPid {
    /// Designs the gains for error dynamics of natural frequency `omega_radps` and
    /// damping `zeta` on the plant of `context`.
    fn design(context: &PitchDesignContext, omega_radps: f64, zeta: f64) -> Self {
        Self {
            proportional_per_s2: omega_radps * omega_radps,
            integral_per_s3: 0.016 * omega_radps.powi(3),
            derivative_per_s: 2.0 * zeta * omega_radps + context.plant.rate_damping_per_s,
            filter_s: 0.05,
            control_power_per_s2: context.plant.control_power_per_s2,
        }
    }
}

impl AxisLaw for FilteredPid {
    type Inputs = PitchLawInputs;

    fn label(&self) -> &str {
        "filtered PID"
    }

    fn state_names(&self) -> &'static [&'static str] {
        &["filtered_pitch_rad", "pitch_error_integral_rad_s"]
    }

    fn initial_state(&self, inputs: &PitchLawInputs, state: &mut [f64]) {
        state[0] = inputs.theta_measured_rad;
        state[1] = 0.0;
    }

    fn surface_command_rad(&self, state: &[f64], inputs: &PitchLawInputs) -> f64 {
        let error = inputs.theta_ref_rad - state[0];
        let equivalent_control = self.proportional_per_s2 * error + self.integral_per_s3 * state[1]
            - self.derivative_per_s * inputs.pitch_rate_measured_radps;
        inputs.elevator_trim_rad + equivalent_control / self.control_power_per_s2
    }

    fn derivative(&self, state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]) {
        rate[0] = (inputs.theta_measured_rad - state[0]) / self.filter_s;
        rate[1] = inputs.theta_ref_rad - state[0];
    }

    /// About trim, over the inputs [r, y, q, δ]: ẋ0 = (y − x0)/T, ẋ1 = r − x0,
    /// u = (K_P·(r − x0) + K_I·x1 − K_D·q)/M_δ; the third state is a placeholder.
    fn linear_law(&self) -> Option<LinearLaw> {
        let (md, t) = (self.control_power_per_s2, self.filter_s);
        Some(LinearLaw {
            state_matrix: [[-1.0 / t, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, -1.0]],
            input_matrix: [[0.0, 1.0 / t, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0; 4]],
            output_states: [
                -self.proportional_per_s2 / md,
                self.integral_per_s3 / md,
                0.0,
            ],
            output_inputs: [
                self.proportional_per_s2 / md,
                0.0,
                -self.derivative_per_s / md,
                0.0,
            ],
        })
    }
}

/// Builds the law for each run: ω_n = 2.5 rad/s, ζ = 1.
fn factory() -> Arc<PitchLawFactory> {
    Arc::new(
        |context: &PitchDesignContext| -> Result<Box<dyn PitchLaw>, ParameterError> {
            Ok(Box::new(FilteredPid::design(context, 2.5, 1.0)))
        },
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let runs: u64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(40);
    let scenario = Scenario::default();
    let law = factory();

    println!("One approach, default scenario, seed {}:", scenario.seed);
    let opd = fly_approach(&scenario)?.summary;
    let own = fly_approach_with_law(&scenario, &*law)?.summary;
    for (label, summary) in [("O-PD", &opd), ("filtered PID", &own)] {
        let touchdown = summary.touchdown.map_or_else(
            || "no touchdown".to_owned(),
            |t| {
                format!(
                    "{:+.1} m from the aim point at {:.2} m/s",
                    t.distance_from_aim_m, t.sink_rate_mps
                )
            },
        );
        println!(
            "  {label:<14} {:<12} {touchdown}, glide-path error RMS {:.2} m",
            summary.outcome.name(),
            summary.glide_path_error_rms_m.unwrap_or(f64::NAN)
        );
    }

    println!("\nCampaign of {runs} approaches, the same seeds under both laws:");
    let mut spec = CampaignSpec::new(scenario, runs, scenario.seed);
    spec.controllers
        .push(ControllerVariant::custom("filtered PID", law));
    let result = run_campaign(&spec, 2, &|_| {}, &AtomicBool::new(false))?;
    for statistics in result.statistics() {
        let boarding = statistics.boarding;
        println!(
            "  {:<14} boarding {:5.1} % [{:.1}, {:.1}], ramp strikes {}, hard landings {}, diverged {}",
            statistics.controller,
            100.0 * boarding.rate,
            100.0 * boarding.ci95_low,
            100.0 * boarding.ci95_high,
            statistics.ramp_strike.count,
            statistics.hard_landing.count,
            statistics.divergence.count,
        );
    }
    Ok(())
}
