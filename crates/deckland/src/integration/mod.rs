//! Numerical integration of ordinary differential equations.
//!
//! Only the integrator sees state vectors as plain arrays; every model keeps its state
//! in a named struct and converts to and from an array at this boundary.

mod rk4;
mod vector;

pub use rk4::{rk4_step, rk4_step_from, OdeSystem};
pub use vector::{Rk4Workspace, VectorSystem};
