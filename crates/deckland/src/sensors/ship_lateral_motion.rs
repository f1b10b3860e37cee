//! The ship's roll, yaw and sway as the aircraft receives them (docs/model.md §3.7;
//! shared model §10.5).
//!
//! The ship's inertial navigation measures roll, yaw, sway and their rates beside heave
//! and pitch ([`super::ShipMotionSensor`]), at the same sample rate and over the same
//! data link with the same latency; each channel carries white noise from its own
//! stream (`ship_sensor_roll`, `ship_sensor_roll_rate`, …; docs/model.md §3.4), so the
//! heave and pitch channels are unchanged. The defaults are assumptions like §3.5's:
//! roll and yaw σ 0.02° (rates 0.02 °/s), sway σ 0.05 m (rate 0.05 m/s).
//!
//! Sampling is on the integration grid as for heave and pitch: a sample is taken at the
//! first step at or after each multiple of the sample period and delivered at the first
//! step at or after its time plus the latency.

use super::channel_sensor::{channel_noise, ChannelMeasurement, ChannelSensor};
use super::data_link::Stamped;
use super::ShipMotionSensingParameters;
use crate::environment::LateralShipMotionOutputs;
use crate::random::{stream_names, NoiseStream, RandomStreams};

/// One measurement of the ship's roll, yaw and sway, as sent over the data link.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateralShipMotionMeasurement {
    /// The time the sample was taken (s).
    pub time_s: f64,
    /// The roll, yaw and sway measured, with their rates (noisy, as measured; the units
    /// and signs of the truth's).
    pub motion: LateralShipMotionOutputs,
}

/// The measurement of `truth` at `time_s` with one noise sample of σ `sigmas` (SI, in
/// the order of [`ShipMotionSensingParameters::lateral_sigmas_si`]) from each stream.
pub fn measure_lateral_ship_motion(
    time_s: f64,
    truth: &LateralShipMotionOutputs,
    sigmas: &[f64; 6],
    streams: &mut [NoiseStream; 6],
) -> LateralShipMotionMeasurement {
    LateralShipMotionMeasurement::with_noise(time_s, truth, channel_noise(sigmas, streams))
}

/// The six lateral noise streams of the scenario, from their start.
pub fn lateral_ship_sensor_streams(streams: &RandomStreams) -> [NoiseStream; 6] {
    [
        stream_names::SHIP_SENSOR_ROLL,
        stream_names::SHIP_SENSOR_ROLL_RATE,
        stream_names::SHIP_SENSOR_YAW,
        stream_names::SHIP_SENSOR_YAW_RATE,
        stream_names::SHIP_SENSOR_SWAY,
        stream_names::SHIP_SENSOR_SWAY_RATE,
    ]
    .map(|name| streams.stream(name))
}

/// The lateral channels of the ship's inertial navigation and the data link: samples,
/// noise and latency (as [`super::ShipMotionSensor`]'s, on the same link).
pub type LateralShipMotionSensor = ChannelSensor<LateralShipMotionMeasurement, 6>;

impl Stamped for LateralShipMotionMeasurement {
    fn time_s(&self) -> f64 {
        self.time_s
    }
}

impl ChannelMeasurement<6> for LateralShipMotionMeasurement {
    type Truth = LateralShipMotionOutputs;

    fn sigmas(parameters: &ShipMotionSensingParameters) -> [f64; 6] {
        parameters.lateral_sigmas_si()
    }

    fn streams(streams: &RandomStreams) -> [NoiseStream; 6] {
        lateral_ship_sensor_streams(streams)
    }

    fn with_noise(time_s: f64, truth: &LateralShipMotionOutputs, noise: [f64; 6]) -> Self {
        LateralShipMotionMeasurement {
            time_s,
            motion: LateralShipMotionOutputs {
                roll_rad: truth.roll_rad + noise[0],
                roll_rate_radps: truth.roll_rate_radps + noise[1],
                yaw_rad: truth.yaw_rad + noise[2],
                yaw_rate_radps: truth.yaw_rate_radps + noise[3],
                sway_m: truth.sway_m + noise[4],
                sway_rate_mps: truth.sway_rate_mps + noise[5],
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_has_the_configured_standard_deviations_and_arrives_late() {
        let parameters = ShipMotionSensingParameters {
            sample_rate_hz: 1000.0,
            ..ShipMotionSensingParameters::default()
        };
        let mut sensor = LateralShipMotionSensor::new(parameters, &RandomStreams::new(9))
            .expect("defaults are valid");
        let truth = LateralShipMotionOutputs {
            sway_m: 1.0,
            ..LateralShipMotionOutputs::default()
        };
        let n = 20_000_u32;
        let mut sums = [0.0; 6];
        let mut first_arrival = None;
        for k in 0..n + 100 {
            let t = f64::from(k) * 0.001;
            if k < n {
                sensor.sample(t, &truth);
            }
            while let Some(m) = sensor.receive(t) {
                first_arrival.get_or_insert(t);
                let errors = [
                    m.motion.roll_rad,
                    m.motion.roll_rate_radps,
                    m.motion.yaw_rad,
                    m.motion.yaw_rate_radps,
                    m.motion.sway_m - 1.0,
                    m.motion.sway_rate_mps,
                ];
                for (sum, e) in sums.iter_mut().zip(errors) {
                    *sum += e * e;
                }
            }
        }
        // 0.1 s latency: the sample of t = 0 arrives at 0.1 s.
        assert!((first_arrival.expect("arrivals") - 0.1).abs() < 1e-12);
        // The sample variance of n normal draws has a relative standard error √(2/n) = 1 %.
        let expected = [
            0.02_f64.to_radians(),
            0.02_f64.to_radians(),
            0.02_f64.to_radians(),
            0.02_f64.to_radians(),
            0.05,
            0.05,
        ];
        for (i, (sum, sigma)) in sums.iter().zip(expected).enumerate() {
            let rms = (sum / f64::from(n)).sqrt();
            assert!(
                (rms / sigma - 1.0).abs() < 0.03,
                "channel {i}: {rms} vs {sigma}"
            );
        }
    }

    #[test]
    fn a_perfect_lateral_sensor_is_refused_by_name() {
        let parameters = ShipMotionSensingParameters {
            sway_rate_sigma_mps: 0.0,
            ..ShipMotionSensingParameters::default()
        };
        let error = parameters.validate().unwrap_err();
        assert_eq!(error.path, "environment.ship_sensing.sway_rate_sigma_mps");
    }
}
