//! # deckland — automatic carrier landing of an unmanned F/A-18
//!
//! A library of models and algorithms for simulating and controlling the automatic
//! landing of an unmanned F/A-18 on a moving aircraft carrier, following Kistyarev &
//! Wang, *Unmanned F/A-18 Aircraft Landing Control on Aircraft Carrier in Adverse
//! Conditions*, corrected and completed by the project's engineering specification
//! (`docs/model.md`).
//!
//! ## Conventions (read these first)
//!
//! - **Units**: SI and radians everywhere inside the library. Degrees appear only at
//!   the edges (configuration, printed tables, plots) and the name then says so
//!   (`glide_slope_deg`, `elevator_deg`).
//! - **Earth axes**: x horizontal, positive in the direction of flight (towards the
//!   ship); altitude h positive up.
//! - **Body axes**: x forward, z down. Pitch angle θ positive nose-up.
//! - **Sink rate** is positive downward: sink = −ḣ.
//! - **Air-relative** quantities: airspeed V_T and angle of attack α. The inertial
//!   flight-path angle is γ = atan2(ḣ, ẋ); in still air γ = θ − α.
//! - **Wind** is the velocity of the air mass in earth axes: W_x positive forward (a
//!   headwind is negative), W_z positive down. Wind enters the aerodynamics only through
//!   the air-relative velocity, never as a force.
//! - **Elevator** δe is the symmetric stabilator, positive trailing edge down, which
//!   produces a nose-down moment.
//!
//! ## Data flow
//!
//! scenario → environment → aircraft plant → sensors → observer → controllers →
//! integrator loop → recorder → metrics. Beside it: trim, linearisation and modes
//! ([`analysis`]), and Monte Carlo campaigns over many seeds and dispersions
//! ([`monte_carlo`]).

pub mod aircraft;
pub mod analysis;
pub mod control;
pub mod environment;
pub mod estimation;
pub mod experiments;
pub mod integration;
pub mod metrics;
pub mod monte_carlo;
pub mod parameters;
pub mod random;
pub mod rare;
pub mod recording;
pub mod scenario;
pub mod sensors;
pub mod simulation;
