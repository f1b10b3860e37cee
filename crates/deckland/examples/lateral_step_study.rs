//! The lateral step's figures of issue 26 (docs/lateral-control.md): the ideal 10° bank
//! step, the adverse one over 20 seeds (median settling time and fraction settled, the
//! aileron's rate RMS and time on its rate limit, the largest sideslip), the sideslip
//! step, and a 5 m/s 1 − cos crosswind gust (4 s) with the wings held level, for the
//! O-PD and the PID, and the O-PD with other crossovers of the sideslip blend. Run with
//! `cargo run --release -p deckland --example lateral_step_study`.

use deckland::experiments::{
    fly_lateral_step, CrosswindGust, LateralAxis, LateralSetup, LateralStep, LateralStepResponse,
};
use deckland::metrics::median;

const SEEDS: u64 = 20;

fn fly(
    setup: &LateralSetup,
    name: &str,
    step: &LateralStep,
) -> Result<LateralStepResponse, Box<dyn std::error::Error>> {
    let (roll, yaw) = setup.registered_laws(name)?;
    Ok(fly_lateral_step(setup, step, roll.as_ref(), yaw.as_ref())?.response)
}

/// The adverse 10° bank step of law `name` on seeds 1–[`SEEDS`], each step as `with`
/// makes it.
fn adverse_bank_steps(
    setup: &LateralSetup,
    name: &str,
    with: impl Fn(LateralStep) -> LateralStep,
) -> Result<Vec<LateralStepResponse>, Box<dyn std::error::Error>> {
    (1..=SEEDS)
        .map(|seed| {
            let step = LateralStep {
                adverse: true,
                seed,
                ..LateralStep::new(LateralAxis::Roll, 10.0, 8.0)
            };
            fly(setup, name, &with(step))
        })
        .collect()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let setup = LateralSetup::approach()?;
    for name in ["observer_pd", "pid"] {
        println!("== {name}");
        let ideal = fly(
            &setup,
            name,
            &LateralStep::new(LateralAxis::Roll, 10.0, 8.0),
        )?;
        println!(
            "ideal 10° bank: settling (±5 %) {:?} s, overshoot {:.1} %, max |β| {:.2}°, \
             aileron rate RMS {:.1} °/s, on rate limit {:.1} %",
            ideal.settling_time_s,
            ideal.overshoot_pct,
            ideal.max_sideslip_error_deg,
            ideal.aileron_rate_rms_degps,
            100.0 * ideal.aileron_rate_limited_fraction
        );
        let runs = adverse_bank_steps(&setup, name, |step| step)?;
        let settled: Vec<f64> = runs
            .iter()
            .filter(|r| r.settled)
            .filter_map(|r| r.settling_time_s)
            .collect();
        let fold = |f: fn(&LateralStepResponse) -> f64| runs.iter().map(f).fold(0.0, f64::max);
        println!(
            "adverse 10° bank, seeds 1–{SEEDS}: settled {}/{SEEDS}, median settling {:.3} s \
             (of the settled), aileron rate RMS median {:.1} °/s (max {:.1}), on rate limit \
             max {:.1} %, max |β| median {:.2}° (max {:.2}°), rudder rate RMS median {:.1} °/s",
            settled.len(),
            median(settled.iter().copied()),
            median(runs.iter().map(|r| r.aileron_rate_rms_degps)),
            fold(|r| r.aileron_rate_rms_degps),
            100.0 * fold(|r| r.aileron_rate_limited_fraction),
            median(runs.iter().map(|r| r.max_sideslip_error_deg)),
            fold(|r| r.max_sideslip_error_deg),
            median(runs.iter().map(|r| r.rudder_rate_rms_degps)),
        );
        let sideslip = fly(&setup, name, &LateralStep::new(LateralAxis::Yaw, 2.0, 10.0))?;
        println!(
            "ideal 2° sideslip step: settling (±5 %) {:?} s, overshoot {:.1} %, max |φ| {:.2}°, \
             peak rudder {:.1}°",
            sideslip.settling_time_s,
            sideslip.overshoot_pct,
            sideslip.max_bank_error_deg,
            sideslip.max_rudder_deg
        );
        let gust = LateralStep {
            gust: Some(CrosswindGust {
                peak_mps: 5.0,
                start_s: 1.0,
                duration_s: 4.0,
            }),
            ..LateralStep::new(LateralAxis::Roll, 0.0, 8.0)
        };
        let gust = fly(&setup, name, &gust)?;
        println!(
            "5 m/s crosswind gust (1 − cos, 4 s), wings level: max |β| {:.2}°, peak rudder \
             {:.1}°, peak aileron {:.1}°\n",
            gust.max_sideslip_error_deg, gust.max_rudder_deg, gust.max_aileron_deg
        );
    }
    // The sideslip blend's crossover: quiet against coordination in the gust (O-PD).
    println!("== the O-PD with the sideslip blend's crossover k_c (none: raw air data)");
    for crossover in [None, Some(2.0), Some(3.0), Some(4.0), Some(5.0), Some(10.0)] {
        let with = |step: LateralStep| LateralStep {
            sideslip_blend_crossover_radps: crossover,
            ..step
        };
        let runs = adverse_bank_steps(&setup, "observer_pd", with)?;
        let settled: Vec<f64> = runs
            .iter()
            .filter(|r| r.settled)
            .filter_map(|r| r.settling_time_s)
            .collect();
        let ideal = fly(
            &setup,
            "observer_pd",
            &with(LateralStep::new(LateralAxis::Roll, 10.0, 8.0)),
        )?;
        let gust = fly(
            &setup,
            "observer_pd",
            &with(LateralStep {
                gust: Some(CrosswindGust {
                    peak_mps: 5.0,
                    start_s: 1.0,
                    duration_s: 4.0,
                }),
                ..LateralStep::new(LateralAxis::Roll, 0.0, 8.0)
            }),
        )?;
        println!(
            "k_c {crossover:?} rad/s: adverse settled {}/{SEEDS}, median {:.3} s, rudder rate \
             RMS median {:.1} °/s, max |β| median {:.2}°; ideal bank step max |β| {:.2}°; \
             gust max |β| {:.2}°",
            settled.len(),
            median(settled.iter().copied()),
            median(runs.iter().map(|r| r.rudder_rate_rms_degps)),
            median(runs.iter().map(|r| r.max_sideslip_error_deg)),
            ideal.max_sideslip_error_deg,
            gust.max_sideslip_error_deg,
        );
    }
    Ok(())
}
