//! Rare-event simulation (docs/rare-events.md): the probability of a catastrophe per
//! approach, down to one in a million, with a confidence interval.
//!
//! - [`splitting`]: generalised adaptive multilevel splitting (AMS) after
//!   C.-E. Bréhier, M. Gazeau, L. Goudenège, T. Lelièvre & M. Rousset,
//!   "Unbiasedness of some generalized adaptive multilevel splitting
//!   algorithms", Annals of Applied Probability 26 (2016), with independent
//!   repetitions and a 95 % confidence interval; generic over any
//!   [`Trajectory`].
//! - [`ornstein_uhlenbeck`]: an exactly discretised Ornstein–Uhlenbeck
//!   process whose exceedance probability is computed without simulation;
//!   it validates the estimator.
//! - [`score`]: each catastrophic event's score along an approach.
//! - [`flight`]: an approach as a trajectory splitting can branch.
//! - [`ramp_forecast`]: the ramp score's forecast along a flight, beside the clearance
//!   flown (how well the score ranks flights), and the calibration flown from it.
//! - [`ramp_calibration`]: the ramp score's calibration, the forecast's mean miss and
//!   spread by the time before the crossing.

pub mod flight;
pub mod ornstein_uhlenbeck;
pub mod ramp_calibration;
pub mod ramp_forecast;
pub mod rate;
pub mod score;
pub mod splitting;

pub use flight::{ApproachFlight, FlightError};
pub use ramp_calibration::RampCalibration;
pub use rate::{
    estimate_rate, estimate_rate_batched, fly_repetition, replay_event_flight, RareError,
    RareRequest, RareResult,
};
pub use score::{EventScore, EventThresholds, RareEvent};
pub use splitting::{
    estimate, estimate_batched, estimate_observed, refly, repetition_seed, run, Advance, AmsError,
    Branch, Budget, Estimate, EventParticle, Outcome, PartialReason, Run, Settings, Stop,
    Trajectory, MIN_REPETITIONS_FOR_TARGET, REPETITIONS_PER_BATCH,
};
