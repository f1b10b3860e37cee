//! The aircraft's environment: ship deck motion, deck geometry, wind and carrier air
//! wake (paper §3.3–3.4; docs/model.md §3).
//!
//! Signs at a glance: the ship sails in +x and the aircraft approaches from astern, also
//! flying +x; heights and heave are positive up; ship pitch is positive bow-up; wind is
//! the air mass's velocity in earth axes, x positive forward (a headwind is negative) and
//! z positive down; X, the argument of the wake model, is the distance aft of the ship's
//! pitch centre (positive aft). In three dimensions (§3.7–3.9) y is positive to the right
//! of the final bearing, ship roll positive starboard side down, ship yaw positive bow to
//! starboard, and W_y positive blowing to the right.

mod angled_deck;
mod deck;
mod deck_window;
pub mod lyapunov;
pub mod seaway;
mod ship;
mod ship_lateral;
mod ship_model;
mod ship_prediction;
mod ship_simulator;
mod turbulence;
mod turbulence_lateral;
mod wind;
mod wind_model;

pub use angled_deck::{DeckCentreline, EarthDirection, ShipAttitude};
pub use deck::{DeckGeometry, EarthPoint, EarthVelocity, ShipPose, ShipPoseRate};
pub use ship::{
    heave_unit_intensity_variance, pitch_unit_intensity_variance, shaping_filter_companion,
    unit_intensity_state_covariance, ShapingFilter, ShipModelKind, ShipMotion, ShipMotionOutputs,
    ShipMotionParameters, ShipMotionState, ShipNoise, HEAVE_FILTER_GAIN, PITCH_FILTER_GAIN,
    SHAPING_FILTER_DENOMINATOR,
};
pub use ship_lateral::{
    roll_filter_companion, roll_unit_intensity_state_covariance, LateralShipMotion,
    LateralShipMotionOutputs, LateralShipMotionState, LateralShipNoise, LateralShipStreams,
    ROLL_FILTER_DAMPING_RATIO, ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
};
pub use ship_model::{
    resolved_ship_parameters, ship_model, ship_motion, validate_seaway, PaperFilters, SeawayShip,
    ShipModel, ShipMotionShape,
};
pub use ship_prediction::{
    DeckPointUncertainty, Matrix4Array, PredictedShipMotion, ShipMotionEstimate,
    ShipMotionForecast, ShipMotionPropagator,
};
pub use ship_simulator::ShipMotionSimulator;
pub use turbulence::Turbulence;
pub use turbulence_lateral::LateralTurbulence;
pub use wind::{
    mean_wind, mean_wind_over_angled_deck, periodic_wake, steady_wake, Wind, WindComponents,
    WindParameters, STEADY_WAKE_EXTENT_M, WAKE_TAPER_M,
};
pub use wind_model::WindModel;

#[cfg(test)]
mod tests;
