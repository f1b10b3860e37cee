//! Sensors and their noise (paper §3.5; docs/model.md §3.3).

mod pitch;

pub use pitch::{PitchNoiseParameters, PitchSensor};
