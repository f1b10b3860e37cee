//! Ship heave and pitch (paper §3.3, Eq. 15–16; docs/model.md §3.1).
//!
//! Heave and pitch are the outputs of the shaping filters G_H(s) = 1.21/D(s) and
//! G_θ(s) = 0.773·s²/D(s), D(s) = s⁴ + 2.08s³ + 1.32s² + 0.4s + 0.16
//! = (s + 1)²(s² + 0.08s + 0.16), each driven by its own white noise. Each filter is
//! realised in controllable canonical form: with the filter state z = (z₁, z₂, z₃, z₄),
//! ż₁ = z₂, ż₂ = z₃, ż₃ = z₄, ż₄ = −0.16z₁ − 0.4z₂ − 1.32z₃ − 2.08z₄ + u, so z₁ = u/D(s)
//! and zₖ = z₁^(k−1). Then heave = 1.21z₁, heave rate = 1.21z₂, pitch = 0.773z₃ and pitch
//! rate = 0.773z₄ exactly, with no direct feed-through of the noise.
//!
//! The paper's noise powers are ambiguous (docs/model.md §3.1), so the configured output RMS
//! sets the noise intensity q through the filter's stationary variance for unit
//! intensity, σ²₁ (Lyapunov equation): q = RMS²/σ²₁. Heave is positive up; pitch θ_s is
//! positive bow-up.

use nalgebra::{DMatrix, Matrix4};
use serde::{Deserialize, Serialize};

use super::deck::{ShipPose, ShipPoseRate};
use super::lyapunov::stationary_covariance;
use crate::parameters::{check_ranges, Bounds, ParameterError};
use crate::random::NoiseStream;

/// Coefficients (d₀, d₁, d₂, d₃) of D(s) = s⁴ + d₃s³ + d₂s² + d₁s + d₀ (paper Eq. 15–16).
pub const SHAPING_FILTER_DENOMINATOR: [f64; 4] = [0.16, 0.4, 1.32, 2.08];
/// Numerator gain of the heave filter G_H(s) = 1.21/D(s) (paper Eq. 15), m per filter unit.
pub const HEAVE_FILTER_GAIN: f64 = 1.21;
/// Numerator gain of the pitch filter G_θ(s) = 0.773·s²/D(s) (paper Eq. 16), rad per unit.
pub const PITCH_FILTER_GAIN: f64 = 0.773;

/// The ship-motion model of a scenario (`environment.ship.model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ShipModelKind {
    /// The paper's shaping filters (docs/model.md §3.1): the paper's set and every file
    /// that names no model.
    Filters,
    /// The carrier in a seaway (docs/model.md §12), from `[environment.seaway]`.
    Seaway,
}

impl ShipModelKind {
    /// The model of a scenario file that names none: the filters, as every file written
    /// before the seaway flew (the built-in default names `seaway`).
    pub fn named_by_none() -> Self {
        Self::Filters
    }

    /// The name a scenario file gives the model.
    pub fn name(self) -> &'static str {
        match self {
            Self::Filters => "filters",
            Self::Seaway => "seaway",
        }
    }

    /// The keys of `[environment.ship]` that this model sets itself (a file that names
    /// the model may not write them).
    pub fn derived_keys(self) -> &'static [&'static str] {
        match self {
            Self::Filters => &[],
            Self::Seaway => &["heave_rms_m", "pitch_rms_deg", "roll_rms_deg"],
        }
    }
}

/// A 4 × 4 matrix as nested arrays (row major).
pub type Matrix4Array = [[f64; 4]; 4];

/// Configuration of the ship motion (docs/model.md §3.1).
///
/// Written out (a campaign's `scenario.toml`), a ship whose model derives the RMS of
/// heave, pitch and roll (the seaway) leaves those keys out, so that the file reads back.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields, into = "ShipMotionFile")]
pub struct ShipMotionParameters {
    /// The ship-motion model: `seaway`, the carrier in the seaway of
    /// `[environment.seaway]` (docs/model.md §12), in the built-in default; `filters`, the
    /// paper's shaping filters, in the paper's set and in every file that names none (the
    /// files written before the seaway keep flying as they did).
    #[serde(default = "ShipModelKind::named_by_none")]
    pub model: ShipModelKind,
    /// Whether the deck heaves and pitches at all; when false the ship is steady.
    pub enabled: bool,
    /// Stationary RMS of heave (m); docs/model.md §3.1 default 2.0.
    pub heave_rms_m: f64,
    /// Stationary RMS of pitch θ_s (deg); docs/model.md §3.1 default 1.5.
    pub pitch_rms_deg: f64,
    /// Ship forward speed along +x (m/s); docs/model.md §3.1: the realistic set's default
    /// 7.7 (15 kn), the paper's set 0 (a stationary ship, as the paper).
    pub forward_speed_mps: f64,
    /// Stationary RMS of roll φ_s (deg); docs/model.md §3.7 default 1.0 (an assumption).
    pub roll_rms_deg: f64,
    /// Stationary RMS of yaw ψ_s about the mean heading (deg); docs/model.md §3.7 default
    /// 0.3 (an assumption).
    pub yaw_rms_deg: f64,
    /// Stationary RMS of sway, the sideways displacement of the ship (m); docs/model.md
    /// §3.7 default 0.5 (an assumption).
    pub sway_rms_m: f64,
}

/// [`ShipMotionParameters`] as a file holds it: the keys the model derives left out.
#[derive(Serialize)]
struct ShipMotionFile {
    model: ShipModelKind,
    enabled: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    heave_rms_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pitch_rms_deg: Option<f64>,
    forward_speed_mps: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    roll_rms_deg: Option<f64>,
    yaw_rms_deg: f64,
    sway_rms_m: f64,
}

impl From<ShipMotionParameters> for ShipMotionFile {
    fn from(p: ShipMotionParameters) -> Self {
        let derived = p.model.derived_keys();
        let keep = |key: &str, value: f64| (!derived.contains(&key)).then_some(value);
        Self {
            model: p.model,
            enabled: p.enabled,
            heave_rms_m: keep("heave_rms_m", p.heave_rms_m),
            pitch_rms_deg: keep("pitch_rms_deg", p.pitch_rms_deg),
            forward_speed_mps: p.forward_speed_mps,
            roll_rms_deg: keep("roll_rms_deg", p.roll_rms_deg),
            yaw_rms_deg: p.yaw_rms_deg,
            sway_rms_m: p.sway_rms_m,
        }
    }
}

impl Default for ShipMotionParameters {
    fn default() -> Self {
        Self {
            model: ShipModelKind::Seaway,
            enabled: true,
            heave_rms_m: 2.0,
            pitch_rms_deg: 1.5,
            forward_speed_mps: 7.7,
            roll_rms_deg: 1.0,
            yaw_rms_deg: 0.3,
            sway_rms_m: 0.5,
        }
    }
}

impl ShipMotionParameters {
    /// The ship of a scenario file with no `[environment.ship]`: the built-in default's
    /// values with the model of a file that names none ([`ShipModelKind::named_by_none`]),
    /// as a section without `model` reads.
    pub fn named_by_none() -> Self {
        Self {
            model: ShipModelKind::named_by_none(),
            ..Self::default()
        }
    }

    /// The configured sea's stationary σ of the height of a deck point `lever_arm_m` aft of
    /// the pitch centre (m): √(σ_H² + (r·σ_θ)²), heave and pitch independent and the pitch
    /// small (§3.1), whether or not the motion is `enabled`: 2.91 m at the landing point
    /// (81 m) and 4.20 m at the ramp (141 m) in the paper's sea. The sea state that the
    /// close-in lift and the heavy-sea wave-off limits are scheduled on.
    pub fn deck_point_height_rms_m(&self, lever_arm_m: f64) -> f64 {
        self.heave_rms_m
            .hypot(lever_arm_m * self.pitch_rms_deg.to_radians())
    }

    /// Checks every field: heave RMS in [0, 50] m, pitch RMS in [0, 30]°, speed in
    /// [0, 30] m/s, roll RMS in [0, 30]°, yaw RMS in [0, 10]°, sway RMS in [0, 20] m.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "environment.ship";
        check_ranges!(SECTION, self, {
            heave_rms_m: Bounds::closed(0.0, 50.0),
            pitch_rms_deg: Bounds::closed(0.0, 30.0),
            forward_speed_mps: Bounds::closed(0.0, 30.0),
            roll_rms_deg: Bounds::closed(0.0, 30.0),
            yaw_rms_deg: Bounds::closed(0.0, 10.0),
            sway_rms_m: Bounds::closed(0.0, 20.0),
        });
        Ok(())
    }
}

/// State of both shaping filters, each in controllable canonical form (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipMotionState {
    /// Heave filter state z = (z₁, ż₁, z̈₁, z⃛₁), z₁ = u_H/D(s).
    pub heave_filter: [f64; 4],
    /// Pitch filter state z = (z₁, ż₁, z̈₁, z⃛₁), z₁ = u_θ/D(s).
    pub pitch_filter: [f64; 4],
}

impl ShipMotionState {
    /// Number of scalar states.
    pub const DIMENSION: usize = 8;

    /// Names of the states, in the order of [`ShipMotionState::to_array`].
    pub const NAMES: [&'static str; 8] = [
        "heave_filter_z",
        "heave_filter_z_rate",
        "heave_filter_z_acceleration",
        "heave_filter_z_jerk",
        "pitch_filter_z",
        "pitch_filter_z_rate",
        "pitch_filter_z_acceleration",
        "pitch_filter_z_jerk",
    ];

    /// The state from a slice of at least 8 numbers (as [`ShipMotionState::from_array`]).
    #[inline(always)]
    pub fn from_slice(x: &[f64]) -> Self {
        Self {
            heave_filter: [x[0], x[1], x[2], x[3]],
            pitch_filter: [x[4], x[5], x[6], x[7]],
        }
    }

    /// The state as an array for the integrator: heave filter first, then pitch filter.
    #[inline]
    pub fn to_array(&self) -> [f64; 8] {
        let mut array = [0.0; 8];
        array[..4].copy_from_slice(&self.heave_filter);
        array[4..].copy_from_slice(&self.pitch_filter);
        array
    }

    /// The inverse of [`ShipMotionState::to_array`].
    #[inline]
    pub fn from_array(array: &[f64; 8]) -> Self {
        let mut state = Self::default();
        state.heave_filter.copy_from_slice(&array[..4]);
        state.pitch_filter.copy_from_slice(&array[4..]);
        state
    }
}

/// White-noise inputs u_H, u_θ of the two filters, held constant over one step
/// (filter input units; already scaled by √(q/dt)).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipNoise {
    /// Input of the heave filter.
    pub heave: f64,
    /// Input of the pitch filter.
    pub pitch: f64,
}

/// Heave and pitch of the ship read from a [`ShipMotionState`] (paper Eq. 15–16).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipMotionOutputs {
    /// Heave of the pitch centre z_G (m, positive up, zero mean).
    pub heave_m: f64,
    /// Heave rate ż_G (m/s, positive up).
    pub heave_rate_mps: f64,
    /// Pitch θ_s (rad, positive bow-up, zero mean).
    pub pitch_rad: f64,
    /// Pitch rate θ̇_s (rad/s).
    pub pitch_rate_radps: f64,
}

/// One motion's shaping filter in controllable canonical form (module docs): with
/// z₁ = u/D(s), D(s) = s⁴ + d₃s³ + d₂s² + d₁s + d₀, the motion is y = g·z₁^(k) (k =
/// `output_state`, 0 to 2: the transfer function g·sᵏ/D(s)) and its rate g·z₁^(k+1).
///
/// The paper's ship is [`ShapingFilter::PAPER_HEAVE`] and [`ShapingFilter::PAPER_PITCH`];
/// the carrier in a seaway fits a band-pass g·ω₀²·s/(s² + 2ζω₀s + ω₀²)² to each motion
/// (k = 1, relative degree 3: finite acceleration variance; docs/model.md §12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapingFilter {
    /// Coefficients (d₀, d₁, d₂, d₃) of the denominator D(s); every root in the open left
    /// half-plane.
    pub denominator: [f64; 4],
    /// k: the motion is state k of the canonical state (z₁, ż₁, z̈₁, z⃛₁), its rate state k + 1.
    pub output_state: usize,
    /// g: output units per filter unit.
    pub gain: f64,
    /// Whether D(s) is the paper's, whose coefficients the derivative then takes as
    /// constants (the loop's cost per step; the same arithmetic either way).
    paper_denominator: bool,
}

impl ShapingFilter {
    /// The paper's heave filter 1.21/D(s) (Eq. 15).
    pub const PAPER_HEAVE: Self = Self {
        denominator: SHAPING_FILTER_DENOMINATOR,
        output_state: 0,
        gain: HEAVE_FILTER_GAIN,
        paper_denominator: true,
    };
    /// The paper's pitch filter 0.773·s²/D(s) (Eq. 16).
    pub const PAPER_PITCH: Self = Self {
        denominator: SHAPING_FILTER_DENOMINATOR,
        output_state: 2,
        gain: PITCH_FILTER_GAIN,
        paper_denominator: true,
    };

    /// The filter g·sᵏ/D(s), D(s) = s⁴ + d₃s³ + d₂s² + d₁s + d₀ with `denominator` =
    /// (d₀, d₁, d₂, d₃), k = `output_state` (checked, with D's stability, when a
    /// [`ShipMotion`] is built on it).
    pub fn new(denominator: [f64; 4], output_state: usize, gain: f64) -> Self {
        Self {
            denominator,
            output_state,
            gain,
            paper_denominator: denominator == SHAPING_FILTER_DENOMINATOR,
        }
    }

    /// The companion matrix A, D(s) in its last row.
    pub fn companion(&self) -> Matrix4<f64> {
        let [d0, d1, d2, d3] = self.denominator;
        #[rustfmt::skip]
        let a = Matrix4::new(
            0.0, 1.0, 0.0, 0.0,
            0.0, 0.0, 1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
            -d0, -d1, -d2, -d3,
        );
        a
    }

    /// The stationary covariance P of the canonical state for unit-intensity white noise,
    /// A P + P Aᵀ + B Bᵀ = 0; `None` when D(s) is not stable.
    pub fn unit_intensity_state_covariance(&self) -> Option<Matrix4Array> {
        let companion = self.companion();
        let a = DMatrix::from_fn(4, 4, |i, j| companion[(i, j)]);
        let b = DMatrix::from_row_slice(4, 1, &[0.0, 0.0, 0.0, 1.0]);
        let p = stationary_covariance(&a, &b)?;
        Some(std::array::from_fn(|i| std::array::from_fn(|j| p[(i, j)])))
    }

    /// Time derivative of the canonical state under a held input `u`.
    #[inline(always)]
    pub fn derivative(&self, z: &[f64; 4], u: f64) -> [f64; 4] {
        let [d0, d1, d2, d3] = if self.paper_denominator {
            SHAPING_FILTER_DENOMINATOR
        } else {
            self.denominator
        };
        [
            z[1],
            z[2],
            z[3],
            u - d0 * z[0] - d1 * z[1] - d2 * z[2] - d3 * z[3],
        ]
    }

    /// The states holding the motion and its rate (constant indices: no bounds checks in
    /// the loop; `output_state` is checked to be 0–2 when the ship is built).
    #[inline(always)]
    fn states(&self, z: &[f64; 4]) -> (f64, f64) {
        match self.output_state {
            0 => (z[0], z[1]),
            1 => (z[1], z[2]),
            _ => (z[2], z[3]),
        }
    }

    /// The motion in state `z`.
    #[inline(always)]
    pub fn output(&self, z: &[f64; 4]) -> f64 {
        self.gain * self.states(z).0
    }

    /// The motion's rate in state `z`.
    #[inline(always)]
    pub fn rate(&self, z: &[f64; 4]) -> f64 {
        self.gain * self.states(z).1
    }

    /// Checks D(s) is stable and k in 0–2 (`what` names the motion in the error).
    fn check(&self, what: &'static str) -> Result<Matrix4Array, ParameterError> {
        let invalid = |allowed: &str| {
            ParameterError::new("environment.ship", &format!("{what}_filter"), self, allowed)
        };
        if self.output_state > 2 || !self.gain.is_finite() || self.gain <= 0.0 {
            return Err(invalid(
                "expected a positive gain and an output state of 0 to 2",
            ));
        }
        self.unit_intensity_state_covariance()
            .filter(|p| p.iter().flatten().all(|v| v.is_finite()) && p[0][0] > 0.0)
            .ok_or_else(|| invalid("the filter's denominator is not stable"))
    }
}

/// The ship motion model: the two shaping filters with noise intensities derived from
/// the configured RMS (docs/model.md §3.1).
#[derive(Debug, Clone, PartialEq)]
pub struct ShipMotion {
    parameters: ShipMotionParameters,
    heave_filter: ShapingFilter,
    pitch_filter: ShapingFilter,
    heave_intensity: f64,
    pitch_intensity: f64,
    /// Lower Cholesky factor L of each filter's unit-intensity stationary covariance P.
    heave_covariance_factor: Matrix4Array,
    pitch_covariance_factor: Matrix4Array,
}

/// The companion matrix A of the paper's shaping filter in controllable canonical form,
/// with the denominator D(s) of paper Eq. 15–16 in its last row (docs/model.md §3.1).
pub fn shaping_filter_companion() -> Matrix4<f64> {
    ShapingFilter::PAPER_HEAVE.companion()
}

/// The stationary covariance P of the paper's canonical filter state for unit-intensity
/// white noise, A P + P Aᵀ + B Bᵀ = 0 (docs/model.md §3.1). The filter is fixed and stable
/// (its poles are −1, −1 and −0.04 ± 0.398i), so the solution always exists.
pub fn unit_intensity_state_covariance() -> Matrix4Array {
    ShapingFilter::PAPER_HEAVE
        .unit_intensity_state_covariance()
        .expect("the fixed shaping filter (s+1)²(s²+0.08s+0.16) is stable")
}

/// Stationary variance of heave for unit-intensity noise, 1.21²·P₁₁ (m²); docs/model.md §3.1
/// gives 43.62.
pub fn heave_unit_intensity_variance() -> f64 {
    HEAVE_FILTER_GAIN.powi(2) * unit_intensity_state_covariance()[0][0]
}

/// Stationary variance of pitch for unit-intensity noise, 0.773²·P₃₃ (rad²); docs/model.md
/// §3.1 gives 0.4858.
pub fn pitch_unit_intensity_variance() -> f64 {
    PITCH_FILTER_GAIN.powi(2) * unit_intensity_state_covariance()[2][2]
}

/// Lower Cholesky factor of a positive-definite 4 × 4 matrix.
fn cholesky_factor(p: &Matrix4Array) -> Matrix4Array {
    let matrix = DMatrix::from_fn(4, 4, |i, j| p[i][j]);
    let cholesky = matrix
        .cholesky()
        .expect("the stationary covariance of a stable filter is positive definite");
    let l = cholesky.l();
    std::array::from_fn(|i| std::array::from_fn(|j| l[(i, j)]))
}

impl ShipMotion {
    /// The model for these parameters, the paper's filters (§3.1); validates them and
    /// solves for the intensities.
    pub fn new(parameters: ShipMotionParameters) -> Result<Self, ParameterError> {
        Self::with_filters(
            parameters,
            ShapingFilter::PAPER_HEAVE,
            ShapingFilter::PAPER_PITCH,
        )
    }

    /// The model with these heave and pitch filters, their noise intensities set so that
    /// heave and pitch have the parameters' RMS; validates both.
    pub fn with_filters(
        parameters: ShipMotionParameters,
        heave_filter: ShapingFilter,
        pitch_filter: ShapingFilter,
    ) -> Result<Self, ParameterError> {
        parameters.validate()?;
        let heave_p = heave_filter.check("heave")?;
        let pitch_p = pitch_filter.check("pitch")?;
        let heave_variance = heave_filter.gain.powi(2)
            * heave_p[heave_filter.output_state][heave_filter.output_state];
        let pitch_variance = pitch_filter.gain.powi(2)
            * pitch_p[pitch_filter.output_state][pitch_filter.output_state];
        Ok(Self {
            parameters,
            heave_filter,
            pitch_filter,
            heave_intensity: parameters.heave_rms_m.powi(2) / heave_variance,
            pitch_intensity: parameters.pitch_rms_deg.to_radians().powi(2) / pitch_variance,
            heave_covariance_factor: cholesky_factor(&heave_p),
            pitch_covariance_factor: cholesky_factor(&pitch_p),
        })
    }

    /// The heave filter.
    pub fn heave_filter(&self) -> &ShapingFilter {
        &self.heave_filter
    }

    /// The pitch filter.
    pub fn pitch_filter(&self) -> &ShapingFilter {
        &self.pitch_filter
    }

    /// The parameters the model was built from.
    pub fn parameters(&self) -> &ShipMotionParameters {
        &self.parameters
    }

    /// Intensity q_H of the heave filter's white noise (filter units² · s).
    pub fn heave_noise_intensity(&self) -> f64 {
        self.heave_intensity
    }

    /// Intensity q_θ of the pitch filter's white noise (filter units² · s).
    pub fn pitch_noise_intensity(&self) -> f64 {
        self.pitch_intensity
    }

    /// Time derivative of the filter states under held noise inputs (paper Eq. 15–16).
    #[inline]
    pub fn derivative(&self, state: &ShipMotionState, noise: ShipNoise) -> ShipMotionState {
        ShipMotionState {
            heave_filter: self
                .heave_filter
                .derivative(&state.heave_filter, noise.heave),
            pitch_filter: self
                .pitch_filter
                .derivative(&state.pitch_filter, noise.pitch),
        }
    }

    /// Draws the noise inputs for one step of `dt` seconds (dt > 0): n·√(q/dt), n ~ N(0, 1)
    /// from each filter's own stream, so that the held sample has the white noise's
    /// intensity. Draws nothing and returns zero when the ship motion is disabled.
    pub fn draw_noise(
        &self,
        heave_stream: &mut NoiseStream,
        pitch_stream: &mut NoiseStream,
        dt: f64,
    ) -> ShipNoise {
        debug_assert!(dt > 0.0, "time step must be positive, got {dt}");
        if !self.parameters.enabled {
            return ShipNoise::default();
        }
        ShipNoise {
            heave: heave_stream.standard_normal() * (self.heave_intensity / dt).sqrt(),
            pitch: pitch_stream.standard_normal() * (self.pitch_intensity / dt).sqrt(),
        }
    }

    /// A state drawn from the filters' stationary distribution, z = √q·L·n with P = L Lᵀ
    /// and n ~ N(0, I₄), four samples from each filter's stream (docs/model.md §3.1). Zero,
    /// with nothing drawn, when the ship motion is disabled.
    pub fn stationary_initial_state(
        &self,
        heave_stream: &mut NoiseStream,
        pitch_stream: &mut NoiseStream,
    ) -> ShipMotionState {
        if !self.parameters.enabled {
            return ShipMotionState::default();
        }
        let draw = |stream: &mut NoiseStream, intensity: f64, factor: &Matrix4Array| {
            let n: [f64; 4] = std::array::from_fn(|_| stream.standard_normal());
            let scale = intensity.sqrt();
            std::array::from_fn(|i| scale * (0..=i).map(|j| factor[i][j] * n[j]).sum::<f64>())
        };
        ShipMotionState {
            heave_filter: draw(
                heave_stream,
                self.heave_intensity,
                &self.heave_covariance_factor,
            ),
            pitch_filter: draw(
                pitch_stream,
                self.pitch_intensity,
                &self.pitch_covariance_factor,
            ),
        }
    }

    /// Heave, pitch and their rates in `state` (zero when the ship motion is disabled).
    #[inline]
    pub fn outputs(&self, state: &ShipMotionState) -> ShipMotionOutputs {
        if !self.parameters.enabled {
            return ShipMotionOutputs::default();
        }
        ShipMotionOutputs {
            heave_m: self.heave_filter.output(&state.heave_filter),
            heave_rate_mps: self.heave_filter.rate(&state.heave_filter),
            pitch_rad: self.pitch_filter.output(&state.pitch_filter),
            pitch_rate_radps: self.pitch_filter.rate(&state.pitch_filter),
        }
    }

    /// The ship's pose at time `time_s` (s) in `state`, its pitch centre having been at
    /// earth x = `initial_pitch_centre_x_m` (m) at t = 0: x_G = x_G0 + V_ship·t.
    #[inline]
    pub fn pose(
        &self,
        state: &ShipMotionState,
        initial_pitch_centre_x_m: f64,
        time_s: f64,
    ) -> ShipPose {
        let outputs = self.outputs(state);
        ShipPose {
            pitch_centre_x_m: initial_pitch_centre_x_m + self.parameters.forward_speed_mps * time_s,
            heave_m: outputs.heave_m,
            pitch_rad: outputs.pitch_rad,
            ..ShipPose::default()
        }
    }

    /// Rates of [`ShipMotion::pose`]: ship speed, heave rate and pitch rate.
    #[inline]
    pub fn pose_rate(&self, state: &ShipMotionState) -> ShipPoseRate {
        let outputs = self.outputs(state);
        ShipPoseRate {
            pitch_centre_x_rate_mps: self.parameters.forward_speed_mps,
            heave_rate_mps: outputs.heave_rate_mps,
            pitch_rate_radps: outputs.pitch_rate_radps,
            ..ShipPoseRate::default()
        }
    }
}
