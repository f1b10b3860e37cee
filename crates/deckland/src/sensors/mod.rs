//! Sensors and their noise (paper §3.5; docs/model.md §3.3, §3.5).

mod channel_sensor;
mod data_link;
mod pitch;
mod ship_lateral_motion;
mod ship_motion;

pub use pitch::{PitchNoiseParameters, PitchSensor};
pub use ship_lateral_motion::{
    lateral_ship_sensor_streams, measure_lateral_ship_motion, LateralShipMotionMeasurement,
    LateralShipMotionSensor,
};
pub use ship_motion::{
    EstimatorStart, ShipMotionMeasurement, ShipMotionSensingParameters, ShipMotionSensor,
};
