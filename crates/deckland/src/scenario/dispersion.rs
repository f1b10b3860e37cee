//! Per-run dispersions of a Monte Carlo campaign: random offsets of the start condition,
//! the approach speed, the sea state and the wind, drawn from each run's own seed.
//!
//! Every draw comes from the run's random stream named [`DISPERSION_STREAM`] (ChaCha8
//! keyed by the run's seed, see [`crate::random`]), so the dispersions never disturb the
//! environment's streams: with every standard deviation at zero a run flies exactly the
//! nominal scenario with its seed. Four standard normal samples are always drawn, in the
//! order of the fields of [`DispersionParameters`], so switching one dispersion on or off
//! leaves the others' values unchanged.

use serde::{Deserialize, Serialize};

use super::Scenario;
use crate::parameters::{check_ranges, Bounds, ParameterError};
use crate::random::RandomStreams;

/// Name of the random stream the dispersions are drawn from.
pub const DISPERSION_STREAM: &str = "dispersion";

/// Standard deviations of the per-run dispersions; all zero (none) by default.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DispersionParameters {
    /// Standard deviation (m) of a Gaussian offset added to
    /// `approach.start_height_offset_m`: the start height of the hook above the glide path.
    pub start_height_offset_sd_m: f64,
    /// Standard deviation (m/s) of a Gaussian error added to `approach.airspeed_mps`: the
    /// approach airspeed, at which the run starts trimmed and which the speed loop holds.
    pub airspeed_error_sd_mps: f64,
    /// Log-standard deviation (–) of the sea-state scale factor exp(σ·n), n ~ N(0, 1), that
    /// multiplies both `environment.ship.heave_rms_m` and `environment.ship.pitch_rms_deg`
    /// (median factor 1; σ = 0.3 gives 0.55–1.8 at ±2σ).
    pub sea_state_log_sd: f64,
    /// Standard deviation (m/s) of a Gaussian error added to
    /// `environment.wind.wind_over_deck_mps`.
    pub wind_over_deck_sd_mps: f64,
}

/// One run's draw of the dispersions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DispersionSample {
    /// Added to the start height offset from the glide path (m).
    pub start_height_offset_m: f64,
    /// Added to the approach airspeed (m/s).
    pub airspeed_error_mps: f64,
    /// Factor on the heave and pitch RMS of the ship motion (–).
    pub sea_state_scale: f64,
    /// Added to the wind over deck (m/s).
    pub wind_over_deck_error_mps: f64,
}

impl Default for DispersionSample {
    /// No dispersion: zero offsets and a unit sea-state factor.
    fn default() -> Self {
        Self {
            start_height_offset_m: 0.0,
            airspeed_error_mps: 0.0,
            sea_state_scale: 1.0,
            wind_over_deck_error_mps: 0.0,
        }
    }
}

impl DispersionParameters {
    /// Whether every standard deviation is zero, so every run flies the nominal scenario.
    pub fn is_none(&self) -> bool {
        *self == Self::default()
    }

    /// Checks every standard deviation is finite, non-negative and below a sane limit.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "dispersion";
        check_ranges!(SECTION, self, {
            start_height_offset_sd_m: Bounds::closed(0.0, 20.0),
            airspeed_error_sd_mps: Bounds::closed(0.0, 10.0),
            sea_state_log_sd: Bounds::closed(0.0, 1.0),
            wind_over_deck_sd_mps: Bounds::closed(0.0, 10.0),
        });
        Ok(())
    }

    /// The draw of the run whose random streams are `streams`: four standard normal
    /// samples from the stream [`DISPERSION_STREAM`], in field order, scaled.
    pub fn sample(&self, streams: &RandomStreams) -> DispersionSample {
        let mut stream = streams.stream(DISPERSION_STREAM);
        let mut normals = [0.0; 4];
        for n in &mut normals {
            *n = stream.standard_normal();
        }
        DispersionSample {
            start_height_offset_m: self.start_height_offset_sd_m * normals[0],
            airspeed_error_mps: self.airspeed_error_sd_mps * normals[1],
            sea_state_scale: (self.sea_state_log_sd * normals[2]).exp(),
            wind_over_deck_error_mps: self.wind_over_deck_sd_mps * normals[3],
        }
    }
}

impl DispersionSample {
    /// `scenario` with this draw applied (the result may be invalid: a tail draw can push
    /// a value out of its range, which [`Scenario::validate`] then reports).
    pub fn apply(&self, scenario: &Scenario) -> Scenario {
        let mut dispersed = *scenario;
        dispersed.approach.start_height_offset_m += self.start_height_offset_m;
        dispersed.approach.airspeed_mps += self.airspeed_error_mps;
        dispersed.environment.ship.heave_rms_m *= self.sea_state_scale;
        dispersed.environment.ship.pitch_rms_deg *= self.sea_state_scale;
        dispersed.environment.wind.wind_over_deck_mps += self.wind_over_deck_error_mps;
        dispersed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_dispersion_leaves_the_scenario_unchanged() {
        let scenario = Scenario::default();
        let sample = DispersionParameters::default().sample(&RandomStreams::new(5));
        assert_eq!(sample, DispersionSample::default());
        assert_eq!(sample.apply(&scenario), scenario);
    }

    #[test]
    fn draws_depend_on_the_seed_and_each_dispersion_keeps_its_value() {
        let all = DispersionParameters {
            start_height_offset_sd_m: 2.0,
            airspeed_error_sd_mps: 1.0,
            sea_state_log_sd: 0.3,
            wind_over_deck_sd_mps: 2.0,
        };
        let a = all.sample(&RandomStreams::new(1));
        let b = all.sample(&RandomStreams::new(2));
        assert_ne!(a, b);
        assert_eq!(a, all.sample(&RandomStreams::new(1)));
        let height_only = DispersionParameters {
            start_height_offset_sd_m: 2.0,
            ..DispersionParameters::default()
        };
        let h = height_only.sample(&RandomStreams::new(1));
        assert_eq!(h.start_height_offset_m, a.start_height_offset_m);
        assert_eq!(h.sea_state_scale, 1.0);
    }

    #[test]
    fn negative_or_non_finite_deviations_are_rejected() {
        for bad in [-1.0, f64::NAN, f64::INFINITY, 1e6] {
            let p = DispersionParameters {
                wind_over_deck_sd_mps: bad,
                ..DispersionParameters::default()
            };
            let error = p.validate().expect_err("out of range");
            assert_eq!(error.path, "dispersion.wind_over_deck_sd_mps");
        }
    }
}
