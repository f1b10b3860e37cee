//! What a lateral step is: the axis, the step, the gust, the recorded samples, the
//! errors (what it measured: `response.rs`).

use serde::Serialize;

use crate::control::lateral::SIDESLIP_BLEND_CROSSOVER_RADPS;
use crate::metrics::MetricsError;
use crate::parameters::ParameterError;

/// Why a lateral step could not be flown or measured.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LateralStepError {
    /// A value of the step, the trim or the design is out of range (the message names it).
    #[error("{0}")]
    Setup(String),
    /// A law's parameters are invalid.
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    /// The run could not be measured.
    #[error("cannot measure the lateral step: {0}")]
    Metrics(#[from] MetricsError),
}

/// The axis stepped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LateralAxis {
    /// A bank-angle step (roll law), sideslip held at zero.
    Roll,
    /// A sideslip step (yaw law), bank held at zero.
    Yaw,
}

/// A 1 − cos gust of the wind's earth-y component (m/s, positive to the right).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CrosswindGust {
    /// Peak wind (m/s).
    pub peak_mps: f64,
    /// Start (s).
    pub start_s: f64,
    /// Duration (s).
    pub duration_s: f64,
}

impl CrosswindGust {
    /// The gust's wind at `time_s` (m/s).
    pub fn wind_mps(&self, time_s: f64) -> f64 {
        let phase = (time_s - self.start_s) / self.duration_s;
        if (0.0..=1.0).contains(&phase) {
            0.5 * self.peak_mps * (1.0 - (2.0 * std::f64::consts::PI * phase).cos())
        } else {
            0.0
        }
    }
}

/// The step to fly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralStep {
    /// Which channel is stepped.
    pub axis: LateralAxis,
    /// Step size (deg): bank positive right wing down, sideslip positive wind from the
    /// right; 0 flies no step (for a gust alone).
    pub step_deg: f64,
    /// Length of the run (s).
    pub seconds: f64,
    /// Lateral turbulence and sensor noise on.
    pub adverse: bool,
    /// Seed of the random streams.
    pub seed: u64,
    /// An optional crosswind gust.
    pub gust: Option<CrosswindGust>,
    /// How often the run is recorded (s).
    pub record_interval_s: f64,
    /// Crossover k_c (rad/s) of the sideslip blend the yaw law reads
    /// (`control::lateral::SideslipBlend`), or `None` for the raw air-data sideslip.
    pub sideslip_blend_crossover_radps: Option<f64>,
}

impl LateralStep {
    /// An ideal step of `step_deg` on `axis` lasting `seconds`, recorded every 2 ms, the
    /// yaw law reading the blended sideslip.
    pub fn new(axis: LateralAxis, step_deg: f64, seconds: f64) -> Self {
        Self {
            axis,
            step_deg,
            seconds,
            adverse: false,
            seed: 1,
            gust: None,
            record_interval_s: 0.002,
            sideslip_blend_crossover_radps: Some(SIDESLIP_BLEND_CROSSOVER_RADPS),
        }
    }
}

/// One recorded instant (degrees, deg/s, m, s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LateralSample {
    /// Time (s).
    pub time_s: f64,
    /// Commanded bank (deg).
    pub bank_command_deg: f64,
    /// True bank φ (deg).
    pub bank_deg: f64,
    /// Commanded sideslip (deg).
    pub sideslip_command_deg: f64,
    /// True sideslip β (deg).
    pub sideslip_deg: f64,
    /// Heading ψ (deg).
    pub heading_deg: f64,
    /// Roll rate p (deg/s).
    pub roll_rate_degps: f64,
    /// Yaw rate r (deg/s).
    pub yaw_rate_degps: f64,
    /// Aileron δa (deg).
    pub aileron_deg: f64,
    /// Aileron rate (deg/s).
    pub aileron_rate_degps: f64,
    /// Rudder δr (deg).
    pub rudder_deg: f64,
    /// Rudder rate (deg/s).
    pub rudder_rate_degps: f64,
    /// Lateral wind W_y (m/s).
    pub wind_y_mps: f64,
    /// Altitude (m).
    pub altitude_m: f64,
}

impl LateralSample {
    /// The recorded signals' names (units in the names), in the order of
    /// [`LateralSample::values`]: the columns of `step.csv` after the controller's prefix
    /// and of the Python package's time series.
    pub const COLUMNS: [&'static str; 12] = [
        "bank_deg",
        "bank_command_deg",
        "sideslip_deg",
        "sideslip_command_deg",
        "heading_deg",
        "roll_rate_degps",
        "yaw_rate_degps",
        "aileron_deg",
        "aileron_rate_degps",
        "rudder_deg",
        "rudder_rate_degps",
        "wind_y_mps",
    ];

    /// The recorded signals in the order of [`LateralSample::COLUMNS`].
    pub fn values(&self) -> [f64; 12] {
        [
            self.bank_deg,
            self.bank_command_deg,
            self.sideslip_deg,
            self.sideslip_command_deg,
            self.heading_deg,
            self.roll_rate_degps,
            self.yaw_rate_degps,
            self.aileron_deg,
            self.aileron_rate_degps,
            self.rudder_deg,
            self.rudder_rate_degps,
            self.wind_y_mps,
        ]
    }
}
