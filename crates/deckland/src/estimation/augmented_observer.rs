//! Augmented finite-time disturbance observer (docs/model.md §4, correcting paper Eq. 11–13).
//!
//! For a plant in the form (paper Eq. 7–10)
//!
//! ```text
//! ẇ1 = w2,   ẇ2 = w3 + h(t),   ẇ3 = η(t),   y = w1 + n(t)
//! ```
//!
//! with known input h and unknown bounded disturbance w3, the observer is
//!
//! ```text
//! e   = x1 − y
//! ẋ1 = x2 −      (k3/ε)·|e|^α3·sign(e)
//! ẋ2 = x3 + h − (k2/ε²)·|e|^α2·sign(e)
//! ẋ3 =         −(k1/ε³)·|e|^α1·sign(e)
//! α2 = (2α1 + 1)/3,   α3 = (α1 + 2)/3
//! ```
//!
//! so x1, x2, x3 estimate w1, w2, w3. The paper's Eq. 12 omits h and its Eq. 13 prints
//! α3 for α1; docs/model.md §4 corrects both.

use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Tuning of the augmented observer (docs/model.md §4; paper §2.3).
///
/// `k1`, `k2`, `k3` place the observer's (normalised) poles; `alpha1` sets the
/// finite-time exponents (closer to 1 is closer to a linear high-gain observer);
/// `epsilon` scales the bandwidth: the observer is roughly 1/ε times faster than its
/// normalised form, so a smaller ε tracks faster and amplifies measurement noise more.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ObserverParameters {
    /// Disturbance-channel gain k1 (dimensionless, > 0; docs/model.md §4).
    pub k1: f64,
    /// Rate-channel gain k2 (dimensionless, > (4/π)·k1/k3; docs/model.md §4).
    pub k2: f64,
    /// Output-channel gain k3 (dimensionless, > 0; docs/model.md §4).
    pub k3: f64,
    /// Exponent α1 of the disturbance channel, in (0, 1) (dimensionless; docs/model.md §4).
    pub alpha1: f64,
    /// Bandwidth parameter ε, in (0, 1) (s, in the sense that gains scale as ε⁻ⁱ;
    /// docs/model.md §4). The default 0.03 is provisional, pending tuning on the full loop.
    pub epsilon: f64,
}

impl Default for ObserverParameters {
    /// The starting values of docs/model.md §4: k1 = 1, k2 = 3, k3 = 3, α1 = 0.8, ε = 0.03.
    fn default() -> Self {
        Self {
            k1: 1.0,
            k2: 3.0,
            k3: 3.0,
            alpha1: 0.8,
            epsilon: 0.03,
        }
    }
}

impl ObserverParameters {
    /// Where the O-PD's observer sits in a scenario file.
    pub const SECTION: &'static str = "control.pitch.observer";

    /// Checks the stability and range conditions of docs/model.md §4 (k1, k3 > 0,
    /// k2 > (4/π)·k1/k3, α1 ∈ (0, 1), ε ∈ (0, 1)) and physical ranges (gains up to 1000,
    /// ε at least 0.001), naming `section.key` in the error.
    pub fn validate_in(&self, section: &str) -> Result<(), ParameterError> {
        let gain = Bounds::positive_up_to(1000.0);
        gain.check(section, "k1", self.k1)?;
        gain.check(section, "k2", self.k2)?;
        gain.check(section, "k3", self.k3)?;
        let bound = 4.0 / std::f64::consts::PI * self.k1 / self.k3;
        if self.k2 <= bound {
            return Err(ParameterError::new(
                section,
                "k2",
                self.k2,
                format_args!("a value above (4/π)·k1/k3 = {bound:.4} for stability"),
            ));
        }
        check_ranges!(section, self, {
            alpha1: Bounds::closed(0.0, 1.0) .exclusive_min() .exclusive_max(),
            epsilon: Bounds::closed(0.001, 1.0) .exclusive_max(),
        });
        Ok(())
    }

    /// [`ObserverParameters::validate_in`] at the O-PD's [`ObserverParameters::SECTION`].
    pub fn validate(&self) -> Result<(), ParameterError> {
        self.validate_in(Self::SECTION)
    }
}

/// Observer state: estimates of w1, w2 and w3 (docs/model.md §4). For the pitch loop these
/// are Δθ (rad), Δq (rad/s) and the lumped disturbance d_θ (rad/s²).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ObserverState {
    /// Estimate x1 of the measured variable w1 (pitch loop: Δθ, rad).
    pub x1: f64,
    /// Estimate x2 of its rate w2 (pitch loop: Δq, rad/s).
    pub x2: f64,
    /// Estimate x3 of the lumped disturbance w3 (pitch loop: d_θ, rad/s²).
    pub x3: f64,
}

impl ObserverState {
    /// The state as `[x1, x2, x3]` for the integrator (units as the fields).
    #[inline]
    pub fn to_array(&self) -> [f64; 3] {
        [self.x1, self.x2, self.x3]
    }

    /// The state from `[x1, x2, x3]` as produced by [`ObserverState::to_array`].
    #[inline]
    pub fn from_array(x: &[f64; 3]) -> Self {
        Self {
            x1: x[0],
            x2: x[1],
            x3: x[2],
        }
    }
}

/// The augmented finite-time disturbance observer of docs/model.md §4 with validated
/// parameters and its gains k3/ε, k2/ε², k1/ε³ precomputed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AugmentedObserver {
    parameters: ObserverParameters,
    /// k3/ε (1/s).
    output_gain: f64,
    /// k2/ε² (1/s²).
    rate_gain: f64,
    /// k1/ε³ (1/s³).
    disturbance_gain: f64,
    /// (α1 − 1)/3: then α3 = (α1 + 2)/3 = 1 + step, α2 = (2α1 + 1)/3 = 1 + 2·step and
    /// α1 = 1 + 3·step.
    alpha_step: f64,
}

impl AugmentedObserver {
    /// Builds the observer after [`ObserverParameters::validate`] (docs/model.md §4).
    pub fn new(parameters: ObserverParameters) -> Result<Self, ParameterError> {
        parameters.validate()?;
        let ObserverParameters {
            k1,
            k2,
            k3,
            alpha1,
            epsilon,
        } = parameters;
        Ok(Self {
            parameters,
            output_gain: k3 / epsilon,
            rate_gain: k2 / (epsilon * epsilon),
            disturbance_gain: k1 / (epsilon * epsilon * epsilon),
            alpha_step: (alpha1 - 1.0) / 3.0,
        })
    }

    /// The parameters the observer was built from.
    pub fn parameters(&self) -> &ObserverParameters {
        &self.parameters
    }

    /// The observer's time derivative (docs/model.md §4) for `measurement` y of w1 (pitch
    /// loop: θ_m − θ*, rad) and `known_input` h (pitch loop: h_θ, rad/s²).
    ///
    /// Pure and allocation-free. The correction terms are written as
    /// |e|^α·sign(e) = copysign(|e|^α, e), which is exactly zero at e = 0 (no NaN).
    #[inline]
    pub fn derivative(
        &self,
        state: &ObserverState,
        measurement: f64,
        known_input: f64,
    ) -> ObserverState {
        self.derivative_with_power(state, measurement, known_input, |magnitude| {
            magnitude.powf(self.alpha_step)
        })
    }

    /// The exponent (α1 − 1)/3 of the one fractional power the derivative takes (ρ below).
    pub fn power_exponent(&self) -> f64 {
        self.alpha_step
    }

    /// [`AugmentedObserver::derivative`] with the power ρ = |e|^((α1 − 1)/3) evaluated by
    /// `power` (called with |e| > 0, finite or not) instead of the library's `powf`; the
    /// same operations otherwise.
    #[inline(always)]
    pub fn derivative_with_power(
        &self,
        state: &ObserverState,
        measurement: f64,
        known_input: f64,
        power: impl FnOnce(f64) -> f64,
    ) -> ObserverState {
        let e = state.x1 - measurement;
        let magnitude = e.abs();
        // With ρ = |e|^((α1 − 1)/3): |e|^α3 = |e|·ρ, |e|^α2 = |e|·ρ², |e|^α1 = |e|·ρ³, so
        // one power serves all three (the hot loop calls this four times per step).
        let (p3, p2, p1) = if magnitude > 0.0 {
            let rho = power(magnitude);
            let p3 = magnitude * rho;
            let p2 = p3 * rho;
            (p3, p2, p2 * rho)
        } else {
            (0.0, 0.0, 0.0)
        };
        ObserverState {
            x1: state.x2 - self.output_gain * p3.copysign(e),
            x2: state.x3 + known_input - self.rate_gain * p2.copysign(e),
            x3: -self.disturbance_gain * p1.copysign(e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The single-power evaluation must equal docs/model.md §4's three powers written out.
    #[test]
    fn derivative_matches_the_three_fractional_powers_written_out() {
        let parameters = ObserverParameters::default();
        let observer = AugmentedObserver::new(parameters).unwrap();
        let (a1, eps) = (parameters.alpha1, parameters.epsilon);
        let (a2, a3) = ((2.0 * a1 + 1.0) / 3.0, (a1 + 2.0) / 3.0);
        for e in [-0.3_f64, -1e-4, 1e-7, 0.02, 1.5] {
            let state = ObserverState {
                x1: 0.1 + e,
                x2: 0.2,
                x3: -0.3,
            };
            let d = observer.derivative(&state, 0.1, 0.05);
            let p = |a: f64| f64::abs(e).powf(a) * f64::signum(e);
            let x1 = 0.2 - parameters.k3 / eps * p(a3);
            let x2 = -0.3 + 0.05 - parameters.k2 / (eps * eps) * p(a2);
            let x3 = -parameters.k1 / (eps * eps * eps) * p(a1);
            assert!((d.x1 - x1).abs() <= 1e-9 * x1.abs().max(1.0), "{e}");
            assert!((d.x2 - x2).abs() <= 1e-9 * x2.abs().max(1.0), "{e}");
            assert!((d.x3 - x3).abs() <= 1e-9 * x3.abs().max(1.0), "{e}");
        }
    }

    #[test]
    fn default_parameters_are_valid() {
        assert_eq!(ObserverParameters::default().validate(), Ok(()));
    }

    #[test]
    fn k2_below_the_stability_bound_is_rejected_with_the_bound() {
        let parameters = ObserverParameters {
            k2: 0.4,
            ..ObserverParameters::default()
        };
        let error = AugmentedObserver::new(parameters).expect_err("k2 = 0.4 < 0.424");
        assert_eq!(error.path, "control.pitch.observer.k2");
        assert_eq!(error.value, "0.4");
        // (4/π)·1/3 = 0.42441…
        assert!(error.allowed.contains("0.4244"), "{error}");
    }

    #[test]
    fn each_invalid_field_is_named() {
        let base = ObserverParameters::default();
        let cases = [
            (ObserverParameters { k1: 0.0, ..base }, "k1"),
            (ObserverParameters { k3: -1.0, ..base }, "k3"),
            (
                ObserverParameters {
                    k2: f64::NAN,
                    ..base
                },
                "k2",
            ),
            (
                ObserverParameters {
                    alpha1: 1.0,
                    ..base
                },
                "alpha1",
            ),
            (
                ObserverParameters {
                    alpha1: 0.0,
                    ..base
                },
                "alpha1",
            ),
            (
                ObserverParameters {
                    epsilon: 1.5,
                    ..base
                },
                "epsilon",
            ),
            (
                ObserverParameters {
                    epsilon: f64::INFINITY,
                    ..base
                },
                "epsilon",
            ),
        ];
        for (parameters, field) in cases {
            let message = parameters
                .validate()
                .expect_err("invalid parameters")
                .to_string();
            assert!(message.contains(field), "{message} should name {field}");
        }
    }

    #[test]
    fn zero_output_error_gives_the_open_loop_model_without_nan() {
        let observer = AugmentedObserver::new(ObserverParameters::default()).expect("valid");
        let state = ObserverState {
            x1: 0.1,
            x2: 0.2,
            x3: 0.3,
        };
        for y in [0.1, -0.0] {
            let state = ObserverState { x1: y, ..state };
            let derivative = observer.derivative(&state, y, 0.5);
            assert_eq!(derivative.to_array(), [0.2, 0.8, 0.0]);
        }
    }

    #[test]
    fn corrections_oppose_the_output_error() {
        let observer = AugmentedObserver::new(ObserverParameters::default()).expect("valid");
        let state = ObserverState::default();
        let above = observer.derivative(&state, -0.01, 0.0);
        let below = observer.derivative(&state, 0.01, 0.0);
        assert!(above.x1 < 0.0 && above.x2 < 0.0 && above.x3 < 0.0);
        assert_eq!(above.to_array().map(|v| -v), below.to_array());
    }

    #[test]
    fn array_round_trip() {
        let state = ObserverState {
            x1: 1.0,
            x2: -2.0,
            x3: 3.5,
        };
        assert_eq!(ObserverState::from_array(&state.to_array()), state);
    }

    #[test]
    fn parameters_deserialise_with_defaults_for_missing_fields() {
        let parameters: ObserverParameters =
            serde_json::from_str(r#"{"epsilon": 0.02}"#).expect("valid JSON");
        assert_eq!(parameters.epsilon, 0.02);
        assert_eq!(parameters.k2, 3.0);
    }
}
