//! Wave spectra, the sea-state table and the encounter frequency (docs/model.md §12).
//!
//! One-sided spectra S(ω) in m²·s/rad over the wave's circular frequency ω (rad/s), so
//! that the surface elevation's variance is m₀ = ∫₀^∞ S(ω) dω and the significant wave
//! height H_s = 4·√m₀.
//!
//! - **ITTC / Pierson–Moskowitz, two parameters** (the modified PM or Bretschneider form
//!   recommended by the 15th ITTC, 1978): S(ω) = (5/16)·H_s²·ω_p⁴·ω⁻⁵·exp(−(5/4)(ω_p/ω)⁴),
//!   ω_p = 2π/T_p the modal (peak) frequency. In closed form m₀ = H_s²/16 exactly, and
//!   T_z = 2π√(m₀/m₂) = T_p/(5π/4)^{1/4} ≈ 0.710·T_p.
//! - **JONSWAP** (Hasselmann et al. 1973, as in DNV-RP-C205 §3.5.5): the PM spectrum times
//!   γ^r, r = exp(−(ω − ω_p)²/(2σ²ω_p²)), σ = 0.07 for ω ≤ ω_p and 0.09 above, times a
//!   normalising factor A_γ chosen here by numerical integration so that 4√m₀ = H_s
//!   exactly (DNV's closed-form approximation A_γ ≈ 1 − 0.287 ln γ is checked in a test).
//!
//! Encounter: a ship at speed U meeting long-crested waves of frequency ω from a heading
//! μ relative to its bow (μ = 180° head seas, waves from ahead; 90° from starboard beam)
//! sees ω_e = ω − ω²·U·cos μ/g (deep water, k = ω²/g). For cos μ ≤ 0 (beam to head seas)
//! the map ω → ω_e is monotone and S_e(ω_e) = S(ω)/(1 − 2ωU cos μ/g). In following and
//! quartering seas (U cos μ > 0) it is not: ω_e rises to 1/(4a) at ω = 1/(2a),
//! a = U cos μ/g, then falls through zero, so up to three wave frequencies meet the ship
//! at one |ω_e| and the Jacobian vanishes at the turning point (an integrable
//! singularity). [`encounter_branches`] returns every branch; [`encounter_spectrum`], the
//! long-crested density, refuses following seas with [`SeawayError::FollowingSeas`].

use serde::{Deserialize, Serialize};

use super::{SeawayError, STANDARD_GRAVITY_MPS2};
use crate::parameters::Bounds;

/// Peak factor γ of JONSWAP by default (Hasselmann et al. 1973, mean of the JONSWAP data).
pub const JONSWAP_DEFAULT_PEAK_FACTOR: f64 = 3.3;
/// JONSWAP spectral width σ below the peak (ω ≤ ω_p), Hasselmann et al. 1973.
pub const JONSWAP_SIGMA_BELOW_PEAK: f64 = 0.07;
/// JONSWAP spectral width σ above the peak (ω > ω_p), Hasselmann et al. 1973.
pub const JONSWAP_SIGMA_ABOVE_PEAK: f64 = 0.09;

/// The spectrum's shape: ITTC/Pierson–Moskowitz or JONSWAP (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SpectrumShape {
    /// Two-parameter ITTC / Pierson–Moskowitz (Bretschneider) spectrum.
    PiersonMoskowitz,
    /// JONSWAP with peak factor γ (dimensionless, default 3.3).
    Jonswap {
        /// Peak enhancement factor γ, in [1, 7] (γ = 1 is Pierson–Moskowitz).
        peak_factor: f64,
    },
}

/// One row of the sea-state table: the sea-state number, H_s (m) and modal period T_p (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeaStateRow {
    /// Sea-state number (WMO code).
    pub sea_state: u8,
    /// Significant wave height H_s (m), the table's most probable value.
    pub significant_wave_height_m: f64,
    /// Modal (peak) period T_p (s), the table's most probable value.
    pub modal_period_s: f64,
}

/// Open-ocean North Atlantic sea states 3–6, most probable H_s and modal period, from the
/// NATO table of Bales, Lee & Voelker, *Standardized wave and wind environments for NATO
/// operational areas*, DTNSRDC/SPD-0919-01 (1981), as commonly cited and as quoted in
/// docs/model.md §12. The figures are not checked against the report itself here.
pub const SEA_STATE_TABLE: [SeaStateRow; 4] = [
    SeaStateRow {
        sea_state: 3,
        significant_wave_height_m: 0.88,
        modal_period_s: 7.5,
    },
    SeaStateRow {
        sea_state: 4,
        significant_wave_height_m: 1.88,
        modal_period_s: 8.8,
    },
    SeaStateRow {
        sea_state: 5,
        significant_wave_height_m: 3.25,
        modal_period_s: 9.7,
    },
    SeaStateRow {
        sea_state: 6,
        significant_wave_height_m: 5.0,
        modal_period_s: 12.4,
    },
];

/// The table row of sea state `sea_state` (3–6, [`SEA_STATE_TABLE`]).
pub fn sea_state_row(sea_state: u8) -> Result<SeaStateRow, SeawayError> {
    SEA_STATE_TABLE
        .iter()
        .find(|row| row.sea_state == sea_state)
        .copied()
        .ok_or(SeawayError::UnknownSeaState { sea_state })
}

/// A wave spectrum set by H_s and T_p (module docs; S in m²·s/rad, ω in rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveSpectrum {
    shape: SpectrumShape,
    significant_wave_height_m: f64,
    peak_period_s: f64,
    /// JONSWAP normalising factor A_γ (1 for Pierson–Moskowitz).
    normalisation: f64,
}

impl WaveSpectrum {
    /// The spectrum of this shape, H_s in (0, 15] m and T_p in [4, 20] s (the range the
    /// fit supports; refused otherwise, naming the key).
    pub fn new(
        shape: SpectrumShape,
        significant_wave_height_m: f64,
        peak_period_s: f64,
    ) -> Result<Self, SeawayError> {
        const SECTION: &str = "environment.seaway";
        Bounds::positive_up_to(15.0).check(
            SECTION,
            "significant_wave_height_m",
            significant_wave_height_m,
        )?;
        Bounds::closed(4.0, 20.0).check(SECTION, "peak_period_s", peak_period_s)?;
        if let SpectrumShape::Jonswap { peak_factor } = shape {
            Bounds::closed(1.0, 7.0).check(SECTION, "peak_factor", peak_factor)?;
        }
        let mut spectrum = Self {
            shape,
            significant_wave_height_m,
            peak_period_s,
            normalisation: 1.0,
        };
        if matches!(shape, SpectrumShape::Jonswap { .. }) {
            let target = significant_wave_height_m.powi(2) / 16.0;
            spectrum.normalisation = target / spectrum.zeroth_moment_numerical();
        }
        Ok(spectrum)
    }

    /// The spectrum of sea state `sea_state` from [`SEA_STATE_TABLE`] with this shape.
    pub fn sea_state(shape: SpectrumShape, sea_state: u8) -> Result<Self, SeawayError> {
        let row = sea_state_row(sea_state)?;
        Self::new(shape, row.significant_wave_height_m, row.modal_period_s)
    }

    /// Significant wave height H_s (m).
    pub fn significant_wave_height_m(&self) -> f64 {
        self.significant_wave_height_m
    }

    /// Modal (peak) period T_p (s).
    pub fn peak_period_s(&self) -> f64 {
        self.peak_period_s
    }

    /// Modal (peak) frequency ω_p = 2π/T_p (rad/s).
    pub fn peak_frequency_radps(&self) -> f64 {
        std::f64::consts::TAU / self.peak_period_s
    }

    /// JONSWAP's normalising factor A_γ (1 for Pierson–Moskowitz).
    pub fn normalisation(&self) -> f64 {
        self.normalisation
    }

    /// Spectral density S(ω) (m²·s/rad) at wave frequency ω (rad/s); 0 for ω ≤ 0.
    pub fn density(&self, omega_radps: f64) -> f64 {
        if omega_radps <= 0.0 {
            return 0.0;
        }
        let omega_p = self.peak_frequency_radps();
        let ratio4 = (omega_p / omega_radps).powi(4);
        let pierson_moskowitz = 5.0 / 16.0 * self.significant_wave_height_m.powi(2) * ratio4
            / omega_radps
            * (-1.25 * ratio4).exp();
        match self.shape {
            SpectrumShape::PiersonMoskowitz => pierson_moskowitz,
            SpectrumShape::Jonswap { peak_factor } => {
                let sigma = if omega_radps <= omega_p {
                    JONSWAP_SIGMA_BELOW_PEAK
                } else {
                    JONSWAP_SIGMA_ABOVE_PEAK
                };
                let r =
                    (-(omega_radps - omega_p).powi(2) / (2.0 * (sigma * omega_p).powi(2))).exp();
                self.normalisation * pierson_moskowitz * peak_factor.powf(r)
            }
        }
    }

    /// m₀ = ∫ S dω (m²) by composite Simpson on [0.2ω_p, 12ω_p] (1600 panels) plus the
    /// ω⁻⁵ tail in closed form; the JONSWAP normalisation uses it.
    fn zeroth_moment_numerical(&self) -> f64 {
        let omega_p = self.peak_frequency_radps();
        let (lower, upper) = (0.2 * omega_p, 12.0 * omega_p);
        let integral = simpson(|omega| self.density(omega), lower, upper, 1600);
        // Above 12 ω_p the JONSWAP factor is 1 and exp(−1.25(ω_p/ω)⁴) ≈ 1: ∫ S ≈ S(u)·u/4.
        integral + self.density(upper) * upper / 4.0
    }
}

/// Composite Simpson's rule of `f` on [a, b] with `panels` (even) panels.
pub(crate) fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    let n = panels + panels % 2;
    let h = (b - a) / n as f64;
    let interior: f64 = (1..n)
        .map(|i| {
            let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
            weight * f(a + h * i as f64)
        })
        .sum();
    h / 3.0 * (f(a) + interior + f(b))
}

/// Encounter frequency ω_e = ω − ω²·U·cos μ/g (rad/s) of waves of frequency ω (rad/s)
/// met at speed U (m/s) from heading μ (rad; π = head seas); deep water (module docs).
pub fn encounter_frequency(omega_radps: f64, speed_mps: f64, heading_rad: f64) -> f64 {
    omega_radps - omega_radps.powi(2) * speed_mps * heading_rad.cos() / STANDARD_GRAVITY_MPS2
}

/// One wave frequency meeting the ship at a given |ω_e|: the wave frequency ω (rad/s) and
/// the Jacobian |dω_e/dω| = |1 − 2ωU cos μ/g| there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EncounterBranch {
    /// Wave frequency ω (rad/s).
    pub wave_frequency_radps: f64,
    /// |dω_e/dω| at that frequency (dimensionless).
    pub jacobian: f64,
}

/// Every wave frequency ω > 0 with |ω_e(ω)| = `encounter_radps` (> 0): one for cos μ ≤ 0 or
/// U = 0, up to three in following seas (module docs).
pub fn encounter_branches(
    encounter_radps: f64,
    speed_mps: f64,
    heading_rad: f64,
) -> Vec<EncounterBranch> {
    let a = speed_mps * heading_rad.cos() / STANDARD_GRAVITY_MPS2;
    let branch = |omega: f64| EncounterBranch {
        wave_frequency_radps: omega,
        jacobian: (1.0 - 2.0 * a * omega).abs(),
    };
    if a.abs() < 1e-12 {
        return vec![branch(encounter_radps)];
    }
    if a < 0.0 {
        // ω + |a|ω² = ω_e: the positive root, written to avoid cancellation.
        let omega = 2.0 * encounter_radps / (1.0 + (1.0 + 4.0 * a.abs() * encounter_radps).sqrt());
        return vec![branch(omega)];
    }
    let mut branches = Vec::with_capacity(3);
    let discriminant = 1.0 - 4.0 * a * encounter_radps;
    if discriminant > 0.0 {
        let root = discriminant.sqrt();
        branches.push(branch(2.0 * encounter_radps / (1.0 + root)));
        branches.push(branch((1.0 + root) / (2.0 * a)));
    }
    // ω − aω² = −ω_e: past the turning point, the waves overtake the ship.
    branches.push(branch(
        (1.0 + (1.0 + 4.0 * a * encounter_radps).sqrt()) / (2.0 * a),
    ));
    branches
}

/// Long-crested encounter spectrum S_e(ω_e) = S(ω)/|dω_e/dω| (m²·s/rad) at ω_e (rad/s) for
/// speed U (m/s) and heading μ (deg, 180 = head seas); refuses following and quartering
/// seas (U cos μ > 0), where the map is many-to-one (module docs).
pub fn encounter_spectrum(
    spectrum: &WaveSpectrum,
    encounter_radps: f64,
    speed_mps: f64,
    heading_deg: f64,
) -> Result<f64, SeawayError> {
    let heading = heading_deg.to_radians();
    if speed_mps * heading.cos() > 1e-9 {
        return Err(SeawayError::FollowingSeas {
            wave_heading_deg: heading_deg,
        });
    }
    if encounter_radps <= 0.0 {
        return Ok(0.0);
    }
    Ok(encounter_branches(encounter_radps, speed_mps, heading)
        .iter()
        .map(|b| spectrum.density(b.wave_frequency_radps) / b.jacobian)
        .sum())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sea_state_5() -> WaveSpectrum {
        WaveSpectrum::sea_state(SpectrumShape::PiersonMoskowitz, 5).expect("in the table")
    }

    /// The spectral moment m_n = ∫ ωⁿ S(ω) dω of `spectrum` from 0.05 ω_p to
    /// `upper_over_peak`·ω_p, by Simpson's rule on `panels` panels.
    fn spectral_moment(
        spectrum: &WaveSpectrum,
        n: i32,
        upper_over_peak: f64,
        panels: usize,
    ) -> f64 {
        let omega_p = spectrum.peak_frequency_radps();
        simpson(
            |w| w.powi(n) * spectrum.density(w),
            0.05 * omega_p,
            upper_over_peak * omega_p,
            panels,
        )
    }

    #[test]
    fn pierson_moskowitz_zeroth_moment_matches_closed_form() {
        // Closed form: ∫ A ω⁻⁵ exp(−B ω⁻⁴) dω = A/(4B) = H_s²/16 (module docs).
        let numerical = spectral_moment(&sea_state_5(), 0, 60.0, 20_000);
        let closed = 3.25_f64.powi(2) / 16.0;
        assert!(
            (numerical / closed - 1.0).abs() < 1e-3,
            "{numerical} vs {closed}"
        );
        assert!((4.0 * numerical.sqrt() - 3.25).abs() < 3e-3);
    }

    #[test]
    fn pierson_moskowitz_zero_crossing_period_is_0_710_of_the_modal_period() {
        // Closed form T_z = T_p/(5π/4)^{1/4} = 0.7104 T_p (e.g. DNV-RP-C205 Table 3-1's
        // T_p = 1.4049 T_z for γ = 1).
        let spectrum = sea_state_5();
        let m0 = spectral_moment(&spectrum, 0, 400.0, 200_000);
        let m2 = spectral_moment(&spectrum, 2, 400.0, 200_000);
        let t_z = std::f64::consts::TAU * (m0 / m2).sqrt();
        let expected = 9.7 / (1.25 * std::f64::consts::PI).powf(0.25);
        // The ω⁻³ tail of m₂ beyond 400 ω_p is left out: about 3·10⁻⁶ of m₂.
        assert!(
            (t_z / expected - 1.0).abs() < 2e-3,
            "T_z {t_z} vs {expected}"
        );
    }

    #[test]
    fn spectra_peak_at_the_modal_frequency() {
        for shape in [
            SpectrumShape::PiersonMoskowitz,
            SpectrumShape::Jonswap { peak_factor: 3.3 },
        ] {
            let spectrum = WaveSpectrum::new(shape, 3.25, 9.7).expect("valid");
            let omega_p = std::f64::consts::TAU / 9.7;
            let peak = (1..4000)
                .map(|i| 0.0005 * i as f64)
                .max_by(|a, b| spectrum.density(*a).total_cmp(&spectrum.density(*b)))
                .expect("non-empty");
            assert!(
                (peak - omega_p).abs() < 1e-3,
                "{shape:?}: peak {peak} vs {omega_p}"
            );
        }
    }

    #[test]
    fn jonswap_is_normalised_to_the_significant_height() {
        let spectrum = WaveSpectrum::new(SpectrumShape::Jonswap { peak_factor: 3.3 }, 3.25, 9.7)
            .expect("valid");
        let m0 = simpson(|w| spectrum.density(w), 0.01, 30.0, 60_000);
        assert!((4.0 * m0.sqrt() / 3.25 - 1.0).abs() < 1e-3);
        // DNV-RP-C205 §3.5.5.5: A_γ ≈ 1 − 0.287 ln γ = 0.657 for γ = 3.3 (an approximation).
        let approx = 1.0 - 0.287 * 3.3_f64.ln();
        assert!((spectrum.normalisation() / approx - 1.0).abs() < 0.02);
    }

    #[test]
    fn encounter_frequency_by_hand() {
        // Head seas at 15 kn (7.7167 m/s), ω = 0.6: 0.6 + 0.36·7.7167/9.80665 = 0.88328.
        let u = 15.0 * 1852.0 / 3600.0;
        let head = encounter_frequency(0.6, u, std::f64::consts::PI);
        assert!((head - 0.883_28).abs() < 1e-5, "{head}");
        // Beam seas: ω_e = ω. Following seas, ω = 1: 1 − 7.7167/9.80665 = 0.21311.
        assert!((encounter_frequency(0.6, u, std::f64::consts::FRAC_PI_2) - 0.6).abs() < 1e-12);
        assert!((encounter_frequency(1.0, u, 0.0) - 0.213_11).abs() < 1e-5);
    }

    #[test]
    fn encounter_branches_invert_the_encounter_frequency() {
        let u = 7.7;
        for heading_deg in [180.0_f64, 135.0, 90.0, 45.0, 0.0] {
            let heading = heading_deg.to_radians();
            for omega_e in [0.05, 0.2, 0.3, 0.9] {
                for b in encounter_branches(omega_e, u, heading) {
                    let back = encounter_frequency(b.wave_frequency_radps, u, heading).abs();
                    assert!(
                        (back - omega_e).abs() < 1e-9,
                        "{heading_deg}: {back} vs {omega_e}"
                    );
                }
            }
        }
        // Following seas below the turning point 1/(4a) meet three wave frequencies.
        assert_eq!(encounter_branches(0.2, u, 0.0).len(), 3);
    }

    #[test]
    fn encounter_spectrum_keeps_the_variance_in_head_seas() {
        let spectrum = sea_state_5();
        let u = 7.7;
        let m0_e = simpson(
            |w| encounter_spectrum(&spectrum, w, u, 180.0).expect("head seas"),
            1e-4,
            40.0,
            40_000,
        );
        assert!(
            (m0_e / (3.25_f64.powi(2) / 16.0) - 1.0).abs() < 2e-3,
            "{m0_e}"
        );
    }

    #[test]
    fn following_seas_and_bad_input_are_refused_by_name() {
        let spectrum = sea_state_5();
        assert!(matches!(
            encounter_spectrum(&spectrum, 0.5, 7.7, 30.0),
            Err(SeawayError::FollowingSeas { .. })
        ));
        let error = WaveSpectrum::new(SpectrumShape::PiersonMoskowitz, 3.0, 30.0).unwrap_err();
        assert!(error.to_string().contains("peak_period_s"), "{error}");
        assert!(matches!(
            sea_state_row(9),
            Err(SeawayError::UnknownSeaState { sea_state: 9 })
        ));
    }
}
