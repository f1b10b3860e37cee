//! The registry of built plants: the aircraft a loop flies, one variant per known model
//! ([`PlantModel`]), each flown by its own monomorphic instantiation of the loop. A new
//! aircraft model is a variant here and a line in each of these dispatches, beside its
//! name in [`PlantModel`].

use super::six_dof::SixDofAircraft;
use super::{Aircraft, AircraftState, Plant, PlantModel};

/// The plant a loop flies: one of the known plants, each flown by its own
/// monomorphic instantiation of the loop (no dynamic dispatch in the hot path).
// One per loop: boxing the larger plant would add a pointer chase to every evaluation.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BuiltPlant {
    /// The longitudinal F/A-18 (`model = "3dof"`).
    ThreeDof(Aircraft),
    /// The 6-DOF F/A-18 (`model = "6dof"`).
    SixDof(SixDofAircraft),
}

impl BuiltPlant {
    /// The model's name.
    pub fn model(&self) -> PlantModel {
        match self {
            Self::ThreeDof(_) => Aircraft::MODEL,
            Self::SixDof(_) => SixDofAircraft::MODEL,
        }
    }

    /// The longitudinal model (the whole plant for the 3-DOF; the aerodynamics, engines
    /// and stabilator the 6-DOF is built on).
    #[inline]
    pub fn longitudinal(&self) -> &Aircraft {
        match self {
            Self::ThreeDof(plant) => plant,
            Self::SixDof(plant) => plant.longitudinal(),
        }
    }

    /// The names of the plant's states.
    pub fn state_names(&self) -> &'static [&'static str] {
        match self {
            Self::ThreeDof(_) => Aircraft::STATE_NAMES,
            Self::SixDof(_) => SixDofAircraft::STATE_NAMES,
        }
    }

    /// The units of the plant's states.
    pub fn state_units(&self) -> &'static [&'static str] {
        match self {
            Self::ThreeDof(_) => Aircraft::STATE_UNITS,
            Self::SixDof(_) => SixDofAircraft::STATE_UNITS,
        }
    }

    /// The longitudinal part of the plant's state in `x` from `offset`.
    #[inline]
    pub fn longitudinal_state(&self, x: &[f64], offset: usize) -> AircraftState {
        match self {
            Self::ThreeDof(_) => Aircraft::state_at(x, offset),
            Self::SixDof(_) => {
                SixDofAircraft::longitudinal_state(&SixDofAircraft::state_at(x, offset))
            }
        }
    }

    /// Writes the plant's state of a longitudinal state into `x` from `offset`.
    pub fn write_longitudinal_state(&self, state: &AircraftState, x: &mut [f64], offset: usize) {
        match self {
            Self::ThreeDof(_) => Aircraft::write_state_at(state, x, offset),
            Self::SixDof(_) => {
                SixDofAircraft::write_state_at(&SixDofAircraft::from_longitudinal(state), x, offset)
            }
        }
    }

    /// Holds the actuators at their stops (`x`: the plant's states).
    #[inline]
    pub fn constrain(&self, x: &mut [f64]) {
        match self {
            Self::ThreeDof(plant) => Plant::constrain(plant, x),
            Self::SixDof(plant) => Plant::constrain(plant, x),
        }
    }
}

/// Work done with the plant a loop flies, generic over the plant: through
/// [`BuiltPlant::with`], the registry's one dispatch from a built plant to the work's
/// monomorphic instantiation for it (no dynamic dispatch in the hot path).
pub trait WithPlant {
    /// What the work gives.
    type Output;
    /// Does the work with `plant`.
    fn with<P: Plant>(self, plant: &P) -> Self::Output;
}

impl BuiltPlant {
    /// Does `work` with the plant, whichever it is.
    #[inline(always)]
    pub fn with<W: WithPlant>(&self, work: W) -> W::Output {
        match self {
            Self::ThreeDof(plant) => work.with(plant),
            Self::SixDof(plant) => work.with(plant),
        }
    }
}
