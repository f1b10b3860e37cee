//! The ship's motion as the aircraft receives it (docs/model.md §3.5).
//!
//! A real aircraft cannot read the ship-motion filters' state. The ship's inertial
//! navigation measures heave, heave rate, pitch and pitch rate at its own sample rate;
//! each measurement carries white noise and reaches the aircraft's guidance computer over
//! a data link `latency_s` later. All four are used: heave and pitch fix the position,
//! the two rates the phase of the ship's slow oscillation, which is what a prediction
//! seconds ahead needs most (the pitch filter's lightly damped pair at 0.4 rad/s).
//!
//! The defaults are assumptions (docs/model.md §3.5 names them as such), chosen as a
//! navigation-grade ship's inertial system's figures: heave σ 0.05 m, heave rate σ
//! 0.05 m/s, pitch σ 0.02°, pitch rate σ 0.02 °/s, 50 Hz, 0.1 s latency.
//!
//! Sampling is on the integration grid: a sample is taken at the first step at or after
//! each multiple of the sample period and stamped with that step's time; it is delivered
//! at the first step at or after its time plus the latency. Each channel's noise comes
//! from its own stream (`ship_sensor_heave`, …; docs/model.md §3.4).

use super::channel_sensor::{ChannelMeasurement, ChannelSensor};
use super::data_link::Stamped;

use serde::{Deserialize, Serialize};

use crate::environment::ShipMotionOutputs;
use crate::parameters::{check_ranges, Bounds, ParameterError};
use crate::random::{stream_names, NoiseStream, RandomStreams};

/// Noise, rate and latency of the ship-motion measurements (docs/model.md §3.5).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ShipMotionSensingParameters {
    /// Standard deviation of the heave measurement (m); assumption: 0.05.
    pub heave_sigma_m: f64,
    /// Standard deviation of the heave-rate measurement (m/s); assumption: 0.05.
    pub heave_rate_sigma_mps: f64,
    /// Standard deviation of the pitch measurement (deg); assumption: 0.02.
    pub pitch_sigma_deg: f64,
    /// Standard deviation of the pitch-rate measurement (deg/s); assumption: 0.02.
    pub pitch_rate_sigma_degps: f64,
    /// Sample rate of the ship's inertial navigation on the data link (Hz); assumption: 50.
    pub sample_rate_hz: f64,
    /// Delay from a sample to its arrival at the aircraft (s); assumption: 0.1.
    pub latency_s: f64,
    /// How the deck-motion estimator starts: `converged` (it has tracked the ship over
    /// the data link since long before the run; the default) or `cold` (knowing only
    /// the model; docs/model.md §3.5).
    pub estimator_start: EstimatorStart,
    /// Standard deviation of the roll measurement (deg); assumption: 0.02 (§3.7).
    pub roll_sigma_deg: f64,
    /// Standard deviation of the roll-rate measurement (deg/s); assumption: 0.02.
    pub roll_rate_sigma_degps: f64,
    /// Standard deviation of the yaw measurement (deg); assumption: 0.02 (§3.7).
    pub yaw_sigma_deg: f64,
    /// Standard deviation of the yaw-rate measurement (deg/s); assumption: 0.02.
    pub yaw_rate_sigma_degps: f64,
    /// Standard deviation of the sway measurement (m); assumption: 0.05 (§3.7).
    pub sway_sigma_m: f64,
    /// Standard deviation of the sway-rate measurement (m/s); assumption: 0.05.
    pub sway_rate_sigma_mps: f64,
}

/// How the deck-motion estimator starts (docs/model.md §3.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EstimatorStart {
    /// At its steady state, as after tracking the ship since long before the run: the
    /// guidance computer receives the ship's motion during the whole approach, and the
    /// pitch filter's slowest state takes about 1000 s to settle. The default.
    #[default]
    Converged,
    /// Knowing only the model: estimate 0, covariance the stationary one.
    Cold,
}

impl Default for ShipMotionSensingParameters {
    fn default() -> Self {
        Self {
            heave_sigma_m: 0.05,
            heave_rate_sigma_mps: 0.05,
            pitch_sigma_deg: 0.02,
            pitch_rate_sigma_degps: 0.02,
            sample_rate_hz: 50.0,
            latency_s: 0.1,
            estimator_start: EstimatorStart::Converged,
            roll_sigma_deg: 0.02,
            roll_rate_sigma_degps: 0.02,
            yaw_sigma_deg: 0.02,
            yaw_rate_sigma_degps: 0.02,
            sway_sigma_m: 0.05,
            sway_rate_sigma_mps: 0.05,
        }
    }
}

impl ShipMotionSensingParameters {
    /// The section's dotted path.
    pub const SECTION: &'static str = "environment.ship_sensing";

    /// Checks every field: σ in (0, 5] m and m/s, (0, 5]° and °/s (a perfect sensor has
    /// no Kalman filter: its measurement covariance must be invertible), the same for
    /// roll, yaw and sway (docs/model.md §3.7); sample rate 1–1000 Hz; latency 0–5 s.
    pub fn validate(&self) -> Result<(), ParameterError> {
        let section = Self::SECTION;
        let sigma = Bounds::positive_up_to(5.0);
        sigma.check(section, "heave_sigma_m", self.heave_sigma_m)?;
        sigma.check(section, "heave_rate_sigma_mps", self.heave_rate_sigma_mps)?;
        sigma.check(section, "pitch_sigma_deg", self.pitch_sigma_deg)?;
        sigma.check(
            section,
            "pitch_rate_sigma_degps",
            self.pitch_rate_sigma_degps,
        )?;
        check_ranges!(section, self, {
            sample_rate_hz: Bounds::closed(1.0, 1000.0),
            latency_s: Bounds::closed(0.0, 5.0),
        });
        for (key, value) in [
            ("roll_sigma_deg", self.roll_sigma_deg),
            ("roll_rate_sigma_degps", self.roll_rate_sigma_degps),
            ("yaw_sigma_deg", self.yaw_sigma_deg),
            ("yaw_rate_sigma_degps", self.yaw_rate_sigma_degps),
            ("sway_sigma_m", self.sway_sigma_m),
            ("sway_rate_sigma_mps", self.sway_rate_sigma_mps),
        ] {
            sigma.check(section, key, value)?;
        }
        Ok(())
    }

    /// The lateral standard deviations in SI units: roll (rad), roll rate (rad/s), yaw
    /// (rad), yaw rate (rad/s), sway (m), sway rate (m/s).
    pub fn lateral_sigmas_si(&self) -> [f64; 6] {
        [
            self.roll_sigma_deg.to_radians(),
            self.roll_rate_sigma_degps.to_radians(),
            self.yaw_sigma_deg.to_radians(),
            self.yaw_rate_sigma_degps.to_radians(),
            self.sway_sigma_m,
            self.sway_rate_sigma_mps,
        ]
    }

    /// The standard deviations in SI units: heave (m), heave rate (m/s), pitch (rad),
    /// pitch rate (rad/s).
    pub fn sigmas_si(&self) -> [f64; 4] {
        [
            self.heave_sigma_m,
            self.heave_rate_sigma_mps,
            self.pitch_sigma_deg.to_radians(),
            self.pitch_rate_sigma_degps.to_radians(),
        ]
    }
}

/// One measurement of the ship's motion, as sent over the data link.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipMotionMeasurement {
    /// The time the sample was taken (s).
    pub time_s: f64,
    /// Heave (m, up).
    pub heave_m: f64,
    /// Heave rate (m/s, up).
    pub heave_rate_mps: f64,
    /// Pitch (rad, bow up).
    pub pitch_rad: f64,
    /// Pitch rate (rad/s).
    pub pitch_rate_radps: f64,
}

/// The ship's inertial navigation and the data link: samples, noise and latency.
pub type ShipMotionSensor = ChannelSensor<ShipMotionMeasurement, 4>;

impl Stamped for ShipMotionMeasurement {
    fn time_s(&self) -> f64 {
        self.time_s
    }
}

impl ChannelMeasurement<4> for ShipMotionMeasurement {
    type Truth = ShipMotionOutputs;

    fn sigmas(parameters: &ShipMotionSensingParameters) -> [f64; 4] {
        parameters.sigmas_si()
    }

    /// The four `ship_sensor_*` streams: heave, heave rate, pitch, pitch rate.
    fn streams(streams: &RandomStreams) -> [NoiseStream; 4] {
        [
            stream_names::SHIP_SENSOR_HEAVE,
            stream_names::SHIP_SENSOR_HEAVE_RATE,
            stream_names::SHIP_SENSOR_PITCH,
            stream_names::SHIP_SENSOR_PITCH_RATE,
        ]
        .map(|name| streams.stream(name))
    }

    fn with_noise(time_s: f64, truth: &ShipMotionOutputs, noise: [f64; 4]) -> Self {
        ShipMotionMeasurement {
            time_s,
            heave_m: truth.heave_m + noise[0],
            heave_rate_mps: truth.heave_rate_mps + noise[1],
            pitch_rad: truth.pitch_rad + noise[2],
            pitch_rate_radps: truth.pitch_rate_radps + noise[3],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn truth(heave_m: f64) -> ShipMotionOutputs {
        ShipMotionOutputs {
            heave_m,
            ..ShipMotionOutputs::default()
        }
    }

    #[test]
    fn samples_at_the_rate_and_delivers_after_the_latency() {
        let mut sensor = ShipMotionSensor::new(
            ShipMotionSensingParameters::default(),
            &RandomStreams::new(1),
        )
        .expect("defaults are valid");
        let mut arrivals = Vec::new();
        for k in 0..200_u32 {
            let t = f64::from(k) * 0.001;
            sensor.sample(t, &truth(t));
            while let Some(m) = sensor.receive(t) {
                arrivals.push((t, m.time_s));
            }
        }
        // 50 Hz: samples at 0, 20, 40, … ms; arriving 100 ms later, by 199 ms the
        // samples of 0–80 ms have arrived (five of them).
        let sent: Vec<f64> = arrivals.iter().map(|a| a.1).collect();
        assert_eq!(sent.len(), 5, "{arrivals:?}");
        for (i, (arrived, sent)) in arrivals.iter().enumerate() {
            assert!((sent - 0.02 * i as f64).abs() < 1e-12);
            assert!((arrived - sent - 0.1).abs() < 1e-12);
        }
    }

    #[test]
    fn noise_has_the_configured_standard_deviation() {
        let parameters = ShipMotionSensingParameters {
            latency_s: 0.0,
            sample_rate_hz: 1000.0,
            ..ShipMotionSensingParameters::default()
        };
        let mut sensor = ShipMotionSensor::new(parameters, &RandomStreams::new(2)).unwrap();
        let n = 20_000;
        let (mut sum_heave, mut sum_pitch) = (0.0, 0.0);
        for k in 0..n {
            let t = f64::from(k) * 0.001;
            sensor.sample(t, &truth(0.0));
            let m = sensor.receive(t).expect("no latency");
            sum_heave += m.heave_m * m.heave_m;
            sum_pitch += m.pitch_rad * m.pitch_rad;
        }
        // The sample variance of n normal draws has a relative standard error √(2/n) = 1 %.
        let heave = (sum_heave / f64::from(n)).sqrt();
        let pitch = (sum_pitch / f64::from(n)).sqrt();
        assert!((heave / 0.05 - 1.0).abs() < 0.02, "{heave}");
        assert!(
            (pitch / 0.02_f64.to_radians() - 1.0).abs() < 0.02,
            "{pitch}"
        );
    }

    #[test]
    fn a_perfect_or_absurd_sensor_is_refused_by_name() {
        for (parameters, key) in [
            (
                ShipMotionSensingParameters {
                    heave_sigma_m: 0.0,
                    ..Default::default()
                },
                "environment.ship_sensing.heave_sigma_m",
            ),
            (
                ShipMotionSensingParameters {
                    latency_s: 10.0,
                    ..Default::default()
                },
                "environment.ship_sensing.latency_s",
            ),
        ] {
            let error = parameters.validate().unwrap_err();
            assert_eq!(error.path, key);
        }
    }
}
