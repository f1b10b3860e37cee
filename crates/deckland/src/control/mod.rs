//! Flight controllers of the landing cascade (docs/model.md §5; paper §4).
//!
//! Cascade: flight-path generator → guidance → sink-rate controller → [`pitch`]
//! controller → elevator; in parallel the speed controller → thrust and, in the
//! realistic set, direct lift control from the glide-path error → lift.
//!
//! The laws of an axis share one interface, [`AxisLaw`], and describe themselves to the
//! design code in one data form, [`LinearLaw`]; the pitch laws are its first instances.

mod arrival_timing;
mod command_ramp;
mod deck_motion_filter;
pub mod design;
mod direct_lift;
mod flight_path;
mod guidance;
pub mod heading_hold;
mod late_abort;
pub mod lateral;
mod law;
pub mod lineup;
mod loop_controller;
pub mod pitch;
pub mod risk;
mod sink_rate;
mod speed;
mod wave_off;
pub mod wave_off_lateral;

pub use arrival_timing::{
    ArrivalTiming, ArrivalTimingInputs, ArrivalTimingParameters, CANDIDATE_SPACING_S,
    REPLAN_PERIOD_S,
};
pub use command_ramp::{smooth_step, CommandRamp};
pub use deck_motion_filter::DeckMotionFilter;
pub use direct_lift::{DirectLiftParameters, LiftLoop};
pub use flight_path::{
    CompensationBlend, DeckForecast, DeckPredictorKind, DeckReference, FlightPathGenerator,
    FlightPathParameters, PathReference,
};
pub use guidance::GuidanceParameters;
pub use late_abort::LateAbortInputs;
pub use law::{AxisLaw, LinearLaw};
pub use loop_controller::{LoopController, LoopGains};
pub use sink_rate::SinkRateControllerParameters;
pub use speed::{SpeedController, SpeedControllerParameters};
pub use wave_off::{
    CommitForecast, FoulDeckModel, HardLandingModel, RampStrikeModel, RecoveryLimits,
    WaveOffCriterion, WaveOffDecision, WaveOffInputs, WaveOffParameters,
};
