//! Sensors and their noise (paper §3.5; docs/model.md §3.3, §3.5).

mod pitch;
mod ship_motion;

pub use pitch::{PitchNoiseParameters, PitchSensor};
pub use ship_motion::{
    EstimatorStart, ShipMotionMeasurement, ShipMotionSensingParameters, ShipMotionSensor,
};
