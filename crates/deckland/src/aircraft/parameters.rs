//! Mass, inertia, geometry and atmosphere constants (paper Table 2, docs/model.md §2.1).

use crate::parameters::{Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Mass properties, reference geometry and the (constant) atmosphere of the F/A-18.
///
/// Defaults are the paper's Table 2: the F/A-18 HARV values of Buttrill, Arbuckle &
/// Hoffler, NASA TM-107601 (1992), converted to SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AircraftParameters {
    /// Aircraft mass m (kg); 15000 kg, the heavy / maximum trap weight (Table 2).
    pub mass_kg: f64,
    /// Air density ρ (kg/m³), constant at low altitude; 1.33 kg/m³ (Table 2).
    pub air_density_kg_m3: f64,
    /// Gravitational acceleration g (m/s²); 9.75 m/s² (Table 2).
    pub gravity_mps2: f64,
    /// Wing reference area S (m²); 37.16 m² (Table 2).
    pub wing_area_m2: f64,
    /// Mean aerodynamic chord c̄ (m); 3.51 m (Table 2).
    pub mean_chord_m: f64,
    /// Pitch moment of inertia J_y (kg·m²); 205000 kg·m² (Table 2).
    pub pitch_inertia_kg_m2: f64,
}

impl Default for AircraftParameters {
    fn default() -> Self {
        Self {
            mass_kg: 15_000.0,
            air_density_kg_m3: 1.33,
            gravity_mps2: 9.75,
            wing_area_m2: 37.16,
            mean_chord_m: 3.51,
            pitch_inertia_kg_m2: 205_000.0,
        }
    }
}

impl AircraftParameters {
    /// Checks that every constant is finite and positive.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "aircraft.parameters";
        Bounds::closed(1000.0, 100_000.0).check(SECTION, "mass_kg", self.mass_kg)?;
        Bounds::closed(0.01, 2.0).check(SECTION, "air_density_kg_m3", self.air_density_kg_m3)?;
        Bounds::closed(1.0, 30.0).check(SECTION, "gravity_mps2", self.gravity_mps2)?;
        Bounds::closed(1.0, 1000.0).check(SECTION, "wing_area_m2", self.wing_area_m2)?;
        Bounds::closed(0.1, 50.0).check(SECTION, "mean_chord_m", self.mean_chord_m)?;
        Bounds::closed(1000.0, 1e8).check(SECTION, "pitch_inertia_kg_m2", self.pitch_inertia_kg_m2)
    }
}
