//! The carrier in a seaway: wave spectra, the hull's response and a fitted time-domain
//! (Markov) model of heave, pitch and roll (docs/model.md §12).
//!
//! Data flow: a [`WaveSpectrum`] (ITTC/Pierson–Moskowitz or JONSWAP, set by H_s and T_p
//! or by a sea-state number) and a wave heading, optionally spread over directions by
//! cos^{2s}, meet a [`HullParameters`] hull at speed U; its heave, pitch and roll
//! amplitudes per unit wave amplitude ([`HullParameters::amplitudes`], Jensen, Mansour &
//! Olsen 2004 for heave and pitch) turn the wave spectrum into each motion's spectrum over
//! the encounter frequency, |H|²·S_e(ω_e); [`SeawayModel::fit`] fits to each a stable
//! state-space model driven by unit white noise ([`MarkovModel`], a sum of band-pass
//! resonant sections) and reports the fit ([`FitReport`]).
//!
//! Conventions as the rest of `environment`: SI inside (m, rad, s); heave positive up,
//! pitch positive bow-up, roll positive starboard side down. Each motion here is modelled
//! on its own (independent noises); the cross-spectrum of heave and pitch, which share the
//! waves, is not modelled (as in today's filter ship, docs/model.md §3.1). Waves are deep-
//! water and linear; heading μ is the direction the waves come from relative to the bow
//! (180° head seas, 90° from starboard).
//!
//! Not yet wired into the simulation loop: the loop needs a ship-motion interface first.
//!
//! Heave, pitch and roll RMS of the default hull (Nimitz class, 15 kn, head seas,
//! Pierson–Moskowitz, cos² spreading), from the test
//! `seaway::fit::tests::rms_table_for_sea_states_3_to_6` (`--nocapture` prints it):
//!
//! | sea state | H_s (m) | T_p (s) | heave (m) | pitch (deg) | roll (deg) | landing point (m) |
//! |---|---|---|---|---|---|---|
//! | 3 | 0.88 | 7.5 | 0.006 | 0.007 | 0.002 | 0.011 |
//! | 4 | 1.88 | 8.8 | 0.036 | 0.038 | 0.009 | 0.065 |
//! | 5 | 3.25 | 9.7 | 0.094 | 0.108 | 0.021 | 0.180 |
//! | 6 | 5.0 | 12.4 | 0.308 | 0.384 | 0.077 | 0.624 |
//!
//! The landing point's height is 81 m aft of the pitch centre, √(σ_H² + (81σ_θ)²), heave and
//! pitch independent as the model makes them (their correlation would change it).
//!
//! The hull is long against these waves (λ_p = gT_p²/2π is 147 m in sea state 5 against
//! L = 317 m), so heave and pitch are small, and in head seas with cos² spreading roll is
//! excited only by the oblique components, far above the 22-s roll resonance: the
//! Pierson–Moskowitz sea has almost no energy there (no swell is modelled). In bow seas
//! (μ₀ = 135°, sea state 5) heave is 0.24 m, pitch 0.15° and roll 0.10° RMS.

mod fit;
mod hull;
mod spectrum;

pub use fit::{
    motion_target, ExactDiscretisation, FitReport, MarkovModel, Motion, MotionModel, MotionTarget,
    ResonantSection, SeawayModel,
};
pub use hull::{HullParameters, MotionAmplitudes, KNOT_MPS, SEAWATER_DENSITY_KGPM3};
pub use spectrum::{
    encounter_branches, encounter_frequency, encounter_spectrum, sea_state_row, EncounterBranch,
    SeaStateRow, SpectrumShape, WaveSpectrum, JONSWAP_DEFAULT_PEAK_FACTOR,
    JONSWAP_SIGMA_ABOVE_PEAK, JONSWAP_SIGMA_BELOW_PEAK, SEA_STATE_TABLE,
};

use serde::{Deserialize, Serialize};

use crate::parameters::{check_ranges, Bounds, ParameterError};

/// Standard gravity g (m/s²), CGPM 1901.
pub const STANDARD_GRAVITY_MPS2: f64 = 9.80665;

/// What the seaway model refuses, each naming the key or the motion and the value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SeawayError {
    /// A parameter outside its range (the key, the value and the range).
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    /// A sea-state number not in [`SEA_STATE_TABLE`].
    #[error("`environment.seaway.sea_state` = {sea_state} is not in the table: expected 3 to 6")]
    UnknownSeaState {
        /// The sea-state number given.
        sea_state: u8,
    },
    /// Following or quartering seas with way on: the encounter map is many-to-one.
    #[error(
        "`environment.seaway.wave_heading_deg` = {wave_heading_deg} is following or quartering \
         seas (U·cos μ > 0), which the encounter spectrum and the fit do not represent: expected \
         a heading in [90, 270] (beam to head seas, 180 = head seas)"
    )]
    FollowingSeas {
        /// The wave heading given (deg, 180 = head seas).
        wave_heading_deg: f64,
    },
    /// The motion's encounter spectrum has no energy (e.g. roll in long-crested head seas).
    #[error(
        "the {motion} spectrum has no energy at `environment.seaway.wave_heading_deg` = \
         {wave_heading_deg} (variance {variance:e}); roll in long-crested head or following \
         seas is zero: give directional spreading"
    )]
    NoEnergy {
        /// The motion ("heave", "pitch" or "roll").
        motion: &'static str,
        /// The wave heading (deg).
        wave_heading_deg: f64,
        /// The target variance found (m² or rad²).
        variance: f64,
    },
    /// The fit found no stable model with positive section weights.
    #[error("the {motion} spectrum could not be fitted: {reason}")]
    FitFailed {
        /// The motion ("heave", "pitch" or "roll").
        motion: &'static str,
        /// What went wrong.
        reason: String,
    },
}

/// Configuration of the seaway (docs/model.md §12): the waves, their heading and spreading, and
/// the hull.
///
/// Written out (a campaign's `scenario.toml`, a pickled Python scenario), a sea named by
/// `sea_state` leaves out the H_s and T_p it sets, so that the file reads back.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, into = "SeawayFile")]
pub struct SeawayParameters {
    /// A sea state of [`SEA_STATE_TABLE`] (3–6), whose H_s and T_p the sea then takes in
    /// place of `significant_wave_height_m` and `peak_period_s` ([`Self::resolved`]);
    /// none by default (the two keys set the sea).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sea_state: Option<u8>,
    /// The spectrum's shape; default Pierson–Moskowitz (ITTC two-parameter).
    pub spectrum: SpectrumShape,
    /// Significant wave height H_s (m), in (0, 15]; default 3.25 (sea state 5).
    pub significant_wave_height_m: f64,
    /// Modal (peak) period T_p (s), in [4, 20]; default 9.7 (sea state 5).
    pub peak_period_s: f64,
    /// Mean wave heading μ₀ relative to the bow (deg; 180 head seas, 90 from starboard),
    /// in [90, 270] with way on; default 180.
    pub wave_heading_deg: f64,
    /// Whether the sea is long-crested (no spreading); default false.
    pub long_crested: bool,
    /// Exponent s of the cos^{2s}(μ − μ₀) spreading over ±90°, in [0.5, 20]; default 1,
    /// the cos² spreading of the ITTC for wind seas (St Denis & Pierson 1953).
    pub spreading_exponent: f64,
    /// The hull (default the Nimitz-class carrier at 15 kn).
    pub hull: HullParameters,
}

/// [`SeawayParameters`] as a file holds it: H_s and T_p left out beside a `sea_state`.
#[derive(Serialize)]
struct SeawayFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    sea_state: Option<u8>,
    spectrum: SpectrumShape,
    #[serde(skip_serializing_if = "Option::is_none")]
    significant_wave_height_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    peak_period_s: Option<f64>,
    wave_heading_deg: f64,
    long_crested: bool,
    spreading_exponent: f64,
    hull: HullParameters,
}

impl From<SeawayParameters> for SeawayFile {
    fn from(p: SeawayParameters) -> Self {
        let own = p.sea_state.is_none();
        Self {
            sea_state: p.sea_state,
            spectrum: p.spectrum,
            significant_wave_height_m: own.then_some(p.significant_wave_height_m),
            peak_period_s: own.then_some(p.peak_period_s),
            wave_heading_deg: p.wave_heading_deg,
            long_crested: p.long_crested,
            spreading_exponent: p.spreading_exponent,
            hull: p.hull,
        }
    }
}

impl Default for SeawayParameters {
    fn default() -> Self {
        Self::sea_state(5).expect("sea state 5 is in the table")
    }
}

impl SeawayParameters {
    /// Sea state `sea_state` (3–6) from [`SEA_STATE_TABLE`], head seas, cos² spreading, the
    /// default hull.
    pub fn sea_state(sea_state: u8) -> Result<Self, SeawayError> {
        let row = sea_state_row(sea_state)?;
        Ok(Self {
            sea_state: None,
            spectrum: SpectrumShape::PiersonMoskowitz,
            significant_wave_height_m: row.significant_wave_height_m,
            peak_period_s: row.modal_period_s,
            wave_heading_deg: 180.0,
            long_crested: false,
            spreading_exponent: 1.0,
            hull: HullParameters::default(),
        })
    }

    /// The wave spectrum (validates H_s, T_p and γ).
    pub fn wave_spectrum(&self) -> Result<WaveSpectrum, SeawayError> {
        WaveSpectrum::new(
            self.spectrum,
            self.significant_wave_height_m,
            self.peak_period_s,
        )
    }

    /// These parameters with `sea_state`'s H_s and T_p in place of the two keys when it is
    /// set (and `sea_state` then cleared); refuses a number not in the table.
    pub fn resolved(&self) -> Result<Self, SeawayError> {
        let Some(sea_state) = self.sea_state else {
            return Ok(*self);
        };
        let row = sea_state_row(sea_state)?;
        Ok(Self {
            sea_state: None,
            significant_wave_height_m: row.significant_wave_height_m,
            peak_period_s: row.modal_period_s,
            ..*self
        })
    }

    /// Checks every field, naming the key; following and quartering seas with way on are
    /// refused with [`SeawayError::FollowingSeas`].
    pub fn validate(&self) -> Result<(), SeawayError> {
        const SECTION: &str = "environment.seaway";
        let resolved = self.resolved()?;
        if resolved.sea_state.is_none() && self.sea_state.is_some() {
            return resolved.validate();
        }
        self.wave_spectrum()?;
        self.hull.validate()?;
        check_ranges!(SECTION, self, {
            wave_heading_deg: Bounds::closed(0.0, 360.0),
            spreading_exponent: Bounds::closed(0.5, 20.0),
        });
        let heading = self.wave_heading_deg.to_radians();
        if self.hull.speed_mps * heading.cos() > 1e-9 {
            return Err(SeawayError::FollowingSeas {
                wave_heading_deg: self.wave_heading_deg,
            });
        }
        Ok(())
    }

    /// Wave directions and their weights (summing to 1): the mean heading alone when
    /// long-crested, else 36 bins of 5° over μ₀ ± 90° weighted by cos^{2s} (rad, weight).
    pub fn directions(&self) -> Vec<(f64, f64)> {
        let mean = self.wave_heading_deg.to_radians();
        if self.long_crested {
            return vec![(mean, 1.0)];
        }
        const BINS: usize = 36;
        let width = std::f64::consts::PI / BINS as f64;
        let raw: Vec<(f64, f64)> = (0..BINS)
            .map(|j| {
                let offset = -std::f64::consts::FRAC_PI_2 + width * (j as f64 + 0.5);
                (
                    mean + offset,
                    offset.cos().powf(2.0 * self.spreading_exponent),
                )
            })
            .collect();
        let total: f64 = raw.iter().map(|(_, w)| w).sum();
        raw.into_iter().map(|(mu, w)| (mu, w / total)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_is_sea_state_5_head_seas_at_15_knots() {
        let p = SeawayParameters::default();
        assert_eq!((p.significant_wave_height_m, p.peak_period_s), (3.25, 9.7));
        assert_eq!(p.wave_heading_deg, 180.0);
        assert!((p.hull.speed_mps - 7.716_667).abs() < 1e-6);
        assert!(p.validate().is_ok());
    }

    #[test]
    fn spreading_weights_sum_to_one_and_match_cos_squared() {
        let p = SeawayParameters::default();
        let directions = p.directions();
        assert_eq!(directions.len(), 36);
        let total: f64 = directions.iter().map(|(_, w)| w).sum();
        assert!((total - 1.0).abs() < 1e-12);
        // cos² spreading's density is (2/π)cos²θ; a 5° bin at θ ≈ 0 holds about (2/π)·5°.
        let centre = directions[18].1;
        assert!((centre / (2.0 / std::f64::consts::PI * 5f64.to_radians()) - 1.0).abs() < 1e-2);
    }

    #[test]
    fn following_seas_are_refused_naming_the_heading() {
        let p = SeawayParameters {
            wave_heading_deg: 20.0,
            ..SeawayParameters::default()
        };
        let error = p.validate().unwrap_err();
        assert!(error.to_string().contains("wave_heading_deg"), "{error}");
        let bad = SeawayParameters {
            spreading_exponent: 0.0,
            ..SeawayParameters::default()
        };
        assert!(bad
            .validate()
            .unwrap_err()
            .to_string()
            .contains("spreading_exponent"));
    }
}
