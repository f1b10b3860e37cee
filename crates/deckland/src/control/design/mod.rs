//! The design code of an axis's attitude loop — pitch, roll or yaw: angle, rate, one
//! surface — which works for any law that describes itself in its linear limit
//! ([`LinearLaw`]) and never names a concrete law (docs/stabilator-design.md,
//! docs/lateral-control.md; docs/model.md §2.6, §3.3, §4–5):
//!
//! - [`loop_model`]: the reduced linear loop — plant ([`AxisPlantDerivatives`], with the
//!   pitch axis's optional angle-of-attack coupling), actuator, sensor noise and the law's
//!   [`LinearLaw`] — with its loop gain at the surface command and its closed-loop
//!   transfer functions;
//! - [`assess_loop`]: a law's margins with the actuator and the computer's delay, the
//!   angle's lag behind its command seen by the outer loop, the sensor noise at the
//!   surface and the rate limit's limit cycle ([`rate_limit`], describing function), and
//!   [`shortfalls`], how far that is from a [`DesignRequest`];
//! - [`design_command`]: the jerk-limited command the surface's rate and travel allow
//!   ([`JerkLimitedStep`] with the feed-forward of
//!   [`command_shaping::reference_equivalent_control`]). The feed-forward surface
//!   δ_ff = (ω̇_r − M_q·ω_r)/M_δ may use a fraction η of the rate limit R and a fraction κ
//!   of the travel to the nearer stop:
//!   A = κ·|M_δ|·min(δ* − δ_min, δ_max − δ*),  J = η·R·|M_δ| − |M_q|·A
//!   (M_q: the rate damping, M_δ: the control power).
//!   **Criterion** (the one a request can fail): the command settling time of a design
//!   step is the trajectory's duration plus the actuator's lag 2ζ_a/ω_a; a requested
//!   settling time below it is refused, naming the rate limit (when the jerk bound sets
//!   the duration) or the stop (when the acceleration bound does), by the axis's
//!   [`ActuatorKeys`];
//! - [`check_tuning`]: setup's refusal of a tuning the hardware cannot fly.
//!
//! A law's own design procedure sits beside the law and calls these: the pitch O-PD's
//! search over its settling time, ε and fed-back attitude is
//! `control::pitch::observer_pd::design_observer_pd`.

pub use crate::control::LinearLaw;
#[cfg(doc)]
use command_shaping::JerkLimitedStep;

mod assessment;
mod command;
pub mod command_shaping;
pub mod loop_model;
mod plant;
pub mod rate_limit;
mod request;
#[cfg(test)]
pub(crate) mod tests;
mod tuning;

pub use assessment::{assess_loop, shortfalls, LoopAssessment, NoiseBudget};
pub use command::{command_bounds, design_command, nearer_stop_travel_rad};
#[cfg(test)]
pub(crate) use plant::PAPER_PITCH_PLANT;
pub use plant::{ActuatorKeys, AngleOfAttackCoupling, AxisPlantDerivatives, LinearActuator};
pub use request::{
    check_request, AxisHardware, DesignError, DesignRequest, LinearisedLaw, SensorNoise,
};
pub use tuning::{check_tuning, TuningProblem};
