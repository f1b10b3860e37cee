//! The section of the actuators, the simulation and the environment (paper §3.3–3.7).

use deckland::experiments::reproduction::SEED;
use deckland::scenario::Scenario;

use super::{given_row, row, seeds_text, stated, Findings, Section};

/// Paper §3.3–3.7: actuators, simulation and environment.
pub(super) fn environment(f: &Findings) -> Section {
    let scenario = Scenario::paper();
    let engines = scenario.aircraft.engines;
    let actuator = scenario.aircraft.elevator_actuator;
    let study = &f.reproduction.environment;
    let environment = &study.parameters;
    let wind = environment.wind;
    let noise = environment.pitch_noise;
    let record_s = study.record.seconds;
    let seeds = seeds_text(study.heave_peaks_m.len());
    Section {
        title: "Actuators, simulation and environment (paper §3.3–3.7)",
        rows: vec![
            given_row(
                "engine time constant (s)",
                "engine_time_constant",
                engines.time_constant_s,
            ),
            row(
                "elevator actuator ω_n (rad/s), ζ",
                stated("actuator"),
                format!(
                    "{}, {}",
                    actuator.natural_frequency_rad_s, actuator.damping_ratio
                ),
                "",
            ),
            row(
                "elevator range (deg)",
                stated("elevator_range"),
                format!(
                    "{} … {}",
                    actuator.min_deflection_deg, actuator.max_deflection_deg
                ),
                "limits on the actuator's position",
            ),
            row(
                "integration step (s), method",
                stated("integration"),
                format!("{}, RK4", scenario.time_step_s),
                "",
            ),
            given_row(
                "landing point aft of the ship's pitch centre (m)",
                "landing_point_aft",
                environment.deck.landing_point_aft_of_pitch_centre_m,
            ),
            row(
                "ship heave: maximum (m)",
                stated("heave_max"),
                format!(
                    "peak {:.2} over {record_s:.0} s (seed {SEED})",
                    study.heave_peak_m
                ),
                format!(
                    "the noise is set by the output RMS ({} m), not the paper's dB power, \
                     which depends on an unstated sample time; over {record_s:.0} s records \
                     of {seeds} the median peak is {:.2} m (docs/model.md §3.1)",
                    environment.ship.heave_rms_m, study.median_heave_peak_m
                ),
            ),
            row(
                "ship pitch: maximum (deg)",
                stated("ship_pitch_max"),
                format!(
                    "peak {:.2} over {record_s:.0} s (seed {SEED})",
                    study.ship_pitch_peak_deg
                ),
                format!(
                    "RMS {}°; median {record_s:.0}-s peak of {seeds} {:.2}° (docs/model.md §3.1)",
                    environment.ship.pitch_rms_deg, study.median_pitch_peak_deg
                ),
            ),
            row(
                "ship white-noise power, pitch / heave (dB)",
                stated("ship_noise_power"),
                format!(
                    "RMS {}° / {} m",
                    environment.ship.pitch_rms_deg, environment.ship.heave_rms_m
                ),
                "replaced by output RMS (see above)",
            ),
            row(
                "landing point vertical motion (Fig. 7)",
                stated("landing_point_motion"),
                format!(
                    "peak {:.2} m about the mean over {record_s:.0} s",
                    study.landing_point_peak_m
                ),
                "",
            ),
            given_row(
                "wind over deck V_w/d (m/s)",
                "wind_over_deck",
                wind.wind_over_deck_mps,
            ),
            row(
                "periodic wake θ_s (rad), ω_p (rad/s)",
                stated("periodic_wake"),
                format!(
                    "{}, {}",
                    wind.periodic_wake_ship_pitch_rad, wind.periodic_wake_frequency_radps
                ),
                "",
            ),
            row(
                "free-air turbulence spectra Φ_u1, Φ_w1 numerators",
                stated("turbulence"),
                format!(
                    "σ_u = {} m/s, σ_w = {} m/s, L = {} m",
                    wind.turbulence_sigma_u_mps,
                    wind.turbulence_sigma_w_mps,
                    wind.turbulence_scale_m
                ),
                "the same Dryden spectra written as σ and scale (σ² = aπ/(2L), L = 100 ft)",
            ),
            row(
                "x-wind 400 m behind the deck (Fig. 8)",
                stated("wind_x"),
                format!(
                    "{:.2} … {:.2} m/s (positive forward: a headwind is negative)",
                    study.wind_x_range_mps.0, study.wind_x_range_mps.1
                ),
                "the paper's Eq. 21–22 only make sense with X positive aft",
            ),
            row(
                "pitch measurement noise",
                stated("pitch_noise"),
                format!(
                    "{} sin({}t) + N(0, {}²) rad per 1-ms step",
                    noise.sinusoid_amplitude_rad,
                    noise.sinusoid_frequency_radps,
                    noise.white_noise_sigma_rad
                ),
                "−60 dBW in MATLAB's wgn is variance 10⁻⁶",
            ),
        ],
    }
}
