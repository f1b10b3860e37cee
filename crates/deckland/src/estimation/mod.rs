//! State and disturbance estimation (docs/model.md §4; paper §2.3).
//!
//! The [`AugmentedObserver`] estimates a measured variable, its rate and a lumped
//! disturbance acting on its second derivative. The O-PD pitch controller runs one on
//! the pitch-attitude deviation from trim. The [`DeckMotionEstimator`] is a Kalman filter
//! of the ship's motion from the ship's measurements (docs/model.md §3.5).

mod augmented_observer;
mod deck_motion;
mod fractional_power;

pub use augmented_observer::{AugmentedObserver, ObserverParameters, ObserverState};
pub use deck_motion::DeckMotionEstimator;
pub use fractional_power::FractionalPower;
