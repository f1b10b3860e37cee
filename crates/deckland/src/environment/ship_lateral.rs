//! Ship roll, yaw and sway (docs/model.md §3.7; shared model §10.5).
//!
//! Each is the output of a shaping filter driven by its own white noise, as heave and
//! pitch are (§3.1); no source gives a carrier's lateral spectra here, so the filters
//! are assumptions, named in docs/model.md §3.7:
//! - roll φ_s: a lightly damped second-order filter G_φ(s) = 1/(s² + 2ζωs + ω²),
//!   ω = 0.314 rad/s (natural period 20 s), ζ = 0.1, realised as ż₁ = z₂,
//!   ż₂ = −ω²z₁ − 2ζωz₂ + u, so φ_s = z₁ and φ̇_s = z₂;
//! - yaw ψ_s and sway y_s: the heave filter's form 1/D(s) (paper Eq. 15,
//!   D(s) = (s + 1)²(s² + 0.08s + 0.16)), in the controllable canonical form of
//!   [`super::ship`], so the output is z₁ and its rate z₂.
//!
//! As for heave and pitch, the configured output RMS sets each noise intensity through
//! the filter's stationary variance for unit intensity (Lyapunov equation):
//! q = RMS²/σ²₁; the filters start from their stationary distribution. Signs: roll
//! positive starboard side down, yaw positive bow to starboard, sway positive to
//! starboard (the ship's own y axis).

use nalgebra::{DMatrix, Matrix2};

use super::deck::{ShipPose, ShipPoseRate};
use super::lyapunov::stationary_covariance;
use super::ship::{
    unit_intensity_state_covariance, ShipMotionParameters, SHAPING_FILTER_DENOMINATOR,
};
use crate::parameters::ParameterError;
use crate::random::{stream_names, NoiseStream, RandomStreams, Reseed};

/// Natural frequency ω of the roll filter (rad/s): a natural period of 20 s
/// (docs/model.md §3.7, an assumption).
pub const ROLL_FILTER_NATURAL_FREQUENCY_RADPS: f64 = 0.314;
/// Damping ratio ζ of the roll filter (–) (docs/model.md §3.7, an assumption).
pub const ROLL_FILTER_DAMPING_RATIO: f64 = 0.1;

/// State of the three lateral shaping filters (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateralShipMotionState {
    /// Roll filter state (φ_s, φ̇_s) (rad, rad/s).
    pub roll_filter: [f64; 2],
    /// Yaw filter state z = (z₁, ż₁, z̈₁, z⃛₁), z₁ = ψ_s (rad).
    pub yaw_filter: [f64; 4],
    /// Sway filter state z = (z₁, ż₁, z̈₁, z⃛₁), z₁ = y_s (m).
    pub sway_filter: [f64; 4],
}

impl LateralShipMotionState {
    /// Number of scalar states.
    pub const DIMENSION: usize = 10;

    /// Names of the states, in the order of [`LateralShipMotionState::to_array`].
    pub const NAMES: [&'static str; 10] = [
        "roll_filter_z",
        "roll_filter_z_rate",
        "yaw_filter_z",
        "yaw_filter_z_rate",
        "yaw_filter_z_acceleration",
        "yaw_filter_z_jerk",
        "sway_filter_z",
        "sway_filter_z_rate",
        "sway_filter_z_acceleration",
        "sway_filter_z_jerk",
    ];

    /// The state as an array for the integrator: roll, yaw, then sway filter.
    pub fn to_array(&self) -> [f64; 10] {
        let mut array = [0.0; 10];
        array[..2].copy_from_slice(&self.roll_filter);
        array[2..6].copy_from_slice(&self.yaw_filter);
        array[6..].copy_from_slice(&self.sway_filter);
        array
    }

    /// The inverse of [`LateralShipMotionState::to_array`].
    pub fn from_array(array: &[f64; 10]) -> Self {
        let mut state = Self::default();
        state.roll_filter.copy_from_slice(&array[..2]);
        state.yaw_filter.copy_from_slice(&array[2..6]);
        state.sway_filter.copy_from_slice(&array[6..]);
        state
    }
}

/// White-noise inputs of the three filters, held constant over one step (filter input
/// units; already scaled by √(q/dt)).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateralShipNoise {
    /// Input of the roll filter.
    pub roll: f64,
    /// Input of the yaw filter.
    pub yaw: f64,
    /// Input of the sway filter.
    pub sway: f64,
}

/// Roll, yaw and sway of the ship read from a [`LateralShipMotionState`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateralShipMotionOutputs {
    /// Roll φ_s (rad, positive starboard side down, zero mean).
    pub roll_rad: f64,
    /// Roll rate φ̇_s (rad/s).
    pub roll_rate_radps: f64,
    /// Yaw ψ_s from the mean heading (rad, positive bow to starboard, zero mean).
    pub yaw_rad: f64,
    /// Yaw rate ψ̇_s (rad/s).
    pub yaw_rate_radps: f64,
    /// Sway y_s, along the ship's own y axis (m, positive to starboard, zero mean).
    pub sway_m: f64,
    /// Sway rate ẏ_s (m/s).
    pub sway_rate_mps: f64,
}

/// The random streams of the three filters (`ship_roll`, `ship_yaw`, `ship_sway`;
/// docs/model.md §3.4): new names, so every existing stream is unchanged.
#[derive(Debug, Clone)]
pub struct LateralShipStreams {
    /// Drives the roll filter.
    pub roll: NoiseStream,
    /// Drives the yaw filter.
    pub yaw: NoiseStream,
    /// Drives the sway filter.
    pub sway: NoiseStream,
}

impl LateralShipStreams {
    /// The three streams of the scenario's random streams, from their start.
    pub fn new(streams: &RandomStreams) -> Self {
        Self {
            roll: streams.stream(stream_names::SHIP_ROLL),
            yaw: streams.stream(stream_names::SHIP_YAW),
            sway: streams.stream(stream_names::SHIP_SWAY),
        }
    }
}

/// The companion matrix of the roll filter, ż = A z + (0, 1)ᵀ u.
pub fn roll_filter_companion() -> Matrix2<f64> {
    let omega = ROLL_FILTER_NATURAL_FREQUENCY_RADPS;
    let zeta = ROLL_FILTER_DAMPING_RATIO;
    Matrix2::new(0.0, 1.0, -omega * omega, -2.0 * zeta * omega)
}

/// Stationary covariance of the roll filter's state for unit-intensity noise
/// (Lyapunov equation, [`super::lyapunov`]).
pub fn roll_unit_intensity_state_covariance() -> [[f64; 2]; 2] {
    let companion = roll_filter_companion();
    let a = DMatrix::from_fn(2, 2, |i, j| companion[(i, j)]);
    let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
    let p = stationary_covariance(&a, &b).expect("the roll filter (ζ = 0.1 > 0) is stable");
    [[p[(0, 0)], p[(0, 1)]], [p[(1, 0)], p[(1, 1)]]]
}

/// Lower Cholesky factor of an n × n covariance given as rows.
fn cholesky_factor<const N: usize>(p: [[f64; N]; N]) -> [[f64; N]; N] {
    let matrix = DMatrix::from_fn(N, N, |i, j| p[i][j]);
    let l = matrix
        .cholesky()
        .expect("the stationary covariance of a stable filter is positive definite")
        .l();
    std::array::from_fn(|i| std::array::from_fn(|j| l[(i, j)]))
}

/// √q·L·n, n ~ N(0, I) drawn from `stream`: a sample of the stationary distribution.
fn stationary_draw<const N: usize>(
    stream: &mut NoiseStream,
    intensity: f64,
    factor: &[[f64; N]; N],
) -> [f64; N] {
    let n: [f64; N] = std::array::from_fn(|_| stream.standard_normal());
    let scale = intensity.sqrt();
    std::array::from_fn(|i| scale * (0..=i).map(|j| factor[i][j] * n[j]).sum::<f64>())
}

/// Derivative of one canonical 1/D(s) filter under a held input.
fn canonical_derivative(z: &[f64; 4], u: f64) -> [f64; 4] {
    let [d0, d1, d2, d3] = SHAPING_FILTER_DENOMINATOR;
    [
        z[1],
        z[2],
        z[3],
        u - d0 * z[0] - d1 * z[1] - d2 * z[2] - d3 * z[3],
    ]
}

/// The ship's roll, yaw and sway: three shaping filters with noise intensities derived
/// from the configured RMS (docs/model.md §3.7).
#[derive(Debug, Clone, PartialEq)]
pub struct LateralShipMotion {
    enabled: bool,
    roll_intensity: f64,
    yaw_intensity: f64,
    sway_intensity: f64,
    roll_factor: [[f64; 2]; 2],
    canonical_factor: [[f64; 4]; 4],
}

impl LateralShipMotion {
    /// The model for the ship parameters (`roll_rms_deg`, `yaw_rms_deg`, `sway_rms_m`,
    /// `enabled`); validates them and solves for the intensities.
    pub fn new(parameters: &ShipMotionParameters) -> Result<Self, ParameterError> {
        parameters.validate()?;
        let roll_p = roll_unit_intensity_state_covariance();
        let canonical_p = unit_intensity_state_covariance();
        Ok(Self {
            enabled: parameters.enabled,
            roll_intensity: parameters.roll_rms_deg.to_radians().powi(2) / roll_p[0][0],
            yaw_intensity: parameters.yaw_rms_deg.to_radians().powi(2) / canonical_p[0][0],
            sway_intensity: parameters.sway_rms_m.powi(2) / canonical_p[0][0],
            roll_factor: cholesky_factor(roll_p),
            canonical_factor: cholesky_factor(canonical_p),
        })
    }

    /// Intensities (q_φ, q_ψ, q_y) of the three filters' white noise (rad²·s, rad²·s,
    /// m²·s per unit input).
    pub fn noise_intensities(&self) -> [f64; 3] {
        [self.roll_intensity, self.yaw_intensity, self.sway_intensity]
    }

    /// Time derivative of the filter states under held noise inputs.
    pub fn derivative(
        &self,
        state: &LateralShipMotionState,
        noise: LateralShipNoise,
    ) -> LateralShipMotionState {
        let omega = ROLL_FILTER_NATURAL_FREQUENCY_RADPS;
        let zeta = ROLL_FILTER_DAMPING_RATIO;
        let [phi, phi_rate] = state.roll_filter;
        LateralShipMotionState {
            roll_filter: [
                phi_rate,
                noise.roll - omega * omega * phi - 2.0 * zeta * omega * phi_rate,
            ],
            yaw_filter: canonical_derivative(&state.yaw_filter, noise.yaw),
            sway_filter: canonical_derivative(&state.sway_filter, noise.sway),
        }
    }

    /// Draws the noise inputs for one step of `dt` seconds (dt > 0): n·√(q/dt), one
    /// sample from each filter's stream. Nothing drawn, and zero, when the ship motion
    /// is disabled.
    pub fn draw_noise(&self, streams: &mut LateralShipStreams, dt: f64) -> LateralShipNoise {
        debug_assert!(dt > 0.0, "time step must be positive, got {dt}");
        if !self.enabled {
            return LateralShipNoise::default();
        }
        LateralShipNoise {
            roll: streams.roll.standard_normal() * (self.roll_intensity / dt).sqrt(),
            yaw: streams.yaw.standard_normal() * (self.yaw_intensity / dt).sqrt(),
            sway: streams.sway.standard_normal() * (self.sway_intensity / dt).sqrt(),
        }
    }

    /// A state drawn from the filters' stationary distribution, z = √q·L·n with P = L Lᵀ
    /// (2 samples from the roll stream, 4 each from the yaw and sway streams). Zero,
    /// with nothing drawn, when the ship motion is disabled.
    pub fn stationary_initial_state(
        &self,
        streams: &mut LateralShipStreams,
    ) -> LateralShipMotionState {
        if !self.enabled {
            return LateralShipMotionState::default();
        }
        LateralShipMotionState {
            roll_filter: stationary_draw(&mut streams.roll, self.roll_intensity, &self.roll_factor),
            yaw_filter: stationary_draw(
                &mut streams.yaw,
                self.yaw_intensity,
                &self.canonical_factor,
            ),
            sway_filter: stationary_draw(
                &mut streams.sway,
                self.sway_intensity,
                &self.canonical_factor,
            ),
        }
    }

    /// Roll, yaw, sway and their rates in `state` (zero when the ship motion is
    /// disabled).
    pub fn outputs(&self, state: &LateralShipMotionState) -> LateralShipMotionOutputs {
        if !self.enabled {
            return LateralShipMotionOutputs::default();
        }
        LateralShipMotionOutputs {
            roll_rad: state.roll_filter[0],
            roll_rate_radps: state.roll_filter[1],
            yaw_rad: state.yaw_filter[0],
            yaw_rate_radps: state.yaw_filter[1],
            sway_m: state.sway_filter[0],
            sway_rate_mps: state.sway_filter[1],
        }
    }

    /// `pose` (the ship's mean track, heave and pitch) completed with the lateral
    /// components of `state`: roll, yaw, and the sway along the ship's own y axis, which
    /// points `mean_heading_rad` (rad, positive to starboard) off earth y, so the pitch
    /// centre moves by y_s·(−sin ψ₀, cos ψ₀) in earth x, y.
    pub fn complete_pose(
        &self,
        state: &LateralShipMotionState,
        pose: ShipPose,
        mean_heading_rad: f64,
    ) -> ShipPose {
        let outputs = self.outputs(state);
        let (sin, cos) = mean_heading_rad.sin_cos();
        ShipPose {
            pitch_centre_x_m: pose.pitch_centre_x_m - outputs.sway_m * sin,
            pitch_centre_y_m: pose.pitch_centre_y_m + outputs.sway_m * cos,
            roll_rad: outputs.roll_rad,
            yaw_rad: outputs.yaw_rad,
            ..pose
        }
    }

    /// Rates of [`LateralShipMotion::complete_pose`]: `rate` with the sway rate, roll
    /// rate and yaw rate of `state`.
    pub fn complete_pose_rate(
        &self,
        state: &LateralShipMotionState,
        rate: ShipPoseRate,
        mean_heading_rad: f64,
    ) -> ShipPoseRate {
        let outputs = self.outputs(state);
        let (sin, cos) = mean_heading_rad.sin_cos();
        ShipPoseRate {
            pitch_centre_x_rate_mps: rate.pitch_centre_x_rate_mps - outputs.sway_rate_mps * sin,
            pitch_centre_y_rate_mps: rate.pitch_centre_y_rate_mps + outputs.sway_rate_mps * cos,
            roll_rate_radps: outputs.roll_rate_radps,
            yaw_rate_radps: outputs.yaw_rate_radps,
            ..rate
        }
    }
}

impl Reseed for LateralShipStreams {
    fn reseed(&mut self, key: u64) {
        self.roll.reseed(key);
        self.yaw.reseed(key);
        self.sway.reseed(key);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roll_covariance_matches_the_closed_form() {
        // ẍ + 2ζωẋ + ω²x = w: var x = 1/(4ζω³), var ẋ = 1/(4ζω).
        let (omega, zeta) = (
            ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
            ROLL_FILTER_DAMPING_RATIO,
        );
        let p = roll_unit_intensity_state_covariance();
        assert!((p[0][0] * 4.0 * zeta * omega.powi(3) - 1.0).abs() < 1e-10);
        assert!((p[1][1] * 4.0 * zeta * omega - 1.0).abs() < 1e-10);
    }

    #[test]
    fn state_array_round_trips() {
        let array = std::array::from_fn(|i| i as f64 + 0.5);
        assert_eq!(LateralShipMotionState::from_array(&array).to_array(), array);
    }

    #[test]
    fn rates_are_the_derivatives_of_the_outputs() {
        let model = LateralShipMotion::new(&ShipMotionParameters::default()).expect("valid");
        let state = LateralShipMotionState::from_array(&[
            0.01, -0.002, 0.003, 0.001, -0.002, 0.004, 0.2, -0.1, 0.05, 0.02,
        ]);
        let derivative = model.outputs(&model.derivative(&state, LateralShipNoise::default()));
        let outputs = model.outputs(&state);
        assert_eq!(derivative.roll_rad, outputs.roll_rate_radps);
        assert_eq!(derivative.yaw_rad, outputs.yaw_rate_radps);
        assert_eq!(derivative.sway_m, outputs.sway_rate_mps);
    }

    #[test]
    fn a_disabled_ship_draws_nothing_and_stays_still() {
        let parameters = ShipMotionParameters {
            enabled: false,
            ..ShipMotionParameters::default()
        };
        let model = LateralShipMotion::new(&parameters).expect("valid");
        let mut streams = LateralShipStreams::new(&RandomStreams::new(4));
        let untouched = streams.roll.clone();
        assert_eq!(
            model.stationary_initial_state(&mut streams),
            LateralShipMotionState::default()
        );
        assert_eq!(
            model.draw_noise(&mut streams, 0.01),
            LateralShipNoise::default()
        );
        assert_eq!(streams.roll, untouched);
    }

    #[test]
    fn sway_moves_the_pitch_centre_along_the_ships_own_y_axis() {
        let model = LateralShipMotion::new(&ShipMotionParameters::default()).expect("valid");
        let mut state = LateralShipMotionState::default();
        state.sway_filter[0] = 2.0;
        let heading = 9.0_f64.to_radians();
        let pose = model.complete_pose(&state, ShipPose::default(), heading);
        assert!((pose.pitch_centre_x_m + 2.0 * heading.sin()).abs() < 1e-15);
        assert!((pose.pitch_centre_y_m - 2.0 * heading.cos()).abs() < 1e-15);
    }
}
