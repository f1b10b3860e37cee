//! The ship motion stepped on its own with RK4 (docs/model.md §3.1, §6), for the command
//! line and tests. A landing simulation instead folds [`ShipMotion::derivative`] into
//! its own larger system.

use super::deck::{ShipPose, ShipPoseRate};
use super::ship::{
    ShipMotion, ShipMotionOutputs, ShipMotionParameters, ShipMotionState, ShipNoise,
};
use crate::integration::{rk4_step, OdeSystem};
use crate::parameters::ParameterError;
use crate::random::{stream_names, NoiseStream, RandomStreams};

/// The shaping filters under one step's held noise, as the integrator sees them.
struct ForcedShipMotion<'a> {
    model: &'a ShipMotion,
    noise: ShipNoise,
}

impl OdeSystem<8> for ForcedShipMotion<'_> {
    fn derivative(&self, _t: f64, x: &[f64; 8]) -> [f64; 8] {
        self.model
            .derivative(&ShipMotionState::from_array(x), self.noise)
            .to_array()
    }
}

/// Ship motion with its state, clock and the `ship_heave` and `ship_pitch` streams.
#[derive(Debug, Clone)]
pub struct ShipMotionSimulator {
    model: ShipMotion,
    state: ShipMotionState,
    time_s: f64,
    initial_pitch_centre_x_m: f64,
    heave_stream: NoiseStream,
    pitch_stream: NoiseStream,
}

impl ShipMotionSimulator {
    /// A simulator at t = 0 started from the stationary distribution, the pitch centre at
    /// earth x = `initial_pitch_centre_x_m` (m).
    pub fn new(
        parameters: ShipMotionParameters,
        streams: &RandomStreams,
        initial_pitch_centre_x_m: f64,
    ) -> Result<Self, ParameterError> {
        Ok(Self::with_model(
            ShipMotion::new(parameters)?,
            streams,
            initial_pitch_centre_x_m,
        ))
    }

    /// As [`ShipMotionSimulator::new`] for a built model (any ship model's filters).
    pub fn with_model(
        model: ShipMotion,
        streams: &RandomStreams,
        initial_pitch_centre_x_m: f64,
    ) -> Self {
        let mut heave_stream = streams.stream(stream_names::SHIP_HEAVE);
        let mut pitch_stream = streams.stream(stream_names::SHIP_PITCH);
        let state = model.stationary_initial_state(&mut heave_stream, &mut pitch_stream);
        Self {
            model,
            state,
            time_s: 0.0,
            initial_pitch_centre_x_m,
            heave_stream,
            pitch_stream,
        }
    }

    /// Advances by `dt` (s, > 0) with one RK4 step, one noise sample per filter held
    /// over the step.
    pub fn step(&mut self, dt: f64) {
        let noise = self
            .model
            .draw_noise(&mut self.heave_stream, &mut self.pitch_stream, dt);
        let system = ForcedShipMotion {
            model: &self.model,
            noise,
        };
        let next = rk4_step(&system, self.time_s, &self.state.to_array(), dt);
        self.state = ShipMotionState::from_array(&next);
        self.time_s += dt;
    }

    /// The model.
    pub fn model(&self) -> &ShipMotion {
        &self.model
    }

    /// The current time (s).
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// The current filter state.
    pub fn state(&self) -> &ShipMotionState {
        &self.state
    }

    /// The current heave, pitch and rates.
    pub fn outputs(&self) -> ShipMotionOutputs {
        self.model.outputs(&self.state)
    }

    /// The current pose (pitch-centre position, heave, pitch).
    pub fn pose(&self) -> ShipPose {
        self.model
            .pose(&self.state, self.initial_pitch_centre_x_m, self.time_s)
    }

    /// The current pose's rates.
    pub fn pose_rate(&self) -> ShipPoseRate {
        self.model.pose_rate(&self.state)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Heave and pitch records sampled every `sample_every` steps of `dt`.
    fn record(seed: u64, dt: f64, steps: usize, sample_every: usize) -> (Vec<f64>, Vec<f64>) {
        let mut ship = ShipMotionSimulator::new(
            ShipMotionParameters::default(),
            &RandomStreams::new(seed),
            0.0,
        )
        .expect("default parameters are valid");
        let (mut heave, mut pitch) = (Vec::new(), Vec::new());
        for k in 0..steps {
            if k % sample_every == 0 {
                let outputs = ship.outputs();
                heave.push(outputs.heave_m);
                pitch.push(outputs.pitch_rad);
            }
            ship.step(dt);
        }
        (heave, pitch)
    }

    /// Mean of the batch mean squares and its standard error from the spread of the
    /// batches (batch-means method; the batches are much longer than the correlation
    /// time, so they are nearly independent).
    fn mean_square_with_standard_error(record: &[f64], batches: usize) -> (f64, f64) {
        let batch_len = record.len() / batches;
        let squares: Vec<f64> = record
            .chunks_exact(batch_len)
            .map(|batch| batch.iter().map(|x| x * x).sum::<f64>() / batch_len as f64)
            .collect();
        let n = squares.len() as f64;
        let mean = squares.iter().sum::<f64>() / n;
        let spread = squares.iter().map(|s| (s - mean).powi(2)).sum::<f64>() / (n - 1.0);
        (mean, (spread / n).sqrt())
    }

    #[test]
    fn long_record_rms_matches_configured_heave_and_pitch_rms() {
        // 400 000 s at dt = 0.1 s: the filters' poles are at |s| ≤ 1 rad/s, so RK4 is exact
        // to ~1e-6 and the held noise's spectrum, q·sinc²(ω·dt/2), is within 0.1 % of q
        // where the filters pass power. The lightly damped pair decays at 0.04 s⁻¹ (25 s),
        // so 100 batches of 4000 s are each ≈ 160 correlation times long and nearly
        // independent; the batch spread then gives the standard error of the variance
        // (about 1 % of it for heave). Tolerance 4 standard errors: a 10 % error in the
        // noise intensity (5 % in RMS) fails by a wide margin.
        let (heave, pitch) = record(21, 0.1, 4_000_000, 1);
        let targets = [
            (heave, 2.0_f64, "heave"),
            (pitch, 1.5_f64.to_radians(), "pitch"),
        ];
        for (samples, rms, name) in targets {
            let (mean_square, standard_error) = mean_square_with_standard_error(&samples, 100);
            let relative_error = standard_error / rms.powi(2);
            // Theory for this record length: relative error of the variance ≈ √(2·12.5 s/T)
            // ≈ 1.6 %; refuse a record too short to test anything.
            assert!(
                relative_error < 0.03,
                "{name}: record too short ({relative_error})"
            );
            assert!(
                (mean_square - rms.powi(2)).abs() < 4.0 * standard_error,
                "{name}: RMS {} vs configured {rms} (standard error of the variance {standard_error})",
                mean_square.sqrt()
            );
        }
    }

    #[test]
    fn pitch_spectrum_peaks_near_the_lightly_damped_pole_pair() {
        // The pole pair s² + 0.08s + 0.16 has ω = 0.4 rad/s; |G_θ(jω)|² peaks at 0.403 rad/s
        // with half-power band 0.367–0.449 rad/s (numpy on a 300 000-point grid).
        // Averaged Hann-windowed periodograms of 50 segments of 2000 s, sampled at 0.25 s.
        let (_, pitch) = record(22, 0.05, 2_000_000, 5);
        let sample_s = 0.25;
        let segment_len = 8000;
        let frequencies: Vec<f64> = (0..=120).map(|i| 0.2 + 0.005 * f64::from(i)).collect();
        let mut power = vec![0.0; frequencies.len()];
        let hann: Vec<f64> = (0..segment_len)
            .map(|k| 0.5 - 0.5 * (std::f64::consts::TAU * k as f64 / segment_len as f64).cos())
            .collect();
        for segment in pitch.chunks_exact(segment_len) {
            let windowed: Vec<f64> = segment.iter().zip(&hann).map(|(x, w)| x * w).collect();
            for (omega, p) in frequencies.iter().zip(power.iter_mut()) {
                // Σ x_k e^(−iωkΔ), the phasor advanced by rotation.
                let (step_sin, step_cos) = (omega * sample_s).sin_cos();
                let (mut phasor_re, mut phasor_im) = (1.0, 0.0);
                let (mut re, mut im) = (0.0, 0.0);
                for x in &windowed {
                    re += x * phasor_re;
                    im += x * phasor_im;
                    (phasor_re, phasor_im) = (
                        phasor_re * step_cos + phasor_im * step_sin,
                        phasor_im * step_cos - phasor_re * step_sin,
                    );
                }
                *p += re * re + im * im;
            }
        }
        let peak = frequencies
            .iter()
            .zip(&power)
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(omega, _)| *omega)
            .unwrap_or(f64::NAN);
        assert!(
            (peak - 0.403).abs() < 0.02,
            "pitch spectrum peaks at {peak} rad/s"
        );
        // And the peak stands well above the spectrum at 0.2 and 0.8 rad/s (theory: ×185, ×29).
        let max = power.iter().copied().fold(0.0, f64::max);
        assert!(max > 50.0 * power[0] && max > 10.0 * power[power.len() - 1]);
    }

    #[test]
    fn same_seed_reproduces_and_different_seed_changes_the_motion() {
        let a = record(3, 0.01, 2000, 10);
        let b = record(3, 0.01, 2000, 10);
        let c = record(4, 0.01, 2000, 10);
        assert_eq!(a, b);
        assert_ne!(a.0, c.0);
        assert_ne!(a.1, c.1);
    }

    #[test]
    fn disabled_ship_stays_level() {
        let parameters = ShipMotionParameters {
            enabled: false,
            ..ShipMotionParameters::default()
        };
        let mut ship = ShipMotionSimulator::new(parameters, &RandomStreams::new(1), 0.0)
            .expect("valid parameters");
        for _ in 0..100 {
            ship.step(0.01);
        }
        assert_eq!(ship.outputs(), ShipMotionOutputs::default());
    }

    #[test]
    fn forward_speed_moves_the_pitch_centre() {
        let parameters = ShipMotionParameters {
            forward_speed_mps: 10.0,
            ..ShipMotionParameters::default()
        };
        let mut ship =
            ShipMotionSimulator::new(parameters, &RandomStreams::new(1), 500.0).expect("valid");
        for _ in 0..100 {
            ship.step(0.01);
        }
        assert!((ship.pose().pitch_centre_x_m - 510.0).abs() < 1e-9);
        assert_eq!(ship.pose_rate().pitch_centre_x_rate_mps, 10.0);
    }
}
