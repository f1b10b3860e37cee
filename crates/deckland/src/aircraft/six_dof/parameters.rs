//! Lateral-directional mass properties, span and the aileron and rudder actuators
//! (docs/six-dof.md).

use super::super::actuator::{ElevatorActuator, ElevatorActuatorParameters};
use crate::parameters::{Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Span and the inertias the longitudinal model does not need.
///
/// Source: NASA TM-107601 (Buttrill, Arbuckle & Hoffler 1992), as used by Chakraborty,
/// Seiler & Balas (JGCD 2011): b = 37.42 ft, I_x = 23 000, I_z = 169 945,
/// I_xz = −2 971 slug·ft² (1 slug·ft² = 1.355 818 kg·m²). The pitch inertia I_y is the
/// longitudinal model's (`AircraftParameters::pitch_inertia_kg_m2`, paper Table 2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LateralParameters {
    /// Wing span b (m); 11.405 m (37.42 ft).
    pub span_m: f64,
    /// Roll moment of inertia I_x (kg·m²); 31 184 kg·m².
    pub roll_inertia_kg_m2: f64,
    /// Yaw moment of inertia I_z (kg·m²); 230 415 kg·m².
    pub yaw_inertia_kg_m2: f64,
    /// Product of inertia I_xz = ∫x·z dm in body axes (x forward, z down) (kg·m²);
    /// −4 028 kg·m², the source's −2 971 slug·ft² taken in the sign convention of
    /// Stevens & Lewis §1.3 (inertia matrix [[I_x, 0, −I_xz], [0, I_y, 0], [−I_xz, 0, I_z]]).
    pub product_of_inertia_xz_kg_m2: f64,
}

impl Default for LateralParameters {
    fn default() -> Self {
        Self {
            span_m: 11.405,
            roll_inertia_kg_m2: 31_184.0,
            yaw_inertia_kg_m2: 230_415.0,
            product_of_inertia_xz_kg_m2: -4_028.0,
        }
    }
}

/// Smallest moment of inertia about any axis of the x–z plane (kg·m²): the floor of
/// `roll_inertia_kg_m2` and `yaw_inertia_kg_m2`, and of the principal moments that the
/// product of inertia leaves ([`LateralParameters::validate`]).
pub const MIN_INERTIA_KG_M2: f64 = 1000.0;

impl LateralParameters {
    /// Checks the span (1–100 m), the inertias (`MIN_INERTIA_KG_M2`, 1000, to 10⁸ kg·m²) and
    /// the product of inertia: |I_xz| ≤ √((I_x − I_min)·(I_z − I_min)), I_min =
    /// `MIN_INERTIA_KG_M2`. That is, the smaller principal moment of inertia of the x–z
    /// plane, ((I_x + I_z) − √((I_x − I_z)² + 4·I_xz²))/2, is at least I_min, the floor of
    /// I_x and I_z themselves. The roll and yaw equations divide by Γ = I_x·I_z − I_xz²
    /// (Stevens & Lewis Eq. 1.7-4): |I_xz| < √(I_x·I_z) alone keeps Γ positive, but near
    /// that bound the roll–yaw accelerations grow as 1/Γ and the 1-ms step diverges
    /// (x = −2.9·10¹⁴ m at t = 0.001 s at |I_xz| = 0.999999·√(I_x·I_z); the default
    /// F/A-18 still flies at 0.999, where the smaller principal moment is 55 kg·m²).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "aircraft.lateral";
        Bounds::closed(1.0, 100.0).check(SECTION, "span_m", self.span_m)?;
        let inertia = Bounds::closed(MIN_INERTIA_KG_M2, 1e8);
        inertia.check(SECTION, "roll_inertia_kg_m2", self.roll_inertia_kg_m2)?;
        inertia.check(SECTION, "yaw_inertia_kg_m2", self.yaw_inertia_kg_m2)?;
        let limit = ((self.roll_inertia_kg_m2 - MIN_INERTIA_KG_M2)
            * (self.yaw_inertia_kg_m2 - MIN_INERTIA_KG_M2))
            .sqrt();
        let product = self.product_of_inertia_xz_kg_m2;
        if product.is_finite() && product.abs() <= limit {
            return Ok(());
        }
        Err(ParameterError::new(
            SECTION,
            "product_of_inertia_xz_kg_m2",
            product,
            format_args!(
                "a value in [{}, {}] for these I_x and I_z: the smaller principal moment of \
                 inertia of the x–z plane must be at least {MIN_INERTIA_KG_M2} kg·m² (the \
                 floor of I_x and I_z), or the roll and yaw equations, which divide by \
                 I_x·I_z − I_xz², diverge within a step",
                crate::parameters::readable_number(-limit),
                crate::parameters::readable_number(limit)
            ),
        ))
    }
}

/// A second-order surface actuator with symmetric travel and a rate limit, in the units
/// of a data sheet. It has the stabilator's dynamics (docs/model.md §2.6):
/// δ̈ = ω_n²(δ_c − δ) − 2ζω_n·δ̇, then the rate limit, then the travel limits on the
/// position (the order of [`ElevatorActuator`], which runs it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceActuatorParameters {
    /// Natural frequency ω_n (rad/s); 30.74 rad/s for both surfaces, the stabilator's
    /// (an assumption: no lateral actuator bandwidths are given, so both surfaces take the
    /// stabilator's).
    pub natural_frequency_rad_s: f64,
    /// Damping ratio ζ (–); 0.509, the stabilator's.
    pub damping_ratio: f64,
    /// Travel either side of neutral (deg): aileron 25°, rudder 30° (docs/six-dof.md).
    pub travel_deg: f64,
    /// Rate limit (deg/s): aileron 100 °/s, rudder 82 °/s (docs/six-dof.md, after the
    /// F/A-18 HARV actuator models); `None` is an ideal actuator.
    pub rate_limit_degps: Option<f64>,
}

impl SurfaceActuatorParameters {
    /// The aileron of the realistic set: ±25°, 100 °/s.
    pub const AILERON: Self = Self {
        natural_frequency_rad_s: 30.74,
        damping_ratio: 0.509,
        travel_deg: 25.0,
        rate_limit_degps: Some(100.0),
    };

    /// The rudder of the realistic set: ±30°, 82 °/s.
    pub const RUDDER: Self = Self {
        natural_frequency_rad_s: 30.74,
        damping_ratio: 0.509,
        travel_deg: 30.0,
        rate_limit_degps: Some(82.0),
    };

    /// Checks natural frequency 1–300 rad/s, damping 0.05–5, travel (0, 60]°, rate limit
    /// (0, 500] °/s; errors name `section.key`.
    pub fn validate(&self, section: &str) -> Result<(), ParameterError> {
        Bounds::closed(1.0, 300.0).check(
            section,
            "natural_frequency_rad_s",
            self.natural_frequency_rad_s,
        )?;
        Bounds::closed(0.05, 5.0).check(section, "damping_ratio", self.damping_ratio)?;
        Bounds::positive_up_to(60.0).check(section, "travel_deg", self.travel_deg)?;
        if let Some(rate) = self.rate_limit_degps {
            Bounds::positive_up_to(500.0).check(section, "rate_limit_degps", rate)?;
        }
        Ok(())
    }

    /// The actuator model, after validating the parameters under `section`.
    pub fn build(&self, section: &str) -> Result<ElevatorActuator, ParameterError> {
        self.validate(section)?;
        // The ranges checked above lie inside the stabilator's, so this cannot fail
        // with an error that names the elevator.
        ElevatorActuator::new(ElevatorActuatorParameters {
            natural_frequency_rad_s: self.natural_frequency_rad_s,
            damping_ratio: self.damping_ratio,
            min_deflection_deg: -self.travel_deg,
            max_deflection_deg: self.travel_deg,
            rate_limit_degps: self.rate_limit_degps,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid() {
        LateralParameters::default().validate().unwrap();
        SurfaceActuatorParameters::AILERON.build("a").unwrap();
        SurfaceActuatorParameters::RUDDER.build("r").unwrap();
    }

    #[test]
    fn conversions_from_the_source_units() {
        // 1 ft = 0.3048 m; 1 slug·ft² = 14.593 903 kg × 0.092 903 04 m² = 1.355 818 kg·m².
        let slug_ft2 = 14.593_903 * 0.3048 * 0.3048;
        let p = LateralParameters::default();
        assert!((p.span_m - 37.42 * 0.3048).abs() < 1e-3);
        assert!((p.roll_inertia_kg_m2 - 23_000.0 * slug_ft2).abs() < 1.0);
        assert!((p.yaw_inertia_kg_m2 - 169_945.0 * slug_ft2).abs() < 1.0);
        assert!((p.product_of_inertia_xz_kg_m2 + 2_971.0 * slug_ft2).abs() < 1.0);
    }

    #[test]
    fn bad_values_are_named() {
        let error = LateralParameters {
            product_of_inertia_xz_kg_m2: 1e6,
            ..Default::default()
        }
        .validate()
        .unwrap_err();
        assert_eq!(error.path, "aircraft.lateral.product_of_inertia_xz_kg_m2");
        let error = SurfaceActuatorParameters {
            travel_deg: -5.0,
            ..SurfaceActuatorParameters::RUDDER
        }
        .build("aircraft.rudder_actuator")
        .unwrap_err();
        assert_eq!(error.path, "aircraft.rudder_actuator.travel_deg");
        assert_eq!(error.value, "-5.0");
    }
}
