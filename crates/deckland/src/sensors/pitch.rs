//! Pitch-attitude measurement (paper §3.5; docs/model.md §3.3).
//!
//! θ_m = θ + a·sin(ω·t) + n, with a = 0.001 rad, ω = 7 rad/s and n ~ N(0, σ²),
//! σ = 0.001 rad (MATLAB `wgn` at −60 dBW: variance 10⁻⁶), drawn anew at every control
//! step from the `pitch_noise` stream.

use serde::{Deserialize, Serialize};

use crate::parameters::{check_ranges, Bounds, ParameterError};
use crate::random::{stream_names, NoiseStream, RandomStreams, Reseed};

/// Configuration of the pitch-attitude measurement noise (docs/model.md §3.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PitchNoiseParameters {
    /// Whether the measurement is noisy; when false θ_m = θ.
    pub enabled: bool,
    /// Amplitude a of the sinusoidal error (rad); paper §3.5: 0.001.
    pub sinusoid_amplitude_rad: f64,
    /// Frequency ω of the sinusoidal error (rad/s); paper §3.5: 7.
    pub sinusoid_frequency_radps: f64,
    /// Standard deviation σ of the white noise per control step (rad); docs/model.md §3.3: 0.001.
    pub white_noise_sigma_rad: f64,
}

impl Default for PitchNoiseParameters {
    fn default() -> Self {
        Self {
            enabled: true,
            sinusoid_amplitude_rad: 0.001,
            sinusoid_frequency_radps: 7.0,
            white_noise_sigma_rad: 0.001,
        }
    }
}

impl PitchNoiseParameters {
    /// Checks every field: amplitude and σ in [0, 0.1] rad, frequency in [0, 1000] rad/s.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "environment.pitch_noise";
        check_ranges!(SECTION, self, {
            sinusoid_amplitude_rad: Bounds::closed(0.0, 0.1),
            sinusoid_frequency_radps: Bounds::closed(0.0, 1000.0),
            white_noise_sigma_rad: Bounds::closed(0.0, 0.1),
        });
        Ok(())
    }
}

/// The pitch-attitude sensor with its own random stream (paper §3.5).
#[derive(Debug, Clone)]
pub struct PitchSensor {
    parameters: PitchNoiseParameters,
    stream: NoiseStream,
}

impl PitchSensor {
    /// A sensor with these parameters drawing from the `pitch_noise` stream.
    pub fn new(
        parameters: PitchNoiseParameters,
        streams: &RandomStreams,
    ) -> Result<Self, ParameterError> {
        parameters.validate()?;
        Ok(Self {
            parameters,
            stream: streams.stream(stream_names::PITCH_NOISE),
        })
    }

    /// The parameters the sensor was built from.
    pub fn parameters(&self) -> &PitchNoiseParameters {
        &self.parameters
    }

    /// The measurement θ_m (rad) of the true pitch `pitch_rad` (rad) at time `time_s` (s):
    /// θ + a·sin(ω·t) + σ·n. Draws one sample: call once per control step. Returns θ
    /// unchanged, drawing nothing, when the noise is disabled.
    pub fn measure(&mut self, time_s: f64, pitch_rad: f64) -> f64 {
        pitch_rad + self.draw_white_noise() + self.sinusoid(time_s)
    }

    /// The white part σ·n (rad) of the error, drawn once per control step and held over
    /// it by the simulation; zero, drawing nothing, when the noise is disabled.
    pub fn draw_white_noise(&mut self) -> f64 {
        let p = &self.parameters;
        if !p.enabled {
            return 0.0;
        }
        p.white_noise_sigma_rad * self.stream.standard_normal()
    }

    /// The periodic part a·sin(ω·t) (rad) of the error at time `time_s` (s); zero when the
    /// noise is disabled.
    #[inline]
    pub fn sinusoid(&self, time_s: f64) -> f64 {
        let p = &self.parameters;
        if !p.enabled {
            return 0.0;
        }
        p.sinusoid_amplitude_rad * (p.sinusoid_frequency_radps * time_s).sin()
    }
}

impl Reseed for PitchSensor {
    fn reseed(&mut self, key: u64) {
        self.stream.reseed(key);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_has_specified_mean_variance_and_sinusoid() {
        let parameters = PitchNoiseParameters::default();
        let mut sensor = PitchSensor::new(parameters, &RandomStreams::new(9)).expect("valid");
        let (dt, count) = (0.001, 400_000);
        let pitch_rad = 0.1;
        let (mut sum, mut sum_squares, mut sine_projection) = (0.0, 0.0, 0.0);
        for k in 0..count {
            let t = k as f64 * dt;
            let sine = (7.0 * t).sin();
            let error = sensor.measure(t, pitch_rad) - pitch_rad;
            // Remove the sinusoid the paper specifies to leave the white noise.
            let white = error - 0.001 * sine;
            sum += white;
            sum_squares += white * white;
            sine_projection += error * sine;
        }
        let n = count as f64;
        let mean = sum / n;
        let variance = sum_squares / n - mean * mean;
        // Independent N(0, σ²) samples: the mean has standard error σ/√n = 1.6e-6 rad, the
        // variance σ²·√(2/n) = 2.2e-9 rad². Tolerances are 4 standard errors.
        assert!(mean.abs() < 4.0 * 0.001 / n.sqrt(), "mean {mean}");
        assert!(
            (variance - 1e-6).abs() < 4.0 * 1e-6 * (2.0 / n).sqrt(),
            "variance {variance}"
        );
        // Over 400 s (445.6 periods) ⟨sin²⟩ ≈ ½: the projection recovers a = 0.001.
        let amplitude = 2.0 * sine_projection / n;
        assert!((amplitude - 0.001).abs() < 1e-5, "amplitude {amplitude}");
    }

    #[test]
    fn disabled_noise_returns_the_true_pitch() {
        let parameters = PitchNoiseParameters {
            enabled: false,
            ..PitchNoiseParameters::default()
        };
        let mut sensor = PitchSensor::new(parameters, &RandomStreams::new(9)).expect("valid");
        assert_eq!(sensor.measure(0.3, 0.05), 0.05);
    }
}
