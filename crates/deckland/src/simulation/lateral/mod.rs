//! The 3-D carrier approach in the loop (docs/model.md §10.1–10.4; shared model
//! §10.5–10.8): a 6-DOF aircraft flown to an angled deck on a ship that steams, rolls,
//! yaws and sways, in a 3-D wind, lined up by lateral guidance through the roll and yaw
//! laws.
//!
//! When the plant is the 6-DOF and `approach.three_dimensional` holds (the default), the
//! loop carries a `LateralLoop`:
//! - **ship**: the roll, yaw and sway shaping filters ([`LateralShipMotion`]) integrate
//!   beside heave and pitch; the ship steams along its mean heading, the deck angle δ to
//!   the right of the final bearing, so the landing area's centreline, through the aim
//!   point, drifts to the right at V·sin δ. The longitudinal blocks (deck predictor,
//!   events, wake) see the ship through an equivalent longitudinal pose whose aim point is
//!   the 3-D aim point (`pose`).
//! - **wind**: [`crate::environment::WindModel::three_dimensional`]: the wind over deck
//!   down the angled deck, the crosswind, lateral turbulence.
//! - **lineup** ([`crate::control::lineup`]): the hook's offset from its reference line
//!   (the mean centreline, moved in close by the forecast of the centreline's lateral
//!   motion at the ramp when the hook crosses it, [`forecast`], with the glide path's
//!   compensation weight, which also tightens the loop) → bank command.
//! - **lateral laws**: the roll O-PD (bank command → aileron) and the yaw O-PD (β = 0 →
//!   rudder; in close, the crab heading: [`crate::control::heading_hold`]), read and
//!   commanded at the flight computer's frames as the pitch law is.
//!
//! Otherwise the 6-DOF's aileron and rudder are held at their trim (`lateral_hold`).

pub(crate) mod build;
mod evaluate;
pub mod floor;
pub mod forecast;
mod free_response;
mod hold;
pub(crate) mod observe;
pub(crate) mod part;
pub(crate) mod pose;
pub mod touchdown;

use std::sync::Arc;

pub use crate::simulation::signals::LateralSignals;
pub use build::lateral_laws;
pub(crate) use build::{attach, flies_three_dimensional, start, ThreeDimensional};
pub(crate) use hold::{LateralStep, LineupAtFrame};
pub use touchdown::LateralTouchdown;

use crate::control::heading_hold::HeadingHold;
use crate::control::lateral::{ChannelInputs, RollLaw, RollLawInputs, YawLaw, YawLawInputs};
use crate::control::lineup::LineupParameters;
use crate::control::pitch::ElevatorSaturation;
use crate::control::wave_off_lateral::LateralWaveOffLimits;
use crate::environment::{LateralShipMotion, LateralShipNoise, LateralShipStreams};
use crate::random::{NoiseStream, Reseed};
use crate::sensors::{LateralShipMotionMeasurement, LateralShipMotionSensor, PitchNoiseParameters};
use crate::simulation::signals::{RecordedColumn, SignalId};

/// The columns the 3-D approach's lateral part records after the approach's own
/// (`experiments::APPROACH_COLUMNS`; docs/model.md §10.1): the lineup, the moving
/// centreline, the lateral states and surfaces, the ship's roll, yaw and sway and the
/// lateral wind. A loop without it records none (the lateral part's `recorded_columns`).
pub const LATERAL_APPROACH_COLUMNS: [RecordedColumn; 18] = [
    RecordedColumn::si("y_m", SignalId::Y),
    RecordedColumn::si("hook_y_m", SignalId::HookY),
    RecordedColumn::si("cross_track_m", SignalId::CrossTrack),
    RecordedColumn::si("cross_track_rate_mps", SignalId::CrossTrackRate),
    RecordedColumn::si("lineup_error_m", SignalId::LineupError),
    RecordedColumn::si("lateral_forecast_m", SignalId::LateralForecast),
    RecordedColumn::si("centreline_y_m", SignalId::AimY),
    RecordedColumn::degrees("centreline_heading_deg", SignalId::CentrelineHeading),
    RecordedColumn::degrees("bank_command_deg", SignalId::BankCommand),
    RecordedColumn::degrees("bank_deg", SignalId::Bank),
    RecordedColumn::degrees("heading_deg", SignalId::Heading),
    RecordedColumn::degrees("sideslip_deg", SignalId::Sideslip),
    RecordedColumn::degrees("aileron_deg", SignalId::Aileron),
    RecordedColumn::degrees("rudder_deg", SignalId::Rudder),
    RecordedColumn::degrees("ship_roll_deg", SignalId::ShipRoll),
    RecordedColumn::degrees("ship_yaw_deg", SignalId::ShipYaw),
    RecordedColumn::si("ship_sway_m", SignalId::ShipSway),
    RecordedColumn::si("wind_y_mps", SignalId::WindY),
];

/// Sideslip measurement noise σ of the air data (rad): 0.2° (shared model §10.7, an
/// assumption).
pub const SIDESLIP_NOISE_SIGMA_RAD: f64 = 0.2 * std::f64::consts::PI / 180.0;

/// Tolerance of "a surface sits on a position limit" for the lateral laws (rad).
const SATURATION_TOLERANCE_RAD: f64 = 1e-9;

/// A surface's trim and travel limits (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SurfaceTrim {
    pub trim_rad: f64,
    pub min_rad: f64,
    pub max_rad: f64,
}

impl SurfaceTrim {
    fn saturation(&self, position_rad: f64) -> ElevatorSaturation {
        ElevatorSaturation::from_position(
            position_rad,
            self.min_rad,
            self.max_rad,
            SATURATION_TOLERANCE_RAD,
        )
    }
}

/// The 3-D approach's parts of the loop (module docs).
#[derive(Debug, Clone)]
pub(crate) struct LateralLoop {
    /// Roll, yaw and sway shaping filters.
    pub ship: LateralShipMotion,
    /// Earth (x, y) of the ship's pitch centre at t = 0 (m): the mean aim point at the
    /// origin.
    pub initial_pitch_centre_m: (f64, f64),
    /// sin, cos of the ship's mean heading ψ₀ (the deck angle), evaluated once.
    pub mean_heading_sin_cos: (f64, f64),
    /// The mean centreline's drift to the right, V·sin δ (m/s).
    pub mean_drift_rate_mps: f64,
    /// The closing speed on the deck the time to go is estimated with (m/s).
    pub closure_mps: f64,
    /// The roll law: bank command → aileron.
    pub roll: Arc<dyn RollLaw>,
    /// The yaw law: β = 0 → rudder.
    pub yaw: Arc<dyn YawLaw>,
    /// The lineup guidance.
    pub lineup: LineupParameters,
    /// The yaw law's heading hold in close.
    pub heading_hold: HeadingHold,
    /// The lateral wave-off criteria.
    pub wave_off: LateralWaveOffLimits,
    /// The floor of the aim point's lateral forecast, for the off-centre probability.
    pub floor: floor::AimPointLateralFloor,
    /// Aileron and rudder trims and limits.
    pub aileron: SurfaceTrim,
    pub rudder: SurfaceTrim,
    /// Trim bank and sideslip (rad).
    pub trim_bank_rad: f64,
    pub trim_sideslip_rad: f64,
    /// The bank measurement's noise: the pitch sensor's form (shared model §10.7).
    pub bank_noise: PitchNoiseParameters,
    /// The ship's lateral motion sensing and its latest measurement.
    pub sensor: LateralShipMotionSensor,
    pub last_measurement: Option<LateralShipMotionMeasurement>,
    /// The landing point's and the ramp's rise per unit sin of the ship's roll (m).
    pub roll_rise_m: (f64, f64),
    /// With a flight computer: the bank and the yaw law's angle read at the frame's
    /// start (rad).
    pub read: (f64, f64),
    /// The last deck view computed ([`pose::DeckViewMemo`]).
    pub view_memo: pose::DeckViewMemo,
    /// The ship's 3-D view at the start of the step being flown, held over its RK4
    /// stages at its rates ([`pose::DeckView3d::at`]); `None` before the first step.
    /// Kept here rather than in the held inputs, which every step copies.
    pub step_view: Option<pose::DeckView3d>,
    /// The lateral forecast of the lineup compensation's station, with the deck's
    /// constants evaluated once.
    pub forecaster: forecast::CentrelineForecaster,
    /// With a flight computer, the lateral guidance's frames (`hold`).
    pub guidance_frames: Option<hold::GuidanceFrames>,
    /// With a flight computer, its frame period (s): the ship's view is computed at each
    /// frame's start and carried over the frame ([`LateralLoop::deck_view`]).
    pub view_frame_period_s: Option<f64>,
    /// What the approach keeps of its flight for the outcome: the trap sheet and the
    /// lateral touchdown.
    pub observation: observe::ApproachObservation,
}

/// The random streams of the 3-D approach, drawn from step by step.
#[derive(Debug, Clone)]
pub struct LateralStreams {
    /// The ship's roll, yaw and sway filters.
    pub ship: LateralShipStreams,
    /// The bank measurement's white noise.
    pub bank: NoiseStream,
    /// The sideslip measurement's white noise.
    pub sideslip: NoiseStream,
    /// The heading measurement's white noise.
    pub heading: NoiseStream,
}

/// The 3-D approach's parts keep one stream source: the ship's lateral sensing.
impl Reseed for LateralLoop {
    fn reseed(&mut self, key: u64) {
        self.sensor.reseed(key);
    }
}

impl Reseed for LateralStreams {
    fn reseed(&mut self, key: u64) {
        self.ship.reseed(key);
        self.bank.reseed(key);
        self.sideslip.reseed(key);
        self.heading.reseed(key);
    }
}

/// What the 3-D approach holds over a step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeldLateral {
    /// White-noise inputs of the roll, yaw and sway filters.
    pub ship_noise: LateralShipNoise,
    /// Bank measurement error (rad).
    pub bank_noise_rad: f64,
    /// Sideslip measurement error (rad).
    pub sideslip_noise_rad: f64,
    /// Heading measurement error (rad).
    pub heading_noise_rad: f64,
    /// The heading hold's weight (–): 0, the yaw law holds β = 0; 1, the crab heading.
    pub heading_hold_weight: f64,
    /// The forecast lateral displacement of the compensation's centreline point (by
    /// default the ramp when the hook crosses it; [`forecast::compensation_station`])
    /// (m, right).
    pub forecast_m: f64,
    /// With a flight computer, the bank and the yaw law's angle (the sideslip, or in
    /// close the heading error) it read at the frame's start (rad).
    pub read: Option<(f64, f64)>,
    /// The time of the ship's 3-D view held over the step (s): the step's start
    /// ([`LateralLoop::step_view`]).
    pub(crate) deck_view_time_s: f64,
}

/// The lateral signals the laws read, from the bus.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct LateralMeasurements {
    pub bank_rad: f64,
    pub roll_rate_radps: f64,
    pub sideslip_rad: f64,
    pub yaw_rate_radps: f64,
    pub heading_rad: f64,
    pub aileron_rad: f64,
    pub rudder_rad: f64,
}

impl LateralLoop {
    /// The roll and yaw laws' inputs for the bank and sideslip commands (rad).
    pub fn law_inputs(
        &self,
        (bank_command_rad, sideslip_command_rad): (f64, f64),
        measured: &LateralMeasurements,
        held: &HeldLateral,
    ) -> (RollLawInputs, YawLawInputs) {
        let (bank_read, sideslip_read) = held.read.unwrap_or_else(|| {
            (
                measured.bank_rad + held.bank_noise_rad,
                self.heading_hold.yaw_channel_angle_rad(
                    measured.sideslip_rad + held.sideslip_noise_rad,
                    measured.heading_rad + held.heading_noise_rad,
                    held.heading_hold_weight,
                ),
            )
        });
        let roll = RollLawInputs(ChannelInputs {
            command_rad: bank_command_rad,
            measured_rad: bank_read,
            rate_measured_radps: measured.roll_rate_radps,
            surface_actual_rad: measured.aileron_rad,
            trim_angle_rad: self.trim_bank_rad,
            surface_trim_rad: self.aileron.trim_rad,
            surface_saturation: self.aileron.saturation(measured.aileron_rad),
            ..ChannelInputs::default()
        });
        let yaw = YawLawInputs(ChannelInputs {
            command_rad: sideslip_command_rad,
            measured_rad: sideslip_read,
            rate_measured_radps: -measured.yaw_rate_radps,
            surface_actual_rad: measured.rudder_rad,
            trim_angle_rad: self.trim_sideslip_rad,
            surface_trim_rad: self.rudder.trim_rad,
            surface_saturation: self.rudder.saturation(measured.rudder_rad),
            ..ChannelInputs::default()
        });
        (roll, yaw)
    }

    /// The bank (or heading) measurement's error at `time_s` with a white-noise sample
    /// drawn from `stream` (rad): white noise plus the sinusoid, as the pitch sensor's
    /// (shared model §10.7).
    pub fn draw_bank_noise(&self, time_s: f64, stream: &mut NoiseStream) -> f64 {
        let p = &self.bank_noise;
        if !p.enabled {
            return 0.0;
        }
        p.white_noise_sigma_rad * stream.standard_normal()
            + p.sinusoid_amplitude_rad * (p.sinusoid_frequency_radps * time_s).sin()
    }

    /// The sideslip measurement's error (rad), σ [`SIDESLIP_NOISE_SIGMA_RAD`], off with
    /// the pitch noise.
    pub fn draw_sideslip_noise(&self, stream: &mut NoiseStream) -> f64 {
        if !self.bank_noise.enabled {
            return 0.0;
        }
        SIDESLIP_NOISE_SIGMA_RAD * stream.standard_normal()
    }
}
