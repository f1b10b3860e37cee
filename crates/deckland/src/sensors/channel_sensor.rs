//! A ship-motion sensor of `N` channels (docs/model.md §3.5, §3.7): each channel's
//! sample carries white noise of its own σ from its own stream, and the samples travel
//! over the data link. The heave and pitch sensor ([`super::ShipMotionSensor`]) and the
//! roll, yaw and sway sensor ([`super::LateralShipMotionSensor`]) are this sensor on
//! their measurements.

use super::data_link::{DataLink, Stamped};
use super::ShipMotionSensingParameters;
use crate::parameters::ParameterError;
use crate::random::{NoiseStream, RandomStreams, Reseed};

/// A ship-motion measurement of `N` channels: the σ and the stream of each channel, and
/// how a sample of the truth with one noise value per channel becomes a measurement.
pub trait ChannelMeasurement<const N: usize>: Stamped + Sized {
    /// The true motion the sensor samples.
    type Truth;

    /// Each channel's σ (SI) from `parameters`.
    fn sigmas(parameters: &ShipMotionSensingParameters) -> [f64; N];

    /// Each channel's noise stream of the scenario, from its start.
    fn streams(streams: &RandomStreams) -> [NoiseStream; N];

    /// The measurement of `truth` at `time_s` with `noise` added channel by channel.
    fn with_noise(time_s: f64, truth: &Self::Truth, noise: [f64; N]) -> Self;
}

/// One noise value of σ `sigmas[i]` from each channel's stream, in the channels' order.
pub(super) fn channel_noise<const N: usize>(
    sigmas: &[f64; N],
    streams: &mut [NoiseStream; N],
) -> [f64; N] {
    std::array::from_fn(|i| sigmas[i] * streams[i].standard_normal())
}

/// The ship's inertial navigation on the channels of `M` and the data link: samples,
/// noise and latency.
#[derive(Debug, Clone)]
pub struct ChannelSensor<M, const N: usize> {
    sigmas: [f64; N],
    streams: [NoiseStream; N],
    link: DataLink<M>,
}

impl<M: ChannelMeasurement<N>, const N: usize> ChannelSensor<M, N> {
    /// A sensor with these parameters, its noise from its channels' `ship_sensor_*`
    /// streams of `streams`.
    pub fn new(
        parameters: ShipMotionSensingParameters,
        streams: &RandomStreams,
    ) -> Result<Self, ParameterError> {
        Ok(Self {
            sigmas: M::sigmas(&parameters),
            streams: M::streams(streams),
            link: DataLink::new(parameters)?,
        })
    }

    /// The parameters.
    pub fn parameters(&self) -> &ShipMotionSensingParameters {
        self.link.parameters()
    }

    /// Whether a sample is due at the step from `time_s` (the first step at or after a
    /// multiple of the sample period).
    pub fn sample_due(&self, time_s: f64) -> bool {
        self.link.sample_due(time_s)
    }

    /// Takes a sample of the true motion `truth` at `time_s` if one is due, drawing one
    /// number from each channel's stream, and puts it on the data link.
    pub fn sample(&mut self, time_s: f64, truth: &M::Truth) {
        let (sigmas, streams) = (&self.sigmas, &mut self.streams);
        self.link.sample(time_s, || {
            M::with_noise(time_s, truth, channel_noise(sigmas, streams))
        });
    }

    /// The oldest measurement that has arrived by `time_s` (sent at or before
    /// `time_s` − latency), if any; call until `None` to take every arrival.
    pub fn receive(&mut self, time_s: f64) -> Option<M> {
        self.link.receive(time_s)
    }
}

impl<M, const N: usize> Reseed for ChannelSensor<M, N> {
    fn reseed(&mut self, key: u64) {
        self.streams.reseed(key);
    }
}
