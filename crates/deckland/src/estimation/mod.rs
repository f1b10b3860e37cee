//! State and disturbance estimation (docs/model.md §4; paper §2.3).
//!
//! The [`AugmentedObserver`] estimates a measured variable, its rate and a lumped
//! disturbance acting on its second derivative. The O-PD pitch controller runs one on
//! the pitch-attitude deviation from trim.

mod augmented_observer;

pub use augmented_observer::{AugmentedObserver, ObserverParameters, ObserverState};
